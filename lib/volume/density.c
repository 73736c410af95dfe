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
 * pressure. Colliders add the density of a mirrored lattice (collide.c). Pressure from the equation of state of desc.pressure:
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
#include <string.h>

#include "volume/volume_impl.h"

float ms_volume_pressure(const ms_volume *v, float rho)
{
    float rho0 = v->desc.rest_density;
    if (v->desc.pressure == MS_PRESSURE_TAIT) {
        float r = rho / rho0;
        if (r <= 2.0f) {
            float r2 = r * r, r3 = r2 * r;
            return fmaxf(v->tait_b * (r3 * r3 * r - 1.0f), 0.0f);
        }
        return v->tait_b * (127.0f + 448.0f * (r - 2.0f)); /* 2^7 - 1, 7 * 2^6 */
    }
    return fmaxf(v->desc.gas_constant * (rho - rho0), 0.0f);
}

#if defined(__AVX512F__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

typedef struct density_ctx {
    ms_volume *v;
    int coincident[MS_VOLUME_MAX_THREADS];
    int surface[MS_VOLUME_MAX_THREADS];
    float max_err[MS_VOLUME_MAX_THREADS];
    double pairs[MS_VOLUME_MAX_THREADS];
} density_ctx;

enum { LANES = MS_VOLUME_LANES };

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

/* Append (j | tag, r^2) for every j in [lo, hi), j != skip, closer than h
 * to q, in order of j. Three versions with the same result: AVX-512
 * (compress-store), SSE2 (compare, movemask, append the set bits) and
 * plain C (branch-free append); the arrays are padded, so a block may read
 * past hi. Returns the number appended. */
static size_t filter_row(const ms_volume *v, int lo, int hi, const float q[3], int skip, int tag,
                         int *restrict out, float *restrict out2)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float h2 = v->K.h2;
    size_t n = 0;
#if defined(__AVX512F__)
    const __m512 qx = _mm512_set1_ps(q[0]), qy = _mm512_set1_ps(q[1]), qz = _mm512_set1_ps(q[2]);
    const __m512 hh = _mm512_set1_ps(h2);
    const __m512i iota = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    for (int j = lo; j < hi; j += 16) {
        int rem = hi - j;
        __mmask16 valid = rem >= 16 ? (__mmask16)0xffff : (__mmask16)((1u << rem) - 1u);
        __m512 dx = _mm512_sub_ps(qx, _mm512_maskz_loadu_ps(valid, x + j));
        __m512 dy = _mm512_sub_ps(qy, _mm512_maskz_loadu_ps(valid, y + j));
        __m512 dz = _mm512_sub_ps(qz, _mm512_maskz_loadu_ps(valid, z + j));
        __m512 r2 = _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(dx, dx), _mm512_mul_ps(dy, dy)),
                                  _mm512_mul_ps(dz, dz));
        unsigned m = _mm512_mask_cmp_ps_mask(valid, r2, hh, _CMP_LT_OQ);
        if ((unsigned)(skip - j) < 16u)
            m &= ~(1u << (skip - j));
        __m512i id = _mm512_add_epi32(_mm512_set1_epi32(j | tag), iota);
        /* compress in registers and store whole blocks (the list has a
         * block of slack): a compress to memory is microcoded and slow */
        _mm512_storeu_si512((void *)(out + n), _mm512_maskz_compress_epi32((__mmask16)m, id));
        _mm512_storeu_ps(out2 + n, _mm512_maskz_compress_ps((__mmask16)m, r2));
        n += (size_t)__builtin_popcount(m);
    }
#elif defined(__SSE2__)
    const __m128 qx = _mm_set1_ps(q[0]), qy = _mm_set1_ps(q[1]), qz = _mm_set1_ps(q[2]);
    const __m128 hh = _mm_set1_ps(h2);
    for (int j = lo; j < hi; j += 4) {
        __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(x + j));
        __m128 dy = _mm_sub_ps(qy, _mm_loadu_ps(y + j));
        __m128 dz = _mm_sub_ps(qz, _mm_loadu_ps(z + j));
        __m128 r2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)),
                               _mm_mul_ps(dz, dz));
        unsigned m = (unsigned)_mm_movemask_ps(_mm_cmplt_ps(r2, hh));
        if (hi - j < 4)
            m &= (1u << (hi - j)) - 1u;
        if ((unsigned)(skip - j) < 4u)
            m &= ~(1u << (skip - j));
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
#else
    for (int j = lo; j < hi; ++j) {
        float dx = q[0] - x[j], dy = q[1] - y[j], dz = q[2] - z[j];
        float r2 = dx * dx + dy * dy + dz * dz;
        out[n] = j | tag;
        out2[n] = r2;
        n += (r2 < h2) & (j != skip);
    }
#endif
    return n;
}

/* Append to L every particle j != skip within h of q, from the 27 cells
 * around cell c. Returns the neighbours appended, -1 if the list could not
 * grow. */
