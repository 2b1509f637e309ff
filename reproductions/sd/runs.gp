# Shared helpers of the SD figures: the data file of run k of this figure and the kappa of each run.
# The driver writes the runs beside the reduced table: <datafile without .dat>/run-NNNN/<scene>/<file>.
run_dir = datafile[1:strlen(datafile)-4]
run_file(k, scene, name) = sprintf("%s/run-%04d/%s/%s", run_dir, k, scene, name)
stats datafile using (column("kappa")) nooutput
runs = STATS_records
array kappa_of[runs]
do for [k=0:runs-1] {
    stats datafile using (column("kappa")) every ::k::k nooutput
    kappa_of[k+1] = STATS_min
}
kappa_title(k) = sprintf("{/Symbol k} = %g", kappa_of[k+1])
