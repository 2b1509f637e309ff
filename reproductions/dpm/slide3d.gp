# DPM-slide3d: a rigid sphere-like particle slid over a flat slab at fixed height. (a) the interaction
# energy along the path over its mean, rough (vertex spheres) and smooth (vertex against faces), for the
# 42-vertex slider (run 2) and the 642-vertex one (run 4), and the smooth half of the slider's vertices
# against the slab (flat to round-off); (b) F_x/F_z on the slider for the same runs.
set multiplot layout 1,2
set xlabel "slider centre x ({/Symbol s})"
set key top left font ",9"
f(d) = word(rundirs, d)."/path.dat"
stats f(2) using "U_rough" nooutput
r42 = STATS_mean
stats f(2) using "U_smooth" nooutput
s42 = STATS_mean
stats f(2) using "U_smooth_slider" nooutput
h42 = STATS_mean
stats f(4) using "U_rough" nooutput
r642 = STATS_mean
stats f(4) using "U_smooth" nooutput
s642 = STATS_mean
set ylabel "U / <U>"
set yrange [0.4:1.6]
set title "(a) energy along the path"
plot f(2) using "x":(column("U_rough") / r42) ls 1 with lines title "rough, N = 42", \
     f(2) using "x":(column("U_smooth") / s42) ls 2 with lines title "smooth, N = 42", \
     f(2) using "x":(column("U_smooth_slider") / h42) ls 3 with lines title "smooth, slider vertices vs slab faces", \
     f(4) using "x":(column("U_rough") / r642) ls 4 with lines title "rough, N = 642", \
     f(4) using "x":(column("U_smooth") / s642) lc rgb '#7f3f98' lw 2 dt 2 with lines title "smooth, N = 642"
set ylabel "F_x / F_z on the slider"
set yrange [-0.4:0.4]
set title "(b) tangential over normal force"
plot f(2) using "x":"mu_rough" ls 1 with lines title "rough, N = 42", \
     f(2) using "x":"mu_smooth" ls 2 with lines title "smooth, N = 42", \
     f(4) using "x":"mu_rough" ls 4 with lines title "rough, N = 642", \
     f(4) using "x":"mu_smooth" lc rgb '#7f3f98' lw 2 dt 2 with lines title "smooth, N = 642"
unset multiplot
