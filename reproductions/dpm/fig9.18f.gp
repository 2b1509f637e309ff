# DPM-Fig9.18(f): theta of the jammed 4-disk packing against the preferred shape parameter A0 of a boundary with
# an area constraint (run 2), with the thetas of the floppy boundary's packings (run 1, Fig. 9.18a-e) dashed.
floppy = word(rundirs, 1)
scan = word(rundirs, 2)
stats floppy."/packings.dat" using "theta" nooutput
floppy_count = STATS_records
stats scan."/packings.dat" using "A0" nooutput
xlo = STATS_min - 0.01
xhi = STATS_max + 0.01
set xrange [xlo:xhi]
set key bottom right
set xlabel "A_0 of the boundary"
set ylabel "{/Symbol q} (degrees)"
set yrange [55:95]
set title "jammed packings of 4 disks, boundary with k_a > 0"
plot for [k = 0:floppy_count - 1] floppy."/packings.dat" every ::k::k using (xlo):"theta":(xhi - xlo):(0) \
       with vectors nohead dt 2 lc rgb '#d62728' notitle, \
     1/0 dt 2 lc rgb '#d62728' title "floppy boundary (a)-(e)", \
     scan."/packings.dat" using "A0":"theta" with linespoints pt 7 lc rgb '#1f77b4' title "k_a > 0"
