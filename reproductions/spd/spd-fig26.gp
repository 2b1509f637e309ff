# spd-fig26: the sample during loading (eta = 0, elastic): at the first contact of the top wall (H0), at a third
# and two thirds of the loading strain and at its end; particles filled grey, the top wall as a thick line.
set multiplot layout 1,4
set size ratio -1
unset key
unset grid
unset xtics
unset ytics
file = word(rundirs, 1).'/snapshot.dat'
stats file using "particle" nooutput
n = int(STATS_max) + 1
stats file using "snapshot" nooutput
snapshots = int(STATS_max) + 1
stats file using "x_over_R" nooutput
x_lo = STATS_min
x_hi = STATS_max
stats file using "H_over_R" nooutput
set xrange [x_lo - 0.2:x_hi + 0.2]
set yrange [-0.2:STATS_max + 0.3]
do for [k=0:snapshots-1] {
    stats file using (column("snapshot") == k ? column("eps") : NaN) nooutput
    set title sprintf("{/Symbol e} = ln(H_0/H) = %.2f", STATS_max)
    stats file using (column("snapshot") == k ? column("H_over_R") : NaN) nooutput
    H = STATS_max
    at(p) = column("snapshot") == k && column("particle") == p ? column("x_over_R") : NaN
    set arrow 1 from x_lo, H to x_hi, H nohead lw 4 lc rgb '#000000' front
    plot for [p=0:n-1] file using (at(p)):"y_over_R" with filledcurves closed fc rgb '#bbbbbb' notitle, \
         for [p=0:n-1] file using (at(p)):"y_over_R" with lines lc rgb '#333333' lw 0.8 notitle
}
unset multiplot
