/* The lane type in plain C (lane.h): 16 floats in a struct, each
 * operation a loop over them; the sum in lane.h's tree order. Include
 * lane.h, not this. */
#ifndef MS_VOLUME_LANE_C_H
#define MS_VOLUME_LANE_C_H

#include <math.h>
#include <stdint.h>

typedef struct ms_lane {
    float f[16];
} ms_lane;
typedef struct ms_lmask {
    int32_t m[16]; /* 0 or -1 */
} ms_lmask;

#define MS_LANE_MAP(expr)        \
    ms_lane r_;                  \
    for (int l = 0; l < 16; ++l) \
        r_.f[l] = (expr);        \
    return r_
#define MS_LANE_CMP(op)                      \
    ms_lmask r_;                             \
    for (int l = 0; l < 16; ++l)             \
        r_.m[l] = a.f[l] op b.f[l] ? -1 : 0; \
    return r_

MS_LANE_FN ms_lane ms_lane_set1(float s)
{
    MS_LANE_MAP(s);
}
MS_LANE_FN ms_lane ms_lane_zero(void)
{
    return ms_lane_set1(0.0f);
}
MS_LANE_FN ms_lane ms_lane_load(const float *p)
{
    MS_LANE_MAP(p[l]);
}
MS_LANE_FN void ms_lane_store(float *p, ms_lane a)
{
    for (int l = 0; l < 16; ++l)
        p[l] = a.f[l];
}
MS_LANE_FN ms_lane ms_lane_load_n(const float *p, int n)
{
    MS_LANE_MAP(l < n ? p[l] : 0.0f);
}
MS_LANE_FN void ms_lane_store_n(float *p, ms_lane a, int n)
{
    for (int l = 0; l < n; ++l)
        p[l] = a.f[l];
}
MS_LANE_FN ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(a.f[l] + b.f[l]);
}
MS_LANE_FN ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(a.f[l] - b.f[l]);
}
MS_LANE_FN ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(a.f[l] * b.f[l]);
}
MS_LANE_FN ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(a.f[l] / b.f[l]);
}
MS_LANE_FN ms_lane ms_lane_sqrt(ms_lane a)
{
    MS_LANE_MAP(sqrtf(a.f[l]));
}
MS_LANE_FN ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(a.f[l] > b.f[l] ? a.f[l] : b.f[l]);
}
MS_LANE_FN ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    MS_LANE_CMP(<);
}
MS_LANE_FN ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    MS_LANE_CMP(<=);
}
MS_LANE_FN ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    MS_LANE_CMP(>);
}
MS_LANE_FN ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    MS_LANE_MAP(m.m[l] ? a.f[l] : b.f[l]);
}
MS_LANE_FN int ms_lane_count(ms_lmask m)
{
    int c = 0;
    for (int l = 0; l < 16; ++l)
        c -= m.m[l];
    return c;
}
MS_LANE_FN float ms_lane_sum(ms_lane a)
{
    float t8[8], t4[4];
    for (int l = 0; l < 8; ++l)
        t8[l] = a.f[l] + a.f[l + 8];
    for (int l = 0; l < 4; ++l)
        t4[l] = t8[l] + t8[l + 4];
    return (t4[0] + t4[2]) + (t4[1] + t4[3]);
}
MS_LANE_FN float ms_lane_max_of(ms_lane a)
{
    float m = a.f[0];
    for (int l = 1; l < 16; ++l)
        m = a.f[l] > m ? a.f[l] : m;
    return m;
}

MS_LANE_FN ms_lane ms_lane_neg(ms_lane a)
{
    MS_LANE_MAP(-a.f[l]);
}
MS_LANE_FN ms_lmask ms_lane_test_bit(const int32_t *p, int32_t bit)
{
    ms_lmask r_;
    for (int l = 0; l < 16; ++l)
        r_.m[l] = p[l] & bit ? -1 : 0;
    return r_;
}
MS_LANE_FN void ms_lane_records8(const float *pk, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3, ms_lane *o4, ms_lane *o5, ms_lane *o6,
                                 ms_lane *o7)
{
    for (int l = 0; l < 16; ++l) {
        const float *r = pk + 8 * (size_t)j[l];
        o0->f[l] = r[0];
        o1->f[l] = r[1];
        o2->f[l] = r[2];
        o3->f[l] = r[3];
        o4->f[l] = r[4];
        o5->f[l] = r[5];
        o6->f[l] = r[6];
        o7->f[l] = r[7];
    }
}
MS_LANE_FN void ms_lane_records4(const float *b, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3)
{
    for (int l = 0; l < 16; ++l) {
        const float *r = b + 8 * (size_t)j[l];
        o0->f[l] = r[0];
        o1->f[l] = r[1];
        o2->f[l] = r[2];
        o3->f[l] = r[3];
    }
}
MS_LANE_FN ms_lane ms_lane_gather(const float *b, const int *restrict j)
{
    MS_LANE_MAP(b[j[l]]);
}
MS_LANE_FN void ms_lane_prefetch(const void *p)
{
    (void)p;
}

#undef MS_LANE_MAP
#undef MS_LANE_CMP

#endif
