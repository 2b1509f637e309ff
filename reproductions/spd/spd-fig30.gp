# spd-fig30: the tissue at set-up: Laguerre cells inset by r (grey), their cohesive links (red, two per
# interior interface), the clamped bottom and the pulled top (thick lines).
set size ratio -1
unset key
unset grid
unset xtics
unset ytics
file = word(rundirs, 1).'/snapshot.dat'
links = word(rundirs, 1).'/links.dat'
stats file using "cell" nooutput
n = int(STATS_max) + 1
stats file using (column("snapshot") == 0 ? column("y_over_R") : NaN) nooutput
y_lo = STATS_min
y_hi = STATS_max
stats file using (column("snapshot") == 0 ? column("x_over_R") : NaN) nooutput
x_lo = STATS_min
x_hi = STATS_max
set xrange [x_lo - 0.5:x_hi + 0.5]
set yrange [y_lo - 0.5:y_hi + 1.5]
set title "set-up: cells (sphero-polygons inset by r), links (red); bottom fixed, top pulled"
set arrow 1 from x_lo, y_lo - 0.05 to x_hi, y_lo - 0.05 nohead lw 4 lc rgb '#000000' front
set arrow 2 from x_lo, y_hi + 0.05 to x_hi, y_hi + 0.05 nohead lw 4 lc rgb '#000000' front
set arrow 3 from 0.5 * (x_lo + x_hi), y_hi + 0.1 to 0.5 * (x_lo + x_hi), y_hi + 0.7 lw 3 lc rgb '#000000' front
at(p) = column("snapshot") == 0 && column("cell") == p ? column("x_over_R") : NaN
plot for [p=0:n-1] file using (at(p)):"y_over_R" with filledcurves closed fc rgb '#cccccc' notitle, \
     for [p=0:n-1] file using (at(p)):"y_over_R" with lines lc rgb '#333333' lw 0.8 notitle, \
     links using "x1_over_R":"y1_over_R":(column("x2_over_R") - column("x1_over_R")):(column("y2_over_R") - column("y1_over_R")) with vectors nohead lc rgb "#d62728" lw 2 notitle, \
     links using (0.5 * (column("x1_over_R") + column("x2_over_R"))):(0.5 * (column("y1_over_R") + column("y2_over_R"))) with points pt 7 ps 0.5 lc rgb "#d62728" notitle
