# DPM-cost: wall time of the jamming protocol and of the mode spectrum against the degrees of freedom, for more
# particles (nodes = 10) and more vertices per particle (particles = 8); the run (8, 10) belongs to both.
set xlabel "degrees of freedom 2 {/Symbol S} N_{/Symbol m}"
set ylabel "wall time (s), one core"
set logscale xy
set format y "10^{%T}"
set key top left
more_particles(c) = column("nodes") == 10 ? column(c) : NaN
more_vertices(c) = column("particles") == 8 ? column(c) : NaN
plot datafile using "degrees_of_freedom":(more_particles("jam_seconds")) ls 1 with linespoints title "jamming, more particles", \
     datafile using "degrees_of_freedom":(more_vertices("jam_seconds")) ls 2 with linespoints title "jamming, more vertices", \
     datafile using "degrees_of_freedom":(more_particles("spectrum_seconds")) ls 1 dashtype 2 with linespoints title "spectrum, more particles", \
     datafile using "degrees_of_freedom":(more_vertices("spectrum_seconds")) ls 2 dashtype 2 with linespoints title "spectrum, more vertices"
