# vsm-stability: non-affine ratio against xi (per nu) and pressure roughness against nu (per xi).
set multiplot layout 1,2
set key top right
set xlabel "stabilisation factor {/Symbol x}"
set ylabel "non-affine ratio at the final deformation"
set yrange [0:1]
plot for [k = 0:2] datafile using (column("nu") == word("0.3 0.45 0.49", k + 1) + 0 ? column("xi") : NaN):"nonaffine_ratio_final" \
     ls (k + 1) with points title sprintf("nu = %s", word("0.3 0.45 0.49", k + 1))
set xlabel "Poisson's ratio {/Symbol n}"
set ylabel "pressure roughness at the final deformation"
set yrange [0:*]
set key top left
plot for [k = 0:2] datafile using (column("xi") == word("0 0.1 1", k + 1) + 0 ? column("nu") : NaN):"pressure_roughness_final" \
     ls (k + 1) with points title sprintf("xi = %s", word("0 0.1 1", k + 1))
unset multiplot
