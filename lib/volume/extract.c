/* Free-surface extraction (paper 3.3.2): the liquid's 2.5D height field.
 *
 * Eqs. 16, 17: the potential of spheres of iso-radius R = h around the
 * particles,
 *     phi(x) = sum_i sqrt(1 - r_i^2 / R^2),   r_i = |x - x_i| < R,
 * and the height of a column is the topmost z where phi reaches the
 * iso-level T. "Just surface particles and their neighbours contribute":
 * surface particles are those with fewer than 3/4 of the neighbours of a
 * particle inside the liquid (the neighbour count of the density pass);
 * they and every particle within h of one are the spheres. T is the phi of
 * a still cubic lattice at half a spacing above its top layer (averaged
 * over where the column lies between particles), so a flat liquid's height
 * is its volume over its area. The domain's side walls and its floor
 * mirror the spheres (a wall is a collider, the liquid goes on in its
 * image), so the field does not sag at the walls, and a film on the floor
 * thinner than two layers, whose own spheres never reach T (a monolayer
 * of a lattice gives phi = 7.3 against T = 10.0), shows as the puddle it
 * is instead of vanishing: a glass emptied onto the floor left nothing to
 * see.
 *
 * Eq. 18, adaptive smoothing. The paper: "If E_kin exceeds a defined
 * threshold, no smoothing occurs. Below this threshold, the number of
 * smoothing steps is increased as E_kin increases until the maximum number
 * of smoothing steps is reached. Thus, still liquids occur to be flat and
 * turbulent liquids remain detailed." Read literally the middle sentence
 * gives a still liquid (E_kin = 0) no smoothing, against the last
 * sentence; what it means, and what is done here, is the opposite ramp:
 *     steps = smooth_steps * (1 - e / smooth_energy)   for e < smooth_energy,
 *     steps = 0                                        above,
 * with e = E_kin / total mass (J/kg, so the threshold does not depend on
 * the particle count), E_kin taken about the mean velocity (flow_energy). A fractional step blends one more pass in, so the
 * field does not jump as e crosses an integer step. One pass is a 3 x 3
 * binomial filter over the cells that hold liquid (dry cells stay 0 and
 * do not pull the shore down); passes update the field in place row by
 * row from a padded copy, so each reads the previous pass only.
 *
 * Two phases (extract.h): A marks the particles over the neighbour lists
 * and snapshots what the columns need; B, a pure function of the snapshot,
 * bins, searches the columns and smooths, on any thread (lib/sim runs it
 * on the surface thread, Fig. 8). B's column search comes in two forms:
 * the band search (columns_band, the default)
 * and the reference (columns_reference, 663cc3c's bytes), kept to measure
 * the first against.
 */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "volume/extract.h"
#include "volume/volume_internal.h"

/* Column phi of a still lattice at half a spacing above the top layer. */
float ms_volume_iso_level(const ms_volume *v)
{
    const double s = v->desc.spacing, R = v->K.h;
    const int r = (int)ceil(R / s) + 1;
    double total = 0.0;
    const int sub = 4;
    for (int oy = 0; oy < sub; ++oy)
        for (int ox = 0; ox < sub; ++ox) {
            double px = s * ox / sub, py = s * oy / sub;
            for (int k = 0; k <= r; ++k)
                for (int j = -r; j <= r; ++j)
                    for (int i = -r; i <= r; ++i) {
                        double dx = i * s - px, dy = j * s - py, dz = (k + 0.5) * s;
                        double q = 1.0 - (dx * dx + dy * dy + dz * dz) / (R * R);
                        if (q > 0.0)
                            total += sqrt(q);
                    }
        }
    return (float)(total / (sub * sub));
}

/* fminf(fmaxf(v, lo), hi) without the library calls (NaN gives lo, as
 * fmaxf's does) */
static inline float clampf(float v, float lo, float hi)
{
    v = v > lo ? v : lo;
    return v < hi ? v : hi;
}

static ms_status scratch(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return MS_OK;
    /* half again what is needed: a growing liquid reallocates a few times,
     * not every frame (steps allocate only at a new high-water mark) */
    size_t grown = need + need / 2;
    void *q = ms_alloc_array(grown, size);
    if (!q)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for height extraction");
    ms_free(*p);
    *p = q;
    *cap = grown;
    return MS_OK;
}

typedef struct mark_ctx {
    ms_volume *v;
    const float *low; /* per grid cell: the lowest surface particle in it and its neighbours */
    float reach;      /* h and a margin far above float round-off */
    const float *top; /* per x-y column of the grid: the highest particle in it and the 8 around */
    float band;       /* m: a particle this close below top is marked (TOP_BAND) */
} mark_ctx;

/* A particle within this many iso-radii plus a spacing below the highest
 * particle of its 3 x 3 grid columns is marked whatever its neighbour
 * count: the top layers of a liquid whatever its packing. The neighbour
 * count alone misses them in a settled, disordered liquid (its top layer
 * holds ~0.7 of an interior particle's neighbours, the surface test's
 * 0.75 is within the noise), which left columns with no sphere and a
 * hole to the floor. columns_verify below makes the field exact either
 * way; the band only keeps it from having to repair every column. */
#define TOP_BAND_R 1.0f

/* mark[i] = 1 surface particle, 2 within h of one, 0 neither: a gather
 * over the neighbour lists of the last density pass (real neighbours; the
 * wall images are the particle's own neighbours mirrored). A particle's
 * neighbours lie in the 27 cells around its cell (neighbours.c's rows), so
 * one more than h below the lowest surface particle of those (or with none
 * there: the deep liquid) has no surface neighbour and its list is not
 * read: the same marks. */
static void mark_part(void *ctxp, int part, int b, int e)
{
    ms_volume *v = ((mark_ctx *)ctxp)->v;
    const float *low = ((mark_ctx *)ctxp)->low, reach = ((mark_ctx *)ctxp)->reach;
    const ms_nlist *L = &v->lists[part];
    const float *top = ((mark_ctx *)ctxp)->top, band = ((mark_ctx *)ctxp)->band;
    const int gxy = v->gx * v->gy;
    for (int i = b; i < e; ++i) {
        if (ms_volume_is_surface(v, i) || v->z[i] >= top[v->cell[i] % gxy] - band) {
            v->mark[i] = 1;
            continue;
        }
        if (!(v->z[i] >= low[v->cell[i]] - reach)) {
            v->mark[i] = 0;
            continue;
        }
        const int *idx = L->idx + v->nl_begin[i];
        const float *r2 = L->r2 + v->nl_begin[i];
        int near = 0;
        for (int k = 0; k < v->nl_count[i] && !near; ++k)
            near = r2[k] < v->K.h2 && ms_volume_is_surface(v, idx[k]);
        v->mark[i] = near ? 2 : 0;
    }
}

#if MS_VOLUME_HAVE_AVX512
#include "volume/records_avx512.h"

/* mark_part in AVX-512: 16 neighbours at a time, their neighbour counts
 * gathered (the same test on the same numbers: the same marks). */
__attribute__((target("avx512f"))) static void mark_part_avx512(void *ctxp, int part, int b, int e)
{
    ms_volume *v = ((mark_ctx *)ctxp)->v;
    const float *low = ((mark_ctx *)ctxp)->low, reach = ((mark_ctx *)ctxp)->reach;
    const ms_nlist *L = &v->lists[part];
    const __m512 vh2 = _mm512_set1_ps(v->K.h2), vsn = _mm512_set1_ps(v->surface_nbrs);
    const __m512i none = _mm512_setzero_si512();
    const float *top = ((mark_ctx *)ctxp)->top, band = ((mark_ctx *)ctxp)->band;
    const int gxy = v->gx * v->gy;
    for (int i = b; i < e; ++i) {
        if (ms_volume_is_surface(v, i) || v->z[i] >= top[v->cell[i] % gxy] - band) {
            v->mark[i] = 1;
            continue;
        }
        if (!(v->z[i] >= low[v->cell[i]] - reach)) {
            v->mark[i] = 0;
            continue;
        }
        const int *idx = L->idx + v->nl_begin[i];
        const float *r2 = L->r2 + v->nl_begin[i];
        const int n = v->nl_count[i];
        int near = 0;
        for (int k = 0; k < n && !near; k += 16) {
            const int left = n - k;
            const __mmask16 live = left >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << left) - 1u);
            const __m512i vi = _mm512_maskz_loadu_epi32(live, idx + k);
            const __mmask16 in =
                _mm512_mask_cmp_ps_mask(live, _mm512_maskz_loadu_ps(live, r2 + k), vh2, _CMP_LT_OQ);
            const __m512i nb = _mm512_mask_i32gather_epi32(none, in, vi, v->nbr, 4);
            near = _mm512_mask_cmp_ps_mask(in, _mm512_cvtepi32_ps(nb), vsn, _CMP_LT_OQ) != 0;
        }
        v->mark[i] = near ? 2 : 0;
    }
}
#endif

/* phi (eq. 16) at height z of a column whose candidates are (zc, a), with
 * a = 1 - horizontal distance^2 / R^2; m is padded to a multiple of half
 * the lanes with a = 0 (weight 0). Summed in lanes, candidate k in lane
 * k % L: vectorisable, fixed order. A last half block adds to the low
 * lanes only (the high ones would add the padding's exact zeros). */
static inline __attribute__((always_inline)) float phi_at(const float *restrict zc,
                                                          const float *restrict a, int m, float z,
                                                          float inv_r2)
{
    enum { L = MS_VOLUME_LANES, H = MS_VOLUME_LANES / 2 };
    float acc[L] = {0};
    int k = 0;
    for (; k + L <= m; k += L)
        for (int l = 0; l < L; ++l) {
            float d = z - zc[k + l];
            float q = a[k + l] - d * d * inv_r2;
            q = q > 0.0f ? q : 0.0f;
            acc[l] += sqrtf(q);
        }
    if (k < m)
        for (int l = 0; l < H; ++l) {
            float d = z - zc[k + l];
            float q = a[k + l] - d * d * inv_r2;
            q = q > 0.0f ? q : 0.0f;
            acc[l] += sqrtf(q);
        }
    return ms_lanes_sum(acc);
}

typedef struct column_ctx {
    const ms_extract_snap *s;
    int nx, ny;     /* the field */
    int i0, j0, rw; /* the rectangle of columns worked on: origin and width */
    float dxe, dye;
    const int *cstart;
    const float *bx, *by, *bz;
    float *cand;
    size_t cand_stride;
    int *reach; /* per thread, 2 ry + 1: the row reaches of row `reach_j` */
    size_t reach_stride;
    float *raw; /* rw x rh, the rectangle's columns */
    /* the band path (not reference): bins of the extended grid ex x ey
     * (rx, ry cells beyond every side, wall images included) and per
     * thread the band of 2 ry + 1 bin rows around the row being worked
     * on, ordered by bin column: band[part] (x, y, z, band_stride floats
     * each), bstart[part] (ex + 1) */
    int ex, ey, rx, ry;
    float *band;
    size_t band_stride;
    int *bstart;
} column_ctx;

/* The bins of row jj = j + dj, dj in [-ry, ry], within R of a column of
 * row j: how far (cells) either side of the column, or -1 if none. A
 * function of j and jj alone, so computed once per row of columns (the
 * same floats each column computed before: the same candidates). */
static void row_reaches(const column_ctx *cc, int j, int *reach)
{
    const ms_extract_snap *s = cc->s;
    const float *lo = s->lo;
    const float dxe = cc->dxe, dye = cc->dye;
    const float R = s->R, R2 = R * R;
    const int rx = (int)ceilf(R / dxe), ry = (int)ceilf(R / dye);
    const float py = lo[1] + ((float)j + 0.5f) * dye;
    for (int jj = j - ry; jj <= j + ry; ++jj) {
        float gy = fabsf(lo[1] + ((float)jj + 0.5f) * dye - py) - 0.5f * dye;
        gy = gy > 0.0f ? gy : 0.0f;
        int r = -1;
        if (gy < R) {
            r = (int)(sqrtf(R2 - gy * gy) / dxe) + 1; /* a ceiling (cells) */
            r = r < rx ? r : rx;
        }
        reach[jj - j + ry] = r;
    }
}

/* The start of the downward walk and the lowest sphere bottom of the
 * candidates (cz, ca, mc > 0): the highest sphere top, but no higher than
 * a spacing above the highest centre (a still lattice's phi there is
 * ~0.6 T: the top crossing lies below). Maxima and minima in lanes: exact
 * in any order, so vectorisable. */
