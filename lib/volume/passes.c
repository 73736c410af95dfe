/* The SPH passes over the lane type (lane.h), written once. This file is
 * the plain-C instance; passes_<isa>.c include it again with MS_LANE_ISA
 * set and are compiled with that instruction set's flags (Makefile), so
 * the one algorithm below is each ISA's code. Each pass keeps the order
 * of its sums fixed (entry k of a run in lane k % 16, the lanes summed
 * once in ms_lane_sum's tree), so every instance gives the same bits. */
#include <math.h>
#include <stdint.h>

#include "volume/dfsph_pass.h"
#include "volume/law.h"
#include "volume/passes.h"

#if MS_LANE_ISA == MS_LANE_ISA_C
#define PASSES ms_volume_passes_c
#elif MS_LANE_ISA == MS_LANE_ISA_SSE2
#define PASSES ms_volume_passes_sse2
#elif MS_LANE_ISA == MS_LANE_ISA_AVX2
#define PASSES ms_volume_passes_avx2
#elif MS_LANE_ISA == MS_LANE_ISA_AVX512
#define PASSES ms_volume_passes_avx512
#elif MS_LANE_ISA == MS_LANE_ISA_NEON
#define PASSES ms_volume_passes_neon
#endif

enum { LANES = MS_LANES };
/* The per-particle pieces are inlined into each pass's part loop: the
 * loops' constants and accumulators stay in registers. */
#if defined(__GNUC__)
#define PASS_INLINE __attribute__((always_inline))
#else
#define PASS_INLINE
#endif
/* The pair loops prefetch their streamed per-pair data (the neighbour
 * indices, and the pair terms or r^2) MS_PREFETCH_ENTRIES entries ahead:
 * a sub-step's pair terms (19 MB on the peer's scene) live in the shared
 * cache, not the core's, and the hardware prefetchers do not keep up (an
 * error pass's pair loop took 0.84 ms without, 0.63-0.70 ms with its data
 * in L2). Measured on the AVX-512 path, the peer's scene's 0.3 s, thread
 * CPU of the phases, three alternated runs: the density solve 0.96-0.97x
 * at 128, 256 and 512 entries (1024: no gain), the factors and divergence
 * solve 0.97x with the factors loop's too. Hints only: the same bits. */
enum { MS_PREFETCH_ENTRIES = 512 };

/* The 4-byte entry MS_PREFETCH_ENTRIES after p (as an integer: that
 * address may lie past the array, where a prefetch does nothing). */
static inline const void *ahead(const void *p)
{
    return (const void *)((uintptr_t)p + MS_PREFETCH_ENTRIES * sizeof(float));
}
_Static_assert(MS_LANES == MS_VOLUME_LANES, "the lists are padded to the lane width");

/* ---- density (density.c: eq. 9 and the law's pressure) ---- */

/* The kernel weights of a particle's real run r2[0..n) and then its image
 * run g2[0..gn) (n, gn multiples of the lanes; padding has r^2 = h^2:
 * weight 0), the image run into the real run's lanes, and the count of
 * its coincident real pairs (r^2 < eps^2). The kernel is a constant at
 * each call site (inlined twice: the choice stays outside the loops). */
static inline PASS_INLINE float weight_runs(const ms_volume *v, const float *restrict r2, int n,
                                            const float *restrict g2, int gn, int *coincident,
                                            int poly6)
{
    const ms_lane h = ms_lane_set1(v->K.h), h2 = ms_lane_set1(v->K.h2);
    const ms_lane eps2 = ms_lane_set1(v->eps2);
    ms_lane acc = ms_lane_zero();
    int close = 0;
    for (int k = 0; k < n; k += LANES) {
        const ms_lane q = ms_lane_load(r2 + k);
        acc = ms_lane_add(acc, poly6 ? ms_lane_poly6_shape(h2, q) : ms_lane_spiky_shape(h, q));
        close += ms_lane_count(ms_lane_lt(q, eps2));
    }
    for (int k = 0; k < gn; k += LANES) {
        const ms_lane q = ms_lane_load(g2 + k);
        acc = ms_lane_add(acc, poly6 ? ms_lane_poly6_shape(h2, q) : ms_lane_spiky_shape(h, q));
    }
    *coincident = close;
    return ms_lane_sum(acc);
}

/* The counts a part's density loop sums. */
typedef struct part_counts {
    int coincident, surface;
    int64_t pairs;
} part_counts;

/* Particle i's density sum from its lists (built), rho = m W sum. */
static inline PASS_INLINE void weigh(ms_volume *v, const ms_nlist *L, const ms_nlist *G, int i,
                                     float mw, int poly6, part_counts *c)
{
    const int nreal = v->nl_count[i], nghost = v->gl_count[i];
    const int n = (nreal + LANES - 1) / LANES * LANES, gn = (nghost + LANES - 1) / LANES * LANES;
    int close = 0;
    const float *g2 = nghost ? G->r2 + v->gl_begin[i] : NULL; /* an image run, if any */
    const float *r2 = L->r2 + v->nl_begin[i];
    const float sum =
        poly6 ? weight_runs(v, r2, n, g2, gn, &close, 1) : weight_runs(v, r2, n, g2, gn, &close, 0);
    v->nbr[i] = nreal + nghost;
    c->coincident += close - 1; /* itself */
    c->pairs += nreal - 1 + nghost;
    c->surface += ms_volume_is_surface(v, i);
    v->rho[i] = mw * sum;
}

