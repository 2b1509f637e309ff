# Work-precision of GSL steppers on sd.approach: error of h(t) in the Hertz regime against integration wall time.
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "integration wall time (s, best of repeats)"
set ylabel "max relative error of h(t), Hertz regime"
set key outside right
names = "rk2 rk4 rkf45 rkck rk8pd msadams rk1imp rk2imp rk4imp bsimp msbdf"
colors = "#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f #bcbd22 #17becf #000000"
plot for [i=0:10] datafile using (column("stepper_index") == i ? column("integration_wall_time_s") : NaN):(column("h_error_hertz")) \
        with linespoints lw 2 pt (i < 6 ? 7 : 5) lc rgb word(colors, i+1) title (word(names, i+1) . (i < 6 ? " (explicit)" : " (implicit)")), \
     1e-6 ls 4 title "accuracy target 10^{-6}"
