/* ms_surface: the high-frequency half of mode splitting (paper section 3.2).
 *
 * A height field f(x, y, t) on an nx x ny grid of square cells (dx metres),
 * row-major with x fastest (index y*nx + x), cell centres at ((x+0.5)dx,
 * (y+0.5)dx). It obeys the 2D wave equation (paper eq. 2), written in flux
 * form so that a speed map c(x) (shallow water: c = sqrt(g * depth)) keeps
 * volume and energy:
 *
 *     d2f/dt2 = div( c^2 grad f ) - damping term + disturbers
 *
 * and is integrated by leapfrog finite differences. ms_surface_step(dt)
 * sub-steps internally so that the Courant number c dt / dx stays below
 * 1/sqrt(2) for the fastest cell; it never goes unstable.
 *
 *     ms_surface_desc d = ms_surface_desc_default();
 *     d.nx = 256; d.ny = 256; d.dx = 0.01f;       // a 2.56 m pool
 *     ms_surface *s;
 *     if (ms_surface_create(&d, &s) != MS_OK) puts(ms_last_error());
 *     ms_surface_add_drop(s, 1.28f, 1.28f, 0.05f, 0.01f);
 *     for (int i = 0; i < 60; ++i) ms_surface_step(s, 1.0f / 60);
 *     int nx, ny; const float *f = ms_surface_height(s, &nx, &ny);
 *     ms_surface_destroy(s);
 *
 * Not thread-safe: one handle, one thread at a time.
 */
#ifndef MODESPLIT_SURFACE_H
#define MODESPLIT_SURFACE_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum ms_boundary {
    MS_BOUNDARY_REFLECT = 0,  /* walls: waves bounce back (zero normal flux) */
    MS_BOUNDARY_ABSORB = 1,   /* open water: waves leave (Mur condition + thin sponge) */
    MS_BOUNDARY_PERIODIC = 2, /* the grid wraps around in x and y */
    MS_BOUNDARY_FORCE_32BIT_ = 0x7fffffff
} ms_boundary;

/* How the surface waves are computed (docs/surface.md). */
typedef enum ms_surface_model {
    MS_SURFACE_MODEL_WAVE = 0,       /* eq. 2: every wavelength at c (non-dispersive) */
    MS_SURFACE_MODEL_DISPERSIVE = 1, /* linear water waves, omega^2 = (g k + T k^3) tanh(k d),
                                        d = c^2 / g the local depth: capillary ripples run
                                        ahead, long waves behind */
    MS_SURFACE_MODEL_FORCE_32BIT_ = 0x7fffffff
} ms_surface_model;

typedef struct ms_surface_desc {
    uint32_t size;    /* sizeof, set by ms_surface_desc_default() (core.h: struct sizes) */
    int nx, ny;       /* cells; 2 .. 16384 each                         */
    float dx;         /* m, cell size; >= 1e-6                          */
    float wave_speed; /* m/s, c of eq. 2 where no speed map is set; > 0 */
    float damping;    /* in (0, 1]: fraction of the wave velocity kept
                            after one second (1 = no damping). Per second,
                            not per step, so the result does not depend on
                            how many sub-steps are taken.                  */
    ms_boundary boundary;
    /* --- grown at the end (ABI: descs only grow) --- */
    uint64_t seed;            /* seeds the rain RNG held in the handle          */
    int max_substeps;         /* refuse a step needing more sub-steps (MS_ERR_UNSTABLE); >= 1 */
    ms_surface_model model;   /* MS_SURFACE_MODEL_WAVE or _DISPERSIVE */
    float gravity;            /* m/s^2, g of the dispersive model; (0, 1000] */
    float surface_tension;    /* m^3/s^2, T = sigma / rho of the dispersive
                               model (capillarity); [0, 1] */
    int advect;               /* 1: in a sim, the waves are carried by the
                                 volume's surface velocity (ms_surface_set_current
                                 each frame); 0: not. A surface alone takes the
                                 current it is given either way. 0 or 1 */
    float turbulence_damping; /* kappa: the current damps the waves at
                                 gamma = kappa |S| (1/s), |S| its strain rate
                                 (docs/surface.md); [0, 100] */
} ms_surface_desc;

