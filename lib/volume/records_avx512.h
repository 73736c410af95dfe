/* The AVX-512 loops' shared pieces: the mask of a block's lanes that
 * are left before a loop's end, the sum of a vector's lanes; for the pair loops (forces.c, dfsph.c)
 * the prefetch of their per-pair streams, and sixteen neighbours' 4-float
 * quads out of the packed 8-float records (v->pk), what the force pass
 * (under DFSPH) and the DFSPH solves read of each neighbour: sixteen
 * 16-byte loads and a 4 x 4 transpose in each 128-bit lane, in place of
 * gathers (AVX-512 gathers were 35 % of a 32k dam break's sub-step).
 * Vector a[k] holds the quads of j[k], j[k+4], j[k+8], j[k+12], so that
 * the transpose leaves the lanes in order. Values are moved, never
 * computed: the same bits as the C loops' loads. Include only where
 * MS_VOLUME_HAVE_AVX512. */
#ifndef MS_VOLUME_RECORDS_AVX512_H
#define MS_VOLUME_RECORDS_AVX512_H

#include <immintrin.h>
#include <stddef.h>
#include <stdint.h>

/* The first min(rem, 16) lanes: a block of 16 that starts rem entries
 * before its loop's end (the entries beyond belong to another part or
 * lie past the arrays). */
__attribute__((target("avx512f,bmi2"), always_inline)) static inline __mmask16 ms_lanes_left(
    size_t rem)
{
    return (__mmask16)_bzhi_u32(0xffffu, rem < 16u ? (unsigned)rem : 16u);
}

/* ms_lanes_sum of a vector, in registers: the same tree order (lane l +
 * l + 8, then + 4, + 2, + 1), so the same bits; the store and sixteen
 * scalar reloads cost more than the sums. */
__attribute__((target("avx512f"), always_inline)) static inline float ms_lanes_sum16(__m512 a)
{
    __m256 t8 = _mm256_add_ps(_mm512_castps512_ps256(a),
                              _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(a), 1)));
    __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    __m128 t2 = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* (0+2, 1+3) */
    return _mm_cvtss_f32(_mm_add_ss(t2, _mm_shuffle_ps(t2, t2, 1)));
}

#define MS_RECORDS_QUAD(k) _mm_loadu_ps(b + 8 * (size_t)j[k])
#define MS_RECORDS_ROW(k)                                                                 \
    _mm512_insertf32x4(                                                                   \
        _mm512_insertf32x4(_mm512_insertf32x4(_mm512_castps128_ps512(MS_RECORDS_QUAD(k)), \
                                              MS_RECORDS_QUAD((k) + 4), 1),               \
                           MS_RECORDS_QUAD((k) + 8), 2),                                  \
        MS_RECORDS_QUAD((k) + 12), 3)
/* Floats b[8 j + 0..3] of the 16 records j[0..15], one float a vector. */
__attribute__((target("avx512f"), always_inline)) static inline void ms_load_quads(
    const float *b, const int *restrict j, __m512 *s, __m512 *u, __m512 *w, __m512 *t)
{
    const __m512 a0 = MS_RECORDS_ROW(0), a1 = MS_RECORDS_ROW(1), a2 = MS_RECORDS_ROW(2),
                 a3 = MS_RECORDS_ROW(3);
    const __m512 t0 = _mm512_unpacklo_ps(a0, a1), t1 = _mm512_unpackhi_ps(a0, a1);
    const __m512 t2 = _mm512_unpacklo_ps(a2, a3), t3 = _mm512_unpackhi_ps(a2, a3);
    *s = _mm512_shuffle_ps(t0, t2, 0x44);
    *u = _mm512_shuffle_ps(t0, t2, 0xee);
    *w = _mm512_shuffle_ps(t1, t3, 0x44);
    *t = _mm512_shuffle_ps(t1, t3, 0xee);
}
#undef MS_RECORDS_ROW
#undef MS_RECORDS_QUAD

/* The AVX-512 pair loops prefetch their streamed per-pair data (indices,
 * r^2, pair terms: 4-byte entries) this many entries ahead (dfsph.c says
 * how it was measured). Hints only: the same bits. */
enum { MS_PREFETCH_ENTRIES = 512 };

/* The 4-byte entry MS_PREFETCH_ENTRIES after p (as an integer: that
 * address may lie past the array, where a prefetch does nothing). */
__attribute__((target("avx512f"), always_inline)) static inline void ms_prefetch_ahead(
    const void *p)
{
    _mm_prefetch((const char *)((uintptr_t)p + MS_PREFETCH_ENTRIES * sizeof(float)), _MM_HINT_T0);
}

#endif
