# compare-solid-work-precision: largest relative deviation of F~ from the finite-element ball over
# 0.01 <= delta~ <= 0.2 against the wall time of one run, one curve per method (the manifest's sweeps keep each
# curve's rows together), points labelled by resolution (surface vertices N or network nodes).
set xlabel "wall time per run [s]"
set ylabel "max |F/F_{FE} - 1| over 0.01 {/Symbol \243} {/Symbol d}/D {/Symbol \243} 0.2"
set logscale xy
set key top right
plot datafile using (column("method_index") == 0 ? column("wall_time_s") : NaN):"fe_error_max" ls 1 with linespoints title "DPM elastic tetrahedra vs FE Saint Venant-Kirchhoff, {/Symbol n} = 0.3", \
     datafile using (column("method_index") == 1 ? column("wall_time_s") : NaN):"fe_error_max" ls 2 with linespoints title "DPM spring network vs FE Saint Venant-Kirchhoff, {/Symbol n} = 1/4", \
     datafile using "wall_time_s":"fe_error_max":(sprintf("%d", column("vertices"))) with labels offset 0,1 notitle
