# DPM-Fig9.4: snapshots before and after 20 % uniaxial compression: (a) soft disks (run 1), (b) deformable
# particles (run 2). snapshots.dat: frame 1 = start, 2 = end; particle -1 = box walls.
set multiplot layout 2,2
set size ratio -1
unset key
unset xtics
unset ytics
set border 0
disks = word(rundirs, 1)."/snapshots.dat"
dps = word(rundirs, 2)."/snapshots.dat"
stats disks using (column("frame") == 1 && column("particle") < 0 ? column("x") : NaN) nooutput
set xrange [-1:STATS_max + 1]
set yrange [-1:STATS_max + 1]
do for [fr = 1:2] {
  set title sprintf("(a) soft disks, %s", fr == 1 ? "start (P_0)" : "after 20 %")
  plot disks using (column("frame") == fr && column("particle") >= 0 ? column("x") : NaN):"y":"radius" \
         with circles fs transparent solid 0.35 lc rgb '#1f77b4', \
       disks using (column("frame") == fr && column("particle") < 0 ? column("x") : NaN):"y":"dx":"dy" \
         with vectors nohead lw 2 lc rgb '#000000'
}
do for [fr = 1:2] {
  set title sprintf("(b) deformable particles, %s", fr == 1 ? "start (P_0)" : "after 20 %")
  plot dps using (column("frame") == fr && column("particle") >= 0 ? column("x") : NaN):"y":"radius" \
         with circles fs transparent solid 0.2 noborder lc rgb '#d62728', \
       dps using (column("frame") == fr && column("particle") >= 0 ? column("x") : NaN):"y":"dx":"dy" \
         with vectors nohead lw 1.5 lc rgb '#7f0000', \
       dps using (column("frame") == fr && column("particle") < 0 ? column("x") : NaN):"y":"dx":"dy" \
         with vectors nohead lw 2 lc rgb '#000000'
}
unset multiplot
