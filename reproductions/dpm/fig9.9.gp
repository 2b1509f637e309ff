# DPM-Fig9.9: (a) rough and (c) smooth frames 1-7 at A0 = 1.3 (frames.dat of runs 3 and 6; beta blue, mu red;
# frame k shifted right by 6 sigma (k - 1)); (b, d) mu_eff against x/D_beta for floppy particles, rough (runs
# 1-3) and smooth (runs 4-6), A0 = A_min, 1.15, 1.30 in sweep order. Runs without any sample in contact draw
# nothing in (b, d).
set multiplot
f(d) = word(rundirs, d)."/shear.dat"
frames(d) = word(rundirs, d)."/frames.dat"
set lmargin at screen 0.08
set rmargin at screen 0.98
unset key
unset xtics
unset ytics
set border 0
set size ratio -1
do for [row = 1:2] {
  d = row == 1 ? 3 : 6
  set origin 0, 1 - row * 0.22
  set size 1, 0.22
  set label 1 word("(a) (c)", row) at screen 0.02, screen 1 - (row - 0.5) * 0.22
  plot frames(d) using (column("particle") == 0 ? column("x") + 6 * (column("frame") - 1) : NaN):"y" \
         with lines lw 1.5 lc rgb '#1f77b4', \
       frames(d) using (column("particle") == 1 ? column("x") + 6 * (column("frame") - 1) : NaN):"y" \
         with lines lw 1.5 lc rgb '#d62728'
}
unset label 1
set size noratio
set border
set xtics
set ytics
set xlabel "x_{{/Symbol b}{/Symbol m}} / D_{/Symbol b}"
set ylabel "{/Symbol m}_{eff}"
set xrange [-0.6:0.6]
set yrange [-1:1.2]
set key bottom left font ",9"
set origin 0, 0
set size 0.5, 0.54
set lmargin
set rmargin
set title "(b) rough floppy particles"
plot f(1) using "x_over_D":"mu_eff" ls 1 with linespoints title "A_0 = A_{min}", \
     f(2) using "x_over_D":"mu_eff" ls 2 with linespoints title "A_0 = 1.15", \
     f(3) using "x_over_D":"mu_eff" ls 3 with linespoints title "A_0 = 1.30", \
     0.577 ls 4 title "{/Symbol \261}0.577", -0.577 ls 4 notitle
set origin 0.5, 0
set title "(d) smooth floppy particles"
plot f(4) using "x_over_D":"mu_eff" ls 1 with linespoints title "A_0 = A_{min}", \
     f(5) using "x_over_D":"mu_eff" ls 2 with linespoints title "A_0 = 1.15", \
     f(6) using "x_over_D":"mu_eff" ls 3 with linespoints title "A_0 = 1.30", \
     0.190 ls 4 title "{/Symbol \261}0.190", -0.190 ls 4 notitle
unset multiplot
