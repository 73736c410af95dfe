/* Density and pressure. Density is eq. 9 with A = rho, rho_i = sum_j m
 * W(x_i - x_j), self included, with the kernel of desc.density_kernel:
 *   MS_DENSITY_SPIKY  W_press of eq. 11 (the default), the kernel whose
 *                     gradient eq. 13 uses, so the pressure force does the
 *                     work the density change stores: energy-consistent;
 *   MS_DENSITY_POLY6  Mueller et al. 2003's poly6. With the spiky gradient
 *                     of eq. 13 the pair is not energy-consistent; measured
 *                     here, an 8000-particle tank settling under gravity
 *                     with mu = 0 went from 1 J to 250 J of kinetic energy
 *                     in 2 s with poly6 and stayed below 1 J with spiky.
 *                     Poly6 needs mu of about 0.01 rho0 c h to stay still. The domain's walls reflect the liquid: a particle within h of
 * a wall also sums the wall images of its neighbours (the ghost particles
 * of the classic mirror boundary: the real particles reflected across the
 * wall, across two walls at an edge, three at a corner), so it is not taken
 * for an under-dense one and the wall pushes back with the liquid's own
 * pressure. A particle within h of a shape collider sums in the same way
 * the images, across the shape's tangent plane at its closest point, of
 * the neighbours on its side of that plane. Pressure from the equation of state of desc.pressure:
 *   MS_PRESSURE_IDEAL_GAS  p = k (rho - rho0)                    (the paper's)
 *   MS_PRESSURE_TAIT       p = B ((rho/rho0)^7 - 1), B = rho0 c0^2 / 7,
 *                          continued along its tangent beyond rho = 2 rho0
 *                          (a float overflows at (rho/rho0)^7 for degenerate
 *                          layouts such as all particles at one point).
 * Both laws are clamped at p >= 0. The paper's law gives negative pressure
 * wherever rho < rho0, i.e. in the under-sampled layers at the free surface
 * and the walls, and with negative pressure the spiky kernel of eq. 11 is
 * tensile-unstable (Swegle et al. 1995: W'' > 0 under tension): measured
 * here, a 1000-particle block at rest with k = 400 m^2/s^2 and no gravity
 * went from 0 to 90 J of kinetic energy in 0.04 s, its surface layer pulled
 * in at 1100 m/s^2. Mueller et al. used k = 3 m^2/s^2 with mu = 3.5 Pa s,
 * a liquid too soft and too viscous for the paper's water. Clamping is the
 * usual remedy for weakly compressible free-surface SPH; it removes the
 * cohesion of the surface layer and nothing else.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "volume/volume_internal.h"

#if MS_VOLUME_HAVE_AVX512
#include <immintrin.h>

#include "volume/records_avx512.h"
#endif

/* max(p, 0) as fmaxf(p, 0.0f) gives it (a NaN p: 0), without the call
 * to libm that fmaxf is at -O2 (once a particle in the density pass). p = -0 cannot occur (k, B > 0; x - x = +0). */
static inline float clamp_positive(float p)
{
    return p > 0.0f ? p : 0.0f;
}

/* The law's pressure (ms_volume_pressure), inlined into the density
 * pass: no call a particle. */
static inline float pressure_of(const ms_volume *v, float rho)
{
    float rho0 = v->desc.rest_density;
    if (v->desc.pressure == MS_PRESSURE_DFSPH)
        return 0.0f; /* the solves of dfsph.c act on the velocities */
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        float r = rho / rho0;
        if (r <= 2.0f) {
            float r2 = r * r, r3 = r2 * r;
            return clamp_positive(v->tait_b * (r3 * r3 * r - 1.0f));
        }
        return v->tait_b * (127.0f + 448.0f * (r - 2.0f)); /* 2^7 - 1, 7 * 2^6 */
    }
    return clamp_positive(v->desc.gas_constant * (rho - rho0));
}

float ms_volume_pressure(const ms_volume *v, float rho)
{
    return pressure_of(v, rho);
}

typedef struct density_ctx {
    ms_volume *v;
    int coincident[MS_VOLUME_MAX_THREADS];
    int surface[MS_VOLUME_MAX_THREADS];
    float max_err[MS_VOLUME_MAX_THREADS];
    double pairs[MS_VOLUME_MAX_THREADS];
} density_ctx;

