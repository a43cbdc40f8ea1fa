set terminal pngcairo size 1100,550
set output 'paper_histories.png'
set termoption noenhanced
set grid
set key right bottom
set yrange [0:*]
set xlabel 'model time t [s]'
set ylabel 'full-scale resistance [kN] (-fx x lambda^3, 0.5 s means)'
set title 'The paper case: resistance histories of our runs and the paper levels'
set object 1 rect from 12,graph 0 to 20,graph 1 fc rgb '#eeeeee' fs solid 1 noborder behind
plot 'paper_histories.dat' index 0 using 1:2 with lines lw 2 title 'R28 liggghts drag', 'paper_histories.dat' index 1 using 1:2 with lines lw 2 title 'R29 liggghts added_mass', 'paper_histories.dat' index 2 using 1:2 with lines lw 2 title 'R30 liggghts both', 'paper_histories.dat' index 3 using 1:2 with lines lw 2 title 'R31 liggghts both', 'paper_histories.dat' index 4 using 1:2 with lines lw 2 title 'R32 liggghts both', 'paper_histories.dat' index 5 using 1:2 with lines lw 2 title 'R37 ode drag (in progress, t = 3.5 s)', 393 with lines dt 2 lc rgb 'black' title 'paper added mass (393 kN)', 378 with lines dt 3 lc rgb 'black' title 'paper drag (378 kN)'
