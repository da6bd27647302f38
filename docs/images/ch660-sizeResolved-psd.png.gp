# gnuplot docs/images/ch660-sizeResolved-psd.png.gp (from docs/): the discharge PSD and the PSD of
# the Voronoi cells fed of tutorials/CH660/sizeResolved (three templates) and of the same feed with
# one template (data: crusherPost's psd.dat of each run in docs/data/ch660SizeResolved;
# docs/validation.md section 6 "A size-resolved feed").
set terminal pngcairo size 1000,620 font "DejaVu Sans,11"
set output "images/ch660-sizeResolved-psd.png"
set datafile separator "\t"
d = "data/ch660SizeResolved/"
set title "CH660, rocks of 60-90 mm, 0.3 s: discharge and the cells fed"
set xlabel "sieve size [mm]"; set ylabel "passing [%]"; set grid; set logscale x
set xrange [7:60]; set yrange [0:100]; set key top left
set xtics (8, 10, 12, 15, 20, 30, 40, 50)
set arrow from 38, graph 0 to 38, graph 1 nohead dt 2 lc rgb "black"
set label "CSS" at 38.5, graph 0.05
plot d."classes-psd.dat" u (1e3*$1):(100*$2) w l lw 2 lc rgb "#1f77b4" t "size classes (198/264/349 cells): discharge", \
     d."classes-psd.dat" u (1e3*$1):(100*$3) w l lw 2 dt 2 lc rgb "#1f77b4" t "size classes: cells fed", \
     d."oneTemplate-psd.dat" u (1e3*$1):(100*$2) w l lw 2 lc rgb "#ff7f0e" t "one template (198 cells): discharge", \
     d."oneTemplate-psd.dat" u (1e3*$1):(100*$3) w l lw 2 dt 2 lc rgb "#ff7f0e" t "one template: cells fed"
