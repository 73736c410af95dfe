/* The neighbour lists (paper 3.3: "an additional space dividing grid with
 * grid length h"): for each particle, its real neighbours within h (itself
 * included) from the 27 cells around its cell, and its wall and shape
 * images, appended to its part's lists in a fixed order. The instruction-
 * set filters and gathers (plain C, SSE2, AVX-512, picked once per volume
 * by ms_volume_pick_isa) give the same lists. Moved here from density.c,
 * which now only sums them (review).
 */
#include <string.h>

#include "volume/volume_internal.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

enum { LANES = MS_VOLUME_LANES };
/* The candidate run of the AVX-512 path (v->cand[part], cand_cap floats
 * per field): x | y | z of the candidates, then x | y | z of the real
 * neighbours the filter kept, in list order, for the image filter of a
 * particle near two or three walls (gather_image_avx512: loads, not
 * gathers); v->cand_idx[part]: the candidates' indices. */
enum { CAND_FIELDS = 6 };

/* Room for `more` entries plus a block of padding. */
static int reserve(ms_nlist *L, size_t more)
{
    size_t need = L->len + more + LANES;
    if (need <= L->cap)
        return 1;
    size_t cap = L->cap ? L->cap : 4096;
    while (cap < need)
        cap *= 2;
    int *idx = ms_alloc_array(cap, sizeof(int));
    float *r2 = ms_alloc_array(cap, sizeof(float));
    if (!idx || !r2) {
        ms_free(idx);
        ms_free(r2);
        return 0;
    }
    if (L->len) {
        memcpy(idx, L->idx, L->len * sizeof(int));
        memcpy(r2, L->r2, L->len * sizeof(float));
    }
    ms_free(L->idx);
    ms_free(L->r2);
    L->idx = idx;
    L->r2 = r2;
    L->cap = cap;
    return 1;
}

/* Room, once, for the lists to grow without allocating during the steps
 * (no allocation in any step after the first). Called by the
 * first density pass with the lengths it needed: the real lists get twice
 * that (measured on the shipped scenes over 400 frames: at most 1.25x the
 * first pass's, as the liquid moves and compresses), the image lists
 * twice theirs or the real list's length, whichever is more (an image run
 * is a filter of its particle's real run; measured: up to 3.3x the first
 * pass's where the liquid spreads along the walls, never more than the
 * real list), the candidate runs twice theirs. Layouts beyond that
 * (liquid compressed to twice its rest density) still grow, geometrically. */
int ms_volume_lists_headroom(ms_volume *v, int part)
{
    ms_nlist *L = &v->lists[part], *G = &v->ghosts[part];
    const size_t real = L->len, images = G->len > real / 2 ? 2 * G->len : real;
    if (!reserve(L, real) || !reserve(G, images - G->len))
        return 0;
    if (v->cand_cap[part]) { /* scratch of the cell in hand: nothing to keep */
        const size_t cap = 2 * v->cand_cap[part];
        ms_free(v->cand[part]);
        ms_free(v->cand_idx[part]);
        v->cand[part] = ms_alloc_array(CAND_FIELDS * cap, sizeof(float));
        v->cand_idx[part] = ms_alloc_array(cap, sizeof(int));
        v->cand_cap[part] = v->cand[part] && v->cand_idx[part] ? cap : 0;
        if (!v->cand_cap[part])
            return 0;
    }
    return 1;
}

/* Append (j | tag, r^2) for every j in the nine row ranges [lo[r], hi[r])
 * closer than h to q (the particle itself included), in order; returns the
 * number appended.
 * Three versions with the same result, chosen once per volume
 * (ms_volume_pick_isa): AVX-512 (compare into a mask, compress in
 * registers, store whole blocks), SSE2 (compare, movemask, append the set
 * bits) and plain C (branch-free append). The particle arrays and the list
 * are padded, so a block may read and write past the end. */
static size_t filter_rows_c(const ms_volume *v, const int *lo, const int *hi, const float q[3],
                            int tag, int *restrict out, float *restrict out2)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float h2 = v->K.h2;
    size_t n = 0;
    for (int r = 0; r < 9; ++r)
        for (int j = lo[r]; j < hi[r]; ++j) {
            float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
            float r2 = dx * dx + dy * dy + dz * dz;
            out[n] = j | tag;
            out2[n] = r2;
            n += r2 < h2;
        }
    return n;
}