static inline __attribute__((always_inline)) void column_span(const float *restrict cz,
                                                              const float *restrict ca, int mc,
                                                              float R, float spacing, float *zstart,
                                                              float *zlow_out)
{
    enum { L = MS_VOLUME_LANES };
    float top[L], cmax[L], low[L];
    for (int l = 0; l < L; ++l) {
        top[l] = -INFINITY;
        cmax[l] = -INFINITY;
        low[l] = INFINITY;
    }
    const int mv = mc / L * L;
    for (int k = 0; k < mv; k += L)
        for (int l = 0; l < L; ++l) {
            const float z = cz[k + l], t = z + R * sqrtf(ca[k + l]), b = z - R;
            top[l] = t > top[l] ? t : top[l];
            cmax[l] = z > cmax[l] ? z : cmax[l];
            low[l] = b < low[l] ? b : low[l];
        }
    for (int k = mv; k < mc; ++k) {
        const float z = cz[k], t = z + R * sqrtf(ca[k]), b = z - R;
        top[0] = t > top[0] ? t : top[0];
        cmax[0] = z > cmax[0] ? z : cmax[0];
        low[0] = b < low[0] ? b : low[0];
    }
    float zmax = -INFINITY, zc = -INFINITY, zlow = INFINITY;
    for (int l = 0; l < L; ++l) {
        zmax = top[l] > zmax ? top[l] : zmax;
        zc = cmax[l] > zc ? cmax[l] : zc;
        zlow = low[l] < zlow ? low[l] : zlow;
    }
    *zstart = zmax < zc + spacing ? zmax : zc + spacing;
    *zlow_out = zlow;
}

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

/* The AVX-512 gather of column_candidates: the same floats (one multiply,
 * one add per operation as the C loop, no contraction) kept in the same
 * order by compressing the kept lanes in a register and storing all 16
 * (a compress straight to memory is microcoded and slow on AMD); the lanes
 * past the count are overwritten later, and the candidate buffers have 16
 * floats to spare (extract_rect's cand_stride). So the same candidates and
 * bytes as the C loop. Particles [k0, k1) of the bins; px, py the column;
 * returns the new count. */
__attribute__((target("avx512f,popcnt"))) static int gather_avx512(const float *bx, const float *by,
                                                                   const float *bz, int k0, int k1,
                                                                   float px, float py, float inv_r2,
                                                                   float *cz, float *ca, int mc)
{
    const __m512 vpx = _mm512_set1_ps(px), vpy = _mm512_set1_ps(py);
    const __m512 vinv = _mm512_set1_ps(inv_r2), one = _mm512_set1_ps(1.0f);
    const __m512 zero = _mm512_setzero_ps();
    for (int k = k0; k < k1; k += 16) {
        const int left = k1 - k;
        const __mmask16 live = left >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << left) - 1u);
        const __m512 ex = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, bx + k), vpx);
        const __m512 ey = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, by + k), vpy);
        const __m512 r2 = _mm512_add_ps(_mm512_mul_ps(ex, ex), _mm512_mul_ps(ey, ey));
        const __m512 a = _mm512_sub_ps(one, _mm512_mul_ps(r2, vinv));
        const __mmask16 keep = _mm512_mask_cmp_ps_mask(live, a, zero, _CMP_GT_OQ);
        _mm512_storeu_ps(ca + mc, _mm512_maskz_compress_ps(keep, a));
        _mm512_storeu_ps(cz + mc,
                         _mm512_maskz_compress_ps(keep, _mm512_maskz_loadu_ps(live, bz + k)));
        mc += __builtin_popcount(keep);
    }
    return mc;
}

/* gather_avx512 for the band search with column_span folded in, from
 * the band (band_build): x, the row's (y - py)^2 and z. The kept lanes'
 * maximum of z and minimum of z as it gathers (exact in any order), and
 * zlow = min z - R after (a rounding is monotone: min(z - R) is
 * (min z) - R). Returns the count; *zstart, *zlow as column_span's
 * (mc > 0).
 *
 * The start is min(zmax, zc + spacing) with zmax the highest sphere top
 * z + R sqrt(a), and almost always zc + spacing: a sphere near the column
 * reaches above it. So no square root while gathering (a 16-float one
 * costs as much as the rest of a block): z + R a is never above the top
 * (0 < a <= 1, so a <= sqrt(a), and the float sqrt(a) rounds to a float
 * no below a; each rounding after is monotone), and where the highest
 * z + R a reaches zc + spacing so does zmax, and the start is
 * zc + spacing. Otherwise zmax is computed as column_span does, from the
 * kept candidates. The same start, the same bytes. */
__attribute__((target("avx512f,bmi2,popcnt"))) static int gather_span_avx512(
    const float *bx, const float *bdy2, const float *bz, int k0, int k1, float px, float inv_r2,
    float R, float spacing, float *cz, float *ca, float *zstart, float *zlow)
{
    const __m512 vpx = _mm512_set1_ps(px), vinv = _mm512_set1_ps(inv_r2);
    const __m512 one = _mm512_set1_ps(1.0f), zero = _mm512_setzero_ps(), vR = _mm512_set1_ps(R);
    __m512 top = _mm512_set1_ps(-INFINITY), cmax = top, low = _mm512_set1_ps(INFINITY);
    int mc = 0;
    for (int k = k0; k < k1; k += 16) {
        const __mmask16 live = ms_lanes_left((size_t)(k1 - k));
        const __m512 ex = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, bx + k), vpx);
        const __m512 r2 =
            _mm512_add_ps(_mm512_mul_ps(ex, ex), _mm512_maskz_loadu_ps(live, bdy2 + k));
        const __m512 a = _mm512_sub_ps(one, _mm512_mul_ps(r2, vinv));
        const __mmask16 keep = _mm512_mask_cmp_ps_mask(live, a, zero, _CMP_GT_OQ);
        const __m512 z = _mm512_maskz_loadu_ps(live, bz + k);
        top = _mm512_mask_max_ps(top, keep, top, _mm512_add_ps(z, _mm512_mul_ps(vR, a)));
        cmax = _mm512_mask_max_ps(cmax, keep, cmax, z);
        low = _mm512_mask_min_ps(low, keep, low, z);
        _mm512_storeu_ps(ca + mc, _mm512_maskz_compress_ps(keep, a));
        _mm512_storeu_ps(cz + mc, _mm512_maskz_compress_ps(keep, z));
        mc += __builtin_popcount(keep);
    }
    const float zc = _mm512_reduce_max_ps(cmax), target = zc + spacing;
    if (!(_mm512_reduce_max_ps(top) >= target)) {
        /* column_span's zmax over the kept candidates */
        top = _mm512_set1_ps(-INFINITY);
        for (int k = 0; k < mc; k += 16) {
            const __mmask16 live = ms_lanes_left((size_t)(mc - k));
            const __m512 sa = _mm512_sqrt_ps(_mm512_maskz_loadu_ps(live, ca + k));
            const __m512 t =
                _mm512_add_ps(_mm512_maskz_loadu_ps(live, cz + k), _mm512_mul_ps(vR, sa));
            top = _mm512_mask_max_ps(top, live, top, t);
        }
    }
    const float zmax = _mm512_reduce_max_ps(top);
    *zstart = zmax < target ? zmax : target;
    *zlow = _mm512_reduce_min_ps(low) - R;
    /* weight-0 lanes to the next multiple of 8 (a store, not a loop of
     * 0 to 7 turns, whose end mispredicts) */
    _mm256_storeu_ps(ca + mc, _mm256_setzero_ps());
    _mm256_storeu_ps(cz + mc, _mm256_setzero_ps());
    return mc;
}

/* phi_at for the band search on an AVX-512 machine: the same floats in
 * the same lanes, and ms_lanes_sum's tree in registers, without the trip
 * of the accumulator through memory. In 8-float halves, lanes 0-7 and
 * 8-15 of a block apart: the evaluations are a chain of latencies
 * (columns_band_body), and an 8-float square root has about 2/3 of a
 * 16-float one's latency on Intel cores at half the work, and the tree's
 * first level is then an add of the two halves, not an extract and an
 * add. */
__attribute__((target("avx512f"))) static inline float phi_at_avx512(const float *restrict zc,
                                                                     const float *restrict a, int m,
                                                                     float z, float inv_r2)
{
    const __m256 vz = _mm256_set1_ps(z), vinv = _mm256_set1_ps(inv_r2);
    const __m256 zero = _mm256_setzero_ps();
    __m256 lo = zero, hi = zero;
    int k = 0;
    if (m >= 16) { /* the first block starts the sums: +0 + x = x for x >= +0 */
        const __m256 dl = _mm256_sub_ps(vz, _mm256_loadu_ps(zc));
        const __m256 dh = _mm256_sub_ps(vz, _mm256_loadu_ps(zc + 8));
        const __m256 ql =
            _mm256_sub_ps(_mm256_loadu_ps(a), _mm256_mul_ps(_mm256_mul_ps(dl, dl), vinv));
        const __m256 qh =
            _mm256_sub_ps(_mm256_loadu_ps(a + 8), _mm256_mul_ps(_mm256_mul_ps(dh, dh), vinv));
        lo = _mm256_sqrt_ps(_mm256_max_ps(ql, zero));
        hi = _mm256_sqrt_ps(_mm256_max_ps(qh, zero));
        k = 16;
    }
    for (; k + 16 <= m; k += 16) {
        const __m256 dl = _mm256_sub_ps(vz, _mm256_loadu_ps(zc + k));
        const __m256 dh = _mm256_sub_ps(vz, _mm256_loadu_ps(zc + k + 8));
        __m256 ql =
            _mm256_sub_ps(_mm256_loadu_ps(a + k), _mm256_mul_ps(_mm256_mul_ps(dl, dl), vinv));
        __m256 qh =
            _mm256_sub_ps(_mm256_loadu_ps(a + k + 8), _mm256_mul_ps(_mm256_mul_ps(dh, dh), vinv));
        ql = _mm256_max_ps(ql, zero); /* +0 for q <= 0, as q > 0 ? q : 0 */
        qh = _mm256_max_ps(qh, zero);
        lo = _mm256_add_ps(lo, _mm256_sqrt_ps(ql));
        hi = _mm256_add_ps(hi, _mm256_sqrt_ps(qh));
    }
    if (k < m) { /* a half block: the low lanes */
        const __m256 d = _mm256_sub_ps(vz, _mm256_loadu_ps(zc + k));
        __m256 q = _mm256_sub_ps(_mm256_loadu_ps(a + k), _mm256_mul_ps(_mm256_mul_ps(d, d), vinv));
        q = _mm256_max_ps(q, zero);
        lo = _mm256_add_ps(lo, _mm256_sqrt_ps(q));
    }
    const __m256 t8 = _mm256_add_ps(lo, hi); /* (l, l + 8) */
    const __m128 t4 = _mm_add_ps(_mm256_castps256_ps128(t8), _mm256_extractf128_ps(t8, 1));
    const __m128 u = _mm_add_ps(t4, _mm_movehl_ps(t4, t4)); /* t0 + t2, t1 + t3 */
    return _mm_cvtss_f32(_mm_add_ss(u, _mm_shuffle_ps(u, u, 1)));
}

/* The same with wall images: na = 2 or 4 terms a particle, in the C
 * loop's order (my outer, mx inner); ex, ey: a particle's offsets are
 * (x - px or 2 wx - x - px, y - py or 2 wy - y - py). The terms of 16
 * particles are interleaved by permutes into that order, then kept like
 * gather_avx512's. */