/* What particles [b, e) take from their density: 1/rho, the law's
 * pressure, the packed copy's p and 1/rho (density.c's pack_part wrote
 * the rest); returns the largest compression rho/rho0 - 1 (at least 0:
 * the maximum starts at +0, and a > m ? a : m does not depend on the
 * order for the numbers it meets; a NaN is never taken). */
static float finish(ms_volume *v, int b, int e)
{
    const ms_lane one = ms_lane_set1(1.0f), rho0 = ms_lane_set1(v->desc.rest_density);
    ms_lane m = ms_lane_zero();
    for (int i = b; i < e; i += LANES) {
        const int n = e - i < LANES ? e - i : LANES;
        /* a tail's lanes past e read 0: rho/rho0 - 1 = -1 leaves m */
        const ms_lane rho = n == LANES ? ms_lane_load(v->rho + i) : ms_lane_load_n(v->rho + i, n);
        const ms_lane inv = ms_lane_div(one, rho);
        const ms_lane p = ms_lane_law_pressure(v, rho);
        if (n == LANES) {
            ms_lane_store(v->inv_rho + i, inv);
            ms_lane_store(v->prs + i, p);
        } else {
            ms_lane_store_n(v->inv_rho + i, inv, n);
            ms_lane_store_n(v->prs + i, p, n);
        }
        m = ms_lane_max(ms_lane_sub(ms_lane_div(rho, rho0), one), m);
        float *restrict pk = v->pk + 8 * (size_t)i;
        for (int l = 0; l < n; ++l) {
            pk[8 * l + 3] = v->prs[i + l];
            pk[8 * l + 7] = v->inv_rho[i + l];
        }
    }
    return ms_lane_max_of(m);
}

/* A particle's weights are summed after the next particle's lists are
 * built: its list's stores, compressed blocks at any offset, have then
 * left the store buffer, and the sum's aligned loads do not wait for
 * them. The same sums: the same bits. */
static void density_range(ms_density_ctx *ctx, int part, int b, int e)
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
            weigh(v, L, G, i - 1, mw, poly6, &c);
    }
    if (e > b)
        weigh(v, L, G, e - 1, mw, poly6, &c);
    const float max_err = finish(v, b, e);
    if (!v->lists_reserved && !ms_volume_lists_headroom(v, part)) {
        v->list_failed[part] = 1;
        return;
    }
    ctx->coincident[part] = c.coincident;
    ctx->surface[part] = c.surface;
    ctx->max_err[part] = max_err;
    ctx->pairs[part] = (double)c.pairs;
}

/* ---- forces (forces.c: eqs. 13 and 14) ---- */

/* Particle i's sums over its lists. */
typedef struct pair_sums {
    float px, py, pz; /* pressure: sum (p_i + p_j)/rho_j (h - r)^2 / r (x_i - x_j) */
    float vx, vy, vz; /* viscosity: sum (h - r)/rho_j (v_j - v_i) */
    float d;          /* sum (h - r)/rho_j, for the viscous bound */
} pair_sums;

/* The seven sums' lanes, named (no array: with a[7] and loops over its
 * index GCC kept them on the stack). */
typedef struct lanes7 {
    ms_lane px, py, pz, vx, vy, vz, d;
} lanes7;

/* The same lanes in memory, for a particle at a shape collider, whose
 * shape images are added one by one (image_term). */
typedef struct pair_lanes {
    float px[16], py[16], pz[16], vx[16], vy[16], vz[16], d[16];
} pair_lanes;

static inline int padded(int n)
{
    return (n + LANES - 1) / LANES * LANES;
}

/* An image's position p and velocity u along axis q: reflected (2 wall -
 * p, a sign flip of u) in the lanes whose image bits have bit q. */
static inline PASS_INLINE void reflect_axis(const int32_t *gidx, int q, float wall, ms_lane *p,
                                            ms_lane *u)
{
    const ms_lmask m = ms_lane_test_bit(gidx, (int32_t)1 << (MS_VOLUME_IMAGE_SHIFT + q));
    *p = ms_lane_select(m, ms_lane_sub(ms_lane_set1(2.0f * wall), *p), *p);
    *u = ms_lane_select(m, ms_lane_neg(*u), *u);
}

/* The wall-image terms of entries [0, 16) of gidx/gr2 (no shape images),
 * added to the lanes a (entry l to lane l). */
