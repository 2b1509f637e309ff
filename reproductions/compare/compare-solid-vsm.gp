# compare-solid-vsm: the VSM ball between two plates (scene vsm.compress_ball). (a) F~ against delta/D at every
# resolution of the sweep (rundirs, in sweep order: the c_pen = 25 runs, then the penalty study) with the
# finite-element neo-Hookean ball (nu = 0.3, data/compare/solid_fe.dat) and Hertz; (b) work-precision: the
# largest |F~/F~_FE - 1| over 0.01 <= delta/D <= 0.2 and the plate-work deficit |1 - W/W_FE| against the wall
# time of one run, labelled by per_radius.
set multiplot layout 1, 2
set key font ",10" spacing 0.9 samplen 2
fe = repo.'/data/compare/solid_fe.dat'
runs = words(rundirs) - 1 # the last run is the penalty study

set title "(a) force"
set xlabel "{/Symbol d}/D"
set ylabel "F (1 - {/Symbol n}^2)/(E D^2)"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set key top left
set yrange [1e-6:0.2]
plot [1e-3:0.3] x**1.5/3 ls 4 lc rgb '#e08000' dt 2 lw 2 with lines title "Hertz, two plates: ({/Symbol d}/D)^{1.5}/3", \
     fe using (column("law_index") == 1 && column("nu") == 0.3 ? column("delta_over_d") : NaN):"F_tilde" ls 4 lc rgb '#000000' with lines title "FE, neo-Hookean, {/Symbol n} = 0.3", \
     for [k = 1 : runs] word(rundirs, k).'/force.dat' using "delta":(column("F_tilde") > 0 ? column("F_tilde") : NaN) ls k with linespoints title sprintf("VSM, sweep run %d (coarse to fine)", k)

set title "(b) work-precision"
set xlabel "wall time per run [s]"
set ylabel "error against the FE ball"
unset format
set format y "10^{%T}"
set yrange [*:*]
set key top right
plot datafile using (column("penalty") == 25 ? column("wall_time_s") : NaN):"fe_error_max" ls 1 with linespoints title "max |F/F_{FE} - 1|, 0.01 {/Symbol \243} {/Symbol d}/D {/Symbol \243} 0.2", \
     datafile using (column("penalty") == 25 ? column("wall_time_s") : NaN):(abs(1 - column("work_ratio_02"))) ls 2 with linespoints title "|1 - W/W_{FE}|, plate work up to {/Symbol d}/D = 0.2", \
     datafile using (column("penalty") == 100 ? column("wall_time_s") : NaN):(abs(1 - column("work_ratio_02"))) ls 2 pt 4 ps 1.5 with points title "|1 - W/W_{FE}| at c_{pen} = 100", \
     datafile using (column("penalty") == 25 ? column("wall_time_s") : NaN):"fe_error_max":(sprintf("%d", column("per_radius"))) with labels offset 0,1 notitle
unset multiplot
