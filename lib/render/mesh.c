/* The height field as a triangle mesh: one vertex per cell centre, world
 * position and the unit normal (-dh/dx, -dh/dy, 1) / |.| from central
 * differences (one-sided at the edges). The outermost vertices are moved
 * out to the grid's edge so the surface meets the pool walls. The same
 * gradients of the full field, as a texture (ms_mesh_gradients), give the
 * shaders per-pixel normals, so the mesh itself can be coarser than the
 * field where the image does not need its vertices. */
#include <math.h>

#include "core/core_internal.h"
#include "render/render_internal.h"

long ms_field_nonfinite(const float *h, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(h[k]))
            return (long)k;
    return -1;
}

/* The gradient (dh/dx, dh/dy) at cell (i, j): central differences inside,
 * one-sided at the edges. */
static inline void gradient(const float *h, const ms_grid *g, int i, int j, float *gx, float *gy)
{
    const int nx = g->nx, ny = g->ny;
    const float *row = h + (size_t)j * (size_t)nx;
    const float *below = h + (size_t)(j > 0 ? j - 1 : j) * (size_t)nx;
    const float *above = h + (size_t)(j < ny - 1 ? j + 1 : j) * (size_t)nx;
    const int il = i > 0 ? i - 1 : i, ir = i < nx - 1 ? i + 1 : i;
    *gx = (row[ir] - row[il]) / ((float)(ir - il) * g->dx);
    /* 1 / (2 dy) inside, 1 / dy at the edges */
    *gy = (above[i] - below[i]) * ((j > 0 && j < ny - 1 ? 0.5f : 1.0f) / g->dy);
}

void ms_mesh_build(const float *h, const ms_grid *g, float floor_z, float *restrict vertices)
{
    const int nx = g->nx, ny = g->ny;
    const float x0 = g->origin[0], y0 = g->origin[1], dx = g->dx, dy = g->dy;
    for (int j = 0; j < ny; ++j) {
        const float *row = h + (size_t)j * (size_t)nx;
        const float y = j == 0        ? y0
                        : j == ny - 1 ? y0 + (float)ny * dy
                                      : y0 + ((float)j + 0.5f) * dy;
        float *v = vertices + (size_t)j * (size_t)nx * 6;
        for (int i = 0; i < nx; ++i) {
            float gx, gy;
            gradient(h, g, i, j, &gx, &gy);
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
}

void ms_mesh_gradients(const float *h, const ms_grid *g, float *restrict out)
{
    for (int j = 0; j < g->ny; ++j)
        for (int i = 0; i < g->nx; ++i) {
            float *o = out + 2 * ((size_t)j * (size_t)g->nx + (size_t)i);
            gradient(h, g, i, j, &o[0], &o[1]);
        }
}

void ms_mesh_coarsen(const float *h, const ms_grid *g, int step, float *restrict out,
                     ms_grid *out_g)
{
    const int nx = g->nx, ny = g->ny, cx = MS_MAX(nx / step, 2), cy = MS_MAX(ny / step, 2);
    *out_g = *g;
    out_g->nx = cx;
    out_g->ny = cy;
    out_g->dx = g->dx * (float)nx / (float)cx;
    out_g->dy = g->dy * (float)ny / (float)cy;
    for (int J = 0; J < cy; ++J) {
        const int j0 = (int)((long)J * ny / cy), j1 = (int)((long)(J + 1) * ny / cy);
        float *o = out + (size_t)J * (size_t)cx;
        for (int I = 0; I < cx; ++I)
            o[I] = 0;
        for (int j = j0; j < j1; ++j) {
            const float *row = h + (size_t)j * (size_t)nx;
            for (int I = 0; I < cx; ++I) {
                const int i0 = (int)((long)I * nx / cx), i1 = (int)((long)(I + 1) * nx / cx);
                float s = 0;
                for (int i = i0; i < i1; ++i)
                    s += row[i];
                o[I] += s / (float)((i1 - i0) * (j1 - j0));
            }
        }
    }
}

double ms_mesh_height_error(const float *h, const ms_grid *g, int step, float *coarse)
{
    ms_grid cg;
    ms_mesh_coarsen(h, g, step, coarse, &cg);
    const int nx = g->nx, ny = g->ny, cx = cg.nx, cy = cg.ny;
    /* the coarse vertices' coordinates in fine cells (centres at i + 0.5) */
    const double sx = (double)nx / cx, sy = (double)ny / cy;
    double worst = 0;
    for (int j = 0; j < ny; ++j) {
        double y = (j + 0.5) / sy - 0.5; /* in coarse vertex units */
        int J = y <= 0 ? 0 : y >= cy - 1 ? cy - 2 : (int)y;
        double fy = MS_CLAMP(y - J, 0.0, 1.0);
        if (J == 0 && j < sy / 2)
            fy = 0; /* the outermost vertex row carries the edge cells */
        if (J == cy - 2 && j >= ny - sy / 2)
            fy = 1;
        const float *r0 = coarse + (size_t)J * (size_t)cx, *r1 = r0 + cx;
        const float *row = h + (size_t)j * (size_t)nx;
        for (int i = 0; i < nx; ++i) {
            double x = (i + 0.5) / sx - 0.5;
            int I = x <= 0 ? 0 : x >= cx - 1 ? cx - 2 : (int)x;
            double fx = MS_CLAMP(x - I, 0.0, 1.0);
            if (I == 0 && i < sx / 2)
                fx = 0;
            if (I == cx - 2 && i >= nx - sx / 2)
                fx = 1;
            double a = r0[I] + fx * (r0[I + 1] - r0[I]), b = r1[I] + fx * (r1[I + 1] - r1[I]);
            double e = fabs(row[i] - (a + fy * (b - a)));
            worst = e > worst ? e : worst;
        }
    }
    return worst;
}

int ms_mesh_auto_step(const ms_renderer_desc *d, const float *h, const ms_grid *g, float *scratch)
{
    /* the nearest point of the field's rectangle, at the still water */
    const float lo[2] = {g->origin[0], g->origin[1]};
    const float hi[2] = {g->origin[0] + (float)g->nx * g->dx, g->origin[1] + (float)g->ny * g->dy};
    double dist2 = 0;
    for (int k = 0; k < 2; ++k) {
        double e = d->eye[k], q = e < lo[k] ? lo[k] - e : e > hi[k] ? e - hi[k] : 0;
        dist2 += q * q;
    }
    dist2 += ((double)d->eye[2] - d->water_level) * ((double)d->eye[2] - d->water_level);
    /* metres per pixel there */
    double px = 2.0 * sqrt(dist2) * tan(0.5 * d->fov * 3.14159265358979 / 180.0) / d->height;
    double cell = MS_MIN(g->dx, g->dy);
    int step = (int)floor(MS_MESH_AUTO_PIXELS * px / cell);
    step = MS_CLAMP(step, 1, MS_MIN(64, MS_MIN(g->nx, g->ny) / 2));
    /* screen-space error: lower the step (by a quarter) while the drawn heights leave the
     * field's by more than MS_MESH_AUTO_ERROR_PX pixels there */
    while (step > 1 && ms_mesh_height_error(h, g, step, scratch) > MS_MESH_AUTO_ERROR_PX * px)
        step = MS_MIN(step - 1, step * 3 / 4);
    return step;
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
