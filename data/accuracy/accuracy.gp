# gnuplot script written by modesplit accuracy (commit several ?see the notes?); run it in this
# directory: gnuplot accuracy.gp. Restyle freely.
set terminal pngcairo noenhanced size 1100,700 font 'sans,11'
set format xy '%g'
set grid
set key outside right
set output 'waves_cost.png'
set logscale x
set logscale y
set title 'waves: standing-mode frequency rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'standing-mode frequency rel. error (relative, 0.01 = 1 %)'
plot 'waves.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'cells per wavelength', \
     'waves.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'waves.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'Courant number', \
     'waves.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle
set output 'waves_cost_ring_front_speed_rel_error.png'
set logscale x
unset logscale y
set title 'waves: ring front speed rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'ring front speed rel. error (relative, 0.01 = 1 %)'
plot 'waves_ring_front_speed_rel_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'cells per drop radius', \
     'waves_ring_front_speed_rel_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'waves_cost_packet_speed_rel_error_vs_c_u.png'
unset logscale x
unset logscale y
set title 'waves: packet speed rel. error vs c + U against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'packet speed rel. error vs c + U (relative, 0.01 = 1 %)'
plot 'waves_packet_speed_rel_error_vs_c_u.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'current u over c', \
     'waves_packet_speed_rel_error_vs_c_u.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'waves_cost_speed_added_by_the_current_vs_u.png'
unset logscale x
unset logscale y
set title 'waves: speed added by the current vs U against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'speed added by the current vs U (relative, 0.01 = 1 %)'
plot 'waves_speed_added_by_the_current_vs_u.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'current u over c', \
     'waves_speed_added_by_the_current_vs_u.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'waves_pareto.png'
set logscale x
set logscale y
set title 'waves: standing-mode frequency rel. error, every configuration;' . "\n" . 'the line joins the Pareto front; labels: knob=value'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'standing-mode frequency rel. error (relative, 0.01 = 1 %)'
plot 'waves_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'waves_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'waves_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'water_error.png'
set logscale x
set logscale y
set title 'water: the paper''s non-dispersive eq. 2 against real capillary-gravity waves, one curve per depth'
set xlabel 'wavelength (m)'
set ylabel 'phase speed rel. error vs real water (relative, 0.01 = 1 %)'
plot 'water.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'lambda m depth 0.02m', \
     'water.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'lambda m depth 0.1m', \
     'water.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'lambda m depth 1m'
set output 'water_error_simulated_phase_speed_rel_error_depth_0_02_m.png'
set logscale x
set logscale y
set title 'water at depth 0.02 m: each surface model''s phase speed (simulated) against real water' . "\n" . '32 cells per wavelength; legend: CPU time per cell per sub-step (256x256, 1 thread)'
set xlabel 'wavelength (m)'
set ylabel 'simulated phase speed rel. error, depth 0.02 m (relative, 0.01 = 1 %)'
plot 'water_simulated_phase_speed_rel_error_depth_0_02_m.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'eq. 2 (surface.model wave): 0.478 ns per cell per step', \
     'water_simulated_phase_speed_rel_error_depth_0_02_m.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'dispersive (surface.model dispersive): 32.1 ns per cell per step'
set output 'water_error_simulated_phase_speed_rel_error_depth_0_1_m.png'
set logscale x
set logscale y
set title 'water at depth 0.1 m: each surface model''s phase speed (simulated) against real water' . "\n" . '32 cells per wavelength; legend: CPU time per cell per sub-step (256x256, 1 thread)'
set xlabel 'wavelength (m)'
set ylabel 'simulated phase speed rel. error, depth 0.1 m (relative, 0.01 = 1 %)'
plot 'water_simulated_phase_speed_rel_error_depth_0_1_m.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'eq. 2 (surface.model wave): 0.443 ns per cell per step', \
     'water_simulated_phase_speed_rel_error_depth_0_1_m.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'dispersive (surface.model dispersive): 48.8 ns per cell per step'
