# DPM-Fig9.11-meshes: exponents, first-contact stiffness and cost of the elastic tetrahedra (nu = 0.3) and the
# elastic shell (nu = 0) against the mesh's vertices.
tetra(c) = column("nu") > 0 ? column(c) : NaN
shell(c) = column("nu") == 0 ? column(c) : NaN
set multiplot layout 1, 3
set logscale x
set xrange [8:1000]
set xlabel "surface vertices N"
set ylabel "exponent {/Symbol a}"
set yrange [0.5:2.2]
set key top left
set title "(a) exponent"
plot datafile using "vertices":(tetra("large_strain_exponent")) ls 3 with linespoints title "tetrahedra, large", \
     datafile using "vertices":(tetra("pole_contact_exponent")) ls 3 pt 8 dt 2 with linespoints title "tetrahedra, pole", \
     datafile using "vertices":(shell("large_strain_exponent")) ls 2 with linespoints title "shell, large", \
     datafile using "vertices":(shell("pole_contact_exponent")) ls 2 pt 4 dt 2 with linespoints title "shell, pole", \
     1.5 ls 4 notitle, 1.0 ls 4 notitle
set title "(b) stiffness at the first contact"
set ylabel "F_a (1 - {/Symbol n}^2) / (E D^2 {/Symbol d}/D) at {/Symbol d}/D = 10^{-3}"
set autoscale y
set logscale y
set key top right
plot datafile using "vertices":(tetra("small_strain_stiffness")) ls 3 with linespoints title "tetrahedra", \
     datafile using "vertices":(shell("small_strain_stiffness")) ls 2 with linespoints title "shell"
set title "(c) cost"
set ylabel "wall time (s), one core"
set key top left
plot datafile using "vertices":(tetra("wall_time_s")) ls 3 with linespoints title "tetrahedra", \
     datafile using "vertices":(shell("wall_time_s")) ls 2 with linespoints title "shell"
unset multiplot