#if defined(__SSE2__)
static size_t filter_rows_sse2(const ms_volume *v, const int *lo, const int *hi, const float q[3],
                               int tag, int *restrict out, float *restrict out2)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const __m128 qx = _mm_set1_ps(q[0]), qy = _mm_set1_ps(q[1]), qz = _mm_set1_ps(q[2]);
    const __m128 hh = _mm_set1_ps(v->K.h2);
    size_t n = 0;
    for (int r = 0; r < 9; ++r)
        for (int j = lo[r]; j < hi[r]; j += 4) {
            __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(x + j));
            __m128 dy = _mm_sub_ps(qy, _mm_loadu_ps(y + j));
            __m128 dz = _mm_sub_ps(qz, _mm_loadu_ps(z + j));
            __m128 r2 =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
            unsigned m = (unsigned)_mm_movemask_ps(_mm_cmplt_ps(r2, hh));
            if (hi[r] - j < 4)
                m &= (1u << (hi[r] - j)) - 1u;
            if (m) {
                float t[4];
                _mm_storeu_ps(t, r2);
                while (m) {
                    int b = __builtin_ctz(m);
                    out[n] = (j + b) | tag;
                    out2[n] = t[b];
                    n++;
                    m &= m - 1u;
                }
            }
        }
    return n;
}
#endif

#if MS_VOLUME_HAVE_AVX512
/* A block of up to 16 candidates at x, y, z (lanes outside valid read 0
 * and are ignored): their positions, their r^2 to q, and which of them
 * lie within h (r^2 < h^2). */
typedef struct near_block {
    __m512 x, y, z, r2;
    __mmask16 keep;
} near_block;

__attribute__((target("avx512f"), always_inline)) static inline near_block near_of(
    __m512 qx, __m512 qy, __m512 qz, __m512 hh, const float *x, const float *y, const float *z,
    __mmask16 valid)
{
    near_block b;
    b.x = _mm512_maskz_loadu_ps(valid, x);
    b.y = _mm512_maskz_loadu_ps(valid, y);
    b.z = _mm512_maskz_loadu_ps(valid, z);
    __m512 dx = _mm512_sub_ps(qx, b.x);
    __m512 dy = _mm512_sub_ps(qy, b.y);
    __m512 dz = _mm512_sub_ps(qz, b.z);
    b.r2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)),
                         _mm512_mul_ps(dz, dz));
    b.keep = _mm512_mask_cmp_ps_mask(valid, b.r2, hh, _CMP_LT_OQ);
    return b;
}

/* The ids (id's lanes) of a block's candidates within h and their r^2,
 * stored as whole compressed blocks (the lists have slack: a compress to
 * memory is microcoded and slow). Returns how many were within h. */
__attribute__((target("avx512f,popcnt"), always_inline)) static inline size_t keep_block(
    const near_block *b, __m512i id, int *out, float *out2)
{
    _mm512_storeu_si512((void *)out, _mm512_maskz_compress_epi32(b->keep, id));
    _mm512_storeu_ps(out2, _mm512_maskz_compress_ps(b->keep, b->r2));
    return (size_t)_mm_popcnt_u32(_cvtmask16_u32(b->keep));
}

/* One block of up to 16 candidates: near_of, then keep_block. */
__attribute__((target("avx512f,bmi,bmi2,popcnt"), always_inline)) static inline size_t filter_block(
    __m512 qx, __m512 qy, __m512 qz, __m512 hh, const float *x, const float *y, const float *z,
    __mmask16 valid, __m512i id, int *out, float *out2)
{
    const near_block b = near_of(qx, qy, qz, hh, x, y, z, valid);
    return keep_block(&b, id, out, out2);
}

__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static size_t filter_rows_avx512(
    const ms_volume *v, const int *lo, const int *hi, const float q[3], int tag, int *restrict out,
    float *restrict out2)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 hh = _mm512_set1_ps(v->K.h2);
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512i sixteen = _mm512_set1_epi32(16);
    size_t n = 0;
    for (int r = 0; r < 9; ++r) {
        __m512i id = _mm512_add_epi32(_mm512_set1_epi32(lo[r] | tag), iota);
        for (int j = lo[r]; j < hi[r]; j += 16) {
            unsigned rem = (unsigned)(hi[r] - j);
            __mmask16 valid = ms_lanes_left(rem);
            n += filter_block(qx, qy, qz, hh, x + j, y + j, z + j, valid, id, out + n, out2 + n);
            id = _mm512_add_epi32(id, sixteen);
        }
    }
    return n;
}

