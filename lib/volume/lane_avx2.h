/* The lane type in AVX2 (lane.h): two __m256, lanes 8k..8k+7 in h[k];
 * a mask is two all-ones-or-zero vectors. Built without FMA. Include
 * lane.h, not this. */
#ifndef MS_VOLUME_LANE_AVX2_H
#define MS_VOLUME_LANE_AVX2_H

#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ms_lane {
    __m256 h[2];
} ms_lane;
typedef struct ms_lmask {
    __m256 h[2];
} ms_lmask;

#define MS_LANE_MAP(T, expr)    \
    T r_;                       \
    for (int k = 0; k < 2; ++k) \
        r_.h[k] = (expr);       \
    return r_

MS_LANE_FN ms_lane ms_lane_set1(float s)
{
    MS_LANE_MAP(ms_lane, _mm256_set1_ps(s));
}
MS_LANE_FN ms_lane ms_lane_zero(void)
{
    MS_LANE_MAP(ms_lane, _mm256_setzero_ps());
}
MS_LANE_FN ms_lane ms_lane_load(const float *p)
{
    MS_LANE_MAP(ms_lane, _mm256_loadu_ps(p + 8 * k));
}
MS_LANE_FN void ms_lane_store(float *p, ms_lane a)
{
    for (int k = 0; k < 2; ++k)
        _mm256_storeu_ps(p + 8 * k, a.h[k]);
}
/* The mask of lanes 8k + l < n of half k. */
MS_LANE_FN __m256i lanes_below(int n, int k)
{
    const __m256i idx = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    return _mm256_cmpgt_epi32(_mm256_set1_epi32(n - 8 * k), idx);
}
MS_LANE_FN ms_lane ms_lane_load_n(const float *p, int n)
{
    MS_LANE_MAP(ms_lane, _mm256_maskload_ps(p + 8 * k, lanes_below(n, k)));
}
MS_LANE_FN void ms_lane_store_n(float *p, ms_lane a, int n)
{
    for (int k = 0; k < 2; ++k)
        _mm256_maskstore_ps(p + 8 * k, lanes_below(n, k), a.h[k]);
}
MS_LANE_FN ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_add_ps(a.h[k], b.h[k]));
}
MS_LANE_FN ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_sub_ps(a.h[k], b.h[k]));
}
MS_LANE_FN ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_mul_ps(a.h[k], b.h[k]));
}
MS_LANE_FN ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_div_ps(a.h[k], b.h[k]));
}
MS_LANE_FN ms_lane ms_lane_sqrt(ms_lane a)
{
    MS_LANE_MAP(ms_lane, _mm256_sqrt_ps(a.h[k]));
}
MS_LANE_FN ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_max_ps(a.h[k], b.h[k])); /* a > b ? a : b */
}
MS_LANE_FN ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_LT_OQ));
}
MS_LANE_FN ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_LE_OQ));
}
MS_LANE_FN ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_GT_OQ));
}
MS_LANE_FN ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_blendv_ps(b.h[k], a.h[k], m.h[k]));
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
    const int bits = _mm256_movemask_ps(m.h[0]) | _mm256_movemask_ps(m.h[1]) << 8;
    return popcount16((unsigned)bits);
}
MS_LANE_FN float ms_lane_sum(ms_lane a)
{
    const __m256 t8 = _mm256_add_ps(a.h[0], a.h[1]);
    const __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    const __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}
MS_LANE_FN float ms_lane_max_of(ms_lane a)
{
    const __m256 t8 = _mm256_max_ps(a.h[0], a.h[1]);
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
}

MS_LANE_FN ms_lane ms_lane_neg(ms_lane a)
{
    MS_LANE_MAP(ms_lane, _mm256_xor_ps(a.h[k], _mm256_set1_ps(-0.0f)));
}
MS_LANE_FN ms_lmask ms_lane_test_bit(const int32_t *p, int32_t bit)
{
    const __m256i b = _mm256_set1_epi32(bit);
    MS_LANE_MAP(
        ms_lmask,
        _mm256_castsi256_ps(_mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_loadu_si256((const __m256i *)(const void *)(p + 8 * k)), b),
            b)));
}
/* Eight records pk[8 j .. 8 j + 7] as eight lanes of eight: an 8 x 8
 * transpose. */
MS_LANE_FN void records8x8(const float *pk, const int *restrict j, __m256 *o)
{
    __m256 r[8], t[8], s[8];
    for (int q = 0; q < 8; ++q)
        r[q] = _mm256_loadu_ps(pk + 8 * (size_t)j[q]);
    for (int q = 0; q < 8; q += 2) {
        t[q] = _mm256_unpacklo_ps(r[q], r[q + 1]);
        t[q + 1] = _mm256_unpackhi_ps(r[q], r[q + 1]);
    }
    for (int q = 0; q < 8; q += 4) {
        s[q] = _mm256_shuffle_ps(t[q], t[q + 2], 0x44);
        s[q + 1] = _mm256_shuffle_ps(t[q], t[q + 2], 0xee);
        s[q + 2] = _mm256_shuffle_ps(t[q + 1], t[q + 3], 0x44);
        s[q + 3] = _mm256_shuffle_ps(t[q + 1], t[q + 3], 0xee);
    }
    for (int q = 0; q < 4; ++q) {
        o[q] = _mm256_permute2f128_ps(s[q], s[q + 4], 0x20);
        o[q + 4] = _mm256_permute2f128_ps(s[q], s[q + 4], 0x31);
    }
}
MS_LANE_FN void ms_lane_records8(const float *pk, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3, ms_lane *o4, ms_lane *o5, ms_lane *o6,
                                 ms_lane *o7)
{
    for (int k = 0; k < 2; ++k) {
        __m256 o[8];
        records8x8(pk, j + 8 * k, o);
        o0->h[k] = o[0];
        o1->h[k] = o[1];
        o2->h[k] = o[2];
        o3->h[k] = o[3];
        o4->h[k] = o[4];
        o5->h[k] = o[5];
        o6->h[k] = o[6];
        o7->h[k] = o[7];
    }
}
MS_LANE_FN __m256 quad_pair(const float *b, int lo, int hi)
{
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(b + 8 * (size_t)lo)),
                                _mm_loadu_ps(b + 8 * (size_t)hi), 1);
}
MS_LANE_FN void ms_lane_records4(const float *b, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3)
{
    for (int k = 0; k < 2; ++k) {
        const int *jj = j + 8 * k;
        const __m256 a0 = quad_pair(b, jj[0], jj[4]), a1 = quad_pair(b, jj[1], jj[5]);
        const __m256 a2 = quad_pair(b, jj[2], jj[6]), a3 = quad_pair(b, jj[3], jj[7]);
        const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);
        const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
        o0->h[k] = _mm256_shuffle_ps(t0, t2, 0x44);
        o1->h[k] = _mm256_shuffle_ps(t0, t2, 0xee);
        o2->h[k] = _mm256_shuffle_ps(t1, t3, 0x44);
        o3->h[k] = _mm256_shuffle_ps(t1, t3, 0xee);
    }
}
MS_LANE_FN ms_lane ms_lane_gather(const float *b, const int *restrict j)
{
    MS_LANE_MAP(ms_lane, _mm256_i32gather_ps(
                             b, _mm256_loadu_si256((const __m256i *)(const void *)(j + 8 * k)), 4));
}
MS_LANE_FN void ms_lane_prefetch(const void *p)
{
    _mm_prefetch((const char *)p, _MM_HINT_T0);
}

#undef MS_LANE_MAP

#endif
