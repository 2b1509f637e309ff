# DPM-Fig9.13a: P against phi - phi_c for each packing (one run per seed), and the mean linear fit.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_c)"
set key top left
stats datafile using "bulk_modulus" nooutput
B = STATS_mean
n = words(rundirs)
plot for [k=1:n] word(rundirs, k)."/pressure.dat" using (column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls 1 with linespoints title (k == 1 ? "smooth disks, one curve per packing" : ""), \
     B*x ls 4 title sprintf("P = B({/Symbol f} - {/Symbol f}_c), B = %.3f", B)
