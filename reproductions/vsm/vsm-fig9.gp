# vsm-fig9: punch test problem definition: the front layer of particles (21 x 11, spacing 1/21 x 0.5/11 m) in
# the reference configuration, the punch on the middle third of the top face (no slip, moving down at 0.1
# m/s), symmetric walls (rollers) elsewhere, the rest of the top free.
file = word(rundirs, 1)."/snapshots.dat"
unset key
set size ratio -1
set xrange [-0.1:1.1]; set yrange [-0.1:0.7]
set xlabel "X_1 [m]"; set ylabel "X_2 [m]"
set object 1 rect from 1.0/3, 0.5 to 2.0/3, 0.56 fc rgb '#888888' fs solid 0.8
set label 1 "punch, 0.1 m/s, no slip" at 0.5, 0.62 center
set arrow 1 from 0.5, 0.68 to 0.5, 0.57 lw 2
set label 2 "symmetric" at -0.05, 0.25 center rotate by 90
set label 3 "symmetric" at 1.05, 0.25 center rotate by 90
set label 4 "symmetric (and front, back)" at 0.5, -0.05 center
set label 5 "free" at 0.15, 0.53 center
set label 6 "free" at 0.85, 0.53 center
set arrow 2 from 0, 0 to 1, 0 nohead lw 3
set arrow 3 from 0, 0 to 0, 0.5 nohead lw 3
set arrow 4 from 1, 0 to 1, 0.5 nohead lw 3
stats file using "strain" nooutput
plot file using (column("strain") == STATS_min && column("x3") < 0.04 ? column("x1") : NaN):"x2" \
    with points pt 7 ps 1.2 lc rgb '#1f77b4'