static inline PASS_INLINE void image_terms(const ms_volume *v, const int *restrict gidx,
                                           const float *restrict gr2, int i, const float wall[3],
                                           int pressure, lanes7 *a)
{
    const float *pi8 = v->pk + 8 * (size_t)i;
    const ms_lane h = ms_lane_set1(v->K.h), eps = ms_lane_set1(sqrtf(v->eps2));
    const ms_lane pi = ms_lane_set1(pi8[3]);
    int j[LANES];
    for (int l = 0; l < LANES; ++l)
        j[l] = gidx[l] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    ms_lane px, py, pz, pj, ux, uy, uz, irj;
    ms_lane_records8(v->pk, j, &px, &py, &pz, &pj, &ux, &uy, &uz, &irj);
    reflect_axis(gidx, 0, wall[0], &px, &ux);
    reflect_axis(gidx, 1, wall[1], &py, &uy);
    reflect_axis(gidx, 2, wall[2], &pz, &uz);
    const ms_lane r = ms_lane_sqrt(ms_lane_load(gr2));
    const ms_lane hr = ms_lane_kernel_hr(h, r);
    const ms_lane fv = ms_lane_mul(irj, hr);
    if (pressure) { /* see sums_of */
        const ms_lane fp =
            ms_lane_div(ms_lane_mul(ms_lane_mul(ms_lane_add(pi, pj), fv), hr), ms_lane_max(r, eps));
        a->px = ms_lane_add(a->px, ms_lane_mul(fp, ms_lane_sub(ms_lane_set1(pi8[0]), px)));
        a->py = ms_lane_add(a->py, ms_lane_mul(fp, ms_lane_sub(ms_lane_set1(pi8[1]), py)));
        a->pz = ms_lane_add(a->pz, ms_lane_mul(fp, ms_lane_sub(ms_lane_set1(pi8[2]), pz)));
    }
    a->vx = ms_lane_add(a->vx, ms_lane_mul(fv, ms_lane_sub(ux, ms_lane_set1(pi8[4]))));
    a->vy = ms_lane_add(a->vy, ms_lane_mul(fv, ms_lane_sub(uy, ms_lane_set1(pi8[5]))));
    a->vz = ms_lane_add(a->vz, ms_lane_mul(fv, ms_lane_sub(uz, ms_lane_set1(pi8[6]))));
    a->d = ms_lane_add(a->d, fv);
}

/* Particle i's sums over its real run (n entries, padded) and, when gn >
 * 0, its wall-image run (gn, padded), entry k of each in lane k % 16,
 * the lanes summed once; with out, the lanes are stored there instead
 * (the caller adds shape images). The neighbours' data come from the
 * packed copy v->pk (x, y, z, p, vx, vy, vz, 1/rho), 16 records at a
 * time.
 *
 * Under DFSPH (pressure 0) the pressure terms are skipped: the law's p is
 * 0 in this pass (the solves of dfsph.c act on the velocities), so each
 * term fp (x_i - x_j) is +0 or -0 and the lanes stay +0 (they start at
 * +0, and +0 + -0 = +0): skipping them gives the same bits, without the
 * pass's only division, and the real neighbours' loop loads the records'
 * velocity halves alone. */
static inline PASS_INLINE pair_sums sums_of(const ms_volume *v, const int *restrict idx,
                                            const float *restrict r2s, int n, int i,
                                            const int *restrict gidx, const float *restrict gr2,
                                            int gn, const float wall[3], pair_lanes *out)
{
    const int pressure = v->desc.pressure != MS_PRESSURE_DFSPH;
    const float *pi8 = v->pk + 8 * (size_t)i;
    const ms_lane xi = ms_lane_set1(pi8[0]), yi = ms_lane_set1(pi8[1]), zi = ms_lane_set1(pi8[2]);
    const ms_lane uxi = ms_lane_set1(pi8[4]), uyi = ms_lane_set1(pi8[5]),
                  uzi = ms_lane_set1(pi8[6]);
    const ms_lane pi = ms_lane_set1(pi8[3]), h = ms_lane_set1(v->K.h);
    const ms_lane eps = ms_lane_set1(sqrtf(v->eps2)), zero = ms_lane_zero();
    lanes7 a = {zero, zero, zero, zero, zero, zero, zero};
    for (int k = 0; k < n && !pressure; k += LANES) { /* DFSPH: the viscosity */
        ms_lane uxj, uyj, uzj, irj;
        /* the streamed r^2 and indices 512 entries ahead, as dfsph.c's
         * loops (hints: the same bits) */
        ms_lane_prefetch(ahead(r2s + k));
        ms_lane_prefetch(ahead(idx + k));
        ms_lane_records4(v->pk + 4, idx + k, &uxj, &uyj, &uzj, &irj); /* vx, vy, vz, 1/rho */
        const ms_lane r = ms_lane_sqrt(ms_lane_load(r2s + k));
        const ms_lane fv = ms_lane_mul(irj, ms_lane_kernel_hr(h, r));
        a.vx = ms_lane_add(a.vx, ms_lane_mul(fv, ms_lane_sub(uxj, uxi)));
        a.vy = ms_lane_add(a.vy, ms_lane_mul(fv, ms_lane_sub(uyj, uyi)));
        a.vz = ms_lane_add(a.vz, ms_lane_mul(fv, ms_lane_sub(uzj, uzi)));
        a.d = ms_lane_add(a.d, fv);
    }
    for (int k = 0; k < n && pressure; k += LANES) {
        ms_lane xj, yj, zj, pj, uxj, uyj, uzj, irj;
        ms_lane_records8(v->pk, idx + k, &xj, &yj, &zj, &pj, &uxj, &uyj, &uzj, &irj);
        const ms_lane dx = ms_lane_sub(xi, xj), dy = ms_lane_sub(yi, yj), dz = ms_lane_sub(zi, zj);
        const ms_lane r = ms_lane_sqrt(ms_lane_load(r2s + k));
        const ms_lane hr = ms_lane_kernel_hr(h, r);
        const ms_lane fv = ms_lane_mul(irj, hr);
        const ms_lane fp =
            ms_lane_div(ms_lane_mul(ms_lane_mul(ms_lane_add(pi, pj), fv), hr), ms_lane_max(r, eps));
        a.px = ms_lane_add(a.px, ms_lane_mul(fp, dx));
        a.py = ms_lane_add(a.py, ms_lane_mul(fp, dy));
        a.pz = ms_lane_add(a.pz, ms_lane_mul(fp, dz));
        a.vx = ms_lane_add(a.vx, ms_lane_mul(fv, ms_lane_sub(uxj, uxi)));
        a.vy = ms_lane_add(a.vy, ms_lane_mul(fv, ms_lane_sub(uyj, uyi)));
        a.vz = ms_lane_add(a.vz, ms_lane_mul(fv, ms_lane_sub(uzj, uzi)));
        a.d = ms_lane_add(a.d, fv);
    }
    for (int k = 0; k < gn; k += LANES) /* the image list is padded to 16 */
        image_terms(v, gidx + k, gr2 + k, i, wall, pressure, &a);
    if (out) {
        ms_lane_store(out->px, a.px);
        ms_lane_store(out->py, a.py);
        ms_lane_store(out->pz, a.pz);
        ms_lane_store(out->vx, a.vx);
        ms_lane_store(out->vy, a.vy);
        ms_lane_store(out->vz, a.vz);
        ms_lane_store(out->d, a.d);
        pair_sums none = {0};
        return none;
    }
    pair_sums s = {ms_lane_sum(a.px), ms_lane_sum(a.py), ms_lane_sum(a.pz), ms_lane_sum(a.vx),
                   ms_lane_sum(a.vy), ms_lane_sum(a.vz), ms_lane_sum(a.d)};
    return s;
}

