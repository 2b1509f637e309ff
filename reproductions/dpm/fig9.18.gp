# DPM-Fig9.18(a)-(e): snapshots of the first five trials (disks blue, boundary vertices yellow) and theta per
# trial.
d = word(rundirs, 1)
set multiplot
unset key
set size ratio -1
unset xtics
unset ytics
set border 0
set xrange [-1.7:1.7]
set yrange [-1.7:1.7]
do for [k = 0:4] {
  set origin (k % 3) * 0.2, 0.5 - (k / 3) * 0.5
  set size 0.2, 0.5
  set title sprintf("trial %d", k + 1)
  plot d."/snapshots.dat" using (column("trial") == k && column("particle") == 4 ? column("x") : NaN):"y":"radius" \
         with circles fs solid 0.8 noborder lc rgb '#e6b800', \
       d."/snapshots.dat" using (column("trial") == k && column("particle") < 4 ? column("x") : NaN):"y":"radius" \
         with circles fs solid 0.6 lc rgb '#1f77b4'
}
set origin 0.62, 0.05
set size 0.38, 0.9
set size noratio
set border
set xtics
set ytics
set autoscale
set yrange [0:95]
set title "{/Symbol q} of each jammed packing"
set xlabel "trial"
set ylabel "{/Symbol q} (degrees)"
plot d."/packings.dat" using ($1 + 1):"theta" ls 1 with points
unset multiplot
