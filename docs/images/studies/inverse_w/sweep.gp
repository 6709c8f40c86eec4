# Written by rastersim sweep: zfight.json, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'near' noenhanced
set yrange [0:*]
set logscale x
set xtics ('0.01' 0.01, '0.03' 0.03, '0.1' 0.1, '0.3' 0.3, '1' 1)
$series0 << EOD
0.01 187585 187486 0.999472 0.000282539 0 76949 12675 0.584793 0 0 0 0
0.03 187585 187486 0.999472 0.000282539 0 69414 5118 0.604419 0 0 0 0
0.1 187585 187486 0.999472 0.000282539 0 66650 2354 0.590713 0 0 0 0
0.3 187585 187486 0.999472 0.000282539 0 64746 454 0.638418 0 0 0 0
1 187585 187486 0.999472 0.000282539 0 64420 126 0.653662 0 0 0 0
EOD
$series1 << EOD
0.01 187593 187486 0.99943 0.000325172 0 64404 108 15.5386 0 0 0 0
0.03 187593 187486 0.99943 0.000325172 0 64393 97 63.5579 0 0 0 0
0.1 187593 187486 0.99943 0.000325172 0 64379 83 255.598 0 0 0 0
0.3 187593 187486 0.99943 0.000325172 0 64394 98 511.572 0 0 0 0
1 187593 187486 0.99943 0.000325172 0 64388 92 2047.5 0 0 0 0
EOD
set output 'cycles.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'fragments.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'fragments_per_clock.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'setup_share.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'stall_share.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'depth_fails.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'wrong_depth_tests.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
set output 'max_depth_error.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'depth_exponent_bits=0' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'depth_exponent_bits=4' noenhanced
