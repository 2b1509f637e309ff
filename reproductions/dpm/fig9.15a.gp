# DPM-Fig9.15a: |lambda~_k| of single 3D floppy / shell / surface-tension particles, N = 42 (runs in sweep
# order: floppy A0 = 1.04, shell A0 = A_min, surface tension A0 = A_min).
set logscale y
set format y "10^{%T}"
set xlabel "mode index k"
set ylabel "|{/Symbol l}~_k|  (k_v v_0^{4/3})"
set yrange [1e-18:1e2]
set key bottom right
f(d) = word(rundirs, d)."/eigenvalues.dat"
plot f(1) using "k":"abs_lambda" ls 1 with linespoints title "floppy, A_0 = 1.04", \
     f(2) using "k":"abs_lambda" ls 2 with linespoints title "elastic shell, A_0 = A_{min}", \
     f(3) using "k":"abs_lambda" ls 3 with linespoints title "surface tension, A_0 = A_{min}", \
     1e-10 ls 4 title "zero-mode threshold 10^{-10}"
