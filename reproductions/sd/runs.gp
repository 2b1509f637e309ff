# Shared helpers of the SD figures: the data file of run k of this figure and the kappa of each run.
# The driver passes each run's output directory in `rundirs`, in sweep order (k = 0 is the first word),
# wherever the runs live (beside the figure, or shared between figures under make reproduce-figures).
run_file(k, name) = word(rundirs, k+1)."/".name
stats datafile using (column("kappa")) nooutput
runs = STATS_records
array kappa_of[runs]
do for [k=0:runs-1] {
    stats datafile using (column("kappa")) every ::k::k nooutput
    kappa_of[k+1] = STATS_min
}
kappa_title(k) = sprintf("{/Symbol k} = %g", kappa_of[k+1])