/* filter_rows_avx512 over candidates already copied into one run
 * (cand_of): the same list, without a short loop per row. With pos, also
 * the kept neighbours' x | y | z (stride apart, in list order), for
 * gather_image_avx512; inlined into both callers, so pos is a constant
 * in each and the test leaves the loop. */
__attribute__((target("avx512f,bmi,bmi2,popcnt"), always_inline)) static inline size_t
filter_run_body_avx512(const float *restrict cx, const int *restrict cidx, size_t nc, size_t stride,
                       const float q[3], float h2, int *restrict out, float *restrict out2,
                       float *restrict pos)
{
    const float *restrict cy = cx + stride, *restrict cz = cx + 2 * stride;
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 hh = _mm512_set1_ps(h2);
    size_t n = 0;
    for (size_t j = 0; j < nc; j += 16) {
        size_t rem = nc - j;
        __mmask16 valid = ms_lanes_left(rem);
        __m512i id = _mm512_maskz_loadu_epi32(valid, cidx + j);
        const near_block b = near_of(qx, qy, qz, hh, cx + j, cy + j, cz + j, valid);
        if (pos) {
            _mm512_storeu_ps(pos + n, _mm512_maskz_compress_ps(b.keep, b.x));
            _mm512_storeu_ps(pos + stride + n, _mm512_maskz_compress_ps(b.keep, b.y));
            _mm512_storeu_ps(pos + 2 * stride + n, _mm512_maskz_compress_ps(b.keep, b.z));
        }
        n += keep_block(&b, id, out + n, out2 + n);
    }
    return n;
}

__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static size_t filter_run_avx512(
    const float *restrict cx, const int *restrict cidx, size_t nc, size_t stride, const float q[3],
    float h2, int *restrict out, float *restrict out2)
{
    return filter_run_body_avx512(cx, cidx, nc, stride, q, h2, out, out2, NULL);
}

/* filter_run_avx512 for a particle near one wall, and in the same pass
 * the run of its wall image (x, y, z; tag) into iout, iout2 (16 entries of
 * slack): the image's neighbours are those of the particle's real
 * neighbours within h of the image (gather_image), in list order, and
 * here they are the candidates the real filter keeps in each block that
 * are also within h of the image, compressed in candidate order: the same
 * entries in the same order, with the same r^2 (the same positions, the
 * same operations), with no stored positions loaded back right after
 * their stores. *nimg gets the image run's length. */
__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static size_t filter_run_image_avx512(
    const float *restrict cx, const int *restrict cidx, size_t nc, size_t stride, const float q[3],
    float h2, int *restrict out, float *restrict out2, const float img[3], int tag,
    int *restrict iout, float *restrict iout2, size_t *nimg)
{
    const float *restrict cy = cx + stride, *restrict cz = cx + 2 * stride;
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 ix = _mm512_set1_ps(img[0]), iy = _mm512_set1_ps(img[1]),
                 iz = _mm512_set1_ps(img[2]);
    const __m512 hh = _mm512_set1_ps(h2);
    const __m512i vtag = _mm512_set1_epi32(tag);
    size_t n = 0, ni = 0;
    for (size_t j = 0; j < nc; j += 16) {
        size_t rem = nc - j;
        __mmask16 valid = ms_lanes_left(rem);
        __m512i id = _mm512_maskz_loadu_epi32(valid, cidx + j);
        const near_block b = near_of(qx, qy, qz, hh, cx + j, cy + j, cz + j, valid);
        n += keep_block(&b, id, out + n, out2 + n);
        __m512 ex = _mm512_sub_ps(ix, b.x), ey = _mm512_sub_ps(iy, b.y),
               ez = _mm512_sub_ps(iz, b.z);
        __m512 g2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(ex, ex), _mm512_mul_ps(ey, ey)),
                                  _mm512_mul_ps(ez, ez));
        __mmask16 hit = _mm512_mask_cmp_ps_mask(b.keep, g2, hh, _CMP_LT_OQ);
        _mm512_storeu_si512((void *)(iout + ni),
                            _mm512_maskz_compress_epi32(hit, _mm512_or_si512(id, vtag)));
        _mm512_storeu_ps(iout2 + ni, _mm512_maskz_compress_ps(hit, g2));
        ni += (size_t)_mm_popcnt_u32(_cvtmask16_u32(hit));
    }
    *nimg = ni;
    return n;
}

