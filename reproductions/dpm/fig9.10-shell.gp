# DPM-Fig9.10-shell: F_a against delta/D for a 2D elastic shell between plates, with the thin-ring law.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol d} / D"
set ylabel "F_a  (k_c {/Symbol s})"
set key top left
d = word(rundirs, 1)."/force.dat"
R = 1.0 / (2 * sin(pi / nodes))
D = 2 * R + 1
compliance = (pi/4 - 2/pi) * R**3 / kb + (4/pi - pi/4) * R / kl
plot d using "delta":"F" ls 1 with linespoints title "elastic shell, N = 100", \
     x * D / compliance ls 4 dt 3 title "thin ring: {/Symbol d}/F = ({/Symbol p}/4 - 2/{/Symbol p})R^3/EI + (4/{/Symbol p} - {/Symbol p}/4)R/EA", \
     2 * x * D / compliance ls 4 title "slope 1"
