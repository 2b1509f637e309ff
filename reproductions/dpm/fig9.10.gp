# DPM-Fig9.10(c): F~ against delta~ for the spring-network disk (run 1) and the elastic shell (run 2), with
# eq. (9.14) for the cylinder at the network's forces.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol d} / D"
set ylabel "F_a (1 - {/Symbol n}^2) / (E D)"
set key top left
n = word(rundirs, 1)."/force.dat"
s = word(rundirs, 2)."/force.dat"
plot n using "delta_eq_9_14":"F_tilde" ls 1 with linespoints title "eq. (9.14), cylinder, D/l = 1", \
     n using "delta":"F_tilde" ls 2 with linespoints title "spring-network disk", \
     s using "delta":"F_tilde" ls 3 with linespoints title "elastic shell, N = 100", \
     1e-1 * x ls 4 title "slope 1"
