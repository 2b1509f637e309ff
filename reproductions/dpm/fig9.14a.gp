# DPM-Fig9.14a: |lambda~_k| of single floppy / shell / surface-tension particles (runs in sweep order:
# floppy A0=min, floppy 1.04, shell min, shell 1.04, surface min, surface 1.04).
set logscale y
set format y "10^{%T}"
set xlabel "mode index k"
set ylabel "|{/Symbol l}~_k|  (k_a a_0)"
set yrange [1e-18:1e2]
set key bottom right
f(d) = word(rundirs, d)."/eigenvalues.dat"
plot f(2) using "k":"abs_lambda" ls 1 with linespoints title "floppy, A_0 = 1.04", \
     f(3) using "k":"abs_lambda" ls 2 with linespoints title "elastic shell, A_0 = A_{min}", \
     f(5) using "k":"abs_lambda" ls 3 with linespoints title "surface tension, A_0 = A_{min}", \
     1e-13 ls 4 title "zero-mode threshold 10^{-13}"
