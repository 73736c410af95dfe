/* The SPH smoothing kernels of Mueller, Charypar & Gross 2003 as the paper
 * gives them (h = smoothing length, r = distance, both m):
 *
 *   poly6 (Mueller's density kernel):      W(r)    = 315/(64 pi h^9) (h^2 - r^2)^3
 *   spiky, pressure (eq. 11; density):     W(r)    = 15/(pi h^6) (h - r)^3
 *        its gradient (eq. 13):            grad W  = -45/(pi h^6) (h - r)^2 r_vec / r
 *   viscosity (eq. 12): its Laplacian (eq. 14) lap W = 45/(pi h^6) (h - r)
 *
 * all zero for r >= h (eq. 8). The constants are precomputed once per
 * volume (struct ms_sph_kernels); the passes call the shapes below, in
 * float as scalars and over the lane type (lane.h) with the same
 * operations in the same order (the same bits), and in double for set-up.
 * This header is the one place that spells them.
 */
#ifndef MS_VOLUME_KERNELS_H
#define MS_VOLUME_KERNELS_H

#include <math.h>

#include "volume/lane.h"

#define MS_PI_D 3.14159265358979323846

typedef struct ms_sph_kernels {
    float h, h2;      /* m, m^2 */
    float poly6;      /* 315 / (64 pi h^9), 1/m^9 */
    float spiky;      /* 15 / (pi h^6), 1/m^6 */
    float spiky_grad; /* 45 / (pi h^6), 1/m^6 (magnitude of grad W / (h-r)^2) */
    float visc_lap;   /* 45 / (pi h^6), 1/m^6 (lap W / (h-r)) */
} ms_sph_kernels;

static inline ms_sph_kernels ms_sph_kernels_make(double h)
{
    ms_sph_kernels k;
    k.h = (float)h;
    k.h2 = (float)(h * h);
    k.poly6 = (float)(315.0 / (64.0 * MS_PI_D * h * h * h * h * h * h * h * h * h));
    k.spiky = (float)(15.0 / (MS_PI_D * h * h * h * h * h * h));
    k.spiky_grad = (float)(45.0 / (MS_PI_D * h * h * h * h * h * h));
    k.visc_lap = (float)(45.0 / (MS_PI_D * h * h * h * h * h * h));
    return k;
}

/* The spiky kernel's shape (eq. 11 over its constant) at r^2 <= h^2:
 * (h - r)^3. */
static inline float ms_spiky_shape(float h, float r2)
{
    const float t = h - sqrtf(r2);
    return t * t * t;
}
MS_LANE_FN ms_lane ms_lane_spiky_shape(ms_lane h, ms_lane r2)
{
    const ms_lane t = ms_lane_sub(h, ms_lane_sqrt(r2));
    return ms_lane_mul(ms_lane_mul(t, t), t);
}

/* poly6's shape (over its constant) at r^2 <= h^2: (h^2 - r^2)^3. */
static inline float ms_poly6_shape(float h2, float r2)
{
    const float t = h2 - r2;
    return t * t * t;
}
MS_LANE_FN ms_lane ms_lane_poly6_shape(ms_lane h2, ms_lane r2)
{
    const ms_lane t = ms_lane_sub(h2, r2);
    return ms_lane_mul(ms_lane_mul(t, t), t);
}

/* max(h - r, 0): the viscosity Laplacian (eq. 14) over its constant, and
 * the factor the spiky gradient (eq. 13) has twice,
 * grad W = -spiky_grad (h - r)^2 r_vec / r. */
static inline float ms_kernel_hr(float h, float r)
{
    const float t = h - r;
    return t > 0.0f ? t : 0.0f;
}
MS_LANE_FN ms_lane ms_lane_kernel_hr(ms_lane h, ms_lane r)
{
    return ms_lane_max(ms_lane_sub(h, r), ms_lane_zero());
}

/* poly6 of r^2, double precision (set-up only). */
static inline double ms_poly6_d(double h, double r2)
{
    double h2 = h * h;
    if (r2 >= h2)
        return 0.0;
    double d = h2 - r2;
    return 315.0 / (64.0 * MS_PI_D * h * h * h * h * h * h * h * h * h) * d * d * d;
}

/* The density kernel of desc.density_kernel at r (m), double (set-up). */
static inline double ms_density_kernel_d(int poly6, double h, double r)
{
    if (r >= h)
        return 0.0;
    if (poly6)
        return ms_poly6_d(h, r * r);
    double t = h - r;
    return 15.0 / (MS_PI_D * h * h * h * h * h * h) * t * t * t;
}

#endif