/* nx = ny = 256, dx = 0.01 m, wave_speed = 0.5 m/s, damping = 0.9,
 * reflecting walls, seed = 1, max_substeps = 100000, model wave,
 * gravity 9.81 m/s^2, surface_tension 7.28e-5 m^3/s^2 (clean water at
 * 20 C: 0.0728 N/m over 1000 kg/m^3), advect 0, turbulence_damping
 * 4 pi^2 0.17^2 = 1.14 (Smagorinsky's eddy viscosity at the flow's
 * resolution, docs/surface.md). With the dispersive model,
 * wave_speed (and the speed map) is the long-wave speed sqrt(g d) of the
 * depth d: ms_surface_speed_from_depth gives it. */
MS_API ms_surface_desc ms_surface_desc_default(void);

MS_API ms_status ms_surface_create(const ms_surface_desc *d, ms_surface **out);
/* The checks ms_surface_create makes, without creating anything: nx, ny
 * in [2, 16384], dx >= 1e-6 m, wave_speed > 0, damping in (0, 1], a
 * boundary value, max_substeps >= 1 (a scene's surface keys are checked
 * here too). */
MS_API ms_status ms_surface_desc_check(const ms_surface_desc *d);
MS_API void ms_surface_destroy(ms_surface *s);

/* Advance by dt seconds (0 <= dt <= 10), in equal sub-steps that keep the
 * Courant number below 1/sqrt(2) (the dispersive model: omega dt <= 2 for
 * the grid's fastest mode). MS_ERR_UNSTABLE if that needs more than
 * desc.max_substeps sub-steps. */
MS_API ms_status ms_surface_step(ms_surface *s, float dt);

/* A smooth radial bump (raised cosine) of the given radius (m) and peak
 * amplitude (m; negative = a dent), centred at (x, y) in metres. A radius
 * under two cells is widened to two cells with the amplitude scaled down so
 * the displaced volume stays the same: a one-cell spike would alias into
 * grid noise. The bump is a displacement with no velocity. */
MS_API ms_status ms_surface_add_drop(ms_surface *s, float x, float y, float radius,
                                     float amplitude);

/* Replace the field (nx*ny values) and reset the previous step to it, so
 * the field starts at rest. Solid cells of the obstacle mask are set to 0. */
MS_API ms_status ms_surface_set_height(ms_surface *s, const float *h);

/* Add gain*dh (nx*ny values) to the current field only: an impulse that
 * changes the surface velocity by gain*dh/dt. The coupler uses it to excite
 * waves from the time derivative of the SPH height field (paper 3.5). */
MS_API ms_status ms_surface_excite(ms_surface *s, const float *dh, float gain);

/* Per-cell wave speed in m/s (nx*ny values, each finite and >= 0; 0 = dry
 * cell that reflects). NULL = uniform desc.wave_speed. */
MS_API ms_status ms_surface_set_speed_map(ms_surface *s, const float *c);

/* Per-cell damping factor in (0, 1] per second, multiplied with
 * desc.damping. NULL = uniform desc.damping. */
MS_API ms_status ms_surface_set_damping_map(ms_surface *s, const float *d);

/* 1 = solid cell: its height stays 0 and waves reflect from it. NULL = no
 * obstacles. */
MS_API ms_status ms_surface_set_obstacle_mask(ms_surface *s, const unsigned char *mask);

/* A horizontal current under the surface, (ux, uy) in m/s per cell (nx*ny
 * values each, |U| <= 100 m/s): each step first carries the waves along it
 * (a packet on a uniform current U travels at c + U) and damps them where
 * it shears, at kappa |S| (desc.turbulence_damping). Both NULL: no current
 * (nothing is allocated, the steps are as without). Either model. */
MS_API ms_status ms_surface_set_current(ms_surface *s, const float *ux, const float *uy);

/* Shallow-water speeds c = sqrt(gravity * depth) for n depths in metres
 * (depth <= 0 gives 0, a dry cell). gravity in m/s^2, > 0. */
MS_API ms_status ms_surface_speed_from_depth(const float *depth, size_t n, float gravity,
                                             float *speed_out);

/* Rain: drops at `rate` per m^2 per s, each a drop of a radius drawn in
 * [radius/2, radius] and an amplitude drawn in [amplitude/2, amplitude],
 * positions uniform over the grid, from the seeded RNG in the handle (same
 * seed, same steps -> same bytes). NULL or rate 0 turns rain off (then no
 * random numbers are drawn). Its work a second is bounded: at most 1e5
 * drops a second over the grid, visiting at most 2^28 cells a second (a
 * drop the square of its diameter); more is MS_ERR_INVALID_ARGUMENT. */
