# SPDX-License-Identifier: MIT
# Pareto plot of the speed-for-accuracy trade: worst and median error
# relative to each body's velocity scale against median ns per collision.
# Called by bench.mk with datafile and outfile set (columns: see plot_data
# in bench.c).
set terminal pngcairo size 1100,720 font ",10" noenhanced
set output outfile
set logscale xy
set format y "1e%L"
set xlabel "ns per collision (median, 4096 in-cache pairs, impacts, e = 1)"
set ylabel "error relative to the body's velocity scale"
set title "collide2d: speed-for-accuracy trade (lower left is better)"
set grid
set key bottom right box opaque
set yrange [1e-18:1e3]
set xrange [2:5000]
set arrow from graph 0, first 2.2e-16 to graph 1, first 2.2e-16 nohead dt 2 lc rgb "gray"
set label "1 ulp of double" at graph 0.01, first 4e-16 tc rgb "gray"
set arrow from graph 0, first 1.2e-7 to graph 1, first 1.2e-7 nohead dt 2 lc rgb "gray"
set label "1 ulp of float" at graph 0.01, first 2.2e-7 tc rgb "gray"
set arrow from graph 0, first 100 to graph 1, first 100 nohead dt 3 lc rgb "red"
set label "fails: NaN / Inf / O(1) error" at graph 0.01, first 200 tc rgb "red"
plot datafile using 2:5 with points pt 9 ps 1.6 lc rgb "red" title "worst error, extreme inputs", \
     datafile using 2:3 with points pt 7 ps 1.5 lc rgb "dark-violet" title "worst error, plain inputs", \
     datafile using 2:4 with points pt 6 ps 1.2 lc rgb "dark-green" title "median error, plain inputs", \
     datafile using 2:($3*$6):1 with labels left offset char 1,0 font ",9" notitle
