# spd-fig17: F/F** against L_c/l, plastic ring, with eq. (34).
set xlabel "L_c / l"
set ylabel "F / F**"
set key top left
d = word(rundirs, 1).'/compression.dat'
plot d using (column("loading") == 1 && column("Lc_over_l") > 0 ? column("Lc_over_l") : NaN):"F_over_F2star" ls 1 with linespoints title "softgrain, M^Y/M* = 5x10^{-5}", \
     x ls 4 title "eq. (34): F/F** = L_c/l"
