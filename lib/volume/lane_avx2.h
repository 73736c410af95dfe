/* The lane type in AVX2 (lane.h): two __m256, lanes 8k..8k+7 in h[k];
 * a mask is two all-ones-or-zero vectors. Built without FMA. Include
 * lane.h, not this. */
#ifndef MS_VOLUME_LANE_AVX2_H
#define MS_VOLUME_LANE_AVX2_H

#include <immintrin.h>

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

static inline ms_lane ms_lane_set1(float s)
{
    MS_LANE_MAP(ms_lane, _mm256_set1_ps(s));
}
static inline ms_lane ms_lane_zero(void)
{
    MS_LANE_MAP(ms_lane, _mm256_setzero_ps());
}
static inline ms_lane ms_lane_load(const float *p)
{
    MS_LANE_MAP(ms_lane, _mm256_loadu_ps(p + 8 * k));
}
static inline void ms_lane_store(float *p, ms_lane a)
{
    for (int k = 0; k < 2; ++k)
        _mm256_storeu_ps(p + 8 * k, a.h[k]);
}
/* The mask of lanes 8k + l < n of half k. */
static inline __m256i lanes_below(int n, int k)
{
    const __m256i idx = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    return _mm256_cmpgt_epi32(_mm256_set1_epi32(n - 8 * k), idx);
}
static inline ms_lane ms_lane_load_n(const float *p, int n)
{
    MS_LANE_MAP(ms_lane, _mm256_maskload_ps(p + 8 * k, lanes_below(n, k)));
}
static inline void ms_lane_store_n(float *p, ms_lane a, int n)
{
    for (int k = 0; k < 2; ++k)
        _mm256_maskstore_ps(p + 8 * k, lanes_below(n, k), a.h[k]);
}
static inline ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_add_ps(a.h[k], b.h[k]));
}
static inline ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_sub_ps(a.h[k], b.h[k]));
}
static inline ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_mul_ps(a.h[k], b.h[k]));
}
static inline ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_div_ps(a.h[k], b.h[k]));
}
static inline ms_lane ms_lane_sqrt(ms_lane a)
{
    MS_LANE_MAP(ms_lane, _mm256_sqrt_ps(a.h[k]));
}
static inline ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_max_ps(a.h[k], b.h[k])); /* a > b ? a : b */
}
static inline ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_LT_OQ));
}
static inline ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_LE_OQ));
}
static inline ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lmask, _mm256_cmp_ps(a.h[k], b.h[k], _CMP_GT_OQ));
}
static inline ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    MS_LANE_MAP(ms_lane, _mm256_blendv_ps(b.h[k], a.h[k], m.h[k]));
}
static inline int ms_lane_count(ms_lmask m)
{
    const int bits = _mm256_movemask_ps(m.h[0]) | _mm256_movemask_ps(m.h[1]) << 8;
    return __builtin_popcount((unsigned)bits);
}
static inline float ms_lane_sum(ms_lane a)
{
    const __m256 t8 = _mm256_add_ps(a.h[0], a.h[1]);
    const __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    const __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}
static inline float ms_lane_max_of(ms_lane a)
{
    const __m256 t8 = _mm256_max_ps(a.h[0], a.h[1]);
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
}

#undef MS_LANE_MAP

#endif
