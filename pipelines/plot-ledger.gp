# Plots a scene's water ledger (pipelines/figure_data.py ledger) with gnuplot.
# Call: gnuplot -e "data='ledger.dat'; scene='drop'; water='water.png'; transfers='transfers.png'" plot-ledger.gp
set terminal pngcairo noenhanced size 800,450 font "DejaVu Sans,11"
set key inside right center box opaque
set xlabel "simulated time (s)"
set grid
set output water
set title sprintf("%s: where the water is", scene)
set ylabel "mass (g)"
plot data using 1:($2*1000) with linespoints title "liquid particles", \
     data using 1:($3*1000) with linespoints title "textures", \
     data using 1:($4*1000) with linespoints title "air (vapor)"
set output transfers
set title sprintf("%s: evaporated and condensed mass (cumulative)", scene)
plot data using 1:($5*1000) with linespoints title "evaporated from particles", \
     data using 1:($6*1000) with linespoints title "condensed into textures (net)", \
     data using 1:($7*1000) with linespoints title "emitted as particles from textures"