/* filter_run_avx512 that also stores the kept neighbours' positions at
 * pos (filter_run_body_avx512). */
__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static size_t filter_run_pos_avx512(
    const float *restrict cx, const int *restrict cidx, size_t nc, size_t stride, const float q[3],
    float h2, int *restrict out, float *restrict out2, float *restrict pos)
{
    return filter_run_body_avx512(cx, cidx, nc, stride, q, h2, out, out2, pos);
}

/* gather_image in AVX-512 for a particle near two or three walls: its
 * real list (n entries from idx) filtered again at the image q, the
 * neighbours' positions loaded from the copy the filter kept (pos: x | y
 * | z, stride apart, in list order); the same r^2, the same order, so the
 * same run as gather_image. Per image it filters the kept neighbours,
 * where filter_run_image_avx512 filters every candidate block once more:
 * with three or seven images that was the slower (fig1). */
__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static int gather_image_avx512(
    const ms_volume *v, ms_nlist *L, const float q[3], int tag, const int *restrict idx, int n,
    const float *restrict pos, size_t stride)
{
    if (!reserve(L, (size_t)n + 2 * LANES))
        return -1;
    const float *restrict px = pos, *restrict py = pos + stride, *restrict pz = pos + 2 * stride;
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 hh = _mm512_set1_ps(v->K.h2);
    const __m512i vtag = _mm512_set1_epi32(tag);
    int *restrict out = L->idx + L->len;
    float *restrict out2 = L->r2 + L->len;
    size_t m = 0;
    for (int k = 0; k < n; k += 16) {
        unsigned rem = (unsigned)(n - k);
        __mmask16 valid = ms_lanes_left(rem);
        /* the list has a block of slack: a whole block is valid memory */
        __m512i j = _mm512_loadu_si512((const void *)(idx + k));
        __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(valid, px + k));
        __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(valid, py + k));
        __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(valid, pz + k));
        __m512 r2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)),
                                  _mm512_mul_ps(dz, dz));
        __mmask16 hit = _mm512_mask_cmp_ps_mask(valid, r2, hh, _CMP_LT_OQ);
        _mm512_storeu_si512((void *)(out + m),
                            _mm512_maskz_compress_epi32(hit, _mm512_or_si512(j, vtag)));
        _mm512_storeu_ps(out2 + m, _mm512_maskz_compress_ps(hit, r2));
        m += (size_t)_mm_popcnt_u32(_cvtmask16_u32(hit));
    }
    L->len += m;
    return (int)m;
}
#endif

typedef size_t filter_fn(const ms_volume *v, const int *lo, const int *hi, const float q[3],
                         int tag, int *restrict out, float *restrict out2);

static filter_fn *filter_of(int isa)
{
#if MS_VOLUME_HAVE_AVX512
    if (isa == MS_VOLUME_ISA_AVX512)
        return filter_rows_avx512;
#endif
#if defined(__SSE2__)
    if (isa >= MS_VOLUME_ISA_SSE2)
        return filter_rows_sse2;
#endif
    (void)isa;
    return filter_rows_c;
}

/* The nine row ranges (x-1 .. x+1) of the 27 cells around cell c, and
 * how many candidates they hold. */

static void rows_of(const ms_volume *v, long c, ms_rows *r)
{
    const int *restrict start = v->cell_start;
    const long sx = v->gx, sxy = (long)v->gx * v->gy;
    static const signed char oz[9] = {-1, -1, -1, 0, 0, 0, 1, 1, 1};
    static const signed char oy[9] = {-1, 0, 1, -1, 0, 1, -1, 0, 1};
    r->cell = c;
    r->cand = 0;
    for (int k = 0; k < 9; ++k) {
        const long row = c + oz[k] * sxy + oy[k] * sx;
        r->lo[k] = start[row - 1];
        r->hi[k] = start[row + 2];
        r->cand += (size_t)(r->hi[k] - r->lo[k]);
    }
}

