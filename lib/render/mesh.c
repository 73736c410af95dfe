/* The height field as a triangle mesh: one vertex per cell centre, world
 * position and the unit normal (-dh/dx, -dh/dy, 1) / |.| from central
 * differences (one-sided at the edges). The outermost vertices are moved
 * out to the grid's edge so the surface meets the pool walls. */
#include <math.h>

#include "core/internal.h"
#include "render/render_internal.h"

long ms_mesh_build(const float *h, const ms_grid *g, float floor_z, float *restrict vertices)
{
    const int nx = g->nx, ny = g->ny;
    const float x0 = g->origin[0], y0 = g->origin[1], dx = g->dx, dy = g->dy;
    for (int j = 0; j < ny; ++j) {
        const float *row = h + (size_t)j * (size_t)nx;
        const float *below = h + (size_t)(j > 0 ? j - 1 : j) * (size_t)nx;
        const float *above = h + (size_t)(j < ny - 1 ? j + 1 : j) * (size_t)nx;
        /* 1 / (2 dy) inside, 1 / dy at the edges */
        const float iy = (j > 0 && j < ny - 1 ? 0.5f : 1.0f) / dy;
        const float y = j == 0 ? y0 : j == ny - 1 ? y0 + (float)ny * dy : y0 + ((float)j + 0.5f) * dy;
        float *v = vertices + (size_t)j * (size_t)nx * 6;
        for (int i = 0; i < nx; ++i) {
            int il = i > 0 ? i - 1 : i, ir = i < nx - 1 ? i + 1 : i;
            float gx = (row[ir] - row[il]) / ((float)(ir - il) * dx);
            float gy = (above[i] - below[i]) * iy;
            float inv = 1.0f / sqrtf(gx * gx + gy * gy + 1.0f);
            float x = i == 0 ? x0 : i == nx - 1 ? x0 + (float)nx * dx : x0 + ((float)i + 0.5f) * dx;
            v[6 * i + 0] = x;
            v[6 * i + 1] = y;
            v[6 * i + 2] = floor_z + row[i];
            v[6 * i + 3] = -gx * inv;
            v[6 * i + 4] = -gy * inv;
            v[6 * i + 5] = inv;
        }
    }
    /* a NaN or infinity anywhere shows in the vertices */
    for (size_t k = 0; k < (size_t)nx * (size_t)ny; ++k)
        if (!isfinite(h[k]))
            return (long)k;
    return -1;
}

void ms_mesh_indices(int nx, int ny, unsigned *restrict idx)
{
    size_t k = 0;
    for (int j = 0; j + 1 < ny; ++j)
        for (int i = 0; i + 1 < nx; ++i) {
            unsigned a = (unsigned)(j * nx + i), b = a + 1, c = a + (unsigned)nx, d = c + 1;
            /* counter-clockwise seen from above (+z) */
            idx[k++] = a, idx[k++] = b, idx[k++] = d;
            idx[k++] = a, idx[k++] = d, idx[k++] = c;
        }
}
