# spd-fig11: a/b0 against eps, elastic ring, with the elastica, eq. (26) and eq. (27).
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "a / b_0"
set key top left
d = word(rundirs, 1).'/compression.dat'
plot d using (column("loading") == 1 ? column("eps") : NaN):"a_over_b0" ls 1 with linespoints title "softgrain, {/Symbol h} = 0", \
     d using "eps":"elastica_a_over_b0" ls 4 lc rgb '#000000' dt 1 with lines title "elastica (our reference)", \
     d using "eps":"ellipse_a_over_b0" ls 2 lw 1 with lines title "ellipse, eq. (26)", \
     d using "eps":(1 + (pi/2 - 1) * column("eps")) ls 3 lw 1 with lines title "stadium, eq. (27)"