/* The seven terms t of an entry of particle i's image list (a wall image
 * or a shape image), one at a time: the same operations as image_terms'
 * lanes. */
static inline void image_term(const ms_volume *v, int gk, float r2, int i, const float wall[3],
                              float t[7])
{
    const float h = v->K.h, eps = sqrtf(v->eps2);
    const float xi = v->x[i], yi = v->y[i], zi = v->z[i];
    const unsigned f = (unsigned)gk >> MS_VOLUME_IMAGE_SHIFT;
    const int j = gk & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
    float pj[3] = {v->x[j], v->y[j], v->z[j]}, uj[3] = {v->vx[j], v->vy[j], v->vz[j]};
    if (f == MS_VOLUME_IMAGE_SHAPE) {
        /* across the tangent plane (point c, normal nn) of the nearest
         * shape; velocity mirrored in the shape's frame */
        const float dd = v->c_d[i];
        const float nn[3] = {v->c_nx[i], v->c_ny[i], v->c_nz[i]};
        const float vs[3] = {v->c_vx[i], v->c_vy[i], v->c_vz[i]};
        const float c[3] = {xi - dd * nn[0], yi - dd * nn[1], zi - dd * nn[2]};
        float sp = (pj[0] - c[0]) * nn[0] + (pj[1] - c[1]) * nn[1] + (pj[2] - c[2]) * nn[2];
        float su = (uj[0] - vs[0]) * nn[0] + (uj[1] - vs[1]) * nn[1] + (uj[2] - vs[2]) * nn[2];
        for (int q = 0; q < 3; ++q) {
            pj[q] -= 2.0f * sp * nn[q];
            uj[q] -= 2.0f * su * nn[q];
        }
    } else {
        for (int q = 0; q < 3; ++q)
            if (f & (1u << q)) {
                pj[q] = 2.0f * wall[q] - pj[q];
                uj[q] = -uj[q];
            }
    }
    const float r = sqrtf(r2);
    const float hr = ms_kernel_hr(h, r);
    const float fv = v->inv_rho[j] * hr;
    const float fp = (v->prs[i] + v->prs[j]) * fv * hr / (r > eps ? r : eps);
    t[0] = fp * (xi - pj[0]);
    t[1] = fp * (yi - pj[1]);
    t[2] = fp * (zi - pj[2]);
    t[3] = fv * (uj[0] - v->vx[i]);
    t[4] = fv * (uj[1] - v->vy[i]);
    t[5] = fv * (uj[2] - v->vz[i]);
    t[6] = fv;
}

/* The image terms of entries [0, gn) of the image list, gn padded to 16,
 * entry k into lane k % 16. */
static void image_lanes(const ms_volume *v, const int *restrict gidx, const float *restrict gr2,
                        int gn, int i, const float wall[3], pair_lanes *restrict a)
{
    for (int k = 0; k < gn; ++k) {
        const int l = k % LANES;
        float t[7];
        image_term(v, gidx[k], gr2[k], i, wall, t);
        a->px[l] += t[0];
        a->py[l] += t[1];
        a->pz[l] += t[2];
        a->vx[l] += t[3];
        a->vy[l] += t[4];
        a->vz[l] += t[5];
        a->d[l] += t[6];
    }
}

static pair_sums lanes_sum(const pair_lanes *a)
{
    pair_sums s = {ms_lanes_sum(a->px), ms_lanes_sum(a->py), ms_lanes_sum(a->pz),
                   ms_lanes_sum(a->vx), ms_lanes_sum(a->vy), ms_lanes_sum(a->vz),
                   ms_lanes_sum(a->d)};
    return s;
}

/* Particle i's acceleration from its sums (eqs. 13, 14), the boundary
 * field and gravity; its viscous rate for the time-step bound. */
