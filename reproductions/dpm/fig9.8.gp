# DPM-Fig9.8(d): mu_eff against x/D_beta for rough C = 1.3, rough C = 0.71, smooth C = 1.3 (runs in sweep order:
# rough 1.3, rough 0.71, smooth 1.3, smooth 0.71).
set xlabel "x_{{/Symbol b}{/Symbol m}} / D_{/Symbol b}"
set ylabel "{/Symbol m}_{eff}"
set xrange [-0.6:0.6]
set yrange [-0.8:0.8]
set key bottom left
f(d) = word(rundirs, d)."/shear.dat"
plot f(1) using "x_over_D":"mu_eff" ls 1 with linespoints title "rough shells, C = 1.3", \
     f(2) using "x_over_D":"mu_eff" ls 2 with linespoints title "rough shells, C = 0.71", \
     f(3) using "x_over_D":"mu_eff" ls 3 with linespoints title "smooth shells, C = 1.3", \
     0.5735 ls 4 title "eq. (9.13), C = 1.3", 0.2823 ls 4 dt 3 title "eq. (9.13), C = 0.71"
