# DPM-text-A3d: A^3D - 1 of the Platonic solids and geodesic icosahedra against the number of vertices N.
set logscale xy
set format y "10^{%T}"
set xlabel "vertices N"
set ylabel "A^{3D} - 1"
set xrange [3:1000]
set key top right
plot datafile using "vertices":(column("shape_parameter_min") - 1) ls 1 pt 7 title "meshes (4, 6, 12: Platonic; 42, 162, 642: geodesic)", \
     '-' using 1:($2 - 1) ls 2 pt 6 ps 2 title "text: 1.8188, 1.2861, 1.0984, 1.024", \
     0.024 * 42 / x ls 4 dt 2 title "slope -1"
N A
4 1.8188
6 1.2861
12 1.0984
42 1.024
e
