# compare-ring-work-precision: largest relative error of F against the elastica (eps = 0.1 ... 0.6) against the
# wall time of the run, one curve per method and time step (the manifest's sweeps keep each curve's rows together),
# points labelled by N.
set xlabel "wall time per run [s]"
set ylabel "max_{/Symbol e} |F/F_{elastica} - 1|"
set logscale xy
set format y "10^{%T}"
set key bottom left
plot datafile using (column("method_index") == 0 && column("dt_factor") == 0.5 ? column("wall_time_s") : NaN):"force_error_max" ls 1 with linespoints title "SPD (damped velocity Verlet, dt = 0.5 dt_c)", \
     datafile using (column("method_index") == 0 && column("dt_factor") == 0.7 ? column("wall_time_s") : NaN):"force_error_max" ls 3 with linespoints title "SPD, dt = 0.7 dt_c", \
     datafile using (column("method_index") == 1 ? column("wall_time_s") : NaN):"force_error_max" ls 2 with linespoints title "DPM (FIRE)", \
     datafile using "wall_time_s":"force_error_max":(sprintf("%d", column("nodes"))) with labels offset 0,1 notitle
