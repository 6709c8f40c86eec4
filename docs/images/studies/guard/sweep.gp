# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'z_guard_bits' noenhanced
set yrange [0:*]
set xtics ('1' 0, '2' 1, '3' 2, '4' 3, '6' 4, '8' 5, 'auto' 6)
set xrange [-0.5:6.5]
$series0 << EOD
0 306957 295019 0.961109 0.362833 0 59401 0 151.831 0 0 0 0
1 306957 295019 0.961109 0.362833 0 59401 0 85.0593 0 0 0 0
2 306957 295019 0.961109 0.362833 0 59401 0 41.8545 0 0 0 0
3 306957 295019 0.961109 0.362833 0 59401 0 21.7101 0 0 0 0
4 306957 295019 0.961109 0.362833 0 59401 0 5.72513 0 0 0 0
5 306957 295019 0.961109 0.362833 0 59401 0 1.69077 0 0 0 0
6 307321 295019 0.95997 0.370163 0 59401 0 0.557158 0 0 0 0
EOD
set output 'cycles.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'cycles' noenhanced
set output 'fragments.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'fragments' noenhanced
set output 'fragments_per_clock.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'fragments_per_clock' noenhanced
set output 'setup_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'setup_share' noenhanced
set output 'stall_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'stall_share' noenhanced
set output 'depth_fails.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'depth_fails' noenhanced
set output 'wrong_depth_tests.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'wrong_depth_tests' noenhanced
set output 'max_depth_error.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'max_depth_error' noenhanced
