# compare-vsm-incompressible: VSM's swinging cube as nu -> 1/2, against 1 - 2 nu. (a) the stability map (runs to
# 0.1 s, check off): dt over the predicted limit 0.55 L_min / c_eff, completed or stopped with exit 3, with the
# linearised band 2/omega_max (decision time-step-limit); (b) steps per ms at cfl = 0.3 against c_p; (c) the
# displacement error at 5 ms. dt/prediction = cfl c_eff / (0.55 c_p), with c_eff/c_p = sqrt(1 + xi E/M), xi = 1
# and M/E = (1 - nu)/((1 + nu)(1 - 2 nu)): exact for every run, completed or not.
over_prediction(cfl, nu) = cfl / (0.55 * sqrt(1 / (1 + (1 + nu) * (1 - 2 * nu) / (1 - nu))))
stability(c) = column("end_time") > 0.05 ? c : NaN
cost(c) = column("end_time") < 0.05 ? c : NaN
# c_p at nu = (1 - x)/2 relative to c_p at nu = 0.3 (x = 0.4): M(x)/E = (1 + x)/((3 - x) x).
cp_ratio(x) = sqrt((1 + x) / ((3 - x) * x) / (1.4 / (2.6 * 0.4)))
stats datafile using (cost(column("nu")) == 0.3 ? column("steps") / (column("end_time") * 1e3) : NaN) nooutput
steps_per_ms_03 = STATS_max
set multiplot
set key font ",10" spacing 0.9 samplen 2
set logscale x
set xrange [1e-4 : 1]
set format x "10^{%T}"
set xlabel "1 - 2{/Symbol n}"

set origin 0, 0
set size 0.5, 1
set title "(a) stability, to t = 0.1 s with the check off"
set ylabel "dt / (0.55 L_{min} / c_{eff})"
set yrange [0.8 : 2.7]
set key top left
plot 1.382 with filledcurves y1 = 1.782 fc rgb '#dddddd' fs solid 0.6 noborder title "2/{/Symbol w}_{max} of the linearised lattices", \
     datafile using (stability(column("exit_code")) == 0 ? 1 - 2 * column("nu") : NaN):(over_prediction(column("cfl"), column("nu"))) ls 3 pt 7 ps 1.2 with points title "completed", \
     datafile using (stability(column("exit_code")) == 3 ? 1 - 2 * column("nu") : NaN):(over_prediction(column("cfl"), column("nu"))) ls 2 pt 2 ps 1.5 lw 2 with points title "stopped, exit 3", \
     1 ls 4 title "prediction (check on: refused above)"

set origin 0.5, 0.5
set size 0.5, 0.5
set title "(b) cost at cfl = 0.3"
set ylabel "steps per ms"
set xlabel ""
set logscale y
set yrange [*:*]
set format y "%g"
set key top right
plot datafile using (cost(1 - 2 * column("nu"))):(column("steps") / (column("end_time") * 1e3)) ls 1 with points title "steps / ms", \
     steps_per_ms_03 * cp_ratio(x) ls 4 title "steps at 0.3 times c_p({/Symbol n})/c_p(0.3)", \
     datafile using (cost(1 - 2 * column("nu"))):(column("wall_time_s") * 1e3) ls 2 pt 5 with points title "wall time [ms]"

set origin 0.5, 0
set size 0.5, 0.5
set xlabel "1 - 2{/Symbol n}"
set title "(c) accuracy at t = 5 ms"
set ylabel "L2 error vs eq. (53)"
unset logscale y
set yrange [0 : *]
set key bottom left
plot datafile using (cost(1 - 2 * column("nu"))):"displacement_error_l2" ls 1 with linespoints title "displacement error", \
     datafile using (cost(1 - 2 * column("nu"))):"displacement_error_mode_part" ls 3 with linespoints title "swinging-mode part"
unset multiplot
