# Tensile strength of the BDT vs cell count (the paper's Fig. 8), from
# results/tensileStrength.dat: every mesh, the mean per cell count, and the
# +-15 % band around the 300-cell mean. Run: gnuplot plotConvergence.gp
set terminal pngcairo size 900,600 font ",11"
set output "results/tensileStrength.png"
set title "BDT granite (DEM): tensile strength 2F/({/Symbol p}Dt) vs number of cells"
set xlabel "number of Voronoi cells [-]"
set ylabel "tensile strength [MPa]"
set grid
set key bottom right box opaque
stats "< awk '!/^#/ && $1 == 300' results/tensileStrength.dat" using ($4/1e6) name "ref" nooutput
set xrange [0:550]
set yrange [0:25]
set object 1 rect from graph 0, first 0.85*ref_mean to graph 1, first 1.15*ref_mean fc rgb "#dddddd" fs solid noborder behind
plot ref_mean lc rgb "#555555" dt 2 title sprintf("300-cell mean %.1f MPa (band: {/Symbol \\261}15 %%)", ref_mean), \
     "results/tensileStrength.dat" using 1:($4/1e6) with points pt 7 ps 0.8 lc rgb "#1f77b4" title "one mesh (seed)", \
     "< awk '!/^#/ { s[$1] += $4; n[$1]++ } END { for (k in s) print k, s[k] / n[k] }' results/tensileStrength.dat | sort -n" \
        using 1:($2/1e6) with linespoints pt 5 lw 2 lc rgb "#d62728" title "mean over seeds"
