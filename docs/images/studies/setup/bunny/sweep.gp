# Written by rastersim sweep: bunny.obj, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'setup_interval' noenhanced
set xtics ('0' 0, '2' 2, '4' 4, '8' 8, '16' 16, '64' 64)
$series0 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 1882449 136844 0.0726947 0.963815 0 61631 0 0.500599 0 0 0 0
4 2423483 136844 0.0564658 0.914523 0 61631 0 0.500599 0 0 0 0
8 3237831 136844 0.0422641 0.850054 0 61631 0 0.500599 0 0 0 0
16 5402887 136844 0.0253279 0.807037 0 61631 0 0.500599 0 0 0 0
64 17322567 136844 0.00789975 0.746791 0 61631 0 0.500599 0 0 0 0
EOD
$series1 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 379813 136844 0.360293 0.996806 0 61631 0 0.500599 0 0 0 0
4 391292 136844 0.349723 0.99737 0 61631 0 0.500599 0 0 0 0
8 559941 136844 0.24439 0.997935 0 61631 0 0.500599 0 0 0 0
16 1116183 136844 0.1226 0.99827 0 61631 0 0.500599 0 0 0 0
64 4458759 136844 0.0306911 0.997315 0 61631 0 0.500599 0 0 0 0
EOD
$series2 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 377875 136844 0.362141 0.996562 0 61631 0 0.500599 0 0 0 0
4 380548 136844 0.359597 0.997081 0 61631 0 0.500599 0 0 0 0
8 559773 136844 0.244463 0.997978 0 61631 0 0.500599 0 0 0 0
16 1115831 136844 0.122639 0.998368 0 61631 0 0.500599 0 0 0 0
64 4458759 136844 0.0306911 0.997315 0 61631 0 0.500599 0 0 0 0
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
