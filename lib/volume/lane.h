/* The lane type of the SPH passes: MS_LANES (16) floats handled as one
 * value, so each pass is written once (passes.h) and compiled once per
 * instruction set (passes_<isa>.c, each with its own flags). Every
 * implementation gives the same bits: IEEE add, sub, mul, div and sqrt
 * lane by lane, no fused multiply-add (lib/volume is built with
 * -ffp-contract=off and the headers call no FMA), compares and selects
 * that move values, and one reduction tree for the sum of the lanes,
 * lane l + lane l+8, then + 4, + 2, + 1 (ms_lane_sum).
 *
 * MS_LANE_ISA picks the implementation before this header is included
 * (unset: plain C):
 *   MS_LANE_ISA_C       lane_c.h       a struct of 16 floats
 *   MS_LANE_ISA_SSE2    lane_sse2.h    4 x __m128
 *   MS_LANE_ISA_AVX2    lane_avx2.h    2 x __m256 (AVX2, no FMA)
 *   MS_LANE_ISA_AVX512  lane_avx512.h  1 x __m512 (F, DQ, BMI2)
 *   MS_LANE_ISA_NEON    lane_neon.h    4 x float32x4_t (aarch64)
 *
 * The operations (a, b lanes; m a mask of lanes):
 *   ms_lane_set1(s), ms_lane_zero(), ms_lane_load(p), ms_lane_store(p, a)
 *   ms_lane_load_n(p, n), ms_lane_store_n(p, a, n): the first n < 16 lanes
 *       only (the rest read as 0, never written): a loop's tail
 *   ms_lane_add, _sub, _mul, _div, _sqrt, _max (a > b ? a : b)
 *   ms_lane_lt, _le, _gt (ordered compares: false with a NaN) -> mask
 *   ms_lane_select(m, a, b) (m ? a : b), ms_lane_count(m) (lanes set)
 *   ms_lane_sum(a) (the tree above), ms_lane_max_of(a) (largest lane)
 *   ms_lane_neg(a) (a sign flip: -(+0) = -0, not 0 - a)
 *   ms_lane_test_bit(p, bit): the lanes l with p[l] & bit (16 int32)
 *   ms_lane_records8(pk, j, o0..o7): field f of the 8-float record
 *       pk[8 j[l] + f] into lane l of o_f (the volume's packed copy)
 *   ms_lane_records4(b, j, o0..o3): b[8 j[l] + f], f < 4 (half records)
 *   ms_lane_gather(b, j): b[j[l]] into lane l
 *   ms_lane_prefetch(p): a hint, nothing on the plain-C path
 * Values are moved by the loads and transposes, never computed.
 */
#ifndef MS_VOLUME_LANE_H
#define MS_VOLUME_LANE_H

#define MS_LANE_ISA_C 0
#define MS_LANE_ISA_SSE2 1
#define MS_LANE_ISA_AVX2 2
#define MS_LANE_ISA_AVX512 3
#define MS_LANE_ISA_NEON 4

#ifndef MS_LANE_ISA
#define MS_LANE_ISA MS_LANE_ISA_C
#endif

#define MS_LANES 16

/* The lane operations are inlined wherever they are used: a call would
 * pass the lanes through memory. */
#if defined(__GNUC__)
#define MS_LANE_FN static inline __attribute__((always_inline))
#else
#define MS_LANE_FN static inline
#endif

/* The instruction sets this target builds (passes_<isa>.c): SSE2, AVX2
 * and AVX-512 on x86-64 with any compiler, NEON on aarch64. */
#if defined(__x86_64__)
#define MS_VOLUME_LANES_X86 1
#else
#define MS_VOLUME_LANES_X86 0
#endif
#if defined(__aarch64__)
#define MS_VOLUME_LANES_NEON 1
#else
#define MS_VOLUME_LANES_NEON 0
#endif

#if MS_LANE_ISA == MS_LANE_ISA_C
#include "volume/lane_c.h"
#elif MS_LANE_ISA == MS_LANE_ISA_SSE2
#include "volume/lane_sse2.h"
#elif MS_LANE_ISA == MS_LANE_ISA_AVX2
#include "volume/lane_avx2.h"
#elif MS_LANE_ISA == MS_LANE_ISA_AVX512
#include "volume/lane_avx512.h"
#elif MS_LANE_ISA == MS_LANE_ISA_NEON
#include "volume/lane_neon.h"
#else
#error "MS_LANE_ISA: unknown instruction set"
#endif

#endif
