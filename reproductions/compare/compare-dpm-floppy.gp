# compare-dpm-floppy: zero modes of a single DPM particle against N (scene dpm.modes, A0 = 1.1): (a) the count,
# with the Maxwell count N - 1 of the floppy particle and the 3 rigid motions of the shell and the
# surface-tension particle; (b) the largest 'zero' and the smallest non-zero eigenvalue (the spectral gap).
model(k, c) = column("model_index") == k ? c : NaN
set multiplot layout 1, 2
set key font ",10" spacing 0.9 samplen 2
set xlabel "vertices N"
set xrange [0 : 52]

set title "(a) zero modes"
set ylabel "zero modes (rigid motions included)"
set yrange [0 : 50]
set key top left
plot x - 1 ls 4 title "Maxwell: 2N - (N + 1) = N - 1", \
     3 ls 4 lc rgb '#888888' title "3 rigid motions", \
     datafile using (model(0, column("nodes"))):"zero_modes" ls 1 with points title "floppy (k_l, k_a)", \
     datafile using (model(1, column("nodes"))):"zero_modes" ls 2 pt 6 ps 1.5 with points title "shell (k_l, k_b, k_a)", \
     datafile using (model(2, column("nodes"))):"zero_modes" ls 3 with points title "surface tension ({/Symbol g}, k_a)"

set title "(b) the spectral gap"
set logscale x
set xrange [6 : 64]
set xtics (8, 12, 16, 24, 32, 48)
set ylabel "eigenvalue [k_a a_0]"
set logscale y
set format y "10^{%T}"
set yrange [1e-18 : 10]
set key center right
plot datafile using (model(0, column("nodes"))):"lambda_smallest_nonzero" ls 1 with linespoints title "floppy: softest non-zero", \
     datafile using (model(1, column("nodes"))):"lambda_smallest_nonzero" ls 2 pt 6 ps 1.5 with linespoints title "shell", \
     datafile using (model(2, column("nodes"))):"lambda_smallest_nonzero" ls 3 with linespoints title "surface tension", \
     datafile using (model(0, column("nodes"))):"lambda_largest_zero" ls 1 pt 2 with points title "largest 'zero' (round-off), each model", \
     datafile using (model(1, column("nodes"))):"lambda_largest_zero" ls 2 pt 2 with points notitle, \
     datafile using (model(2, column("nodes"))):"lambda_largest_zero" ls 3 pt 2 with points notitle, \
     1e-13 ls 4 title "zero threshold 10^{-13}"
unset multiplot
