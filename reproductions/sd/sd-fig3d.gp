# SD Fig. 3d: local exponent lambda1 = d ln delta / d ln h; theory 0 (Stokes), -1/2 (Poiseuille), 0 (Hertz).
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
set logscale x
set format x "10^{%T}"
set xlabel "h / R"
set ylabel "{/Symbol l}_1"
set key outside right
set xrange [1e-7:200]
set yrange [-0.6:0.1]
plot for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(column("lambda1")) with lines lw 2 title kappa_title(k), \
     -0.5 ls 4 title "Poiseuille -1/2", 0 ls 4 title "Stokes, Hertz 0"
