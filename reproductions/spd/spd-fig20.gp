# spd-fig20: shapes at eps = 0 ... 0.3 for eta = 0 (left) and eta = inf (right), as filled polygons.
set multiplot layout 1,2
set size ratio -1
set xrange [-1.6:1.6]
set yrange [-1.2:1.2]
set xlabel "x / R"
set ylabel "y / R"
set key bottom center
do for [k = 1:2] {
  f = word(rundirs, k).'/shapes.dat'
  set title (k == 1 ? "{/Symbol h} = 0" : "{/Symbol h} = {/Symbol \245}")
  # Core filled, shell (thickness h = 0.02 R, vertex radius r = h/2) as the dark outline.
  plot for [e in "0 0.1 0.2 0.3"] f using (column("loading") == 1 && abs(column("eps") - e) < 1e-6 ? column("x_over_R") : NaN):"y_over_R" \
       with filledcurves closed fs transparent solid 0.15 title "{/Symbol e} = ".e, \
       for [e in "0 0.1 0.2 0.3"] f using (column("loading") == 1 && abs(column("eps") - e) < 1e-6 ? column("x_over_R") : NaN):"y_over_R" \
       with lines lw 2 lc rgb '#222222' notitle
}
unset multiplot
