# DPM-Fig9.13-models: P against phi - phi_c for each packing, one colour per model (Fig. 9.13a-d). One run per
# model, in sweep order; each run's pressure.dat holds every packing's states (column "packing").
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_a a_0 of the small particles)"
set key top left
n = words(rundirs)
models = "rough-disk shell floppy surface-tension"
stats word(rundirs, 1)."/pressure.dat" using "packing" nooutput
packings = int(STATS_max) + 1
plot for [m=1:n] for [k=0:packings-1] word(rundirs, m)."/pressure.dat" \
        using (column("packing") == k && column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls m with linespoints title (k == 0 ? word(models, m) : ""), \
     1e-1*x ls 8 dt 2 title "slope 1"
