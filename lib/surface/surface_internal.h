/* Internal layout of ms_surface (lib/surface/ only).
 *
 * The fields are stored padded with one ghost cell on every side, rows of
 * `stride` floats (nx + 2 rounded up to a cache line), so the leapfrog row
 * kernel runs without branches; the ghost cells carry the boundary
 * condition:
 *   reflect  - ghost speed 0: no flux through the wall (Neumann);
 *   periodic - ghosts are copies of the opposite edge;
 *   absorb   - ghost speed = edge speed, ghost height advanced by Mur's
 *              first-order absorbing condition, and a thin sponge of extra
 *              damping just inside the edge takes what Mur reflects at
 *              oblique incidence.
 * Each padded row starts MS_SURFACE_ORIGIN floats into its stride, so the
 * interior of every row begins on a 64-byte boundary (aligned loads and
 * stores for the centre and vertical neighbours of the stencil).
 * ms_surface_row(s, y) is the index of padded row y's west ghost (y = 0 is
 * the south ghost row, y = ny + 1 the north one); interior cell (x, y),
 * 0-based, is at ms_surface_row(s, y + 1) + x + 1.
 */
#ifndef MS_SURFACE_INTERNAL_H
#define MS_SURFACE_INTERNAL_H

#include <stdatomic.h>

#include "core/core_internal.h"
#include "modesplit/surface.h"

typedef struct disturber {
    int id;              /* > 0; 0 = free slot */
    ms_disturber_desc d; /* position and velocity now */
    float *path;         /* npath (x, y) pairs, or NULL */
    int npath, loop;
    int path_cap;     /* pairs path has room for: a new path of up to
                             that many points reuses it */
    float path_speed; /* m/s along the path */
    double path_s;    /* m travelled along the path */
} disturber;

struct ms_surface {
    ms_surface_desc desc;
    int nx, ny;
    int stride;   /* floats per padded row */
    size_t plane; /* floats per padded field: stride * (ny + 2) */

    float *h;             /* f^n, the height field */
    float *v;             /* f^n - f^{n-1}: the last sub-step's displacement
                             (velocity * v_dt). Stored on its own, not as
                             f^{n-1}, so its round-off is relative to the
                             velocity rather than the height: volume and
                             energy drift far less in float. */
    float *speed;         /* m/s per cell as stepped: the map (or desc.wave_speed)
                             with solid cells at 0; ghosts carry the boundary */
    float *speed_map;     /* the user's speed map, padded, or NULL (uniform) */
    float *a;             /* speed * dt / dx for the cached sub-step dt */
    float *delta;         /* damping factor per sub-step, cached dt */
    float *damp_map;      /* per-cell damping per second, or NULL (uniform) */
    unsigned char *solid; /* padded obstacle mask, or NULL */
    float *view;          /* nx * ny contiguous copy for ms_surface_height */
    int view_dirty;

    float coef_dt; /* s, the dt `a` and `delta` hold; 0 = stale */
    int uniform;   /* 1: every interior cell's a is a0 and delta d0
                             (wave.c's uniform rows); 0: not; -1: unknown */
    float a0, d0;
    float max_speed; /* m/s, fastest cell */
    float v_dt;      /* s, the sub-step v belongs to; 0 = none yet */
    double time;     /* s */
    long substeps, drops;

    ms_rng rng;
    ms_rain rain; /* rate 0 = no rain */

    disturber *dist;
    int ndist, cap_dist, next_id;
    float *level_xy;            /* disturber positions at each fused sub-step
                             (wave.c), kept so a step allocates nothing */
    int level_cap;              /* disturbers level_xy has room for */
    _Atomic int cancel;         /* ms_surface_cancel: stop before the next block */
    struct ms_dispersion *disp; /* the dispersive model's state, or NULL (eq. 2) */
    /* the current (current.c), padded, or all NULL: none */
    float *cur_u, *cur_v; /* m/s; one block with cur_gamma */
    float *cur_gamma;     /* 1/s, turbulence damping rate */
    float *cur_tmp;       /* two planes: the advection's copies of h, v */
    float cur_max;        /* m/s, fastest cell of the current */
    float cur_gamma_max;  /* 1/s */
};

