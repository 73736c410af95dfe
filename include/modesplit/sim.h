/* ms_sim: the mode-splitting coupler (paper sections 3.1, 3.4, 3.5, Fig. 8).
 *
 * N_time surface steps per volume step (eq. 19), the SPH height field
 * up-sampled bilinearly by N_surf onto the wave grid and summed (eq. 20),
 * two-way coupling, and the two-core split: the volume thread runs frame n
 * while the surface thread finishes frame n-1. threads = 1 runs the same
 * one-frame pipeline in order, so 1 and 2 threads give the same bytes.
 *
 * Not thread-safe: one handle, one thread at a time (its own worker thread,
 * or the engine's tasks, are internal); only ms_sim_cancel may be called
 * from another thread. A second thread caught in ms_sim_step while the
 * first is still in it gets MS_ERR_STATE (a cheap check, not a lock: it
 * cannot catch every misuse, such as ms_sim_destroy during a step).
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
 * itself (ms_task_fn and friends, core.h): the two-core split and the
 * volume's parallel loops. Given (in the desc, or by ms_sim_set_tasks
 * before the first step), no pthread is created, whatever the thread
 * counts of the sim and volume descs. When both are NULL the sim uses its
 * own pthreads, started by the first ms_sim_step. */

/* threads = 2 runs the volume and the surface tasks at the same time (a
 * volume-only sim instead gives the volume solver two threads; otherwise
 * the volume desc's own `threads` may add threads inside the SPH step);
 * threads = 1 runs everything on the calling thread (the volume's threads
 * is then 1); all give the same bytes. The fields a
 * step publishes are one frame old (the pipeline of Fig. 8): after the n-th
 * ms_sim_step they show time (n - 1) * frame_dt, the first step publishes
 * the start. ms_sim_volume / ms_sim_surface may be used between steps
 * (to add particles, drops, ...), never during one. */
typedef struct ms_sim_desc {
    uint32_t size;                /* sizeof, set by ms_sim_desc_default() (core.h: struct sizes) */
    const ms_volume_desc *volume; /* NULL: no volume flow */
    const ms_surface_desc *surface; /* NULL: no surface waves */
    int field_nx, field_ny;         /* X_SPH x Y_SPH; N_surf = surface nx / field_nx (eq. 20) */
    int surface_substeps;           /* N_time (eq. 19); 0 = derived from the CFL bound */
    float couple_surface_from_volume, couple_volume_from_surface; /* [0, 0.25], [0, 1] */
    int threads; /* 1 = sequential, 2 = two-core split */
    /* --- grown at the end (ABI: descs only grow) --- */
    ms_enqueue_task_fn *enqueue_task;
    ms_finish_task_fn *finish_task;
    void *user_task_context;
} ms_sim_desc;

MS_API ms_sim_desc ms_sim_desc_default(void);
MS_API ms_status ms_sim_create(const ms_sim_desc *d, ms_sim **out);
/* The checks ms_sim_create makes before it allocates: its own fields, the
 * volume and surface descs (ms_volume_desc_check, ms_surface_desc_check)
 * and the x-y extent they must share. */
MS_API ms_status ms_sim_desc_check(const ms_sim_desc *d);
/* The sim desc of a scene (threads, coupling, volume.field) whose volume
 * and surface point at the scene's descs (ms_scene_volume_desc): valid
 * while the scene lives. The effects, fills and obstacles of the scene
 * are not in it: ms_sim_create_from_scene adds them. out is written up to
 * its .size (core.h: struct sizes). */
MS_API ms_status ms_scene_sim_desc(const ms_scene *sc, ms_sim_desc *out);
/* A sim of the scene's parts and effects, filled as the scene says.
 * threads: 1, 2, or 0 = the scene's `threads`. The scene must outlive the
 * sim (ms_sim_scene returns it). */
MS_API ms_status ms_sim_create_from_scene(const ms_scene *sc, int threads, ms_sim **out);
MS_API void ms_sim_destroy(ms_sim *sim);
/* Hand the two-core split to an engine's task system (as ms_sim_desc's
 * enqueue_task/finish_task, for a sim made from a scene), or with both
 * NULL back to the sim's own thread. Between steps only. */
MS_API ms_status ms_sim_set_tasks(ms_sim *sim, ms_enqueue_task_fn *enqueue_task,
                                  ms_finish_task_fn *finish_task, void *user_task_context);
/* Advance one frame of frame_dt seconds, (0, 10]. MS_ERR_UNSTABLE (with
 * the bound) when a solver cannot keep it stable, e.g. a scene's n_time
 * too small for the CFL bound; after a failed step every further step
 * returns MS_ERR_STATE. */
MS_API ms_status ms_sim_step(ms_sim *sim, float frame_dt);
/* Ask a step in progress to stop (any thread, e.g. an engine's watchdog or
 * a signal handler's flag): the volume and the surface stop at their next
 * sub-step and ms_sim_step returns MS_ERR_CANCELED; the sim is then failed
 * (further steps return MS_ERR_STATE) but its views, stats and a writer's
 * frames stay valid. */
