/* ms_volume: the low-frequency half of mode splitting (paper section 3.3).
 *
 * Smoothed particle hydrodynamics after Mueller, Charypar & Gross 2003, as
 * the paper gives it: density by eq. 9, the spiky pressure kernel and force
 * (eqs. 11, 13), the viscosity kernel and force (eqs. 12, 14), gravity,
 * symplectic Euler, and the collider force field of eq. 15. The domain box
 * is always a collider (its walls reflect the liquid). ms_volume_extract_height
 * gives the 2.5D free surface of eqs. 16-18 over the domain's x-y extent.
 *
 *     ms_volume_desc d = ms_volume_desc_default();  // 1 m box, h = 0.08 m
 *     ms_volume *v;
 *     if (ms_volume_create(&d, &v) != MS_OK) puts(ms_last_error());
 *     ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.3f, 1, 0.5f});
 *     for (int f = 0; f < 60; ++f) ms_volume_step(v, 1.0f / 60);
 *     float h[50 * 50];
 *     ms_volume_extract_height(v, 50, 50, h);     // m above domain_min[2]
 *     ms_volume_destroy(v);
 *
 * Departures from the printed equations, each measured (see lib/volume/):
 * eq. 14's leading minus sign is Mueller's plus (the printed sign is
 * anti-diffusion); eq. 13 is scaled by a constant so that p is the pressure
 * the liquid exerts (hydrostatic p = rho0 g d); pressures are clamped at 0
 * (tensile instability); the density kernel is eq. 11's by default
 * (energy-consistent with eq. 13), Mueller's poly6 on request.
 *
 * MS_PRESSURE_DFSPH replaces the equation of state by the incompressible
 * solves of Bender & Koschier 2015/2017 (lib/volume/dfsph.c): sub-steps
 * at the velocity's CFL, average compression <= desc.max_density_error.
 *
 * Deterministic: the same calls give the same bytes, for any desc.threads.
 * Not thread-safe: one handle, one thread at a time (its own worker threads
 * are internal).
 */
#ifndef MODESPLIT_VOLUME_H
#define MODESPLIT_VOLUME_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ms_pressure {
    MS_PRESSURE_IDEAL_GAS = 0, /* p = k (rho - rho0), the paper's */
    MS_PRESSURE_TAIT = 1,      /* weakly compressible, gamma = 7 */
    MS_PRESSURE_DFSPH = 2,     /* incompressible: divergence-free SPH (Bender &
                                  Koschier 2015, 2017), steps at the velocity's CFL */
    MS_PRESSURE_FORCE_32BIT_ = 0x7fffffff
} ms_pressure;

/* The kernel of the density sum (eq. 9 with A = rho). */
typedef enum ms_density_kernel {
    MS_DENSITY_SPIKY = 0, /* W_press of eq. 11, the kernel of the pressure
                             force: energy-consistent, stable with mu = 0 */
    MS_DENSITY_POLY6 = 1, /* Mueller et al. 2003's poly6: not energy-consistent
                             with eq. 13's spiky gradient; needs mu of about
                             0.01 rho0 c h to stay still */
    MS_DENSITY_FORCE_32BIT_ = 0x7fffffff
} ms_density_kernel;

/* The most particles a volume holds (desc.max_particles). */
#define MS_VOLUME_MAX_PARTICLES (1L << 24)

