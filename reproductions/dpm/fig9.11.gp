# DPM-Fig9.11(d): F~ against delta~ for the spring-network ball (run 1), the elastic shell (run 2) and the
# elastic tetrahedra (run 3), with Hertz between two plates (F~ = delta~^1.5/3) and slopes 1 and 1.5.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol d} / D"
set ylabel "F_a (1 - {/Symbol n}^2) / (E D^2)"
set key top left
set xrange [8e-4:0.25]
set yrange [1e-6:0.1]
n = word(rundirs, 1)."/force.dat"
s = word(rundirs, 2)."/force.dat"
t = word(rundirs, 3)."/force.dat"
plot n using "delta":"F_tilde" ls 1 with linespoints title "spring network", \
     s using "delta":"F_tilde" ls 2 with linespoints title "elastic shell", \
     t using "delta":"F_tilde" ls 3 with linespoints title "elastic tetrahedra", \
     x**1.5 / 3 lc rgb '#000000' lw 1.5 dt 3 title "Hertz, two plates: {/Symbol d}^{1.5}/3", \
     0.05 * x ls 4 title "slope 1", \
     0.05 * x**1.5 lc rgb '#000000' lw 1.5 dt 4 title "slope 1.5"
