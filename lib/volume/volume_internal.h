/* lib/volume: the SPH liquid volume (paper section 3.3; Mueller, Charypar &
 * Gross 2003). Internal, never installed.
 *
 * Files, one job each:
 *   kernels.h    the smoothing kernels of eqs. 9, 11, 12 (poly6, spiky, viscosity),
 *                scalar and over lanes: the one place that spells them
 *   lane.h       the lane type (16 floats) and its implementations per
 *                instruction set, lane_<isa>.h: the same bits on each
 *   passes.c     the density, force and DFSPH passes written once over it,
 *                compiled per instruction set (passes_<isa>.c); passes.h
 *                their table, isa.c the choice of path (MODESPLIT_ISA)
 *   law.h        the equations of state, scalar and over lanes
 *   desc.c       ms_volume_desc defaults and validation
 *   volume.c     the handle: create, particles in and out, info
 *   pool.c       the worker threads of a step (static split, same bytes for any count)
 *   grid.c       neighbour grid of cell size h, counting sort into cell order
 *   neighbours.c the neighbour lists of a density pass (instruction-set filters)
 *   density.c    density (eq. 9) and pressure (ideal gas, Tait)
 *   forces.c     pressure force (eq. 13), viscosity force (eq. 14), gravity
 *   collide.c    the collider force field (eq. 15), the domain box, no tunnelling
 *   step.c       ms_volume_step: time-step bounds, sub-steps, symplectic Euler
 *   dfsph.c      MS_PRESSURE_DFSPH: the divergence-free and constant-density
 *                solves of Bender & Koschier 2015/2017 (their pair loops in
 *                passes.c, the shared pieces in dfsph_pass.h)
 *   interact.c   drag, push, remove, viscosity change, coupling from the waves
 *   extract.c    height field: eq. 16-17 iso-surface, eq. 18 adaptive smoothing
 *
 * Storage is structure-of-arrays float, kept in cell order (the order of
 * the last counting sort), so the neighbour loops stream through memory.
 * Every per-particle sum is a gather over the 27 neighbour cells in a fixed
 * order (9 rows of 3 cells, each contiguous in memory), so the bytes do not
 * depend on how particles are split among threads.
 */
#ifndef MS_VOLUME_INTERNAL_H
#define MS_VOLUME_INTERNAL_H

#include <stddef.h>

#include "core/core_internal.h"
#include "modesplit/shape.h"
#include "modesplit/volume.h"
#include "volume/extract.h"
#include "volume/kernels.h"

#define MS_VOLUME_MAX_COLLIDERS 64
#define MS_VOLUME_MAX_ACTIONS 16
#define MS_VOLUME_MAX_THREADS 64
#define MS_VOLUME_MAX_CELLS (1L << 24)
/* The pair loops run over neighbours in blocks of MS_VOLUME_LANES with one
 * accumulator per lane, summed in lane order at the end: a fixed order the
 * compiler can put in vector registers, the same bytes on any ISA. The
 * particle arrays have MS_VOLUME_LANES elements of padding at the end, so
 * a block may read past the last particle (those lanes are masked). */
#define MS_VOLUME_LANES 16

/* The hand-written AVX-512 code still outside the lane passes (passes.c)
 * needs GCC's target attribute; TSan builds stay on SSE2. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define MS_VOLUME_HAVE_AVX512 1
#else
#define MS_VOLUME_HAVE_AVX512 0
#endif
/* The instruction-set paths (v->isa), in order of width on each target:
 * the lane passes' tables (passes.h) and the neighbour filter. Every
 * path gives the same bytes. */
enum {
    MS_VOLUME_ISA_C = 0,
    MS_VOLUME_ISA_SSE2 = 1,
    MS_VOLUME_ISA_AVX2 = 2,
    MS_VOLUME_ISA_AVX512 = 3,
    MS_VOLUME_ISA_NEON = 4,
    MS_VOLUME_ISA_COUNT = 5
};

/* The sum of MS_VOLUME_LANES lane accumulators in one fixed tree order,
 * (l, l+8), then (l, l+4), (l, l+2), (0, 1): what the AVX-512 code does
 * with register halves, so both give the same bits. */
