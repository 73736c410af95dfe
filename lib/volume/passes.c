/* The SPH passes over the lane type (lane.h), written once. This file is
 * the plain-C instance; passes_<isa>.c include it again with MS_LANE_ISA
 * set and are compiled with that instruction set's flags (Makefile), so
 * the one algorithm below is each ISA's code. Each pass keeps the order
 * of its sums fixed (entry k of a run in lane k % 16, the lanes summed
 * once in ms_lane_sum's tree), so every instance gives the same bits. */
#include <math.h>
#include <stdint.h>

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
/* The pair loops prefetch their streamed per-pair data (indices, r^2:
 * 4-byte entries) this many entries ahead (dfsph.c says how it was
 * measured). Hints only: the same bits. */
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
static inline float weight_runs(const ms_volume *v, const float *restrict r2, int n,
                                const float *restrict g2, int gn, int *coincident, int poly6)
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
static inline void weigh(ms_volume *v, const ms_nlist *L, const ms_nlist *G, int i, float mw,
                         int poly6, part_counts *c)
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
static inline void reflect_axis(const int32_t *gidx, int q, float wall, ms_lane *p, ms_lane *u)
{
    const ms_lmask m = ms_lane_test_bit(gidx, (int32_t)1 << (MS_VOLUME_IMAGE_SHIFT + q));
    *p = ms_lane_select(m, ms_lane_sub(ms_lane_set1(2.0f * wall), *p), *p);
    *u = ms_lane_select(m, ms_lane_neg(*u), *u);
}

/* The wall-image terms of entries [0, 16) of gidx/gr2 (no shape images),
 * added to the lanes a (entry l to lane l). */
static inline void image_terms(const ms_volume *v, const int *restrict gidx,
                               const float *restrict gr2, int i, const float wall[3], int pressure,
                               lanes7 *a)
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
static inline pair_sums sums_of(const ms_volume *v, const int *restrict idx,
                                const float *restrict r2s, int n, int i, const int *restrict gidx,
                                const float *restrict gr2, int gn, const float wall[3],
                                pair_lanes *out)
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
static inline void accel_of(ms_volume *v, int i, pair_sums s, float cp, float cv)
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

const ms_volume_passes PASSES = {
    .density = density_range,
    .forces = forces_range,
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
