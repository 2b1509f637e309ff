# vsm-fig5: swinging-cube displacement error against the mean particle spacing, with a slope-2 guide.
set logscale xy
set format y "10^{%T}"
set xlabel "mean particle spacing h [m]"
set ylabel "normalised L2 displacement error at t = 5 ms"
set key bottom right
stats datafile using "spacing":"displacement_error_l2" nooutput
h0 = STATS_max_x; e0 = STATS_max_y
plot e0 * (x / h0)**2 ls 4 title "slope 2", \
     datafile using "spacing":"displacement_error_l2" ls 1 with linespoints title "vsm.swinging\\_cube, eq. (43)"