typedef struct ms_volume_desc {
    uint32_t size; /* sizeof, set by ms_volume_desc_default() (core.h: struct sizes) */
    float domain_min[3], domain_max[3]; /* m, the box the liquid lives in (a collider) */
    float spacing;                      /* m, particle spacing of fill_box */
    float smoothing_length;             /* m, h of eqs. 11-14; >= spacing */
    float rest_density;                 /* kg/m^3 */
    float gas_constant;                 /* J/kg (m^2/s^2), k of p = k (rho - rho0) */
    float viscosity;                    /* Pa s, mu of eq. 14 */
    float gravity[3];                   /* m/s^2 */
    ms_pressure pressure;
    int max_particles;
    /* --- grown at the end (ABI: descs only grow) --- */
    float sound_speed;   /* m/s, c0 of Tait's law p = B((rho/rho0)^7 - 1),
                            B = rho0 c0^2 / 7; (0, 1e4]. Unused by IDEAL_GAS,
                            whose sound speed is sqrt(gas_constant). */
    float courant;       /* CFL number lambda of dt <= lambda h / (c + v_max);
                            (0, 0.5]. 0.5 is the largest the tests prove stable. */
    int max_substeps;    /* sub-steps one ms_volume_step may take; beyond it the
                            step stops with MS_ERR_UNSTABLE; 1 .. 10^7 */
    int threads;         /* 1 .. 64 threads inside a step; every count gives
                            the same bytes (per-particle sums in a fixed order).
                            The threads - 1 pthreads start at the first step,
                            none if ms_volume_set_tasks gave an engine's tasks */
    int smooth_steps;    /* eq. 18: smoothing passes of the extracted height
                            field when the liquid is still; 0 .. 64 */
    float smooth_energy; /* J/kg, eq. 18: E_kin / total mass at and above which
                            the height field is not smoothed; > 0 */
    ms_density_kernel density_kernel;
    /* --- DFSPH (MS_PRESSURE_DFSPH; unused by the other laws) --- */
    float max_density_error;       /* average predicted compression (rho/rho0 - 1) the
                                   constant-density solve stops at; (0, 0.1] */
    float max_divergence_error;    /* average dt (D rho/Dt) / rho0 the divergence-free
                                   solve stops at; (0, 0.1] */
    int max_density_iterations;    /* cap of the constant-density solve, 1 .. 10000;
                                      beyond it the sub-step goes on with the error
                                      reached (ms_volume_info says how many) */
    int max_divergence_iterations; /* cap of the divergence-free solve, 0 (off) .. 10000 */
} ms_volume_desc;

/* A 1 x 1 x 1 m domain at the origin, spacing 0.04 m, h = 0.08 m, water
 * (1000 kg/m^3), k = 400 m^2/s^2 (sound speed 20 m/s, ~1% compression per
 * 0.5 m of depth), viscosity 1 Pa s, gravity (0, 0, -9.81), ideal gas,
 * max_particles 262144, sound_speed 20 m/s, courant 0.4, max_substeps
 * 100000, threads 1, smooth_steps 4, smooth_energy 0.02 J/kg; DFSPH:
 * max_density_error 0.001 (0.1 %), max_divergence_error 0.001 (0.1 % of
 * rho0 per sub-step, SPlisHSPlasH's default: the divergence solve then
 * leaves no more drift per sub-step than the density solve allows),
 * max_density_iterations 100, max_divergence_iterations 100. */
MS_API ms_volume_desc ms_volume_desc_default(void);

/* Refuses (MS_ERR_INVALID_ARGUMENT, a sentence naming the value and the
 * bound) any non-finite value, an empty domain, spacing <= 0, h < spacing,
 * h > 4 spacing, a domain narrower than 2 h, a neighbour grid over 2^24 cells,
 * and out-of-range counts; DFSPH with the poly6 density kernel (the
 * solve differentiates the spiky kernel) or DFSPH limits out of range. */
MS_API ms_status ms_volume_create(const ms_volume_desc *d, ms_volume **out);
/* The checks ms_volume_create makes, without creating anything: the place
 * every default's range lives (a scene file's volume keys are checked
 * here too). Every field is range-checked whichever pressure law reads
 * it, so sound_speed -5 m/s is refused under the ideal gas as NaN is. */
MS_API ms_status ms_volume_desc_check(const ms_volume_desc *d);
MS_API void ms_volume_destroy(ms_volume *v);

/* Particles on a cubic lattice of desc.spacing at lo + (i + 0.5) spacing,
 * filling the part of the box [lo, hi] (m) that lies inside the domain, at
 * rest. Refused (nothing added) if the count would pass max_particles. */
