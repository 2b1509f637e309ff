# spd-fig22: L_c/b0 against eps for eta = 0 and eta = inf, with slopes pi/2 and 2.1.
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "L_c / b_0"
set key top left
plot word(rundirs, 1).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"Lc_over_b0" ls 1 with linespoints title "{/Symbol h} = 0", \
     word(rundirs, 2).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"Lc_over_b0" ls 2 with linespoints title "{/Symbol h} = {/Symbol \245}", \
     word(rundirs, 1).'/compression.dat' using "eps":(column("eps") >= 0.25 ? pi/2 * (column("eps") - 0.25) : NaN) ls 4 with lines title "slope {/Symbol p}/2", \
     word(rundirs, 1).'/compression.dat' using "eps":(column("eps") >= 0.25 ? 2.1 * (column("eps") - 0.25) + 0.4 : NaN) ls 4 lc rgb '#d62728' with lines title "slope 2.1 (paper, {/Symbol h} = {/Symbol \245})"
