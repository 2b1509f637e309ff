# compare-ring-thin: the ring between the plates as h/R -> 0 at N = 32 (decision compare-ring-thickness). (a) the
# cost: SPD's steps and DPM's FIRE iterations against R/h, with a line ~ R/h through SPD's thickest ring (the ratio
# omega_c/omega_2 of the fastest to the slowest time scale); (b) SPD's compression in ovalisation periods
# (steps dt omega_2 / 2 pi), flat; (c) the largest force error against the elastica and the stretching error
# (h/R)^2/12.
spd(c) = column("method_index") == 0 ? c : NaN
dpm(c) = column("method_index") == 1 ? c : NaN
stats datafile using (spd(1 / column("h_over_R"))):"steps" nooutput
thick_steps = STATS_min_y
thick_R_over_h = STATS_min_x
set multiplot
set key font ",10" spacing 0.9 samplen 2
set logscale x
set xrange [10 : 2000]
set xlabel "R/h"

set origin 0, 0
set size 0.5, 1
set title "(a) cost of the compression to {/Symbol e} = 0.6, N = 32"
set ylabel "SPD steps, DPM FIRE iterations"
set logscale y
set format y "10^{%T}"
set key top left
plot datafile using (spd(1 / column("h_over_R"))):"steps" ls 1 with points title "SPD (0.5 dt_c)", \
     datafile using (dpm(1 / column("h_over_R"))):"steps" ls 2 pt 6 ps 1.5 with points title "DPM (FIRE)", \
     thick_steps * x / thick_R_over_h ls 4 title "slope 1: R/h, as {/Symbol w}_c/{/Symbol w}_2"

set origin 0.5, 0.5
set size 0.5, 0.5
set title "(b) SPD: the compression in ovalisation periods"
set ylabel "steps dt {/Symbol w}_2 / 2{/Symbol p}"
set xlabel ""
unset logscale y
set format y "%g"
set yrange [0 : 30]
set key bottom right
plot datafile using (spd(1 / column("h_over_R"))):"ovalisation_periods" ls 1 with linespoints title "SPD"

set origin 0.5, 0
set size 0.5, 0.5
set title "(c) accuracy: force against the elastica"
set ylabel "error"
set xlabel "R/h"
set logscale y
set format y "10^{%T}"
set yrange [1e-8 : 1]
set key top right
plot datafile using (spd(1 / column("h_over_R"))):"force_error_max" ls 1 with points title "SPD: max_{/Symbol e} |F/F_{el} - 1|", \
     datafile using (dpm(1 / column("h_over_R"))):"force_error_max" ls 2 pt 6 ps 1.5 with points title "DPM", \
     datafile using (spd(1 / column("h_over_R"))):"stretch_over_bending_stiffness" ls 3 with lines title "stretching error (h/R)^2/12"
unset multiplot