__attribute__((target("avx512f,popcnt"))) static int gather_images_avx512(
    const float *bx, const float *by, const float *bz, int k0, int k1, float px, float py,
    float wx2, float wy2, int nxm, int nym, float inv_r2, float *cz, float *ca, int mc)
{
    const __m512 vpx = _mm512_set1_ps(px), vpy = _mm512_set1_ps(py);
    const __m512 vwx = _mm512_set1_ps(wx2), vwy = _mm512_set1_ps(wy2);
    const __m512 vinv = _mm512_set1_ps(inv_r2), one = _mm512_set1_ps(1.0f);
    const __m512 zero = _mm512_setzero_ps(), dead = _mm512_set1_ps(-1.0f);
    /* interleave (a0 b0 a1 b1 ...): lo from lanes 0-7, hi from 8-15 */
    const __m512i ilo = _mm512_set_epi32(23, 7, 22, 6, 21, 5, 20, 4, 19, 3, 18, 2, 17, 1, 16, 0);
    const __m512i ihi =
        _mm512_set_epi32(31, 15, 30, 14, 29, 13, 28, 12, 27, 11, 26, 10, 25, 9, 24, 8);
    const __m512i plo = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
    const __m512i phi = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
    const int na = nxm * nym;
    for (int k = k0; k < k1; k += 16) {
        const int left = k1 - k;
        const __mmask16 live = left >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << left) - 1u);
        const __m512 x = _mm512_maskz_loadu_ps(live, bx + k);
        const __m512 y = _mm512_maskz_loadu_ps(live, by + k);
        const __m512 z = _mm512_maskz_loadu_ps(live, bz + k);
        const __m512 ex[2] = {_mm512_sub_ps(x, vpx), _mm512_sub_ps(_mm512_sub_ps(vwx, x), vpx)};
        const __m512 ey[2] = {_mm512_sub_ps(y, vpy), _mm512_sub_ps(_mm512_sub_ps(vwy, y), vpy)};
        __m512 t[4];
        int n = 0;
        for (int my = 0; my < nym; ++my)
            for (int mx = 0; mx < nxm; ++mx) {
                const __m512 r2 =
                    _mm512_add_ps(_mm512_mul_ps(ex[mx], ex[mx]), _mm512_mul_ps(ey[my], ey[my]));
                const __m512 a = _mm512_sub_ps(one, _mm512_mul_ps(r2, vinv));
                t[n++] = _mm512_mask_blend_ps(live, dead, a); /* dead lanes: never kept */
            }
        __m512 oa[4], oz[4];
        if (na == 2) {
            oa[0] = _mm512_permutex2var_ps(t[0], ilo, t[1]);
            oa[1] = _mm512_permutex2var_ps(t[0], ihi, t[1]);
            oz[0] = _mm512_permutex2var_ps(z, ilo, z);
            oz[1] = _mm512_permutex2var_ps(z, ihi, z);
        } else {
            /* pairs (t0 t1) and (t2 t3) per particle, then the pairs
             * interleaved as 64-bit units */
            const __m512d p0 = _mm512_castps_pd(_mm512_permutex2var_ps(t[0], ilo, t[1]));
            const __m512d p1 = _mm512_castps_pd(_mm512_permutex2var_ps(t[0], ihi, t[1]));
            const __m512d q0 = _mm512_castps_pd(_mm512_permutex2var_ps(t[2], ilo, t[3]));
            const __m512d q1 = _mm512_castps_pd(_mm512_permutex2var_ps(t[2], ihi, t[3]));
            oa[0] = _mm512_castpd_ps(_mm512_permutex2var_pd(p0, plo, q0));
            oa[1] = _mm512_castpd_ps(_mm512_permutex2var_pd(p0, phi, q0));
            oa[2] = _mm512_castpd_ps(_mm512_permutex2var_pd(p1, plo, q1));
            oa[3] = _mm512_castpd_ps(_mm512_permutex2var_pd(p1, phi, q1));
            const __m512d z0 = _mm512_castps_pd(_mm512_permutex2var_ps(z, ilo, z));
            const __m512d z1 = _mm512_castps_pd(_mm512_permutex2var_ps(z, ihi, z));
            oz[0] = _mm512_castpd_ps(_mm512_permutex2var_pd(z0, plo, z0));
            oz[1] = _mm512_castpd_ps(_mm512_permutex2var_pd(z0, phi, z0));
            oz[2] = _mm512_castpd_ps(_mm512_permutex2var_pd(z1, plo, z1));
            oz[3] = _mm512_castpd_ps(_mm512_permutex2var_pd(z1, phi, z1));
        }
        const int nv = (left >= 16 ? 16 : left) * na; /* live terms */
        for (int q = 0; q < na && q * 16 < nv; ++q) {
            const __mmask16 keep = _mm512_cmp_ps_mask(oa[q], zero, _CMP_GT_OQ);
            _mm512_storeu_ps(ca + mc, _mm512_maskz_compress_ps(keep, oa[q]));
            _mm512_storeu_ps(cz + mc, _mm512_maskz_compress_ps(keep, oz[q]));
            mc += __builtin_popcount(keep);
        }
    }
    return mc;
}
#endif

/* Column (i, j)'s candidates: the spheres (and their images in the nearer
 * side walls) within R horizontally, as (z, a = 1 - horizontal r^2 / R^2)
 * in cz, ca, padded with weight-0 lanes; their count (padded), where the
 * downward walk starts (*zstart) and the lowest sphere bottom (*zlow).
 * reach: row_reaches of row j. */
static inline __attribute__((always_inline)) int column_candidates(const column_ctx *cc, int i,
                                                                   int j, const int *reach_row,
                                                                   int avx512, float *cz, float *ca,
                                                                   float *zstart, float *zlow_out)
{
    (void)avx512; /* without MS_VOLUME_HAVE_AVX512 only the C gather */
    const ms_extract_snap *s = cc->s;
    const int nx = cc->nx, ny = cc->ny;
    const float *lo = s->lo, *hi = s->hi;
    const float dxe = cc->dxe, dye = cc->dye;
    const float R = s->R, R2 = R * R, inv_r2 = 1.0f / R2;
    const int rx = (int)ceilf(R / dxe), ry = (int)ceilf(R / dye);
    const int *cstart = cc->cstart;
    const float *bx = cc->bx, *by = cc->by, *bz = cc->bz;
    const float px = lo[0] + ((float)i + 0.5f) * dxe, py = lo[1] + ((float)j + 0.5f) * dye;
    const float wx = px - lo[0] <= hi[0] - px ? lo[0] : hi[0];
    const float wy = py - lo[1] <= hi[1] - py ? lo[1] : hi[1];
    const int nxm = fabsf(px - wx) < R ? 2 : 1, nym = fabsf(py - wy) < R ? 2 : 1;
    const int images = nxm * nym > 1;
    int mc = 0;
    for (int jj = j - ry; jj <= j + ry; ++jj) {
        if (jj < 0 || jj >= ny)
            continue;
        /* the bins of row jj within R of the column are one run of the
         * binned particles (bins are ordered y-major) */
        int reach = rx;
        if (!images) {
            reach = reach_row[jj - j + ry];
            if (reach < 0)
                continue;
        }
        const int i0 = i - reach < 0 ? 0 : i - reach;
        const int i1 = i + reach > nx - 1 ? nx - 1 : i + reach;
        const int k0 = cstart[jj * nx + i0], k1 = cstart[jj * nx + i1 + 1];
#if MS_VOLUME_HAVE_AVX512
        if (avx512) {
            mc = images ? gather_images_avx512(bx, by, bz, k0, k1, px, py, 2.0f * wx, 2.0f * wy,
                                               nxm, nym, inv_r2, cz, ca, mc)
                        : gather_avx512(bx, by, bz, k0, k1, px, py, inv_r2, cz, ca, mc);
            continue;
        }
#endif
        if (!images) {
            for (int k = k0; k < k1; ++k) {
                const float ex = bx[k] - px, ey = by[k] - py;
                const float a = 1.0f - (ex * ex + ey * ey) * inv_r2;
                cz[mc] = bz[k];
                ca[mc] = a;
                mc += a > 0.0f;
            }
            continue;
        }
        for (int k = k0; k < k1; ++k) {
            /* the particle and its images in the nearer side walls */
            const float ex[2] = {bx[k] - px, 2.0f * wx - bx[k] - px};
            const float ey[2] = {by[k] - py, 2.0f * wy - by[k] - py};
            for (int my = 0; my < nym; ++my)
                for (int mx = 0; mx < nxm; ++mx) {
                    float a = 1.0f - (ex[mx] * ex[mx] + ey[my] * ey[my]) * inv_r2;
                    cz[mc] = bz[k];
                    ca[mc] = a;
                    mc += a > 0.0f;
                }
        }
    }
    /* the floor's image of every sphere within R of it */
    for (int k = 0, m0 = mc; k < m0; ++k)
        if (cz[k] - lo[2] < R) {
            cz[mc] = 2.0f * lo[2] - cz[k];
            ca[mc] = ca[k];
            mc++;
        }
    float zmax = -INFINITY, zlow = INFINITY;
    if (mc > 0)
        column_span(cz, ca, mc, R, s->spacing, &zmax, &zlow);
    for (int pad = mc; pad % (MS_VOLUME_LANES / 2); ++pad) { /* weight-0 lanes */
        cz[pad] = 0.0f;
        ca[pad] = 0.0f;
    }
    mc = (mc + MS_VOLUME_LANES / 2 - 1) / (MS_VOLUME_LANES / 2) * (MS_VOLUME_LANES / 2);
    *zstart = zmax;
    *zlow_out = zlow;
    return mc;
}

/* Below spray (the walk of column_height went 6 steps without reaching
 * T, z the next step): an upper bound of phi in slabs of height ~R (the
 * sum of the sphere maxima sqrt(a) overlapping a slab) skips the slabs
 * that cannot reach T; the walk goes on in the others. Returns found,
 * the bracket's ends updated as the walk's. */
static inline __attribute__((always_inline)) int spray_search(const ms_extract_snap *s,
                                                              const float *cz, const float *ca,
                                                              int mc, float z, float zlow,
                                                              float *za, float *fa, float *zb,
                                                              float *fb)
{
    const float R = s->R, inv_r2 = 1.0f / (R * R);
    const float T = s->iso, dz = 0.5f * s->spacing;
    int found = 0;
    enum { MAXSLABS = 256 };
    float bound[MAXSLABS];
    const float zhi = z + dz, span = zhi - zlow;
    int ns = (int)(span / R) + 2;
    ns = ns > MAXSLABS ? MAXSLABS : ns;
    const float bs = span / (float)ns, inv_bs = 1.0f / bs;
    for (int q = 0; q < ns; ++q)
        bound[q] = 0.0f;
    for (int k = 0; k < mc; ++k) {
        if (!(ca[k] > 0.0f))
            continue;
        float sa = sqrtf(ca[k]), ext = R * sa;
        int q0 = (int)((cz[k] - ext - zlow) * inv_bs);
        int q1 = (int)((cz[k] + ext - zlow) * inv_bs);
        q0 = q0 < 0 ? 0 : q0;
        q1 = q1 > ns - 1 ? ns - 1 : q1;
        for (int q = q0; q <= q1; ++q)
            bound[q] += sa;
    }
    for (int q = ns - 1; q >= 0 && !found; --q) {
        if (bound[q] < T)
            continue;
        float top = zlow + (float)(q + 1) * bs;
        top = top < zhi ? top : zhi;
        const float bot = zlow + (float)q * bs;
        for (float zz = top; zz >= bot - dz; zz -= dz) {
            float phi = phi_at(cz, ca, mc, zz, inv_r2);
            if (phi >= T) {
                *zb = zz;
                *fb = phi - T;
                found = 1;
                break;
            }
            *za = zz;
            *fa = phi - T;
        }
    }
    return found;
}

/* The reference search's height (m above the domain floor, 0 if phi
 * never reaches T) of a column with candidates (cz, ca, mc): walk down
 * from zmax in steps of half a spacing until phi reaches T, and close in
 * on the crossing by regula falsi until the bracket is 1/256 of a spacing
 * (ms_extract_snap.reference; the band search below takes secant steps
 * instead, ~2 evaluations where this takes ~3.5, and test_volume checks it
 * lands as near a root of eq. 17). */
static inline __attribute__((always_inline)) float column_height(const ms_extract_snap *s,
                                                                 const float *cz, const float *ca,
                                                                 int mc, float zmax, float zlow)
{
    const float *lo = s->lo, *hi = s->hi;
    const float R = s->R, inv_r2 = 1.0f / (R * R);
    const float T = s->iso, dz = 0.5f * s->spacing;
    const float ztop = hi[2] - lo[2];
    float height = 0.0f;
    if (mc > 0) {
        float za = zmax, zb = zmax, fa = -T, fb = -T;
        int found = 0, steps = 0;
        float z = zmax;
        /* walk down in steps of half a spacing: a calm surface is met
         * within a few */
        for (; z >= zlow && steps < 6 && !found; z -= dz, ++steps) {
            float phi = phi_at(cz, ca, mc, z, inv_r2);
            if (phi >= T) {
                zb = z;
                fb = phi - T;
                found = 1;
            } else {
                za = z;
                fa = phi - T;
            }
        }
        if (!found && z >= zlow)
            found = spray_search(s, cz, ca, mc, z, zlow, &za, &fa, &zb, &fb);
        if (found && za <= zb) { /* the crossing is at the very top */
            za = zb + dz;
            fa = phi_at(cz, ca, mc, za, inv_r2) - T;
            found = fa < 0.0f;
        }
        if (found) {
            /* the reference (ms_extract_snap.reference): regula falsi
             * (Illinois) until the bracket is 1/256 of a spacing wide */
            const float tol = s->spacing / 256.0f;
            int side = 0;
            for (int it = 0; it < 12 && za - zb > tol; ++it) {
                float zm = fb != fa ? zb + (za - zb) * fb / (fb - fa) : 0.5f * (za + zb);
                if (!(zm < za && zm > zb))
                    zm = 0.5f * (za + zb);
                float fm = phi_at(cz, ca, mc, zm, inv_r2) - T;
                if (fm >= 0.0f) {
                    zb = zm;
                    fb = fm;
                    if (side == -1)
                        fa *= 0.5f;
                    side = -1;
                } else {
                    za = zm;
                    fa = fm;
                    if (side == 1)
                        fb *= 0.5f;
                    side = 1;
                }
            }
            height = fminf(fmaxf(0.5f * (za + zb) - lo[2], 0.0f), ztop);
        }
    }
    return height;
}

