# SD Fig. 3b: phase diagram (h/R, kappa). Thick lines: theory (h = R; delta = h, i.e. kappa = 2 alpha (h/R)^(3/2)).
# Thin lines: the gaps crossed by each constant-kappa simulation, coloured where a regime's width is <= 0.1.
f = word(rundirs, 1)."/phase_diagram.dat"
g = word(rundirs, 1)."/crossover_lines.dat"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "h / R"
set ylabel "{/Symbol k} = F_{ext}/(E R^2)"
set xrange [1e-7:200]
set yrange [3e-7:1]
set key bottom right
set arrow from 1, graph 0 to 1, graph 1 nohead lw 6 lc rgb '#bbbbbb'
set label "Stokes" at 10, 1e-5
set label "Poiseuille" at 3e-3, 1e-6
set label "Hertz" at 1e-6, 1e-2
plot g using (column("h")):(column("kappa_exact")) with lines lw 6 lc rgb '#bbbbbb' title "theory {/Symbol d} = h", \
     g using (column("h")):(column("kappa_asymptotic")) with lines lw 1.5 dt 2 lc rgb '#000000' title "2{/Symbol a} (h/R)^{3/2}", \
     f using (column("h_end")):(column("kappa")):(column("h_start")-column("h_end")):(0) with vectors nohead lc rgb '#888888' title "simulated range", \
     f using (column("stokes_h_min")):(column("kappa")):(column("stokes_h_max")-column("stokes_h_min")):(0) with vectors nohead ls 1 lw 4 title "Stokes (w {/Symbol \243} 0.1)", \
     f using (column("poiseuille_h_min")):(column("kappa")):(column("poiseuille_h_max")-column("poiseuille_h_min")):(0) with vectors nohead ls 3 lw 4 title "Poiseuille", \
     f using (column("hertz_h_min")):(column("kappa")):(column("hertz_h_max")-column("hertz_h_min")):(0) with vectors nohead ls 2 lw 4 title "Hertz", \
     f using (column("h_crossover")):(column("kappa")) with points pt 6 ps 1.5 lc rgb '#000000' title "simulated {/Symbol d} = h"
