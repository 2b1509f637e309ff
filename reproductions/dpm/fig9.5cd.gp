# DPM-Fig9.5cd: (c) the lowest-frequency quartic mode and (d) the highest-frequency mode of a jammed packing of
# floppy particles: particle outlines (vertex centres joined) and the mode's displacement at every vertex.
file = word(rundirs, 1).'/mode_fields.dat'
set size ratio -1
unset key
unset grid
set xlabel "x / {/Symbol s}"
set ylabel "y / {/Symbol s}"
on(panel, q, value) = column("panel") == panel && column("particle") == q ? value : NaN
arrow(panel, value) = column("panel") == panel && column("closing") < 0.5 ? value : NaN
stats file using "x" nooutput
set xrange [STATS_min - 1:STATS_max + 1]
stats file using "y" nooutput
set yrange [STATS_min - 1:STATS_max + 1]
stats file using "particle" nooutput
particles = int(STATS_max) + 1
set multiplot layout 1,2
do for [panel=0:1] {
    stats file using (arrow(panel, sqrt(column("ux")**2 + column("uy")**2))) nooutput
    scale = 1.5 / STATS_max # the longest arrow 1.5 sigma
    set title (panel == 0 ? "(c) lowest quartic mode" : "(d) highest (quadratic) mode")
    plot for [q=0:particles-1] file using (on(panel, q, column("x"))):"y" with lines lc rgb '#888888' lw 1, \
         file using (arrow(panel, column("x"))):"y":(column("ux") * scale):(column("uy") * scale) \
            with vectors head filled size 0.15,20 lc rgb 'black' lw 1.2
}
unset multiplot
