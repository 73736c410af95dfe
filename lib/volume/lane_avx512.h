/* The lane type in AVX-512 (lane.h): one __m512 and a 16-bit mask
 * register. Built with AVX-512 F and DQ and BMI2. Include lane.h, not
 * this. */
#ifndef MS_VOLUME_LANE_AVX512_H
#define MS_VOLUME_LANE_AVX512_H

#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ms_lane {
    __m512 z;
} ms_lane;
typedef struct ms_lmask {
    __mmask16 k;
} ms_lmask;

MS_LANE_FN ms_lane ms_lane_of(__m512 z)
{
    ms_lane r;
    r.z = z;
    return r;
}
MS_LANE_FN ms_lmask ms_lmask_of(__mmask16 k)
{
    ms_lmask r;
    r.k = k;
    return r;
}
MS_LANE_FN ms_lane ms_lane_set1(float s)
{
    return ms_lane_of(_mm512_set1_ps(s));
}
MS_LANE_FN ms_lane ms_lane_zero(void)
{
    return ms_lane_of(_mm512_setzero_ps());
}
MS_LANE_FN ms_lane ms_lane_load(const float *p)
{
    return ms_lane_of(_mm512_loadu_ps(p));
}
MS_LANE_FN void ms_lane_store(float *p, ms_lane a)
{
    _mm512_storeu_ps(p, a.z);
}
MS_LANE_FN __mmask16 lanes_below(int n)
{
    return (__mmask16)_bzhi_u32(0xffffu, (unsigned)n);
}
MS_LANE_FN ms_lane ms_lane_load_n(const float *p, int n)
{
    return ms_lane_of(_mm512_maskz_loadu_ps(lanes_below(n), p));
}
MS_LANE_FN void ms_lane_store_n(float *p, ms_lane a, int n)
{
    _mm512_mask_storeu_ps(p, lanes_below(n), a.z);
}
MS_LANE_FN ms_lane ms_lane_add(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_add_ps(a.z, b.z));
}
MS_LANE_FN ms_lane ms_lane_sub(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_sub_ps(a.z, b.z));
}
MS_LANE_FN ms_lane ms_lane_mul(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_mul_ps(a.z, b.z));
}
MS_LANE_FN ms_lane ms_lane_div(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_div_ps(a.z, b.z));
}
MS_LANE_FN ms_lane ms_lane_sqrt(ms_lane a)
{
    return ms_lane_of(_mm512_sqrt_ps(a.z));
}
MS_LANE_FN ms_lane ms_lane_max(ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_max_ps(a.z, b.z)); /* a > b ? a : b */
}
MS_LANE_FN ms_lmask ms_lane_lt(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_LT_OQ));
}
MS_LANE_FN ms_lmask ms_lane_le(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_LE_OQ));
}
MS_LANE_FN ms_lmask ms_lane_gt(ms_lane a, ms_lane b)
{
    return ms_lmask_of(_mm512_cmp_ps_mask(a.z, b.z, _CMP_GT_OQ));
}
MS_LANE_FN ms_lane ms_lane_select(ms_lmask m, ms_lane a, ms_lane b)
{
    return ms_lane_of(_mm512_mask_blend_ps(m.k, b.z, a.z));
}
MS_LANE_FN int ms_lane_count(ms_lmask m)
{
    return __builtin_popcount((unsigned)m.k);
}
MS_LANE_FN float ms_lane_sum(ms_lane a)
{
    const __m256 t8 =
        _mm256_add_ps(_mm512_castps512_ps256(a.z),
                      _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a.z), 1)));
    const __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    const __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}
MS_LANE_FN float ms_lane_max_of(ms_lane a)
{
    return _mm512_reduce_max_ps(a.z);
}

MS_LANE_FN ms_lane ms_lane_neg(ms_lane a)
{
    return ms_lane_of(_mm512_castsi512_ps(
        _mm512_xor_si512(_mm512_castps_si512(a.z), _mm512_set1_epi32((int)0x80000000u))));
}
MS_LANE_FN ms_lmask ms_lane_test_bit(const int32_t *p, int32_t bit)
{
    return ms_lmask_of(
        _mm512_test_epi32_mask(_mm512_loadu_si512((const void *)p), _mm512_set1_epi32(bit)));
}

/* The records pk[8 j .. 8 j + 7] of j[0..16) as eight lanes: sixteen
 * 32-byte loads and an 8 x 8 transpose in each 256-bit half, in place of
 * eight gathers (measured on a Zen 4 CPU, the force pass's share of a 32k
 * sub-step went from 30 % to 20 %; with arrays in place of the written-out
 * temporaries GCC spilled them to the stack and there was no gain).
 * Vector a[k] holds the records of j[k] | j[k+4] (k < 4) or j[k+4] |
 * j[k+8] (k >= 4), so that the last lane shuffle puts the lanes in order. */
