# Speed-up of edyn's multithreaded step against threads. Called by scripts/bench.sh --scaling with
#   gnuplot -e "out='<png>'; cores=<cores>; piles=\"<plot clauses, one per pile>\"" bench/scaling.gp
# where each clause plots a file of lines "threads speed-up".
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
eval("plot ".piles.", x with lines lc rgb '#7f7f7f' dt 3 title 'linear'")