set output 'water_error_simulated_phase_speed_rel_error_depth_1_m.png'
set logscale x
set logscale y
set title 'water at depth 1 m: each surface model''s phase speed (simulated) against real water' . "\n" . '32 cells per wavelength; legend: CPU time per cell per sub-step (256x256, 1 thread)'
set xlabel 'wavelength (m)'
set ylabel 'simulated phase speed rel. error, depth 1 m (relative, 0.01 = 1 %)'
plot 'water_simulated_phase_speed_rel_error_depth_1_m.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'eq. 2 (surface.model wave): 0.353 ns per cell per step', \
     'water_simulated_phase_speed_rel_error_depth_1_m.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'dispersive (surface.model dispersive): 40.5 ns per cell per step'
set output 'sph_cost.png'
set logscale x
unset logscale y
set title 'sph: dam-break front Z rel. RMS error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break front Z rel. RMS error (relative, 0.01 = 1 %)'
plot 'sph.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_column_h_rel_rms_error.png'
set logscale x
unset logscale y
set title 'sph: dam-break column H rel. RMS error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break column H rel. RMS error (relative, 0.01 = 1 %)'
plot 'sph_dam_break_column_h_rel_rms_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_column_h_rel_rms_error.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_max_compression.png'
set logscale x
set logscale y
set title 'sph: dam-break max compression against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break max compression (relative, 0.01 = 1 %)'
plot 'sph_dam_break_max_compression.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_max_compression.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_max_compression.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_max_compression.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_max_compression.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_max_compression.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_max_compression.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_max_compression.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_max_compression.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_max_compression.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_max_compression.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_max_compression.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_max_compression.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_max_compression.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_max_compression.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_max_compression.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_max_compression.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_max_compression.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_max_compression.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_max_compression.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_max_compression.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_max_compression.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_max_compression.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_max_compression.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_max_compression.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_max_compression.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_max_compression.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_max_compression.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_max_compression.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_max_compression.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_max_compression.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_max_compression.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_max_compression.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_max_compression.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_max_compression.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_max_compression.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_max_compression.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_max_compression.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_front_z_rms_error_after_time_shift.png'
set logscale x
unset logscale y
set title 'sph: dam-break front Z RMS error after time shift against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break front Z RMS error after time shift (relative, 0.01 = 1 %)'
plot 'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_front_z_best_time_shift_t0.png'
set logscale x
unset logscale y
set title 'sph: dam-break front Z best time shift T0 against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break front Z best time shift T0 (T = t sqrt(2 g / a))'
plot 'sph_dam_break_front_z_best_time_shift_t0.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_column_h_rms_error_after_time_shift.png'
set logscale x
unset logscale y
set title 'sph: dam-break column H RMS error after time shift against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break column H RMS error after time shift (relative, 0.01 = 1 %)'
plot 'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_dam_break_late_front_dz_dt_ritter_speed.png'
set logscale x
unset logscale y
set title 'sph: dam-break late front dZ/dT / Ritter speed against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break late front dZ/dT / Ritter speed (ratio)'
plot 'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'ideal gas sqrt(k) = 20 m/s, by particle count', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'Tait c0 = 20 m/s, by particle count', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'DFSPH 0.1 %, by particle count', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas: sqrt(k) (m/s), 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas: sqrt(k) (m/s), 1568 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'ideal gas: sqrt(k) (m/s), 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait: sound speed c0 (m/s), 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait: sound speed c0 (m/s), 1568 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'Tait: sound speed c0 (m/s), 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH: max density error, 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH: max density error, 1568 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'DFSPH: max density error, 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas: Courant factor, 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas: Courant factor, 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait: Courant factor, 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait: Courant factor, 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'DFSPH: Courant factor, 800 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH: Courant factor, 3200 particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle
set output 'sph_cost_hydrostatic_pressure_rms_rho0_g_h.png'
set logscale x
unset logscale y
set title 'sph: hydrostatic pressure RMS / (rho0 g H) against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'hydrostatic pressure RMS / (rho0 g H) (fraction of rho0 g H)'
plot 'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'ideal gas at rest, by particle count', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'Tait at rest, by particle count', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'ideal gas at rest: sqrt(k) (m/s), 175 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'ideal gas at rest: sqrt(k) (m/s), 704 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas at rest: sqrt(k) (m/s), 1400 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'Tait at rest: sound speed c0 (m/s), 175 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'Tait at rest: sound speed c0 (m/s), 704 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait at rest: sound speed c0 (m/s), 1400 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'ideal gas at rest: Courant factor, 175 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'ideal gas at rest: Courant factor, 704 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'ideal gas at rest: Courant factor, 1400 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'Tait at rest: Courant factor, 175 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'Tait at rest: Courant factor, 704 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'Tait at rest: Courant factor, 1400 particles', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle
set output 'sph_cost_max_compression_at_rest_all_particles.png'
set logscale x
set logscale y
set title 'sph: max compression at rest (all particles) against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'max compression at rest (all particles) (relative, 0.01 = 1 %)'
plot 'sph_max_compression_at_rest_all_particles.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'ideal gas at rest, by particle count', \
     'sph_max_compression_at_rest_all_particles.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'Tait at rest, by particle count', \
     'sph_max_compression_at_rest_all_particles.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'DFSPH at rest, by particle count', \
     'sph_max_compression_at_rest_all_particles.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'ideal gas at rest: sqrt(k) (m/s), 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas at rest: sqrt(k) (m/s), 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas at rest: sqrt(k) (m/s), 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'Tait at rest: sound speed c0 (m/s), 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait at rest: sound speed c0 (m/s), 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait at rest: sound speed c0 (m/s), 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'DFSPH at rest: max density error, 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH at rest: max density error, 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH at rest: max density error, 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'ideal gas at rest: Courant factor, 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas at rest: Courant factor, 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas at rest: Courant factor, 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait at rest: Courant factor, 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait at rest: Courant factor, 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'Tait at rest: Courant factor, 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH at rest: Courant factor, 175 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 19 using 1:2 with linespoints pt 7 lc 20 title 'DFSPH at rest: Courant factor, 704 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 19 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 20 notitle, \
     'sph_max_compression_at_rest_all_particles.dat' index 20 using 1:2 with linespoints pt 7 lc 21 title 'DFSPH at rest: Courant factor, 1400 particles', \
     'sph_max_compression_at_rest_all_particles.dat' index 20 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 21 notitle
