set terminal pngcairo size 880,600 font 'Sans,11' noenhanced
set output 'docs/compare_quick/.compare.png.tmp11906'
set title 'Full-scale ice resistance per run (bars, 95 % CI) and FSICR R_CH (points)'
set ylabel 'resistance [kN]'
set yrange [0:*]
set offsets 0, 0, graph 0.12, 0
set bmargin 6
set xrange [-0.6:3.6]
set style fill solid 0.7 border -1
set boxwidth 0.6
set grid ytics
set key top right
plot 'docs/compare_quick/post/compare.dat' using 1:3:xtic(2) with boxes lc rgb '#2e86c1' title 'simulation', \
     '' using 1:3:4 with yerrorbars lc rgb 'black' pt -1 lw 2 notitle, \
     '' using 1:5 with points pt 7 ps 2 lc rgb '#c0392b' title 'FSICR R_CH', \
     393 with lines dt 2 lc rgb '#888888' title 'paper added mass 393 kN'

unset output
