# spd-fig13: V/V0 against eps, elastic ring, with the elastica and eq. (29).
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "V / V_0"
set key bottom left
d = word(rundirs, 1).'/compression.dat'
plot d using (column("loading") == 1 ? column("eps") : NaN):"V_over_V0" ls 1 with points title "softgrain, {/Symbol h} = 0", \
     d using "eps":"elastica_V_over_V0" ls 4 lc rgb '#000000' dt 1 with lines title "elastica (our reference)", \
     d using "eps":(1 - column("eps")**2) ls 2 lw 1 dt 2 with lines title "stadium, eq. (29): 1 - {/Symbol e}^2"
