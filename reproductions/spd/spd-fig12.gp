# spd-fig12: L_c/b0 against eps, elastic ring, with the elastica flat length and slope pi/2.
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "L_c / b_0"
set key top left
d = word(rundirs, 1).'/compression.dat'
# The paper's onset of faceting (section 4.2): L_c = 0.16 b0 = b0/(2 pi) at eps = 0.25.
set label 1 "paper: faceting from L_c = b_0/2{/Symbol p} at {/Symbol e} = 0.25" at 0.24, 0.16 right
set object 1 circle at 0.25, 0.16 size 0.004 fs solid fc rgb '#000000'
plot d using (column("loading") == 1 ? column("eps") : NaN):"Lc_over_b0" ls 1 with linespoints title "softgrain, L_c = N' l_0", \
     d using "eps":"elastica_Lc_over_b0" ls 4 lc rgb '#000000' dt 1 with lines title "elastica, flat length 2c", \
     d using "eps":(column("eps") >= 0.3 ? pi/2 * (column("eps") - 0.3) + 0.147 : NaN) ls 4 with lines title "slope {/Symbol p}/2 (paper, eq. 28)", \
     d using "eps":(pi/2 * column("eps")) ls 3 lw 1 with lines title "stadium, eq. (28)"
