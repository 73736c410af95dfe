/* The lane type in NEON (lane.h, aarch64): four float32x4_t, lanes
 * 4k..4k+3 in q[k]; a mask is four all-ones-or-zero vectors. The max is
 * a compare and select (vmaxq_f32 differs from a > b ? a : b on a NaN).
 * Include lane.h, not this. */
#ifndef MS_VOLUME_LANE_NEON_H
#define MS_VOLUME_LANE_NEON_H

#include <arm_neon.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ms_lane {
    float32x4_t q[4];
} ms_lane;
typedef struct ms_lmask {
    uint32x4_t q[4];
} ms_lmask;

#define MS_LANE_MAP(T, expr)    \
    T r_;                       \
    for (int k = 0; k < 4; ++k) \
        r_.q[k] = (expr);       \
    return r_

MS_LANE_FN ms_lane ms_lane_set1(float s)
{
    MS_LANE_MAP(ms_lane, vdupq_n_f32(s));
}
MS_LANE_FN ms_lane ms_lane_zero(void)
{
    return ms_lane_set1(0.0f);
}
MS_LANE_FN ms_lane ms_lane_load(const float *p)
{
    MS_LANE_MAP(ms_lane, vld1q_f32(p + 4 * k));
}
MS_LANE_FN void ms_lane_store(float *p, ms_lane a)
{
    for (int k = 0; k < 4; ++k)
        vst1q_f32(p + 4 * k, a.q[k]);
}
MS_LANE_FN ms_lane ms_lane_load_n(const float *p, int n)
{
    float t[16] = {0};
    for (int l = 0; l < n; ++l)
        t[l] = p[l];
    return ms_lane_load(t);
}
MS_LANE_FN void ms_lane_store_n(float *p, ms_lane a, int n)
{
    float t[16];
    ms_lane_store(t, a);
    for (int l = 0; l < n; ++l)
        p[l] = t[l];
}
MS_LANE_FN ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vaddq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vsubq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vmulq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vdivq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_sqrt(ms_lane a)
{
    MS_LANE_MAP(ms_lane, vsqrtq_f32(a.q[k]));
}
MS_LANE_FN ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vbslq_f32(vcgtq_f32(a.q[k], b.q[k]), a.q[k], b.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, vcltq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, vcleq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, vcgtq_f32(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, vbslq_f32(m.q[k], a.q[k], b.q[k]));
}
MS_LANE_FN int ms_lane_count(ms_lmask m)
{
    uint32x4_t c = vaddq_u32(vaddq_u32(vshrq_n_u32(m.q[0], 31), vshrq_n_u32(m.q[1], 31)),
                             vaddq_u32(vshrq_n_u32(m.q[2], 31), vshrq_n_u32(m.q[3], 31)));
    return (int)vaddvq_u32(c);
}
MS_LANE_FN float ms_lane_sum(ms_lane a)
{
    const float32x4_t t4 = vaddq_f32(vaddq_f32(a.q[0], a.q[2]), vaddq_f32(a.q[1], a.q[3]));
    const float32x2_t t2 = vadd_f32(vget_low_f32(t4), vget_high_f32(t4)); /* (0+2, 1+3) */
    return vget_lane_f32(t2, 0) + vget_lane_f32(t2, 1);
}
MS_LANE_FN float ms_lane_max_of(ms_lane a)
{
    float t[16];
    ms_lane_store(t, a);
    float m = t[0];
    for (int l = 1; l < 16; ++l)
        m = t[l] > m ? t[l] : m;
    return m;
}

MS_LANE_FN ms_lane ms_lane_neg(ms_lane a)
{
    MS_LANE_MAP(ms_lane, vnegq_f32(a.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_test_bit(const int32_t *p, int32_t bit)
{
    MS_LANE_MAP(ms_lmask,
                vtstq_u32(vreinterpretq_u32_s32(vld1q_s32(p + 4 * k)), vdupq_n_u32((uint32_t)bit)));
}
/* Four records' quads b[8 j + 0..3] as four lanes of four. */
MS_LANE_FN void quads4(const float *b, const int *restrict j, float32x4_t *o0, float32x4_t *o1,
                       float32x4_t *o2, float32x4_t *o3)
{
    const float32x4_t a0 = vld1q_f32(b + 8 * (size_t)j[0]), a1 = vld1q_f32(b + 8 * (size_t)j[1]);
    const float32x4_t a2 = vld1q_f32(b + 8 * (size_t)j[2]), a3 = vld1q_f32(b + 8 * (size_t)j[3]);
    const float32x4x2_t t01 = vtrnq_f32(a0, a1), t23 = vtrnq_f32(a2, a3);
    *o0 = vcombine_f32(vget_low_f32(t01.val[0]), vget_low_f32(t23.val[0]));
    *o1 = vcombine_f32(vget_low_f32(t01.val[1]), vget_low_f32(t23.val[1]));
    *o2 = vcombine_f32(vget_high_f32(t01.val[0]), vget_high_f32(t23.val[0]));
    *o3 = vcombine_f32(vget_high_f32(t01.val[1]), vget_high_f32(t23.val[1]));
}
MS_LANE_FN void ms_lane_records8(const float *pk, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3, ms_lane *o4, ms_lane *o5, ms_lane *o6,
                                 ms_lane *o7)
{
    for (int k = 0; k < 4; ++k) {
        quads4(pk, j + 4 * k, &o0->q[k], &o1->q[k], &o2->q[k], &o3->q[k]);
        quads4(pk + 4, j + 4 * k, &o4->q[k], &o5->q[k], &o6->q[k], &o7->q[k]);
    }
}
MS_LANE_FN void ms_lane_records4(const float *b, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3)
{
    for (int k = 0; k < 4; ++k)
        quads4(b, j + 4 * k, &o0->q[k], &o1->q[k], &o2->q[k], &o3->q[k]);
}
MS_LANE_FN ms_lane ms_lane_gather(const float *b, const int *restrict j)
{
    float t[16];
    for (int l = 0; l < 16; ++l)
        t[l] = b[j[l]];
    return ms_lane_load(t);
}
MS_LANE_FN void ms_lane_prefetch(const void *p)
{
    __builtin_prefetch(p);
}

#undef MS_LANE_MAP

#endif
