# Written by rastersim sweep: zfight.json, 640x480, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'z_bits' noenhanced
set yrange [0:*]
set xtics ('16' 16, '18' 18, '20' 20, '22' 22, '24' 24, '28' 28, '32' 32)
$series0 << EOD
16 187585 187486 0.999472 0.000282539 0 74852 10878 0.626721 0 0 0 0
18 187589 187486 0.999451 0.000303856 0 64227 1947 0.560427 0 0 0 0
20 187589 187486 0.999451 0.000303856 0 65186 920 0.567118 0 0 0 0
22 187593 187486 0.99943 0.000325172 0 64297 107 0.562548 0 0 0 0
24 187593 187486 0.99943 0.000325172 0 64328 36 0.57437 0 0 0 0
28 187593 187486 0.99943 0.000325172 0 64299 3 0.597511 0 0 0 0
32 187593 187486 0.99943 0.000325172 0 64296 0 0.571241 0 0 0 0
EOD
$series1 << EOD
16 187585 187486 0.999472 0.000282539 0 64601 725 0.610573 0 0 0 0
18 187589 187486 0.999451 0.000303856 0 65078 782 0.609452 0 0 0 0
20 187589 187486 0.999451 0.000303856 0 64278 46 0.589998 0 0 0 0
22 187593 187486 0.99943 0.000325172 0 64321 25 0.606921 0 0 0 0
24 187593 187486 0.99943 0.000325172 0 64304 8 0.658274 0 0 0 0
28 187593 187486 0.99943 0.000325172 0 64296 0 0.596292 0 0 0 0
32 187593 187486 0.99943 0.000325172 0 64296 0 0.627302 0 0 0 0
EOD
$series2 << EOD
16 187585 187486 0.999472 0.000282539 0 64422 128 0.625376 0 0 0 0
18 187589 187486 0.999451 0.000303856 0 64329 33 0.567012 0 0 0 0
20 187589 187486 0.999451 0.000303856 0 64298 4 0.613749 0 0 0 0
22 187593 187486 0.99943 0.000325172 0 64296 0 0.611339 0 0 0 0
24 187593 187486 0.99943 0.000325172 0 64296 0 0.603394 0 0 0 0
28 187593 187486 0.99943 0.000325172 0 64296 0 0.588487 0 0 0 0
32 187593 187486 0.99943 0.000325172 0 64296 0 0.654208 0 0 0 0
EOD
set output 'cycles.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:2 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'fragments.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:3 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'fragments_per_clock.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:4 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'setup_share.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:5 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'stall_share.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:6 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'depth_fails.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:7 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'wrong_depth_tests.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:8 with linespoints pointtype 7 title 'near=1' noenhanced
set output 'max_depth_error.png'
set title 'zfight.json, 640x480, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'near=0.01' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'near=0.1' noenhanced, $series2 using 1:9 with linespoints pointtype 7 title 'near=1' noenhanced
