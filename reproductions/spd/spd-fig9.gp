# spd-fig9: measured ring moduli over eqs. (23) and (25), against N.
set xlabel "N (nodes)"
set ylabel "modulus / theory"
set logscale x 2
set key center right
set yrange [0.9:2.2]
plot datafile using "nodes":(column("K_shell")/column("K_shell_theory")) ls 1 with linespoints title "K_{shell}, eta = 0 / eq. (23)", \
     datafile using "nodes":(column("K_effective")/column("K_effective_theory")) ls 2 with linespoints title "K_e, eta = 10 / eq. (25)", \
     datafile using "nodes":(column("K_shell_printed_approximation")/column("K_shell_theory")) ls 4 with lines title "eq. (23) printed approximation / exact"
