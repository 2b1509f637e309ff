# spd-fig21: V/V0 against eps for eta = 0, the paper's eta = 1e5 (penalty, eq. (4)) and eta = inf (constraint).
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "V / V_0"
set key bottom left
plot word(rundirs, 1).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 1 with linespoints title "{/Symbol h} = 0", \
     word(rundirs, 2).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 3 with linespoints title "{/Symbol h} = 10^5 (eq. (4))", \
     word(rundirs, 3).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 2 with lines title "{/Symbol h} = {/Symbol \245} (area constraint)", \
     word(rundirs, 1).'/compression.dat' using "eps":(1 - column("eps")**2) ls 4 with lines title "eq. (29)"
