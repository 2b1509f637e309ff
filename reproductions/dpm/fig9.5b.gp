# DPM-Fig9.5b: the lowest non-zero mode of a jammed soft-disk packing (arrows at the disk centres).
set size ratio -1
unset key
unset grid
set xlabel "x / {/Symbol s}_{small}"
set ylabel "y / {/Symbol s}_{small}"
file = word(rundirs, 1).'/lowest_mode.dat'
stats file using (sqrt(column("ux")**2 + column("uy")**2)) nooutput
scale = 1.5 / STATS_max # the longest arrow 1.5 small diameters
plot file using "x":"y" with points pt 7 ps 1.2 lc rgb '#bbbbbb', \
     file using "x":"y":(column("ux") * scale):(column("uy") * scale) with vectors head filled size 0.1,20 lc rgb '#d62728' lw 1.5
