/* Helpers of the render suites (tests/test_render.c, tests/test_caustics.c):
 * height fields on the unit pool, filled or with a Gaussian bump. */
#ifndef MS_TESTS_SUPPORT_RENDER_H
#define MS_TESTS_SUPPORT_RENDER_H

#include <check.h>
#include <math.h>
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

#endif