MS_LANE_FN __m512 record_pair(const float *pk, int lo, int hi)
{
    return _mm512_insertf32x8(_mm512_castps256_ps512(_mm256_loadu_ps(pk + 8 * (size_t)lo)),
                              _mm256_loadu_ps(pk + 8 * (size_t)hi), 1);
}

#define MS_LANE_TRANSPOSE4(a0, a1, a2, a3, s0, s1, s2, s3)                               \
    do {                                                                                 \
        const __m512 t0_ = _mm512_unpacklo_ps(a0, a1), t1_ = _mm512_unpackhi_ps(a0, a1); \
        const __m512 t2_ = _mm512_unpacklo_ps(a2, a3), t3_ = _mm512_unpackhi_ps(a2, a3); \
        s0 = _mm512_shuffle_ps(t0_, t2_, 0x44);                                          \
        s1 = _mm512_shuffle_ps(t0_, t2_, 0xee);                                          \
        s2 = _mm512_shuffle_ps(t1_, t3_, 0x44);                                          \
        s3 = _mm512_shuffle_ps(t1_, t3_, 0xee);                                          \
    } while (0)

MS_LANE_FN void ms_lane_records8(const float *pk, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3, ms_lane *o4, ms_lane *o5, ms_lane *o6,
                                 ms_lane *o7)
{
    const __m512 a0 = record_pair(pk, j[0], j[4]), a1 = record_pair(pk, j[1], j[5]);
    const __m512 a2 = record_pair(pk, j[2], j[6]), a3 = record_pair(pk, j[3], j[7]);
    const __m512 a4 = record_pair(pk, j[8], j[12]), a5 = record_pair(pk, j[9], j[13]);
    const __m512 a6 = record_pair(pk, j[10], j[14]), a7 = record_pair(pk, j[11], j[15]);
    __m512 s0, s1, s2, s3, s4, s5, s6, s7;
    MS_LANE_TRANSPOSE4(a0, a1, a2, a3, s0, s1, s2, s3);
    MS_LANE_TRANSPOSE4(a4, a5, a6, a7, s4, s5, s6, s7);
    o0->z = _mm512_shuffle_f32x4(s0, s4, 0x88);
    o4->z = _mm512_shuffle_f32x4(s0, s4, 0xdd);
    o1->z = _mm512_shuffle_f32x4(s1, s5, 0x88);
    o5->z = _mm512_shuffle_f32x4(s1, s5, 0xdd);
    o2->z = _mm512_shuffle_f32x4(s2, s6, 0x88);
    o6->z = _mm512_shuffle_f32x4(s2, s6, 0xdd);
    o3->z = _mm512_shuffle_f32x4(s3, s7, 0x88);
    o7->z = _mm512_shuffle_f32x4(s3, s7, 0xdd);
}

/* The quads b[8 j + 0..3] of j[0..16): sixteen 16-byte loads and a 4 x 4
 * transpose in each 128-bit lane; vector a[k] holds the quads of j[k],
 * j[k+4], j[k+8], j[k+12]. */
#define MS_LANE_QUAD(k) _mm_loadu_ps(b + 8 * (size_t)j[k])
#define MS_LANE_ROW(k)                                                                             \
    _mm512_insertf32x4(                                                                            \
        _mm512_insertf32x4(                                                                        \
            _mm512_insertf32x4(_mm512_castps128_ps512(MS_LANE_QUAD(k)), MS_LANE_QUAD((k) + 4), 1), \
            MS_LANE_QUAD((k) + 8), 2),                                                             \
        MS_LANE_QUAD((k) + 12), 3)
MS_LANE_FN void ms_lane_records4(const float *b, const int *restrict j, ms_lane *o0, ms_lane *o1,
                                 ms_lane *o2, ms_lane *o3)
{
    const __m512 a0 = MS_LANE_ROW(0), a1 = MS_LANE_ROW(1), a2 = MS_LANE_ROW(2), a3 = MS_LANE_ROW(3);
    MS_LANE_TRANSPOSE4(a0, a1, a2, a3, o0->z, o1->z, o2->z, o3->z);
}
#undef MS_LANE_ROW
#undef MS_LANE_QUAD
#undef MS_LANE_TRANSPOSE4

MS_LANE_FN ms_lane ms_lane_gather(const float *b, const int *restrict j)
{
    return ms_lane_of(_mm512_i32gather_ps(_mm512_loadu_si512((const void *)j), b, 4));
}

MS_LANE_FN void ms_lane_prefetch(const void *p)
{
    _mm_prefetch((const char *)p, _MM_HINT_T0);
}

#endif
