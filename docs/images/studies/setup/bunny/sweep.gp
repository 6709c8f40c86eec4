# Written by rastersim sweep: bunny.obj, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'setup_interval' noenhanced
set yrange [0:*]
set xtics ('0' 0, '2' 2, '4' 4, '8' 8, '16' 16, '64' 64)
$series0 << EOD
0 104211315 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 2283886 136844 0.0599172 0.970421 0 61631 0 0.500599 0 0 0 0
4 2959074 136844 0.0462455 0.930133 0 61631 0 0.500599 0 0 0 0
8 3773638 136844 0.0362631 0.871396 0 61631 0 0.500599 0 0 0 0
16 6474758 136844 0.021135 0.839002 0 61631 0 0.500599 0 0 0 0
64 21610566 136844 0.00633227 0.797033 0 61631 0 0.500599 0 0 0 0
EOD
$series1 << EOD
0 104211315 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 292031 136844 0.468594 0.997966 1.36972e-05 61631 0 0.500599 0 0 0 0
4 375585 136844 0.364349 0.998759 0 61631 0 0.500599 0 0 0 0
8 558894 136844 0.244848 0.99883 0 61631 0 0.500599 0 0 0 0
16 1115494 136844 0.122676 0.999029 0 61631 0 0.500599 0 0 0 0
64 4458822 136844 0.0306906 0.9984 0 61631 0 0.500599 0 0 0 0
EOD
$series2 << EOD
0 104211315 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 208291 136844 0.656985 0.99686 3.84078e-05 61631 0 0.500599 0 0 0 0
4 280806 136844 0.487326 0.998209 7.12235e-06 61631 0 0.500599 0 0 0 0
8 558662 136844 0.24495 0.998971 0 61631 0 0.500599 0 0 0 0
16 1115110 136844 0.122718 0.999085 0 61631 0 0.500599 0 0 0 0
64 4458822 136844 0.0306906 0.9984 0 61631 0 0.500599 0 0 0 0
EOD
set output 'cycles.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'fragments.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'fragments_per_clock.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'setup_share.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'stall_share.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'depth_fails.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'wrong_depth_tests.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'max_depth_error.png'
set title 'bunny.obj, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
