# DPM-Fig9.13bd: P against phi per packing, compression (filled symbols) and decompression (crosses), one colour
# per model. Runs are in sweep order: model outer (smooth disk, rough disk, shell), seed inner.
set logscale y
set format y "10^{%T}"
set xlabel "{/Symbol f}"
set ylabel "P  (k_c for disks, k_a a_0 for polygons)"
set key top left
n = words(rundirs)
seeds = n / 3
models = "smooth-disks rough-disks shells"
model_of(k) = 1 + (k - 1) / seeds
branch(d) = column("decompression") == d ? column("P") : NaN
plot for [k=1:n] word(rundirs, k)."/pressure.dat" using "phi":(branch(0)) ls model_of(k) pt 7 with linespoints \
        title ((k - 1) % seeds == 0 ? word(models, model_of(k))." compression" : ""), \
     for [k=1:n] word(rundirs, k)."/pressure.dat" using "phi":(branch(1)) ls model_of(k) pt 2 ps 2 with points \
        title ((k - 1) % seeds == 0 ? word(models, model_of(k))." decompression" : "")
