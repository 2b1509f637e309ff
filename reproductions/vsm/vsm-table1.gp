# vsm-table1: patch-test errors per seed for tests A, B, C (relative), against the round-off level.
set logscale y
set format y "10^{%T}"
set xlabel "seed of the irregular arrangement"
set ylabel "relative error"
set xrange [0.5:3.5]
set yrange [1e-18:1e-6]
set xtics 1
set key top right
plot 2.2e-16 ls 4 title "machine epsilon", \
     2.2e-16 / (alpha * sqrt(6**2 + 15**2 + 24**2)) lc rgb '#888888' dt 3 title "eps (1 m) / max |u| (B, C floor)", \
     datafile using (column("test_id") == 1 ? column("seed") - 0.1 : NaN):"relative_error" ls 1 with points \
        title "A: max |f_a| / (E alpha h^2)", \
     datafile using (column("test_id") == 2 ? column("seed") : NaN):"relative_error" ls 2 with points \
        title "B: max |x_a - x_a^{exact}| / max |u|", \
     datafile using (column("test_id") == 3 ? column("seed") + 0.1 : NaN):"relative_error" ls 3 with points \
        title "C: max |x_a - x_a^{exact}| / max |u|"
