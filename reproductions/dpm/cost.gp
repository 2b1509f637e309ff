# DPM-cost: wall time of the jamming protocol (left) and of the mode spectrum (right) against the degrees of
# freedom, for more particles (nodes = 10) and more vertices per particle (particles = 8), before (FIRE alone,
# every mode dense; lowest_modes = 0) and after (the Newton finisher, the 20 lowest modes by Lanczos;
# lowest_modes = 20). Each series with its least-squares power law t = A n^b, b in the key.
set logscale xy
set format y "10^{%T}"
set key top left font ",9"
set fit quiet nolog
series(c, grow, after) = \
    (grow == 0 ? column("nodes") == 10 : column("particles") == 8) && \
    (after ? column("lowest_modes") > 0 : column("lowest_modes") == 0) ? column(c) : 1/0
# The power law of one series: fit ln t = ln A + b ln n, then define the line and its slope.
line(x, a, b) = exp(a) * x**b
set multiplot layout 1, 2
do for [panel = 1:2] {
    quantity = panel == 1 ? "jam_seconds" : "spectrum_seconds"
    set title (panel == 1 ? "jamming (dpm.jam protocol)" : "spectrum (eq. 9.28)")
    set xlabel "degrees of freedom 2 {/Symbol S} N_{/Symbol m}"
    set ylabel "wall time (s), one core"
    array A[4]
    array B[4]
    do for [k = 1:4] {
        grow = (k - 1) % 2
        after = (k - 1) / 2
        stats datafile using (series(quantity, grow, after)) nooutput
        A[k] = NaN
        B[k] = NaN
        if (STATS_records >= 3) { # two sizes fit any power law exactly (smoke has one or two)
            offset = 1
            slope = 1
            fit offset + slope * x datafile using (log(column("degrees_of_freedom"))):(log(series(quantity, grow, after))) \
                via offset, slope
            A[k] = offset
            B[k] = slope
        }
    }
    plot for [k = 1:4] datafile using "degrees_of_freedom":(series(quantity, (k - 1) % 2, (k - 1) / 2)) \
             ls ((k - 1) % 2 + 1) pt ((k - 1) / 2 == 0 ? 7 : 6) notitle, \
         for [k = 1:4] line(x, A[k], B[k]) ls ((k - 1) % 2 + 1) dashtype 1 + (k - 1) / 2 \
             title sprintf("%s, more %s: %s", (k - 1) / 2 == 0 ? "before" : "after", \
                           (k - 1) % 2 == 0 ? "particles" : "vertices", \
                           B[k] == B[k] ? sprintf("slope %.2f", B[k]) : "below three sizes, no fit")
}
unset multiplot
