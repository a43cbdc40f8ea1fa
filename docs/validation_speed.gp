set terminal pngcairo size 900,600
set output 'validation_speed.png'
set logscale xy
set xlabel 'ship speed U [m/s] (model scale)'
set ylabel 'resistance R [N] (model scale)'
set termoption noenhanced
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set key left top
set grid
set title 'Speed sweep: R = a U^n (least squares in log-log)'
plot 'validation_speed.dat' index 0 using 1:2:3 with yerrorbars pt 7 lc 1 title 'liggghts both', 46.50916451684066 * x**1.1987144823128946 with lines lc 1 title 'fit n = 1.20', 'validation_speed.dat' index 1 using 1:2:3 with yerrorbars pt 7 lc 2 title 'liggghts drag', 43.416626070905195 * x**1.1679101417561968 with lines lc 2 title 'fit n = 1.17'