static inline float ms_lanes_sum(const float a[16])
{
    float t8[8], t4[4];
    for (int l = 0; l < 8; ++l)
        t8[l] = a[l] + a[l + 8];
    for (int l = 0; l < 4; ++l)
        t4[l] = t8[l] + t8[l + 4];
    return (t4[0] + t4[2]) + (t4[1] + t4[3]);
}

/* ---- worker threads (pool.c) ---- */
typedef struct ms_vpool ms_vpool;
/* Work on items [begin, end) of a parallel loop; `part` is the chunk index. */
typedef void ms_vpool_fn(void *ctx, int part, int begin, int end);
ms_status ms_vpool_create(int threads, ms_vpool **out);
/* Start a volume pool's own threads unless they run, the engine's tasks
 * are set, or it has none (a step calls it first; pool.c says why not
 * create). */
ms_status ms_vpool_start(ms_vpool *p);
/* A pool of `parts` chunks and no threads of its own (pool.c): the caller
 * and a lent helper (ms_vpool_help, extract.h) claim them. */
ms_status ms_vpool_create_shared(int parts, ms_vpool **out);
void ms_vpool_destroy(ms_vpool *p);
/* Run the chunks as the engine's tasks (both set), or on the pool's own
 * threads again (both NULL). Between loops only. */
ms_status ms_vpool_set_tasks(ms_vpool *p, ms_enqueue_task_fn *enqueue, ms_finish_task_fn *finish,
                             void *user);
/* Split [0, n) into `parts` contiguous chunks (parts <= threads of the
 * pool, or 1 with a NULL pool) and run fn on each; returns when all are
 * done. The chunk bounds depend only on n and parts. */
void ms_vpool_run(ms_vpool *p, ms_vpool_fn *fn, void *ctx, int n);
int ms_vpool_threads(const ms_vpool *p);
/* The chunks of each loop: the threads, or a shared pool's parts. */
int ms_vpool_parts(const ms_vpool *p);

/* The neighbour lists of one chunk of particles (one per thread). Each
 * particle's real neighbours are one run of entries, padded up to a
 * multiple of MS_VOLUME_LANES with (the particle itself, r^2 = h^2) so the
 * pair loops need no masks (a padding pair is at r = h: weight 0). Its
 * wall-image neighbours are a second run in `ghost`, packed as
 * j | image << MS_VOLUME_IMAGE_SHIFT (bit k < 3 of the image: reflected
 * across the nearer domain wall of axis k; MS_VOLUME_IMAGE_SHAPE: across
 * the tangent plane of the particle's nearest shape collider). Rebuilt by
 * every density pass. A list has a cache line of its own: each thread
 * bumps its part's `len` once a particle, and with the parts' lists
 * sharing a line that line went back and forth between the two cores
 * (bench_volume's 31k sub-step took 5.4 ms on 2 threads against 4.8 on
 * 1; 3.3 with the line apart). */
#define MS_VOLUME_IMAGE_SHIFT 24
#define MS_VOLUME_IMAGE_SHAPE 8u
typedef struct ms_nlist {
    _Alignas(64) int *idx;
    float *r2;  /* m^2 */
    size_t cap; /* entries */
    size_t len;
} ms_nlist;

typedef enum { MS_ACTION_DRAG, MS_ACTION_PUSH } ms_action_kind;
typedef struct ms_action {
    ms_action_kind kind;
    float centre[3]; /* m */
    float radius;    /* m */
    float vec[3];    /* drag: target velocity m/s; push: acceleration m/s^2 */
    float strength;  /* drag: 1/s */
} ms_action;

struct ms_volume {
    ms_volume_desc desc;
    ms_sph_kernels K;
    float mass;         /* kg per particle: a full lattice has rho = rho0 */
    float press_scale;  /* 2/M: eq. 13 renormalised to -grad p / rho (volume.c) */
    float c0;           /* m/s, sound speed at rest density */
    float tait_b;       /* Pa, B of Tait's law */
    float col_range;    /* m, reach of the collider field (eq. 15) */
    float col_accel;    /* m/s^2, its strength at contact */
    float col_damp;     /* 1/s, damping of the approach inside the field */
    float surface_nbrs; /* fewer neighbours (self included) = surface particle */
    float iso_level;    /* eq. 16 threshold of phi */
    float eps2;         /* m^2, pairs closer than this are "coincident" */

