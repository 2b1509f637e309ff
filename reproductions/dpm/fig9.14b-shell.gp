# DPM-Fig9.14b-shell: |lambda~_k| of a jammed packing of elastic shells.
set logscale y
set format y "10^{%T}"
set xlabel "mode index k"
set ylabel "|{/Symbol l}~_k|  (k_a a_0)"
set yrange [1e-18:1e3]
set key bottom right
plot word(rundirs, 1)."/eigenvalues.dat" using "k":"abs_lambda" ls 2 with points title "jammed elastic shells, N = 16", \
     1e-13 ls 4 title "zero-mode threshold 10^{-13}"
