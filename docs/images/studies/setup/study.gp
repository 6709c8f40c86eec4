set terminal pngcairo size 1100,460 font ',10'
set output 'cycles_vs_setup_luts.png'
set datafile separator ','
set multiplot layout 1,2 title 'Setup unit: frame cycles against iCE40 LUTs (labels: setup\_interval; 0 = serial)'
set xlabel 'setup unit, iCE40 LUTs (yosys synth\_ice40)'
set ylabel 'frame cycles'
set logscale y
set key top right
set grid
set title 'scene default'
plot 'study.csv' using 6:(strcol(1) eq 'default' && $3 == 1 ? $4 : 1/0) with points pt 6 ps 1.6 title 'setup\_fifo\_depth 1', 'study.csv' using 6:(strcol(1) eq 'default' && $3 == 1 ? $4 : 1/0):(stringcolumn(2)) with labels offset 1.2,0.8 notitle, 'study.csv' using 6:(strcol(1) eq 'default' && $3 == 8 ? $4 : 1/0) with points pt 8 ps 1.6 title 'setup\_fifo\_depth 8', 'study.csv' using 6:(strcol(1) eq 'default' && $3 == 16 ? $4 : 1/0) with points pt 2 ps 1.6 title 'setup\_fifo\_depth 16', 'study.csv' using 6:(strcol(1) eq 'default' && $3 == 16 ? $4 : 1/0):(stringcolumn(2)) with labels offset 1.2,-0.8 notitle
set title 'bunny.obj (69,666 triangles)'
plot 'study.csv' using 6:(strcol(1) eq 'bunny' && $3 == 1 ? $4 : 1/0) with points pt 6 ps 1.6 title 'setup\_fifo\_depth 1', 'study.csv' using 6:(strcol(1) eq 'bunny' && $3 == 1 ? $4 : 1/0):(stringcolumn(2)) with labels offset 1.2,0.8 notitle, 'study.csv' using 6:(strcol(1) eq 'bunny' && $3 == 8 ? $4 : 1/0) with points pt 8 ps 1.6 title 'setup\_fifo\_depth 8', 'study.csv' using 6:(strcol(1) eq 'bunny' && $3 == 16 ? $4 : 1/0) with points pt 2 ps 1.6 title 'setup\_fifo\_depth 16', 'study.csv' using 6:(strcol(1) eq 'bunny' && $3 == 16 ? $4 : 1/0):(stringcolumn(2)) with labels offset 1.2,-0.8 notitle
unset multiplot
