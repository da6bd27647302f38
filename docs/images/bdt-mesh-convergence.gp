# The picture of docs/validation.md section 2 (run in docs/images: gnuplot bdt-mesh-convergence.gp).
set terminal pngcairo size 900,600 font ",11"
set output "bdt-mesh-convergence.png"
set title "BDT granite (DEM): tensile strength 2F/({/Symbol p}Dt) vs number of cells, 10 seeds each"
set xlabel "number of Voronoi cells [-]"
set ylabel "tensile strength [MPa]"
set grid
set key bottom right box opaque
stats "< awk '!/^#/ && $1 == 300' bdt-mesh-convergence.dat" using ($4/1e6) name "ref" nooutput
set xrange [0:550]
set yrange [0:25]
set object 1 rect from graph 0, first 0.85*ref_mean to graph 1, first 1.15*ref_mean fc rgb "#dddddd" fs solid noborder behind
plot ref_mean lc rgb "#555555" dt 2 title sprintf("300-cell mean %.1f MPa (band: {/Symbol \261}15 %%)", ref_mean), \
     "bdt-mesh-convergence.dat" using 1:($4/1e6) with points pt 7 ps 0.7 lc rgb "#1f77b4" title "one mesh, bond size effect m = 7", \
     "< awk '!/^#/ { s[$1] += $4; n[$1]++ } END { for (k in s) print k, s[k] / n[k] }' bdt-mesh-convergence.dat | sort -n" \
        using 1:($2/1e6) with linespoints pt 5 lw 2 lc rgb "#1f77b4" title "mean, bond size effect (tutorials)", \
     "bdt-mesh-convergence-paperModel.dat" using 1:($4/1e6) with points pt 6 ps 0.7 lc rgb "#d62728" title "one mesh, paper's model", \
     "< awk '!/^#/ { s[$1] += $4; n[$1]++ } END { for (k in s) print k, s[k] / n[k] }' bdt-mesh-convergence-paperModel.dat | sort -n" \
        using 1:($2/1e6) with linespoints pt 4 lw 2 dt 2 lc rgb "#d62728" title "mean, paper's model (no size effect)"
