# vsm-cost: error against wall time, one curve per time-step factor; failed runs (exit 3) marked at the top.
set logscale xy
set format y "10^{%T}"
set xlabel "wall time of the run [s] (one core)"
set ylabel "normalised L2 displacement error at t = 30 ms"
set key top right
set yrange [1e-3:2]
plot datafile using (column("cfl") == 0.15 && column("exit_code") == 0 ? column("run_wall_time_s") : NaN):"displacement_error_l2" ls 1 with points title "cfl 0.15", \
     datafile using (column("cfl") == 0.3 && column("exit_code") == 0 ? column("run_wall_time_s") : NaN):"displacement_error_l2" ls 3 with points title "cfl 0.3", \
     datafile using (column("cfl") == 0.45 && column("exit_code") == 0 ? column("run_wall_time_s") : NaN):"displacement_error_l2" ls 4 with points title "cfl 0.45", \
     datafile using (column("exit_code") == 3 ? 1e-2 * column("per_side") : NaN):(1.5) ls 2 with points title "cfl >= 0.6: refused (exit 3), x = n/100"
