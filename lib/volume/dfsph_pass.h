/* What dfsph.c and its lane pass (passes.c, compiled once per
 * instruction set) share: the kinds of pass, their context, and the
 * per-particle pieces both call (images, the gradient factor, the
 * velocity cap, the packed copy's velocities, the error's quantisation).
 * Internal to lib/volume. */
#ifndef MS_VOLUME_DFSPH_PASS_H
#define MS_VOLUME_DFSPH_PASS_H

#include <math.h>
#include <stdint.h>

#include "volume/volume_internal.h"

/* The pair loops are inlined into each instance's dfsph_range (passes.c):
 * no call a particle, the loops' constants kept in registers. */
#if defined(__GNUC__)
#define MS_DFSPH_INLINE __attribute__((always_inline))
#else
#define MS_DFSPH_INLINE
#endif
enum { MIN_DENSITY_ITERATIONS = 2, MIN_DIVERGENCE_ITERATIONS = 1 };
#define WARM_FACTOR 0.5f
/* The density solve's momentum (the header): the share of a particle's
 * last update s carried into its next. */
#define DENSITY_MOMENTUM 0.3f

typedef enum { F_FACTORS, F_DENSITY_ERROR, F_DIVERGENCE_ERROR, F_APPLY, F_PRESSURE } pass_kind;

typedef struct ms_dfsph_ctx {
    ms_volume *v;
    pass_kind kind;
    float dt;    /* s, the sub-step (density) or the error's scale (divergence) */
    float scale; /* F_APPLY: 1/dt (density) or 1 (divergence), 1/s or 1; warm_kick:
                       the last solve's s rescaled to this dt, (dt / dt_last)^2 */
    float warm;  /* warm_kick: dt / dt_last^2 m G, the factor of df_wx..z */
    int64_t err[MS_VOLUME_MAX_THREADS]; /* sum of e_i / rho0 (or dt e_i / rho0), 2^-32 units */
    /* F_FACTORS: the gradient moments of the particles inside the liquid
     * (2^-32 units) and their count; F_PRESSURE: the moment M, the weight
     * of this sub-step in the step's mean and whether the mean restarts */
    int64_t mom[MS_VOLUME_MAX_THREADS];
    int nmom[MS_VOLUME_MAX_THREADS];
    float moment, weight;
    int restart;
    float momentum; /* F_DENSITY_ERROR: DENSITY_MOMENTUM, 0 at a solve's first error pass */
} ms_dfsph_ctx;

static inline int ms_dfsph_padded(int n)
{
    return (n + MS_VOLUME_LANES - 1) / MS_VOLUME_LANES * MS_VOLUME_LANES;
}

/* Entry g of particle i's image list: particle j's position and velocity
 * mirrored as density.c and forces.c mirror them (velocity in the shape's
 * frame at a shape). */
static inline MS_DFSPH_INLINE void image_of(const ms_volume *v, int i, int g, const float wall[3],
                                            float pj[3], float uj[3])
{
    const unsigned f = (unsigned)g >> MS_VOLUME_IMAGE_SHIFT;
    const int j = g & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    pj[0] = v->x[j];
    pj[1] = v->y[j];
    pj[2] = v->z[j];
    uj[0] = v->vx[j];
    uj[1] = v->vy[j];
    uj[2] = v->vz[j];
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float dd = v->c_d[i];
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float c[3] = {v->x[i] - dd * nn[0], v->y[i] - dd * nn[1], v->z[i] - dd * nn[2]};
        float sp = (pj[0] - c[0]) * nn[0] + (pj[1] - c[1]) * nn[1] + (pj[2] - c[2]) * nn[2];
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int a = 0; a < 3; ++a) {
            pj[a] -= 2.0f * sp * nn[a];
            uj[a] -= 2.0f * su * nn[a];
        }
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a)) {
                pj[a] = 2.0f * wall[a] - pj[a];
                uj[a] = -uj[a];
            }
    }
}

/* The velocity half of image_of (the same operations): the passes after
 * the factors read the image's g and x_i - x_j' from v->df_img. */
static inline MS_DFSPH_INLINE void image_velocity(const ms_volume *v, int i, int g, float uj[3])
{
    const unsigned f = (unsigned)g >> MS_VOLUME_IMAGE_SHIFT;
    const int j = g & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    uj[0] = v->vx[j];
    uj[1] = v->vy[j];
    uj[2] = v->vz[j];
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int a = 0; a < 3; ++a)
            uj[a] -= 2.0f * su * nn[a];
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a))
                uj[a] = -uj[a];
    }
}

