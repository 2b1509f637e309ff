# Fixed-step GSL steppers on sd.approach: outcome against dt max_h |d(dh/dt)/dh| (the max over the path is in the
# summary of every completed run). Completed runs: their error of h(t); stopped runs (exit 3, with a diagnosis):
# crosses at the top. Rows come in the order of the manifest sweep: stepper outer, dt inner; `steppers` below
# must list the manifest's steppers in the same order.
steppers = "rk2 rk4 rkf45 rk2imp rk4imp bsimp"
colors = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #17becf"
stats datafile using (column("exit_code") == 0 ? column("gap_rate_derivative_max") : 1/0) nooutput
rate = STATS_max
stats datafile using (column("dt")) nooutput
per_stepper = STATS_records / words(steppers)
set logscale xy
set format y "10^{%T}"
set xlabel "dt  max_h |d(dh/dt)/dh|"
set ylabel "max relative error of h(t)"
set key outside right
set yrange [1e-8:100]
set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc rgb '#888888'
plot for [i=1:words(steppers)] datafile using (int($0/per_stepper) == i-1 && column("exit_code") == 0 ? column("dt")*rate : NaN):(column("h_error_max")) \
        with linespoints lw 2 pt (i <= 3 ? 7 : 5) lc rgb word(colors, i) title (word(steppers, i) . (i <= 3 ? " (explicit)" : " (implicit)")), \
     for [i=1:words(steppers)] datafile using (int($0/per_stepper) == i-1 && column("exit_code") == 3 ? column("dt")*rate : NaN):(10.0 * 1.4**(i-1)) \
        with points pt 2 ps 2 lw 2 lc rgb word(colors, i) notitle, \
     1/0 with points pt 2 ps 2 lw 2 lc rgb '#000000' title "x: stopped, exit 3 (diagnosed)"
