# DPM-Fig9.16b: ensemble-averaged shear modulus <G> against pressure P of 3D packings, one run per model (sweep
# order: floppy, shell, surface tension); each run writes its tables with the model's name.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "P  (k_v v_0)"
set ylabel "<G>  (k_v v_0)"
set key top left
models = "floppy shell surface_tension"
titles = "floppy shell surface-tension"
n = words(rundirs)
mean(k) = word(rundirs, k)."/mean_modulus_".word(models, k).".dat"
each(k) = word(rundirs, k)."/modulus_".word(models, k).".dat"
plot for [k=1:n] mean(k) using "P":(column("G") > 0 ? column("G") : NaN) ls k with linespoints \
        title word(titles, k), \
     for [k=1:n] each(k) using "P":(column("G") > 0 ? column("G") : NaN) ls k pt 1 ps 0.5 notitle, \
     1e-1*x**0.5 ls 8 dt 2 title "slope 0.5", 1*x ls 8 dt 4 title "slope 1"