typedef struct ms_rain {
    uint32_t size;   /* sizeof, set by ms_rain_default() (core.h: struct sizes) */
    float rate;      /* drops per m^2 per s, >= 0 */
    float radius;    /* m, > 0 */
    float amplitude; /* m, finite (negative = dents, as real drops make) */
} ms_rain;
/* rate 0 (off), radius 0.01 m, amplitude -0.002 m. */
MS_API ms_rain ms_rain_default(void);
MS_API ms_status ms_surface_set_rain(ms_surface *s, const ms_rain *rain);

/* A moving disturber: the paper's swimming object or boat (Fig. 3c, 10b).
 * It presses a smooth dent of the given depth and radius into the surface
 * as a pressure term inside the wave equation, so it displaces water
 * without adding any: a still disturber settles into a dent, a moving one
 * leaves bow waves and a wake. */
typedef struct ms_disturber_desc {
    uint32_t size; /* sizeof, set by ms_disturber_desc_default() (core.h: struct sizes) */
    float x, y;    /* m, start position */
    float vx, vy;  /* m/s, velocity (used when no path is set) */
    float radius;  /* m, > 0 */
    float depth;   /* m, finite: how deep it presses */
} ms_disturber_desc;
/* At (0, 0), still, radius 0.05 m, depth 0.01 m. */
MS_API ms_disturber_desc ms_disturber_desc_default(void);
MS_API ms_status ms_surface_add_disturber(ms_surface *s, const ms_disturber_desc *d, int *id);
/* Place it and give it a velocity (m, m/s); cancels a path. */
MS_API ms_status ms_surface_move_disturber(ms_surface *s, int id, float x, float y, float vx,
                                           float vy);
/* Let it travel along a polyline of npoints (x, y) pairs (m) at speed m/s;
 * loop != 0 returns to the first point and goes round again, otherwise it
 * stops at the last point. The path is copied. */
MS_API ms_status ms_surface_set_disturber_path(ms_surface *s, int id, int npoints, const float *xy,
                                               float speed, int loop);
/* Where it is now (m), for objects that ride on it. */
MS_API ms_status ms_surface_disturber_position(const ms_surface *s, int id, float *x, float *y);
MS_API ms_status ms_surface_remove_disturber(ms_surface *s, int id);

/* The field (view, valid until the next mutating call on s). */
MS_API const float *ms_surface_height(const ms_surface *s, int *nx, int *ny);

/* Wave energy, in double: (1/2) sum over cells of (df/dt)^2 dx^2 plus
 * (1/2) sum over faces of c^2 (grad f)^2 dx^2, in m^4/s^2 (multiply by the
 * density over the depth for joules). It is the quantity the leapfrog
 * scheme conserves exactly without damping, so it is constant to round-off
 * on a closed, undamped basin. The dispersive model: (1/2) sum of
 * (df/dt)^2 dx^2 plus (1/2) sum of f Omega^2 f dx^2, Omega^2 its operator
 * (the same staggered form, kept the same way). */
MS_API double ms_surface_energy(const ms_surface *s);

typedef struct ms_surface_info {
    uint32_t size;   /* sizeof, set by ms_surface_info_init() (core.h: struct sizes) */
    double time;     /* s simulated                                  */
    long substeps;   /* leapfrog steps taken                         */
    float max_dt;    /* s, largest stable sub-step for the current maps */
    float max_speed; /* m/s, fastest cell                            */
    size_t bytes;    /* memory held                                  */
    long drops;      /* drops added (by hand and by rain)            */
} ms_surface_info;
static inline ms_surface_info ms_surface_info_init(void)
{
    ms_surface_info x = MS_ZERO_INIT;
    x.size = (uint32_t)sizeof x;
    return x;
}
MS_API void ms_surface_get_info(const ms_surface *s, ms_surface_info *out);
/* The desc the handle was created from. */
MS_API ms_surface_desc ms_surface_get_desc(const ms_surface *s);
/* Ask a step in progress (on another thread) to stop: it returns
 * MS_ERR_CANCELED before its next block of sub-steps, the field valid at
 * the time reached. Safe from any thread; a request made between steps
 * stops the next step at once. */
MS_API void ms_surface_cancel(ms_surface *s);

#ifdef __cplusplus
}
#endif

#endif /* MODESPLIT_SURFACE_H */
