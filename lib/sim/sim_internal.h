/* lib/sim: the mode-splitting coupler (internal layout).
 *
 * Owns: running the volume (SPH) and the surface (wave equation) side by
 * side at their own time steps and resolutions (paper 3.1), N_time wave
 * steps per volume step (eq. 19), the bilinear up-sampling of the SPH
 * height field by N_surf onto the wave grid and the sum (eq. 20, Fig. 7),
 * the two-way coupling (3.5), the scene's effects (rain, boat, drops,
 * obstacles, the dragging pointer, the moved container, floating leaves),
 * the two-core split of Fig. 8 and the stage statistics.
 *
 * The one-frame pipeline. Call n of ms_sim_step (n = 1, 2, ...) runs two
 * tasks that share no mutable data:
 *   V (volume thread):  interaction at t_{n-1} (drag, moved container and
 *                       obstacles, surface->volume coupling with the wave
 *                       field W_{n-2}), SPH from t_{n-1} to t_n, phase A
 *                       of the extraction at t_n (the surface particles
 *                       marked over the neighbour lists and copied into a
 *                       snapshot, volume/extract.h) and a copy of the
 *                       particles.
 *   S (surface thread): frame m = n-1: phase B of the extraction, the
 *                       height field H_m from V's snapshot of t_m (column
 *                       search and smoothing, eqs. 16-18) and, with
 *                       floaters, the surface flow; scripted effects at
 *                       t_{m-1}, the waves excited by the SPH field's rate
 *                       (H_m - H_{m-1}) / dt (3.5), N_time wave steps from
 *                       t_{m-1} to t_m, the combined field up(H_m) + W_m,
 *                       floaters.
 * V writes slot n % 2 of the hand-over buffers (snapshot, particles) and
 * S reads slot (n-1) % 2 (what V wrote in the previous call) and writes
 * H_{n-1} into hfield[(n-1) % 2]; the same for the wave field copy handed
 * from S to V. The pointer's drag in V needs the height H_{n-1} at one
 * cell while S is computing that field: V computes that cell alone from
 * the same snapshot (ms_extract_cell, the same bits). With threads = 1 the
 * two tasks run one after the other, with threads = 2 at the same time:
 * same inputs, same operations, same bytes. Only phase A touches the
 * volume handle, which the volume thread is stepping (Fig. 8 puts the
 * extraction on the surface core).
 */
#ifndef MS_SIM_INTERNAL_H
#define MS_SIM_INTERNAL_H

#include <pthread.h>
#include <stdatomic.h>

#include "core/core_internal.h"
#include "modesplit/shape.h"
#include "modesplit/sim.h"
#include "scene/scene_internal.h"
#include "volume/extract.h"

#define MS_SIM_MAX_DRAGS 8
#define MS_SIM_ERR_LEN 1024

/* A shape of the scene: one instance for the volume thread (collider) and
 * one for the surface thread (footprint), so the threads never share one. */
typedef struct ms_sim_shape {
    ms_shape *vol;   /* NULL without a volume */
    ms_shape *surf;  /* NULL without a surface or without surface_mask */
    ms_shape *spray; /* the spray's twin (surface thread), NULL without spray */
    const ms_scene_shape *spec;
    int moving;  /* has a path, a velocity or was moved by the API */
    int api_set; /* pose given by ms_sim_move_* (overrides the path) */
    float api_pos[3], api_vel[3];
    int api_turn; /* orientation given by ms_sim_turn_* */
    float api_quat[4], api_omega[3];
} ms_sim_shape;

/* Spray and foam (spray.c), made only for a scene's effects.spray. */
typedef struct ms_sim_spray_state {
    int cap, n;             /* the budget; spray particles alive */
    float *pos, *vel;       /* 3 * cap each: x, y, z (m), vx, vy, vz (m/s) */
    float g[3];             /* m/s^2, the volume's gravity */
    float *cell_v;          /* 3 * fnx * fny: the surface band's mean velocity */
    float *cell_n;          /* fnx * fny: particles in the band */
    int gnx, gny;           /* the foam grid: the wave grid, or the SPH field's */
    float gdx, gdy;         /* m */
    float *foam, *foam_tmp; /* gnx * gny: cover in [0, 1], and the advection's scratch */
    int foam_on;            /* some cell holds foam (else decay and advection are skipped) */
    int box[4];             /* with foam_on: the cells holding foam lie in [box[0], box[1]] x
                             * [box[2], box[3]] */
    ms_rng rng;             /* seeded from the scene's seed */
    long emitted, landed;   /* since creation (not state: statistics) */
    double ms;              /* ms spent, statistics */
} ms_sim_spray_state;