MS_API void ms_sim_cancel(ms_sim *sim);
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
 * vel[0..2] = vx, vy, vz, n each; *n = 0 and NULL views without a volume.
 * The three arrays of pos (and of vel) lie in one block at equal distances
 * (pos[2] - pos[1] == pos[1] - pos[0] > 0), so an FFI user can view them as
 * one (n, 3) array with strides (sizeof(float), pos[1] - pos[0]). */
MS_API ms_status ms_sim_particles(const ms_sim *sim, int *n, const float *pos[3],
                                  const float *vel[3]);
MS_API double ms_sim_time(const ms_sim *sim);           /* s, time of the fields above */
MS_API long ms_sim_frame(const ms_sim *sim);            /* frames finished */
MS_API const ms_scene *ms_sim_scene(const ms_sim *sim); /* NULL when made from a desc */

/* Statistics since creation. The stage times are the milliseconds each
 * stage ran (with threads = 2 the volume and surface stages overlap, so
 * they may add up to more than total_ms, the wall time of ms_sim_step).
 *   volume_ms   interaction, surface->volume coupling and SPH (volume thread),
 *               with the neighbour pass at the step's end positions that
 *               the extraction reads and the next step starts from
 *   extract_ms  height-field extraction (eqs. 16-18) and the particle copy:
 *               the surface particles on the volume thread, the columns
 *               and the smoothing on the surface thread (the flow of the
 *               floaters too)
 *   surface_ms  scripted effects, volume->surface coupling, wave steps
 *   combine_ms  up-sampling and sum (eq. 20), floaters, spray (spray_ms
 *               is its share)
 * volume_steps / surface_steps are the SPH / leapfrog sub-steps taken;
 * bytes is all memory held, split below. An effect the scene does not name
 * adds nothing to any of them. */
typedef struct ms_stats {
    uint32_t size; /* sizeof, set by ms_stats_init() (core.h: struct sizes) */
    double volume_ms, surface_ms, extract_ms, combine_ms, render_ms, total_ms;
    long volume_steps, surface_steps, frames;
    size_t bytes;
    /* --- grown at the end --- */
    size_t volume_bytes;  /* SPH solver, its height fields and particle copies */
    size_t surface_bytes; /* wave solver, combined field, up-sampling, coupling buffers */
    size_t effects_bytes; /* obstacle masks, floaters, shapes' bookkeeping */
    long drops;           /* drops added to the waves (scripted and rain) */
    int n_time;           /* wave steps in the last frame (eq. 19) */
    int spray;            /* spray particles in flight (scene effects.spray) */
    long spray_emitted;   /* spray particles emitted since creation */
    double spray_ms;      /* emission, flight and foam (on the surface thread) */
} ms_stats;
static inline ms_stats ms_stats_init(void)
{
    ms_stats x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}
MS_API void ms_sim_get_stats(const ms_sim *sim, ms_stats *out);
/* The old name of ms_sim_get_stats (one pattern: *_get_info, *_get_stats). */
MS_DEPRECATED("use ms_sim_get_stats")
MS_API void ms_sim_stats(const ms_sim *sim, ms_stats *out);

/* What the sim runs (for listings such as `modesplit info`). */
typedef struct ms_sim_info {
    uint32_t size; /* sizeof, set by ms_sim_info_init() (core.h: struct sizes) */
    int has_volume, has_surface;
    int threads;                /* 1 or 2 as created */
    int field_nx, field_ny;     /* X_SPH x Y_SPH (0 without a volume) */
    int surface_nx, surface_ny; /* X_WE x Y_WE (0 without a surface) */
    float n_surf_x, n_surf_y;   /* eq. 20: X_WE / X_SPH, Y_WE / Y_SPH (0 if either is absent) */
    int n_time;                 /* eq. 19: as given, or 0 = derived each frame */
    int particles;              /* particles now */
    int floaters;               /* floating objects */
    int obstacles;              /* obstacles + container */
    /* --- grown at the end --- */
    float spacing;    /* m, the volume's particle spacing (0 without a volume) */
    int spray_budget; /* spray particles in flight at most (scene effects.spray; 0 = none) */
} ms_sim_info;
static inline ms_sim_info ms_sim_info_init(void)
{
    ms_sim_info x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}
MS_API void ms_sim_get_info(const ms_sim *sim, ms_sim_info *out);

/* Objects carried by the flow (scene effects.floaters, the paper's
 * leaves): 3n floats x, y, z (m; z on the combined surface) of the
 * published frame; NULL and *n = 0 without floaters. View valid until the
 * next ms_sim_step. */
MS_API const float *ms_sim_floaters(const ms_sim *sim, int *n);