static int gather(const ms_volume *v, ms_nlist *L, const float q[3], long c, int skip, int tag)
{
    const int *restrict start = v->cell_start;
    const long sx = v->gx, sxy = (long)v->gx * v->gy;
    size_t cand = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy) {
            const long row = c + dz * sxy + dy * sx;
            cand += (size_t)(start[row + 2] - start[row - 1]);
        }
    if (!reserve(L, cand + 2 * LANES))
        return -1;
    size_t n = 0;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy) {
            const long row = c + dz * sxy + dy * sx;
            n += filter_row(v, start[row - 1], start[row + 2], q, skip, tag, L->idx + L->len + n,
                            L->r2 + L->len + n);
        }
    L->len += n;
    return (int)n;
}

/* Pad a run that began at `begin` to a multiple of the lanes. */
static void pad(ms_nlist *L, size_t begin, int index, float h2)
{
    while ((L->len - begin) % LANES) {
        L->idx[L->len] = index;
        L->r2[L->len] = h2;
        L->len++;
    }
}

static inline float cube(float a)
{
    return a * a * a;
}

/* Sum of the kernel weights of entries r2[0..n), n a multiple of the lanes
 * (padding has r^2 = h^2: weight 0), in lanes, in a fixed order. */
static float weight_sum(const ms_volume *v, const float *restrict r2, int n, int *coincident)
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
    } else {
        for (int k = 0; k < n; k += LANES)
            for (int l = 0; l < LANES; ++l) {
                float q = r2[k + l];
                float t = h - sqrtf(q);
                acc[l] += t * t * t;
                cl[l] += q < eps2 ? 1.0f : 0.0f;
            }
    }
    float s = 0.0f, c = 0.0f;
    for (int l = 0; l < LANES; ++l) {
        s += acc[l];
        c += cl[l];
    }
    *coincident = (int)c;
    return s;
}

static void density_part(void *ctxp, int part, int b, int e)
{
    density_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    ms_nlist *L = &v->lists[part], *G = &v->ghosts[part];
    const int poly6 = v->desc.density_kernel == MS_DENSITY_POLY6;
    const float mw = v->mass * (poly6 ? v->K.poly6 : v->K.spiky);
    const float self = poly6 ? cube(v->K.h2) : cube(v->K.h); /* W(0) / its constant */
    const float rho0 = v->desc.rest_density, h2 = v->K.h2;
    int coincident = 0, surface = 0;
    float max_err = 0.0f;
    double pairs = 0.0;
    L->len = 0;
    G->len = 0;
    v->list_failed[part] = 0;
    for (int i = b; i < e; ++i) {
        const float p[3] = {v->x[i], v->y[i], v->z[i]};
        const size_t begin = L->len, gbegin = G->len;
        int nreal = gather(v, L, p, v->cell[i], i, 0);
        if (nreal < 0) {
            v->list_failed[part] = 1;
            return;
        }
        pad(L, begin, i, h2);
        int nghost = 0;
        float wall[3];
        unsigned near = ms_volume_walls_near(v, p[0], p[1], p[2], wall);
        for (unsigned f = 1; f < 8; ++f) { /* the wall images, in a fixed order */
            if ((f & near) != f)
                continue;
            float q[3] = {p[0], p[1], p[2]};
            for (int k = 0; k < 3; ++k)
                if (f & (1u << k))
                    q[k] = 2.0f * wall[k] - q[k];
            int got = gather(v, G, q, ms_volume_cell_of(v, q[0], q[1], q[2]), -1,
                             (int)(f << MS_VOLUME_IMAGE_SHIFT));
            if (got < 0) {
                v->list_failed[part] = 1;
                return;
            }
            nghost += got;
        }
        pad(G, gbegin, i, h2);
        v->nl_begin[i] = (int)begin;
        v->nl_count[i] = nreal;
        v->gl_begin[i] = (int)gbegin;
        v->gl_count[i] = nghost;
        int close = 0, gclose = 0;
        float sum = self + weight_sum(v, L->r2 + begin, (int)(L->len - begin), &close);
        if (nghost)
            sum += weight_sum(v, G->r2 + gbegin, (int)(G->len - gbegin), &gclose);
        v->nbr[i] = 1 + nreal + nghost;
        coincident += close;
        pairs += nreal + nghost;
        int is_surface = ms_volume_is_surface(v, i);
        surface += is_surface;
        float rho = mw * sum + v->b_rho[i];
        v->rho[i] = rho;
        v->inv_rho[i] = 1.0f / rho;
        v->prs[i] = ms_volume_pressure(v, rho);
        float err = rho / rho0 - 1.0f; /* compression */
        max_err = err > max_err ? err : max_err;
    }
    ctx->coincident[part] = coincident;
    ctx->surface[part] = surface;
    ctx->max_err[part] = max_err;
    ctx->pairs[part] = pairs;
}

ms_status ms_volume_density(ms_volume *v)
{
    density_ctx ctx = {.v = v};
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
    v->surface_count = surface;
    v->pairs = pairs;
    v->counts_valid = 1;
    v->coincident = coincident;
    v->max_density_error = max_err;
    return MS_OK;
}

ms_status ms_volume_count_neighbours(ms_volume *v)
{
    ms_volume_boundary(v, 0.0);
    return ms_volume_density(v);
}
