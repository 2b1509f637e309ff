# SD Fig. 3f: local exponent lambda2 = d ln|h-dot| / d ln h; theory 0, 1, 3 (Stokes, Poiseuille, Hertz).
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
set logscale x
set format x "10^{%T}"
set xlabel "h / R"
set ylabel "{/Symbol l}_2"
set key outside right
set xrange [1e-7:200]
set yrange [-0.2:3.3]
plot for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(column("lambda2")) with lines lw 2 title kappa_title(k), \
     0 ls 4 notitle, 1 ls 4 notitle, 3 ls 4 title "theory 0, 1, 3"