static inline PASS_INLINE void accel_of(ms_volume *v, int i, pair_sums s, float cp, float cv)
{
    const float ri = v->inv_rho[i];
    s.d -= ri * v->K.h; /* the list holds the particle itself: not a neighbour */
    v->ax[i] = cp * ri * s.px + cv * ri * s.vx + v->b_ax[i] + v->desc.gravity[0];
    v->ay[i] = cp * ri * s.py + cv * ri * s.vy + v->b_ay[i] + v->desc.gravity[1];
    v->az[i] = cp * ri * s.pz + cv * ri * s.vz + v->b_az[i] + v->desc.gravity[2];
    v->visc_rate[i] = cv * ri * (s.d > 0.0f ? s.d : 0.0f);
}

/* The force pass of particles [b, e): each particle's real neighbours
 * (in its list: padded with itself at r = h, adding 0) and wall images
 * in lanes, a particle at a shape its shape images one by one. */
static void forces_range(ms_volume *v, int part, int b, int e)
{
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    const float cp = 0.5f * v->press_scale * v->mass * v->K.spiky_grad;  /* eq. 13 */
    const float cv = 0.5f * v->mass * v->K.visc_lap * v->desc.viscosity; /* eq. 14 */
    for (int i = b; i < e; ++i) {
        const int *idx = lst->idx + v->nl_begin[i], *gidx = gst->idx + v->gl_begin[i];
        const float *r2s = lst->r2 + v->nl_begin[i], *gr2 = gst->r2 + v->gl_begin[i];
        const int n = padded(v->nl_count[i]), gn = padded(v->gl_count[i]);
        float wall[3] = {0.0f, 0.0f, 0.0f};
        if (gn)
            ms_volume_walls_near(v, v->x[i], v->y[i], v->z[i], wall);
        if (!gn || !(v->c_d[i] < v->K.h)) { /* wall images only */
            accel_of(v, i, sums_of(v, idx, r2s, n, i, gidx, gr2, gn, wall, NULL), cp, cv);
            continue;
        }
        pair_lanes a;
        sums_of(v, idx, r2s, n, i, gidx, gr2, 0, wall, &a);
        image_lanes(v, gidx, gr2, gn, i, wall, &a);
        accel_of(v, i, lanes_sum(&a), cp, cv);
    }
}

/* ---- DFSPH (dfsph.c: the factors, the divergence and density solves) ---- */

/* The Jacobi diagonal of particle i: how much rho*_i falls per unit of s_i
 * when i moves by -(s_i/dt) G_i (G_i = sum_k m grad W_ik over the real
 * neighbours and the images) and each real neighbour j answers with
 * +(s_i/dt) m grad W_ij (Bender & Koschier 2017, eq. 9):
 *     |G_i|^2 + sum_j |m grad W_ij|^2
 * An image moves as the mirror M of its particle: an image of i itself
 * adds -m (M G_i) . grad W_ii'; an image j' of a real neighbour j adds
 * m^2 (M grad W_ij) . grad W_ij' twice (j' follows j's answer, and j
 * answers to i's image in its own list at the same distance). Without
 * them a particle in a corner (seven images of itself) had its diagonal
 * underestimated several times over and a tank at rest blew up.
 * Returns sum_k g_ik r_ik^2 over the same entries: the trace of i's
 * gradient moment in units of 1 / (m G) (the pressure read-out's M).
 * Also sums the warm start's sum_k (w_i + w_k) g_ik (x_i - x_k) into
 * df_wx..z (w: df_sum, set by warm_weights; the header). */

