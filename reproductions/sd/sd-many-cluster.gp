# Note [20] in 2D: the three gaps of a symmetric triangle against time, and the radial speed of particle 0.
f = word(rundirs, 1)."/many.dat"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "t V / R"
set ylabel "gap / R,  |V_0| / V"
set key bottom left
plot f using (column("t")):(column("h_0")) with lines lw 6 lc rgb '#bbbbbb' title "h_{01}", \
     f using (column("t")):(column("h_1")) with lines ls 1 title "h_{12}", \
     f using (column("t")):(column("h_2")) with points pt 6 ps 0.6 lc rgb '#d62728' title "h_{20}", \
     f using (column("t")):(sqrt(column("v_0x")**2 + column("v_0y")**2)) with lines ls 3 title "|V_0|"
