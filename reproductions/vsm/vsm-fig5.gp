# vsm-fig5: (left) swinging-cube error against the mean particle spacing, split into the error of the swinging
# mode itself (phase, amplitude) and the rest (other modes excited by the discrete initial state), with a
# slope-2 guide; (right) the local order log(e_k / e_k+1) / log(h_k / h_k+1) between successive resolutions.
set multiplot layout 1,2
set logscale xy
set format y "10^{%T}"
set xlabel "mean particle spacing h [m]"
set ylabel "normalised L2 displacement error at t = 5 ms"
set key top left
set xrange [0.025:0.3]
set yrange [1e-4:0.3]
stats datafile using "spacing":"displacement_error_l2" nooutput
h0 = STATS_max_x; e0 = STATS_max_y
plot e0 * (x / h0)**2 ls 4 title "slope 2", \
     datafile using "spacing":"displacement_error_l2" ls 1 pt 7 with linespoints title "total (eq. (43))", \
     datafile using "spacing":"displacement_error_other_part" ls 2 with linespoints title "other modes", \
     datafile using "spacing":"displacement_error_mode_part" ls 3 with linespoints title "swinging mode (phase)"
unset logscale y
set format y "%g"
set ylabel "local order between successive resolutions"
set yrange [0:4]
set key bottom right
hp = NaN; ep = NaN; mp = NaN; op = NaN
plot 2 ls 4 title "2 (paper: quadratic)", \
     datafile using (h1 = hp, hp = column("spacing"), sqrt(h1 * hp)):(e1 = ep, ep = column("displacement_error_l2"), \
        log(e1 / ep) / log(h1 / hp)) ls 1 pt 7 with linespoints title "total", \
     datafile using (h1 = hp, hp = column("spacing"), sqrt(h1 * hp)):(e1 = op, op = column("displacement_error_other_part"), \
        log(e1 / op) / log(h1 / hp)) ls 2 with linespoints title "other modes", \
     datafile using (h1 = hp, hp = column("spacing"), sqrt(h1 * hp)):(e1 = mp, mp = column("displacement_error_mode_part"), \
        log(e1 / mp) / log(h1 / hp)) ls 3 with linespoints title "swinging mode"
unset multiplot