typedef struct ms_sim_drag_req {
    float pos[2], vel[2]; /* m, m/s */
    float radius, depth, strength;
} ms_sim_drag_req;

/* A running task's result: the status and the sentence of the thread that
 * ran it (ms_last_error is thread-local), and its stage times. */
/* One frame's plan, made once by ms_sim_step for the frame it is called
 * with (n) and received by both tasks: the volume task steps frame n by
 * dt within its sub-step budget; the surface task, one call later (the
 * pipeline's lag), takes the same record up and advances the waves over
 * that frame in n_time steps of wave_dt (eq. 19). The wave part is filled
 * when the surface takes the frame up (ms_sim_plan_waves), so a speed map
 * an engine sets between the two calls is honoured. */
typedef struct ms_frame_plan {
    float dt;            /* s, the frame, in (0, 10] (checked once, in ms_sim_step) */
    int volume_substeps; /* the volume's sub-step budget (its desc's max_substeps) */
    int n_time;          /* eq. 19: wave steps over dt; 0 until the surface takes it up */
    float wave_dt;       /* s, dt / n_time: each within the wave grid's CFL bound */
} ms_frame_plan;

typedef struct ms_sim_task {
    ms_sim *sim;
    const ms_frame_plan *plan; /* V: frame n's; S: frame n - 1's */
    ms_status status;
    char err[MS_SIM_ERR_LEN];
    double ms_a, ms_b; /* V: step, extract (phase A, particle copy); S: waves, combine */
    double ms_x;       /* S: extract (phase B, surface flow) */
    int alone;         /* S runs while V does not: it may use the volume's threads */
} ms_sim_task;

struct ms_sim {
    const ms_scene *scene; /* NULL when made from a desc; not owned */
    int threads;
    ms_enqueue_task_fn *enqueue;
    ms_finish_task_fn *finish;
    void *user_ctx;

    ms_volume *volume;
    ms_surface *surface;
    float domain_min[3], domain_max[3]; /* m */
    float level;                        /* m above domain_min z: still water (no volume) */
    float gravity;                      /* m/s^2, |g| for floaters on wave slopes */
    float spacing;                      /* m, particle spacing (near-surface band) */

    /* grids */
    int fnx, fny;           /* X_SPH x Y_SPH */
    int snx, sny;           /* X_WE x Y_WE */
    float sdx;              /* m */
    int n_time_fixed;       /* eq. 19 from the scene/desc; 0 = derived */
    float gain_sv, gain_vs; /* surface<-volume, volume<-surface */

    /* hand-over buffers (slot = call % 2, see above) */
    ms_extract_snap snap[2];        /* phase A of the extraction, from V */
    ms_extract_work work_v, work_s; /* phase B's scratch of V (drag) and S */
    float *hfield[2];               /* fnx * fny: H, phase B in S */
    float *flow[2];                 /* 2 * fnx * fny: surface flow (vx, vy) from V, for floaters and
                          surface.advect */
    float *flow_count;              /* fnx * fny: S's scratch for the flow */
    float *flow_comp;               /* fnx * fny: one component of the flow (surface.advect) */
    float *current[2];              /* snx * sny: the flow up-sampled, ux and uy (surface.advect) */
    float *current_wall; /* snx * sny: up(H), then 1 on the waves' walls (surface.advect) */
    float *current_line; /* max(snx, sny): a row's or column's distances to a wall */
    float *ppos[2][3], *pvel[2][3]; /* particle copies, SoA */
    int pcount[2], pcap[2];
    float *wave_snap[2]; /* fnx * fny: W averaged per SPH cell, from S (gain_vs > 0) */
    int *wave_colmap;    /* snx: SPH column of each wave column */
    float *wave_rowsum;  /* fnx * fny: S's scratch for the average */
    ms_grid wave_grid, field_grid;