set output 'sph_cost_mean_compression_at_rest_interior.png'
set logscale x
set logscale y
set title 'sph: mean compression at rest (interior) against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'mean compression at rest (interior) (relative, 0.01 = 1 %)'
plot 'sph_mean_compression_at_rest_interior.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'ideal gas at rest, by particle count', \
     'sph_mean_compression_at_rest_interior.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'Tait at rest, by particle count', \
     'sph_mean_compression_at_rest_interior.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'DFSPH at rest, by particle count', \
     'sph_mean_compression_at_rest_interior.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'ideal gas at rest: sqrt(k) (m/s), 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'ideal gas at rest: sqrt(k) (m/s), 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'ideal gas at rest: sqrt(k) (m/s), 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'Tait at rest: sound speed c0 (m/s), 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'Tait at rest: sound speed c0 (m/s), 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'Tait at rest: sound speed c0 (m/s), 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'DFSPH at rest: max density error, 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'DFSPH at rest: max density error, 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'DFSPH at rest: max density error, 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 12 using 1:2 with linespoints pt 7 lc 13 title 'ideal gas at rest: Courant factor, 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 12 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 13 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 13 using 1:2 with linespoints pt 7 lc 14 title 'ideal gas at rest: Courant factor, 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 13 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 14 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 14 using 1:2 with linespoints pt 7 lc 15 title 'ideal gas at rest: Courant factor, 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 14 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 15 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 15 using 1:2 with linespoints pt 7 lc 16 title 'Tait at rest: Courant factor, 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 15 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 16 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 16 using 1:2 with linespoints pt 7 lc 17 title 'Tait at rest: Courant factor, 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 16 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 17 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 17 using 1:2 with linespoints pt 7 lc 18 title 'Tait at rest: Courant factor, 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 17 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 18 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 18 using 1:2 with linespoints pt 7 lc 19 title 'DFSPH at rest: Courant factor, 175 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 18 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 19 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 19 using 1:2 with linespoints pt 7 lc 20 title 'DFSPH at rest: Courant factor, 704 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 19 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 20 notitle, \
     'sph_mean_compression_at_rest_interior.dat' index 20 using 1:2 with linespoints pt 7 lc 21 title 'DFSPH at rest: Courant factor, 1400 particles', \
     'sph_mean_compression_at_rest_interior.dat' index 20 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 21 notitle