/* Columns [b, e) of the rectangle (index (j - j0) * rw + i - i0), the
 * gather in AVX-512 or in C; inlined into one function per instruction
 * set: the same floats in the same lanes on each (no contraction under
 * -std=c11), the same bytes. */
static inline __attribute__((always_inline)) void columns_body(const column_ctx *cc, int part,
                                                               int b, int e, int avx512)
{
    float *cz = cc->cand + (size_t)part * cc->cand_stride, *ca = cz + cc->cand_stride / 2;
    int *reach = cc->reach + (size_t)part * cc->reach_stride, reach_j = -1;
    for (int col = b; col < e; ++col) {
        const int i = cc->i0 + col % cc->rw, j = cc->j0 + col / cc->rw;
        if (j != reach_j) { /* columns go row by row: once a row */
            row_reaches(cc, j, reach);
            reach_j = j;
        }
        float zmax, zlow;
        const int mc = column_candidates(cc, i, j, reach, avx512, cz, ca, &zmax, &zlow);
        cc->raw[col] = column_height(cc->s, cz, ca, mc, zmax, zlow);
    }
}

/* The band of row j: the bins of extended rows j .. j + 2 ry (field rows
 * j - ry .. j + ry) copied bin column by bin column, so the bins of
 * columns i - rx .. i + rx of every one of those rows are one run,
 * [bst[i], bst[i + 2 rx + 1]). Once a row of columns. */
static void band_build(const column_ctx *cc, int j, float *tx, float *ty, float *tz, int *bst)
{
    const int ex = cc->ex, ey = cc->ey, span = 2 * cc->ry + 1;
    const int *cstart = cc->cstart;
    const float py = cc->s->lo[1] + ((float)j + 0.5f) * cc->dye;
    int k = 0;
    for (int ix = 0; ix < ex; ++ix) {
        /* the bins are x-major: rows j .. j + 2 ry of bin column ix are
         * one run of the binned particles, in the order the bins held */
        const int q0 = cstart[ix * ey + j], n = cstart[ix * ey + j + span] - q0;
        bst[ix] = k;
        for (int q = 0; q < n; ++q) { /* a few a run: no library calls */
            tx[k + q] = cc->bx[q0 + q];
            const float dy = cc->by[q0 + q] - py;
            ty[k + q] = dy * dy;
            tz[k + q] = cc->bz[q0 + q];
        }
        k += n;
    }
    bst[ex] = k;
}

#if MS_VOLUME_HAVE_AVX512
/* band_build copying 16 floats at a time under a mask: a run is a few
 * particles, and a loop of varying length mispredicts its end. */
__attribute__((target("avx512f"))) static void band_build_avx512(const column_ctx *cc, int j,
                                                                 float *tx, float *ty, float *tz,
                                                                 int *bst)
{
    const int ex = cc->ex, ey = cc->ey, span = 2 * cc->ry + 1;
    const int *cstart = cc->cstart;
    const __m512 vpy = _mm512_set1_ps(cc->s->lo[1] + ((float)j + 0.5f) * cc->dye);
    int k = 0;
    for (int ix = 0; ix < ex; ++ix) {
        const int q0 = cstart[ix * ey + j], n = cstart[ix * ey + j + span] - q0;
        bst[ix] = k;
        for (int q = 0; q < n; q += 16) {
            const int left = n - q;
            const __mmask16 live = left >= 16 ? (__mmask16)0xFFFF : (__mmask16)((1u << left) - 1u);
            _mm512_mask_storeu_ps(tx + k + q, live, _mm512_maskz_loadu_ps(live, cc->bx + q0 + q));
            const __m512 dy = _mm512_sub_ps(_mm512_maskz_loadu_ps(live, cc->by + q0 + q), vpy);
            _mm512_mask_storeu_ps(ty + k + q, live, _mm512_mul_ps(dy, dy));
            _mm512_mask_storeu_ps(tz + k + q, live, _mm512_maskz_loadu_ps(live, cc->bz + q0 + q));
        }
        k += n;
    }
    bst[ex] = k;
}
#endif

/* The band search's column height as a machine that stops before each
 * phi evaluation (at ze), so that NSLOT columns' evaluations run side by
 * side: each is a chain of dependent latencies (square roots, the lane
 * sum, the secant's division) that one column alone leaves the core
 * partly waiting on. The walk is column_height's; then secant steps inside
 * the bracket [zb, za] (phi(zb) >= T > phi(za)) from the regula falsi
 * point, superlinear where phi is smooth; a step that leaves the bracket
 * (near a sphere's rim phi's slope is unbounded) falls back to regula
 * falsi, then bisection; a step under a quarter of 1/256 of a spacing is
 * checked (SEARCH_CHECK) before its estimate stands. An estimate stands
 * only where the bracket proves it within tol/2 of a root (tol = 1/256
 * of a spacing), or within tol (the bracket closed under tol around it);
 * ten steps without such a proof (a secant stalled on one side of a root
 * where phi dips under T below the surface: on glass under DFSPH it
 * ended 7.7 tol/2 from a root) hand the bracket to bisection
 * (SEARCH_BISECT) until it is under tol, its midpoint the height. */
enum { SEARCH_DONE, SEARCH_WALK, SEARCH_TOP, SEARCH_SECANT, SEARCH_CHECK, SEARCH_BISECT };
typedef struct search {
    float *cz, *ca; /* this slot's candidates */
    int mc, col, state, found, steps, it;
    float ze;      /* where phi is wanted next */
    float z, zlow; /* the walk */
    float za, zb, fa, fb, zp, fp, zr;
    float height;
} search;

/* zr stands (proven within tol/2 or tol of a root, see above). */
static inline __attribute__((always_inline)) void search_done(const ms_extract_snap *s, search *q)
{
    q->height = fminf(fmaxf(q->zr - s->lo[2], 0.0f), s->hi[2] - s->lo[2]);
    q->state = SEARCH_DONE;
}

/* The bracket's midpoint next, or (under tol wide, or no float between
 * its ends) the height. */
static inline __attribute__((always_inline)) void search_bisect_next(const ms_extract_snap *s,
                                                                     search *q)
{
    const float zm = 0.5f * (q->za + q->zb);
    if (q->za - q->zb < s->spacing / 256.0f || !(zm > q->zb && zm < q->za)) {
        q->zr = zm;
        search_done(s, q);
        return;
    }
    q->ze = zm;
    q->state = SEARCH_BISECT;
}

static inline __attribute__((always_inline)) void search_secant_next(const ms_extract_snap *s,
                                                                     search *q)
{
    if (q->it >= 10) { /* no proof in ten steps */
        search_bisect_next(s, q);
        return;
    }
    if (!(q->zr > q->zb && q->zr < q->za))
        q->zr = 0.5f * (q->za + q->zb);
    q->ze = q->zr;
    q->state = SEARCH_SECANT;
}

/* After the walk (and the top's evaluation): the secant's start, or 0. */
static inline __attribute__((always_inline)) void search_after_top(const ms_extract_snap *s,
                                                                   search *q)
{
    if (!q->found) {
        q->height = 0.0f;
        q->state = SEARCH_DONE;
        return;
    }
    const float za = q->za, zb = q->zb, fa = q->fa, fb = q->fb;
    q->zp = fb < -fa ? zb : za;
    q->fp = fb < -fa ? fb : fa;
    q->zr = zb + (za - zb) * fb / (fb - fa);
    q->it = 0;
    search_secant_next(s, q);
}

static inline __attribute__((always_inline)) void search_after_walk(const ms_extract_snap *s,
                                                                    search *q)
{
    if (!q->found && q->z >= q->zlow)
        q->found =
            spray_search(s, q->cz, q->ca, q->mc, q->z, q->zlow, &q->za, &q->fa, &q->zb, &q->fb);
    if (q->found && q->za <= q->zb) { /* the crossing is at the very top */
        q->za = q->zb + 0.5f * s->spacing;
        q->ze = q->za;
        q->state = SEARCH_TOP;
        return;
    }
    search_after_top(s, q);
}

static inline __attribute__((always_inline)) void search_start(const ms_extract_snap *s, search *q,
                                                               float zmax, float zlow)
{
    q->height = 0.0f;
    if (q->mc <= 0) {
        q->state = SEARCH_DONE;
        return;
    }
    q->za = q->zb = q->z = zmax;
    q->fa = q->fb = -s->iso;
    q->found = 0;
    q->steps = 0;
    q->zlow = zlow;
    if (q->z >= zlow) {
        q->ze = q->z;
        q->state = SEARCH_WALK;
        return;
    }
    search_after_walk(s, q);
}

/* phi = phi_at(q->ze): the next step. */
static inline __attribute__((always_inline)) void search_step(const ms_extract_snap *s, search *q,
                                                              float phi)
{
    const float T = s->iso;
    if (q->state == SEARCH_WALK) {
        if (phi >= T) {
            q->zb = q->z;
            q->fb = phi - T;
            q->found = 1;
        } else {
            q->za = q->z;
            q->fa = phi - T;
        }
        q->z -= 0.5f * s->spacing;
        q->steps++;
        if (q->z >= q->zlow && q->steps < 6 && !q->found) {
            q->ze = q->z;
            return;
        }
        search_after_walk(s, q);
    } else if (q->state == SEARCH_TOP) {
        q->fa = phi - T;
        q->found = q->fa < 0.0f;
        search_after_top(s, q);
    } else if (q->state == SEARCH_CHECK) {
        /* the secant's last step fell under a quarter of tol, but near a
         * sphere's rim phi's slope changes fast and such a step can
         * underestimate the error (glass under DFSPH: 1.3 tol from a
         * root): phi half a tol beyond the estimate zr, away from the
         * last evaluated point zp (a bracket end, on the other side of
         * the root's), must be on the root's far side. Then the root is
         * within tol/2 of zr, which stands; else the bracket closes on
         * the check point and the secant goes on. */
        const float f = phi - T, zc = q->ze;
        const int up = zc > q->zr;
        if (up ? f < 0.0f : f >= 0.0f) {
            search_done(s, q);
            return;
        }
        if (f >= 0.0f) {
            q->zb = zc;
            q->fb = f;
        } else {
            q->za = zc;
            q->fa = f;
        }
        q->zp = zc;
        q->fp = f;
        q->zr = q->zb + (q->za - q->zb) * q->fb / (q->fb - q->fa);
        q->it++;
        search_secant_next(s, q);
    } else if (q->state == SEARCH_BISECT) {
        if (phi >= T) {
            q->zb = q->ze;
            q->fb = phi - T;
        } else {
            q->za = q->ze;
            q->fa = phi - T;
        }
        search_bisect_next(s, q);
    } else { /* SEARCH_SECANT */
        const float tol = s->spacing / 256.0f, zr = q->zr, f = phi - T;
        if (f >= 0.0f) {
            q->zb = zr;
            q->fb = f;
        } else {
            q->za = zr;
            q->fa = f;
        }
        const float zb = q->zb, za = q->za, fb = q->fb, fa = q->fa;
        float zn = f != q->fp ? zr - f * (zr - q->zp) / (f - q->fp) : zr;
        if (!(zn > zb && zn < za))
            zn = zb + (za - zb) * fb / (fb - fa);
        const int closed = za - zb < tol, small = fabsf(zn - zr) < 0.25f * tol;
        q->zp = zr;
        q->fp = f;
        q->zr = zn;
        q->it++;
        if (closed) {
            /* the root is in [zb, za], under tol wide, and so is zn (the
             * midpoint would be within tol/2: it moved test_sim's
             * two_way_coupling_stays_bounded's 100-frame wave peaks from
             * decaying to 0.0305, 0.0316 m) */
            search_done(s, q);
            return;
        }
        if (small) {
            /* zn lies on the root's side of zr (now a bracket end) */
            const float zc = zn > zr ? zn + 0.5f * tol : zn - 0.5f * tol;
            if (zn > zr ? zc >= za : zc <= zb) {
                search_done(s, q); /* the bracket's far end is within tol/2 */
                return;
            } else {
                q->ze = zc;
                q->state = SEARCH_CHECK;
                return;
            }
        }
        search_secant_next(s, q);
    }
}

