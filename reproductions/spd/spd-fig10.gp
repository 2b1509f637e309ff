# spd-fig10: snapshots of the compression-decompression cycle of a ring with an incompressible core (eta = inf):
# row 1 purely elastic, row 2 plastic (M^Y/M* = 5e-5). Columns: loading eps = 0, 0.2, 0.35, unloading 0.2, 0,
# and after release. Core filled, shell (thickness h = 0.02 R) drawn as the dark outline, walls as grey bars.
set multiplot layout 2,6 margins 0.03,0.99,0.04,0.92 spacing 0.01,0.06
set size ratio -1
set xrange [-1.5:1.5]
set yrange [-1.25:1.25]
unset xtics
unset ytics
unset grid
unset key
r = 0.01 # vertex radius r = h/2 over R
eps_of(j) = j == 1 ? 0 : j == 2 ? 0.2 : j == 3 ? 0.35 : j == 4 ? 0.2 : j == 5 ? 0 : -1
loading_of(j) = j <= 3 ? 1 : 0
label_of(j) = j <= 3 ? sprintf("loading {/Symbol e} = %g", eps_of(j)) : j <= 5 ? sprintf("unloading {/Symbol e} = %g", eps_of(j)) : "released"
do for [k = 1:2] {
  f = word(rundirs, k).'/shapes.dat'
  do for [j = 1:6] {
    e = eps_of(j)
    w = e < 0 ? 1.1 + r : 1 - e + r
    set title (j == 1 ? (k == 1 ? "elastic  " : "plastic  ") : "").label_of(j) font ",9"
    set object 1 rect from -1.5, w to 1.5, w + 0.05 fc rgb '#999999' fs solid noborder
    set object 2 rect from -1.5, -w - 0.05 to 1.5, -w fc rgb '#999999' fs solid noborder
    plot f using ((abs(column("eps") - e) < 1e-6 && (e < 0 || column("loading") == loading_of(j))) ? column("x_over_R") : NaN):"y_over_R" \
           with filledcurves closed fs solid 0.35 lc rgb (k == 1 ? '#1f77b4' : '#d62728'), \
         f using ((abs(column("eps") - e) < 1e-6 && (e < 0 || column("loading") == loading_of(j))) ? column("x_over_R") : NaN):"y_over_R" \
           with lines lw 2 lc rgb '#222222'
  }
}
unset multiplot