set output 'sph_pareto.png'
set logscale x
unset logscale y
set title 'sph: dam-break column H rel. RMS error, every configuration;' . "\n" . 'the line joins the Pareto front; c sound speed, e max density error, C Courant factor, p particles'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break column H rel. RMS error (relative, 0.01 = 1 %)'
plot 'sph_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'sph_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'sph_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'sph_pareto_compression.png'
set logscale x
set logscale y
set title 'sph: dam-break max compression, every configuration;' . "\n" . 'the line joins the Pareto front; c sound speed, e max density error, C Courant factor, p particles'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break max compression (relative, 0.01 = 1 %)'
plot 'sph_pareto_compression.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'sph_pareto_compression.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'sph_pareto_compression.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'sph_solvers_compression.png'
set logscale x
set logscale y
set title 'dam break: dam-break max compression against cost, every configuration per solver;' . "\n" . 'lines: each solver''s front; c sound speed, e max density error, C Courant factor, p particles'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break max compression (relative, 0.01 = 1 %)'
plot 'sph_solvers_compression.dat' index 0 using 1:2 with points pt 6 lc 1 title 'ideal gas, every configuration', \
     'sph_solvers_compression.dat' index 1 using 1:2 with linespoints lw 2 pt 7 lc 1 title 'ideal gas, front', \
     'sph_solvers_compression.dat' index 1 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 1 notitle, \
     'sph_solvers_compression.dat' index 2 using 1:2 with points pt 6 lc 2 title 'Tait, every configuration', \
     'sph_solvers_compression.dat' index 3 using 1:2 with linespoints lw 2 pt 7 lc 2 title 'Tait, front', \
     'sph_solvers_compression.dat' index 3 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 2 notitle, \
     'sph_solvers_compression.dat' index 4 using 1:2 with points pt 6 lc 3 title 'DFSPH, every configuration', \
     'sph_solvers_compression.dat' index 5 using 1:2 with linespoints lw 2 pt 7 lc 3 title 'DFSPH, front', \
     'sph_solvers_compression.dat' index 5 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 3 notitle
set output 'sph_solvers_column.png'
set logscale x
unset logscale y
set title 'dam break: dam-break column H rel. RMS error against cost, every configuration per solver;' . "\n" . 'lines: each solver''s front; c sound speed, e max density error, C Courant factor, p particles'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'dam-break column H rel. RMS error (relative, 0.01 = 1 %)'
plot 'sph_solvers_column.dat' index 0 using 1:2 with points pt 6 lc 1 title 'ideal gas, every configuration', \
     'sph_solvers_column.dat' index 1 using 1:2 with linespoints lw 2 pt 7 lc 1 title 'ideal gas, front', \
     'sph_solvers_column.dat' index 1 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 1 notitle, \
     'sph_solvers_column.dat' index 2 using 1:2 with points pt 6 lc 2 title 'Tait, every configuration', \
     'sph_solvers_column.dat' index 3 using 1:2 with linespoints lw 2 pt 7 lc 2 title 'Tait, front', \
     'sph_solvers_column.dat' index 3 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 2 notitle, \
     'sph_solvers_column.dat' index 4 using 1:2 with points pt 6 lc 3 title 'DFSPH, every configuration', \
     'sph_solvers_column.dat' index 5 using 1:2 with linespoints lw 2 pt 7 lc 3 title 'DFSPH, front', \
     'sph_solvers_column.dat' index 5 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 3 notitle