enum { LANES = MS_VOLUME_LANES };

static inline float cube(float a)
{
    return a * a * a;
}

/* Sum of the kernel weights of a particle's real run r2[0..n) and then
 * its image run g2[0..gn) (n, gn multiples of the lanes; padding has
 * r^2 = h^2: weight 0), entry k of each run in lane k % 16, the lanes
 * summed once in ms_lanes_sum's fixed order; the coincident real pairs
 * (r^2 < eps^2) are counted. Built for AVX-512, AVX2 and the baseline
 * (no FMA contraction with -std=c11: the same bits on each). The image
 * run goes into the real run's lanes, not into a sum of its own. */
#if MS_VOLUME_HAVE_AVX512
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
static float
weight_sum(const ms_volume *v, const float *restrict r2, int n, const float *restrict g2, int gn,
           int *coincident)
{
    const float h = v->K.h, h2 = v->K.h2, eps2 = v->eps2;
    float acc[LANES] = {0}, cl[LANES] = {0};
    if (v->desc.density_kernel == MS_DENSITY_POLY6) {
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                float q = r2[k + l];
                acc[l] += cube(h2 - q);
                cl[l] += q < eps2 ? 1.0f : 0.0f;
            }
        for (int k = 0; k < gn; k += LANES)
            for (int l = 0; l < LANES; ++l)
                acc[l] += cube(h2 - g2[k + l]);
    } else {
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                float q = r2[k + l];
                float t = h - sqrtf(q);
                acc[l] += t * t * t;
                cl[l] += q < eps2 ? 1.0f : 0.0f;
            }
        for (int k = 0; k < gn; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                float t = h - sqrtf(g2[k + l]);
                acc[l] += t * t * t;
            }
    }
    *coincident = (int)ms_lanes_sum(cl);
    return ms_lanes_sum(acc);
}

#if MS_VOLUME_HAVE_AVX512
/* The kernel weight of 16 entries r^2: (h - r)^3 (spiky) or (h^2 - r^2)^3
 * (poly6), the C loop's operations in its order. */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline __m512 weight16(__m512 q,
                                                                                         int poly6,
                                                                                         __m512 h,
                                                                                         __m512 h2)
{
    const __m512 t = poly6 ? _mm512_sub_ps(h2, q) : _mm512_sub_ps(h, _mm512_sqrt_ps(q));
    return _mm512_mul_ps(_mm512_mul_ps(t, t), t);
}

/* weight_sum in AVX-512 intrinsics, inlined into the density pass
 * (a call of the clone once a particle sent its lanes through the stack
 * to ms_lanes_sum): the same terms in the
 * same lanes and the same lane sum, so the same bits; the coincident
 * count is a popcount (the C loop's float count of small integers is
 * exact). */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline float weight_runs(
    const ms_volume *v, const float *restrict r2, int n, const float *restrict g2, int gn,
    int *coincident, int poly6)
{
    const __m512 h = _mm512_set1_ps(v->K.h), h2 = _mm512_set1_ps(v->K.h2);
    const __m512 eps2 = _mm512_set1_ps(v->eps2);
    __m512 acc = _mm512_setzero_ps();
    int close = 0;
    for (int k = 0; k < n; k += LANES) {
        const __m512 q = _mm512_loadu_ps(r2 + k);
        acc = _mm512_add_ps(acc, weight16(q, poly6, h, h2));
        close += _mm_popcnt_u32(_cvtmask16_u32(_mm512_cmp_ps_mask(q, eps2, _CMP_LT_OQ)));
    }
    for (int k = 0; k < gn; k += LANES)
        acc = _mm512_add_ps(acc, weight16(_mm512_loadu_ps(g2 + k), poly6, h, h2));
    *coincident = close;
    return ms_lanes_sum16(acc);
}

/* The kernel chosen once, outside the loops (-O2 does not unswitch). */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline float weight_sum_avx512(
    const ms_volume *v, const float *restrict r2, int n, const float *restrict g2, int gn,
    int *coincident)
{
    if (v->desc.density_kernel == MS_DENSITY_POLY6)
        return weight_runs(v, r2, n, g2, gn, coincident, 1);
    return weight_runs(v, r2, n, g2, gn, coincident, 0);
}
#endif

