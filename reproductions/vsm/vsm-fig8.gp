# vsm-fig8: (left) angular momentum about the origin against time for eq. (43) (run 0) and eq. (41) (run 1), from
# each run's momentum.dat; (right) largest relative changes of linear and angular momentum against round-off.
set multiplot layout 1,2
file43 = word(rundirs, 1)."/momentum.dat"
file41 = word(rundirs, 2)."/momentum.dat"
set xlabel "t [s]"
set ylabel "angular momentum l_i [10^5 kg m^2/s]"
set key center right
plot file43 using "t":(column("l1") / 1e5) ls 1 with lines title "l_1, eq. (43)", \
     file43 using "t":(column("l2") / 1e5) ls 2 with lines title "l_2, eq. (43)", \
     file43 using "t":(column("l3") / 1e5) ls 3 with lines title "l_3, eq. (43)", \
     file41 using "t":(column("l1") / 1e5) ls 1 dt 2 with lines title "l_1, eq. (41)", \
     file41 using "t":(column("l2") / 1e5) ls 2 dt 2 with lines title "l_2, eq. (41)", \
     file41 using "t":(column("l3") / 1e5) ls 3 dt 2 with lines title "l_3, eq. (41)"
set logscale y
set format y "10^{%T}"
set xlabel ""
set ylabel "largest relative change"
set xrange [-0.5:1.5]
set yrange [1e-17:1]
set xtics ("eq. (43)" 0, "eq. (41)/(42)" 1)
set boxwidth 0.3
set style fill solid 0.6
set key top left
plot 2.2e-16 ls 4 title "machine epsilon", \
     datafile using (column("internal_force_id") == 43 ? -0.17 : 0.83):"linear_momentum_drift_relative" with boxes ls 1 \
        title "linear, from t = 0", \
     datafile using (column("internal_force_id") == 43 ? 0.17 : 1.17):"angular_momentum_drift_after_load_relative" \
        with boxes ls 2 title "angular, from t = 5 s"
unset multiplot
