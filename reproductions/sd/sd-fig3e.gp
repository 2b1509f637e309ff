# SD Fig. 3e: |h-dot|(h) in units of V = F/(eta R) for each kappa.
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "h / R"
set ylabel "|dh/dt| / V"
set key outside right
set xrange [1e-7:200]
plot for [k=0:runs-1] run_file(k, "approach.dat") using (column("h")):(-column("h_dot")) with lines lw 2 title kappa_title(k), \
     [1:200] 1/(6*pi) ls 4 title "Stokes 1/(6{/Symbol p})", [1e-4:1] x/(6*pi) ls 4 title "Poiseuille (h/R)/(6{/Symbol p})"