enum { NSLOT = 2 };

/* A column gathered ahead of its search (columns_band_body). */
typedef struct pending {
    float *cz, *ca;
    int mc, col;
    float zmax, zlow;
} pending;

/* The next column of a thread's columns [next, e): its (i, j) in the
 * rectangle, stepped along (no division a column), and the row whose band
 * (band_build) the thread holds. */
typedef struct cursor {
    int next, e, i, j, band_j;
} cursor;

/* The cursor's column's candidates into p (its row's band built if the
 * band holds another row), and the cursor on to the next; past e, p->col
 * is -1 and nothing is gathered. */
static inline __attribute__((always_inline)) void band_gather(const column_ctx *cc, cursor *at,
                                                              float *tx, float *ty, float *tz,
                                                              int *bst, int avx512, pending *p)
{
    (void)avx512;
    p->col = -1;
    if (at->next >= at->e)
        return;
    const int col = at->next++, i = cc->i0 + at->i, j = cc->j0 + at->j;
    at->j += at->i + 1 == cc->rw;
    at->i = at->i + 1 == cc->rw ? 0 : at->i + 1;
    const ms_extract_snap *s = cc->s;
    const float R = s->R, inv_r2 = 1.0f / (R * R);
    if (j != at->band_j) { /* columns go row by row: once a row */
#if MS_VOLUME_HAVE_AVX512
        if (avx512)
            band_build_avx512(cc, j, tx, ty, tz, bst);
        else
#endif
            band_build(cc, j, tx, ty, tz, bst);
        at->band_j = j;
    }
    const float px = s->lo[0] + ((float)i + 0.5f) * cc->dxe;
    const int k0 = bst[i], k1 = bst[i + 2 * cc->rx + 1];
    float *cz = p->cz, *ca = p->ca;
    int mc = 0;
    float zmax = -INFINITY, zlow = INFINITY;
#if MS_VOLUME_HAVE_AVX512
    if (avx512) {
        mc =
            gather_span_avx512(tx, ty, tz, k0, k1, px, inv_r2, R, s->spacing, cz, ca, &zmax, &zlow);
        if (mc == 0)
            zmax = -INFINITY, zlow = INFINITY;
    } else
#endif
    {
        for (int k2 = k0; k2 < k1; ++k2) {
            const float dx = tx[k2] - px;
            const float a = 1.0f - (dx * dx + ty[k2]) * inv_r2;
            cz[mc] = tz[k2];
            ca[mc] = a;
            mc += a > 0.0f;
        }
        if (mc > 0)
            column_span(cz, ca, mc, R, s->spacing, &zmax, &zlow);
        for (int pad = mc; pad % (MS_VOLUME_LANES / 2); ++pad) { /* weight-0 lanes */
            cz[pad] = 0.0f;
            ca[pad] = 0.0f;
        }
    }
    p->mc = (mc + MS_VOLUME_LANES / 2 - 1) / (MS_VOLUME_LANES / 2) * (MS_VOLUME_LANES / 2);
    p->col = col;
    p->zmax = zmax;
    p->zlow = zlow;
}

/* Columns [b, e) of the rectangle by the band: one run of candidates a
 * column (images are particles of the extended bins), then the secant
 * root search, NSLOT columns at a time (search): two measured 1.09-1.14x
 * faster than one on fig1 (same process, interleaved; bench_extract),
 * three and four no faster than two. A column is gathered one column ahead of its search (into
 * an NSLOT + 1-th buffer): the gather's overlapping compress stores are
 * then written to the cache by the time the column's first evaluation
 * loads them, not still in the store buffer, which cannot forward a load
 * that spans two of them (a stall on the search's chain). The same
 * columns, the same searches. Per instruction set as columns_body. */
static inline __attribute__((always_inline)) void columns_band_body(const column_ctx *cc, int part,
                                                                    int b, int e, int avx512)
{
    (void)avx512;
    const ms_extract_snap *s = cc->s;
    float *tx = cc->band + (size_t)part * 3 * cc->band_stride, *ty = tx + cc->band_stride,
          *tz = ty + cc->band_stride;
    int *bst = cc->bstart + (size_t)part * (size_t)(cc->ex + 1);
    const float R = s->R, inv_r2 = 1.0f / (R * R);
    float *cand = cc->cand + (size_t)part * (NSLOT + 1) * cc->cand_stride;
    search slot[NSLOT];
    memset(slot, 0, sizeof slot);
    for (int k = 0; k < NSLOT; ++k) {
        slot[k].cz = cand + (size_t)k * cc->cand_stride;
        slot[k].ca = slot[k].cz + cc->cand_stride / 2;
        slot[k].state = SEARCH_DONE;
        slot[k].col = -1;
    }
    pending pend = {.cz = cand + (size_t)NSLOT * cc->cand_stride};
    pend.ca = pend.cz + cc->cand_stride / 2;
    cursor at = {.next = b, .e = e, .i = b % cc->rw, .j = b / cc->rw, .band_j = -1};
    int live = 0;
    band_gather(cc, &at, tx, ty, tz, bst, avx512, &pend);
    for (;;) {
        /* a finished slot stores its height and takes the pending column,
         * and the next column is gathered into the slot's old buffer */
        for (int k = 0; k < NSLOT; ++k) {
            search *q = &slot[k];
            while (q->state == SEARCH_DONE) {
                if (q->col >= 0) {
                    cc->raw[q->col] = q->height;
                    q->col = -1;
                    live--;
                }
                if (pend.col < 0)
                    break;
                float *cz = q->cz, *ca = q->ca;
                q->cz = pend.cz;
                q->ca = pend.ca;
                q->mc = pend.mc;
                q->col = pend.col;
                live++;
                search_start(s, q, pend.zmax, pend.zlow);
                pend.cz = cz;
                pend.ca = ca;
                band_gather(cc, &at, tx, ty, tz, bst, avx512, &pend);
            }
        }
        if (live == 0)
            break;
        /* the slots' evaluations, independent of each other; a walking
         * slot's next step too (the walk's points are known ahead: z,
         * then z - spacing / 2, computed as search_step will), one chain
         * of latencies shorter where the walk goes on (2.3 steps a column
         * on fig1), the same points and values */
        const float dz = 0.5f * s->spacing;
        float phi[NSLOT], phi2[NSLOT];
        int walking[NSLOT];
#pragma GCC unroll 4
        for (int k = 0; k < NSLOT; ++k) {
            const search *q = &slot[k];
            phi[k] = phi2[k] = 0.0f;
            walking[k] = q->state == SEARCH_WALK;
            if (q->state == SEARCH_DONE)
                continue;
#if MS_VOLUME_HAVE_AVX512
            if (avx512) {
                phi[k] = phi_at_avx512(q->cz, q->ca, q->mc, q->ze, inv_r2);
                if (walking[k])
                    phi2[k] = phi_at_avx512(q->cz, q->ca, q->mc, q->ze - dz, inv_r2);
                continue;
            }
#endif
            phi[k] = phi_at(q->cz, q->ca, q->mc, q->ze, inv_r2);
            if (walking[k])
                phi2[k] = phi_at(q->cz, q->ca, q->mc, q->ze - dz, inv_r2);
        }
#pragma GCC unroll 4
        for (int k = 0; k < NSLOT; ++k) {
            search *q = &slot[k];
            if (q->state == SEARCH_DONE)
                continue;
            search_step(s, q, phi[k]);
            if (walking[k] && q->state == SEARCH_WALK) /* q->ze is the point of phi2 */
                search_step(s, q, phi2[k]);
        }
    }
}

#if MS_VOLUME_HAVE_AVX512
__attribute__((target("avx512f,popcnt"))) static void columns_avx512(void *ctxp, int part, int b,
                                                                     int e)
{
    columns_body(ctxp, part, b, e, 1);
}

__attribute__((target("avx512f,popcnt"))) static void columns_band_avx512(void *ctxp, int part,
                                                                          int b, int e)
{
    columns_band_body(ctxp, part, b, e, 1);
}

__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static void
columns_c(void *ctxp, int part, int b, int e)
{
    columns_body(ctxp, part, b, e, 0);
}

#if MS_VOLUME_HAVE_AVX512
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static void
columns_band_c(void *ctxp, int part, int b, int e)
{
    columns_band_body(ctxp, part, b, e, 0);
}

ms_status ms_volume_extract_counts(ms_volume *v, int *for_step)
{
    *for_step = 0;
    if (v->n == 0 || v->counts_valid)
        return MS_OK;
    ms_volume_grid_build(v);
    ms_status st = ms_volume_count_neighbours(v);
    *for_step = st == MS_OK && v->pass_ready;
    return st;
}

/* Eq. 18's E_kin per unit mass (J/kg), taken relative to the liquid's
 * mean velocity: the energy of the flow inside the liquid, not of the
 * liquid carried as a whole. A glass of water moved at 0.2 m/s holds
 * 0.02 J/kg of bulk motion, the default threshold, and its still surface
 * went unsmoothed, showing every particle; a liquid at rest in its
 * container is still whether or not the container moves. Sums in double
 * in the internal order. */
static double flow_energy(const ms_volume *v)
{
    double e = 0.0, px = 0.0, py = 0.0, pz = 0.0;
    for (int i = 0; i < v->n; ++i) {
        e +=
            (double)v->vx[i] * v->vx[i] + (double)v->vy[i] * v->vy[i] + (double)v->vz[i] * v->vz[i];
        px += v->vx[i];
        py += v->vy[i];
        pz += v->vz[i];
    }
    const double n = v->n;
    const double rel = e / n - (px * px + py * py + pz * pz) / (n * n);
    return rel > 0.0 ? 0.5 * rel : 0.0;
}

/* Phase A (extract.h): mark, then copy the marked particles (internal
 * order of the volume, which the binning keeps) and the constants. */
ms_status ms_volume_extract_snap(ms_volume *v, ms_extract_snap *s)
{
    s->empty = v->n == 0;
    s->m = 0;
    s->e = 0.0;
    s->iso = v->iso_level;
    s->R = v->K.h;
    s->spacing = v->desc.spacing;
    memcpy(s->lo, v->desc.domain_min, sizeof s->lo);
    memcpy(s->hi, v->desc.domain_max, sizeof s->hi);
    s->smooth_steps = v->desc.smooth_steps;
    s->smooth_energy = v->desc.smooth_energy;
    s->isa = v->isa;
    s->reference = 0; /* a bench or test sets it between the phases */
    if (v->n == 0)
        return MS_OK;
    int for_step;
    ms_status st = ms_volume_extract_counts(v, &for_step);
    if (st != MS_OK)
        return st;
    /* per cell the lowest surface particle in it or the cells around it:
     * a 3 x 3 x 3 minimum, one axis at a time (a particle's cell is never
     * on the grid's padding, so the neighbours of the cells read exist) */
    const size_t nc = (size_t)v->ncells, nxy = (size_t)v->gx * (size_t)v->gy;
    if (2 * nc + 2 * nxy > s->cells_cap) {
        float *c = ms_alloc_array(2 * nc + 2 * nxy, sizeof(float));
        if (!c)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for height extraction");
        ms_free(s->cells);
        s->cells = c;
        s->cells_cap = 2 * nc + 2 * nxy;
    }
    float *low = s->cells, *t = s->cells + nc;
    /* per x-y column of the grid the highest particle, then the 3 x 3
     * maximum (a particle's x-y column is never on the padding) */
    float *ctop = s->cells + 2 * nc, *top = ctop + nxy;
    for (size_t c = 0; c < nxy; ++c)
        ctop[c] = top[c] = -INFINITY;
    for (int i = 0; i < v->n; ++i) {
        const size_t c = (size_t)v->cell[i] % nxy;
        ctop[c] = v->z[i] > ctop[c] ? v->z[i] : ctop[c];
    }
    for (int cy = 1; cy + 1 < v->gy; ++cy)
        for (int cx = 1; cx + 1 < v->gx; ++cx) {
            float mx = -INFINITY;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const float z = ctop[(size_t)(cy + dy) * v->gx + cx + dx];
                    mx = z > mx ? z : mx;
                }
            top[(size_t)cy * v->gx + cx] = mx;
        }
    for (size_t c = 0; c < nc; ++c)
        low[c] = INFINITY;
    for (int i = 0; i < v->n; ++i) {
        const int c = v->cell[i];
        if (ms_volume_is_surface(v, i) && v->z[i] < low[c])
            low[c] = v->z[i];
    }
    const size_t sx = 1, sy = (size_t)v->gx, sz = (size_t)v->gx * (size_t)v->gy;
    const size_t step[3] = {sx, sy, sz};
    for (int axis = 0; axis < 3; ++axis) {
        /* low -> t -> low -> t: the last into t */
        const float *src = axis == 1 ? t : low;
        float *dst = axis == 1 ? low : t;
        const size_t d = step[axis];
        for (size_t c = 0; c < d; ++c)
            dst[c] = dst[nc - d + c] = INFINITY;
#pragma omp simd
        for (size_t c = d; c < nc - d; ++c) {
            const float m = src[c - d] < src[c] ? src[c - d] : src[c];
            dst[c] = src[c + d] < m ? src[c + d] : m;
        }
    }
    /* |dz| <= r for a neighbour at r < h: h and a 64th */
    mark_ctx mc = {.v = v,
                   .low = t,
                   .reach = v->K.h * (1.0f + 1.0f / 64.0f),
                   .top = top,
                   .band = TOP_BAND_R * v->K.h + v->desc.spacing};
    ms_vpool_fn *mark = mark_part;