MS_API ms_status ms_volume_fill_box(ms_volume *v, const float lo[3], const float hi[3]);
/* Brings the particles to a packing at rest, before the first step (the
 * opt-in start of a scene's volume.settle). The cubic lattice fill_box
 * makes is not one: it is unstable under the pressure that holds its own
 * weight, even with every layer at its hydrostatic density (a lattice
 * relaxed to that equilibrium, moved by 1e-7 m, still rearranges 1.5 s
 * later), and it collapses into a disordered packing in the first seconds
 * of a run, sloshing while it does. settle moves every particle by a
 * seeded jitter of up to a tenth of desc.spacing along each axis (the
 * lattice broken at once, the same bytes on every run), then takes
 * `seconds` of sub-steps with the velocities damped after each,
 * and leaves the particles at rest; the volume's clock and step counts do
 * not move and no thread is started. seconds in [0,
 * MS_VOLUME_SETTLE_MAX_S]; 0 does nothing. */
#define MS_VOLUME_SETTLE_MAX_S 60.0f /* s */
MS_API ms_status ms_volume_settle(ms_volume *v, float seconds);
/* n particles, pos and vel 3n floats (x0 y0 z0 x1 ...; vel NULL = at rest).
 * Every position must lie inside the domain: a particle outside it is
 * refused (the sentence names it) and nothing is added. */
MS_API ms_status ms_volume_add_particles(ms_volume *v, int n, const float *pos, const float *vel);

/* Advance by dt seconds (0 <= dt <= 10). Sub-steps inside: each sub-step
 * takes the largest dt the CFL, viscous, force and collider bounds allow
 * at the current state (times desc.courant), and the step is split into
 * equal parts of at most that, so the same state and dt always take the
 * same sub-steps. A frame hitch (dt = 1 s) is sub-stepped in full, not
 * clamped: it costs time, never stability. If more than desc.max_substeps
 * sub-steps would be needed, the step stops there with MS_ERR_UNSTABLE
 * (the state stays valid, at the time reached). */
MS_API ms_status ms_volume_step(ms_volume *v, float dt);
MS_API int ms_volume_count(const ms_volume *v);
/* Positions (m) and velocities (m/s), 3n floats each, x0 y0 z0 x1 ...,
 * either may be NULL, in the order the particles were added (stable
 * across steps; ms_volume_remove_box keeps the order of the rest). */
MS_API ms_status ms_volume_get_particles(const ms_volume *v, float *pos, float *vel);

/* The liquid's height field (paper section 3.3.2) on an nx x ny grid over
 * the domain's x-y extent: cell (i, j) has its centre at domain_min +
 * ((i + 0.5) extent_x / nx, (j + 0.5) extent_y / ny); out[j*nx + i] is the
 * height in metres of the liquid surface above domain_min[2], 0 where the
 * column holds no liquid.
 *   - surface particles are those with fewer than 3/4 of the neighbours
 *     a particle inside the liquid has; they and their neighbours are the
 *     spheres of eq. 16, phi(x) = sum sqrt(1 - r_i^2 / h^2), and the height
 *     is the topmost z where phi reaches the iso-level that puts a still,
 *     flat liquid's surface half a spacing above its top particle layer;
 *   - adaptive smoothing (eq. 18): the field is smoothed over liquid cells
 *     by desc.smooth_steps passes of a 3 x 3 binomial filter when the liquid
 *     is still, fewer as E_kin / mass rises, none at desc.smooth_energy.
 * Deterministic: the same state gives the same bytes. nx, ny in 1 .. 4096. */
MS_API ms_status ms_volume_extract_height(ms_volume *v, int nx, int ny, float *out);
/* Eq. 18: sum of m v^2 / 2 over the particles, J. */
MS_API double ms_volume_kinetic_energy(const ms_volume *v);

/* A collider (eq. 15): a shape (plane, box, sphere, glass, ... plugins)
 * whose eq. 15 field acts on the particles near it, whose tangent plane
 * reflects the liquid like a wall, and which no particle ends inside or
 * crosses (a swept test in the shape's frame). The volume does not own the
 * shape: the caller keeps it alive (and does not destroy it) while the
 * volume uses it, i.e. until ms_volume_remove_collider or
 * ms_volume_destroy. A moving collider (a glass carried by the user) is
 * moved by the caller with ms_shape_set_pose between steps: during
 * ms_volume_step(dt) the shape starts at its pose and moves on with its
 * velocity, and the liquid is pushed and carried along with it (so after
 * the step set the pose to pos + vel dt). If the caller puts it elsewhere
 * than its velocity took it (a teleport, a pose set without a velocity),
 * the next step sweeps it from there to the new place with the extra
 * velocity jump/dt: the liquid in the way is pushed, not crushed. A
 * particle squeezed between a collider and the domain's wall stays in the
 * domain. At most 64 colliders. */