/* Copy the candidates of the rows r (positions and indices, in row
 * order) into part's run; its length, or -1 if the run could not grow.
 * The particles of a cell share it: each then filters one run (about 14
 * full blocks; 5-6 since the pruning below) instead of nine short rows
 * (18 blocks, half of them part-empty, and a mispredicted loop exit per
 * row).
 * Only the candidates that may lie within h of one
 * of the cell's particles are copied: box [lo, hi] holds the positions
 * of the particles that share the run, and a candidate whose per-axis
 * gaps to it (g = max(lo - x, x - hi, 0)) give g2 = (gx^2 + gy^2) + gz^2
 * >= h^2 is left out. The filter's r^2 of such a candidate is >= g2 for
 * every particle in the box, computed in float: rounding is monotonic,
 * so |fl(p - x)| >= fl(lo - x) (or fl(x - hi)) for lo <= p <= hi, and
 * the filter squares and sums in the same order; it would not have kept
 * it. So the lists are the same, entry for entry (same bytes), from
 * fewer candidates: the box of a cell's particles is smaller than the
 * cell, and the 27 cells reach beyond h of it (at the corners). A NaN
 * gap keeps the candidate (the filter decides). */
#if MS_VOLUME_HAVE_AVX512
__attribute__((target("avx512f,bmi,bmi2,popcnt"))) static long cand_of(ms_volume *v, int part,
                                                                       const ms_rows *r,
                                                                       const float lo[3],
                                                                       const float hi[3])
{
    size_t need = r->cand + LANES;
    if (need > v->cand_cap[part]) {
        size_t cap = v->cand_cap[part] ? v->cand_cap[part] : 1024;
        while (cap < need)
            cap *= 2;
        ms_free(v->cand[part]);
        ms_free(v->cand_idx[part]);
        v->cand[part] = ms_alloc_array(CAND_FIELDS * cap, sizeof(float));
        v->cand_idx[part] = ms_alloc_array(cap, sizeof(int));
        v->cand_cap[part] = v->cand[part] && v->cand_idx[part] ? cap : 0;
        if (!v->cand_cap[part])
            return -1;
    }
    const size_t stride = v->cand_cap[part];
    float *restrict cx = v->cand[part], *restrict cy = cx + stride, *restrict cz = cx + 2 * stride;
    int *restrict ci = v->cand_idx[part];
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512 zero = _mm512_setzero_ps(), hh = _mm512_set1_ps(v->K.h2);
    const __m512 lox = _mm512_set1_ps(lo[0]), loy = _mm512_set1_ps(lo[1]),
                 loz = _mm512_set1_ps(lo[2]);
    const __m512 hix = _mm512_set1_ps(hi[0]), hiy = _mm512_set1_ps(hi[1]),
                 hiz = _mm512_set1_ps(hi[2]);
    size_t n = 0;
    for (int k = 0; k < 9; ++k) {
        const int rlo = r->lo[k], rhi = r->hi[k];
        for (int j = rlo; j < rhi; j += 16) {
            unsigned rem = (unsigned)(rhi - j);
            __mmask16 m = ms_lanes_left(rem);
            const __m512 xj = _mm512_maskz_loadu_ps(m, v->x + j);
            const __m512 yj = _mm512_maskz_loadu_ps(m, v->y + j);
            const __m512 zj = _mm512_maskz_loadu_ps(m, v->z + j);
            /* max(0, t): a NaN t is the second operand and stays NaN */
            const __m512 gx =
                _mm512_max_ps(zero, _mm512_max_ps(_mm512_sub_ps(lox, xj), _mm512_sub_ps(xj, hix)));
            const __m512 gy =
                _mm512_max_ps(zero, _mm512_max_ps(_mm512_sub_ps(loy, yj), _mm512_sub_ps(yj, hiy)));
            const __m512 gz =
                _mm512_max_ps(zero, _mm512_max_ps(_mm512_sub_ps(loz, zj), _mm512_sub_ps(zj, hiz)));
            const __m512 g2 = _mm512_add_ps(
                _mm512_add_ps(_mm512_mul_ps(gx, gx), _mm512_mul_ps(gy, gy)), _mm512_mul_ps(gz, gz));
            const __mmask16 keep = _mm512_mask_cmp_ps_mask(m, g2, hh, _CMP_NGE_UQ);
            const __m512i id = _mm512_add_epi32(_mm512_set1_epi32(j), iota);
            _mm512_storeu_ps(cx + n, _mm512_maskz_compress_ps(keep, xj));
            _mm512_storeu_ps(cy + n, _mm512_maskz_compress_ps(keep, yj));
            _mm512_storeu_ps(cz + n, _mm512_maskz_compress_ps(keep, zj));
            _mm512_storeu_si512((void *)(ci + n), _mm512_maskz_compress_epi32(keep, id));
            n += (size_t)_mm_popcnt_u32(_cvtmask16_u32(keep));
        }
    }
    return (long)n;
}