    /* particles, cell order: state */
    int n, cap;
    float *x, *y, *z, *vx, *vy, *vz;
    int *id; /* 0..n-1, insertion order (get_particles order) */
    /* scratch of the same size, swapped with the state when sorting; it
     * also holds the positions before the drift (for the no-tunnel test) */
    float *x2, *y2, *z2, *vx2, *vy2, *vz2;
    int *id2;
    /* derived per particle, valid for the current order after a pass */
    float *rho, *prs, *inv_rho; /* kg/m^3, Pa, m^3/kg */
    float *ax, *ay, *az;        /* m/s^2 */
    float *visc_rate;           /* 1/s, D_i of the viscous bound */
    /* boundary terms near each particle (collide.c) */
    float *b_ax, *b_ay, *b_az; /* m/s^2, the eq. 15 field of the walls and colliders */
    /* the nearest shape collider within h: its distance (m, > h: none), the
     * outward normal and velocity there, and the weight of its eq. 15
     * field; the particle's images across its tangent plane stand for the
     * liquid beyond it, and the damping uses its normal */
    float *c_d, *c_w, *c_nx, *c_ny, *c_nz, *c_vx, *c_vy, *c_vz;
    int *nbr;                 /* neighbours within h, self and wall images included */
    int *nl_begin, *nl_count; /* its run in its chunk's list: first entry, neighbours */
    int *gl_begin, *gl_count; /* its run of wall-image neighbours */
    int *cell;                /* cell of each particle (sorted order) */
    unsigned char *mark;      /* extraction: 1 surface, 2 neighbour of one */
    int counts_valid;         /* nbr[] matches the current positions */
    /* The pass of the last ms_volume_count_neighbours (grid,
     * boundary terms, lists, density), offered only when it saw every
     * collider at its pose (as the next step's tau = 0 does: none moving
     * since the step, or the caller put it where the step left it), which
     * the next step's first sub-step takes as its own while counts_valid holds, the
     * colliders are the same shapes at the same poses (pass_col,
     * pass_pose: pos, vel, orientation, omega) and none jumped. Cleared
     * by every step and by adding or removing a collider; the positions'
     * mutators clear counts_valid. */
    int pass_ready, pass_ncol;
    const ms_shape *pass_col[MS_VOLUME_MAX_COLLIDERS];
    float pass_pose[MS_VOLUME_MAX_COLLIDERS][13];

    /* neighbour grid, 1 cell of padding on each side */
    int gx, gy, gz;
    long ncells;
    float inv_h;
    int *cell_start; /* ncells + 1 */
    int *cell_fill;  /* ncells, scratch of the sort */
    int *grid_hist;  /* parts x ncells, the parallel sort's counts (grid.c) */
    size_t grid_hist_cap;

    ms_shape *colliders[MS_VOLUME_MAX_COLLIDERS];
    int ncolliders;
    /* where each collider's velocity took it at the end of the last step,
     * and, during a step, the velocity (m/s) it is swept with and the jump
     * (m) the caller moved it by on top of that (collide.c) */
    float col_expect[MS_VOLUME_MAX_COLLIDERS][3];
    int col_expect_valid[MS_VOLUME_MAX_COLLIDERS];
    float col_vel[MS_VOLUME_MAX_COLLIDERS][3];
    float col_jump[MS_VOLUME_MAX_COLLIDERS][3];
    /* where the particles left each collider at the end of the last step
     * (valid with col_expect_valid): its origin (m, 0..2) and rotation
     * (3..11, row-major), the pose + vel tau and R(tau) of the time tau the
     * step reached; the passes between steps view it there (collide.c) */
    float col_end[MS_VOLUME_MAX_COLLIDERS][12];
    int in_step;
    ms_action actions[MS_VOLUME_MAX_ACTIONS];
    int nactions;
    _Atomic int cancel; /* ms_volume_cancel: stop at the next sub-step */

    /* coupling from the waves: the previous wave field */
    float *wave_prev;
    size_t wave_cap;
    ms_grid wave_grid;
    double wave_time;
    int wave_valid;

    /* ms_volume_particles: the particles in insertion order, one block
     * x | y | z | vx | vy | vz of cap floats each (a fixed stride, so an
     * FFI user views it as (n, 3)); kept only once a caller asked for it
     * (pub_on), refreshed by ms_volume_publish at the end of every public
     * call that changes the particles, reallocated only by ms_volume_reserve */
    float *pub;
    int pub_on;

