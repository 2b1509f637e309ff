# DPM-Fig9.13a: P against phi - phi_c for each packing of the ensemble (one run, its pressure.dat holds every
# packing's states, column "packing"), and the fit of the mean bulk modulus.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_c)"
set key top left
stats datafile using "bulk_modulus" nooutput
B = STATS_mean
states = word(rundirs, 1)."/pressure.dat"
stats states using "packing" nooutput
packings = int(STATS_max) + 1
plot for [k=0:packings-1] states using (column("packing") == k && column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls 1 with linespoints title (k == 0 ? "smooth disks, one curve per packing" : ""), \
     B*x ls 4 title sprintf("P = B({/Symbol f} - {/Symbol f}_c), B = %.3f", B)
