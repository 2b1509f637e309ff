# compare-ring-stability: SPD runs over (N, dt/dt_c): completed (circles) and stopped with a diagnosis (exit 3,
# crosses), with the stability limit the scheme checks before the run (decision spd-stability-limit; the same
# for every N of these thin rings, read from the completed runs' summaries).
stats datafile using "dt_stable_over_dt_critical" nooutput
limit = STATS_max
stats datafile using "nodes" nooutput
set xrange [STATS_min / 1.5 : STATS_max * 1.5]
set xlabel "vertices N"
set ylabel "dt / dt_c"
set logscale x
set xtics ("8" 8, "16" 16, "32" 32, "64" 64, "128" 128, "256" 256, "512" 512)
set key bottom right
set yrange [0:1.3]
plot datafile using (column("exit_code") == 0 ? column("nodes") : NaN):"dt_factor" ls 3 pt 7 ps 1.5 with points title "completed (exit 0)", \
     datafile using (column("exit_code") == 3 ? column("nodes") : NaN):"dt_factor" ls 2 pt 2 ps 2 lw 2 with points title "stopped, exit 3 (diagnosed)", \
     limit ls 4 title sprintf("limit checked before the run (damped wall contact), %.3f dt_c", limit), \
     1 ls 4 lc rgb '#888888' title "dt_c = sqrt(m/k_{max})"
