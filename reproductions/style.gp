# Shared style of every softgrain figure; loaded before each figure's own script.
# The driver defines: the terminal and output, `datafile` (the reduced table), and each numeric base
# parameter of the figure as a gnuplot variable.
set datafile columnheaders
set grid lc rgb '#dddddd'
set key top left box opaque
set style line 1 lc rgb '#1f77b4' lw 2 pt 7 ps 1.2
set style line 2 lc rgb '#d62728' lw 2 pt 5 ps 1.2
set style line 3 lc rgb '#2ca02c' lw 2 pt 9 ps 1.2
set style line 4 lc rgb '#000000' lw 1.5 dt 2
