# DPM-Fig9.13a-shells: P against phi - phi_c for each packing of rough elastic shells (one run, its
# pressure.dat holds every packing's states, column "packing").
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_a a_0)"
set key top left
states = word(rundirs, 1)."/pressure.dat"
stats states using "packing" nooutput
packings = int(STATS_max) + 1
plot for [k=0:packings-1] states using (column("packing") == k && column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls 2 with linespoints title (k == 0 ? "elastic shells, one curve per packing" : ""), \
     1e-1*x ls 4 title "slope 1"
