# spd-fig32: three snapshots of the tensile loading of the elastic tissue (eps_peak/2, the peak, halfway from the
# peak to failure), each cell filled by its elastic energy W/W0, W0 = (f_n^0)^2/(2 k_n); broken links at the
# end are not drawn here (Fig. 34).
set multiplot layout 1,3
set size ratio -1
unset key
unset grid
unset xtics
unset ytics
set palette defined (0 '#ffffff', 0.25 '#ffffb2', 0.5 '#fd8d3c', 1 '#bd0026')
file = word(rundirs, 1).'/snapshot.dat'
stats file using "cell" nooutput
n = int(STATS_max) + 1
stats file using (column("snapshot") >= 1 && column("snapshot") <= 3 ? column("W_over_W0") : NaN) nooutput
set cbrange [0:STATS_max]
set cblabel "W / W_0"
stats file using "x_over_R" nooutput
x_lo = STATS_min - 0.5
x_hi = STATS_max + 0.5
stats file using (column("snapshot") <= 3 ? column("y_over_R") : NaN) nooutput
y_lo = STATS_min - 0.5
y_hi = STATS_max + 0.5
do for [k=1:3] {
    set autoscale xy # stats of one column obeys the x range
    stats file using (column("snapshot") == k ? column("eps_h") : NaN) nooutput
    eps = STATS_max
    stats file using (column("snapshot") == k ? column("broken_links") : NaN) nooutput
    set title sprintf("{/Symbol e}_h = %.3f, %d links broken", eps, int(STATS_max))
    set xrange [x_lo:x_hi]
    set yrange [y_lo:y_hi]
    at(p) = column("snapshot") == k && column("cell") == p ? column("x_over_R") : NaN
    plot for [p=0:n-1] file using (at(p)):"y_over_R":"W_over_W0" with filledcurves closed fc palette notitle, \
         for [p=0:n-1] file using (at(p)):"y_over_R" with lines lc rgb '#333333' lw 0.6 notitle
}
unset multiplot
