# DPM-Fig9.15b: |lambda~_k| of jammed 3D packings of floppy / shell / surface-tension particles at P_t (runs in
# sweep order: floppy, shell, surface tension).
set logscale y
set format y "10^{%T}"
set xlabel "mode index k"
set ylabel "|{/Symbol l}~_k|  (k_v v_0^{4/3})"
set yrange [1e-18:1e2]
set key bottom right
f(d) = word(rundirs, d)."/eigenvalues.dat"
plot f(1) using "k":"abs_lambda" ls 1 with linespoints title "floppy packing", \
     f(2) using "k":"abs_lambda" ls 2 with linespoints title "elastic-shell packing", \
     f(3) using "k":"abs_lambda" ls 3 with linespoints title "surface-tension packing", \
     1e-10 ls 4 title "zero-mode threshold 10^{-10}"
