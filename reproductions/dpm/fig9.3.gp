# DPM-Fig9.3: slump tests. (a) rough confined, (b) rough released, (c) smooth confined, (d) smooth released;
# particles as filled polygons with their vertex disks; right: free-surface profiles with their linear fits.
rough = word(rundirs, 1)
smooth = word(rundirs, 2)
stats rough."/snapshots.dat" using "particle" nooutput
last = int(STATS_max)
stats rough."/snapshots.dat" using "x" nooutput
xmax = STATS_max
stats smooth."/snapshots.dat" using "x" nooutput
xmax = (STATS_max > xmax ? STATS_max : xmax) + 0.5
stats rough."/snapshots.dat" using "y" nooutput
ymax = STATS_max + 0.5
set multiplot
unset key
set size ratio -1
set border 0
unset xtics
unset ytics
set xrange [-0.5:xmax]
set yrange [-0.2:ymax]
array panels[4] = ["(a) rough, confined", "(b) rough, right wall removed", "(c) smooth, confined", \
                   "(d) smooth, right wall removed"]
do for [k = 0:3] {
  d = k < 2 ? rough : smooth
  frame = k % 2 + 1
  set origin 0, 0.75 - 0.25 * k
  set size 0.68, 0.25
  set size ratio -1
  set title panels[k + 1] noenhanced
  plot for [m = 0:last] d."/snapshots.dat" using (column("frame") == frame && column("particle") == m ? \
         column("x") : NaN):"y" with filledcurves closed fs solid 0.5 lc rgb (k < 2 ? '#d62728' : '#2ca02c'), \
       d."/snapshots.dat" using (column("frame") == frame ? column("x") : NaN):"y":"radius" with circles \
         lc rgb '#333333' lw 0.3, \
       0 lc rgb 'black' lw 2
}
set origin 0.68, 0.05
set size 0.32, 0.9
set size noratio
set border
set xtics
set ytics
set autoscale
set key top right
set title "free surface after the run-out"
set xtics 5
set xlabel "x / D"
set ylabel "height / D"
plot rough."/profile.dat" using "x":"height" with points pt 7 lc rgb '#d62728' title "rough", \
     rough."/profile.dat" using "x":"fit" with lines lc rgb '#d62728' notitle, \
     smooth."/profile.dat" using "x":"height" with points pt 5 lc rgb '#2ca02c' title "smooth", \
     smooth."/profile.dat" using "x":"fit" with lines lc rgb '#2ca02c' notitle
unset multiplot
