# spd-fig14: W_s/W_b against eps for eta = 0 and eta = inf.
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "W_s / W_b"
set logscale y
set format y "10^{%T}"
set key top left
plot word(rundirs, 1).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"Ws_over_Wb" ls 1 with linespoints title "{/Symbol h} = 0", \
     word(rundirs, 2).'/compression.dat' using (column("loading") == 1 ? column("eps") : NaN):"Ws_over_Wb" ls 2 with linespoints title "{/Symbol h} = {/Symbol \245}"
