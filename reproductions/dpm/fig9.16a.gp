# DPM-Fig9.16a: ensemble-averaged shear modulus <G> against pressure P, one run per model.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "P  (k_a a_0)"
set ylabel "<G>  (k_a a_0)"
set key top left
models = "floppy shell surface-tension"
n = words(rundirs)
plot for [k=1:n] word(rundirs, k)."/mean_modulus.dat" using "P":(column("G") > 0 ? column("G") : NaN) \
        ls k with linespoints title word(models, k), \
     for [k=1:n] word(rundirs, k)."/modulus.dat" using "P":(column("G") > 0 ? column("G") : NaN) \
        ls k pt 1 ps 0.5 notitle, \
     3e-1*x**0.5 ls 8 dt 2 title "slope 0.5", 3*x ls 8 dt 4 title "slope 1"