/* The box of the positions of the particles from i on that share cell c
 * (a run of the sorted arrays: those that will use c's candidates). */
static void cell_box(const ms_volume *v, int i, long c, float lo[3], float hi[3])
{
    lo[0] = hi[0] = v->x[i];
    lo[1] = hi[1] = v->y[i];
    lo[2] = hi[2] = v->z[i];
    /* comparisons, not fminf (a call here): a NaN position is passed over,
     * a NaN first one makes the box NaN and every candidate kept */
    for (int k = i + 1; k < v->n && v->cell[k] == c; ++k) {
        const float q[3] = {v->x[k], v->y[k], v->z[k]};
        for (int a = 0; a < 3; ++a) {
            lo[a] = q[a] < lo[a] ? q[a] : lo[a];
            hi[a] = q[a] > hi[a] ? q[a] : hi[a];
        }
    }
}
#endif

/* Append to L every particle within h of q from the rows r. Returns the
 * neighbours appended, -1 if the list could not grow. */
static int gather(const ms_volume *v, ms_nlist *L, const float q[3], const ms_rows *r, int tag)
{
    if (!reserve(L, r->cand + 2 * LANES))
        return -1;
    size_t n = filter_of(v->isa)(v, r->lo, r->hi, q, tag, L->idx + L->len, L->r2 + L->len);
    L->len += n;
    return (int)n;
}

/* The wall image q of particle p (p reflected across the domain walls of
 * the image bits in tag) has as neighbours a subset of p's: for j inside
 * the domain, |q - x_j|^2 = |p - x_j|^2 + 4 sum_k d_k e_k (d_k, e_k the
 * distances of p and x_j from wall k, both >= 0). So the image list is
 * p's real list (n entries from idx) filtered again at q, in its order:
 * no search of the cells around q. Plain C, for the C and SSE2 paths
 * (AVX-512: filter_run_image_avx512 and gather_image_avx512, the same
 * runs). */
static int gather_image(const ms_volume *v, ms_nlist *L, const float q[3], int tag,
                        const int *restrict idx, int n)
{
    if (!reserve(L, (size_t)n + 2 * LANES))
        return -1;
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float h2 = v->K.h2;
    int *restrict out = L->idx + L->len;
    float *restrict out2 = L->r2 + L->len;
    size_t m = 0;
    for (int k = 0; k < n; ++k) {
        const int j = idx[k];
        float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
        float r2 = dx * dx + dy * dy + dz * dz;
        out[m] = j | tag;
        out2[m] = r2;
        m += r2 < h2;
    }
    L->len += m;
    return (int)m;
}

/* The images of particle i's neighbours across the tangent plane of its
 * nearest shape collider (point c = p - d n, normal n): the particles j on
 * the liquid side of the plane within h of p's mirror image q = p - 2 d n.
 * Rare (particles at a shape): plain C. */
static int gather_plane(const ms_volume *v, ms_nlist *L, const float p[3], int i)
{
    const float d = v->c_d[i], n[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
    const float c[3] = {p[0] - d * n[0], p[1] - d * n[1], p[2] - d * n[2]};
    const float q[3] = {p[0] - 2.0f * d * n[0], p[1] - 2.0f * d * n[1], p[2] - 2.0f * d * n[2]};
    const int *restrict start = v->cell_start;
    const long sx = v->gx, sxy = (long)v->gx * v->gy;
    const long cq = ms_volume_cell_of(v, q[0], q[1], q[2]);
    const float h2 = v->K.h2;
    const int tag = (int)(MS_VOLUME_IMAGE_SHAPE << MS_VOLUME_IMAGE_SHIFT);
    size_t cand = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy) {
            const long row = cq + dz * sxy + dy * sx;
            cand += (size_t)(start[row + 2] - start[row - 1]);
        }
    if (!reserve(L, cand + 2 * LANES))
        return -1;
    int n_in = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy) {
            const long row = cq + dz * sxy + dy * sx;
            for (int j = start[row - 1]; j < start[row + 2]; ++j) {
                float dx = q[0] - v->x[j], dyy = q[1] - v->y[j], dzz = q[2] - v->z[j];
                float r2 = dx * dx + dyy * dyy + dzz * dzz;
                float side =
                    (v->x[j] - c[0]) * n[0] + (v->y[j] - c[1]) * n[1] + (v->z[j] - c[2]) * n[2];
                if (r2 < h2 && side > 0.0f) {
                    L->idx[L->len] = j | tag;
                    L->r2[L->len] = r2;
                    L->len++;
                    n_in++;
                }
            }
        }
    return n_in;
}

