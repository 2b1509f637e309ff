# DPM-Fig9.15c: Delta U against Delta r along every mode of a jammed 3D packing of floppy particles (soft
# modes, lambda~ < 1e-4, drawn larger).
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "{/Symbol D}r  (v_0^{1/3})"
set ylabel "{/Symbol D}U  (k_v v_0^2)"
set yrange [1e-14:*]
set key top left
set palette defined (0 "dark-blue", 1 "cyan", 2 "yellow", 3 "dark-red")
set cblabel "mode index k"
f = word(rundirs, 1)."/mode_energy.dat"
plot f using "dr":(column("zero_mode") == 0 && column("dU") > 0 ? column("dU") : NaN):"k" \
       with points pt 7 ps 0.3 lc palette notitle, \
     f using "dr":(column("zero_mode") == 0 && column("lambda") < 1e-4 && column("dU") > 0 ? column("dU") : NaN) \
       with points pt 6 ps 0.6 lc rgb "black" title "soft modes ({/Symbol l}~ < 10^{-4})", \
     1e-2*x**2 ls 8 dt 2 title "{/Symbol D}U ~ {/Symbol D}r^2", 1e-1*x**4 ls 8 dt 4 title "{/Symbol D}U ~ {/Symbol D}r^4"
