# gnuplot docs/images/fem-crack-band.png.gp (from docs/): the crack band's effect on the FEM
# (granite; data in docs/data/crackBand, docs/validation.md section 3 "The crack band").
set terminal pngcairo size 1500,480 font "DejaVu Sans,11"
set output "images/fem-crack-band.png"
set datafile separator "\t"
set multiplot layout 1,3
set xlabel "gap change [mm]"; set ylabel "plate force [kN]"; set grid; set key top left
d = "data/crackBand/"
set title "BDT granite: complete cracks (sigma_w 22.5 MPa)\nvs crack band (G_F 30 N/m, sigma_w 10.7 MPa)"
set xrange [0:0.2]
plot d."bdt-granite-4mm-complete.dat" u 1:2 w l lw 2 t "complete, 4 mm", \
     d."bdt-granite-2mm-crackBand.dat" u 1:2 w l lw 2 t "crack band, 2 mm", \
     13.19 w l dt 2 lc rgb "black" t "measured mean 13.19 kN"
set xrange [0:1]
set key bottom right
set title "SPB granite rock 7 (measured 14.3 kN)"
plot d."spb-granite-rock7-4mm-complete.dat" u 1:2 w l lw 2 t "complete, 4 mm", \
     d."spb-granite-rock7-4mm-crackBand.dat" u 1:2 w l lw 2 t "crack band, 4 mm", \
     d."spb-granite-rock7-1.5mm-crackBand.dat" u 1:2 w l lw 2 t "crack band, 1.5 mm", \
     14.3 w l dt 2 lc rgb "black" t "measured"
set title "SPB granite rock 2 (measured 22.6 kN)"
plot d."spb-granite-rock2-4mm-complete.dat" u 1:2 w l lw 2 t "complete, 4 mm", \
     d."spb-granite-rock2-4mm-crackBand.dat" u 1:2 w l lw 2 t "crack band, 4 mm", \
     d."spb-granite-rock2-1.5mm-crackBand.dat" u 1:2 w l lw 2 t "crack band, 1.5 mm", \
     22.6 w l dt 2 lc rgb "black" t "measured"
unset multiplot
