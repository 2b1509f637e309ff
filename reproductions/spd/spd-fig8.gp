# spd-fig8: delta_max/delta_th against 1/N, with the exact discrete hinge-chain ratios.
set xlabel "1 / N"
set ylabel "{/Symbol d}_{max} / {/Symbol d}_{max}^{th}"
set key top left
set xrange [0:0.12]
set yrange [0.98:1.22]
cbr(n) = (n) * (2*(n-1) + 1) / (2.0 * (n-1)**2)
ssr(n) = 1 + 2.0 / (n-1)**2
set samples 400
plot datafile using (column("support_index") == 0 ? column("inverse_nodes") : NaN):"ratio" ls 1 with points title "CB, softgrain", \
     cbr(1/x) ls 1 dt 2 lw 1 title "CB, (n+1)(2n+1)/(2n^2)", \
     datafile using (column("support_index") == 1 ? column("inverse_nodes") : NaN):"ratio" ls 2 with points title "SSB, softgrain", \
     ssr(1/x) ls 2 dt 2 lw 1 title "SSB, 1 + 2/n^2", \
     1 ls 4 notitle
