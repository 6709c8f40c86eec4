# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'memory_stall_percent' noenhanced
set xtics ('0' 0, '10' 10, '20' 20, '30' 30, '40' 40, '60' 60)
$series0 << EOD
0 3074550 295019 0.0959552 0.131237 0 59401 0 0.557158 0 0 0 0
10 3101394 295019 0.0951246 0.130101 0.0105153 59401 0 0.557158 0 0 0 0
20 3135218 295019 0.0940984 0.128698 0.0233521 59401 0 0.557158 0 0 0 0
30 3179646 295019 0.0927836 0.1269 0.0397101 59401 0 0.557158 0 0 0 0
40 3240961 295019 0.0910282 0.124499 0.0608039 59401 0 0.557158 0 0 0 0
60 3463417 295019 0.0851815 0.116502 0.127494 59401 0 0.557158 0 0 0 0
EOD
$series1 << EOD
0 3074562 295019 0.0959548 0.131237 0 59401 0 0.557158 0 0 0 0
10 3101406 295019 0.0951243 0.130101 0.0105152 59401 0 0.557158 0 0 0 0
20 3135230 295019 0.094098 0.128697 0.023352 59401 0 0.557158 0 0 0 0
30 3179658 295019 0.0927832 0.126899 0.0397099 59401 0 0.557158 0 0 0 0
40 3240973 295019 0.0910279 0.124498 0.0608037 59401 0 0.557158 0 0 0 0
60 3463429 295019 0.0851812 0.116502 0.127494 59401 0 0.557158 0 0 0 0
EOD
$series2 << EOD
0 604774 295019 0.487817 0.667185 0 59401 0 0.557158 0 0 0 0
10 628320 295019 0.469536 0.642182 0.0521486 59401 0 0.557158 0 0 0 0
20 657995 295019 0.448361 0.61322 0.112188 59401 0 0.557158 0 0 0 0
30 696727 295019 0.423436 0.579131 0.181275 59401 0 0.557158 0 0 0 0
40 749773 295019 0.393478 0.538158 0.261777 59401 0 0.557158 0 0 0 0
60 945586 295019 0.311996 0.426715 0.466785 59401 0 0.557158 0 0 0 0
EOD
$series3 << EOD
0 604789 295019 0.487805 0.667168 0 59401 0 0.557158 0 0 0 0
10 628335 295019 0.469525 0.642167 0.0521473 59401 0 0.557158 0 0 0 0
20 658010 295019 0.44835 0.613206 0.112185 59401 0 0.557158 0 0 0 0
30 696742 295019 0.423426 0.579118 0.181271 59401 0 0.557158 0 0 0 0
40 749788 295019 0.39347 0.538147 0.261771 59401 0 0.557158 0 0 0 0
60 945601 295019 0.311991 0.426709 0.466777 59401 0 0.557158 0 0 0 0
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
