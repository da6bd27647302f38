# gnuplot docs/images/fem-spb-element-size.png.gp (from docs/): the FEM's SPB failure loads
# against the element size of the rocks (docs/validation.md section 3, "The paper's rule";
# data in data/femSameElementVolume, data/spbFemPaperResolution and the flagship's run).
set terminal pngcairo size 1400,520 font "DejaVu Sans,11"
set output "images/fem-spb-element-size.png"
# Median of the seven rocks / measured median (granite 17.90 kN, limestone 14.70 kN).
# columns: element size [mm], granite, limestone
$flagship << EOD
4   0.894 0.847
2   1.223 1.143
1.5 1.171 1.384
EOD
$ownDisc << EOD
4   0.917 0.786
EOD
# 4 mm, sigma_w of the 2 mm disc, threshold seeds 1-5: lowest and highest median
# columns: element size, granite low, granite high, limestone low, limestone high
$seeds << EOD
4 0.891 0.898 0.847 0.907
EOD
set multiplot layout 1,2
set grid
set xlabel "element size of the rocks [mm]"
set xrange [1.2:4.3]
set ylabel "median SPB failure load / measured median [-]"
set yrange [0.6:1.5]
set key top right box opaque
set title "FEM (KST-DFH, crack band), 7 rocks per type\nsigma_w calibrated on the 2 mm disc, or on a disc of the rocks' size"
set style fill transparent solid 0.15 noborder
plot 0.9 w l lc rgb "dark-green" dt 2 t "within 10 % of measured", 1.1 w l lc rgb "dark-green" dt 2 not, \
     1.0 w l lc rgb "black" t "measured", \
     $flagship u ($1-0.03):2 w lp pt 7 ps 1.5 lw 2 lc rgb "#b03020" t "granite, sigma_w of the 2 mm disc", \
     $flagship u ($1+0.03):3 w lp pt 5 ps 1.5 lw 2 lc rgb "#2050b0" t "limestone, sigma_w of the 2 mm disc", \
     $ownDisc u ($1-0.03):2 w p pt 6 ps 2 lw 2 lc rgb "#b03020" t "granite, sigma_w of the 4 mm disc", \
     $ownDisc u ($1+0.03):3 w p pt 4 ps 2 lw 2 lc rgb "#2050b0" t "limestone, sigma_w of the 4 mm disc", \
     $seeds u ($1-0.09):(($2+$3)/2):2:3 w yerrorbars lc rgb "#b03020" pt -1 lw 2 t "granite, threshold seeds 1-5", \
     $seeds u ($1+0.09):(($4+$5)/2):4:5 w yerrorbars lc rgb "#2050b0" pt -1 lw 2 t "limestone, threshold seeds 1-5"
# Rock by rock (sigma_w of the 2 mm disc): failure load / measured; at 1.5 mm granite rock 6 and
# limestone rock 2 crushed and were stopped before a drop (left out), limestone rock 3 at its peak.
$rocksG << EOD
4 0.902 0.808 0.946 0.558 1.026 2.924 1.104
2 1.669 0.995 0.877 0.763 1.312 2.951 1.252
1.5 1.646 0.951 1.032 0.708 1.337 1.466
EOD
$rocksL << EOD
4 0.683 2.293 0.767 1.040 1.350 0.946 0.847
2 0.885 2.460 1.023 1.300 2.325 1.282 0.888
1.5 1.096 0.999 1.249 3.022 1.282 1.495
EOD
set title "Rock by rock (sigma_w of the 2 mm disc)\n1.5 mm: two rocks that crushed without a drop left out"
set ylabel "failure load / measured [-]"
set yrange [0.4:3.2]
set logscale y
set ytics (0.5, 0.7, 1, 1.5, 2, 3)
set key top center box opaque
plot 0.9 w l lc rgb "dark-green" dt 2 t "within 10 %", 1.1 w l lc rgb "dark-green" dt 2 not, \
     for [i=2:8] $rocksG u ($1-0.05):i w p pt 7 ps 1.2 lc rgb "#b03020" t (i==2 ? "granite rocks" : ""), \
     for [i=2:8] $rocksL u ($1+0.05):i w p pt 5 ps 1.2 lc rgb "#2050b0" t (i==2 ? "limestone rocks" : "")
unset multiplot
