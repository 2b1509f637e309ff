# spd-fig28: (a) void ratio e and (b) Delta V_s/Delta V against sigma/sigma* (log axis), loading solid,
# unloading dashed, four sets.
set multiplot layout 1,2
set logscale x
set format x "10^{%L}"
set xlabel "{/Symbol s} / {/Symbol s}*"
set key bottom left
titles = "'{/Symbol h} = 0' '{/Symbol h} = 1' '{/Symbol h} = {/Symbol \245}' '{/Symbol h} = 0, plastic'"
colors = "#1f77b4 #d62728 #2ca02c #9467bd"
positive(x) = x > 0 ? x : NaN
set ylabel "e"
set title "(a)"
plot for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 1 ? positive(column("sigma_over_sigmastar")) : NaN):"e" with lines lw 2 lc rgb word(colors, k) title word(titles, k), \
     for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 0 ? positive(column("sigma_over_sigmastar")) : NaN):"e" with lines lw 2 dt 2 lc rgb word(colors, k) notitle
set ylabel "{/Symbol D}V_s / {/Symbol D}V"
set title "(b)"
set key top left
plot for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 1 ? positive(column("sigma_over_sigmastar")) : NaN):"dVs_over_dV" with lines lw 2 lc rgb word(colors, k) title word(titles, k), \
     for [k=1:4] word(rundirs, k).'/compaction.dat' using (column("loading") == 0 ? positive(column("sigma_over_sigmastar")) : NaN):"dVs_over_dV" with lines lw 2 dt 2 lc rgb word(colors, k) notitle
unset multiplot
