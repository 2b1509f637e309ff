# spd-fig16: contact pressure profiles p/p* against x/R at eps = 0.1 ... 0.5, elastic ring.
set xlabel "x / R"
set ylabel "p / p*"
set key top right
set yrange [0:*]
d = word(rundirs, 1).'/profiles.dat'
set datafile missing NaN
plot for [e in "0.1 0.2 0.3 0.4 0.5"] d using (abs(column("eps") - e) < 1e-6 ? column("x_over_R") : NaN):"p_over_pstar" with linespoints lw 2 title "{/Symbol e} = ".e, \
     1 ls 4 title "paper: plateau at p*"
