/* ms_sim: the mode-splitting coupler (paper sections 3.1, 3.4, 3.5, Fig. 8).
 *
 * N_time surface steps per volume step (eq. 19), the SPH height field
 * up-sampled bilinearly by N_surf onto the wave grid and summed (eq. 20),
 * two-way coupling, and the two-core split: the volume thread runs frame n
 * while the surface thread finishes frame n-1. threads = 1 runs the same
 * one-frame pipeline in order, so 1 and 2 threads give the same bytes.
 */
#ifndef MODESPLIT_SIM_H
#define MODESPLIT_SIM_H

#include "core.h"
#include "surface.h"
#include "volume.h"
#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A game engine that owns its threads can run the sim's parallel work
 * itself (as Box2D v3's enqueueTask/finishTask): enqueue starts task(ctx)
 * and returns a handle (NULL = it ran the task inline already); finish
 * waits for that handle. When both are NULL the sim uses its own pthread. */
typedef void ms_task_fn(void *task_context);
typedef void *ms_enqueue_task_fn(ms_task_fn *task, void *task_context, void *user_context);
typedef void ms_finish_task_fn(void *user_task, void *user_context);

typedef struct ms_sim_desc {
    const ms_volume_desc *volume;    /* NULL: no volume flow */
    const ms_surface_desc *surface;  /* NULL: no surface waves */
    int field_nx, field_ny;          /* X_SPH x Y_SPH; N_surf = surface nx / field_nx (eq. 20) */
    int surface_substeps;            /* N_time (eq. 19); 0 = derived from the CFL bound */
    float couple_surface_from_volume, couple_volume_from_surface;
    int threads;                     /* 1 = sequential, 2 = two-core split */
    /* --- grown at the end (ABI: descs only grow) --- */
    ms_enqueue_task_fn *enqueue_task;
    ms_finish_task_fn *finish_task;
    void *user_task_context;
} ms_sim_desc;

MS_API ms_sim_desc ms_sim_desc_default(void);
MS_API ms_status ms_sim_create(const ms_sim_desc *d, ms_sim **out);
MS_API ms_status ms_sim_create_from_scene(const ms_scene *sc, int threads, ms_sim **out);
MS_API void ms_sim_destroy(ms_sim *sim);
MS_API ms_status ms_sim_step(ms_sim *sim, float frame_dt);
MS_API const float *ms_sim_height(const ms_sim *sim, int *nx, int *ny); /* combined field */
MS_API ms_volume *ms_sim_volume(ms_sim *sim);   /* NULL when the scene has no volume */
MS_API ms_surface *ms_sim_surface(ms_sim *sim); /* NULL when the scene has no surface */

/* The parts of the last finished frame (views, valid until the next
 * ms_sim_step). NULL (and *nx = *ny = 0) for a part the sim does not have. */
MS_API const float *ms_sim_surface_height(const ms_sim *sim, int *nx, int *ny);
MS_API const float *ms_sim_volume_height(const ms_sim *sim, int *nx, int *ny);
/* Where a field (one MS_FIELD_COMBINED/SURFACE/VOLUME bit) lies in the world. */
MS_API ms_status ms_sim_field_grid(const ms_sim *sim, unsigned field, ms_grid *out);
/* Particles as structure-of-arrays views: pos[0..2] = x, y, z and
 * vel[0..2] = vx, vy, vz, n each; *n = 0 and NULL views without a volume. */
MS_API ms_status ms_sim_particles(const ms_sim *sim, int *n, const float *pos[3],
                                  const float *vel[3]);
MS_API double ms_sim_time(const ms_sim *sim);   /* s, time of the fields above */
MS_API long ms_sim_frame(const ms_sim *sim);    /* frames finished */
MS_API const ms_scene *ms_sim_scene(const ms_sim *sim); /* NULL when made from a desc */

typedef struct ms_stats {
    double volume_ms, surface_ms, extract_ms, combine_ms, render_ms, total_ms;
    long volume_steps, surface_steps, frames;
    size_t bytes;
} ms_stats;
MS_API void ms_sim_stats(const ms_sim *sim, ms_stats *out);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SIM_H */
