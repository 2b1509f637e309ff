# SD Fig. 3a: delta/R, a/R and |h-dot|/V along one approach (kappa of the run) with the asymptotes of Fig. 3a.
load ARG0[1:strstrt(ARG0, "sd-fig")-1] . "runs.gp"  # beside this script
f = run_file(0, "approach.dat")
k = kappa_of[1]
al = 4.0/9.0
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "h / R"
set ylabel "{/Symbol d}/R,  a/R,  |dh/dt|/V"
set key bottom right
set xrange [1e-7:200]
set yrange [1e-9:10]
# Asymptotes with the prefactors of eqs. (3)-(5) (the paper's Fig. 3a gives the powers only).
dS(x) = k/(al*sqrt(2))
dP(x) = k/(al*sqrt(2))/sqrt(x)
dH(x) = (k*k/(2*al*al))**(1.0/3)
vS(x) = 1/(6*pi)
vP(x) = x/(6*pi)
vH(x) = x**3/(6*pi*dH(x)**2)
aS(x) = sqrt(2)
aP(x) = sqrt(2*x)
aH(x) = sqrt(2*dH(x))
plot f using (column("h")):(column("delta")) ls 1 with lines title "{/Symbol d}/R (sd.approach)", \
     f using (column("h")):(column("a")) ls 3 with lines title "a/R", \
     f using (column("h")):(-column("h_dot")) ls 2 with lines title "|dh/dt|/V", \
     [1:200] dS(x) ls 4 notitle, [1e-4:1] dP(x) ls 4 notitle, [1e-7:1e-3] dH(x) ls 4 title "Stokes | Poiseuille | Hertz asymptotes", \
     [1:200] vS(x) ls 4 notitle, [1e-4:1] vP(x) ls 4 notitle, [1e-7:1e-3] vH(x) ls 4 notitle, \
     [1:200] aS(x) ls 4 notitle, [1e-4:1] aP(x) ls 4 notitle, [1e-7:1e-3] aH(x) ls 4 notitle