    /* extraction scratch */
    float *ex_buf;
    size_t ex_cap;
    int *ex_start, *ex_list;
    size_t ex_start_cap, ex_list_cap;
    ms_extract_work ex_verify; /* its repairs' scratch (start, list, buf unused) */

    int isa; /* MS_VOLUME_ISA_*: the lane passes' table, the neighbour filter */
    ms_vpool *pool;
    ms_nlist lists[MS_VOLUME_MAX_THREADS], ghosts[MS_VOLUME_MAX_THREADS];
    int list_failed[MS_VOLUME_MAX_THREADS];
    int lists_reserved; /* the first density pass gave the lists their headroom */

    /* statistics */
    double time;
    long steps, substeps;
    float last_dt, max_dt;
    const char *dt_limit;
    float max_speed, max_density_error;
    int surface_count;
    double pairs;
    int coincident; /* pairs closer than eps in the last density pass */

    /* per particle, 8 floats packed for the 32-byte record loads of the
     * AVX-512 force pass (forces.c): x, y, z, prs, vx, vy, vz, inv_rho of
     * the last density pass */
    float *pk;
    /* density.c, per thread: the candidates (x, y, z; index) of the 27
     * cells around the cell in hand, copied into one run */
    float *cand[MS_VOLUME_MAX_THREADS];
    int *cand_idx[MS_VOLUME_MAX_THREADS];
    size_t cand_cap[MS_VOLUME_MAX_THREADS];

    /* DFSPH (dfsph.c). Per particle, cell order, valid during a sub-step:
     * 1 / (|sum_j m grad W_ij|^2 + sum_j |m grad W_ij|^2) (the Jacobi
     * diagonal: alpha_i / rho_i of Bender & Koschier 2017), the current
     * iterate s_i (m^5/kg, kappa_i dt^2 / rho_i or its divergence twin) and
     * its running total; the pair terms and the warm start below. */
    float *df_inv_diag, *df_s, *df_sum;
    /* per part, the pair terms g_ij (x_i - x_j) of its real-neighbour list
     * (same entries as lists[part]), computed once per sub-step by the
     * factors pass and read by every iteration: gx | gy | gz blocks of
     * df_grad_cap floats each */
    float *df_grad[MS_VOLUME_MAX_THREADS];
    /* the warm start: each particle's total s of the last density solve,
     * by id (the sort moves particles), valid while n == df_warm_n; the
     * sub-step it was solved for (s) */
    float *df_warm;
    int df_warm_n;
    float df_warm_dt;
    size_t df_grad_cap[MS_VOLUME_MAX_THREADS];
    int df_density_iters, df_divergence_iters;
    long df_density_total, df_divergence_total;
    float df_density_err, df_divergence_err;
    /* per part, the image-list twin of df_grad: g and x_i - x_j' of each
     * entry of ghosts[part], 4 floats an entry, df_img_cap entries */
    float *df_img[MS_VOLUME_MAX_THREADS];
    size_t df_img_cap[MS_VOLUME_MAX_THREADS];
    /* The pressure read-out (dfsph.c). Per particle, cell order: the
     * divergence solve's total s of this sub-step (m^5 s / kg). By id: the
     * pressure averaged over the step's sub-steps so far (Pa), over
     * df_pmean_t seconds, valid while n == df_pmean_n, v->steps ==
     * df_pmean_step and v->time == df_pmean_until (the end of the last
     * sub-step it holds). */
    float *df_div_sum, *df_pmean;
    float df_pmean_t;
    /* the mean gradient moment M of the particles inside the liquid,
     * measured by this sub-step's factors pass (dfsph.c) */
    float df_moment;
    int df_pmean_n;
    long df_pmean_step;
    double df_pmean_until;
    /* The warm start folded into the factors pass (dfsph.c).
     * Per particle, cell order, valid during a sub-step while df_warm_on:
     * sum_j (w_i + w_j) g_ij (x_i - x_j) over the real neighbours and the
     * images, w the warm start's s at the last sub-step's dt (m^5/kg times
     * m^-1: the density solve adds dt / dt_last^2 m G times it to v) */
    float *df_wx, *df_wy, *df_wz;
    int df_warm_on;
};

/* A surface particle: fewer neighbours (self and wall images included)
 * than 3/4 of a particle inside the liquid has. */
