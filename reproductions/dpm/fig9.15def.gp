# DPM-Fig9.15def: eigenvalues lambda~_k of jammed 3D packings against pressure, one panel per model
# (as DPM-Fig9.14def in 2D).
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "P  (k_v v_0)"
set ylabel "{/Symbol l}~_k  (k_v v_0^{4/3})"
set yrange [1e-10:*]
set palette defined (0 "dark-blue", 1 "cyan", 2 "yellow", 3 "dark-red")
set multiplot layout 1,3
n = words(rundirs)
per = n / 3
models = "floppy shell surface-tension"
# The pressure reached by each run: column 2 (pressure_reached) of the reduced table, in run order.
pressures = system("grep -v '^#' ".datafile." | tail -n +2 | awk '{print $2}'")
unset key
set xtics 100
set xrange [(word(pressures, 1) + 0) / 3.0:(word(pressures, per) + 0) * 3.0]
# Runs: model outer, pressure inner (sweep order); each file holds one packing's spectrum.
do for [m=1:3] {
    set title word(models, m)
    plot for [k=(m-1)*per+1:m*per] word(rundirs, k)."/eigenvalues.dat" \
        using (word(pressures, k) + 0):(column("lambda") > 1e-10 ? column("lambda") : NaN):"k" \
        with points pt 7 ps 0.3 lc palette notitle
}
unset multiplot
