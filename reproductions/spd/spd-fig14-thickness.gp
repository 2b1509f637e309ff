# spd-fig14-thickness: W_s/W_b against eps for h = 0.01, 0.02, 0.04 R, rescaled to h = 0.02 R by the expected
# power of h: (h/0.02)^2 for eta = inf (W_s/W_b ~ h^-2), (0.02/h)^2 for eta = 0 (W_s/W_b ~ h^2).
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "W_s / W_b, rescaled to h = 0.02 R"
set logscale y
set format y "10^{%T}"
set key center right
h(i) = 0.01 * 2**((i - 1) % 3)
scale(i) = i <= 3 ? (0.02 / h(i))**2 : (h(i) / 0.02)**2
series_title(i) = (i <= 3 ? "{/Symbol h} = 0" : "{/Symbol h} = {/Symbol \245}").sprintf(", h = %.2f R", h(i))
file(i) = word(rundirs, i).'/compression.dat'
eps_loading = '(column("loading") == 1 ? column("eps") : NaN)'
plot for [i=1:3] file(i) using @eps_loading:(column("Ws_over_Wb") * scale(i)) \
         with linespoints ls i dashtype 2 title series_title(i), \
     for [i=4:6] file(i) using @eps_loading:(column("Ws_over_Wb") * scale(i)) \
         with linespoints ls (i - 3) title series_title(i)