typedef float weight_fn(const ms_volume *v, const float *restrict r2, int n,
                        const float *restrict g2, int gn, int *coincident);

/* What the density gives particles [b, e) once rho is summed: 1/rho, the
 * law's pressure, the packed copy's p and 1/rho; returns the largest
 * compression rho/rho0 - 1 (at least 0). */
typedef float finish_fn(ms_volume *v, int b, int e);

static inline void finish_one(ms_volume *v, int i)
{
    const float rho = v->rho[i];
    v->inv_rho[i] = 1.0f / rho;
    v->prs[i] = pressure_of(v, rho);
    float *restrict pk = v->pk + 8 * (size_t)i; /* pack_part wrote the rest */
    pk[3] = v->prs[i];
    pk[7] = v->inv_rho[i];
}

static float finish_c(ms_volume *v, int b, int e)
{
    const float rho0 = v->desc.rest_density;
    float max_err = 0.0f;
    for (int i = b; i < e; ++i) {
        finish_one(v, i);
        float err = v->rho[i] / rho0 - 1.0f; /* compression */
        max_err = err > max_err ? err : max_err;
    }
    return max_err;
}

#if MS_VOLUME_HAVE_AVX512
/* pressure_of in 16 lanes: the same operations per lane (the Tait law's
 * two branches blended), so the same bits. */
__attribute__((target("avx512f,avx512dq"), always_inline)) static inline __m512 pressure16(
    const ms_volume *v, __m512 rho)
{
    const __m512 rho0 = _mm512_set1_ps(v->desc.rest_density), zero = _mm512_setzero_ps();
    __m512 p;
    if (v->desc.pressure == MS_PRESSURE_DFSPH)
        return zero;
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        const __m512 b = _mm512_set1_ps(v->tait_b), r = _mm512_div_ps(rho, rho0);
        const __m512 r2 = _mm512_mul_ps(r, r), r3 = _mm512_mul_ps(r2, r);
        const __m512 lo = _mm512_mul_ps(
            b, _mm512_sub_ps(_mm512_mul_ps(_mm512_mul_ps(r3, r3), r), _mm512_set1_ps(1.0f)));
        const __m512 hi =
            _mm512_mul_ps(b, _mm512_add_ps(_mm512_set1_ps(127.0f),
                                           _mm512_mul_ps(_mm512_set1_ps(448.0f),
                                                         _mm512_sub_ps(r, _mm512_set1_ps(2.0f)))));
        const __mmask16 low = _mm512_cmp_ps_mask(r, _mm512_set1_ps(2.0f), _CMP_LE_OQ);
        const __mmask16 pos = _mm512_cmp_ps_mask(lo, zero, _CMP_GT_OQ);
        /* r <= 2: clamp_positive(lo); else (NaN r too) hi */
        return _mm512_mask_blend_ps(low, hi, _mm512_maskz_mov_ps(pos, lo));
    }
    p = _mm512_mul_ps(_mm512_set1_ps(v->desc.gas_constant), _mm512_sub_ps(rho, rho0));
    return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(p, zero, _CMP_GT_OQ), p);
}

/* finish_c in 16 lanes (the C loop is two scalar divisions a particle,
 * beside the density loop's square roots): the same
 * operations per lane; the maximum (max_ps(a, m) = a > m ? a : m, the C
 * test, from +0) does not depend on the order. The packed copy's p and
 * 1/rho are stored lane by lane. */
__attribute__((target("avx512f,avx512dq,bmi2"), always_inline)) static inline float finish_avx512(
    ms_volume *v, int b, int e)
{
    const __m512 one = _mm512_set1_ps(1.0f), rho0 = _mm512_set1_ps(v->desc.rest_density);
    __m512 m = _mm512_setzero_ps();
    for (int i = b; i < e; i += 16) {
        const unsigned rem = (unsigned)(e - i), n = rem < 16u ? rem : 16u;
        const __mmask16 valid = ms_lanes_left(rem);
        const __m512 rho = _mm512_maskz_loadu_ps(valid, v->rho + i);
        const __m512 inv = _mm512_maskz_div_ps(valid, one, rho);
        const __m512 p = pressure16(v, rho);
        _mm512_mask_storeu_ps(v->inv_rho + i, valid, inv);
        _mm512_mask_storeu_ps(v->prs + i, valid, p);
        const __m512 err = _mm512_sub_ps(_mm512_maskz_div_ps(valid, rho, rho0), one);
        m = _mm512_mask_max_ps(m, valid, err, m);
        float *restrict pk = v->pk + 8 * (size_t)i;
        for (unsigned l = 0; l < n; ++l) {
            pk[8 * l + 3] = v->prs[i + (int)l];
            pk[8 * l + 7] = v->inv_rho[i + (int)l];
        }
    }
    return _mm512_reduce_max_ps(m);
}
#endif

