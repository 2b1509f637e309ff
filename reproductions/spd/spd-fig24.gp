# spd-fig24: p/p* profiles for eta = inf.
set xlabel "x / R"
set ylabel "p / p*"
set key top left
set yrange [0:*]
d = word(rundirs, 1).'/profiles.dat'
plot for [e in "0.1 0.2 0.3 0.4"] d using (abs(column("eps") - e) < 1e-6 ? column("x_over_R") : NaN):"p_over_pstar" with linespoints lw 2 title "{/Symbol e} = ".e