#if MS_VOLUME_HAVE_AVX512
    if (v->isa == MS_VOLUME_ISA_AVX512)
        mark = mark_part_avx512;
#endif
    ms_vpool_run(v->pool, mark, &mc, v->n);
    int m = 0;
    for (int i = 0; i < v->n; ++i)
        m += v->mark[i] != 0;
    if (v->n > s->cap) {
        int cap = v->n; /* all, marked first (steps do not allocate) */
        float *q = ms_alloc_array((size_t)cap * 3, sizeof(float));
        if (!q)
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for height extraction");
        ms_free(s->x);
        s->x = q;
        s->y = q + cap;
        s->z = q + 2 * (size_t)cap;
        s->cap = cap;
    }
    /* the marked particles, then the others (columns_verify's repairs) */
    float *restrict x = s->x, *restrict y = s->y, *restrict z = s->z;
    for (int i = 0, k = 0, u = m; i < v->n; ++i) {
        const int q = v->mark[i] ? k++ : u++;
        x[q] = v->x[i];
        y[q] = v->y[i];
        z[q] = v->z[i];
    }
    s->m = m;
    s->n_all = v->n;
    s->e = flow_energy(v); /* eq. 18, J/kg */
    return MS_OK;
}

ms_vpool *ms_volume_extract_pool(ms_volume *v)
{
    return v->pool;
}

ms_status ms_volume_share_loops(ms_volume *v)
{
    if (v->pool)
        return MS_OK; /* threads of its own already */
    /* four chunks a loop for two threads: a helper that arrives while the
     * volume thread runs its first chunk still takes half of the rest
     * (any count gives the same bytes) */
    return ms_vpool_create_shared(MS_VPOOL_SHARED_PARTS, &v->pool);
}

void ms_extract_snap_free(ms_extract_snap *s)
{
    ms_free(s->x);
    ms_free(s->cells);
    memset(s, 0, sizeof *s);
}

void ms_extract_work_free(ms_extract_work *w)
{
    ms_free(w->start);
    ms_free(w->list);
    ms_free(w->buf);
    ms_free(w->cell);
    ms_free(w->vtop);
    ms_free(w->vbuf);
    ms_free(w->vstart);
    ms_free(w->vlist);
    memset(w, 0, sizeof *w);
}

size_t ms_extract_snap_bytes(const ms_extract_snap *s)
{
    return ((size_t)s->cap * 3 + s->cells_cap) * sizeof(float);
}

size_t ms_extract_work_bytes(const ms_extract_work *w)
{
    return (w->start_cap + w->list_cap + w->vstart_cap + w->vlist_cap) * sizeof(int) +
           (w->buf_cap + w->cell_cap + w->vtop_cap + w->vbuf_cap) * sizeof(float);
}

/* Eq. 18: the smoothing passes from E_kin / total mass, the last one
 * weighted by frac. */
static int smooth_passes(const ms_extract_snap *s, int *full, float *frac)
{
    double ramp = 1.0 - s->e / s->smooth_energy;
    double steps = ramp > 0.0 ? s->smooth_steps * ramp : 0.0;
    *full = (int)floor(steps);
    *frac = (float)(steps - *full);
    return *full + (*frac > 0.0f);
}

/* The counting sort's second half: cfill[c] holds bin c's count; cstart
 * gets the bins' starts (cstart[cells] the total) and the m positions
 * (x, y, z)[q] of keys ckey[q] go to (bx, by, bz) in bin order, stable. */
static void bin_scatter(const int *ckey, int m, size_t cells, const float *x, const float *y,
                        const float *z, int *cstart, int *cfill, float *bx, float *by, float *bz)
{
    ms_counts_to_starts(cstart, cfill, cells);
    for (int q = 0; q < m; ++q) {
        const int d = cfill[ckey[q]]++;
        bx[d] = x[q];
        by[d] = y[q];
        bz[d] = z[q];
    }
}

/* Phase B on the rectangle [i0, i0 + rw) x [j0, j0 + rh) of the nx x ny
 * field, into out (rw x rh). The columns are the field's; the smoothing
 * sees dry cells beyond the rectangle, so a cell's value is the field's
 * when the rectangle holds every cell within the passes of it (or the
 * field ends there): the 3 x 3 filter reaches one cell further per pass. */
/* The columns of the reference (663cc3c's code, bytes unchanged): bins of
 * the field, a run per bin row trimmed to R, the wall images computed per
 * column, the bracketing root search. Into *raw_out (rw x rh in buf);
 * tmp_out, blend_out: the smoothing's scratch. */
static ms_status columns_reference(const ms_extract_snap *s, ms_extract_work *w, ms_vpool *pool,
                                   int nx, int ny, int i0, int j0, int rw, int rh, float **raw_out,
                                   float **tmp_out, float **blend_out)
{
    const size_t rcells = (size_t)rw * rh;
    const size_t cells = (size_t)nx * ny;
    const int m = s->m;
    const float *lo = s->lo, *hi = s->hi;
    const float dxe = (hi[0] - lo[0]) / (float)nx, dye = (hi[1] - lo[1]) / (float)ny;

    /* bin the marked particles by column (counting sort, stable) */
    /* list: the bin keys, the bin fills and for each thread the row
     * reaches (row_reaches) */
    const int parts = ms_vpool_parts(pool);
    const size_t reach_stride = 2 * (size_t)ceilf(s->R / dye) + 1;
    /* sized for the snapshot's capacity, not its m: no growth as m does */
    const size_t mcap = (size_t)s->cap;
    ms_status st = scratch((void **)&w->start, &w->start_cap, cells + 1, sizeof(int));
    if (st == MS_OK)
        st = scratch((void **)&w->list, &w->list_cap,
                     mcap + cells + 1 + (size_t)parts * reach_stride, sizeof(int));
    /* buf: 3m binned positions, 3 fields, and for each thread 2 x 4m
     * candidates (a particle and its images) */
    const size_t cand_stride = 16 * (mcap + MS_VOLUME_LANES);
    const size_t padded = (size_t)(rw + 2) * (rh + 2);
    if (st == MS_OK)
        st = scratch((void **)&w->buf, &w->buf_cap,
                     3 * mcap + 2 * rcells + padded + (size_t)parts * cand_stride, sizeof(float));
    if (st != MS_OK)
        return st;
    int *cstart = w->start, *ckey = w->list, *cfill = w->list + m, *reach = cfill + cells + 1;
    float *bx = w->buf, *by = bx + m, *bz = by + m;
    float *raw = bz + m, *tmp = raw + rcells, *blend = tmp + padded;
    float *cand = blend + rcells;
    memset(cfill, 0, cells * sizeof *cfill);
    for (int k = 0; k < m; ++k) {
        int ix = (int)fminf(fmaxf((s->x[k] - lo[0]) / dxe, 0.0f), (float)(nx - 1));
        int iy = (int)fminf(fmaxf((s->y[k] - lo[1]) / dye, 0.0f), (float)(ny - 1));
        ckey[k] = iy * nx + ix;
        cfill[ckey[k]]++;
    }
    bin_scatter(ckey, m, cells, s->x, s->y, s->z, cstart, cfill, bx, by, bz);

    /* the topmost crossing of phi = T in every column, columns split among
     * the threads (each column on its own: the same bytes for any split) */
    column_ctx cc = {.s = s,
                     .nx = nx,
                     .ny = ny,
                     .i0 = i0,
                     .j0 = j0,
                     .rw = rw,
                     .dxe = dxe,
                     .dye = dye,
                     .cstart = cstart,
                     .bx = bx,
                     .by = by,
                     .bz = bz,
                     .cand = cand,
                     .cand_stride = cand_stride,
                     .reach = reach,
                     .reach_stride = reach_stride,
                     .raw = raw};
    ms_vpool_fn *columns = columns_c;
#if MS_VOLUME_HAVE_AVX512
    if (s->isa == MS_VOLUME_ISA_AVX512)
        columns = columns_avx512;
#endif
    ms_vpool_run(pool, columns, &cc, (int)rcells);
    *raw_out = raw;
    *tmp_out = tmp;
    *blend_out = blend;
    return MS_OK;
}

/* The columns by bands (the default): the marked particles and their
 * wall images (a particle within R of a side wall is mirrored in it, in
 * both at a corner: every image a column within R of that wall sees,
 * whichever wall is nearer to the column) binned on the field grid
 * extended by rx, ry cells each side; a thread copies the 2 ry + 1 bin
 * rows around its row of columns into a band ordered by bin column, so a
 * column's candidates are one run of it (more particles tested than the
 * reference's trimmed runs, but in one run, not 2 ry + 1); the secant
 * root search. The same spheres as the reference, summed in another
 * order, the root to the same tolerance by another path: not the same
 * bytes (bench_extract and test_volume measure the difference). */
