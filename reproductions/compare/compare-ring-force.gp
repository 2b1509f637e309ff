# compare-ring-force: F R^2/B against eps for SPD and DPM at the finest resolution of the figure, with the
# elastica. rundirs (the manifest's sweep order): SPD at N/2 and N, then DPM at N/2 and N.
set xlabel "{/Symbol e} = 1 - b/b_0"
set ylabel "F R^2 / B"
set key top left
spd = word(rundirs, 2).'/ring.dat'
dpm = word(rundirs, 4).'/ring.dat'
plot spd using "eps":"elastica_F_R2_over_B" ls 4 lc rgb '#000000' dt 1 with lines title "elastica (inextensible)", \
     spd using "eps":"F_R2_over_B" ls 1 with points title "SPD, {/Symbol h} = 0, finest N", \
     dpm using "eps":"F_R2_over_B" ls 2 pt 6 ps 2 with points title "DPM shell (k_a = 0), finest N"
