# vsm-stability: where VSM fails, on the punch test. (a) time step over the predicted limit (check off):
# completed (0) or stopped with J <= 0 (3); (b) non-affine ratio against xi; (c) pressure roughness against nu;
# (d) punch depth: completed or stopped with J <= 0; (e, f) front-layer pressure at nu = 0.3 and 0.499.
set multiplot layout 2,3
set tics font ",9"
set key font ",9"
set key center right
# (a) dt / limit of each run: cfl times the ratio seen in the completed runs (failed runs write no summary).
stats datafile using (column("time_step_check") == 0 ? column("dt_over_limit") / column("cfl") : NaN) nooutput
ratio = STATS_mean
set xlabel "dt / predicted limit (0.55 L_{min} / c_{eff})"
set ylabel "exit code (3: J <= 0)"
set yrange [-0.5:3.5]
set arrow 1 from 1, graph 0 to 1, graph 1 nohead dt 2
plot datafile using (column("time_step_check") == 0 && column("exit_code") == 0 ? column("cfl") * ratio : NaN):"exit_code" \
        ls 1 pt 7 ps 1.5 title "completed", \
     datafile using (column("time_step_check") == 0 && column("exit_code") == 3 ? column("cfl") * ratio : NaN):"exit_code" \
        ls 2 pt 5 ps 1.5 title "J <= 0", \
     datafile using (column("time_step_check") == 1 && column("cfl") != 0.3 ? column("cfl") * ratio : NaN):"exit_code" \
        ls 3 pt 9 ps 1.5 title "refused (check on)"
unset arrow 1
set autoscale y
set key top right
set xlabel "contact stabilisation xi"
set ylabel "non-affine bond displacement ratio"
plot datafile using "xi":"nonaffine_ratio_final" ls 1 pt 7 with linespoints title "nu = 0.45"
set key top left
set xlabel "Poisson ratio nu"
set xtics 0.05
set ylabel "pressure roughness"
plot datafile using "nu":"pressure_roughness_final" ls 2 pt 7 with linespoints title "xi = 1"
set xtics 0.2
set xlabel "punch depth / height"
set ylabel "exit code (3: J <= 0)"
set yrange [-0.5:3.5]
plot datafile using (column("time_step_check") == 1 && column("cfl") == 0.3 ? column("final_strain") : NaN):"exit_code" ls 2 pt 7 ps 1.5 \
        title "nu = 0.45, xi = 1"
set autoscale y
# (e, f) pressure snapshots: the runs of the nu scan are found by their parameters line.
files = ""
do for [d in rundirs] { files = files." ".d."/snapshots.dat" }
low = system("grep -l '\"nu\":0.3,' ".files." 2>/dev/null | head -1")
high = system("grep -l '\"nu\":0.499,' ".files." 2>/dev/null | head -1")
unset key
set xtics 0.25
set ytics 0.25
set xlabel "x_1 [m]"
set ylabel "x_2 [m]"
set size ratio -1
set cblabel "pressure [kPa]"
set palette defined (0 "blue", 1 "white", 2 "red")
stats high using "strain" nooutput
last = STATS_max
set title "front layer, nu = 0.3"
plot low using (column("strain") == last && column("x3") < 0.04 ? column("x1") : NaN):"x2":(column("pressure") / 1e3) \
        with points pt 7 ps 1 palette title "nu = 0.3"
set title "front layer, nu = 0.499"
plot high using (column("strain") == last && column("x3") < 0.04 ? column("x1") : NaN):"x2":(column("pressure") / 1e3) \
        with points pt 7 ps 1 palette title "nu = 0.499"
unset multiplot