static inline MS_DFSPH_INLINE float factors_of(ms_volume *v, const ms_nlist *lst,
                                               const ms_nlist *gst, float *restrict cgx,
                                               float *restrict cgy, float *restrict cgz,
                                               float *restrict img, int i)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const float *restrict r2s = lst->r2 + v->nl_begin[i];
    const int n = ms_dfsph_padded(v->nl_count[i]);
    const float h = v->K.h, h2 = v->K.h2, eps = sqrtf(v->eps2);
    const float xi = x[i], yi = y[i], zi = z[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    const float *restrict w = v->df_sum; /* the warm start's s (warm_weights) */
    const float wi = w[i];
    float gx, gy, gz, q; /* in units of (m G)^2: grad W = -G g d */
    float mom;           /* sum_j g r^2: the gradient moment's trace */
    float ax, ay, az;    /* the warm start's sum */
    {
        /* the neighbours' positions as the 16-byte records x, y, z, p of
         * v->pk (the density pass filled them from the positions the
         * solves use); the fourth float holds the warm start's s then
         * (warm_weights): w_j without a gather */
        const ms_lane hv = ms_lane_set1(h), ev = ms_lane_set1(eps), zero = ms_lane_zero();
        const ms_lane xv = ms_lane_set1(xi), yv = ms_lane_set1(yi), zv = ms_lane_set1(zi);
        const ms_lane wv = ms_lane_set1(wi);
        ms_lane sx = zero, sy = zero, sz = zero, sq = zero, sm = zero, wx = zero, wy = zero,
                wz = zero;
        for (int k = 0; k < n; k += LANES) {
            ms_lane xj, yj, zj, pj;
            ms_lane_prefetch(ahead(r2s + k));
            ms_lane_prefetch(ahead(idx + k));
            ms_lane_records4(v->pk, idx + k, &xj, &yj, &zj, &pj);
            const ms_lane r2 = ms_lane_load(r2s + k);
            const ms_lane g = ms_lane_grad_factor(ms_lane_sqrt(r2), hv, ev);
            const ms_lane dx = ms_lane_mul(g, ms_lane_sub(xv, xj)),
                          dy = ms_lane_mul(g, ms_lane_sub(yv, yj)),
                          dz = ms_lane_mul(g, ms_lane_sub(zv, zj));
            ms_lane_store(cgx + k, dx);
            ms_lane_store(cgy + k, dy);
            ms_lane_store(cgz + k, dz);
            sx = ms_lane_add(sx, dx);
            sy = ms_lane_add(sy, dy);
            sz = ms_lane_add(sz, dz);
            sq = ms_lane_add(sq, ms_lane_mul(ms_lane_mul(g, g), r2));
            sm = ms_lane_add(sm, ms_lane_mul(g, r2));
            const ms_lane f = ms_lane_add(wv, pj);
            wx = ms_lane_add(wx, ms_lane_mul(f, dx));
            wy = ms_lane_add(wy, ms_lane_mul(f, dy));
            wz = ms_lane_add(wz, ms_lane_mul(f, dz));
        }
        gx = ms_lane_sum(sx);
        gy = ms_lane_sum(sy);
        gz = ms_lane_sum(sz);
        q = ms_lane_sum(sq);
        mom = ms_lane_sum(sm);
        ax = ms_lane_sum(wx);
        ay = ms_lane_sum(wy);
        az = ms_lane_sum(wz);
    }
    if (v->coincident > 0)
        for (int k = 0; k < v->nl_count[i]; ++k) {
            float u[3];
            if (coincident(v, i, idx[k], r2s[k], u)) {
                cgx[k] = u[0]; /* the cached pair term of the solves' passes */
                cgy[k] = u[1];
                cgz[k] = u[2];
                gx += u[0];
                gy += u[1];
                gz += u[2];
                q += h2 * h2;
                const float f = wi + w[idx[k]];
                ax += f * u[0];
                ay += f * u[1];
                az += f * u[2];
            }
        }
    float qm = 0.0f; /* the images' mirror terms */
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *gr2 = gst->r2 + v->gl_begin[i];
        float wall[3];
        ms_volume_walls_near(v, xi, yi, zi, wall);
        float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            float pj[3], uj[3];
            image_of(v, i, gidx[k], wall, pj, uj);
            float g = grad_factor(gr2[k], h, eps);
            c[4 * k] = g; /* the image's terms for the solves' passes */
            c[4 * k + 1] = xi - pj[0];
            c[4 * k + 2] = yi - pj[1];
            c[4 * k + 3] = zi - pj[2];
            gx += g * (xi - pj[0]);
            gy += g * (yi - pj[1]);
            gz += g * (zi - pj[2]);
            /* the warm start's term as apply_of takes an image's */
            const float f = (wi + w[gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1)]) * g;
            ax += f * c[4 * k + 1];
            ay += f * c[4 * k + 2];
            az += f * c[4 * k + 3];
            mom += g * (c[4 * k + 1] * c[4 * k + 1] + c[4 * k + 2] * c[4 * k + 2] +
                        c[4 * k + 3] * c[4 * k + 3]);
        }
        for (int k = 0; k < gn; ++k) {
            const int j = gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
            const unsigned f = (unsigned)gidx[k] >> MS_VOLUME_IMAGE_SHIFT;
            /* the image's g and x_i - x_j' as the first loop stored them
             * (the same values; image_of and grad_factor once an image) */
            const float g = c[4 * k];
            const float d[3] = {c[4 * k + 1], c[4 * k + 2], c[4 * k + 3]};
            float u[3];
            float wt;
            if (j == i) { /* i's own image moves as M dv_i */
                u[0] = gx;
                u[1] = gy;
                u[2] = gz;
                wt = -1.0f;
            } else { /* j answers to i, and to i's image in j's list */
                u[0] = xi - x[j];
                u[1] = yi - y[j];
                u[2] = zi - z[j];
                float r2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
                if (!(r2 < h2))
                    continue;
                wt = 2.0f * grad_factor(r2, h, eps);
            }
            mirror(v, i, f, u);
            qm += wt * g * (u[0] * d[0] + u[1] * d[1] + u[2] * d[2]);
        }
    }
    const float mg = v->mass * v->K.spiky_grad;
    /* the mirror terms only ever stiffen the diagonal: a negative sum
     * (a particle pressed onto a wall, its own image nearly on it) would
     * shrink it towards 0 and blow the update up */
    float den = mg * mg * (gx * gx + gy * gy + gz * gz + q + (qm > 0.0f ? qm : 0.0f));
    v->df_inv_diag[i] = den > 0.0f ? 1.0f / den : 0.0f;
    v->df_wx[i] = ax;
    v->df_wy[i] = ay;
    v->df_wz[i] = az;
    return mom;
}

/* sum_j (v_i - v_j) . (x_i - x_j) g_ij over real neighbours and images:
 * D rho_i/Dt = -m G times it. */