    /* surface-thread buffers */
    float *hprev;           /* fnx * fny: H_{m-1} */
    float *dh;              /* fnx * fny: the coupling's impulse (m) */
    float *u_prev;          /* fnx * fny: the coupling's velocity offset of the last frame (m/s) */
    unsigned char *rim;     /* fnx * fny: 1 within the rim radius of a dry cell (no drive) */
    unsigned char *rim_row; /* fnx * fny: the dilation's first (along x) pass */
    float wave_dt_last;     /* s, the last wave step taken */
    float *excite;          /* snx * sny: up(dh) */
    float *combined;        /* snx * sny (with a surface) */
    int *ix0, *ix1, *iy0, *iy1; /* bilinear taps per column / row (eq. 20) */
    float *wx, *wy;
    float *rowtmp;                     /* fny * snx: SPH rows up-sampled along x */
    unsigned char *mask_static, *mask; /* snx * sny obstacle masks */
    int have_moving_mask;

    /* effects */
    ms_sim_shape *shapes;   /* obstacles then the container */
    int nshapes, container; /* container: index into shapes, -1 = none */
    int boat_id, boat_started;
    float *boat_xy; /* the boat's path from the wave grid's corner (m) */
    int drag_id;    /* surface disturber for a drag without volume */
    int next_drop;  /* scripted drops applied so far (scene order is by time) */
    int *drop_order;
    int nfloaters;
    float *floater_xyz; /* 3 * n: x, y, z (m) */
    float *floater_vel; /* 2 * n: m/s */
    ms_sim_drag_req drags[MS_SIM_MAX_DRAGS];
    int ndrags;
    ms_sim_spray_state spray; /* spray and foam (spray.c); all 0 unless the scene asks */

    /* time */
    long calls;      /* ms_sim_step calls done = frames finished */
    double t_volume; /* s, the volume's time (t_n after call n) */
    double t_fields; /* s, time of the published fields (t_{n-1}) */
    /* the plans of the last two frames, frame n's at plan[n % 2]: while
     * call n runs, the volume's plan[n % 2], the surface's plan[(n - 1) % 2] */
    ms_frame_plan plan[2];
    int primed; /* H_0 and the particle copy of t_0 taken */
    int failed;
    _Atomic int busy; /* a thread is in ms_sim_step (one thread per handle) */
    char fail_msg[MS_SIM_ERR_LEN];
    ms_status fail_status;

    /* statistics */
    ms_stats stats;
    size_t own_volume_bytes, own_surface_bytes, own_effects_bytes;

    /* the sim's own worker thread (threads = 2, no engine callbacks) */
    int have_worker;
    pthread_t worker;
    pthread_mutex_t mu;
    pthread_cond_t cv_go, cv_done;
    long go_gen, done_gen;
    int quit;
    ms_task_fn *worker_fn;
    void *worker_arg;
};

/* step.c: eq. 19 for a frame of dt seconds: *n_time wave steps of
 * *wave_dt, the scene's N_time or the fewest within the CFL bound of the
 * wave grid, the one place the sim reads that bound. MS_ERR_UNSTABLE when
 * a fixed N_time's steps exceed it, or more than 1e7 steps are needed. */
ms_status ms_sim_plan_waves(const ms_sim *sim, float dt, int *n_time, float *wave_dt);
/* The plan of the frame whose waves were stepped last (n_time 0 before the
 * surface took one up), and of the frame the volume stepped last. */
static inline const ms_frame_plan *ms_sim_wave_plan(const ms_sim *sim)
{
    return &sim->plan[(unsigned long)(sim->calls - 1) & 1u];
}
static inline const ms_frame_plan *ms_sim_volume_plan(const ms_sim *sim)
{
    return &sim->plan[(unsigned long)sim->calls & 1u];
}
/* create.c */
ms_status ms_sim_setup_effects(ms_sim *sim, const ms_scene *sc);

/* upsample.c: up[j*snx + i] = bilinear(f at the wave cell centre) (eq. 20) */
ms_status ms_sim_upsample_init(ms_sim *sim);
/* Frees what ms_sim_upsample_init made. */
void ms_sim_upsample_free(ms_sim *sim);
void ms_sim_upsample(const ms_sim *sim, const float *field, float *rowtmp, float *out);
/* out = up(field) + wave */
void ms_sim_upsample_add(const ms_sim *sim, const float *field, const float *wave, float add,
                         float *rowtmp, float *out);
