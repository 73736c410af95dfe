/* Helpers of the render suites (tests/test_render.c, tests/test_caustics.c,
 * the look suites): height fields on the unit pool, filled or with a
 * Gaussian bump; where a world point lands in a camera's picture. */
#ifndef MS_TESTS_SUPPORT_RENDER_H
#define MS_TESTS_SUPPORT_RENDER_H

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "modesplit/modesplit.h"

/* An n x n height field at `level` (m); free() it. */
static inline float *field(int n, float level)
{
    float *h = malloc(sizeof *h * (size_t)n * (size_t)n);
    ck_assert_ptr_nonnull(h);
    for (int i = 0; i < n * n; ++i)
        h[i] = level;
    return h;
}

/* The n x n grid over the 1 m x 1 m pool at the origin. */
static inline ms_grid grid(int n)
{
    ms_grid g = {n, n, 1.0f / (float)n, 1.0f / (float)n, {0, 0}};
    return g;
}

/* A Gaussian bump of amplitude a (m) and width sigma (m) at (x, y). */
static inline void add_bump(float *h, int n, float x, float y, float a, float sigma)
{
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float dx = ((float)i + 0.5f) / (float)n - x, dy = ((float)j + 0.5f) / (float)n - y;
            h[j * n + i] += a * expf(-(dx * dx + dy * dy) / (2 * sigma * sigma));
        }
}

/* Where world point p lands in a w x h picture of d's camera (pixel
 * column, row from the top, continuous); 0 if behind the eye. */
static inline int ms_test_project(const ms_renderer_desc *d, const float p[3], int w, int h,
                                  double *col, double *row)
{
    double f[3], v[3], rt[3], up[3], len = 0;
    for (int k = 0; k < 3; ++k)
        f[k] = d->target[k] - d->eye[k], len += f[k] * f[k];
    for (int k = 0; k < 3; ++k)
        f[k] /= sqrt(len), v[k] = p[k] - d->eye[k];
    rt[0] = f[1] * d->up[2] - f[2] * d->up[1];
    rt[1] = f[2] * d->up[0] - f[0] * d->up[2];
    rt[2] = f[0] * d->up[1] - f[1] * d->up[0];
    len = sqrt(rt[0] * rt[0] + rt[1] * rt[1] + rt[2] * rt[2]);
    for (int k = 0; k < 3; ++k)
        rt[k] /= len;
    up[0] = rt[1] * f[2] - rt[2] * f[1];
    up[1] = rt[2] * f[0] - rt[0] * f[2];
    up[2] = rt[0] * f[1] - rt[1] * f[0];
    const double z = v[0] * f[0] + v[1] * f[1] + v[2] * f[2];
    if (z <= 0)
        return 0;
    const double t = tan(0.5 * d->fov * 3.14159265358979 / 180.0);
    const double x = (v[0] * rt[0] + v[1] * rt[1] + v[2] * rt[2]) / (z * t * w / h);
    const double y = (v[0] * up[0] + v[1] * up[1] + v[2] * up[2]) / (z * t);
    *col = 0.5 * w * (1 + x);
    *row = 0.5 * h * (1 - y);
    return 1;
}

/* The look suites' pictures: with MS_LOOK_DUMP=DIR, r's last picture is
 * written to DIR/name.png for a person to look at; without it, nothing. */
static inline void ms_test_dump_png(const ms_renderer *r, const char *name)
{
    const char *dir = getenv("MS_LOOK_DUMP");
    if (!dir)
        return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.png", dir, name);
    ck_assert_int_eq(ms_renderer_write_png(r, path), MS_OK);
}

#endif