/* Pad a run that began at `begin` to a multiple of the lanes (the list
 * has a block of slack: a whole block is written). */
static void pad(ms_nlist *L, size_t begin, int index, float h2)
{
    if (L->len == begin)
        return; /* an empty run (the list may not even exist yet) */
    size_t end = begin + (L->len - begin + LANES - 1) / LANES * LANES;
    int *restrict idx = L->idx + L->len;
    float *restrict r2 = L->r2 + L->len;
#if defined(__SSE2__)
    const __m128i vi = _mm_set1_epi32(index);
    const __m128 vr = _mm_set1_ps(h2);
    for (int l = 0; l < LANES; l += 4) { /* the compiler keeps this scalar */
        _mm_storeu_si128((__m128i *)(void *)(idx + l), vi);
        _mm_storeu_ps(r2 + l, vr);
    }
#else
    for (int l = 0; l < LANES; ++l) {
        idx[l] = index;
        r2[l] = h2;
    }
#endif
    L->len = end;
}

#if MS_VOLUME_HAVE_AVX512
/* pad() of the real list in AVX-512: the slots [len, end) only, by two
 * masked stores, where pad writes a whole block in eight 16-byte stores
 * (two whole 64-byte stores were 1.049x slower on a Zen 4 CPU). The image
 * list keeps pad(): this gained nothing there. */
__attribute__((target("avx512f,bmi2"))) static void pad_avx512(ms_nlist *L, size_t begin, int index,
                                                               float h2)
{
    const size_t end = begin + (L->len - begin + LANES - 1) / LANES * LANES;
    const __mmask16 m = (__mmask16)_bzhi_u32(0xffffu, (unsigned)(end - L->len));
    _mm512_mask_storeu_epi32(L->idx + L->len, m, _mm512_set1_epi32(index));
    _mm512_mask_storeu_ps(L->r2 + L->len, m, _mm512_set1_ps(h2));
    L->len = end;
}
#endif

/* Image f of p: p reflected across the walls of the bits of f. */
static inline void image_of(const float p[3], unsigned f, const float wall[3], float q[3])
{
    for (int k = 0; k < 3; ++k)
        q[k] = f & (1u << k) ? 2.0f * wall[k] - p[k] : p[k];
}

#if MS_VOLUME_HAVE_AVX512
/* Particle i's real list (appended to the part's list, unpadded) and, near
 * a wall, its wall images' runs (appended to the image list in the fixed
 * order of the images, as the loop of ms_volume_neighbours_of): near one
 * wall in the same pass (filter_run_image_avx512), near two or three
 * from the kept neighbours (gather_image_avx512; measured on fig1, whose
 * shallow tank has a sixth of its particles near two walls: 0.99 of a
 * frame against filtering every candidate block once an image). The
 * number of image entries, or -1 if a list could not grow. */
