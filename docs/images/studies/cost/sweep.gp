# Written by rastersim sweep: scene overlap, 64x48, model
set terminal pngcairo size 800,500 font ',11'
set grid
set key outside right top
set xlabel 'memory_latency' noenhanced
set xtics ('1' 1, '4' 4, '16' 16)
$series0 << EOD
1 6588 3114 0.472678 0.0364299 0 630 0 0.666769 93322 36556 3142 153600
4 6588 3114 0.472678 0.0364299 0 630 0 0.666769 93748 36721 3267 153600
16 6596 3114 0.472104 0.0363857 0 630 0 0.666769 96118 38248 4003 153600
EOD
$series1 << EOD
1 3300 3114 0.943636 0.0727273 0 630 0 0.666769 93322 36556 3142 153600
4 3303 3114 0.942779 0.0726612 0 630 0 0.666769 93748 36721 3267 153600
16 3315 3114 0.939367 0.0723982 0 630 0 0.666769 96118 38248 4003 153600
EOD
set output 'cycles.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'cycles' noenhanced
plot $series0 using 1:2 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:2 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'fragments.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'fragments' noenhanced
plot $series0 using 1:3 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:3 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'fragments_per_clock.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'fragments_per_clock' noenhanced
plot $series0 using 1:4 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:4 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'setup_share.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'setup_share' noenhanced
plot $series0 using 1:5 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:5 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'stall_share.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'stall_share' noenhanced
plot $series0 using 1:6 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:6 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'depth_fails.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'depth_fails' noenhanced
plot $series0 using 1:7 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:7 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'wrong_depth_tests.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'wrong_depth_tests' noenhanced
plot $series0 using 1:8 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:8 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'max_depth_error.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'max_depth_error' noenhanced
plot $series0 using 1:9 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:9 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'yosys_cells.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'yosys_cells' noenhanced
plot $series0 using 1:10 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:10 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'ice40_luts.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'ice40_luts' noenhanced
plot $series0 using 1:11 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:11 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'ice40_ffs.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'ice40_ffs' noenhanced
plot $series0 using 1:12 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:12 with linespoints pointtype 7 title 'traversal=span' noenhanced
set output 'memory_bits.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'memory_bits' noenhanced
plot $series0 using 1:13 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 1:13 with linespoints pointtype 7 title 'traversal=span' noenhanced
unset logscale x
unset xtics
set xtics
set xrange [*:*]
set xlabel 'cycles'
set output 'cycles_vs_ice40_luts.png'
set title 'scene overlap, 64x48, model' noenhanced
set ylabel 'ice40_luts' noenhanced
plot $series0 using 2:11 with linespoints pointtype 7 title 'traversal=bbox' noenhanced, $series1 using 2:11 with linespoints pointtype 7 title 'traversal=span' noenhanced
