# spd-fig29: the samples at eps = strain_max, each particle filled by W_i/<W> when above the mean, white below:
# (a) eta = 0 elastic, (b) eta = inf elastic, (c) eta = 0 plastic.
set multiplot layout 1,3
set size ratio -1
unset key
unset grid
unset xtics
unset ytics
set palette defined (1 '#ffffff', 1.001 '#ffffb2', 2 '#fd8d3c', 4 '#bd0026')
set cbrange [1:4]
set cblabel "W_i / <W>"
labels = "'(a) {/Symbol h} = 0' '(b) {/Symbol h} = {/Symbol \245}' '(c) {/Symbol h} = 0, plastic'"
do for [k=1:3] {
    set title word(labels, k)
    file = word(rundirs, k).'/snapshot.dat'
    stats file using "particle" nooutput
    n = int(STATS_max) + 1
    stats file using "snapshot" nooutput
    last = int(STATS_max) # the end of loading
    at(p) = column("snapshot") == last && column("particle") == p ? column("x_over_R") : NaN
    plot for [p=0:n-1] file using (at(p)):"y_over_R":(column("W_over_mean") > 1 ? column("W_over_mean") : 1) with filledcurves closed fc palette lw 0.5 notitle, \
         for [p=0:n-1] file using (at(p)):"y_over_R" with lines lc rgb '#333333' lw 0.8 notitle
}
unset multiplot