/* ms_surface_excite(s, up(e), 1) in one pass, into the solver's rows */
ms_status ms_sim_upsample_excite(ms_sim *sim, const float *e, ms_surface *s);
/* out = up(field) + wave (rows stride floats apart) and, if avg is not
 * NULL, ms_sim_average_waves of it, in one pass */
/* The largest fraction of the local depth up(H) the waves may add or
 * take away in the combined field (ms_sim_waves_on_liquid): a trough of
 * 0.8 of the depth leaves a fifth of the liquid, never the floor. */
#define MS_SIM_WAVE_DEPTH_FRAC 0.8f
void ms_sim_waves_on_liquid(ms_sim *sim, const float *field);
void ms_sim_combine(ms_sim *sim, const float *field, const float *wave, size_t stride, float *out,
                    float *avg);

/* volume_task.c / surface_task.c */
/* Place s (the volume's or the surface's twin of sh) where sh is at time
 * t (s): its pose (the engine's, its path, or position + velocity t) and,
 * when turned or turning, its orientation. */
ms_status ms_sim_shape_place(const ms_sim_shape *sh, ms_shape *s, double t);
/* Moves or turns during the run (its footprint is redrawn each frame). */
static inline int ms_sim_shape_dynamic(const ms_sim_shape *sh)
{
    return sh->moving || sh->api_set || sh->api_turn;
}
int ms_sim_motion_active(const ms_scene_motion *p, double t);
void ms_sim_volume_task(void *task);
void ms_sim_surface_task(void *task);
/* Phase A of the extraction into snap[slot] and the particle copy (V). */
ms_status ms_sim_volume_snap(ms_sim *sim, int slot);
/* Phase B into hfield[slot] and the surface flow of slot (S). */
ms_status ms_sim_volume_field(ms_sim *sim, int slot, int alone);

/* The wave field averaged over each SPH cell (fnx * fny), for the volume. */
void ms_sim_average_waves(ms_sim *sim, const float *wave, float *out);

/* worker.c */
ms_status ms_sim_worker_start(ms_sim *sim);
/* The threads of threads = 2 (worker.c): the engine's tasks when given,
 * else the sim's own second thread (from the first frame); either way a volume of one thread
 * shares its loops with the other side (or with the engine's tasks). */
ms_status ms_sim_setup_threads(ms_sim *sim);
/* The sim's own second thread, started by the first frame that needs it
 * (threads = 2, a volume, no engine tasks); MS_OK otherwise. */
ms_status ms_sim_worker_ensure(ms_sim *sim);
void ms_sim_worker_stop(ms_sim *sim);
void ms_sim_worker_run(ms_sim *sim, ms_task_fn *fn, void *arg);
void ms_sim_worker_wait(ms_sim *sim);

/* spray.c: set up from the scene (its buffers, counted as effects), one
 * frame's spray and foam on the surface thread (slot: the particle copy
 * and field of t_m; dt: frame m's, 0 for the first), and the landing
 * surface (m, world z) at (x, y). */
ms_status ms_sim_spray_setup(ms_sim *sim, const ms_scene *sc);
void ms_sim_spray_free(ms_sim *sim);
void ms_sim_spray_frame(ms_sim *sim, int slot, float dt);
float ms_sim_surface_z(const ms_sim *sim, int slot, float x, float y);
/* The frame's parts (tests call them alone): the ballistic flight over dt
 * (landing adds foam to the cell), and the foam's fade over dt, carried
 * by flow (2 floats per SPH field cell) when it is not NULL. */
void ms_sim_spray_fly(ms_sim *sim, int slot, float dt, float foam);
void ms_sim_foam_step(ms_sim *sim, const float *flow, float dt, float lifetime);

/* floaters.c */
/* Bilinear sample of a cell-centred nx x ny field (stride comp floats per
 * cell, component k) at world (x, y), the grid's corner at (x0, y0), cells
 * dx x dy (m), edges held. */
float ms_sim_sample(const float *f, int nx, int ny, int comp, int k, float x0, float y0, float dx,
                    float dy, float x, float y);
void ms_sim_floaters_step(ms_sim *sim, const float *flow, const float *wave, float dt);
void ms_sim_floaters_height(ms_sim *sim);

#endif /* MS_SIM_INTERNAL_H */