/* Spray (scene effects.spray): 3n floats x, y, z (m) of the particles in
 * flight at the published frame, thrown by fast SPH particles at the
 * surface and falling back ballistically; NULL and *n = 0 without spray.
 * The foam cover on the surface, in [0, 1], nx * ny cells on the wave grid
 * (the SPH field's grid without waves; ms_sim_foam_grid): where spray
 * lands and the surface breaks, fading with the scene's lifetime; NULL
 * and *nx = *ny = 0 without spray. Views valid until the next
 * ms_sim_step. */
MS_API const float *ms_sim_spray(const ms_sim *sim, int *n);
MS_API const float *ms_sim_foam(const ms_sim *sim, int *nx, int *ny);
/* Where the foam cover lies in the world; MS_ERR_STATE without spray. */
MS_API ms_status ms_sim_foam_grid(const ms_sim *sim, ms_grid *out);

/* The user dragging the water (paper Fig. 1), for engines: during the
 * next frame's volume step, water within radius (m) of the point `depth`
 * (m) below the surface at (pos[0], pos[1]) (m) is pulled towards the
 * velocity vel (m/s, horizontal) at `strength` (1/s). Up to 8 per frame.
 * MS_ERR_STATE without a volume. */
MS_API ms_status ms_sim_drag(ms_sim *sim, const float pos[2], const float vel[2], float radius,
                             float depth, float strength);

/* Move the scene's container (the glass of water) or obstacle i (scene
 * order) to pos (m) with velocity vel (m/s) from the next frame on,
 * replacing its scripted path. MS_ERR_STATE without one. */
MS_API ms_status ms_sim_move_container(ms_sim *sim, const float pos[3], const float vel[3]);
MS_API ms_status ms_sim_move_obstacle(ms_sim *sim, int i, const float pos[3], const float vel[3]);
/* Turn the container (tilt the glass to pour) or obstacle i about its
 * origin: orientation as a quaternion (w, x, y, z) from the shape's frame
 * to the world's (normalised; a zero or non-finite one is refused), omega
 * its angular velocity (rad/s, world axes, NULL = 0), from the next frame
 * on (ms_shape_set_orientation). Its path or ms_sim_move_* still sets
 * where it is. */
MS_API ms_status ms_sim_turn_container(ms_sim *sim, const float orientation[4],
                                       const float omega[3]);
MS_API ms_status ms_sim_turn_obstacle(ms_sim *sim, int i, const float orientation[4],
                                      const float omega[3]);

/* A user at the controls (lib/sim/interact.c). Rain on (1: the scene's
 * effects.rain, or a light shower when it names none) or off (0), from
 * the next frame on; MS_ERR_STATE without a surface. */
MS_API ms_status ms_sim_set_rain(ms_sim *sim, int on);
/* Steer the scene's boat (effects.boat) by hand: from the next frame on it
 * moves at vel (m/s, each in [-100, 100]) from where it is, its scripted
 * path dropped; it stops at the pool's edge. MS_ERR_STATE without a boat. */
MS_API ms_status ms_sim_steer_boat(ms_sim *sim, const float vel[2]);
/* Where the boat is now (world x, y, m). MS_ERR_STATE without a boat. */
MS_API ms_status ms_sim_boat(const ms_sim *sim, float pos[2]);
/* Where the container is now (m) and its orientation (w, x, y, z; NULL to
 * skip), to move or tilt it from there. MS_ERR_STATE without one. */
MS_API ms_status ms_sim_container_pose(const ms_sim *sim, float pos[3], float orientation[4]);

/* Snapshot and restore: the whole state of the sim between two
 * steps as one byte blob (particles in the solver's order, the wave field
 * and its previous step, maps set at run time, the pipeline's hand-over
 * buffers, RNG states, effect phases, floaters, time and frame counter),
 * so that a sim restored from it steps to the same bytes as one never
 * stopped, with 1 or 2 threads. The blob is versioned and size-led: a
 * header with the format version, the library version, a hash of the
 * scene or desc, a checksum; then named records. It is for the build that
 * wrote it (machine byte order). Statistics are not restored: they count
 * this handle's work. Between steps only.
 * ms_sim_snapshot_size gives the bytes ms_sim_snapshot writes now (it
 * changes as particles are added); ms_sim_snapshot refuses a smaller
 * buffer and a failed sim. ms_sim_restore takes a blob of a sim made the
 * same way (same scene text, or the same descs; the threads may differ)
 * and refuses another format or library version (MS_ERR_UNSUPPORTED), a
 * cut, corrupt or foreign blob and another scene (MS_ERR_INVALID_ARGUMENT,
 * naming what differs) before it changes anything; a restore clears a
 * failed sim. */
MS_API ms_status ms_sim_snapshot_size(const ms_sim *sim, size_t *bytes);
MS_API ms_status ms_sim_snapshot(const ms_sim *sim, void *buf, size_t capacity, size_t *written);
MS_API ms_status ms_sim_restore(ms_sim *sim, const void *buf, size_t bytes);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SIM_H */
