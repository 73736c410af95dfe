# gnuplot script written by `modesplit accuracy` (commit several (see the notes)); run it in this
# directory: gnuplot accuracy.gp. Restyle freely.
set terminal pngcairo noenhanced size 1000,650 font 'sans,11'
set logscale xy
set grid
set key outside right
set output 'waves_cost.png'
set title 'waves: standing-mode frequency rel. error against cost'
set xlabel 'cost (ms per simulated second)'
set ylabel 'error'
plot 'waves.dat' index 0 using 1:2 with linespoints pt 7 title 'cells_per_wavelength', \
     'waves.dat' index 1 using 1:2 with linespoints pt 7 title 'courant', \
     'waves.dat' index 2 using 1:2 with linespoints pt 7 title 'ring_cells_per_drop_radius'
set output 'waves_pareto.png'
set title 'waves: every configuration; the line joins those no other beats on both cost and error'
plot 'waves_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'waves_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'waves_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'water_error.png'
set title 'water: the paper''s non-dispersive model (eq. 2) against real capillary-gravity waves'
set xlabel 'wavelength (m)'
set ylabel 'phase speed rel. error'
plot 'water.dat' index 0 using 1:2 with linespoints pt 7 title 'lambda_m_depth_0.02m', \
     'water.dat' index 1 using 1:2 with linespoints pt 7 title 'lambda_m_depth_0.1m', \
     'water.dat' index 2 using 1:2 with linespoints pt 7 title 'lambda_m_depth_1m'
set output 'sph_cost.png'
set title 'sph: dam-break front Z rel. RMS error against cost'
set xlabel 'cost (ms per simulated second)'
set ylabel 'error'
plot 'sph.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph.dat' index 6 using 1:2 with linespoints pt 7 title 'courant', \
     'sph.dat' index 7 using 1:2 with linespoints pt 7 title 'rest_particles_ideal_gas', \
     'sph.dat' index 8 using 1:2 with linespoints pt 7 title 'rest_particles_tait', \
     'sph.dat' index 9 using 1:2 with linespoints pt 7 title 'rest_particles_dfsph'
set output 'sph_pareto.png'
set title 'sph: every configuration; the line joins those no other beats on both cost and error'
plot 'sph_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'sph_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'sph_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'extract_cost.png'
set title 'extract: height RMS error in spacings against cost'
set xlabel 'cost (ms per call)'
set ylabel 'error'
plot 'extract.dat' index 0 using 1:2 with linespoints pt 7 title 'flat_field_cells', \
     'extract.dat' index 1 using 1:2 with linespoints pt 7 title 'flat_smoothing_passes', \
     'extract.dat' index 2 using 1:2 with linespoints pt 7 title 'tilted_field_cells', \
     'extract.dat' index 3 using 1:2 with linespoints pt 7 title 'tilted_smoothing_passes', \
     'extract.dat' index 4 using 1:2 with linespoints pt 7 title 'column_field_cells', \
     'extract.dat' index 5 using 1:2 with linespoints pt 7 title 'column_smoothing_passes'
set output 'extract_pareto.png'
set title 'extract: every configuration; the line joins those no other beats on both cost and error'
plot 'extract_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'extract_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'extract_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'coupler_cost.png'
set title 'coupler: sub-SPH-cell detail energy rel. error against cost'
set xlabel 'cost (ms per simulated second)'
set ylabel 'error'
plot 'coupler.dat' index 0 using 1:2 with linespoints pt 7 title 'n_surf', \
     'coupler.dat' index 1 using 1:2 with linespoints pt 7 title 'n_time', \
     'coupler.dat' index 2 using 1:2 with linespoints pt 7 title 'two_way_gain'
set output 'coupler_pareto.png'
set title 'coupler: every configuration; the line joins those no other beats on both cost and error'
plot 'coupler_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'coupler_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'coupler_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
