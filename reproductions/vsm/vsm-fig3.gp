# vsm-fig3: the irregular 3 x 3 x 3 particles of the patch tests in the unit cube (the cube's edges drawn);
# one panel per seed, from each run's particles.dat.
set multiplot layout 1,words(rundirs)
unset key
set view 65, 30
set xyplane at 0
set xrange [0:1]; set yrange [0:1]; set zrange [0:1]
set xtics 0.5; set ytics 0.5; set ztics 0.5
set xlabel "X_1"; set ylabel "X_2"; set zlabel "X_3"
$cube << EOD
0 0 0
1 0 0
1 1 0
0 1 0
0 0 0
0 0 1
1 0 1
1 1 1
0 1 1
0 0 1

1 0 0
1 0 1

1 1 0
1 1 1

0 1 0
0 1 1
EOD
do for [k = 1:words(rundirs)] {
    set title sprintf("seed %d", k)
    splot $cube using 1:2:3 with lines lc rgb '#555555', \
          word(rundirs, k)."/particles.dat" using "X1":"X2":"X3" with points pt 7 ps 2 lc rgb '#888888'
}
unset multiplot
