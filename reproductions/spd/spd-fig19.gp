# spd-fig19: V/V0 against eps, plastic vs elastic ring; shapes after unloading and release.
set multiplot layout 1,2
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "V / V_0"
set key bottom left
plot word(rundirs, 1).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 1 with linespoints title "elastic", \
     word(rundirs, 2).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 2 with linespoints title "plastic, M^Y/M* = 5x10^{-5}", \
     word(rundirs, 1).'/compression.dat' using "eps":(1 - column("eps")**2) ls 4 with lines title "eq. (29)"
set size ratio -1
set xlabel "x / R"
set ylabel "y / R"
set xrange [-1.5:1.5]
set yrange [-1.5:1.5]
set key top right
plot word(rundirs, 1).'/shapes.dat' using (column("eps") == -1 ? column("x_over_R") : NaN):"y_over_R" with filledcurves closed fs transparent solid 0.3 lc rgb '#1f77b4' title "elastic, released", \
     word(rundirs, 2).'/shapes.dat' using (column("eps") == -1 ? column("x_over_R") : NaN):"y_over_R" with filledcurves closed fs transparent solid 0.3 lc rgb '#d62728' title "plastic, released", \
     for [k = 1:2] word(rundirs, k).'/shapes.dat' using (column("eps") == -1 ? column("x_over_R") : NaN):"y_over_R" with lines lw 2 lc rgb '#222222' notitle
unset multiplot
