set terminal pngcairo size 1100,650
set output 'paper_bars.png'
set termoption noenhanced
set style fill solid 0.85 border -1
set boxwidth 0.6
set grid ytics
set yrange [0:*]
set xtics rotate by -30 scale 0
set bmargin 9
set rmargin 14
set ylabel 'full-scale resistance [kN] (model x lambda^3)'
set title 'Full-scale resistance, our paper-case runs with CI95 vs the paper (Fig. 6 analog)'
plot 'paper_bars.dat' using 0:2:(0.6):4:xtic(1) with boxes lc rgb variable notitle, \
     '' using 0:2:3 with yerrorbars lc rgb 'black' pt 7 ps 0 notitle