static inline int ms_volume_is_surface(const ms_volume *v, int i)
{
    return (float)v->nbr[i] < v->surface_nbrs;
}

/* The domain walls within h of (x, y, z): bit k set when the nearer wall
 * of axis k is closer than h; wall[k] is that wall's coordinate (m). The
 * wall images (ghost particles) of a particle are the reflections of the
 * real particles across each non-empty subset of these walls. */
static inline unsigned ms_volume_walls_near(const ms_volume *v, float x, float y, float z,
                                            float wall[3])
{
    const float p[3] = {x, y, z}, h = v->K.h;
    unsigned mask = 0;
    for (int k = 0; k < 3; ++k) {
        float lo = v->desc.domain_min[k], hi = v->desc.domain_max[k];
        wall[k] = p[k] - lo <= hi - p[k] ? lo : hi;
        if (fabsf(p[k] - wall[k]) < h)
            mask |= 1u << k;
    }
    return mask;
}

/* volume.c */
ms_status ms_volume_reserve(ms_volume *v, int n);
/* Refresh ms_volume_particles' block (nothing if no caller asked for it);
 * the last thing every public call that changes the particles does. */
void ms_volume_publish(ms_volume *v);

/* grid.c: sort the particles into cell order; fills cell[] and cell_start. */
void ms_volume_grid_build(ms_volume *v);
/* A counting sort's middle (grid.c): fill[c] holds bin c's count; start
 * gets the bins' first slots (start[cells] the total) and fill a copy of
 * them, the next free slot of each bin. Also the extraction's bins. */
void ms_counts_to_starts(int *start, int *fill, size_t cells);
/* The grid's shape, copied out of the volume for the loops that store
 * ints (an int store may alias v->gx, and the compiler then reloads). */
typedef struct ms_grid_shape {
    float lo[3], inv_h;
    int gx, gy, gz;
} ms_grid_shape;
static inline ms_grid_shape ms_volume_grid_shape(const ms_volume *v)
{
    ms_grid_shape g = {{v->desc.domain_min[0], v->desc.domain_min[1], v->desc.domain_min[2]},
                       v->inv_h,
                       v->gx,
                       v->gy,
                       v->gz};
    return g;
}
/* Cell of a position (padded indices; a position outside the domain, a
 * wall image, gets the nearest cell inside it). */
static inline long ms_grid_cell(const ms_grid_shape *g, float x, float y, float z)
{
    /* "a > 0 ? a : 0" also turns a NaN into 0: never cast a NaN */
    float fx = (x - g->lo[0]) * g->inv_h, fy = (y - g->lo[1]) * g->inv_h,
          fz = (z - g->lo[2]) * g->inv_h;
    fx = fx > 0.0f ? fx : 0.0f;
    fy = fy > 0.0f ? fy : 0.0f;
    fz = fz > 0.0f ? fz : 0.0f;
    fx = fx < (float)(g->gx - 3) ? fx : (float)(g->gx - 3);
    fy = fy < (float)(g->gy - 3) ? fy : (float)(g->gy - 3);
    fz = fz < (float)(g->gz - 3) ? fz : (float)(g->gz - 3);
    long cx = (long)fx + 1, cy = (long)fy + 1, cz = (long)fz + 1;
    return (cz * g->gy + cy) * g->gx + cx;
}
static inline long ms_volume_cell_of(const ms_volume *v, float x, float y, float z)
{
    const ms_grid_shape g = ms_volume_grid_shape(v);
    return ms_grid_cell(&g, x, y, z);
}

/* neighbours.c: the nine row ranges (x-1 .. x+1) of the 27 cells around
 * a cell, and how many candidates they hold; particle i's runs of real
 * neighbours and images appended to its part's lists (nl_*, gl_*), with
 * the rows of its cell in own (kept while the cell stays the same) and, on
 * the AVX-512 path, *ncand candidates copied; -1 if a list could not grow.
 * The path of the filter is v->isa (ms_volume_choose_isa). */
typedef struct ms_rows {
    long cell;
    int lo[9], hi[9];
    size_t cand;
} ms_rows;
int ms_volume_neighbours_of(ms_volume *v, int part, int i, ms_rows *own, long *ncand);
/* 1, or 0 if the lists could not get their headroom (neighbours.c) */
int ms_volume_lists_headroom(ms_volume *v, int part);
/* Room for a wave field of `cells` for ms_volume_adapt_to_waves (interact.c),
 * so the sim's steps allocate nothing. */
