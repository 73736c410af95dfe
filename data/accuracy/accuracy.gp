# gnuplot script written by `modesplit accuracy` (commit dde8f23); run it in this
# directory: gnuplot accuracy.gp. Restyle freely.
set terminal pngcairo noenhanced size 1000,650 font 'sans,11'
set logscale xy
set format xy '%g'
set grid
set key outside right
set output 'waves_cost.png'
set title 'waves: standing-mode frequency rel. error against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'standing-mode frequency rel. error'
plot 'waves.dat' index 0 using 1:2 with linespoints pt 7 title 'cells_per_wavelength', \
     'waves.dat' index 1 using 1:2 with linespoints pt 7 title 'courant'
set output 'waves_cost_ring_front_speed_rel_error.png'
set title 'waves: ring front speed rel. error against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'ring front speed rel. error'
plot 'waves_ring_front_speed_rel_error.dat' index 0 using 1:2 with linespoints pt 7 title 'ring_cells_per_drop_radius'
set output 'waves_pareto.png'
set title "waves: standing-mode frequency rel. error, every configuration;\nthe line joins those no other beats on both cost and error"
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'standing-mode frequency rel. error'
plot 'waves_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'waves_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'waves_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'water_error.png'
set title 'water: the paper''s non-dispersive eq. 2 against real capillary-gravity waves, one curve per depth'
set xlabel 'wavelength (m)'
set ylabel 'phase speed rel. error vs real water'
plot 'water.dat' index 0 using 1:2 with linespoints pt 7 title 'lambda_m_depth_0.02m', \
     'water.dat' index 1 using 1:2 with linespoints pt 7 title 'lambda_m_depth_0.1m', \
     'water.dat' index 2 using 1:2 with linespoints pt 7 title 'lambda_m_depth_1m'
set output 'sph_cost.png'
set title 'sph: dam-break front Z rel. RMS error against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break front Z rel. RMS error'
plot 'sph.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_column_h_rel_rms_error.png'
set title 'sph: dam-break column H rel. RMS error against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break column H rel. RMS error'
plot 'sph_dam_break_column_h_rel_rms_error.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_column_h_rel_rms_error.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_max_compression.png'
set title 'sph: dam-break max compression against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break max compression'
plot 'sph_dam_break_max_compression.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_max_compression.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_max_compression.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_max_compression.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_max_compression.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_max_compression.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_max_compression.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_front_z_rms_error_after_time_shift.png'
set title 'sph: dam-break front Z RMS error after time shift against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break front Z RMS error after time shift'
plot 'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_front_z_rms_error_after_time_shift.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_front_z_best_time_shift_t0.png'
set title 'sph: dam-break front Z best time shift T0 against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break front Z best time shift T0'
plot 'sph_dam_break_front_z_best_time_shift_t0.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_front_z_best_time_shift_t0.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_column_h_rms_error_after_time_shift.png'
set title 'sph: dam-break column H RMS error after time shift against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break column H RMS error after time shift'
plot 'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_column_h_rms_error_after_time_shift.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_dam_break_late_front_dz_dt_ritter_speed.png'
set title 'sph: dam-break late front dZ/dT / Ritter speed against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break late front dZ/dT / Ritter speed'
plot 'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 0 using 1:2 with linespoints pt 7 title 'particles', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 1 using 1:2 with linespoints pt 7 title 'law_ideal_gas', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 2 using 1:2 with linespoints pt 7 title 'law_tait', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 3 using 1:2 with linespoints pt 7 title 'law_dfsph', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 4 using 1:2 with linespoints pt 7 title 'sound_speed_ideal_gas', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 5 using 1:2 with linespoints pt 7 title 'sound_speed_tait', \
     'sph_dam_break_late_front_dz_dt_ritter_speed.dat' index 6 using 1:2 with linespoints pt 7 title 'courant'
set output 'sph_cost_hydrostatic_pressure_rms_rho0_g_h.png'
set title 'sph: hydrostatic pressure RMS / (rho0 g H) against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'hydrostatic pressure RMS / (rho0 g H)'
plot 'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 0 using 1:2 with linespoints pt 7 title 'rest_particles_ideal_gas', \
     'sph_hydrostatic_pressure_rms_rho0_g_h.dat' index 1 using 1:2 with linespoints pt 7 title 'rest_particles_tait'
set output 'sph_cost_max_compression_at_rest_all_particles.png'
set title 'sph: max compression at rest (all particles) against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'max compression at rest (all particles)'
plot 'sph_max_compression_at_rest_all_particles.dat' index 0 using 1:2 with linespoints pt 7 title 'rest_particles_ideal_gas', \
     'sph_max_compression_at_rest_all_particles.dat' index 1 using 1:2 with linespoints pt 7 title 'rest_particles_tait', \
     'sph_max_compression_at_rest_all_particles.dat' index 2 using 1:2 with linespoints pt 7 title 'rest_particles_dfsph'
set output 'sph_cost_mean_compression_at_rest_interior.png'
set title 'sph: mean compression at rest (interior) against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'mean compression at rest (interior)'
plot 'sph_mean_compression_at_rest_interior.dat' index 0 using 1:2 with linespoints pt 7 title 'rest_particles_ideal_gas', \
     'sph_mean_compression_at_rest_interior.dat' index 1 using 1:2 with linespoints pt 7 title 'rest_particles_tait', \
     'sph_mean_compression_at_rest_interior.dat' index 2 using 1:2 with linespoints pt 7 title 'rest_particles_dfsph'
set output 'sph_pareto.png'
set title "sph: dam-break front Z rel. RMS error, every configuration;\nthe line joins those no other beats on both cost and error"
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'dam-break front Z rel. RMS error'
plot 'sph_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'sph_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'sph_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'extract_cost.png'
set title 'extract: height RMS error in spacings against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per extraction call (1 thread)'
set ylabel 'height RMS error in spacings'
plot 'extract.dat' index 0 using 1:2 with linespoints pt 7 title 'flat_field_cells', \
     'extract.dat' index 1 using 1:2 with linespoints pt 7 title 'flat_smoothing_passes', \
     'extract.dat' index 2 using 1:2 with linespoints pt 7 title 'tilted_field_cells', \
     'extract.dat' index 3 using 1:2 with linespoints pt 7 title 'tilted_smoothing_passes', \
     'extract.dat' index 4 using 1:2 with linespoints pt 7 title 'column_field_cells', \
     'extract.dat' index 5 using 1:2 with linespoints pt 7 title 'column_smoothing_passes'
set output 'extract_pareto.png'
set title "extract: height RMS error in spacings, every configuration;\nthe line joins those no other beats on both cost and error"
set xlabel 'cost: ms of wall clock per extraction call (1 thread)'
set ylabel 'height RMS error in spacings'
plot 'extract_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'extract_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'extract_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
set output 'coupler_cost.png'
set title 'coupler: sub-SPH-cell detail energy rel. error against cost, one curve per knob'
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'sub-SPH-cell detail energy rel. error'
plot 'coupler.dat' index 0 using 1:2 with linespoints pt 7 title 'n_surf', \
     'coupler.dat' index 1 using 1:2 with linespoints pt 7 title 'n_time', \
     'coupler.dat' index 2 using 1:2 with linespoints pt 7 title 'two_way_gain'
set output 'coupler_pareto.png'
set title "coupler: sub-SPH-cell detail energy rel. error, every configuration;\nthe line joins those no other beats on both cost and error"
set xlabel 'cost: ms of wall clock per simulated second (1 thread)'
set ylabel 'sub-SPH-cell detail energy rel. error'
plot 'coupler_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \
     'coupler_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \
     'coupler_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle
