# vsm-fig7: deformed shapes of the L-shaped block at the snapshot times of shapes.dat (t = 0, 5, 10, 20, 35,
# 55 s; each the first sample at or after that time), one panel each, particles coloured by their height x3.
file = word(rundirs, 1)."/shapes.dat"
stats file using "t" nooutput
set multiplot layout 2,3
unset key
unset colorbox
set view 60, 30, 1.4
set xyplane at 0
set xrange [-6:12]; set yrange [-4:14]; set zrange [-6:8]
set xtics 5; set ytics 5; set ztics 5
array times[6] = [0, 5, 10, 20, 35, 55]
do for [k = 1:6] {
    if (times[k] <= STATS_max) {
        set title sprintf("t = %g s", times[k])
        splot file using (column("t") > times[k] - 1e-6 && column("t") < times[k] + 1 ? column("x1") : NaN):"x2":"x3":"x3" \
            with points pt 7 ps 0.4 palette
    }
}
unset multiplot
