# spd-fig33: vertical stress over its peak against eps_h = ln(H/H0), elastic (M^Y/M* = inf) and plastic cells
# (eta = 0), and the number of broken links.
set multiplot layout 2,1
set key top right
set ylabel "{/Symbol s} / {/Symbol s}_{max}"
set yrange [-0.1:1.1]
unset xlabel
titles = "'elastic cells' 'plastic cells'"
plot for [k=1:2] word(rundirs, k).'/tissue.dat' using "eps_h":"sigma_over_sigmamax" with lines ls k title word(titles, k)
set ylabel "broken links"
set xlabel "{/Symbol e}_h = ln(H/H_0)"
set autoscale y
plot for [k=1:2] word(rundirs, k).'/tissue.dat' using "eps_h":"broken_links" with lines ls k title word(titles, k)
unset multiplot
