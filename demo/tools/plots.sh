#!/bin/sh
# SPDX-License-Identifier: MIT
# Pictures for docs/POOL.md and docs/GAME.md (make demo-plots): the elastic scene's energy
# over time for both responses, the gas speed histogram against the
# 2-D Maxwell-Boltzmann (Rayleigh) distribution, and one shot's path with
# its events.  (The table pictures, docs/billiards.png and
# docs/eight_ball.png, are window captures under Xvfb: a game in progress
# with its aiming aids, which a headless screenshot does not draw.)
# usage: demo/tools/plots.sh BILLIARDS_BINARY OUTPUT_DIR
set -eu
BIN=$1
OUT=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"

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
# One shot's path: a cut with draw and a little english.  --events holds
# each ball's full state after each event, and between events every ball
# moves in closed form: sliding, a = -mu_s g u/|u| with the contact point's
# slip u = (vx - R wy, vy + R wx); rolling, a = -mu_r g v/|v|.  So the paths
# are drawn from the events alone, with the model's parameters from --json.
json_get() { sed -n "s/.*\"$2\":\([^,}]*\).*/\1/p" "$1"; }
"$BIN" --headless --place 0,0.9,0.45 --place 1,1.3,0.6 --shot 18,3,0.15,-0.45 --events "$TMP/path.csv" \
    --json > "$TMP/path.json"
awk -F, -v mu_s="$(json_get "$TMP/path.json" mu_slide)" -v mu_r="$(json_get "$TMP/path.json" mu_roll)" \
    -v g="$(json_get "$TMP/path.json" gravity)" -v R="$(json_get "$TMP/path.json" ball_radius)" \
    -v slide="$TMP/sliding.dat" -v roll="$TMP/rolling.dat" -v marks="$TMP/events.dat" '
    NR == 1 { next }
    { n = ++count[$3]; row[$3, n] = $0
      label = $2; gsub("_", "-", label)
      print $5, $6, ($2 == "ball_ball" && $3 > $4) ? "" : label > marks }
    END {
        for (b in count)
            for (k = 1; k < count[b]; ++k) {
                split(row[b, k], s, ","); split(row[b, k + 1], e, ",")
                x = s[5]; y = s[6]; vx = s[7]; vy = s[8]; ux = vx - R * s[10]; uy = vy + R * s[9]
                u = sqrt(ux * ux + uy * uy); v = sqrt(vx * vx + vy * vy)
                if (u > 1e-9) { ax = -mu_s * g * ux / u; ay = -mu_s * g * uy / u; f = slide }
                else if (v > 0) { ax = -mu_r * g * vx / v; ay = -mu_r * g * vy / v; f = roll }
                else continue
                for (i = 0; i <= 60; ++i) {
                    h = (e[1] - s[1]) * i / 60
                    print x + vx * h + 0.5 * ax * h * h, y + vy * h + 0.5 * ay * h * h > f
                }
                print "" > f
            }
    }' "$TMP/path.csv"
gnuplot <<GP
set terminal pngcairo size 1000,560 font ",11"
set output "$OUT/shot_path.png"
set title "A cut with draw and right english (--shot 18,3,0.15,-0.45): sliding paths curve, rolling ones are straight"
set size ratio -1
set xrange [-0.05:2.59]
set yrange [-0.05:1.32]
set xlabel "x (m)"
set ylabel "y (m)"
set key outside bottom center horizontal
set object 1 rect from 0,0 to 2.54,1.27 fillstyle empty border rgb "#2e7d32" lw 2
plot "$TMP/sliding.dat" with lines lw 2.5 lc rgb "#d62728" title "sliding", \
     "$TMP/rolling.dat" with lines lw 2.5 lc rgb "#1f77b4" title "rolling", \
     "$TMP/events.dat" using 1:2 with points pt 7 ps 1.2 lc rgb "black" title "events", \
     "$TMP/events.dat" using 1:2:3 with labels offset 0.8,0.8 left font ",9" noenhanced notitle
GP
echo "wrote $OUT/energy.png $OUT/gas_histogram.png $OUT/shot_path.png"