static ms_status columns_band(const ms_extract_snap *s, ms_extract_work *w, ms_vpool *pool, int nx,
                              int ny, int i0, int j0, int rw, int rh, float **raw_out,
                              float **tmp_out, float **blend_out)
{
    const size_t rcells = (size_t)rw * rh;
    const int m = s->m;
    const float *lo = s->lo, *hi = s->hi;
    const float dxe = (hi[0] - lo[0]) / (float)nx, dye = (hi[1] - lo[1]) / (float)ny;
    const float R = s->R;
    const int rx = (int)ceilf(R / dxe), ry = (int)ceilf(R / dye);
    const int ex = nx + 2 * rx, ey = ny + 2 * ry;
    const size_t ecells = (size_t)ex * ey;
    const int parts = ms_vpool_parts(pool);
    /* sized for the snapshot's capacity, not its m: no growth as m does */
    /* a particle, 3 side-wall images, and the floor's image of each */
    const size_t mcap = (size_t)s->cap, icap = 8 * mcap;
    ms_status st = scratch((void **)&w->start, &w->start_cap, ecells + 1, sizeof(int));
    if (st == MS_OK)
        st = scratch((void **)&w->list, &w->list_cap,
                     icap + ecells + 1 + (size_t)parts * (size_t)(ex + 1), sizeof(int));
    /* buf: 3 x 4m binned positions, 3 fields, per thread NSLOT + 1
     * columns' candidates (cz, ca) and the band (x, (y - py)^2, z) */
    const size_t cand_stride = 2 * (icap + MS_VOLUME_LANES);
    const size_t band_stride = icap + MS_VOLUME_LANES;
    const size_t padded = (size_t)(rw + 2) * (rh + 2);
    if (st == MS_OK)
        st = scratch((void **)&w->buf, &w->buf_cap,
                     3 * icap + 2 * rcells + padded +
                         (size_t)parts * ((NSLOT + 1) * cand_stride + 3 * band_stride),
                     sizeof(float));
    if (st != MS_OK)
        return st;
    int *cstart = w->start, *ckey = w->list, *cfill = ckey + icap, *bstart = cfill + ecells + 1;
    float *bx = w->buf, *by = bx + icap, *bz = by + icap;
    float *raw = bz + icap, *tmp = raw + rcells, *blend = tmp + padded;
    float *cand = blend + rcells, *band = cand + (size_t)parts * (NSLOT + 1) * cand_stride;
    memset(cfill, 0, ecells * sizeof *cfill);
    /* the bin of a particle or image: the particles' clamped to the field
     * as the reference's, the images' to the extension */
    /* the keys and the positions in particle order (the band's scratch,
     * 3 x icap floats or more, holds the positions until the columns),
     * then a counting sort: stable, so a bin holds its particles and
     * images in that order */
    float *ux = band, *uy = ux + icap, *uz = uy + icap;
    int mi = 0;
    for (int k = 0; k < m; ++k) {
        const float x = s->x[k], y = s->y[k];
        /* the image in the wall within R (a domain narrower than 2 R:
         * the low wall's) */
        const int nxm = x - lo[0] < R || hi[0] - x < R ? 2 : 1;
        const int nym = y - lo[1] < R || hi[1] - y < R ? 2 : 1;
        const float xs[2] = {x, 2.0f * (x - lo[0] < R ? lo[0] : hi[0]) - x};
        const float ys[2] = {y, 2.0f * (y - lo[1] < R ? lo[1] : hi[1]) - y};
        for (int my = 0; my < nym; ++my)
            for (int mx = 0; mx < nxm; ++mx) {
                int ix, iy;
                if (mx == 0)
                    ix = (int)clampf((x - lo[0]) / dxe, 0.0f, (float)(nx - 1));
                else
                    ix = (int)clampf(floorf((xs[1] - lo[0]) / dxe), (float)-rx,
                                     (float)(nx + rx - 1));
                if (my == 0)
                    iy = (int)clampf((y - lo[1]) / dye, 0.0f, (float)(ny - 1));
                else
                    iy = (int)clampf(floorf((ys[1] - lo[1]) / dye), (float)-ry,
                                     (float)(ny + ry - 1));
                /* x-major: a bin column's rows are one run (band_build) */
                const int key = (ix + rx) * ey + iy + ry;
                const float z = s->z[k];
                for (int mz = 0; mz < (z - lo[2] < R ? 2 : 1); ++mz) {
                    ckey[mi] = key;
                    cfill[key]++;
                    ux[mi] = mx ? xs[1] : x;
                    uy[mi] = my ? ys[1] : y;
                    uz[mi] = mz ? 2.0f * lo[2] - z : z;
                    mi++;
                }
            }
    }
    bin_scatter(ckey, mi, ecells, ux, uy, uz, cstart, cfill, bx, by, bz);
    assert((size_t)mi <= icap);
    (void)mi;
    column_ctx cc = {.s = s,
                     .nx = nx,
                     .ny = ny,
                     .i0 = i0,
                     .j0 = j0,
                     .rw = rw,
                     .dxe = dxe,
                     .dye = dye,
                     .cstart = cstart,
                     .bx = bx,
                     .by = by,
                     .bz = bz,
                     .cand = cand,
                     .cand_stride = cand_stride,
                     .raw = raw,
                     .ex = ex,
                     .ey = ey,
                     .rx = rx,
                     .ry = ry,
                     .band = band,
                     .band_stride = band_stride,
                     .bstart = bstart};
    ms_vpool_fn *columns = columns_band_c;
#if MS_VOLUME_HAVE_AVX512
    if (s->isa == MS_VOLUME_ISA_AVX512)
        columns = columns_band_avx512;
#endif
    ms_vpool_run(pool, columns, &cc, (int)rcells);
    *raw_out = raw;
    *tmp_out = tmp;
    *blend_out = blend;
    return MS_OK;
}

/* Every column checked against eq. 16 over every particle. phi is a sum
 * of non-negative terms, so the marked spheres' phi_m <= phi everywhere,
 * and phi_m = phi at every height more than R above the highest unmarked
 * particle within R of the column (B). A column whose crossing zr of
 * phi_m lies above B + R (with a margin for the root's tolerance) has the
 * same crossing with every particle, if nothing above zr reaches T: the
 * band search walks down in half-spacing steps and can step over a sheet
 * thinner than that (a dam break's front over the liquid behind it), so
 * an upper bound of phi above zr (each sphere at its largest there) must
 * be under T, or the heights above zr are searched again (fine_search).
 * Columns that fail the first test (a crossing within R of an unmarked
 * particle, or no crossing with particles near) are searched again over
 * every particle from the top. B is a maximum over a box of bins of
 * half-width ceil(R / cell) + 1, which holds every particle within R of
 * the column and every wall image within R (an image is within R of a
 * column only if its particle is). Runs on the calling thread: one
 * column's result does not depend on the others or on the rectangle, so
 * the bytes are those of any split. */
/* An upper bound of phi over the heights [z1, z2] of a column's
 * candidates: each sphere at its largest there (at its centre's height
 * clamped into the interval). */
static float phi_bound(const float *cz, const float *ca, int mc, float z1, float z2, float inv_r2)
{
    float u = 0.0f;
    for (int k = 0; k < mc; ++k) {
        const float d = cz[k] < z1 ? z1 - cz[k] : (cz[k] > z2 ? cz[k] - z2 : 0.0f);
        const float q = ca[k] - d * d * inv_r2;
        u += q > 0.0f ? sqrtf(q) : 0.0f;
    }
    return u;
}

/* The topmost crossing of phi = T at or above zlow (m, absolute) of a
 * column's candidates (column_candidates), m above the floor, or -1 if phi
 * stays under T there. From the highest sphere top down in chunks of half
 * a spacing: a chunk whose bound (phi_bound) is under T is skipped, the
 * others walked in steps of a 32nd of a spacing; the crossing is then
 * bisected to a 256th. A chunk's top is either the highest sphere top or
 * the bottom of the chunk above, where phi is known to be under T. */
static float fine_search(const ms_extract_snap *s, const float *cz, const float *ca, int mc,
                         float zlow)
{
    const float R = s->R, inv_r2 = 1.0f / (R * R), T = s->iso;
    const float chunk = 0.5f * s->spacing, step = s->spacing / 32.0f, tol = s->spacing / 256.0f;
    float top = -INFINITY;
    for (int k = 0; k < mc; ++k)
        if (ca[k] > 0.0f)
            top = fmaxf(top, cz[k] + R * sqrtf(ca[k]));
    for (float z2 = top; z2 > zlow; z2 -= chunk) {
        const float z1 = fmaxf(z2 - chunk, zlow);
        if (phi_bound(cz, ca, mc, z1, z2, inv_r2) < T)
            continue;
        for (float z = z2 - step; z >= z1 - step; z -= step) {
            const float zz = fmaxf(z, z1);
            if (phi_at(cz, ca, mc, zz, inv_r2) < T) {
                if (zz <= z1)
                    break;
                continue;
            }
            float zb = zz, za = fminf(zz + step, z2); /* phi(zb) >= T > phi(za) */
            while (za - zb > tol) {
                const float zm = 0.5f * (za + zb);
                if (!(zm > zb && zm < za))
                    break;
                if (phi_at(cz, ca, mc, zm, inv_r2) >= T)
                    zb = zm;
                else
                    za = zm;
            }
            return fminf(fmaxf(0.5f * (za + zb) - s->lo[2], 0.0f), s->hi[2] - s->lo[2]);
        }
    }
    return -1.0f;
}

/* phi_bound over [za, inf) of column (i, j) straight from the bins,
 * each sorted highest first: a bin is read down to the first particle
 * more than R below za (it and those below add nothing there). The
 * spheres and wall images of column_candidates. */
static float bound_above(const column_ctx *cc, int i, int j, const int *reach_row, float za,
                         float inv_r2)
{
    const ms_extract_snap *s = cc->s;
    const float *lo = s->lo, *hi = s->hi, R = s->R;
    const int rx = (int)ceilf(R / cc->dxe), ry = (int)ceilf(R / cc->dye);
    const float px = lo[0] + ((float)i + 0.5f) * cc->dxe, py = lo[1] + ((float)j + 0.5f) * cc->dye;
    const float wx = px - lo[0] <= hi[0] - px ? lo[0] : hi[0];
    const float wy = py - lo[1] <= hi[1] - py ? lo[1] : hi[1];
    const int nxm = fabsf(px - wx) < R ? 2 : 1, nym = fabsf(py - wy) < R ? 2 : 1;
    const int images = nxm * nym > 1;
    const float zcut = za - R;
    float u = 0.0f;
    for (int jj = j - ry; jj <= j + ry; ++jj) {
        if (jj < 0 || jj >= cc->ny)
            continue;
        int reach = rx;
        if (!images) {
            reach = reach_row[jj - j + ry];
            if (reach < 0)
                continue;
        }
        const int a0 = i - reach < 0 ? 0 : i - reach;
        const int a1 = i + reach > cc->nx - 1 ? cc->nx - 1 : i + reach;
        for (int ii = a0; ii <= a1; ++ii) {
            const int c = jj * cc->nx + ii;
            for (int k = cc->cstart[c]; k < cc->cstart[c + 1] && cc->bz[k] > zcut; ++k) {
                const float ex[2] = {cc->bx[k] - px, 2.0f * wx - cc->bx[k] - px};
                const float ey[2] = {cc->by[k] - py, 2.0f * wy - cc->by[k] - py};
                const float d = cc->bz[k] < za ? za - cc->bz[k] : 0.0f;
                /* the floor's image, below the particle: farther from za */
                const float df = za - (2.0f * lo[2] - cc->bz[k]);
                const int nz = cc->bz[k] - lo[2] < R ? 2 : 1;
                for (int my = 0; my < nym; ++my)
                    for (int mx = 0; mx < nxm; ++mx)
                        for (int mz = 0; mz < nz; ++mz) {
                            const float dd = mz ? df : d;
                            const float q = 1.0f - (ex[mx] * ex[mx] + ey[my] * ey[my]) * inv_r2 -
                                            dd * dd * inv_r2;
                            u += q > 0.0f ? sqrtf(q) : 0.0f;
                        }
            }
        }
    }
    return u;
}

