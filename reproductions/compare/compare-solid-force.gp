# compare-solid-force: F~ = F (1 - nu^2)/(E D^2) against delta~ = delta/D for a ball between two plates: the DPM
# elastic tetrahedra and the DPM spring network at the finest resolution of the figure (rundirs: tetrahedra, then
# network), the finite-element ball of data/compare/solid_fe.dat (Saint Venant-Kirchhoff at nu = 0.3 and 1/4,
# neo-Hookean at nu = 0.3) and Hertz between two plates, (1/3) delta~^1.5. A network sample below 1e-6 (a node
# just touching) lies below the drawn range.
set xlabel "{/Symbol d}/D"
set ylabel "F (1 - {/Symbol n}^2)/(E D^2)"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set key top left
fe = repo.'/data/compare/solid_fe.dat'
tetrahedra = word(rundirs, 1).'/force.dat'
network = word(rundirs, 2).'/force.dat'
set yrange [1e-6:0.2]
plot [1e-3:0.3] x**1.5/3 ls 4 lc rgb '#e08000' dt 2 lw 2 with lines title "Hertz, two plates: ({/Symbol d}/D)^{1.5}/3", \
     fe using (column("law_index") == 0 && column("nu") == 0.3 ? column("delta_over_d") : NaN):"F_tilde" ls 4 lc rgb '#000000' with lines title "FE, Saint Venant-Kirchhoff, {/Symbol n} = 0.3", \
     fe using (column("law_index") == 1 && column("nu") == 0.3 ? column("delta_over_d") : NaN):"F_tilde" ls 4 lc rgb '#777777' dt 3 with lines title "FE, neo-Hookean, {/Symbol n} = 0.3", \
     fe using (column("law_index") == 0 && column("nu") == 0.25 ? column("delta_over_d") : NaN):"F_tilde" ls 4 lc rgb '#3060c0' dt 4 with lines title "FE, Saint Venant-Kirchhoff, {/Symbol n} = 1/4", \
     tetrahedra using "delta":"F_tilde" ls 1 with points title "DPM elastic tetrahedra (eq. 9.15), {/Symbol n} = 0.3", \
     network using "delta":"F_tilde" ls 2 pt 6 with points title "DPM spring network (affine E, {/Symbol n} = 1/4)"