static inline MS_DFSPH_INLINE float divergence_sum(const ms_volume *v, const ms_nlist *lst,
                                                   const ms_nlist *gst, const float *restrict cgx,
                                                   const float *restrict cgy,
                                                   const float *restrict cgz,
                                                   const float *restrict img, int i)
{
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const int n = ms_dfsph_padded(v->nl_count[i]);
    const float ui = vx[i], wi = vy[i], ti = vz[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    float s;
    {
        /* the neighbours' velocities as the 16-byte records p, vx, vy, vz
         * of v->pk (apply_of and warm_kick keep them; the p slot is not
         * read) */
        const ms_lane u = ms_lane_set1(ui), w = ms_lane_set1(wi), t = ms_lane_set1(ti);
        ms_lane a = ms_lane_zero();
        for (int k = 0; k < n; k += LANES) {
            ms_lane sj, uj, wj, tj;
            ms_lane_prefetch(ahead(cgx + k));
            ms_lane_prefetch(ahead(cgy + k));
            ms_lane_prefetch(ahead(cgz + k));
            ms_lane_prefetch(ahead(idx + k));
            ms_lane_records4(v->pk + 3, idx + k, &sj, &uj, &wj, &tj);
            (void)sj;
            ms_lane d = ms_lane_mul(ms_lane_sub(u, uj), ms_lane_load(cgx + k));
            d = ms_lane_add(d, ms_lane_mul(ms_lane_sub(w, wj), ms_lane_load(cgy + k)));
            d = ms_lane_add(d, ms_lane_mul(ms_lane_sub(t, tj), ms_lane_load(cgz + k)));
            a = ms_lane_add(a, d);
        }
        s = ms_lane_sum(a);
    }
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            float uj[3];
            image_velocity(v, i, gidx[k], uj);
            s += c[4 * k] * ((ui - uj[0]) * c[4 * k + 1] + (wi - uj[1]) * c[4 * k + 2] +
                             (ti - uj[2]) * c[4 * k + 3]);
        }
    }
    return s;
}

/* v_i += scale m G sum_j (s_i + s_j) g_ij (x_i - x_j): the pressure term. */
static inline MS_DFSPH_INLINE void apply_of(ms_volume *v, const ms_nlist *lst, const ms_nlist *gst,
                                            const float *restrict cgx, const float *restrict cgy,
                                            const float *restrict cgz, const float *restrict img,
                                            int i, float scale)
{
    const float *restrict s = v->df_s;
    const int *restrict idx = lst->idx + v->nl_begin[i];
    const int n = ms_dfsph_padded(v->nl_count[i]);
    const float si = s[i];
    cgx += v->nl_begin[i];
    cgy += v->nl_begin[i];
    cgz += v->nl_begin[i];
    float sum[3];
    {
        /* s_j by a gather from df_s: the update reads nothing else of a
         * neighbour (sixteen record loads and their transpose, for one
         * value of four, took 1/0.88 the time on fig1 under DFSPH) */
        const ms_lane sv = ms_lane_set1(si);
        ms_lane a = ms_lane_zero(), b = a, c = a;
        for (int k = 0; k < n; k += LANES) {
            ms_lane_prefetch(ahead(cgx + k));
            ms_lane_prefetch(ahead(cgy + k));
            ms_lane_prefetch(ahead(cgz + k));
            ms_lane_prefetch(ahead(idx + k));
            const ms_lane f = ms_lane_add(sv, ms_lane_gather(s, idx + k));
            a = ms_lane_add(a, ms_lane_mul(f, ms_lane_load(cgx + k)));
            b = ms_lane_add(b, ms_lane_mul(f, ms_lane_load(cgy + k)));
            c = ms_lane_add(c, ms_lane_mul(f, ms_lane_load(cgz + k)));
        }
        sum[0] = ms_lane_sum(a);
        sum[1] = ms_lane_sum(b);
        sum[2] = ms_lane_sum(c);
    }
    float sx = sum[0], sy = sum[1], sz = sum[2];
    const int gn = v->gl_count[i];
    if (gn) {
        const int *gidx = gst->idx + v->gl_begin[i];
        const float *c = img + 4 * (size_t)v->gl_begin[i];
        for (int k = 0; k < gn; ++k) {
            const int j = gidx[k] & ((1 << MS_VOLUME_IMAGE_SHIFT) - 1);
            float sb = si + s[j];
            float f = sb * c[4 * k];
            sx += f * c[4 * k + 1];
            sy += f * c[4 * k + 2];
            sz += f * c[4 * k + 3];
        }
    }
    const float c = scale * v->mass * v->K.spiky_grad;
    set_capped(v, i, v->vx[i] + c * sx, v->vy[i] + c * sy, v->vz[i] + c * sz);
    /* the running total of s, and the new velocity into the packed copy
     * the error loops read: no pass of an update reads pk (the
     * update gathers s from df_s), so i's record may change under it:
     * one per-particle pass fewer an iteration */
    v->df_sum[i] += si;
    pack_velocity(v, i);
}

/* The divergence error of particle i (D rho_i/Dt, 0 at the surface and
 * where the liquid expands) into its iterate s_i; returns dt e_i / rho0
 * quantised. */
static inline MS_DFSPH_INLINE int64_t divergence_error_of(ms_volume *v, const ms_nlist *lst,
                                                          const ms_nlist *gst, const float *cgx,
                                                          const float *cgy, const float *cgz,
                                                          const float *restrict img, int i,
                                                          float dt)
{
    float ei = 0.0f;
    if (!ms_volume_is_surface(v, i)) {
        const float mg = v->mass * v->K.spiky_grad;
        ei = -mg * divergence_sum(v, lst, gst, cgx, cgy, cgz, img, i); /* D rho_i/Dt */
        ei = ei > 0.0f ? ei : 0.0f;
    }
    v->df_s[i] = ei * v->df_inv_diag[i];
    return quantise(dt * ei / v->desc.rest_density);
}