MS_API ms_status ms_volume_add_collider(ms_volume *v, ms_shape *shape);
MS_API ms_status ms_volume_remove_collider(ms_volume *v, ms_shape *shape);

/* --- interaction (between steps) --- */

/* The paper's mouse drag: during the next ms_volume_step only, particles
 * within radius (m) of centre (m) are pulled towards `velocity` (m/s) at a
 * rate strength * w (1/s) with w = (1 - r/radius)^2, as an exact
 * exponential relaxation, so a drag can never make a particle faster than
 * the faster of its own and the target velocity. Up to 16 drags and pushes
 * per step; they are cleared when the step ends. */
MS_API ms_status ms_volume_drag(ms_volume *v, const float centre[3], float radius,
                                const float velocity[3], float strength);
/* During the next ms_volume_step only, particles within radius (m) of
 * centre get the extra acceleration accel * w (m/s^2), w as above. */
MS_API ms_status ms_volume_push(ms_volume *v, const float centre[3], float radius,
                                const float accel[3]);
/* Remove the particles inside the box [lo, hi] (m); *removed (may be
 * NULL) gets how many. The rest keep their order. */
MS_API ms_status ms_volume_remove_box(ms_volume *v, const float lo[3], const float hi[3],
                                      int *removed);
/* Change mu of eq. 14 (Pa s, >= 0, finite) from the next step on (honey,
 * molten wax; the viscous time-step bound follows). */
MS_API ms_status ms_volume_set_viscosity(ms_volume *v, float viscosity);

/* Coupling from the surface (paper 3.5: "the positions of SPH particles can
 * be adapted according to high surface waves"). wave_height is the wave
 * field (m, g->nx * g->ny values, row-major, placed by g). Each call
 * compares it with the field of the previous call to get the waves'
 * vertical velocity u = dw/dt over the volume time between the two calls,
 * and relaxes the vertical velocity of each surface particle towards u by
 * the factor gain (0 .. 1): vz += gain (u - vz). A convex blend cannot
 * make a particle faster than the faster of itself and the wave, so the
 * energy it adds is bounded by the waves' own; u is also capped at a
 * tenth of the sound speed. The first call (or a call with another grid)
 * only records the field. gain 0 = off (nothing is recorded). */
MS_API ms_status ms_volume_adapt_to_waves(ms_volume *v, const float *wave_height, const ms_grid *g,
                                          float gain);

/* --- what a coupler needs --- */

typedef struct ms_volume_info {
    uint32_t size;           /* sizeof, set by ms_volume_info_init() (core.h: struct sizes) */
    double time;             /* s simulated                                       */
    long steps;              /* ms_volume_step calls that advanced time           */
    long substeps;           /* SPH sub-steps taken                               */
    float last_dt;           /* s, the last sub-step                              */
    float max_dt;            /* s, largest stable sub-step at the current state   */
    const char *dt_limit;    /* which bound set max_dt: "cfl", "viscous", "force" */
    float max_speed;         /* m/s, fastest particle                             */
    float sound_speed;       /* m/s, of the pressure law at rest density (DFSPH:
                             desc.sound_speed, used only to cap the coupling) */
    float max_density_error; /* max rho/rho0 - 1: the liquid's compression     */
    float particle_mass;     /* kg                                                */
    int count;               /* particles                                         */
    int surface_count;       /* surface particles at the last density pass        */
    double pairs;            /* neighbour pairs (i != j, r < h) of the last sub-step */
    size_t bytes;            /* memory held                                       */
    int threads;             /* threads used inside a step                        */
    /* --- grown at the end: DFSPH (0 for the other laws) --- */
    int density_iterations;        /* of the last sub-step's constant-density solve */
    int divergence_iterations;     /* of the last sub-step's divergence-free solve  */
    long density_iterations_total; /* over all sub-steps                    */
    long divergence_iterations_total;
    float density_error;    /* average predicted rho/rho0 - 1 the last solve reached */
    float divergence_error; /* average dt (D rho/Dt)/rho0 the last solve reached */
} ms_volume_info;
static inline ms_volume_info ms_volume_info_init(void)
{
    ms_volume_info x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}