ms_status ms_volume_reserve_waves(ms_volume *v, size_t cells);

/* density.c: the neighbour lists, and rho, prs, inv_rho, nbr for every
 * particle; surface count and density error statistics. MS_ERR_OUT_OF_MEMORY
 * if a list could not grow. */
ms_status ms_volume_density(ms_volume *v);
/* Pressure of a density (the equation of state of desc.pressure). */
float ms_volume_pressure(const ms_volume *v, float rho);
/* The widest path (MS_VOLUME_ISA_*) this build and CPU run (isa.c). */
int ms_volume_pick_isa(void);
/* Whether this build has path isa and this CPU runs it. */
int ms_volume_isa_runs(int isa);
/* "c", "sse2", "avx2", "avx512", "neon". */
const char *ms_volume_isa_name(int isa);
/* The path a new volume takes: MODESPLIT_ISA's, else the widest; fails
 * with a sentence naming this CPU's paths when the variable names none
 * of them. */
ms_status ms_volume_choose_isa(int *out);
/* The boundary terms and a density pass at the current positions
 * (extraction and coupling between steps); marks the pass ready for the
 * next step (pass_ready). */
ms_status ms_volume_count_neighbours(ms_volume *v);
/* After ms_volume_colliders_begin: 1 if the step's first sub-step may take
 * the pass of ms_volume_count_neighbours as its own (the same bytes as
 * building it again), having refreshed the packed velocities (the
 * coupling to the waves changes them between steps). */
int ms_volume_take_counted_pass(ms_volume *v);

/* dfsph.c: after a density pass (prs = 0 under DFSPH): the Jacobi
 * diagonals; the divergence-free solve of the velocities (dt_scale, s, the
 * step its error is measured over); the constant-density solve of the
 * velocities v* after the kick, for a sub-step of dt, which also leaves the
 * pressure (Pa) in prs. MS_ERR_UNSTABLE if a value is not finite. */
ms_status ms_volume_dfsph_divergence(ms_volume *v, float dt_scale);
void ms_volume_dfsph_density(ms_volume *v, float dt);

/* forces.c: ax, ay, az (pressure, viscosity, gravity) and visc_rate. */
void ms_volume_forces(ms_volume *v);
/* forces.c: the direction given to a coincident pair (r < eps) of ids
 * a != b, a unit vector with dir(a, b) = -dir(b, a); dfsph.c uses it too. */
void ms_volume_pair_direction(int a, int b, float u[3]);

/* collide.c */
/* The eq. 15 field b_a of the domain box and the colliders, and each
 * particle's nearest shape collider (c_*), at the current positions; tau
 * is the time (s) since the start of the ms_volume_step (moving
 * colliders). */
void ms_volume_boundary(ms_volume *v, double tau);
/* The same between steps, with each collider where the last step left it
 * (col_end) rather than at its pose, which is the step's start or where
 * the caller has put it since. Returns 1 if a collider was viewed
 * elsewhere than at its pose (the pass then differs from the next step's
 * first at tau = 0). */
int ms_volume_boundary_after_step(ms_volume *v);
/* After the kick: implicit damping of the approach inside the field. */
void ms_volume_collider_damp(ms_volume *v, double tau, float dt);
/* Largest collider speed (m/s) in the current step, for the CFL bound. */
float ms_volume_collider_speed(const ms_volume *v);
/* At the start and end of a step of dt seconds (dt > 0). */
void ms_volume_colliders_begin(ms_volume *v, float dt);
/* reached: the time into the step the particles got to (dt, or less
 * after a cancel). */
void ms_volume_colliders_end(ms_volume *v, float dt, double reached);
/* After the drift from (x2, y2, z2) at tau to the positions at tau + dt:
 * no particle inside a collider (swept test in the collider's frame, so
 * none tunnels) or outside the domain. */
void ms_volume_collider_resolve(ms_volume *v, double tau, float dt);

/* extract.c: the eq. 16 iso-level that puts a still, flat liquid's surface
 * half a spacing above its top layer. */
float ms_volume_iso_level(const ms_volume *v);

/* interact.c: accelerations of the pending pushes, relaxation of drags. */
void ms_volume_actions_accel(ms_volume *v);
void ms_volume_actions_drag(ms_volume *v, float dt);

#endif
