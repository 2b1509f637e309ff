# DPM-Fig9.13ef: a smooth-disk packing (e) before and (f) after the compression step with the first irreversible
# change of its contact network. Contacts in both networks black, broken ones (only before) green, formed ones
# (only after) red; disks whose contacts changed are shaded.
dir = word(rundirs, 1)
disks = dir.'/disks.dat'
contacts = dir.'/contacts.dat'
stats dir.'/box.dat' using "L" nooutput
L = STATS_max
set size ratio -1
unset key
unset grid
set xrange [0:L]
set yrange [0:L]
set xlabel "x / {/Symbol s}_{small}"
set ylabel "y / {/Symbol s}_{small}"
set object 1 rectangle from 0,0 to L,L fillstyle empty border lc rgb '#888888' back
on(state, value) = column("state") == state ? value : NaN
kind(state, k) = column("state") == state && column("kind") == k ? column("dx") : NaN
set multiplot layout 1,2
do for [state=0:1] {
    set title (state == 0 ? "(e) before" : "(f) after the step")
    plot disks using (on(state, column("x"))):"y":(column("diameter") / 2):(column("changed") > 0.5 ? 0x9ecae1 : 0xeeeeee) \
            with circles lc rgb variable fs solid 1.0 border lc rgb '#999999', \
         contacts using (on(state, column("x"))):"y":(kind(state, 0)):"dy" with vectors nohead lc rgb 'black' lw 1.5, \
         contacts using (on(state, column("x"))):"y":(kind(state, 1)):"dy" with vectors nohead lc rgb '#2ca02c' lw 3, \
         contacts using (on(state, column("x"))):"y":(kind(state, 2)):"dy" with vectors nohead lc rgb '#d62728' lw 3
}
unset multiplot
