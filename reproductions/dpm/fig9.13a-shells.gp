# DPM-Fig9.13a-shells: P against phi - phi_c for each packing of rough elastic shells.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol f} - {/Symbol f}_c"
set ylabel "P  (k_a a_0)"
set key top left
n = words(rundirs)
plot for [k=1:n] word(rundirs, k)."/pressure.dat" using (column("dphi") > 0 ? column("dphi") : NaN):"P" \
        ls 2 with linespoints title (k == 1 ? "elastic shells, one curve per packing" : ""), \
     1e-1*x ls 4 title "slope 1"
