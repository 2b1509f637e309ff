# SD Fig. 4 (the method): consistency of the integrated (X, h) along each approach. Force balance eq. (1)
# |F_ela/F_ext - 1| and deflection of eq. (2) against the balanced one, |delta/delta_eq(h) - 1|.
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "h / R"
set ylabel "relative residual"
set key outside right
set xrange [1e-7:200]
set yrange [1e-17:1e-5]
plot for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(column("force_balance_residual") + 1e-17) with lines lw 2 lc (k+1) title kappa_title(k). " eq. (1)", \
     for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(column("deflection_residual") + 1e-17) with points pt 7 ps 0.3 lc (k+1) notitle
