# DPM-Fig9.14c-single: Delta U against Delta r along every mode of a relaxed floppy particle.
set logscale xy
set format y "10^{%T}"
set format x "10^{%T}"
set xlabel "{/Symbol D}r  (a_0^{1/2})"
set ylabel "{/Symbol D}U  (k_a a_0^2)"
set yrange [1e-16:10]
set key top left
set palette defined (0 '#08306b', 1 '#2171b5', 2 '#fdae6b', 3 '#a50f15')
unset colorbox
d = word(rundirs, 1)."/mode_energy.dat"
plot d using "dr":(column("dU") > 0 ? column("dU") : NaN):"k" with lines lc palette lw 1.5 notitle, \
     0.5*x**2 ls 4 title "slope 2", \
     0.05*x**4 ls 4 dt 4 title "slope 4"
