# spd-fig25: F/F* against eps for eta = 0 and eta = inf.
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "F / F*"
set logscale y
set key top left
plot word(rundirs, 1).'/compression.dat' using (column("loading") == 1 && column("eps") > 0 ? column("eps") : NaN):"F_over_Fstar" ls 1 with linespoints title "{/Symbol h} = 0", \
     word(rundirs, 1).'/compression.dat' using (column("eps") > 0 ? column("eps") : NaN):"elastica_F_over_Fstar" ls 4 lc rgb '#000000' dt 1 with lines title "elastica, {/Symbol h} = 0", \
     word(rundirs, 2).'/compression.dat' using (column("loading") == 1 && column("eps") > 0 ? column("eps") : NaN):"F_over_Fstar" ls 2 with linespoints title "{/Symbol h} = {/Symbol \245}"
