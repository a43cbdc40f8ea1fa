set terminal pngcairo size 900,600
set output 'performance_pareto.png'
set termoption noenhanced
set xlabel 'speed-up over the reference (summed wall time of the ensemble)'
set ylabel 'mean resistance: paired difference to the reference [%]'
set grid
set key right center
set title 'Run time vs error (jbc_quick, paired-seed ensembles; bars: 95 % CI)'
set offsets graph 0.1, graph 0.1, graph 0.1, graph 0.1
plot 2 with lines dt 2 lc 'grey' title '+-2 %', -2 with lines dt 2 lc 'grey' notitle, 'performance_pareto.dat' index 0 using 1:2:3 with yerrorbars pt 7 ps 1.5 lc 1 title 'knob', '' index 0 using 1:2:4 with labels offset 2,1 notitle, '' index 1 using 1:2 with points pt 5 ps 1.5 lc 2 title 'reference'
