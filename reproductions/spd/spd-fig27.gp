# spd-fig27: sigma/sigma* against eps = ln(H0/H), loading (solid) and unloading (dashed), four sets.
set xlabel "{/Symbol e} = ln(H_0/H)"
set ylabel "{/Symbol s} / {/Symbol s}*"
set key top left
set style line 5 lc rgb '#9467bd' lw 2
titles = "'{/Symbol h} = 0' '{/Symbol h} = 1' '{/Symbol h} = {/Symbol \245}' '{/Symbol h} = 0, plastic'"
colors = "#1f77b4 #d62728 #2ca02c #9467bd"
plot for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 1 ? column("eps") : NaN):"sigma_over_sigmastar" with lines lw 2 lc rgb word(colors, k) title word(titles, k), \
     for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 0 ? column("eps") : NaN):"sigma_over_sigmastar" with lines lw 2 dt 2 lc rgb word(colors, k) notitle
