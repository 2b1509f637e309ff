# vsm-fig6: the L-shaped block in its reference configuration (particles), the loaded faces X1 = 6 (T1) and
# X2 = 10 (T2 = -T1) marked by the particles next to them, from shapes.dat at t = 0.
unset key
set view equal xyz
set view 60, 30
set xyplane at 0
set xlabel "X_1 [m]"; set ylabel "X_2 [m]"; set zlabel "X_3 [m]"
file = word(rundirs, 1)."/shapes.dat"
loaded(x1, x2) = (x1 > 6 - spacing || x2 > 10 - spacing) ? 1 : 0
set title "L-shaped block: loaded faces X_1 = 6 m (T_1) and X_2 = 10 m (T_2 = -T_1) in red"
splot file using (column("t") < 1e-9 && !loaded(column("x1"), column("x2")) ? column("x1") : NaN):"x2":"x3" \
        with points pt 7 ps 0.8 lc rgb '#888888', \
      file using (column("t") < 1e-9 && loaded(column("x1"), column("x2")) ? column("x1") : NaN):"x2":"x3" \
        with points pt 7 ps 0.8 lc rgb '#d62728'
