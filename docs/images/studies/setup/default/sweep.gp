# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'setup_interval' noenhanced
set xtics ('0' 0, '2' 2, '4' 4, '8' 8, '16' 16, '64' 64)
$series0 << EOD
0 8850111 295019 0.0333351 0.997854 0 59401 0 0.557158 0 0 0 0
2 396960 295019 0.743196 0.386659 0 59401 0 0.557158 0 0 0 0
4 428958 295019 0.687757 0.437292 0 59401 0 0.557158 0 0 0 0
8 486150 295019 0.606848 0.47935 0 59401 0 0.557158 0 0 0 0
16 652824 295019 0.451912 0.565855 0 59401 0 0.557158 0 0 0 0
64 1598840 295019 0.184521 0.685935 0 59401 0 0.557158 0 0 0 0
EOD
$series1 << EOD
0 8831178 295019 0.0334065 0.999994 0 59401 0 0.557158 0 0 0 0
2 358671 295019 0.822534 0.329207 0 59401 0 0.557158 0 0 0 0
4 358832 295019 0.822165 0.362454 0 59401 0 0.557158 0 0 0 0
8 359697 295019 0.820188 0.390017 0 59401 0 0.557158 0 0 0 0
16 367411 295019 0.802967 0.444143 0 59401 0 0.557158 0 0 0 0
64 567864 295019 0.519524 0.717677 0 59401 0 0.557158 0 0 0 0
EOD
$series2 << EOD
0 8831178 295019 0.0334065 0.999994 0 59401 0 0.557158 0 0 0 0
2 358641 295019 0.822603 0.328554 0 59401 0 0.557158 0 0 0 0
4 358664 295019 0.82255 0.361472 0 59401 0 0.557158 0 0 0 0
8 359038 295019 0.821693 0.388115 0 59401 0 0.557158 0 0 0 0
16 365859 295019 0.806373 0.440959 0 59401 0 0.557158 0 0 0 0
64 566814 295019 0.520486 0.718324 0 59401 0 0.557158 0 0 0 0
EOD
set output 'cycles.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:2 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'fragments.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:3 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'fragments_per_clock.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:4 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'setup_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:5 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'stall_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:6 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'depth_fails.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:7 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'wrong_depth_tests.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:8 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
set output 'max_depth_error.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=1' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=8' noenhanced, $series2 using 1:9 with linespoints pointtype 7 title 'setup_fifo_depth=16' noenhanced