/* grad W_ij = -G g (x_i - x_j), G = 45/(pi h^6), g = (h - r)^2 / r: the
 * factor g of an entry at r^2 (0 at and beyond h; a coincident pair,
 * r <= eps, has no direction and gets 0 here: see coincident()). */
static inline float grad_factor(float r2, float h, float eps)
{
    const float r = sqrtf(r2);
    const float hr = ms_kernel_hr(h, r);
    return r > eps ? hr * hr / r : 0.0f;
}
MS_LANE_FN ms_lane ms_lane_grad_factor(ms_lane r, ms_lane h, ms_lane eps)
{
    const ms_lane hr = ms_lane_kernel_hr(h, r);
    return ms_lane_select(ms_lane_gt(r, eps), ms_lane_div(ms_lane_mul(hr, hr), r), ms_lane_zero());
}

/* Coincident pairs (r <= eps, which density.c counts): the lanes give them
 * no term, so particles at one point could never be pushed apart (300 at
 * one point fell as one lump, each sub-step's density solve at its cap of
 * 100 iterations over 90 000 pairs to no effect: 83 s for one second).
 * They take the limit of g (x_i - x_j) as r -> 0, h^2, along the pair's
 * direction from forces.c (as the weakly compressible laws' pressure
 * does). Entry k of i's list is coincident when this returns 1, with
 * w = h^2 dir(i, j). */
static inline int coincident(const ms_volume *v, int i, int j, float r2, float w[3])
{
    if (!(r2 <= v->eps2) || j == i)
        return 0;
    ms_volume_pair_direction(v->id[i], v->id[j], w);
    for (int a = 0; a < 3; ++a)
        w[a] *= v->K.h2;
    return 1;
}

static inline void mirror(const ms_volume *v, int i, unsigned f, float u[3])
{
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        float un = u[0] * nn[0] + u[1] * nn[1] + u[2] * nn[2];
        for (int a = 0; a < 3; ++a)
            u[a] -= 2.0f * un * nn[a];
    } else {
        for (int a = 0; a < 3; ++a)
            if (f & (1u << a))
                u[a] = -u[a];
    }
}

/* Particle i's share of its last total s in the warm start (see the
 * header): 0 at the surface, WARM_FACTOR inside. */
static inline float warm_share(const ms_volume *v, int i)
{
    return ms_volume_is_surface(v, i) ? 0.0f : WARM_FACTOR;
}

/* v_i = (nx, ny, nz), an update of the pressure solve or the warm start.
 * The pressure makes no particle faster than the sound speed (or than it
 * was): a liquid of sound speed c0 expands from a compression at about
 * c0, never faster. Measured: without it a box packed at twice rest
 * density (every particle's target out of reach in one sub-step) reached
 * 150 m/s, then non-finite velocities; with it the kinetic energy stays
 * below the elastic energy of the compression. Only binds far from any
 * state the shipped scenes reach. */
static inline void set_capped(ms_volume *v, int i, float nx, float ny, float nz)
{
    const float ux = v->vx[i], uy = v->vy[i], uz = v->vz[i];
    const float n2 = nx * nx + ny * ny + nz * nz, o2 = ux * ux + uy * uy + uz * uz;
    const float lim2 = o2 > v->c0 * v->c0 ? o2 : v->c0 * v->c0;
    if (n2 > lim2) {
        const float f = sqrtf(lim2 / n2);
        nx *= f;
        ny *= f;
        nz *= f;
    }
    v->vx[i] = nx;
    v->vy[i] = ny;
    v->vz[i] = nz;
}

/* i's velocity into the packed copy the error loops read (passes.c) (floats
 * 4..6 of its record) */
static inline void pack_velocity(ms_volume *v, int i)
{
    float *pk = v->pk + 8 * (size_t)i;
    pk[4] = v->vx[i];
    pk[5] = v->vy[i];
    pk[6] = v->vz[i];
}

/* e / rho0 in units of 2^-32, clamped to [0, 64] (NaN counts as 64) so
 * that 2^24 particles cannot overflow the sum. */
static inline int64_t quantise(float e_rel)
{
    float c = e_rel < 64.0f ? e_rel : 64.0f;
    c = c > 0.0f ? c : 0.0f;
    return (int64_t)((double)c * 4294967296.0);
}

#endif