set output 'sph_solvers_rest_compression.png'
set logscale x
set logscale y
set title 'column at rest: max compression at rest (all particles) against cost, every configuration per solver;' . "\n" . 'lines: each solver''s front; c sound speed, e max density error, C Courant factor, p particles'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'max compression at rest (all particles) (relative, 0.01 = 1 %)'
plot 'sph_solvers_rest_compression.dat' index 0 using 1:2 with points pt 6 lc 1 title 'ideal gas, every configuration', \
     'sph_solvers_rest_compression.dat' index 1 using 1:2 with linespoints lw 2 pt 7 lc 1 title 'ideal gas, front', \
     'sph_solvers_rest_compression.dat' index 1 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 1 notitle, \
     'sph_solvers_rest_compression.dat' index 2 using 1:2 with points pt 6 lc 2 title 'Tait, every configuration', \
     'sph_solvers_rest_compression.dat' index 3 using 1:2 with linespoints lw 2 pt 7 lc 2 title 'Tait, front', \
     'sph_solvers_rest_compression.dat' index 3 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 2 notitle, \
     'sph_solvers_rest_compression.dat' index 4 using 1:2 with points pt 6 lc 3 title 'DFSPH, every configuration', \
     'sph_solvers_rest_compression.dat' index 5 using 1:2 with linespoints lw 2 pt 7 lc 3 title 'DFSPH, front', \
     'sph_solvers_rest_compression.dat' index 5 using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt 3 notitle
set output 'extract_cost.png'
set logscale x
set logscale y
set title 'extract: height RMS error in spacings against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per extraction call (ms, 1 thread)'
set ylabel 'height RMS error in spacings (particle spacings)'
plot 'extract.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'flat field cells', \
     'extract.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'extract.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'flat smoothing passes', \
     'extract.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'extract.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'flat fine field cells', \
     'extract.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle, \
     'extract.dat' index 3 using 1:2 with linespoints pt 7 lc 4 title 'flat fine smoothing passes', \
     'extract.dat' index 3 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 4 notitle, \
     'extract.dat' index 4 using 1:2 with linespoints pt 7 lc 5 title 'tilted field cells', \
     'extract.dat' index 4 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 5 notitle, \
     'extract.dat' index 5 using 1:2 with linespoints pt 7 lc 6 title 'tilted smoothing passes', \
     'extract.dat' index 5 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 6 notitle, \
     'extract.dat' index 6 using 1:2 with linespoints pt 7 lc 7 title 'tilted fine field cells', \
     'extract.dat' index 6 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 7 notitle, \
     'extract.dat' index 7 using 1:2 with linespoints pt 7 lc 8 title 'tilted fine smoothing passes', \
     'extract.dat' index 7 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 8 notitle, \
     'extract.dat' index 8 using 1:2 with linespoints pt 7 lc 9 title 'column field cells', \
     'extract.dat' index 8 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 9 notitle, \
     'extract.dat' index 9 using 1:2 with linespoints pt 7 lc 10 title 'column smoothing passes', \
     'extract.dat' index 9 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 10 notitle, \
     'extract.dat' index 10 using 1:2 with linespoints pt 7 lc 11 title 'column fine field cells', \
     'extract.dat' index 10 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 11 notitle, \
     'extract.dat' index 11 using 1:2 with linespoints pt 7 lc 12 title 'column fine smoothing passes', \
     'extract.dat' index 11 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 12 notitle
