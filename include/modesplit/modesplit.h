/* libmodesplit: highly detailed, interactive liquid simulation by mode
 * splitting (after H. Cords, "Mode-Splitting for Highly Detailed,
 * Interactive Liquid Simulation").
 *
 * The slow 3D flow of the liquid volume is simulated with SPH (ms_volume),
 * the fast free-surface waves with a 2D wave equation on a much finer grid
 * (ms_surface); ms_sim runs both at their own time steps and sums the two
 * height fields into one surface. SI units throughout (m, s, kg), z is up,
 * grids are row-major with x fastest (index y*nx + x).
 *
 *     #include <modesplit/modesplit.h>
 *     #include <stdio.h>
 *
 *     int main(void) {
 *         ms_volume_desc vol = ms_volume_desc_default();   // a 1 m pool, SPH
 *         ms_surface_desc surf = ms_surface_desc_default(); // 256x256 waves
 *         surf.dx = 1.0f / 256;       // the waves cover the pool's 1 m x 1 m
 *         ms_sim_desc d = ms_sim_desc_default();
 *         d.volume = &vol;            // NULL: no volume flow, no particles
 *         d.surface = &surf;          // NULL: the SPH field is the surface
 *         d.field_nx = d.field_ny = 32;  // X_SPH x Y_SPH, N_surf = 256/32
 *         d.threads = 2;              // the paper's two-core split
 *         ms_sim *sim;
 *         if (ms_sim_create(&d, &sim) != MS_OK) {
 *             fprintf(stderr, "%s\n", ms_last_error());
 *             return 1;
 *         }
 *         ms_volume_fill_box(ms_sim_volume(sim), (float[3]){0, 0, 0},
 *                            (float[3]){0.3f, 1, 0.5f}); // a dam to break
 *         ms_surface_add_drop(ms_sim_surface(sim), 0.7f, 0.5f, 0.03f, 0.01f);
 *         for (int frame = 0; frame < 300; ++frame) {
 *             if (ms_sim_step(sim, 1.0f / 60) != MS_OK) break;
 *             int nx, ny;
 *             const float *h = ms_sim_height(sim, &nx, &ny); // combined
 *             printf("%d %g\n", frame, h[(ny / 2) * nx + nx / 2]);
 *         }
 *         ms_sim_destroy(sim);
 *         return 0;
 *     }
 *
 * Every fallible call returns ms_status (MS_OK == 0, negative = error) and
 * ms_last_error() then says, in one sentence, which value broke which bound.
 * Handles are not shared between threads; views returned by the library
 * (ms_surface_height, ms_sim_height, ...) stay valid until the next mutating
 * call on the same handle.
 */
#ifndef MODESPLIT_MODESPLIT_H
#define MODESPLIT_MODESPLIT_H

#include "core.h"
#include "surface.h"
#include "volume.h"
#include "shape.h"
#include "scene.h"
#include "sim.h"
#include "render.h"
#include "io.h"

#endif /* MODESPLIT_MODESPLIT_H */
