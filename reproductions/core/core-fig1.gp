# core-fig1: energy error of velocity Verlet against dt/dt_c; theory (dt/dt_c)^2 below the limit.
dtc = 2.0 * sqrt(mass / stiffness)
set logscale xy
set format y "10^{%T}"
set xlabel "dt / dt_c   (dt_c = 2/{/Symbol w})"
set ylabel "max |E/E_0 - 1|"
set xrange [0.002:3]
set yrange [1e-6:5]
set arrow from 1, graph 0 to 1, graph 1 nohead dt 3 lc rgb '#888888'
set label "dt_c" at 1.05, 2e-6
set key bottom right
plot x**2 ls 4 title "theory (dt/dt_c)^2", \
     datafile using (column("dt")/dtc):(column("exit_code") == 0 ? column("energy_error_max") : NaN) \
        ls 1 with points title "core.harmonic (completed)", \
     datafile using (column("dt")/dtc):(column("exit_code") == 3 ? 2.0 : NaN) \
        ls 2 with points title "stopped, exit 3 (diagnosed unstable)"
