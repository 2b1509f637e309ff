# spd-fig23: F/F* against L_c/l for eta = 0 and eta = inf, with eqs. (31) and (35).
set xlabel "L_c / l"
set ylabel "F / F*"
set logscale y
set key top left
a = word(rundirs, 1).'/compression.dat'
b = word(rundirs, 2).'/compression.dat'
plot a using (column("loading") == 1 && column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"F_over_Fstar" ls 1 with linespoints title "{/Symbol h} = 0", \
     b using (column("loading") == 1 && column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"F_over_Fstar" ls 2 with linespoints title "{/Symbol h} = {/Symbol \245}", \
     b using (column("loading") == 1 && column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):(column("p_term") * column("Lc_over_l")) ls 4 lc rgb '#d62728' with lines title "eq. (35) with the simulated p", \
     a using (column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"Lc_over_l" ls 4 with lines title "eq. (31)"
