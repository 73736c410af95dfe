/* The lane type in AVX-512 (lane.h): one __m512 and a 16-bit mask
 * register. Built with AVX-512 F and DQ and BMI2. Include lane.h, not
 * this. */
#ifndef MS_VOLUME_LANE_AVX512_H
#define MS_VOLUME_LANE_AVX512_H

#include <immintrin.h>

typedef struct ms_lane {
    __m512 z;
} ms_lane;
typedef struct ms_lmask {
    __mmask16 k;
} ms_lmask;

static inline ms_lane ms_lane_of(__m512 z)
{
    ms_lane r;
    r.z = z;
    return r;
}
static inline ms_lmask ms_lmask_of(__mmask16 k)
{
    ms_lmask r;
    r.k = k;
    return r;
}
static inline ms_lane ms_lane_set1(float s)
{
    return ms_lane_of(_mm512_set1_ps(s));
}
static inline ms_lane ms_lane_zero(void)
{
    return ms_lane_of(_mm512_setzero_ps());
}
static inline ms_lane ms_lane_load(const float *p)
{
    return ms_lane_of(_mm512_loadu_ps(p));
}
static inline void ms_lane_store(float *p, ms_lane a)
{
    _mm512_storeu_ps(p, a.z);
}
static inline __mmask16 lanes_below(int n)
{
    return (__mmask16)_bzhi_u32(0xffffu, (unsigned)n);
}
static inline ms_lane ms_lane_load_n(const float *p, int n)
{
    return ms_lane_of(_mm512_maskz_loadu_ps(lanes_below(n), p));
}
static inline void ms_lane_store_n(float *p, ms_lane a, int n)
{
    _mm512_mask_storeu_ps(p, lanes_below(n), a.z);
}
static inline ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_add_ps(a.z, b.z));
}
static inline ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_sub_ps(a.z, b.z));
}
static inline ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_mul_ps(a.z, b.z));
}
static inline ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_div_ps(a.z, b.z));
}
static inline ms_lane ms_lane_sqrt(ms_lane a)
{
    return ms_lane_of(_mm512_sqrt_ps(a.z));
}
static inline ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_max_ps(a.z, b.z)); /* a > b ? a : b */
}
static inline ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_LT_OQ));
}
static inline ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_LE_OQ));
}
static inline ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_GT_OQ));
}
static inline ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_mask_blend_ps(m.k, b.z, a.z));
}
static inline int ms_lane_count(ms_lmask m)
{
    return __builtin_popcount((unsigned)m.k);
}
static inline float ms_lane_sum(ms_lane a)
{
    const __m256 t8 =
        _mm256_add_ps(_mm512_castps512_ps256(a.z),
                      _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a.z), 1)));
    const __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    const __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}
static inline float ms_lane_max_of(ms_lane a)
{
    return _mm512_reduce_max_ps(a.z);
}

#endif