set output 'extract_pareto_flat.png'
set logscale x
set logscale y
set title 'extract: height RMS error in spacings, every configuration;' . "\n" . 'the line joins the Pareto front; labels: knob=value'
set xlabel 'cost: CPU time per extraction call (ms, 1 thread)'
set ylabel 'height RMS error in spacings (particle spacings)'
plot 'extract_pareto_flat.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'extract_pareto_flat.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'extract_pareto_flat.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'extract_pareto_tilted.png'
set logscale x
set logscale y
set title 'extract: height RMS error in spacings, every configuration;' . "\n" . 'the line joins the Pareto front; labels: knob=value'
set xlabel 'cost: CPU time per extraction call (ms, 1 thread)'
set ylabel 'height RMS error in spacings (particle spacings)'
plot 'extract_pareto_tilted.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'extract_pareto_tilted.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'extract_pareto_tilted.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'extract_pareto_column.png'
set logscale x
set logscale y
set title 'extract: height RMS error in spacings, every configuration;' . "\n" . 'the line joins the Pareto front; labels: knob=value'
set xlabel 'cost: CPU time per extraction call (ms, 1 thread)'
set ylabel 'height RMS error in spacings (particle spacings)'
plot 'extract_pareto_column.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'extract_pareto_column.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'extract_pareto_column.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'coupler_cost.png'
set logscale x
set logscale y
set title 'coupler: sub-SPH-cell spectrum rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'sub-SPH-cell spectrum rel. error (relative, 0.01 = 1 %)'
plot 'coupler.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'N_surf (wave cells per SPH cell)', \
     'coupler.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle, \
     'coupler.dat' index 1 using 1:2 with linespoints pt 7 lc 2 title 'N_time (wave steps per SPH step)', \
     'coupler.dat' index 1 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 2 notitle, \
     'coupler.dat' index 2 using 1:2 with linespoints pt 7 lc 3 title 'two-way coupling gain', \
     'coupler.dat' index 2 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 3 notitle
set output 'coupler_cost_energy_at_1_2_cm_rel_error.png'
set logscale x
set logscale y
set title 'coupler: energy at 1-2 cm rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'energy at 1-2 cm rel. error (relative, 0.01 = 1 %)'
plot 'coupler_energy_at_1_2_cm_rel_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'N_surf (wave cells per SPH cell)', \
     'coupler_energy_at_1_2_cm_rel_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'coupler_cost_energy_at_0_5_1_cm_rel_error.png'
set logscale x
set logscale y
set title 'coupler: energy at 0.5-1 cm rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'energy at 0.5-1 cm rel. error (relative, 0.01 = 1 %)'
plot 'coupler_energy_at_0_5_1_cm_rel_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'N_surf (wave cells per SPH cell)', \
     'coupler_energy_at_0_5_1_cm_rel_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'coupler_cost_energy_at_0_25_0_5_cm_rel_error.png'
set logscale x
set logscale y
set title 'coupler: energy at 0.25-0.5 cm rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'energy at 0.25-0.5 cm rel. error (relative, 0.01 = 1 %)'
plot 'coupler_energy_at_0_25_0_5_cm_rel_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'N_surf (wave cells per SPH cell)', \
     'coupler_energy_at_0_25_0_5_cm_rel_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'coupler_cost_energy_at_0_125_0_25_cm_rel_error.png'
set logscale x
unset logscale y
set title 'coupler: energy at 0.125-0.25 cm rel. error against cost, one curve per knob' . "\n" . 'labels: the knob''s value, or the particle or cell count where the curve runs over it'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'energy at 0.125-0.25 cm rel. error (relative, 0.01 = 1 %)'
plot 'coupler_energy_at_0_125_0_25_cm_rel_error.dat' index 0 using 1:2 with linespoints pt 7 lc 1 title 'N_surf (wave cells per SPH cell)', \
     'coupler_energy_at_0_125_0_25_cm_rel_error.dat' index 0 using 1:2:4 with labels offset 0.6,0.5 left font ',7' tc lt 1 notitle
