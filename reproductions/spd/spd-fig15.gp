# spd-fig15: F/F* against L_c/l, elastic ring, with the elastica and eq. (31).
set xlabel "L_c / l"
set ylabel "F / F*"
set key top left
set logscale y
set yrange [0.01:30]
d = word(rundirs, 1).'/compression.dat'
plot d using (column("loading") == 1 && column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"F_over_Fstar" ls 1 with linespoints title "softgrain, {/Symbol h} = 0", \
     d using (column("elastica_Lc_over_b0") > 0 ? column("elastica_Lc_over_b0") * column("Lc_over_l") / column("Lc_over_b0") + 1 : NaN):"elastica_F_over_Fstar" ls 4 lc rgb '#000000' dt 1 with lines title "elastica, against (2c + l_0)/l_0", \
     d using (column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"Lc_over_l" ls 2 dt 2 with lines title "paper, eq. (31): F/F* = L_c/l"
