# spd-fig7: delta/delta_max along the beams (21 nodes), from each run's profile.dat.
set xlabel "x / L"
set ylabel "{/Symbol d} / {/Symbol d}_{max}"
set key bottom right
set xrange [0:1]
set yrange [0:1.1]
cb = word(rundirs, 1).'/profile.dat'
ss = word(rundirs, 2).'/profile.dat'
plot cb using "x_over_L":"delta_over_max" ls 1 with points title "CB, softgrain (21 nodes)", \
     cb using "x_over_L":"theory" ls 1 dt 1 lw 1 with lines title "CB, eq. (14)", \
     ss using "x_over_L":"delta_over_max" ls 2 with points title "SSB, softgrain (21 nodes)", \
     ss using "x_over_L":"theory" ls 2 dt 1 lw 1 with lines title "SSB, point load 3{/Symbol x} - 4{/Symbol x}^3", \
     ss using "x_over_L":"eq16_printed" ls 4 with lines title "SSB, eq. (16) as printed (uniform load)"
