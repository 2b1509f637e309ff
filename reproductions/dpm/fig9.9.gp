# DPM-Fig9.9(b, d): mu_eff against x/D_beta for floppy particles, rough (runs 1-3) and smooth (runs 4-6),
# A0 = A_min, 1.15, 1.30 in sweep order. Runs without any sample in contact draw nothing.
set multiplot layout 1,2
set xlabel "x_{{/Symbol b}{/Symbol m}} / D_{/Symbol b}"
set ylabel "{/Symbol m}_{eff}"
set xrange [-0.6:0.6]
set yrange [-1:1.2]
set key bottom left font ",9"
f(d) = word(rundirs, d)."/shear.dat"
set title "(b) rough floppy particles"
plot f(1) using "x_over_D":"mu_eff" ls 1 with linespoints title "A_0 = A_{min}", \
     f(2) using "x_over_D":"mu_eff" ls 2 with linespoints title "A_0 = 1.15", \
     f(3) using "x_over_D":"mu_eff" ls 3 with linespoints title "A_0 = 1.30", \
     0.577 ls 4 title "{/Symbol \261}0.577", -0.577 ls 4 notitle
set title "(d) smooth floppy particles"
plot f(4) using "x_over_D":"mu_eff" ls 1 with linespoints title "A_0 = A_{min}", \
     f(5) using "x_over_D":"mu_eff" ls 2 with linespoints title "A_0 = 1.15", \
     f(6) using "x_over_D":"mu_eff" ls 3 with linespoints title "A_0 = 1.30", \
     0.190 ls 4 title "{/Symbol \261}0.190", -0.190 ls 4 notitle
unset multiplot
