# vsm-fig8: momentum changes of the L-block with eq. (43) and eq. (41), against round-off.
set logscale y
set format y "10^{%T}"
set ylabel "largest relative change"
set xrange [-0.5:1.5]
set yrange [1e-17:1]
set xtics ("eq. (43)" 0, "eq. (41)/(42)" 1)
set boxwidth 0.3
set style fill solid 0.6
set key top left
plot 2.2e-16 ls 4 title "machine epsilon", \
     datafile using (column("internal_force_id") == 43 ? -0.17 : 0.83):"linear_momentum_drift_relative" with boxes ls 1 \
        title "linear momentum, from t = 0", \
     datafile using (column("internal_force_id") == 43 ? 0.17 : 1.17):"angular_momentum_drift_after_load_relative" \
        with boxes ls 2 title "angular momentum, from t = 5 s"
