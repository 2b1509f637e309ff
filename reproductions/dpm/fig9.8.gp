# DPM-Fig9.8: (a)-(c) frames 1-7 of the shear test (frames.dat of runs 1 = rough C = 1.3, 2 = rough C = 0.71,
# 3 = smooth C = 1.3; beta blue, mu red; frame k shifted right by 6 sigma (k - 1)); (d) mu_eff against x/D_beta
# (runs in sweep order: rough 1.3, rough 0.71, smooth 1.3, smooth 0.71).
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
do for [d = 1:3] {
  set origin 0, 1 - d * 0.18
  set size 1, 0.18
  set label 1 word("(a) (b) (c)", d) at screen 0.02, screen 1 - (d - 0.5) * 0.18
  plot frames(d) using (column("particle") == 0 ? column("x") + 6 * (column("frame") - 1) : NaN):"y" \
         with lines lw 1.5 lc rgb '#1f77b4', \
       frames(d) using (column("particle") == 1 ? column("x") + 6 * (column("frame") - 1) : NaN):"y" \
         with lines lw 1.5 lc rgb '#d62728'
}
unset label 1
set origin 0, 0
set size 1, 0.46
set size noratio
set border
set xtics
set ytics
set key bottom left
unset title
set xlabel "x_{{/Symbol b}{/Symbol m}} / D_{/Symbol b}"
set ylabel "{/Symbol m}_{eff}"
set xrange [-0.6:0.6]
set yrange [-0.8:0.8]
plot f(1) using "x_over_D":"mu_eff" ls 1 with linespoints title "rough shells, C = 1.3", \
     f(2) using "x_over_D":"mu_eff" ls 2 with linespoints title "rough shells, C = 0.71", \
     f(3) using "x_over_D":"mu_eff" ls 3 with linespoints title "smooth shells, C = 1.3", \
     0.5735 ls 4 title "eq. (9.13), C = 1.3", 0.2823 ls 4 dt 3 title "eq. (9.13), C = 0.71"
unset multiplot
