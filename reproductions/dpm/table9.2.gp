# DPM-Table9.2 / Fig. 9.12(a): the packing (polygons and vertex disks, sigma = 1) with its periodic images.
d = word(rundirs, 1)."/vertices.dat"
stats d using "L" nooutput
L = STATS_max
set size ratio -1
set xrange [-0.1*L:1.1*L]
set yrange [-0.1*L:1.1*L]
set xlabel "x / {/Symbol s}"
set ylabel "y / {/Symbol s}"
set key off
set object 1 rect from 0,0 to L,L fs empty border lc rgb 'black' lw 2 front
stats datafile using "phi_analytic" nooutput
phi_a = STATS_max
stats datafile using "phi_monte_carlo" nooutput
phi_mc = STATS_max
stats datafile using "phi_monte_carlo_error" nooutput
set title sprintf("{/Symbol f} = %.4f (eqs. 9.18-9.22),  Monte-Carlo %.4f {/Symbol \261} %.4f", phi_a, phi_mc, STATS_max)
stats d using "particle" nooutput
P = int(STATS_max)
disk(i, j) = (column("closing") == 0 ? column("x") + i*L : NaN)
plot for [i=-1:1] for [j=-1:1] d using (disk(i, j)):(column("y") + j*L):(0.5) \
        with circles fs transparent solid 0.5 noborder lc rgb (i == 0 && j == 0 ? '#1f77b4' : '#aaaaaa'), \
     for [k=0:P] for [i=-1:1] for [j=-1:1] d using (column("particle") == k ? column("x") + i*L : NaN):(column("y") + j*L) \
        with lines lc rgb 'black' lw 1
