# Written by rastersim sweep: scene default, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'memory_stall_percent' noenhanced
set yrange [0:*]
set xtics ('0' 0, '10' 10, '20' 20, '30' 30, '40' 40, '60' 60)
$series0 << EOD
0 2943224 295019 0.100237 0.0681885 0 59401 0 0.557158 0 0 0 0
10 2975872 295019 0.099137 0.0679935 0.0109719 59401 0 0.557158 0 0 0 0
20 3016964 295019 0.0977867 0.0676405 0.0244434 59401 0 0.557158 0 0 0 0
30 3068640 295019 0.09614 0.0671682 0.0408732 59401 0 0.557158 0 0 0 0
40 3139932 295019 0.0939571 0.0663432 0.0626514 59401 0 0.557158 0 0 0 0
60 3386511 295019 0.0871159 0.0631139 0.130905 59401 0 0.557158 0 0 0 0
EOD
$series1 << EOD
0 2943236 295019 0.100236 0.0681882 0 59401 0 0.557158 0 0 0 0
10 2975884 295019 0.0991366 0.0679932 0.0109719 59401 0 0.557158 0 0 0 0
20 3016976 295019 0.0977863 0.0676402 0.0244433 59401 0 0.557158 0 0 0 0
30 3068652 295019 0.0961396 0.0671679 0.040873 59401 0 0.557158 0 0 0 0
40 3139944 295019 0.0939568 0.0663429 0.0626511 59401 0 0.557158 0 0 0 0
60 3386523 295019 0.0871156 0.0631137 0.130905 59401 0 0.557158 0 0 0 0
EOD
$series2 << EOD
0 306590 295019 0.962259 0.354591 0 59401 0 0.557158 0 0 0 0
10 339190 295019 0.869775 0.343698 0.0965182 59401 0 0.557158 0 0 0 0
20 380239 295019 0.775878 0.330766 0.194501 59401 0 0.557158 0 0 0 0
30 432760 295019 0.681715 0.316323 0.292684 59401 0 0.557158 0 0 0 0
40 502724 295019 0.586841 0.297527 0.39125 59401 0 0.557158 0 0 0 0
60 747592 295019 0.394626 0.234663 0.590999 59401 0 0.557158 0 0 0 0
EOD
$series3 << EOD
0 306637 295019 0.962112 0.354559 0.000127186 59401 0 0.557158 0 0 0 0
10 339205 295019 0.869737 0.343789 0.0965552 59401 0 0.557158 0 0 0 0
20 380280 295019 0.775794 0.330885 0.194567 59401 0 0.557158 0 0 0 0
30 432848 295019 0.681576 0.316384 0.292756 59401 0 0.557158 0 0 0 0
40 502739 295019 0.586823 0.297484 0.391249 59401 0 0.557158 0 0 0 0
60 747607 295019 0.394618 0.234613 0.590984 59401 0 0.557158 0 0 0 0
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
