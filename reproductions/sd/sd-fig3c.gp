# SD Fig. 3c: delta(h) for each kappa (the paper draws a 3D plot over (h/R, kappa); a family of curves here).
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "h / R"
set ylabel "{/Symbol d} / R"
set key outside right
set xrange [1e-7:200]
plot for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(column("delta")) with lines lw 2 title kappa_title(k)
