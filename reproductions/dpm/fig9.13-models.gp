# DPM-Fig9.13-models: P against phi - phi_c for each packing, one colour per model (Fig. 9.13a-d).
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_a a_0 of the small particles)"
set key top left
n = words(rundirs)
seeds = n / 4
# Runs are in sweep order: model outer (4 models), seed inner.
models = "rough-disk shell floppy surface-tension"
plot for [k=1:n] word(rundirs, k)."/pressure.dat" using (column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls (1 + (k - 1) / seeds) with linespoints \
        title ((k - 1) % seeds == 0 ? word(models, 1 + (k - 1) / seeds) : ""), \
     1e-1*x ls 8 dt 2 title "slope 1"
