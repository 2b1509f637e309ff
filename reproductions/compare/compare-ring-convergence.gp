# compare-ring-convergence: errors against the elastica against N for both methods: the largest relative force error
# over eps = 0.1 ... 0.6 with its least-squares slope (gnuplot's fit, drawn only; the claims fit the same points in
# the manifest), and the width and contact-length errors at eps = 0.3.
set xlabel "vertices N"
set ylabel "error against the elastica"
set logscale xy
set format y "10^{%T}"
set key bottom left
set fit quiet nolog
fs(x) = cs - ps * x
fd(x) = cd - pd * x
cs = 1; ps = 2; cd = 1; pd = 2
fit fs(x) datafile using (column("method_index") == 0 ? log(column("nodes")) : NaN):(log(column("force_error_max"))) via cs, ps
fit fd(x) datafile using (column("method_index") == 1 ? log(column("nodes")) : NaN):(log(column("force_error_max"))) via cd, pd
plot datafile using (column("method_index") == 0 ? column("nodes") : NaN):"force_error_max" ls 1 with points title sprintf("SPD: max_{/Symbol e} |F/F_{el} - 1|, order %.2f", ps), \
     datafile using (column("method_index") == 1 ? column("nodes") : NaN):"force_error_max" ls 2 pt 6 ps 2 with points title sprintf("DPM: max_{/Symbol e} |F/F_{el} - 1|, order %.2f", pd), \
     exp(fs(log(x))) ls 1 lw 1 notitle, exp(fd(log(x))) ls 2 lw 1 dt 3 notitle, \
     datafile using (column("method_index") == 0 ? column("nodes") : NaN):"width_error_eps03" ls 3 with points title "SPD: |a/a_{el} - 1| at {/Symbol e} = 0.3", \
     datafile using (column("method_index") == 0 ? column("nodes") : NaN):"contact_length_error_eps03" lc rgb '#9467bd' pt 13 ps 1.2 with points title "SPD: |L_c - 2c|/b_0 at {/Symbol e} = 0.3", \
     datafile using (column("method_index") == 1 ? column("nodes") : NaN):"contact_length_error_eps03" lc rgb '#9467bd' pt 12 ps 2 with points title "DPM: |L_c - 2c|/b_0 at {/Symbol e} = 0.3"
