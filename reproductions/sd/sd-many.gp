# Note [20]: gap of the first bond of each line against time; all coincide with the two-particle approach.
stats datafile using (column("particles")) nooutput
runs = STATS_records
array n_of[runs]
do for [k=0:runs-1] {
    stats datafile using (column("particles")) every ::k::k nooutput
    n_of[k+1] = STATS_min
}
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "t V / R"
set ylabel "gap h_{01} / R"
set key bottom left
plot for [k=0:runs-1] word(rundirs, k+1)."/many.dat" using (column("t")):(column("h_0")) \
        with linespoints lw 2 pt (k+4) ps 0.6 title sprintf("line of %d particles", n_of[k+1])