/* density_part's loop over particles [b, e), with the weight sum w (a
 * constant at each call site, inlined). */
/* The counts a part's density loop sums. */
typedef struct part_counts {
    int coincident, surface;
    int64_t pairs; /* exact: the double it was summed the same integers */
} part_counts;

/* Particle i's density sum from its lists (built), rho = m W sum. */
__attribute__((always_inline)) static inline void weigh(ms_volume *v, const ms_nlist *L,
                                                        const ms_nlist *G, int i, float mw,
                                                        weight_fn *w, part_counts *c)
{
    const int nreal = v->nl_count[i], nghost = v->gl_count[i];
    const int n = (nreal + LANES - 1) / LANES * LANES, gn = (nghost + LANES - 1) / LANES * LANES;
    int close = 0;
    const float *g2 = nghost ? G->r2 + v->gl_begin[i] : NULL; /* an image run, if any */
    const float sum = w(v, L->r2 + v->nl_begin[i], n, g2, gn, &close);
    v->nbr[i] = nreal + nghost;
    c->coincident += close - 1; /* itself */
    c->pairs += nreal - 1 + nghost;
    c->surface += ms_volume_is_surface(v, i);
    v->rho[i] = mw * sum;
}

/* density_part's loop over particles [b, e), with the weight sum w and
 * finish fin (constants at each call site, inlined). A particle's weights
 * are summed after the next particle's lists are built: its list's stores, compressed blocks at any offset, have
 * then left the store buffer, and the sum's aligned loads do not wait
 * for them. The same sums: the same bits. */
__attribute__((always_inline)) static inline void density_range(density_ctx *ctx, int part, int b,
                                                                int e, weight_fn *w, finish_fn *fin)
{
    ms_volume *v = ctx->v;
    ms_nlist *L = &v->lists[part], *G = &v->ghosts[part];
    const int poly6 = v->desc.density_kernel == MS_DENSITY_POLY6;
    const float mw = v->mass * (poly6 ? v->K.poly6 : v->K.spiky);
    part_counts c = {0, 0, 0};
    L->len = 0;
    G->len = 0;
    v->list_failed[part] = 0;
    ms_rows own = {.cell = -1};
    long ncand = 0;
    for (int i = b; i < e; ++i) {
        if (ms_volume_neighbours_of(v, part, i, &own, &ncand) < 0) {
            v->list_failed[part] = 1;
            return;
        }
        if (i > b)
            weigh(v, L, G, i - 1, mw, w, &c);
    }
    if (e > b)
        weigh(v, L, G, e - 1, mw, w, &c);
    const float max_err = fin(v, b, e);
    if (!v->lists_reserved && !ms_volume_lists_headroom(v, part)) {
        v->list_failed[part] = 1;
        return;
    }
    ctx->coincident[part] = c.coincident;
    ctx->surface[part] = c.surface;
    ctx->max_err[part] = max_err;
    ctx->pairs[part] = (double)c.pairs;
}

#if MS_VOLUME_HAVE_AVX512
__attribute__((target("avx512f,avx512dq,bmi2"))) static void density_range_avx512(density_ctx *ctx,
                                                                                  int part, int b,
                                                                                  int e)
{
    density_range(ctx, part, b, e, weight_sum_avx512, finish_avx512);
}
#endif

static void density_part(void *ctxp, int part, int b, int e)
{
    density_ctx *ctx = ctxp;
#if MS_VOLUME_HAVE_AVX512
    if (ctx->v->isa == MS_VOLUME_ISA_AVX512) {
        density_range_avx512(ctx, part, b, e);
        return;
    }
#endif
    density_range(ctx, part, b, e, weight_sum, finish_c);
}

