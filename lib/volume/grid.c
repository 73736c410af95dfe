/* The neighbour grid (paper 3.3: "an additional space dividing grid with
 * grid length h"): cubic cells of edge h over the domain plus one cell of
 * padding on each side, so the 27 cells around any particle's cell exist.
 * Rebuilt at every sub-step by a stable counting sort that reorders the
 * particle arrays into cell order (x fastest), so the three cells of a
 * row (x-1, x, x+1) are one contiguous run of particles. */
#include <string.h>

#include "volume/volume_internal.h"

#define SWAP(T, a, b)  \
    do {               \
        T *t_ = (a);   \
        (a) = (b);     \
        (b) = t_;      \
    } while (0)

void ms_volume_grid_build(ms_volume *v)
{
    int n = v->n;
    long nc = v->ncells;
    int *start = v->cell_start, *fill = v->cell_fill;
    int *key = v->nbr; /* scratch: recomputed by the density pass */
    memset(fill, 0, (size_t)nc * sizeof *fill);
    for (int i = 0; i < n; ++i) {
        long c = ms_volume_cell_of(v, v->x[i], v->y[i], v->z[i]);
        key[i] = (int)c;
        fill[c]++;
    }
    int sum = 0;
    for (long c = 0; c < nc; ++c) {
        start[c] = sum;
        sum += fill[c];
        fill[c] = start[c];
    }
    start[nc] = sum;
    for (int i = 0; i < n; ++i) {
        int c = key[i];
        int d = fill[c]++;
        v->x2[d] = v->x[i];
        v->y2[d] = v->y[i];
        v->z2[d] = v->z[i];
        v->vx2[d] = v->vx[i];
        v->vy2[d] = v->vy[i];
        v->vz2[d] = v->vz[i];
        v->id2[d] = v->id[i];
        v->cell[d] = c;
    }
    SWAP(float, v->x, v->x2);
    SWAP(float, v->y, v->y2);
    SWAP(float, v->z, v->z2);
    SWAP(float, v->vx, v->vx2);
    SWAP(float, v->vy, v->vy2);
    SWAP(float, v->vz, v->vz2);
    SWAP(int, v->id, v->id2);
    v->counts_valid = 0;
}
