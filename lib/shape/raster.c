/* Shapes on a surface grid: the footprint at the water level (the obstacle
 * mask of the wave equation, eq. 2: solid cells reflect) and the water depth
 * above the shape (the speed map c = sqrt(g depth) over terrain). */
#include <math.h>

#include "core/core_internal.h"
#include "shape/shape_internal.h"

static ms_status check_grid(const char *what, const ms_grid *g, float z, const void *arr)
{
    ms_status st;
    if ((st = ms_check_not_null("shape", "grid", g)) != MS_OK ||
        (st = ms_check_not_null("shape", what, arr)) != MS_OK ||
        (st = ms_check_int_range("shape", "grid nx", g->nx, 1, 1 << 16)) != MS_OK ||
        (st = ms_check_int_range("shape", "grid ny", g->ny, 1, 1 << 16)) != MS_OK ||
        (st = ms_check_positive("shape", "grid dx", g->dx, "m")) != MS_OK ||
        (st = ms_check_positive("shape", "grid dy", g->dy, "m")) != MS_OK ||
        (st = ms_check_finite("shape", "grid origin[0]", g->origin[0])) != MS_OK ||
        (st = ms_check_finite("shape", "grid origin[1]", g->origin[1])) != MS_OK ||
        (st = ms_check_finite("shape", "water level z", z)) != MS_OK)
        return st;
    return MS_OK;
}

/* The cells [*i0, *i1) whose centres lie within [lo, hi] along one axis. */
static void cell_range(float lo, float hi, float origin, float d, int n, int *i0, int *i1)
{
    double a = ceil(((double)lo - origin) / d - 0.5), b = floor(((double)hi - origin) / d - 0.5);
    a = a < 0 ? 0 : a;
    b = b > n - 1 ? n - 1 : b;
    *i0 = (int)a;
    *i1 = b < a ? (int)a : (int)b + 1;
}

ms_status ms_shape_footprint(const ms_shape *s, const ms_grid *g, float z, unsigned char *mask)
{
    ms_status st = ms_check_not_null("shape", "shape", s);
    if (st != MS_OK || (st = check_grid("mask", g, z, mask)) != MS_OK)
        return st;
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    if (z < lo[2] || z > hi[2])
        return MS_OK;
    int x0, x1, y0, y1;
    cell_range(lo[0], hi[0], g->origin[0], g->dx, g->nx, &x0, &x1);
    cell_range(lo[1], hi[1], g->origin[1], g->dy, g->ny, &y0, &y1);
    for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) {
            const float p[3] = {g->origin[0] + ((float)i + 0.5f) * g->dx,
                                g->origin[1] + ((float)j + 0.5f) * g->dy, z};
            if (ms_shape_distance(s, p, NULL) < 0.0f)
                mask[(size_t)j * (size_t)g->nx + (size_t)i] = 1;
        }
    return MS_OK;
}

/* The height (m, local) of the first surface met going down the local
 * column (x, y) from local height z, by sphere tracing the distance field
 * (a step of d never crosses the surface; steps are at least tol, so a
 * feature thinner than tol may be missed), then bisection between the last
 * point outside and the first inside. Returns 0 when the column is empty
 * below z (down to zmin). world: the column and heights are in the world's
 * frame (a turned shape, whose own z is not up). */
static float dist(const ms_shape *s, int world, const float p[3])
{
    return world ? ms_shape_distance(s, p, NULL) : s->vt->distance(s->self, p, NULL);
}

static int march_down(const ms_shape *s, int world, float x, float y, float z, float zmin,
                      float tol, float *top)
{
    float p[3] = {x, y, z};
    float d = dist(s, world, p);
    if (d <= 0.0f) {
        *top = z;
        return 1;
    }
    for (int it = 0; it < 100000 && p[2] >= zmin; ++it) {
        float step = MS_MAX(d, tol);
        float z_prev = p[2];
        p[2] -= step;
        d = dist(s, world, p);
        if (d <= 0.0f) {
            /* the surface lies in [p[2], z_prev]: bisect */
            float a = p[2], b = z_prev;
            for (int k = 0; k < 40 && b - a > 1e-6f * (1.0f + fabsf(b)); ++k) {
                float m = 0.5f * (a + b);
                p[2] = m;
                if (dist(s, world, p) <= 0.0f)
                    a = m;
                else
                    b = m;
            }
            *top = 0.5f * (a + b);
            return 1;
        }
    }
    return 0;
}

ms_status ms_shape_depth(const ms_shape *s, const ms_grid *g, float z, float *depth)
{
    ms_status st = ms_check_not_null("shape", "shape", s);
    if (st != MS_OK || (st = check_grid("depth", g, z, depth)) != MS_OK)
        return st;
    float lo[3], hi[3];
    s->vt->bounds(s->self, lo, hi); /* local */
    float wlo[3], whi[3];
    ms_shape_bounds(s, wlo, whi);
    /* a turned shape is marched in the world's frame (its height_at is
     * along its own z) */
    const int world = s->turned;
    if (world)
        lo[2] = wlo[2];
    const float zl = world ? z : z - s->pos[2]; /* water level, in the marching frame */
    int x0, x1, y0, y1;
    cell_range(wlo[0], whi[0], g->origin[0], g->dx, g->nx, &x0, &x1);
    cell_range(wlo[1], whi[1], g->origin[1], g->dy, g->ny, &y0, &y1);
    const float tol = 1e-3f * MS_MIN(g->dx, g->dy);
    const float zmin = lo[2] > -1e29f ? lo[2] - tol : zl - 1e4f;
    for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) {
            const float x = g->origin[0] + ((float)i + 0.5f) * g->dx - (world ? 0.0f : s->pos[0]);
            const float y = g->origin[1] + ((float)j + 0.5f) * g->dy - (world ? 0.0f : s->pos[1]);
            float top;
            int hit = s->vt->height_at && !world ? s->vt->height_at(s->self, x, y, &top)
                                                 : march_down(s, world, x, y, zl, zmin, tol, &top);
            if (!hit)
                continue;
            float dep = MS_MAX(zl - top, 0.0f); /* m */
            float *dst = &depth[(size_t)j * (size_t)g->nx + (size_t)i];
            if (dep < *dst)
                *dst = dep;
        }
    return MS_OK;
}