/* The packed copy's positions and velocities (v->pk: x, y, z, -, vx, vy,
 * vz, -), for the record loads of the force pass (forces.c);
 * density_part adds p and 1/rho. */
static void pack_part(void *ctxp, int part, int b, int e)
{
    (void)part;
    const ms_volume *v = ((density_ctx *)ctxp)->v;
    float *restrict pk = v->pk;
    for (int i = b; i < e; ++i) {
        pk[8 * (size_t)i] = v->x[i];
        pk[8 * (size_t)i + 1] = v->y[i];
        pk[8 * (size_t)i + 2] = v->z[i];
        pk[8 * (size_t)i + 4] = v->vx[i];
        pk[8 * (size_t)i + 5] = v->vy[i];
        pk[8 * (size_t)i + 6] = v->vz[i];
    }
}

ms_status ms_volume_density(ms_volume *v)
{
    density_ctx ctx = {.v = v};
    ms_vpool_run(v->pool, pack_part, &ctx, v->n);
    ms_vpool_run(v->pool, density_part, &ctx, v->n);
    int coincident = 0, surface = 0;
    float max_err = 0.0f;
    double pairs = 0.0;
    int failed = 0;
    for (int p = 0; p < MS_VOLUME_MAX_THREADS; ++p) { /* integer sums, a max: order-free */
        coincident += ctx.coincident[p];
        surface += ctx.surface[p];
        max_err = ctx.max_err[p] > max_err ? ctx.max_err[p] : max_err;
        pairs += ctx.pairs[p];
        failed |= v->list_failed[p];
    }
    if (failed)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the neighbour lists");
    v->lists_reserved = 1;
    v->surface_count = surface;
    v->pairs = pairs;
    v->counts_valid = 1;
    v->coincident = coincident;
    v->max_density_error = max_err;
    return MS_OK;
}

/* A collider's pose as the boundary pass outside a step sees it. */
static void collider_pose(const ms_shape *s, float out[13])
{
    ms_shape_get_pose(s, out, out + 3);
    ms_shape_get_orientation(s, out + 6, out + 10);
}

ms_status ms_volume_count_neighbours(ms_volume *v)
{
    /* the particles are where the last step left them, and so are the
     * colliders they met (a moving glass seen at its pose, the step's
     * start, read its leading wall's particles 25-35 % compressed) */
    int moved = ms_volume_boundary_after_step(v);
    ms_status st = ms_volume_density(v);
    v->pass_ready = st == MS_OK && !moved; /* the next step starts at the poses */
    v->pass_ncol = v->ncolliders;
    for (int c = 0; c < v->ncolliders; ++c) {
        v->pass_col[c] = v->colliders[c];
        collider_pose(v->colliders[c], v->pass_pose[c]);
    }
    return st;
}

/* After the step's last drift the extraction (and the coupling
 * to the waves) rebuilt the grid and ran a density pass at the end-of-step
 * positions; the next step's first sub-step would build the same again:
 * the sort of particles already in cell order is the identity, and the
 * boundary terms at tau = 0 are those of the step's view of the colliders
 * when none jumped (col_jump 0: shift 0, col_vel the shape's own velocity,
 * compared bit for bit). Nothing else the pass reads can change between
 * steps without clearing counts_valid (positions, count, order) or
 * showing in the colliders' poses; the velocities can (ms_volume_adapt_to
 * _waves), so the packed copy of them is refreshed. */
int ms_volume_take_counted_pass(ms_volume *v)
{
    int ok = v->pass_ready && v->counts_valid && v->pass_ncol == v->ncolliders;
    v->pass_ready = 0;
    for (int c = 0; ok && c < v->ncolliders; ++c) {
        float now[13];
        collider_pose(v->colliders[c], now);
        ok = v->pass_col[c] == v->colliders[c] && !memcmp(now, v->pass_pose[c], sizeof now);
        for (int k = 0; ok && k < 3; ++k) {
            const float zero = 0.0f;
            ok = !memcmp(&v->col_jump[c][k], &zero, sizeof zero) &&
                 !memcmp(&v->col_vel[c][k], &now[3 + k], sizeof zero);
        }
    }
    if (ok) {
        density_ctx ctx = {.v = v};
        ms_vpool_run(v->pool, pack_part, &ctx, v->n);
    }
    return ok;
}
