/* The lane type in SSE2 (lane.h): four __m128, lanes 4k..4k+3 in q[k];
 * a mask is four all-ones-or-zero vectors. Include lane.h, not this. */
#ifndef MS_VOLUME_LANE_SSE2_H
#define MS_VOLUME_LANE_SSE2_H

#include <emmintrin.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ms_lane {
    __m128 q[4];
} ms_lane;
typedef struct ms_lmask {
    __m128 q[4];
} ms_lmask;

#define MS_LANE_MAP(T, expr)    \
    T r_;                       \
    for (int k = 0; k < 4; ++k) \
        r_.q[k] = (expr);       \
    return r_

MS_LANE_FN ms_lane ms_lane_set1(float s)
{
    MS_LANE_MAP(ms_lane, _mm_set1_ps(s));
}
MS_LANE_FN ms_lane ms_lane_zero(void)
{
    MS_LANE_MAP(ms_lane, _mm_setzero_ps());
}
MS_LANE_FN ms_lane ms_lane_load(const float *p)
{
    MS_LANE_MAP(ms_lane, _mm_loadu_ps(p + 4 * k));
}
MS_LANE_FN void ms_lane_store(float *p, ms_lane a)
{
    for (int k = 0; k < 4; ++k)
        _mm_storeu_ps(p + 4 * k, a.q[k]);
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
    MS_LANE_MAP(ms_lane, _mm_add_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm_sub_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm_mul_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm_div_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_sqrt(ms_lane a)
{
    MS_LANE_MAP(ms_lane, _mm_sqrt_ps(a.q[k]));
}
MS_LANE_FN ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm_max_ps(a.q[k], b.q[k])); /* a > b ? a : b */
}
MS_LANE_FN ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm_cmplt_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm_cmple_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm_cmpgt_ps(a.q[k], b.q[k]));
}
MS_LANE_FN ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm_or_ps(_mm_and_ps(m.q[k], a.q[k]), _mm_andnot_ps(m.q[k], b.q[k])));
}
/* The set bits of a 16-bit mask (SSE2 has no popcnt instruction). */
MS_LANE_FN int popcount16(unsigned x)
{
    x = x - ((x >> 1) & 0x5555u);
    x = (x & 0x3333u) + ((x >> 2) & 0x3333u);
    x = (x + (x >> 4)) & 0x0f0fu;
    return (int)((x + (x >> 8)) & 0x1fu);
}
MS_LANE_FN int ms_lane_count(ms_lmask m)
{
    const int bits = _mm_movemask_ps(m.q[0]) | _mm_movemask_ps(m.q[1]) << 4 |
                     _mm_movemask_ps(m.q[2]) << 8 | _mm_movemask_ps(m.q[3]) << 12;
    return popcount16((unsigned)bits);
}
MS_LANE_FN float ms_lane_sum(ms_lane a)
{
    const __m128 t4 = _mm_add_ps(_mm_add_ps(a.q[0], a.q[2]), _mm_add_ps(a.q[1], a.q[3]));
    const __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}
MS_LANE_FN float ms_lane_max_of(ms_lane a)
{
    __m128 m = _mm_max_ps(_mm_max_ps(a.q[0], a.q[1]), _mm_max_ps(a.q[2], a.q[3]));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
}

MS_LANE_FN ms_lane ms_lane_neg(ms_lane a)
{
    MS_LANE_MAP(ms_lane, _mm_xor_ps(a.q[k], _mm_set1_ps(-0.0f)));
}
MS_LANE_FN ms_lmask ms_lane_test_bit(const int32_t *p, int32_t bit)
{
    const __m128i b = _mm_set1_epi32(bit);
    MS_LANE_MAP(
        ms_lmask,
        _mm_castsi128_ps(_mm_cmpeq_epi32(
            _mm_and_si128(_mm_loadu_si128((const __m128i *)(const void *)(p + 4 * k)), b), b)));
}
/* Four records' quads b[8 j + 0..3] as four lanes of four: a 4 x 4
 * transpose. */
MS_LANE_FN void quads4(const float *b, const int *restrict j, __m128 *o0, __m128 *o1, __m128 *o2,
                       __m128 *o3)
{
    __m128 a0 = _mm_loadu_ps(b + 8 * (size_t)j[0]), a1 = _mm_loadu_ps(b + 8 * (size_t)j[1]);
    __m128 a2 = _mm_loadu_ps(b + 8 * (size_t)j[2]), a3 = _mm_loadu_ps(b + 8 * (size_t)j[3]);
    _MM_TRANSPOSE4_PS(a0, a1, a2, a3);
    *o0 = a0;
    *o1 = a1;
    *o2 = a2;
    *o3 = a3;
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
    MS_LANE_MAP(ms_lane,
                _mm_setr_ps(b[j[4 * k]], b[j[4 * k + 1]], b[j[4 * k + 2]], b[j[4 * k + 3]]));
}
MS_LANE_FN void ms_lane_prefetch(const void *p)
{
    _mm_prefetch((const char *)p, _MM_HINT_T0);
}

#undef MS_LANE_MAP

#endif
