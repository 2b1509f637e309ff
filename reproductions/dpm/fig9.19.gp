# DPM-Fig9.19: (a) the starred configuration of smooth shells (Fig. 9.8d); (e) mu_eff with the shapes frozen
# and mu translated, against r_{beta r, mu t}.
set multiplot layout 1,2
d = word(rundirs, 1)
set title "(a) configuration at the maximum (star)"
set size ratio -1
set xlabel "x / {/Symbol s}"
set ylabel "y / {/Symbol s}"
unset key
plot d."/star_shape.dat" using "x":(column("particle") == 0 ? column("y") : NaN) ls 1 with linespoints, \
     d."/star_shape.dat" using "x":(column("particle") == 1 ? column("y") : NaN) ls 2 with linespoints
set title "(e) {/Symbol m}_{eff}, shapes frozen, {/Symbol m} translated"
set size noratio
set xlabel "x of r_{{/Symbol b}r,{/Symbol m}t} / {/Symbol s}"
set ylabel "y of r_{{/Symbol b}r,{/Symbol m}t} / {/Symbol s}"
set cblabel "{/Symbol m}_{eff}"
set palette defined (-0.3 '#2166ac', 0 '#f7f7f7', 0.3 '#b2182b')
set cbrange [-0.3:0.3]
stats datafile using "frozen_star_rx" nooutput
star_rx = STATS_max
stats datafile using "frozen_star_ry" nooutput
star_ry = STATS_max
plot d."/frozen_contact.dat" using "rx":"ry":"mu_eff" with points pt 5 ps 1.1 palette, \
     d."/frozen_contact.dat" using "rx":(column("overlap_fraction") > 0.999 ? column("ry") : NaN) with lines lc rgb '#000000' lw 1.5, \
     '+' using (star_rx):(star_ry) every ::0::0 with points title 'star' pt 2 ps 3 lw 3 lc rgb '#000000'
unset multiplot
