# DPM-Fig9.5a: the displacement field of the lowest non-zero mode of the soft-disk crystal (arrows at the disk
# centres, disks drawn at half their diameter for legibility).
set size ratio -1
unset key
unset grid
set xlabel "x / {/Symbol s}"
set ylabel "y / {/Symbol s}"
file = word(rundirs, 1).'/mode.dat'
stats file using (sqrt(column("ux")**2 + column("uy")**2)) nooutput
scale = 0.8 / STATS_max # the longest arrow 0.8 sigma
plot file using "x":"y":(0.25) with circles lc rgb '#bbbbbb' fs solid 0.5, \
     file using "x":"y":(column("ux") * scale):(column("uy") * scale) with vectors head filled size 0.08,20 lc rgb '#1f77b4' lw 1.5
