# spd-fig7ab: equilibrium shapes of the 9-node beams (8 elements), (a) cantilever, (b) simply supported, drawn as
# chains of sphero-segments (nodes as disks); deflection normalised by delta_max and drawn at 0.3 L, with the
# point-load theory (line) and the load (arrow).
set multiplot layout 2,1 margins 0.05,0.97,0.08,0.94 spacing 0,0.1
set xrange [-0.08:1.08]
set yrange [-0.52:0.12]
unset xlabel
unset ytics
set key bottom left
mag = 0.3
cb = word(rundirs, 1).'/profile.dat'
ss = word(rundirs, 2).'/profile.dat'
set title "(a) cantilever, 9 nodes: deflection / {/Symbol d}_{max} x 0.3 L"
set object 1 rect from -0.06, -0.1 to 0, 0.1 fc rgb '#999999' fs pattern 2 border lc rgb '#444444'
set arrow 1 from 1, 0.1 to 1, -mag - 0.01 head filled lw 2 lc rgb '#000000' front
plot cb using "x_over_L":(-mag * column("theory")) with lines ls 4 title "eq. (14)", \
     cb using "x_over_L":(-mag * column("delta_over_max")) with lines lw 5 lc rgb '#1f77b4' title "softgrain (sphero-segments)", \
     cb using "x_over_L":(-mag * column("delta_over_max")) with points pt 7 ps 1.6 lc rgb '#1f77b4' notitle
unset object 1
unset arrow 1
set xlabel "x / L"
set title "(b) simply supported, 9 nodes: deflection / {/Symbol d}_{max} x 0.3 L"
set object 2 polygon from 0, 0 to -0.03, -0.06 to 0.03, -0.06 to 0, 0 fc rgb '#999999' fs solid
set object 3 polygon from 1, 0 to 0.97, -0.06 to 1.03, -0.06 to 1, 0 fc rgb '#999999' fs solid
set arrow 2 from 0.5, 0.1 to 0.5, -mag - 0.01 head filled lw 2 lc rgb '#000000' front
plot ss using "x_over_L":(-mag * column("theory")) with lines ls 4 title "3{/Symbol x} - 4{/Symbol x}^3 (point load)", \
     ss using "x_over_L":(-mag * column("delta_over_max")) with lines lw 5 lc rgb '#d62728' title "softgrain (sphero-segments)", \
     ss using "x_over_L":(-mag * column("delta_over_max")) with points pt 7 ps 1.6 lc rgb '#d62728' notitle
unset multiplot
