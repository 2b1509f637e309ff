# spd-work-precision: errors against the elastica versus wall time, labelled by N.
set xlabel "wall time [s]"
set ylabel "largest deviation from the elastica (eps <= 0.3)"
set logscale xy
set format y "10^{%T}"
set key bottom left
plot datafile using "wall_time_s":"elastica_force_error_max" ls 1 with points title "wall force F (relative)", \
     datafile using "wall_time_s":"elastica_width_error_max" ls 2 with points title "a/b_0 (relative)", \
     datafile using "wall_time_s":"elastica_volume_error_max" ls 3 with points title "V/V_0 (absolute)", \
     datafile using "wall_time_s":"elastica_force_error_max":(sprintf("N=%d", column("nodes"))) with labels offset 0,1 notitle, \
     0.01 ls 4 title "1%"