set output 'coupler_pareto.png'
set logscale x
set logscale y
set title 'coupler: sub-SPH-cell spectrum rel. error, every configuration;' . "\n" . 'the line joins the Pareto front; labels: knob=value'
set xlabel 'cost: CPU time per simulated second (ms, 1 thread)'
set ylabel 'sub-SPH-cell spectrum rel. error (relative, 0.01 = 1 %)'
plot 'coupler_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'coupler_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'coupler_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'sph_front_overlay.png'
unset logscale x
unset logscale y
set title 'dam break, surge front: simulated Z(T) at each solver''s defaults against Martin & Moyce (1952)'
set xlabel 'T = t sqrt(2 g / a)'
set ylabel 'Z = front x / a'
plot 'sph_trace.dat' index 0 using 1:2 with points pt 5 ps 1.3 lc rgb 'black' title 'Martin & Moyce (1952)', \
     'sph_trace.dat' index 2 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'ideal gas, 800 particles', \
     'sph_trace.dat' index 4 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'Tait, 800 particles', \
     'sph_trace.dat' index 6 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'DFSPH, 800 particles', \
     'sph_trace.dat' index 8 using 1:2 with lines lw 1.5 dt 2 lc 1 title 'ideal gas, 1568 particles', \
     'sph_trace.dat' index 10 using 1:2 with lines lw 1.5 dt 2 lc 2 title 'Tait, 1568 particles', \
     'sph_trace.dat' index 12 using 1:2 with lines lw 1.5 dt 2 lc 3 title 'DFSPH, 1568 particles', \
     'sph_trace.dat' index 14 using 1:2 with lines lw 1.5 dt 3 lc 1 title 'ideal gas, 3200 particles', \
     'sph_trace.dat' index 16 using 1:2 with lines lw 1.5 dt 3 lc 2 title 'Tait, 3200 particles', \
     'sph_trace.dat' index 18 using 1:2 with lines lw 1.5 dt 3 lc 3 title 'DFSPH, 3200 particles'
set output 'sph_column_overlay.png'
unset logscale x
unset logscale y
set title 'dam break, residual column at the wall: simulated H(tau) against Martin & Moyce (1952)'
set xlabel 'tau = t sqrt(g / a)'
set ylabel 'H = height / 2a'
plot 'sph_trace.dat' index 1 using 1:2 with points pt 5 ps 1.3 lc rgb 'black' title 'Martin & Moyce (1952)', \
     'sph_trace.dat' index 3 using 1:2 with lines lw 1.5 dt 1 lc 1 title 'ideal gas, 800 particles', \
     'sph_trace.dat' index 5 using 1:2 with lines lw 1.5 dt 1 lc 2 title 'Tait, 800 particles', \
     'sph_trace.dat' index 7 using 1:2 with lines lw 1.5 dt 1 lc 3 title 'DFSPH, 800 particles', \
     'sph_trace.dat' index 9 using 1:2 with lines lw 1.5 dt 2 lc 1 title 'ideal gas, 1568 particles', \
     'sph_trace.dat' index 11 using 1:2 with lines lw 1.5 dt 2 lc 2 title 'Tait, 1568 particles', \
     'sph_trace.dat' index 13 using 1:2 with lines lw 1.5 dt 2 lc 3 title 'DFSPH, 1568 particles', \
     'sph_trace.dat' index 15 using 1:2 with lines lw 1.5 dt 3 lc 1 title 'ideal gas, 3200 particles', \
     'sph_trace.dat' index 17 using 1:2 with lines lw 1.5 dt 3 lc 2 title 'Tait, 3200 particles', \
     'sph_trace.dat' index 19 using 1:2 with lines lw 1.5 dt 3 lc 3 title 'DFSPH, 3200 particles'