MS_API void ms_volume_get_info(const ms_volume *v, ms_volume_info *out);
/* The desc the handle was created from (viscosity as last set). */
MS_API ms_volume_desc ms_volume_get_desc(const ms_volume *v);
/* Run the step's parallel loops (desc.threads chunks) as an engine's tasks
 * (core.h) instead of the volume's own worker threads: given after create
 * and before the first step, no pthread of the library's is ever started;
 * later, the running ones are stopped. Both NULL: the next step starts
 * them again. The same split, so the same bytes. Between steps only;
 * nothing to do with threads = 1. ms_sim hands its own task
 * interface on to its volume (with threads 2 and a volume of one thread,
 * each loop's chunks are shared with one engine task per loop). */
/* Ask a step in progress (on another thread) to stop: it returns
 * MS_ERR_CANCELED at its next sub-step, the state valid at the time
 * reached. Safe from any thread; a request made between steps stops the
 * next step at once. */
MS_API void ms_volume_cancel(ms_volume *v);
MS_API ms_status ms_volume_set_tasks(ms_volume *v, ms_enqueue_task_fn *enqueue_task,
                                     ms_finish_task_fn *finish_task, void *user_task_context);
/* Zero-copy views of the internal arrays (structure of arrays: pos[0..2] =
 * x, y, z, vel[0..2] = vx, vy, vz; *n particles each), in the internal
 * (cell-sorted) order, which changes at every step. Valid until the next
 * mutating call on v. */
MS_API ms_status ms_volume_particle_views(const ms_volume *v, int *n, const float *pos[3],
                                          const float *vel[3]);
/* The particles in the order they were added (as ms_volume_get_particles),
 * as views the volume keeps current: pos[0..2] = x, y, z and vel[0..2] =
 * vx, vy, vz, *n each. As ms_sim_particles, the three arrays of pos (and
 * of vel) lie in one block at equal distances (pos[2] - pos[1] ==
 * pos[1] - pos[0] > 0), so an FFI user views them as one (n, 3) array with
 * strides (sizeof(float), pos[1] - pos[0]) without a copy.
 * The first call makes the volume keep them (6 floats a particle, in
 * ms_volume_info.bytes); from then on each call that changes the particles
 * (ms_volume_step, add_particles, fill_box, remove_box, adapt_to_waves)
 * refreshes them before it returns, one copy of the n particles per call.
 * Lifetime: the pointers stay valid, and what they hold is the current
 * state, across those calls until the volume is destroyed, except that
 * ms_volume_add_particles or ms_volume_fill_box moves them when the count
 * grows past the storage (then the old pointers dangle: call again). After
 * a removal the first *n (new count) entries are the survivors. NULL views
 * while the volume has never held a particle. */
MS_API ms_status ms_volume_particles(ms_volume *v, int *n, const float *pos[3],
                                     const float *vel[3]);

/* What this build of the library is: its compiler, the instruction-set
 * paths of the volume's passes built in and the ones this CPU runs (names
 * from c, sse2, avx2, avx512, neon, space-separated, narrowest first;
 * every path gives the same bytes), and the one a new volume takes: the
 * widest, or the one the environment variable MODESPLIT_ISA names. A
 * MODESPLIT_ISA that names no path or one this CPU lacks makes this call
 * (and ms_volume_create) fail with a sentence naming the paths it has;
 * path_chosen is then NULL. The strings are the library's (static). */
typedef struct ms_build_info {
    const char *compiler;
    const char *paths_built;
    const char *paths_cpu;
    const char *path_chosen;
} ms_build_info;
MS_API ms_status ms_get_build_info(ms_build_info *out);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_VOLUME_H */
