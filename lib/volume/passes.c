/* The SPH passes over the lane type (lane.h), written once. This file is
 * the plain-C instance; passes_<isa>.c include it again with MS_LANE_ISA
 * set and are compiled with that instruction set's flags (Makefile), so
 * the one algorithm below is each ISA's code. Each pass keeps the order
 * of its sums fixed (entry k of a run in lane k % 16, the lanes summed
 * once in ms_lane_sum's tree), so every instance gives the same bits. */
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

const ms_volume_passes PASSES = {
    .density = density_range,
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