#define MS_SURFACE_ORIGIN 15
#define MS_SURFACE_MAX_LEVELS 8 /* sub-steps wave.c fuses into one sweep */

/* Room for cap disturbers (disturber.c): the array and wave.c's level_xy
 * grow together, outside the steps. */
ms_status ms_surface_reserve_disturbers(ms_surface *s, int cap);

static inline size_t ms_surface_row(const ms_surface *s, int y)
{
    return (size_t)y * (size_t)s->stride + MS_SURFACE_ORIGIN;
}

static inline size_t ms_surface_at(const ms_surface *s, int x, int y)
{
    return ms_surface_row(s, y + 1) + (size_t)(x + 1);
}

/* maps.c */
void ms_surface_refresh_coefficients(ms_surface *s, float dt);
/* s->uniform, a0, d0 from the coefficients a and delta */
void ms_surface_find_uniform(ms_surface *s);
/* wave.c */
float ms_surface_stable_dt(const ms_surface *s);
/* `calls` calls of ms_surface_step(s, dt), the same bytes (and the same
 * clock): without rain and at one sub-step a call, in fused sweeps */
ms_status ms_surface_step_calls(ms_surface *s, float dt, int calls);
/* drops.c */
void ms_surface_rain(ms_surface *s, float dt);
/* The checks of ms_surface_set_rain (rate > 0: its ranges and the cap on
 * drops a second) and ms_surface_add_disturber, for values a snapshot
 * brings back (snapshot.c). */
ms_status ms_surface_check_rain(const ms_surface *s, const ms_rain *rain);
/* Cells one drop of this radius visits (its square of side 2 radius, at
 * least MIN_RADIUS_CELLS cells, clipped to the grid): a drop's work. */
double ms_surface_drop_cells(const ms_surface *s, float radius);
/* The scripted drops of a scene visit at most this many cells in all
 * (2^28: about 3 s of one core at the ~11 ns a cell a splat was measured
 * to take at 512^2), so no set of in-range drops makes a frame endless
 * (4096 drops of a whole 512^2 grid each took about a minute for two
 * frames). The rain's cells a second share it (ms_surface_check_rain). */
#define MS_SURFACE_MAX_DROP_CELLS 268435456.0
ms_status ms_surface_check_disturber(const ms_surface *s, const ms_disturber_desc *d);
/* disturber.c */
void ms_surface_disturbers_advance(ms_surface *s, float dt);
void ms_surface_disturbers_positions(const ms_surface *s, float *xy);
void ms_surface_disturbers_force_row(const ms_surface *s, int y, float *v_row, const float *xy);
void ms_surface_disturbers_head_field(const ms_surface *s, const float *xy, float *field);
/* dispersive.c: the dispersive model (desc.model), NULL disp for eq. 2 */
ms_status ms_surface_dispersive_create(ms_surface *s);
void ms_surface_dispersive_destroy(ms_surface *s);
size_t ms_surface_dispersive_bytes(const ms_surface *s);
/* depth bands from the stepped speeds: when the speeds change */
ms_status ms_surface_dispersive_bands(ms_surface *s);
/* how many depth bands the operator sums (0 for eq. 2) */
int ms_surface_dispersive_band_count(const ms_surface *s);
/* the operator's symbols are stale (the coefficients were recomputed) */
void ms_surface_dispersive_invalidate(ms_surface *s);
float ms_surface_dispersive_stable_dt(const ms_surface *s);
ms_status ms_surface_dispersive_advance(ms_surface *s, float dt, int n);
double ms_surface_dispersive_energy(const ms_surface *s);
/* energy.c: the energy of the cells in [x0, x1) x [y0, y1) */
double ms_surface_energy_region(const ms_surface *s, int x0, int x1, int y0, int y1);
/* current.c: carry the waves along the current for dt and damp them
 * where it shears (no current: nothing) */
ms_status ms_surface_current_advance(ms_surface *s, float dt);
size_t ms_surface_current_bytes(const ms_surface *s);
/* surface.c */
void ms_surface_zero_solid(ms_surface *s, float *field);

#endif /* MS_SURFACE_INTERNAL_H */