static ms_status columns_verify(const ms_extract_snap *s, ms_extract_work *w, int nx, int ny,
                                int i0, int j0, int rw, int rh, float *raw)
{
    const int m = s->m, n = s->n_all;
    const size_t cells = (size_t)nx * ny;
    const float *lo = s->lo, *hi = s->hi;
    const float dxe = (hi[0] - lo[0]) / (float)nx, dye = (hi[1] - lo[1]) / (float)ny;
    const float R = s->R, T = s->iso, margin = s->spacing / 8.0f; /* > the searches' tol */
    const int bx_r = (int)ceilf(R / dxe) + 1, by_r = (int)ceilf(R / dye) + 1;
    /* all the scratch at once, before any column needs it, so a run's
     * later frames allocate nothing (sized for the snapshot's capacity) */
    const size_t ncap = (size_t)s->cap;
    const size_t cand_stride = 16 * (ncap + MS_VOLUME_LANES);
    ms_status st = scratch((void **)&w->vtop, &w->vtop_cap, 4 * cells, sizeof(float));
    if (st == MS_OK)
        st = scratch((void **)&w->vstart, &w->vstart_cap, 2 * (cells + 1), sizeof(int));
    if (st == MS_OK)
        st = scratch((void **)&w->vlist, &w->vlist_cap, ncap + 2 * (size_t)ceilf(R / dye) + 1,
                     sizeof(int));
    if (st == MS_OK)
        st = scratch((void **)&w->vbuf, &w->vbuf_cap, 3 * ncap + cand_stride, sizeof(float));
    if (st != MS_OK)
        return st;
    /* per bin the highest unmarked particle (ub) and the highest of all
     * (ab), then their box maxima (ut, at) */
    float *ub = w->vtop, *ut = ub + cells, *ab = ut + cells, *at = ab + cells;
    /* each particle's bin on the field (the reference's bins), kept for
     * the binning below */
    int *cstart = w->vstart, *cfill = w->vstart + cells + 1, *ckey = w->vlist;
    memset(cfill, 0, cells * sizeof *cfill);
    for (size_t c = 0; c < cells; ++c)
        ub[c] = ab[c] = -INFINITY;
    for (int k = 0; k < n; ++k) {
        const int ix = (int)clampf((s->x[k] - lo[0]) / dxe, 0.0f, (float)(nx - 1));
        const int iy = (int)clampf((s->y[k] - lo[1]) / dye, 0.0f, (float)(ny - 1));
        const size_t c = (size_t)iy * nx + ix;
        ckey[k] = (int)c;
        cfill[c]++;
        ab[c] = s->z[k] > ab[c] ? s->z[k] : ab[c];
        if (k >= m)
            ub[c] = s->z[k] > ub[c] ? s->z[k] : ub[c];
    }
    for (int j = 0; j < ny; ++j)
        for (int i = i0; i < i0 + rw; ++i) {
            float mu = -INFINITY, ma = -INFINITY;
            for (int q = MS_MAX(i - bx_r, 0); q <= MS_MIN(i + bx_r, nx - 1); ++q) {
                mu = ub[(size_t)j * nx + q] > mu ? ub[(size_t)j * nx + q] : mu;
                ma = ab[(size_t)j * nx + q] > ma ? ab[(size_t)j * nx + q] : ma;
            }
            ut[(size_t)j * nx + i] = mu;
            at[(size_t)j * nx + i] = ma;
        }
    for (int j = j0; j < j0 + rh; ++j)
        for (int i = i0; i < i0 + rw; ++i) {
            float b = -INFINITY, a = -INFINITY;
            for (int q = MS_MAX(j - by_r, 0); q <= MS_MIN(j + by_r, ny - 1); ++q) {
                b = ut[(size_t)q * nx + i] > b ? ut[(size_t)q * nx + i] : b;
                a = at[(size_t)q * nx + i] > a ? at[(size_t)q * nx + i] : a;
            }
            ab[(size_t)j * nx + i] = a; /* the highest particle near, for below */
            float *h = raw + (size_t)(j - j0) * rw + (i - i0);
            /* a dry column with particles near may be a thin sheet the
             * walk's half-spacing steps went over: searched again too */
            const int ok =
                *h > 0.0f ? b == -INFINITY || *h + lo[2] - R - margin >= b : a == -INFINITY;
            if (!ok)
                *h = -1.0f; /* to be searched again */
        }
    /* every particle binned on the field */
    int *reach = w->vlist + ncap;
    float *vx = w->vbuf, *vy = vx + ncap, *vz = vy + ncap, *cz = vz + ncap;
    float *ca = cz + cand_stride / 2;
    bin_scatter(ckey, n, cells, s->x, s->y, s->z, cstart, cfill, vx, vy, vz);
    /* each bin highest first (stable), so the bound above a height reads
     * only the bins' tops */
    for (size_t c = 0; c < cells; ++c)
        for (int k = cstart[c] + 1; k < cstart[c + 1]; ++k) {
            const float x = vx[k], y = vy[k], z = vz[k];
            int q = k;
            for (; q > cstart[c] && vz[q - 1] < z; --q) {
                vx[q] = vx[q - 1];
                vy[q] = vy[q - 1];
                vz[q] = vz[q - 1];
            }
            vx[q] = x;
            vy[q] = y;
            vz[q] = z;
        }
    column_ctx cc = {.s = s,
                     .nx = nx,
                     .ny = ny,
                     .i0 = i0,
                     .j0 = j0,
                     .rw = rw,
                     .dxe = dxe,
                     .dye = dye,
                     .cstart = cstart,
                     .bx = vx,
                     .by = vy,
                     .bz = vz};
    const float inv_r2 = 1.0f / (R * R), lift = s->spacing / 128.0f; /* 2 x the root's tol */
    for (int j = j0; j < j0 + rh; ++j) {
        int row_done = 0;
        for (int i = i0; i < i0 + rw; ++i) {
            float *h = raw + (size_t)(j - j0) * rw + (i - i0);
            if (*h == 0.0f)
                continue; /* dry, and no particle near */
            if (!row_done) {
                row_reaches(&cc, j, reach);
                row_done = 1;
            }
            /* the search's crossing zr: nothing above it may reach T (a
             * sheet the walk stepped over): certified by the bound, or
             * searched */
            const float za = *h + lo[2] + lift;
            /* above every sphere's centre phi only falls: nothing above zr */
            if (*h > 0.0f && *h + lo[2] >= ab[(size_t)j * nx + i])
                continue;
            if (*h > 0.0f && bound_above(&cc, i, j, reach, za, inv_r2) < T)
                continue;
            float zmax, zlow;
            const int mc = column_candidates(&cc, i, j, reach, 0, cz, ca, &zmax, &zlow);
            if (*h < 0.0f) { /* the marked particles could not decide */
                const float f = fine_search(s, cz, ca, mc, zlow);
                *h = f > 0.0f ? f : 0.0f;
                continue;
            }
            const float f = fine_search(s, cz, ca, mc, za);
            if (f > *h)
                *h = f;
        }
    }
    return MS_OK;
}

/* One eq. 18 pass over the rectangle (rw x rh) from pad (the field,
 * zero-padded), weighted by f; dry cells keep their 0 (selected, not
 * skipped: vectorises; one operation at a time, so every width gives
 * the same floats). */
#if MS_VOLUME_HAVE_AVX512
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static void
smooth_pass(const float *restrict pad, const float *restrict raw, const float *restrict inv_w,
            float *restrict out, int rw, int rh, float f)
{
    const int px = rw + 2;
    for (int j = 0; j < rh; ++j) {
        const float *r0 = pad + (size_t)j * px, *r1 = r0 + px, *r2 = r1 + px;
        const float *rr = raw + (size_t)j * rw, *iw = inv_w + (size_t)j * rw;
        float *o = out + (size_t)j * rw;
        /* omp simd: -O2's cost model leaves a loop of unknown length
         * scalar; element by element, so the same floats */
        if (f == 1.0f) {
#pragma omp simd
            for (int i = 0; i < rw; ++i) {
                const float acc = (r0[i] + 2.0f * r0[i + 1] + r0[i + 2]) +
                                  (2.0f * r1[i] + 4.0f * r1[i + 1] + 2.0f * r1[i + 2]) +
                                  (r2[i] + 2.0f * r2[i + 1] + r2[i + 2]);
                o[i] = rr[i] > 0.0f ? acc * iw[i] : o[i];
            }
        } else {
#pragma omp simd
            for (int i = 0; i < rw; ++i) {
                const float acc = (r0[i] + 2.0f * r0[i + 1] + r0[i + 2]) +
                                  (2.0f * r1[i] + 4.0f * r1[i + 1] + 2.0f * r1[i + 2]) +
                                  (r2[i] + 2.0f * r2[i + 1] + r2[i + 2]);
                const float smoothed = acc * iw[i];
                o[i] = rr[i] > 0.0f ? o[i] + f * (smoothed - o[i]) : o[i];
            }
        }
    }
}

static ms_status extract_rect(const ms_extract_snap *s, ms_extract_work *w, ms_vpool *pool, int nx,
                              int ny, int i0, int j0, int rw, int rh, float *out)
{
    const size_t rcells = (size_t)rw * rh;
    memset(out, 0, rcells * sizeof *out);
    if (s->empty)
        return MS_OK;
    float *raw, *tmp, *blend;
    ms_status st = s->reference
                       ? columns_reference(s, w, pool, nx, ny, i0, j0, rw, rh, &raw, &tmp, &blend)
                       : columns_band(s, w, pool, nx, ny, i0, j0, rw, rh, &raw, &tmp, &blend);
    if (st == MS_OK)
        st = columns_verify(s, w, nx, ny, i0, j0, rw, rh, raw);
    if (st != MS_OK)
        return st;

    /* eq. 18: the number of smoothing passes from E_kin / total mass */
    int full;
    float frac;
    const int passes = smooth_passes(s, &full, &frac);
    /* One pass: the 3 x 3 binomial weights over the wet cells, as sums over
     * a zero-padded copy (dry cells hold 0) times the inverse of the wet
     * weight around each cell, computed once. */
    const int px = rw + 2;
    float *pad = tmp, *inv_w = blend; /* (rw+2)(rh+2) and rw*rh floats */
    memcpy(out, raw, rcells * sizeof *out);
    if (passes > 0) {
        /* the wet weight of a cell: the same 3 x 3 sum over a padded wet
         * mask (1 wet, 0 dry or outside); small integers, exact in any
         * order, so branch-free */
        memset(pad, 0, (size_t)px * (rh + 2) * sizeof *pad);
        for (int j = 0; j < rh; ++j)
            for (int i = 0; i < rw; ++i)
                pad[(size_t)(j + 1) * px + i + 1] = raw[(size_t)j * rw + i] > 0.0f ? 1.0f : 0.0f;
        for (int j = 0; j < rh; ++j) {
            const float *r0 = pad + (size_t)j * px, *r1 = r0 + px, *r2 = r1 + px;
            float *iw = inv_w + (size_t)j * rw;
            /* vectorised (omp simd: -O2 leaves it scalar); wt is 0 or a
             * sum of weights >= 1, so 1 / max(wt, 1) is 1 / wt where it
             * is kept, and no lane divides by 0 */
#pragma omp simd
            for (int i = 0; i < rw; ++i) {
                const float wt = (r0[i] + 2.0f * r0[i + 1] + r0[i + 2]) +
                                 (2.0f * r1[i] + 4.0f * r1[i + 1] + 2.0f * r1[i + 2]) +
                                 (r2[i] + 2.0f * r2[i + 1] + r2[i + 2]);
                iw[i] = wt > 0.0f ? 1.0f / (wt > 1.0f ? wt : 1.0f) : 0.0f;
            }
        }
    }
    for (int pass = 0; pass < passes; ++pass) {
        for (int j = 0; j < rh; ++j)
            memcpy(pad + (size_t)(j + 1) * px + 1, out + (size_t)j * rw, (size_t)rw * sizeof *out);
        const float f = pass < full ? 1.0f : frac; /* the last may be a fraction */
        smooth_pass(pad, raw, inv_w, out, rw, rh, f);
    }
    return MS_OK;
}

static ms_status check_grid(int nx, int ny)
{
    if (nx < 1 || ny < 1 || nx > 4096 || ny > 4096)
        return ms_fail(MS_ERR_INVALID_ARGUMENT,
                       "volume: extract_height grid %d x %d is outside 1 .. 4096 per side", nx, ny);
    return MS_OK;
}

ms_status ms_extract_field(const ms_extract_snap *s, ms_extract_work *w, ms_vpool *pool, int nx,
                           int ny, float *out)
{
    ms_status st = check_grid(nx, ny);
    return st == MS_OK ? extract_rect(s, w, pool, nx, ny, 0, 0, nx, ny, out) : st;
}

ms_status ms_extract_cell(const ms_extract_snap *s, ms_extract_work *w, int nx, int ny, int i,
                          int j, float *out)
{
    ms_status st = check_grid(nx, ny);
    if (st != MS_OK)
        return st;
    assert(i >= 0 && i < nx && j >= 0 && j < ny);
    int full;
    float frac;
    const int r = s->empty ? 0 : smooth_passes(s, &full, &frac);
    const int i0 = MS_MAX(i - r, 0), i1 = MS_MIN(i + r, nx - 1);
    const int j0 = MS_MAX(j - r, 0), j1 = MS_MIN(j + r, ny - 1);
    const int rw = i1 - i0 + 1, rh = j1 - j0 + 1;
    st = scratch((void **)&w->cell, &w->cell_cap, (size_t)rw * rh, sizeof(float));
    if (st == MS_OK)
        st = extract_rect(s, w, NULL, nx, ny, i0, j0, rw, rh, w->cell);
    if (st == MS_OK)
        *out = w->cell[(size_t)(j - j0) * rw + (i - i0)];
    return st;
}

ms_status ms_volume_extract_height(ms_volume *v, int nx, int ny, float *out)
{
    if (!v || !out)
        return ms_fail(MS_ERR_INVALID_ARGUMENT, "volume: extract_height needs a volume and out");
    ms_status st = check_grid(nx, ny);
    if (st != MS_OK)
        return st;
    ms_extract_snap s = {0};
    /* the volume's scratch serves as phase B's */
    ms_extract_work w = v->ex_verify;
    w.start = v->ex_start;
    w.list = v->ex_list;
    w.buf = v->ex_buf;
    w.start_cap = v->ex_start_cap;
    w.list_cap = v->ex_list_cap;
    w.buf_cap = v->ex_cap;
    st = ms_volume_extract_snap(v, &s);
    if (st == MS_OK)
        st = ms_extract_field(&s, &w, v->pool, nx, ny, out);
    else
        memset(out, 0, (size_t)nx * ny * sizeof *out);
    v->ex_start = w.start;
    v->ex_list = w.list;
    v->ex_buf = w.buf;
    v->ex_start_cap = w.start_cap;
    v->ex_list_cap = w.list_cap;
    v->ex_cap = w.buf_cap;
    assert(!w.cell);
    w.start = w.list = NULL;
    w.buf = NULL;
    w.start_cap = w.list_cap = w.buf_cap = 0;
    v->ex_verify = w; /* the repairs' scratch */
    ms_extract_snap_free(&s);
    return st;
}