/* One DFSPH pass of ctx->kind over particles [b, e) of part `part`;
 * its error (and moments) into ctx. */
static void dfsph_range(ms_dfsph_ctx *ctx, int part, int b, int e)
{
    ms_volume *v = ctx->v;
    const ms_nlist *lst = &v->lists[part], *gst = &v->ghosts[part];
    float *cgx = v->df_grad[part], *cgy = cgx + v->df_grad_cap[part],
          *cgz = cgy + v->df_grad_cap[part];
    float *img = v->df_img[part];
    const float rho0 = v->desc.rest_density, mg = v->mass * v->K.spiky_grad, dt = ctx->dt;
    int64_t err = 0;
    switch (ctx->kind) {
    case F_FACTORS: { /* and the divergence solve's first error, while i's terms are hot */
        /* M_i = V G sum_k g r^2 / 3, V = m / rho0: i's gradient moment
         * (the trace's third), as volume.c's lattice M */
        const float mvol = mg / (3.0f * rho0);
        int64_t mom = 0;
        int nmom = 0;
        for (int i = b; i < e; ++i) {
            const float mi = mvol * factors_of(v, lst, gst, cgx, cgy, cgz, img, i);
            err += divergence_error_of(v, lst, gst, cgx, cgy, cgz, img, i, dt);
            if (!ms_volume_is_surface(v, i)) {
                mom += quantise(mi);
                nmom++;
            }
        }
        ctx->mom[part] = mom;
        ctx->nmom[part] = nmom;
        break;
    }
    case F_DENSITY_ERROR: {
        /* The compression one sub-step may remove, rho0 c0 dt / h: a
         * compressed liquid of sound speed c0 relaxes at about c0, one
         * kernel radius in h / c0. Without it a sub-step tries to remove
         * all of it at once, whatever dt: 300 particles at one point (179
         * times rest density) left at 136 m/s with 3800 J; with it, at
         * most 10 m/s and 65 J (the ideal-gas law: 39 m/s, 1278 J). It
         * only binds when rho/rho0 - 1 > c0 dt / h, near 1 for the
         * shipped scenes' sub-steps, so never in their flows. */
        const float cap = rho0 * v->c0 * dt / v->K.h;
        for (int i = b; i < e; ++i) {
            /* rho*_i - rho0 = rho_i - rho0 + dt D rho_i/Dt */
            float ci = v->rho[i] - rho0;
            ci = ci < cap ? ci : cap;
            float ei = ci - dt * mg * divergence_sum(v, lst, gst, cgx, cgy, cgz, img, i);
            ei = ei > 0.0f ? ei : 0.0f;
            /* the Jacobi update plus, while i is still compressed, the
             * momentum share of its last one (df_s still holds it; both
             * >= 0: the total only grows; the header) */
            v->df_s[i] = ei > 0.0f ? ei * v->df_inv_diag[i] + ctx->momentum * v->df_s[i] : 0.0f;
            err += quantise(ei / rho0); /* compression only: quantise clamps at 0 */
        }
        break;
    }
    case F_DIVERGENCE_ERROR:
        for (int i = b; i < e; ++i)
            err += divergence_error_of(v, lst, gst, cgx, cgy, cgz, img, i, dt);
        break;
    case F_APPLY:
        for (int i = b; i < e; ++i)
            apply_of(v, lst, gst, cgx, cgy, cgz, img, i, ctx->scale);
        break;
    case F_PRESSURE: {
        /* the pressure the liquid exerts (eq. 13's convention): both
         * solves' impulses of this sub-step as a pressure over it, its
         * mean over the step's sub-steps so far into prs (see the header) */
        const float inv_dt2 = 1.0f / (dt * dt), inv_dt = 1.0f / dt, w = ctx->weight;
        for (int i = b; i < e; ++i) {
            const float p = ctx->moment * (v->df_sum[i] * inv_dt2 + v->df_div_sum[i] * inv_dt) *
                            v->rho[i] * v->rho[i];
            float *mean = &v->df_pmean[v->id[i]];
            *mean = ctx->restart ? p : *mean + w * (p - *mean);
            v->prs[i] = *mean;
            v->pk[8 * (size_t)i + 3] = v->prs[i];
            v->df_warm[v->id[i]] = v->df_sum[i]; /* the next sub-step's start */
        }
        break;
    }
    }
    ctx->err[part] = err;
}

const ms_volume_passes PASSES = {
    .density = density_range,
    .forces = forces_range,
    .dfsph = dfsph_range,
};

#if MS_LANE_ISA == MS_LANE_ISA_C
const ms_volume_passes *ms_volume_passes_of(int isa)
{
    switch (isa) {
    case MS_VOLUME_ISA_C:
        return &ms_volume_passes_c;
#if MS_VOLUME_LANES_X86
    case MS_VOLUME_ISA_SSE2:
        return &ms_volume_passes_sse2;
    case MS_VOLUME_ISA_AVX2:
        return &ms_volume_passes_avx2;
    case MS_VOLUME_ISA_AVX512:
        return &ms_volume_passes_avx512;
#endif
#if MS_VOLUME_LANES_NEON
    case MS_VOLUME_ISA_NEON:
        return &ms_volume_passes_neon;
#endif
    default:
        return NULL;
    }
}
#endif
