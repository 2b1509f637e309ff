# vsm-fig10: punch test, front layer of particles at the final deformation coloured by pressure; runs in sweep order
# (regular xi=1, regular xi=0, irregular xi=1, irregular xi=0).
set datafile columnheaders
unset key
set size ratio -1
set xrange [-0.02:1.02]
set yrange [-0.02:0.52]
set palette defined (0 '#2c7bb6', 0.5 '#ffffbf', 1 '#d7191c')
set cblabel "pressure [kPa]"
set cbrange [-500:1500]
set xlabel "x_1 [m]"
set ylabel "x_2 [m]"
set multiplot layout 2,2
array titles[4] = ["regular, xi = 1", "regular, xi = 0 (no stabilisation)", "irregular, xi = 1", "irregular, xi = 0 (no stabilisation)"]
do for [k = 0:3] {
    file = word(rundirs, k + 1)."/snapshots.dat"
    set title titles[k + 1] noenhanced
    plot file using (column("strain") == final_strain && column("x3") < 0.1 / 3 ? column("x1") : NaN):"x2":(column("pressure") / 1000) \
         with points pt 7 ps 0.7 palette
}
unset multiplot
