# Speed-up of edyn's multithreaded step against threads. Called by scripts/bench.sh --scaling with
#   gnuplot -e "dir='<folder of the series files>'; out='<png>'; cores=<cores>" bench/scaling.gp
# where <dir>/pile-<bodies>.dat has lines "threads speed-up".
set terminal pngcairo size 900,600 noenhanced font ",11"
set output out
set title sprintf("edyn-bench pile: speed-up of sequential_multithreaded over one thread (%d cores)", cores)
set xlabel "threads"
set ylabel "speed-up"
set logscale x 2
set xrange [0.9:cores * 1.1]
set yrange [0:*]
set grid xtics ytics
set key top left
set style line 1 lc rgb "#1f77b4" lw 2 pt 7
set style line 2 lc rgb "#2ca02c" lw 2 pt 5
set style line 3 lc rgb "#7f7f7f" lw 1 dt 3
plot dir."/pile-4096.dat" using 1:2 with linespoints ls 1 title "pile, 4,096 bodies", \
     dir."/pile-16384.dat" using 1:2 with linespoints ls 2 title "pile, 16,384 bodies", \
     x with lines ls 3 title "linear"
