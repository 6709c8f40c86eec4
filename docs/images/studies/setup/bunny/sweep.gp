# Written by rastersim sweep: bunny.obj, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'setup_interval' noenhanced
set xtics ('0' 0, '2' 2, '4' 4, '8' 8, '16' 16, '64' 64)
$series0 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 2284235 136844 0.059908 0.970273 0 61631 0 0.500599 0 0 0 0
4 2959279 136844 0.0462423 0.930068 0 61631 0 0.500599 0 0 0 0
8 3773743 136844 0.0362621 0.871371 0 61631 0 0.500599 0 0 0 0
16 6474807 136844 0.0211348 0.838995 0 61631 0 0.500599 0 0 0 0
64 21610567 136844 0.00633227 0.797033 0 61631 0 0.500599 0 0 0 0
EOD
$series1 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 385562 136844 0.354921 0.99745 0 61631 0 0.500599 0 0 0 0
4 415265 136844 0.329534 0.998163 0 61631 0 0.500599 0 0 0 0
8 560077 136844 0.244331 0.998507 0 61631 0 0.500599 0 0 0 0
16 1116247 136844 0.122593 0.998917 0 61631 0 0.500599 0 0 0 0
64 4458823 136844 0.0306906 0.9984 0 61631 0 0.500599 0 0 0 0
EOD
$series2 << EOD
0 104211316 136844 0.00131314 1 0 61631 0 0.500599 0 0 0 0
2 377881 136844 0.362135 0.997168 0 61631 0 0.500599 0 0 0 0
4 380912 136844 0.359254 0.997779 0 61631 0 0.500599 0 0 0 0
8 559789 136844 0.244456 0.998533 0 61631 0 0.500599 0 0 0 0
16 1115879 136844 0.122633 0.999001 0 61631 0 0.500599 0 0 0 0
64 4458823 136844 0.0306906 0.9984 0 61631 0 0.500599 0 0 0 0
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
