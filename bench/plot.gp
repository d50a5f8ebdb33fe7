# ms/step against body count for both engines, log-log. Called by scripts/bench.sh with
#   gnuplot -e "dir='<folder of the series files>'; out='<png>'; c=<n log n coefficient>" bench/plot.gp
# where each series is <dir>/<scene>-<engine>.dat with lines "bodies median_ms p95_ms".
set terminal pngcairo size 900,600 noenhanced font ",11"
set output out
set title "edyn-bench: ms per 1/60 s step (median; bars to p95), one thread"
set xlabel "dynamic bodies"
set ylabel "ms / step"
set logscale xy
set grid xtics ytics mxtics mytics
set key top left
set style line 1 lc rgb "#1f77b4" lw 2 pt 7
set style line 2 lc rgb "#d62728" lw 2 pt 7
set style line 3 lc rgb "#1f77b4" lw 2 pt 5 dt 2
set style line 4 lc rgb "#d62728" lw 2 pt 5 dt 2
set style line 5 lc rgb "#7f7f7f" lw 1 dt 3
nlogn(x) = c * x * log(x)
plot dir."/pile-edyn.dat" using 1:2 with linespoints ls 1 title "edyn, pile", \
     dir."/pile-bullet.dat" using 1:2 with linespoints ls 2 title "Bullet, pile", \
     dir."/pyramid-edyn.dat" using 1:2 with linespoints ls 3 title "edyn, pyramid", \
     dir."/pyramid-bullet.dat" using 1:2 with linespoints ls 4 title "Bullet, pyramid", \
     dir."/pile-edyn.dat" using 1:2:2:3 with yerrorbars ls 1 notitle, \
     dir."/pile-bullet.dat" using 1:2:2:3 with yerrorbars ls 2 notitle, \
     dir."/pyramid-edyn.dat" using 1:2:2:3 with yerrorbars ls 3 notitle, \
     dir."/pyramid-bullet.dat" using 1:2:2:3 with yerrorbars ls 4 notitle, \
     [1000:20000] nlogn(x) with lines ls 5 title "n log n through edyn's smallest pile"
