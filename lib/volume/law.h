/* The equations of state of desc.pressure (density.c says why each is
 * clamped at p >= 0), as a scalar and over the lane type with the same
 * operations per lane, so the same bits:
 *   MS_PRESSURE_IDEAL_GAS  p = k (rho - rho0)
 *   MS_PRESSURE_TAIT       p = B ((rho/rho0)^7 - 1), continued along its
 *                          tangent beyond rho = 2 rho0
 *   MS_PRESSURE_DFSPH      0 (the solves of dfsph.c act on the velocities)
 */
#ifndef MS_VOLUME_LAW_H
#define MS_VOLUME_LAW_H

#include "volume/volume_internal.h"

/* max(p, 0) as fmaxf(p, 0.0f) gives it (a NaN p: 0), without the call
 * to libm that fmaxf is at -O2. p = -0 cannot occur (k, B > 0;
 * x - x = +0). */
static inline float ms_law_clamp(float p)
{
    return p > 0.0f ? p : 0.0f;
}

static inline float ms_law_pressure(const ms_volume *v, float rho)
{
    const float rho0 = v->desc.rest_density;
    if (v->desc.pressure == MS_PRESSURE_DFSPH)
        return 0.0f;
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        const float r = rho / rho0;
        if (r <= 2.0f) {
            const float r2 = r * r, r3 = r2 * r;
            return ms_law_clamp(v->tait_b * (r3 * r3 * r - 1.0f));
        }
        return v->tait_b * (127.0f + 448.0f * (r - 2.0f)); /* 2^7 - 1, 7 * 2^6 */
    }
    return ms_law_clamp(v->desc.gas_constant * (rho - rho0));
}

/* ms_law_pressure lane by lane: the Tait law's two branches both
 * computed and selected (r <= 2, false for a NaN r, as the scalar's
 * test). */
MS_LANE_FN ms_lane ms_lane_law_pressure(const ms_volume *v, ms_lane rho)
{
    const ms_lane rho0 = ms_lane_set1(v->desc.rest_density), zero = ms_lane_zero();
    if (v->desc.pressure == MS_PRESSURE_DFSPH)
        return zero;
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        const ms_lane b = ms_lane_set1(v->tait_b), r = ms_lane_div(rho, rho0);
        const ms_lane r2 = ms_lane_mul(r, r), r3 = ms_lane_mul(r2, r);
        const ms_lane lo =
            ms_lane_mul(b, ms_lane_sub(ms_lane_mul(ms_lane_mul(r3, r3), r), ms_lane_set1(1.0f)));
        const ms_lane hi = ms_lane_mul(
            b, ms_lane_add(ms_lane_set1(127.0f),
                           ms_lane_mul(ms_lane_set1(448.0f), ms_lane_sub(r, ms_lane_set1(2.0f)))));
        const ms_lane lo_clamped = ms_lane_select(ms_lane_gt(lo, zero), lo, zero);
        return ms_lane_select(ms_lane_le(r, ms_lane_set1(2.0f)), lo_clamped, hi);
    }
    const ms_lane p = ms_lane_mul(ms_lane_set1(v->desc.gas_constant), ms_lane_sub(rho, rho0));
    return ms_lane_select(ms_lane_gt(p, zero), p, zero);
}

#endif
