#!/bin/sh
# Pictures for the README (make demo-plots): the table, the elastic scene's
# energy over time for both responses, and the gas speed histogram against
# the 2-D Maxwell-Boltzmann (Rayleigh) distribution.
# usage: demo/plots.sh BILLIARDS_BINARY OUTPUT_DIR
set -eu
BIN=$1
OUT=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"

"$BIN" --headless --seconds 1.5 --screenshot "$OUT/billiards.png" > /dev/null

for response in collide2d box2d; do
    "$BIN" --headless --scene elastic --seconds 60 --response "$response" --trace "$TMP/$response.csv" > /dev/null
done
gnuplot <<GP
set terminal pngcairo size 900,500 font ",11"
set output "$OUT/energy.png"
set datafile separator ","
set key top left
set title "Elastic break (restitution 1, no losses), 60 frames/s: kinetic energy / initial"
set xlabel "time (s)"
set ylabel "E(t) / E(0)"
set grid
e0c = system("sed -n 2p $TMP/collide2d.csv | cut -d, -f2") + 0
e0b = system("sed -n 2p $TMP/box2d.csv | cut -d, -f2") + 0
plot "$TMP/collide2d.csv" every ::1 using 1:(\$2/e0c) with lines lw 2 title "collide2d response (Box2D broadphase only)", \
     "$TMP/box2d.csv" every ::1 using 1:(\$2/e0b) with lines lw 2 title "Box2D 2.4.1 solver"
GP

"$BIN" --headless --scene gas --balls 10000 --seconds 10 --speeds "$TMP/speeds.txt" > /dev/null
sigma2=$(awk '{ s += $1 * $1 } END { printf "%.10g", s / NR / 2 }' "$TMP/speeds.txt")
gnuplot <<GP
set terminal pngcairo size 900,500 font ",11"
set output "$OUT/gas_histogram.png"
set title "Disk gas, 10,000 disks after 10 s: speed distribution vs 2-D Maxwell-Boltzmann"
set xlabel "speed (m/s)"
set ylabel "probability density (s/m)"
set grid
n = system("wc -l < $TMP/speeds.txt") + 0
w = 0.05
bin(v) = w * (floor(v / w) + 0.5)
s2 = $sigma2
set style fill solid 0.5
set xrange [0:*]
plot "$TMP/speeds.txt" using (bin(\$1)):(1.0 / (n * w)) smooth frequency with boxes title "simulation", \
     x / s2 * exp(-x * x / (2 * s2)) with lines lw 2 title "Rayleigh, sigma^2 = <v^2>/2"
GP
echo "wrote $OUT/billiards.png $OUT/energy.png $OUT/gas_histogram.png"
