/* The neighbour grid (paper 3.3: "an additional space dividing grid with
 * grid length h"): cubic cells of edge h over the domain plus one cell of
 * padding on each side, so the 27 cells around any particle's cell exist.
 * Rebuilt at every sub-step by a stable counting sort that reorders the
 * particle arrays into cell order (x fastest), so the three cells of a
 * row (x-1, x, x+1) are one contiguous run of particles; a step's first
 * sub-step takes instead the build the extraction made between steps
 * while nothing moved since (ms_volume_take_counted_pass, density.c).
 * With a pool the sort runs in the pool's chunks (on one thread it was the largest serial part of a sub-step, ~8 % of fig1_x10's frame):
 * each chunk counts its particles per cell, the counts are summed in
 * (cell, chunk) order, and each chunk places its particles after those of
 * the chunks before it in the same cell: the same permutation as the
 * sequential stable sort, so the same bytes. */
#include <string.h>

#include "volume/volume_internal.h"

#define SWAP(T, a, b) \
    do {              \
        T *t_ = (a);  \
        (a) = (b);    \
        (b) = t_;     \
    } while (0)

typedef struct sort_ctx {
    ms_volume *v;
    int used[MS_VOLUME_MAX_THREADS]; /* chunks that ran (a short loop runs as one) */
} sort_ctx;

/* Pass 1: the cell of each particle of [b, e) and the chunk's counts. */
static void count_part(void *ctxp, int part, int b, int e)
{
    sort_ctx *ctx = ctxp;
    ms_volume *v = ctx->v;
    int *restrict hist = v->grid_hist + (size_t)part * (size_t)v->ncells;
    int *restrict key = v->nbr;
    const ms_grid_shape g = ms_volume_grid_shape(v);
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    memset(hist, 0, (size_t)v->ncells * sizeof *hist);
    for (int i = b; i < e; ++i) {
        long c = ms_grid_cell(&g, x[i], y[i], z[i]);
        key[i] = (int)c;
        hist[c]++;
    }
    ctx->used[part] = 1;
}

/* The particles of [b, e) to their places: particle i to next[key[i]]++.
 * Between two sub-steps few particles change cells (measured: 2-16 of fig1's 2000 in most sub-steps, none in 30 %), so the particles
 * land in long runs of consecutive places: a run grows while the next
 * particle's place follows the run's last one (the same cell, or a new
 * cell whose next place is just after), and each run is copied with one
 * memcpy per array. The same places as one particle at a time (runs end
 * where next[] could differ; next[] of a run's cells is updated before the
 * next run reads it), so the same permutation. Measured before, the
 * per-particle copy was ~9 % of a 32k sub-step, stalled on its stores. */
static void place_range(ms_volume *v, int b, int e, int *restrict next, const int *restrict key)
{
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    const float *restrict vx = v->vx, *restrict vy = v->vy, *restrict vz = v->vz;
    const int *restrict id = v->id;
    float *restrict x2 = v->x2, *restrict y2 = v->y2, *restrict z2 = v->z2;
    float *restrict vx2 = v->vx2, *restrict vy2 = v->vy2, *restrict vz2 = v->vz2;
    int *restrict id2 = v->id2, *restrict cell = v->cell;
    int i = b;
    while (i < e) {
        const int d = next[key[i]]; /* the run [i, j) goes to [d, d + j - i) */
        int j = i + 1, c = key[i];
        next[c]++;
        while (j < e) {
            const int k = key[j];
            if (k != c) {
                if (next[k] != d + (j - i))
                    break;
                c = k;
            }
            next[c]++;
            ++j;
        }
        const size_t nf = (size_t)(j - i) * sizeof(float), ni = (size_t)(j - i) * sizeof(int);
        memcpy(x2 + d, x + i, nf);
        memcpy(y2 + d, y + i, nf);
        memcpy(z2 + d, z + i, nf);
        memcpy(vx2 + d, vx + i, nf);
        memcpy(vy2 + d, vy + i, nf);
        memcpy(vz2 + d, vz + i, nf);
        memcpy(id2 + d, id + i, ni);
        memcpy(cell + d, key + i, ni);
        i = j;
    }
}

/* Pass 2: the particles of [b, e) to their places, in order. */
static void place_part(void *ctxp, int part, int b, int e)
{
    ms_volume *v = ((sort_ctx *)ctxp)->v;
    place_range(v, b, e, v->grid_hist + (size_t)part * (size_t)v->ncells, v->nbr);
}

/* The pooled sort; 0 if it cannot run (no pool, few particles, or no
 * memory for the counts: the sequential sort then does it). */
static int grid_build_pooled(ms_volume *v)
{
    const int parts = ms_vpool_parts(v->pool);
    const long nc = v->ncells;
    /* a chunk's counts cost a pass over the cells: only where there are
     * not many more cells than particles */
    if (parts < 2 || v->n < 4096 || nc > 4L * v->n)
        return 0;
    const size_t need = (size_t)parts * (size_t)nc;
    if (need > v->grid_hist_cap) {
        int *h = ms_alloc_array(need, sizeof *h);
        if (!h)
            return 0;
        ms_free(v->grid_hist);
        v->grid_hist = h;
        v->grid_hist_cap = need;
    }
    sort_ctx ctx = {.v = v};
    ms_vpool_run(v->pool, count_part, &ctx, v->n);
    int *start = v->cell_start;
    int sum = 0;
    for (long c = 0; c < nc; ++c) { /* cell by cell, chunk by chunk */
        start[c] = sum;
        for (int p = 0; p < parts; ++p) {
            if (!ctx.used[p])
                continue;
            int *hc = v->grid_hist + (size_t)p * (size_t)nc + c;
            const int t = *hc;
            *hc = sum;
            sum += t;
        }
    }
    start[nc] = sum;
    ms_vpool_run(v->pool, place_part, &ctx, v->n);
    return 1;
}

void ms_counts_to_starts(int *start, int *fill, size_t cells)
{
    int sum = 0;
    for (size_t c = 0; c < cells; ++c) {
        start[c] = sum;
        sum += fill[c];
        fill[c] = start[c];
    }
    start[cells] = sum;
}

/* The sorted copies become the particle arrays. */
static void swap_sorted(ms_volume *v)
{
    SWAP(float, v->x, v->x2);
    SWAP(float, v->y, v->y2);
    SWAP(float, v->z, v->z2);
    SWAP(float, v->vx, v->vx2);
    SWAP(float, v->vy, v->vy2);
    SWAP(float, v->vz, v->vz2);
    SWAP(int, v->id, v->id2);
    v->counts_valid = 0;
}

void ms_volume_grid_build(ms_volume *v)
{
    if (grid_build_pooled(v)) {
        swap_sorted(v);
        return;
    }
    int n = v->n;
    long nc = v->ncells;
    int *start = v->cell_start, *fill = v->cell_fill;
    int *key = v->nbr; /* scratch: recomputed by the density pass */
    const ms_grid_shape g = ms_volume_grid_shape(v);
    const float *restrict x = v->x, *restrict y = v->y, *restrict z = v->z;
    memset(fill, 0, (size_t)nc * sizeof *fill);
    for (int i = 0; i < n; ++i) {
        long c = ms_grid_cell(&g, x[i], y[i], z[i]);
        key[i] = (int)c;
        fill[c]++;
    }
    ms_counts_to_starts(start, fill, (size_t)nc);
    place_range(v, 0, n, fill, key);
    swap_sorted(v);
}
