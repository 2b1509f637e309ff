# spd-beam-work-precision: |delta_max/delta_th - 1| against wall time, cantilever and simply supported beams,
# labelled by N, for three time steps.
set xlabel "wall time [s]"
set ylabel "|{/Symbol d}_{max}/{/Symbol d}_{th} - 1|"
set logscale xy
set format y "10^{%T}"
set key bottom left
err(s, f) = (column("support_index") == s && abs(column("dt_factor") - f) < 1e-9) ? abs(column("ratio") - 1) : NaN
plot datafile using "wall_time_s":(err(0, 0.25)) ls 1 pt 6 with points title "CB, dt = 0.25 dt_c", \
     datafile using "wall_time_s":(err(0, 0.5)) ls 1 pt 7 with points title "CB, dt = 0.5 dt_c", \
     datafile using "wall_time_s":(err(0, 0.9)) ls 1 pt 5 with points title "CB, dt = 0.9 dt_c", \
     datafile using "wall_time_s":(err(1, 0.25)) ls 2 pt 6 with points title "SSB, dt = 0.25 dt_c", \
     datafile using "wall_time_s":(err(1, 0.5)) ls 2 pt 7 with points title "SSB, dt = 0.5 dt_c", \
     datafile using "wall_time_s":(err(1, 0.9)) ls 2 pt 5 with points title "SSB, dt = 0.9 dt_c", \
     datafile using "wall_time_s":(err(0, 0.5)):(sprintf("N=%d", column("nodes"))) with labels offset 0,1 notitle, \
     datafile using "wall_time_s":(err(1, 0.5)):(sprintf("N=%d", column("nodes"))) with labels offset 0,-1 notitle, \
     0.01 ls 4 title "1%"
