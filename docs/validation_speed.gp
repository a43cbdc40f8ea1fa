set terminal pngcairo size 900,600
set output 'validation_speed.png'
set logscale xy
set xlabel 'ship speed U [m/s] (model scale)'
set ylabel 'resistance R [N] (model scale)'
set termoption noenhanced
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set key left top
set grid
set title 'Speed sweep: each group with its preferred speed law (lowest AICc)'
plot 'validation_speed.dat' index 0 using 1:2:3 with yerrorbars pt 7 lc 1 title 'liggghts both', 6.1590526546793605 + 46.13572750582529 * x**2 with lines lc 1 title 'R = 6.16 + 46.1 U^2.00', 'validation_speed.dat' index 1 using 1:2:3 with yerrorbars pt 7 lc 2 title 'liggghts drag', 6.126838244485704 + 42.82166122079444 * x**2 with lines lc 2 title 'R = 6.13 + 42.8 U^2.00'
