set terminal pngcairo size 900,600
set output 'study_speed.png'
set logscale xy
set xlabel 'ship speed U [m/s] (model scale)'
set ylabel 'resistance R [N] (model scale)'
set termoption noenhanced
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set key left top
set grid
set title 'Speed sweep: R = a U^n (least squares in log-log)'
plot 'study_speed.dat' index 0 using 1:2:3 with yerrorbars pt 7 lc 1 title 'liggghts added_mass', 29.69402744473343 * x**1.2513465364572594 with lines lc 1 title 'fit n = 1.25', 'study_speed.dat' index 1 using 1:2:3 with yerrorbars pt 7 lc 2 title 'liggghts drag', 30.899032071966996 * x**1.2942809426275992 with lines lc 2 title 'fit n = 1.29'
