# spd-fig34: the fractured tissues at the end of the runs, (a) elastic and (b) plastic cells, filled by W/W0, with
# the broken links (red).
set multiplot layout 1,2
set size ratio -1
unset key
unset grid
unset xtics
unset ytics
set palette defined (0 '#ffffff', 0.25 '#ffffb2', 0.5 '#fd8d3c', 1 '#bd0026')
set cblabel "W / W_0"
labels = "'(a) elastic cells' '(b) plastic cells'"
do for [k=1:2] {
    file = word(rundirs, k).'/snapshot.dat'
    broken = word(rundirs, k).'/broken.dat'
    stats file using "cell" nooutput
    n = int(STATS_max) + 1
    stats file using (column("snapshot") == 4 ? column("W_over_W0") : NaN) nooutput
    set cbrange [0:STATS_max > 0 ? STATS_max : 1]
    stats file using (column("snapshot") == 4 ? column("eps_h") : NaN) nooutput
    set title sprintf("%s, {/Symbol e}_h = %.3f", word(labels, k), STATS_max)
    set autoscale xy
    at(p) = column("snapshot") == 4 && column("cell") == p ? column("x_over_R") : NaN
    plot for [p=0:n-1] file using (at(p)):"y_over_R":"W_over_W0" with filledcurves closed fc palette notitle, \
         for [p=0:n-1] file using (at(p)):"y_over_R" with lines lc rgb '#333333' lw 0.6 notitle, \
         broken using "x1_over_R":"y1_over_R":(column("x2_over_R") - column("x1_over_R")):(column("y2_over_R") - column("y1_over_R")) with vectors nohead lc rgb '#d62728' lw 2 notitle
}
unset multiplot