static int lists_avx512(ms_volume *v, int part, long ncand, const float p[3], unsigned near,
                        const float wall[3])
{
    ms_nlist *L = &v->lists[part], *G = &v->ghosts[part];
    const size_t stride = v->cand_cap[part];
    const float h2 = v->K.h2;
    if (!reserve(L, (size_t)ncand + 2 * LANES))
        return -1;
    if (!near) {
        L->len += filter_run_avx512(v->cand[part], v->cand_idx[part], (size_t)ncand, stride, p, h2,
                                    L->idx + L->len, L->r2 + L->len);
        return 0;
    }
    if (!reserve(G, (size_t)ncand + 2 * LANES))
        return -1;
    if (near & (near - 1)) { /* two or three walls: three or seven images */
        const size_t begin = L->len;
        float *pos = v->cand[part] + 3 * stride;
        const int nreal =
            (int)filter_run_pos_avx512(v->cand[part], v->cand_idx[part], (size_t)ncand, stride, p,
                                       h2, L->idx + begin, L->r2 + begin, pos);
        L->len += (size_t)nreal;
        int got = 0;
        for (unsigned f = 1; f < 8; ++f) { /* the wall images, in a fixed order */
            if ((f & near) != f)
                continue;
            float q[3];
            image_of(p, f, wall, q);
            const int k = gather_image_avx512(v, G, q, (int)(f << MS_VOLUME_IMAGE_SHIFT),
                                              L->idx + begin, nreal, pos, stride);
            if (k < 0)
                return -1;
            got += k;
        }
        return got;
    }
    float q[3]; /* one wall: its image's run straight into the image list */
    image_of(p, near, wall, q);
    size_t got = 0;
    L->len += filter_run_image_avx512(v->cand[part], v->cand_idx[part], (size_t)ncand, stride, p,
                                      h2, L->idx + L->len, L->r2 + L->len, q,
                                      (int)(near << MS_VOLUME_IMAGE_SHIFT), G->idx + G->len,
                                      G->r2 + G->len, &got);
    G->len += got;
    return (int)got;
}
#endif

/* Particle i's runs (see volume_internal.h): its real neighbours from the rows
 * of its cell (own, shared by the particles of a cell, recomputed when the
 * cell changes; *ncand the candidates copied for the AVX-512 path) and its
 * images; sets nl_begin, nl_count, gl_begin, gl_count. 0, or -1 if a list
 * could not grow. */
int ms_volume_neighbours_of(ms_volume *v, int part, int i, ms_rows *own, long *ncand)
{
    ms_nlist *L = &v->lists[part], *G = &v->ghosts[part];
    const float h2 = v->K.h2;
#if MS_VOLUME_HAVE_AVX512
    const int run = v->isa == MS_VOLUME_ISA_AVX512;
#endif
    const float p[3] = {v->x[i], v->y[i], v->z[i]};
    const size_t begin = L->len, gbegin = G->len;
    if (v->cell[i] != own->cell) { /* the particles of a cell share their rows */
        rows_of(v, v->cell[i], own);
#if MS_VOLUME_HAVE_AVX512
        if (run) {
            float lo[3], hi[3];
            cell_box(v, i, own->cell, lo, hi);
            *ncand = cand_of(v, part, own, lo, hi);
        }
#endif
        if (*ncand < 0) {
            return -1;
        }
    }
    float wall[3];
    const unsigned near = ms_volume_walls_near(v, p[0], p[1], p[2], wall);
    int nreal, nghost = 0; /* the particle itself included in nreal */
#if MS_VOLUME_HAVE_AVX512
    if (run) {
        nghost = lists_avx512(v, part, *ncand, p, near, wall);
        if (nghost < 0)
            return -1;
        nreal = (int)(L->len - begin);
    } else
#endif
    {
        nreal = gather(v, L, p, own, 0);
        if (nreal < 0)
            return -1;
    }
#if MS_VOLUME_HAVE_AVX512
    if (run)
        pad_avx512(L, begin, i, h2);
    else
#endif
        pad(L, begin, i, h2);
#if MS_VOLUME_HAVE_AVX512
    if (!run)
#endif
        for (unsigned f = 1; f < 8; ++f) { /* the wall images, in a fixed order */
            if ((f & near) != f)
                continue;
            float q[3];
            image_of(p, f, wall, q);
            const int got =
                gather_image(v, G, q, (int)(f << MS_VOLUME_IMAGE_SHIFT), L->idx + begin, nreal);
            if (got < 0)
                return -1;
            nghost += got;
        }
    if (v->c_d[i] < v->K.h) {
        int got = gather_plane(v, G, p, i);
        if (got < 0) {
            return -1;
        }
        nghost += got;
    }
    pad(G, gbegin, i, h2);
    v->nl_begin[i] = (int)begin;
    v->nl_count[i] = nreal;
    v->gl_begin[i] = (int)gbegin;
    v->gl_count[i] = nghost;
    return 0;
}
