# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'setup_interval' noenhanced
set yrange [0:*]
set xtics ('0' 0, '2' 2, '4' 4, '8' 8, '16' 16, '64' 64)
$series0 << EOD
0 8848859 295019 0.0333398 0.997996 0 59401 0 0.557158 0 0 0 0
2 395939 295019 0.745112 0.47376 0 59401 0 0.557158 0 0 0 0
4 445926 295019 0.661587 0.522589 0 59401 0 0.557158 0 0 0 0
8 508501 295019 0.580174 0.547672 0 59401 0 0.557158 0 0 0 0
16 722133 295019 0.408538 0.637439 0 59401 0 0.557158 0 0 0 0
64 1932789 295019 0.152639 0.755565 0 59401 0 0.557158 0 0 0 0
EOD
$series1 << EOD
0 8831175 295019 0.0334065 0.999994 0 59401 0 0.557158 0 0 0 0
2 305919 295019 0.96437 0.333814 0 59401 0 0.557158 0 0 0 0
4 306591 295019 0.962256 0.35459 0 59401 0 0.557158 0 0 0 0
8 308691 295019 0.95571 0.372978 0 59401 0 0.557158 0 0 0 0
16 322671 295019 0.914303 0.438428 0 59401 0 0.557158 0 0 0 0
64 551733 295019 0.534713 0.768707 0 59401 0 0.557158 0 0 0 0
EOD
$series2 << EOD
0 8831175 295019 0.0334065 0.999994 0 59401 0 0.557158 0 0 0 0
2 305449 295019 0.965854 0.331934 0 59401 0 0.557158 0 0 0 0
4 305643 295019 0.96524 0.3516 0 59401 0 0.557158 0 0 0 0
8 307891 295019 0.958193 0.370517 0 59401 0 0.557158 0 0 0 0
16 320973 295019 0.91914 0.43547 0 59401 0 0.557158 0 0 0 0
64 550197 295019 0.536206 0.769452 0 59401 0 0.557158 0 0 0 0
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
