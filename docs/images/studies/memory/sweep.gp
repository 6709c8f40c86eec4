# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'memory_stall_percent' noenhanced
set yrange [0:*]
set xtics ('0' 0, '10' 10, '20' 20, '30' 30, '40' 40, '60' 60)
$series0 << EOD
0 2943257 295019 0.100236 0.077136 0 59401 0 0.557158 0 0 0 0
10 2967148 295019 0.0994285 0.0768624 0.0109839 59401 0 0.557158 0 0 0 0
20 2997734 295019 0.098414 0.0765228 0.024648 59401 0 0.557158 0 0 0 0
30 3036872 295019 0.0971457 0.0761241 0.0415233 59401 0 0.557158 0 0 0 0
40 3089860 295019 0.0954797 0.0755571 0.0632579 59401 0 0.557158 0 0 0 0
60 3283797 295019 0.0898408 0.0730325 0.134517 59401 0 0.557158 0 0 0 0
EOD
$series1 << EOD
0 2943270 295019 0.100235 0.0771356 0 59401 0 0.557158 0 0 0 0
10 2967161 295019 0.099428 0.076862 0.0109839 59401 0 0.557158 0 0 0 0
20 2997748 295019 0.0984135 0.0765224 0.0246478 59401 0 0.557158 0 0 0 0
30 3036886 295019 0.0971452 0.0761237 0.0415231 59401 0 0.557158 0 0 0 0
40 3089875 295019 0.0954793 0.0755568 0.0632576 59401 0 0.557158 0 0 0 0
60 3283812 295019 0.0898404 0.0730322 0.134516 59401 0 0.557158 0 0 0 0
EOD
$series2 << EOD
0 307320 295019 0.959973 0.370165 0 59401 0 0.557158 0 0 0 0
10 339061 295019 0.870106 0.359062 0.0966935 59401 0 0.557158 0 0 0 0
20 379347 295019 0.777702 0.346176 0.195127 59401 0 0.557158 0 0 0 0
30 431004 295019 0.684492 0.332134 0.293967 59401 0 0.557158 0 0 0 0
40 499651 295019 0.59045 0.31474 0.393417 59401 0 0.557158 0 0 0 0
60 742192 295019 0.397497 0.260321 0.594951 59401 0 0.557158 0 0 0 0
EOD
$series3 << EOD
0 307335 295019 0.959926 0.370147 0.000107375 59401 0 0.557158 0 0 0 0
10 339076 295019 0.870067 0.359046 0.0967777 59401 0 0.557158 0 0 0 0
20 379362 295019 0.777671 0.346163 0.195215 59401 0 0.557158 0 0 0 0
30 431019 295019 0.684469 0.332122 0.294024 59401 0 0.557158 0 0 0 0
40 499666 295019 0.590432 0.314722 0.393463 59401 0 0.557158 0 0 0 0
60 742207 295019 0.397489 0.26034 0.595013 59401 0 0.557158 0 0 0 0
EOD
set output 'cycles.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:2 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:2 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'fragments.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:3 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:3 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'fragments_per_clock.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:4 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:4 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'setup_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:5 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:5 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'stall_share.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:6 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:6 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'depth_fails.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:7 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:7 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'wrong_depth_tests.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:8 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:8 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
set output 'max_depth_error.png'
set title 'scene default, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=1' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'traversal=bbox, memory_latency=16' noenhanced, $series2 using 1:9 with linespoints pointtype 7 title 'traversal=span, memory_latency=1' noenhanced, $series3 using 1:9 with linespoints pointtype 7 title 'traversal=span, memory_latency=16' noenhanced
