# spd-fig31: the yield surface of eq. (39), alpha = 2, in the (f_t/f_t^0, f_n/|f_n^0|) plane: the library's
# zeta = 0 curve (line), its closed form f_n = f_n^0 (1 - (f_t/f_t^0)^2) (dashed), and the forces of the links
# when they broke in the run (points, just outside: a link breaks at the first step beyond zeta = 0).
set xlabel "f_t / f_t^0"
set ylabel "f_n / |f_n^0|  (compression > 0)"
set key top center
set xrange [-2:2]
closed(x) = -(1 - x**2)
set label 1 "{/Symbol z} < 0: elastic" at 0, 0.6 center
plot word(rundirs, 1).'/yield_curve.dat' using "ft_over_ft0":"fn_over_fn0" with lines ls 1 title "{/Symbol z} = 0, library (eq. 39)", \
     closed(x) with lines ls 4 title "f_n^0 (1 - (f_t/f_t^0)^2), closed form", \
     word(rundirs, 1).'/broken.dat' using "ft_over_ft0":"fn_over_fn0" with points ls 2 title "links at breaking"
