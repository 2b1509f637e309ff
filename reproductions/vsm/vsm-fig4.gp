# vsm-fig4: the slightly irregular swinging-cube configurations coloured by the initial von Mises stress,
# from each run's particles.dat (one panel per resolution).
set multiplot layout 2,2
unset key
set view 65, 30
set xyplane at 0
set xtics 0.5; set ytics 0.5; set ztics 0.5
set cblabel "von Mises [kPa]"
set palette rgb 33,13,10
round(x) = int(x + 0.5)
do for [k = 1:words(rundirs)] {
    stats word(rundirs, k)."/particles.dat" using "X1" nooutput
    set title sprintf("%d x %d x %d particles", round(STATS_records**(1.0/3)), round(STATS_records**(1.0/3)), round(STATS_records**(1.0/3)))
    splot word(rundirs, k)."/particles.dat" using "X1":"X2":"X3":(column("von_mises") / 1e3) with points pt 7 ps 0.6 palette
}
unset multiplot
