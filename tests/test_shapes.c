/* Collision shapes: distances and normals against closed forms at random
 * points (inside, outside, edges, corners), normals continuous across box
 * edges, footprints against analytic areas, depths, parameter refusals. */
#define _DEFAULT_SOURCE /* mkdtemp */
#include <check.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "shape/shape_internal.h"
#include "support.h"

#define PI 3.14159265358979323846

static ms_shape *make(const char *kind, const char *json)
{
    ms_shape *s = NULL;
    ms_status st = ms_shape_create(kind, json, &s);
    ck_assert_msg(st == MS_OK, "%s %s: %s", kind, json ? json : "(defaults)", ms_last_error());
    return s;
}

static float urand(ms_rng *r, float lo, float hi)
{
    return lo + (hi - lo) * ms_rng_uniform(r);
}

static double dot3(const float a[3], const float b[3])
{
    return (double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2];
}

static double len3(const float a[3])
{
    return sqrt(dot3(a, a));
}

/* The normal is the gradient of the distance where the field is smooth:
 * central differences with step e. */
static void num_gradient(const ms_shape *s, const float p[3], float e, float g[3])
{
    for (int k = 0; k < 3; ++k) {
        float a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
        a[k] += e;
        b[k] -= e;
        g[k] = (ms_shape_distance(s, a, NULL) - ms_shape_distance(s, b, NULL)) / (2 * e);
    }
}

START_TEST(sphere_matches_closed_form)
{
    ms_shape *s = make("sphere", "{\"radius\": 0.3}");
    const float c[3] = {0.5f, -0.2f, 1.0f};
    ck_assert_int_eq(ms_shape_set_pose(s, c, NULL), MS_OK);
    ms_rng r;
    ms_rng_seed(&r, 1);
    int inside = 0;
    for (int i = 0; i < 2000; ++i) {
        float p[3], n[3], d3[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = c[k] + urand(&r, -0.6f, 0.6f);
            d3[k] = p[k] - c[k];
        }
        float d = ms_shape_distance(s, p, n);
        double l = len3(d3);
        ck_assert_double_lt(fabs(d - (l - 0.3)), 1e-6);
        for (int k = 0; k < 3; ++k)
            ck_assert_double_lt(fabs(n[k] - d3[k] / l), 1e-5);
        inside += d < 0;
    }
    ck_assert_int_gt(inside, 100); /* points on both sides were tried */
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    for (int k = 0; k < 3; ++k) {
        ck_assert_float_eq_tol(lo[k], c[k] - 0.3f, 1e-6f);
        ck_assert_float_eq_tol(hi[k], c[k] + 0.3f, 1e-6f);
    }
    ck_assert_str_eq(ms_shape_kind(s), "sphere");
    ms_shape_destroy(s);
}
END_TEST

/* Closed form of the sharp box of half extents h: outside, the length of
 * the excess over each face; inside, minus the depth below the nearest face. */
static double box_closed(const float h[3], const float p[3])
{
    double out = 0, depth = 1e30;
    int in = 1;
    for (int k = 0; k < 3; ++k) {
        double e = fabs(p[k]) - h[k];
        if (e > 0) {
            out += e * e;
            in = 0;
        }
        depth = fmin(depth, -e);
    }
    return in ? -depth : sqrt(out);
}

START_TEST(box_matches_closed_form_inside_outside_edges_corners)
{
    /* a sharp box (radius 0, smooth 0: the normal is the exact gradient) */
    ms_shape *s = make("box", "{\"size\": [0.4, 0.6, 1.0], \"smooth\": 0}");
    const float h[3] = {0.2f, 0.3f, 0.5f};
    ms_rng r;
    ms_rng_seed(&r, 2);
    int inside = 0, edge = 0, corner = 0;
    for (int i = 0; i < 5000; ++i) {
        float p[3], n[3];
        for (int k = 0; k < 3; ++k)
            p[k] = urand(&r, -1.6f * h[k], 1.6f * h[k]);
        float d = ms_shape_distance(s, p, n);
        ck_assert_double_lt(fabs(d - box_closed(h, p)), 2e-6);
        ck_assert_double_lt(fabs(len3(n) - 1), 1e-5);
        int out_axes = 0;
        for (int k = 0; k < 3; ++k)
            out_axes += fabsf(p[k]) > h[k];
        inside += out_axes == 0;
        edge += out_axes == 2;
        corner += out_axes == 3;
        /* outside, the normal is the direction from the closest point */
        if (out_axes > 0) {
            float q[3];
            for (int k = 0; k < 3; ++k)
                q[k] = fmaxf(-h[k], fminf(h[k], p[k]));
            for (int k = 0; k < 3; ++k)
                ck_assert_double_lt(fabs(n[k] - (p[k] - q[k]) / d), 1e-4);
        }
    }
    ck_assert_int_gt(inside, 500);
    ck_assert_int_gt(edge, 500);
    ck_assert_int_gt(corner, 200);
    /* exact values at an edge and a corner */
    float n[3];
    float d = ms_shape_distance(s, (float[3]){0.3f, 0.4f, 0.0f}, n);
    ck_assert_float_eq_tol(d, (float)sqrt(0.02), 1e-6f);
    ck_assert_float_eq_tol(n[0], (float)(1 / sqrt(2)), 1e-5f);
    ck_assert_float_eq_tol(n[1], (float)(1 / sqrt(2)), 1e-5f);
    ck_assert_float_eq_tol(n[2], 0.0f, 1e-6f);
    d = ms_shape_distance(s, (float[3]){-0.3f, -0.4f, 0.6f}, n);
    ck_assert_float_eq_tol(d, (float)sqrt(0.03), 1e-6f);
    ck_assert_float_eq_tol(n[0], (float)(-1 / sqrt(3)), 1e-5f);
    ck_assert_float_eq_tol(n[2], (float)(1 / sqrt(3)), 1e-5f);
    d = ms_shape_distance(s, (float[3]){0.05f, 0.0f, -0.45f}, n);
    ck_assert_float_eq_tol(d, -0.05f, 1e-6f);
    ck_assert_float_eq_tol(n[2], -1.0f, 1e-6f);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(rounded_box_distance_and_gradient)
{
    /* radius = smooth: the normal is the exact gradient outside the core */
    const float rad = 0.05f;
    ms_shape *s = make("box", "{\"size\": [0.4, 0.6, 1.0], \"radius\": 0.05, \"smooth\": 0.05}");
    const float c[3] = {0.2f - rad, 0.3f - rad, 0.5f - rad}; /* the core */
    ms_rng r;
    ms_rng_seed(&r, 3);
    int tried = 0;
    for (int i = 0; i < 5000; ++i) {
        float p[3], n[3];
        for (int k = 0; k < 3; ++k)
            p[k] = urand(&r, -1.6f * (c[k] + rad), 1.6f * (c[k] + rad));
        float d = ms_shape_distance(s, p, n);
        ck_assert_double_lt(fabs(d - (box_closed(c, p) - rad)), 2e-6);
        if (box_closed(c, p) < 1e-3)
            continue; /* inside the core: not the gradient by design */
        float g[3];
        num_gradient(s, p, 1e-4f, g);
        for (int k = 0; k < 3; ++k)
            ck_assert_double_lt(fabs(n[k] - g[k] / len3(g)), 2e-2);
        /* the closest point p - d n lies on the surface */
        float q[3] = {p[0] - d * n[0], p[1] - d * n[1], p[2] - d * n[2]};
        ck_assert_double_lt(fabs(ms_shape_distance(s, q, NULL)), 1e-5);
        ++tried;
    }
    ck_assert_int_gt(tried, 3000);
    /* the rounded corner: distance along the diagonal */
    float p[3] = {c[0] + 0.1f, c[1] + 0.1f, c[2] + 0.1f};
    ck_assert_float_eq_tol(ms_shape_distance(s, p, NULL), (float)(0.1 * sqrt(3) - rad), 1e-6f);
    ms_shape_destroy(s);
}
END_TEST

/* Walk a path, the normal must turn by small steps (no jump). Returns the
 * largest change between neighbours. */
static double max_normal_step(const ms_shape *s, const float a[3], const float b[3], int n,
                              float n0[3], float n1[3])
{
    float prev[3] = {0, 0, 0};
    double worst = 0;
    for (int i = 0; i <= n; ++i) {
        float t = (float)i / (float)n, p[3], nn[3];
        for (int k = 0; k < 3; ++k)
            p[k] = a[k] + t * (b[k] - a[k]);
        ms_shape_distance(s, p, nn);
        if (i > 0) {
            float dd[3] = {nn[0] - prev[0], nn[1] - prev[1], nn[2] - prev[2]};
            worst = fmax(worst, len3(dd));
        } else
            memcpy(n0, nn, sizeof nn);
        memcpy(prev, nn, sizeof nn);
    }
    memcpy(n1, prev, sizeof prev);
    return worst;
}

START_TEST(box_normals_are_continuous_across_edges)
{
    /* the default box smooths its normal over a band at each edge */
    const char *boxes[] = {"{\"size\": [1, 1, 1]}", "{\"size\": [1, 0.5, 2], \"radius\": 0.1}",
                           "{\"size\": [1, 1, 1], \"smooth\": 0}"};
    for (int b = 0; b < 3; ++b) {
        ms_shape *s = make("box", boxes[b]);
        float lo[3], hi[3], n0[3], n1[3];
        ms_shape_bounds(s, lo, hi);
        /* paths over the +x/+z edge at several depths: outside (above),
         * on, and inside (below) the surface; each crosses the diagonal */
        const float offs[] = {0.05f, 0.01f, 0.0f, -0.01f, -0.05f, -0.15f};
        for (int o = 0; o < 6; ++o) {
            if (b == 2 && offs[o] == 0.0f)
                continue; /* the sharp edge line itself has no single normal */
            float e = offs[o];
            float a[3] = {hi[0] - 0.3f, 0.0f, hi[2] + e}, z[3] = {hi[0] + e, 0.0f, hi[2] - 0.3f};
            const int steps = 4000;
            double worst = max_normal_step(s, a, z, steps, n0, n1);
            /* the path is 0.42 m long: a jump would be a change of O(1) */
            ck_assert_msg(worst < 0.02, "box %d offset %g: normal jumps by %g", b, e, worst);
            /* starts with the top face's normal, ends with the side's */
            ck_assert_msg(fabsf(n0[2] - 1) < 1e-3f && fabsf(n1[0] - 1) < 1e-3f,
                          "box %d offset %g: normals (%g %g %g) .. (%g %g %g)", b, e, n0[0], n0[1],
                          n0[2], n1[0], n1[1], n1[2]);
        }
        ms_shape_destroy(s);
    }
}
END_TEST

START_TEST(plane_matches_closed_form)
{
    ms_shape *s = make("plane", "{\"normal\": [0, 3, 4], \"offset\": 0.5}");
    ms_rng r;
    ms_rng_seed(&r, 4);
    for (int i = 0; i < 1000; ++i) {
        float p[3] = {urand(&r, -2, 2), urand(&r, -2, 2), urand(&r, -2, 2)}, n[3];
        float d = ms_shape_distance(s, p, n);
        ck_assert_double_lt(fabs(d - (0.6 * p[1] + 0.8 * p[2] - 0.5)), 1e-6);
        ck_assert_float_eq_tol(n[1], 0.6f, 1e-6f);
        ck_assert_float_eq_tol(n[2], 0.8f, 1e-6f);
    }
    ms_shape_destroy(s);
    s = make("plane", NULL); /* the floor z = 0 */
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){3, 4, -0.25f}, NULL), -0.25f, 1e-7f);
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    ck_assert_float_eq(hi[2], 0.0f);
    ck_assert_float_le(lo[2], -1e29f);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(pose_translates_and_moves)
{
    ms_shape *s = make("box", "{\"size\": [1, 1, 1]}");
    float pos[3] = {1, 2, 3}, vel[3] = {0.5f, 0, -1}, gp[3], gv[3];
    ck_assert_int_eq(ms_shape_set_pose(s, pos, vel), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){1, 2, 4}, NULL), 0.5f, 1e-6f);
    ms_shape_get_pose(s, gp, gv);
    float v[3];
    ms_shape_velocity(s, (float[3]){1.2f, 2, 3}, v);
    for (int k = 0; k < 3; ++k) {
        ck_assert_float_eq(gp[k], pos[k]);
        ck_assert_float_eq(gv[k], vel[k]);
        ck_assert_float_eq(v[k], vel[k]);
    }
    MS_ASSERT_REFUSED(ms_shape_set_pose(s, (float[3]){0, NAN, 0}, NULL), MS_ERR_INVALID_ARGUMENT,
                      "pos[1]");
    MS_ASSERT_REFUSED(ms_shape_set_pose(s, NULL, (float[3]){0, 0, INFINITY}),
                      MS_ERR_INVALID_ARGUMENT, "vel[2]");
    MS_ASSERT_REFUSED(ms_shape_set_pose(NULL, pos, vel), MS_ERR_INVALID_ARGUMENT, "shape");
    ms_shape_get_pose(s, gp, gv); /* a refused call changes nothing */
    ck_assert_float_eq(gp[1], 2.0f);
    ck_assert_float_eq(gv[2], -1.0f);
    /* NULL position keeps it, NULL velocity stops the shape */
    ck_assert_int_eq(ms_shape_set_pose(s, NULL, NULL), MS_OK);
    ms_shape_get_pose(s, gp, gv);
    ck_assert_float_eq(gp[2], 3.0f);
    ck_assert_float_eq(gv[0], 0.0f);
    ms_shape_destroy(s);
    ms_shape_destroy(NULL);
}
END_TEST

/* A turned shape: its distance at p is the unturned one at R^T (p - pos),
 * its normal is R times the unturned one, its material moves at
 * v + omega x (p - pos), its bounds hold every point inside it, the depth
 * over it is marched in the world's frame, and a zero or NaN quaternion or
 * a huge omega is refused, changing nothing. */
START_TEST(orientation_turns_distance_normal_velocity_and_bounds)
{
    ms_shape *s = make("box", "{\"size\": [0.4, 0.2, 0.1], \"radius\": 0.02}");
    ms_shape *ref = make("box", "{\"size\": [0.4, 0.2, 0.1], \"radius\": 0.02}");
    const float pos[3] = {0.5f, -0.3f, 0.2f}, vel[3] = {0.1f, 0, 0};
    ck_assert_int_eq(ms_shape_set_pose(s, pos, vel), MS_OK);
    /* 60 degrees about the axis (1, 2, 2)/3, given unnormalised (x 2) */
    const double half = PI / 6, ax[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
    const float q[4] = {(float)(2 * cos(half)), (float)(2 * sin(half) * ax[0]),
                        (float)(2 * sin(half) * ax[1]), (float)(2 * sin(half) * ax[2])};
    const float omega[3] = {0, 0, 3};
    ck_assert_int_eq(ms_shape_set_orientation(s, q, omega), MS_OK);
    float gq[4], gw[3];
    ms_shape_get_orientation(s, gq, gw);
    ck_assert_float_eq_tol(gq[0], (float)cos(half), 1e-6f);
    ck_assert_float_eq(gw[2], 3.0f);
    /* R from Rodrigues in double, to compare with */
    double R[9], c = cos(2 * half), sn = sin(2 * half);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double cross = 0;
            if (i != j) {
                int k = 3 - i - j;
                double sign =
                    ((i == 0 && j == 1) || (i == 1 && j == 2) || (i == 2 && j == 0)) ? -1 : 1;
                cross = sign * ax[k];
            }
            R[3 * i + j] = (i == j ? c : 0) + (1 - c) * ax[i] * ax[j] + sn * cross;
        }
    ms_rng r;
    ms_rng_seed(&r, 7);
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    int inside = 0;
    for (int t = 0; t < 2000; ++t) {
        float p[3], n[3], nr[3], l[3];
        for (int k = 0; k < 3; ++k)
            p[k] = pos[k] + urand(&r, -0.3f, 0.3f);
        for (int k = 0; k < 3; ++k) /* l = R^T (p - pos) */
            l[k] = (float)(R[k] * (p[0] - pos[0]) + R[3 + k] * (p[1] - pos[1]) +
                           R[6 + k] * (p[2] - pos[2]));
        float d = ms_shape_distance(s, p, n), dr = ms_shape_distance(ref, l, nr);
        ck_assert_msg(fabsf(d - dr) < 2e-6f, "point %d: %g != %g", t, d, dr);
        for (int k = 0; k < 3; ++k)
            ck_assert_float_eq_tol(
                n[k], R[3 * k] * nr[0] + R[3 * k + 1] * nr[1] + R[3 * k + 2] * nr[2], 2e-5f);
        float u[3];
        ms_shape_velocity(s, p, u);
        ck_assert_float_eq_tol(u[0], 0.1f - 3 * (p[1] - pos[1]), 1e-6f);
        ck_assert_float_eq_tol(u[1], 3 * (p[0] - pos[0]), 1e-6f);
        ck_assert_float_eq_tol(u[2], 0.0f, 1e-6f);
        if (d < 0) {
            ++inside;
            for (int k = 0; k < 3; ++k)
                ck_assert(p[k] >= lo[k] && p[k] <= hi[k]);
        }
    }
    ck_assert_int_gt(inside, 20);
    /* the depth over a turned box is marched down the world's z: a box
     * turned 90 degrees about x stands 0.2 m tall (its y extent) */
    ms_shape *tall = make("box", "{\"size\": [0.4, 0.2, 0.1]}");
    ck_assert_int_eq(ms_shape_set_pose(tall, (float[3]){0.5f, 0.5f, -0.3f}, NULL), MS_OK);
    const float q90[4] = {(float)cos(PI / 4), (float)sin(PI / 4), 0, 0};
    ck_assert_int_eq(ms_shape_set_orientation(tall, q90, NULL), MS_OK);
    const ms_grid g = {.nx = 10, .ny = 10, .dx = 0.1f, .dy = 0.1f, .origin = {0, 0}};
    float depth[100];
    for (int i = 0; i < 100; ++i)
        depth[i] = 1.0f;
    ck_assert_int_eq(ms_shape_depth(tall, &g, 0.0f, depth), MS_OK);
    ck_assert_float_eq_tol(depth[5 * 10 + 5], 0.2f, 1e-4f); /* top at -0.3 + 0.1 */
    ck_assert_float_eq(depth[0], 1.0f);                     /* beside it */
    unsigned char mask[100] = {0};
    ck_assert_int_eq(ms_shape_footprint(tall, &g, -0.25f, mask), MS_OK);
    int cells = 0; /* 0.4 x 0.1 m at the level: 4 x 1 cells of 0.1 m */
    for (int i = 0; i < 100; ++i)
        cells += mask[i];
    ck_assert_int_eq(cells, 4);
    /* refusals change nothing */
    MS_ASSERT_REFUSED(ms_shape_set_orientation(s, (float[4]){0, 0, 0, 0}, NULL),
                      MS_ERR_INVALID_ARGUMENT, "length 0");
    MS_ASSERT_REFUSED(ms_shape_set_orientation(s, (float[4]){1, NAN, 0, 0}, NULL),
                      MS_ERR_INVALID_ARGUMENT, "orientation[1]");
    MS_ASSERT_REFUSED(ms_shape_set_orientation(s, NULL, (float[3]){0, 2e3f, 0}),
                      MS_ERR_INVALID_ARGUMENT, "omega[1]");
    MS_ASSERT_REFUSED(ms_shape_set_orientation(NULL, q, NULL), MS_ERR_INVALID_ARGUMENT, "shape");
    ms_shape_get_orientation(s, gq, gw);
    ck_assert_float_eq_tol(gq[0], (float)cos(half), 1e-6f);
    ck_assert_float_eq(gw[2], 3.0f);
    /* back to (1, 0, 0, 0) at rest: the plain translated shape again */
    ck_assert_int_eq(ms_shape_set_orientation(s, (float[4]){1, 0, 0, 0}, NULL), MS_OK);
    ck_assert_float_eq(ms_shape_distance(s, pos, NULL),
                       ms_shape_distance(ref, (float[3]){0, 0, 0}, NULL));
    ms_shape_destroy(tall);
    ms_shape_destroy(ref);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(bad_parameters_name_the_key)
{
    ms_shape *s = (ms_shape *)&s;
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": -1}", &s), MS_ERR_INVALID_ARGUMENT,
                      "radius -1 m");
    ck_assert_ptr_null(s);
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": \"big\"}", &s), MS_ERR_PARSE,
                      "radius must be a number");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radus\": 1}", &s), MS_ERR_INVALID_ARGUMENT,
                      "unknown key \"radus\"");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": 1", &s), MS_ERR_PARSE, "line 1");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "[1]", &s), MS_ERR_PARSE, "JSON object");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"size\": [1, 2]}", &s), MS_ERR_PARSE,
                      "size must be an array of 3");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"size\": [1, 0, 1]}", &s), MS_ERR_INVALID_ARGUMENT,
                      "size[1] 0 m");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"size\": [1, 1, 1], \"radius\": 0.6}", &s),
                      MS_ERR_INVALID_ARGUMENT, "radius 0.6 m is outside [0, 0.5]");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"radius\": 0.2, \"smooth\": 0.1}", &s),
                      MS_ERR_INVALID_ARGUMENT, "smooth 0.1 m");
    MS_ASSERT_REFUSED(ms_shape_create("plane", "{\"normal\": [0, 0, 0]}", &s),
                      MS_ERR_INVALID_ARGUMENT, "normal [0, 0, 0] has length 0");
    MS_ASSERT_REFUSED(ms_shape_create("box", NULL, NULL), MS_ERR_INVALID_ARGUMENT, "out");
    /* every message says which shape */
    MS_ASSERT_REFUSED(ms_shape_create("plane", "{\"offset\": null}", &s), MS_ERR_PARSE,
                      "shape plane: offset");
}
END_TEST

/* Footprint area against the analytic cross-section: cells whose centre
 * is inside, times the cell area, differ from the area by at most the
 * boundary cells, about perimeter * cell size. */
START_TEST(footprints_match_analytic_areas)
{
    const ms_grid g = {.nx = 200, .ny = 160, .dx = 0.01f, .dy = 0.0125f, .origin = {-1, -1}};
    unsigned char *mask = calloc((size_t)g.nx * g.ny, 1);
    /* a sphere cut at several water levels: a disc of radius sqrt(R^2 - z^2) */
    ms_shape *s = make("sphere", "{\"radius\": 0.5}");
    ck_assert_int_eq(ms_shape_set_pose(s, (float[3]){0.03f, -0.01f, 0.2f}, NULL), MS_OK);
    const float levels[] = {0.2f, 0.5f, -0.1f, 0.65f};
    for (int l = 0; l < 4; ++l) {
        memset(mask, 0, (size_t)g.nx * g.ny);
        ck_assert_int_eq(ms_shape_footprint(s, &g, levels[l], mask), MS_OK);
        long cells = 0;
        for (int i = 0; i < g.nx * g.ny; ++i)
            cells += mask[i];
        double rho2 = 0.25 - pow(levels[l] - 0.2, 2), area = PI * rho2;
        double err = fabs(cells * (double)g.dx * g.dy - area);
        ck_assert_msg(err <= 2 * PI * sqrt(rho2) * g.dy * 0.5 + 1e-9,
                      "level %g: %ld cells, area %g m^2, error %g", levels[l], cells, area, err);
        ck_assert_msg(err < 0.01 * area, "level %g: error %g of %g", levels[l], err, area);
    }
    ms_shape_destroy(s);
    /* a box: a rectangle, OR-ed into the mask left by the sphere */
    s = make("box", "{\"size\": [0.5, 0.3, 0.4]}");
    ck_assert_int_eq(ms_shape_set_pose(s, (float[3]){-0.5f, 0.4f, 0.0f}, NULL), MS_OK);
    long before = 0, after = 0;
    for (int i = 0; i < g.nx * g.ny; ++i)
        before += mask[i];
    ck_assert_int_eq(ms_shape_footprint(s, &g, 0.1f, mask), MS_OK);
    for (int i = 0; i < g.nx * g.ny; ++i)
        after += mask[i];
    double err = fabs((after - before) * (double)g.dx * g.dy - 0.15);
    ck_assert_double_le(err, 2 * (0.5 + 0.3) * g.dy);
    /* above the box nothing is marked */
    memset(mask, 0, (size_t)g.nx * g.ny);
    ck_assert_int_eq(ms_shape_footprint(s, &g, 0.3f, mask), MS_OK);
    for (int i = 0; i < g.nx * g.ny; ++i)
        ck_assert_int_eq(mask[i], 0);
    MS_ASSERT_REFUSED(ms_shape_footprint(s, &g, NAN, mask), MS_ERR_INVALID_ARGUMENT, "water level");
    ms_grid bad = g;
    bad.dx = 0;
    MS_ASSERT_REFUSED(ms_shape_footprint(s, &bad, 0, mask), MS_ERR_INVALID_ARGUMENT, "grid dx");
    MS_ASSERT_REFUSED(ms_shape_footprint(s, &g, 0, NULL), MS_ERR_INVALID_ARGUMENT, "mask");
    ms_shape_destroy(s);
    free(mask);
}
END_TEST

/* Depth over a submerged sphere: z minus its top sqrt(R^2 - r^2), by the
 * plugin's exact height_at and by marching down the distance field. */
START_TEST(depth_over_a_submerged_sphere)
{
    const ms_grid g = {.nx = 64, .ny = 64, .dx = 0.02f, .dy = 0.02f, .origin = {0, 0}};
    ms_shape *s = make("sphere", "{\"radius\": 0.4}");
    const float c[3] = {0.64f, 0.6f, -0.5f}, z = 0.0f;
    ck_assert_int_eq(ms_shape_set_pose(s, c, NULL), MS_OK);
    ms_shape_vtable marched = *s->vt;
    marched.height_at = NULL;
    for (int mode = 0; mode < 2; ++mode) {
        const ms_shape_vtable *keep = s->vt;
        if (mode == 1)
            s->vt = &marched;
        float *depth = malloc(sizeof(float) * (size_t)(g.nx * g.ny));
        for (int i = 0; i < g.nx * g.ny; ++i)
            depth[i] = 0.6f; /* the pool's depth without the sphere */
        ck_assert_int_eq(ms_shape_depth(s, &g, z, depth), MS_OK);
        int over = 0;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                double x = (i + 0.5) * g.dx - c[0], y = (j + 0.5) * g.dy - c[1];
                double r2 = x * x + y * y, want = 0.6;
                if (r2 < 0.16) {
                    want = fmin(0.6, z - (c[2] + sqrt(0.16 - r2)));
                    ++over;
                }
                ck_assert_msg(fabs(depth[j * g.nx + i] - want) < 2e-5,
                              "mode %d cell %d %d: %g != %g", mode, i, j, depth[j * g.nx + i],
                              want);
            }
        ck_assert_int_gt(over, 1000);
        free(depth);
        s->vt = keep;
    }
    ms_shape_destroy(s);
}
END_TEST

/* Where the distance field is smooth (its finite-difference gradient has
 * unit length: not on a medial surface), the normal is that gradient. */
static int normal_is_gradient(const ms_shape *s, const float p[3], const float n[3], double tol)
{
    float g[3];
    num_gradient(s, p, 1e-4f, g);
    double gl = len3(g);
    if (fabs(gl - 1) > 1e-2)
        return -1; /* not smooth here: not checked */
    for (int k = 0; k < 3; ++k)
        if (fabs(n[k] - g[k] / gl) > tol)
            return 0;
    return 1;
}

START_TEST(capsule_matches_closed_form)
{
    ms_shape *s = make("capsule", "{\"a\": [-0.2, 0.1, 0], \"b\": [0.3, -0.1, 0.2], "
                                  "\"radius\": 0.15}");
    const double a[3] = {-0.2, 0.1, 0}, b[3] = {0.3, -0.1, 0.2};
    ms_rng r;
    ms_rng_seed(&r, 5);
    int checked = 0, inside = 0;
    for (int i = 0; i < 3000; ++i) {
        float p[3] = {urand(&r, -0.5f, 0.6f), urand(&r, -0.4f, 0.4f), urand(&r, -0.3f, 0.5f)};
        float n[3];
        float d = ms_shape_distance(s, p, n);
        double ab[3], ap[3], abab = 0, apab = 0;
        for (int k = 0; k < 3; ++k) {
            ab[k] = b[k] - a[k];
            ap[k] = p[k] - a[k];
            abab += ab[k] * ab[k];
            apab += ap[k] * ab[k];
        }
        double t = fmin(fmax(apab / abab, 0), 1), v2 = 0;
        for (int k = 0; k < 3; ++k)
            v2 += pow(ap[k] - t * ab[k], 2);
        ck_assert_double_lt(fabs(d - (sqrt(v2) - 0.15)), 2e-6);
        ck_assert_double_lt(fabs(len3(n) - 1), 1e-5);
        int ok = normal_is_gradient(s, p, n, 1e-2);
        ck_assert_int_ne(ok, 0);
        checked += ok == 1;
        inside += d < 0;
    }
    ck_assert_int_gt(checked, 2500);
    ck_assert_int_gt(inside, 200);
    ms_shape_destroy(s);
}
END_TEST

/* The glass profile in (rho, z), sampled densely: brute-force distance. */
static double glass_brute(double R, double H, double w, double f, double rho, double z)
{
    const double e[5][4] = {
        {0, 0, R, 0}, {R, 0, R, H}, {R, H, R - w, H}, {R - w, H, R - w, f}, {R - w, f, 0, f}};
    double best = 1e30;
    for (int k = 0; k < 5; ++k)
        for (int i = 0; i <= 4000; ++i) {
            double t = i / 4000.0;
            double x = e[k][0] + t * (e[k][2] - e[k][0]), y = e[k][1] + t * (e[k][3] - e[k][1]);
            best = fmin(best, hypot(rho - x, z - y));
        }
    int in = (rho <= R && z >= 0 && z <= f) || (rho >= R - w && rho <= R && z >= 0 && z <= H);
    return in ? -best : best;
}

START_TEST(glass_matches_closed_form)
{
    const double R = 0.05, H = 0.12, w = 0.01, f = 0.02;
    ms_shape *s = make("glass", "{\"radius\": 0.05, \"height\": 0.12, \"wall\": 0.01, "
                                "\"floor\": 0.02, \"smooth\": 0}");
    ck_assert_int_eq(ms_shape_set_pose(s, (float[3]){1, 1, 0.5f}, NULL), MS_OK);
    ms_rng r;
    ms_rng_seed(&r, 6);
    int in_wall = 0, in_cavity = 0, checked = 0;
    for (int i = 0; i < 600; ++i) {
        float l[3] = {urand(&r, -0.08f, 0.08f), urand(&r, -0.08f, 0.08f), urand(&r, -0.03f, 0.16f)};
        float p[3] = {1 + l[0], 1 + l[1], 0.5f + l[2]}, n[3];
        float d = ms_shape_distance(s, p, n);
        double rho = hypot(l[0], l[1]);
        /* the sampling step is H/4000 = 3e-5 m */
        ck_assert_double_lt(fabs(d - glass_brute(R, H, w, f, rho, l[2])), 4e-5);
        in_wall += d < 0 && rho > R - w && l[2] > f;
        in_cavity += rho < R - w && l[2] > f && l[2] < H;
        int ok = normal_is_gradient(s, p, n, 2e-2);
        ck_assert_msg(ok != 0, "normal (%g %g %g) at (%g %g %g)", n[0], n[1], n[2], l[0], l[1],
                      l[2]);
        checked += ok == 1;
    }
    ck_assert_int_gt(in_wall, 10);
    ck_assert_int_gt(in_cavity, 30);
    ck_assert_int_gt(checked, 500);
    /* on the axis, inside the cavity, the floor is below: normal up */
    float n[3];
    float d = ms_shape_distance(s, (float[3]){1, 1, 0.5f + 0.025f}, n);
    ck_assert_float_eq_tol(d, 0.005f, 1e-6f);
    ck_assert_float_eq_tol(n[2], 1.0f, 1e-6f);
    ms_shape_destroy(s);
}
END_TEST

/* Walk a half-plane arc (x = cx + r cos th, z = cz + r sin th, y = 0)
 * outside a shape: returns the largest change of the normal between
 * neighbours; n0, n1 get the first and last normals. */
static double walk_arc(const ms_shape *s, double cx, double cz, double r, double th0, double th1,
                       float n0[3], float n1[3])
{
    float prev[3] = {0, 0, 0};
    double worst = 0;
    for (int i = 0; i <= 3000; ++i) {
        double th = th0 + (th1 - th0) * i / 3000;
        float p[3] = {(float)(cx + r * cos(th)), 0, (float)(cz + r * sin(th))}, nn[3];
        ck_assert_float_gt(ms_shape_distance(s, p, nn), 0.0f);
        if (i > 0) {
            float dd[3] = {nn[0] - prev[0], nn[1] - prev[1], nn[2] - prev[2]};
            worst = fmax(worst, len3(dd));
        } else
            memcpy(n0, nn, sizeof nn);
        memcpy(prev, nn, sizeof nn);
    }
    memcpy(n1, prev, sizeof prev);
    return worst;
}

START_TEST(glass_normals_are_continuous_over_rim_and_corners)
{
    ms_shape *s = make("glass", "{\"radius\": 0.05, \"height\": 0.12, \"wall\": 0.01, "
                                "\"floor\": 0.02}");
    float n0[3], n1[3];
    /* around the rim on a half circle of 9 mm about its middle (the rim
     * is 1 cm wide): from outside (normal +x) over it into the cavity (-x) */
    double worst = walk_arc(s, 0.045, 0.12, 0.009, 0, PI, n0, n1);
    ck_assert_msg(worst < 0.02, "over the rim the normal jumps by %g", worst);
    ck_assert_float_eq_tol(n0[0], 1.0f, 1e-3f);
    ck_assert_float_eq_tol(n1[0], -1.0f, 1e-3f);
    /* the concave inner corner, 3 mm from the floor, towards the wall */
    const float c0[3] = {0.0f, 0, 0.023f}, c1[3] = {0.037f, 0, 0.023f};
    worst = max_normal_step(s, c0, c1, 3000, n0, n1);
    ck_assert_msg(worst < 0.02, "in the inner corner the normal jumps by %g", worst);
    ck_assert_float_eq_tol(n0[2], 1.0f, 1e-3f);
    ck_assert_double_lt(n1[0], -0.5); /* turned towards the wall's normal */
    /* around the outer bottom edge, 4 mm from it */
    worst = walk_arc(s, 0.05, 0, 0.004, -PI / 2, 0, n0, n1);
    ck_assert_msg(worst < 0.02, "at the bottom edge the normal jumps by %g", worst);
    ck_assert_float_eq_tol(n0[2], -1.0f, 1e-3f);
    ck_assert_float_eq_tol(n1[0], 1.0f, 1e-3f);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(glass_footprint_and_depth)
{
    const ms_grid g = {
        .nx = 120, .ny = 120, .dx = 0.002f, .dy = 0.002f, .origin = {-0.12f, -0.12f}};
    ms_shape *s = make("glass", "{\"radius\": 0.1, \"height\": 0.12, \"wall\": 0.03, "
                                "\"floor\": 0.02}");
    unsigned char *mask = calloc((size_t)g.nx * g.ny, 1);
    ck_assert_int_eq(ms_shape_footprint(s, &g, 0.06f, mask), MS_OK); /* an annulus */
    long cells = 0;
    for (int i = 0; i < g.nx * g.ny; ++i)
        cells += mask[i];
    double area = PI * (0.01 - 0.0049), err = fabs(cells * 4e-6 - area);
    ck_assert_msg(err < 2 * PI * (0.1 + 0.07) * 0.002 * 0.5, "annulus %g vs %g", cells * 4e-6,
                  area);
    memset(mask, 0, (size_t)g.nx * g.ny);
    ck_assert_int_eq(ms_shape_footprint(s, &g, 0.01f, mask), MS_OK); /* the floor: a disc */
    cells = 0;
    for (int i = 0; i < g.nx * g.ny; ++i)
        cells += mask[i];
    ck_assert_double_lt(fabs(cells * 4e-6 - PI * 0.01), 2 * PI * 0.1 * 0.002 * 0.5);
    /* depth of water at level 0.1 m: 0.08 m over the floor, 0 on the wall */
    float *depth = malloc(sizeof(float) * (size_t)(g.nx * g.ny));
    for (int i = 0; i < g.nx * g.ny; ++i)
        depth[i] = 1.0f;
    ck_assert_int_eq(ms_shape_depth(s, &g, 0.1f, depth), MS_OK);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            double rho = hypot(-0.12 + (i + 0.5) * 0.002, -0.12 + (j + 0.5) * 0.002);
            double want = rho > 0.1 ? 1.0 : rho >= 0.07 ? 0.0 : 0.08;
            ck_assert_double_lt(fabs(depth[j * g.nx + i] - want), 1e-6);
        }
    free(depth);
    free(mask);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(capsule_footprint_and_marched_depth)
{
    /* lying along x: its section at height z is a stadium */
    ms_shape *s = make("capsule", "{\"a\": [-0.2, 0, 0], \"b\": [0.2, 0, 0], \"radius\": 0.1}");
    ck_assert_int_eq(ms_shape_set_pose(s, (float[3]){0.5f, 0.5f, -0.02f}, NULL), MS_OK);
    const ms_grid g = {.nx = 250, .ny = 250, .dx = 0.004f, .dy = 0.004f, .origin = {0, 0}};
    unsigned char *mask = calloc((size_t)g.nx * g.ny, 1);
    ck_assert_int_eq(ms_shape_footprint(s, &g, 0.04f, mask), MS_OK);
    long cells = 0;
    for (int i = 0; i < g.nx * g.ny; ++i)
        cells += mask[i];
    double hw = sqrt(0.01 - 0.06 * 0.06); /* half width at 6 cm above the axis */
    double area = 0.4 * 2 * hw + PI * hw * hw, perim = 0.8 + 2 * PI * hw;
    ck_assert_double_lt(fabs(cells * 1.6e-5 - area), perim * 0.004 * 0.5);
    /* the depth of water at z = 0.2 m above it, marched (no height_at) */
    float *depth = malloc(sizeof(float) * (size_t)(g.nx * g.ny));
    for (int i = 0; i < g.nx * g.ny; ++i)
        depth[i] = 1.0f;
    ck_assert_int_eq(ms_shape_depth(s, &g, 0.2f, depth), MS_OK);
    int over = 0;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            double x = (i + 0.5) * 0.004 - 0.5, y = (j + 0.5) * 0.004 - 0.5;
            double ex = fmax(fabs(x) - 0.2, 0), q = 0.01 - ex * ex - y * y;
            double want = q > 0 ? 0.2 - (-0.02 + sqrt(q)) : 1.0;
            over += q > 0;
            ck_assert_msg(fabs(depth[j * g.nx + i] - want) < 1e-4, "%d %d: %g != %g", i, j,
                          depth[j * g.nx + i], want);
        }
    ck_assert_int_gt(over, 3000);
    free(depth);
    free(mask);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(terrain_from_heights_matches_a_plane)
{
    /* a planar ramp h = 0.1 x - 0.05 y + 0.2 sampled 5 x 4 over 2 x 1.5 m */
    char json[1024];
    size_t len = (size_t)snprintf(json, sizeof json, "{\"size\": [2, 1.5], \"heights\": [");
    for (int j = 0; j < 4; ++j) {
        len += (size_t)snprintf(json + len, sizeof json - len, "%s[", j ? "," : "");
        for (int i = 0; i < 5; ++i)
            len += (size_t)snprintf(json + len, sizeof json - len, "%s%.6f", i ? "," : "",
                                    0.1 * (i * 0.5) - 0.05 * (j * 0.5) + 0.2);
        len += (size_t)snprintf(json + len, sizeof json - len, "]");
    }
    snprintf(json + len, sizeof json - len, "], \"base\": 0.5}");
    ms_shape *s = make("terrain", json);
    const double k = 1 / sqrt(1 + 0.01 + 0.0025);
    ms_rng r;
    ms_rng_seed(&r, 7);
    for (int i = 0; i < 2000; ++i) {
        float p[3] = {urand(&r, 0.3f, 1.7f), urand(&r, 0.3f, 1.2f), 0}, n[3];
        double h = 0.1 * p[0] - 0.05 * p[1] + 0.2;
        /* inside no deeper than 0.1 m: the sides (0.3 m away) do not blend in */
        p[2] = (float)(h + urand(&r, -0.1f, 0.2f));
        float d = ms_shape_distance(s, p, n);
        ck_assert_double_lt(fabs(d - (p[2] - h) * k), 2e-6);
        ck_assert_double_lt(fabs(n[0] + 0.1 * k), 1e-5);
        ck_assert_double_lt(fabs(n[1] - 0.05 * k), 1e-5);
        ck_assert_double_lt(fabs(n[2] - k), 1e-5);
    }
    /* beside the map: the side face; below the base: the bottom */
    float n[3];
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){2.3f, 0.7f, 0.1f}, n), 0.3f, 1e-6f);
    ck_assert_float_eq_tol(n[0], 1.0f, 1e-6f);
    float lo[3], hi[3];
    ms_shape_bounds(s, lo, hi);
    ck_assert_float_eq_tol(lo[2], 0.2f - 0.075f - 0.5f, 1e-6f);
    ck_assert_float_eq_tol(hi[2], 0.4f, 1e-6f);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){1, 0.7f, lo[2] - 0.1f}, n), 0.1f, 1e-6f);
    ck_assert_float_eq_tol(n[2], -1.0f, 1e-6f);
    /* depth for a water level z = 0.35: z - h, 0 where the ground is dry */
    const ms_grid g = {.nx = 40, .ny = 30, .dx = 0.05f, .dy = 0.05f, .origin = {0, 0}};
    float depth[40 * 30];
    for (int i = 0; i < 40 * 30; ++i)
        depth[i] = 9;
    ck_assert_int_eq(ms_shape_depth(s, &g, 0.35f, depth), MS_OK);
    int dry = 0;
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) {
            double x = (i + 0.5) * 0.05, y = (j + 0.5) * 0.05;
            double want = fmax(0.35 - (0.1 * x - 0.05 * y + 0.2), 0);
            dry += want == 0;
            ck_assert_double_lt(fabs(depth[j * 40 + i] - want), 1e-6);
        }
    ck_assert_int_gt(dry, 10);
    ms_shape_destroy(s);
}
END_TEST

/* Writes a w x h grey PNG (16 bit if wide) of f(i, row) in [0, 1]. */
static void write_png(const char *path, int w, int h, int wide, double (*f)(int, int))
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = wide ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
    void *pix = malloc(PNG_IMAGE_SIZE(img));
    for (int r = 0; r < h; ++r)
        for (int i = 0; i < w; ++i) {
            double v = f(i, r);
            if (wide)
                ((png_uint_16 *)pix)[r * w + i] = (png_uint_16)lround(v * 65535);
            else
                ((png_byte *)pix)[r * w + i] = (png_byte)lround(v * 255);
        }
    ck_assert(png_image_write_to_file(&img, path, 0, pix, 0, NULL));
    free(pix);
}

/* a bowl: 1 at the rim, 0 at the centre of a 33 x 33 image */
static double bowl(int i, int r)
{
    double x = (i - 16) / 16.0, y = (r - 16) / 16.0;
    return fmin(1, 0.5 * (x * x + y * y));
}

static double ramp_rows(int i, int r)
{
    (void)i;
    return r / 8.0; /* 9 rows: the top row is 0 */
}

START_TEST(terrain_from_png)
{
    char dir[] = "/tmp/ms_test_terrain_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char path[256], json[512];
    for (int wide = 0; wide < 2; ++wide) {
        snprintf(path, sizeof path, "%s/bowl%d.png", dir, wide);
        write_png(path, 33, 33, wide, bowl);
        snprintf(json, sizeof json,
                 "{\"png\": \"%s\", \"size\": [0.64, 0.64], \"height_range\": [-0.3, -0.1]}", path);
        ms_shape *s = make("terrain", json);
        /* at the samples the height is the pixel's, quantised */
        const ms_grid g = {
            .nx = 33, .ny = 33, .dx = 0.02f, .dy = 0.02f, .origin = {-0.01f, -0.01f}};
        float depth[33 * 33];
        for (int i = 0; i < 33 * 33; ++i)
            depth[i] = 9;
        ck_assert_int_eq(ms_shape_depth(s, &g, 0.0f, depth), MS_OK);
        double q = wide ? 0.2 / 65535 : 0.2 / 255;
        for (int j = 0; j < 33; ++j) /* cell centres on the samples */
            for (int i = 0; i < 33; ++i) {
                double h = -0.3 + 0.2 * bowl(i, 32 - j);
                ck_assert_double_le(fabs(depth[j * 33 + i] + h), 0.5 * q + 1e-6);
            }
        /* off the map the depth is left as it was */
        const ms_grid off = {.nx = 4, .ny = 4, .dx = 0.1f, .dy = 0.1f, .origin = {0.6f, 0.6f}};
        float d4[16];
        for (int i = 0; i < 16; ++i)
            d4[i] = 9;
        ck_assert_int_eq(ms_shape_depth(s, &off, 0.0f, d4), MS_OK);
        /* centres from 0.65 m: the 0.64 m map ends before */
        for (int i = 0; i < 16; ++i)
            ck_assert_float_eq(d4[i], 9.0f);
        /* the middle is the lowest: the normal there points up */
        float n[3];
        ms_shape_distance(s, (float[3]){0.32f, 0.32f, 0}, n);
        ck_assert_float_eq_tol(n[2], 1.0f, 1e-4f);
        ms_shape_destroy(s);
    }
    /* the image's top row is the far (y = sy) edge */
    snprintf(path, sizeof path, "%s/rows.png", dir);
    write_png(path, 3, 9, 0, ramp_rows);
    snprintf(json, sizeof json, "{\"png\": \"%s\", \"size\": [1, 1], \"height_range\": [0, 1]}",
             path);
    ms_shape *s = make("terrain", json);
    /* h = 1 - y (8-bit steps of 1/255): distance (z - h)/sqrt(2) */
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0.5f, 1, 2}, NULL), 2 / sqrtf(2), 5e-3f);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0.5f, 0, 2}, NULL), 1 / sqrtf(2), 5e-3f);
    ms_shape_destroy(s);
    /* refusals name the key or the file */
    ms_shape *bad;
    snprintf(json, sizeof json, "{\"png\": \"%s/missing.png\"}", dir);
    MS_ASSERT_REFUSED(ms_shape_create("terrain", json, &bad), MS_ERR_IO, "missing.png");
    snprintf(path, sizeof path, "%s/colour.png", dir);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = img.height = 2;
    img.format = PNG_FORMAT_RGB;
    unsigned char rgb[12] = {0};
    ck_assert(png_image_write_to_file(&img, path, 0, rgb, 0, NULL));
    snprintf(json, sizeof json, "{\"png\": \"%s\"}", path);
    MS_ASSERT_REFUSED(ms_shape_create("terrain", json, &bad), MS_ERR_INVALID_ARGUMENT,
                      "grey-scale");
    snprintf(path, sizeof path, "%s/text.png", dir);
    FILE *f = fopen(path, "w");
    fputs("not a png", f);
    fclose(f);
    snprintf(json, sizeof json, "{\"png\": \"%s\"}", path);
    MS_ASSERT_REFUSED(ms_shape_create("terrain", json, &bad), MS_ERR_IO, "text.png");
    MS_ASSERT_REFUSED(ms_shape_create("terrain", "{\"heights\": [[0, 1], [0]]}", &bad),
                      MS_ERR_PARSE, "heights[1]");
    MS_ASSERT_REFUSED(ms_shape_create("terrain", "{\"heights\": [[0, 1], [0, \"x\"]]}", &bad),
                      MS_ERR_PARSE, "heights[1][1]");
    MS_ASSERT_REFUSED(ms_shape_create("terrain", "{\"heights\": [[0, 1]]}", &bad), MS_ERR_PARSE,
                      "at least 2 rows");
    MS_ASSERT_REFUSED(ms_shape_create("terrain",
                                      "{\"heights\": [[0, 1], [0, 1]], "
                                      "\"height_range\": [0, 1]}",
                                      &bad),
                      MS_ERR_INVALID_ARGUMENT, "height_range");
    MS_ASSERT_REFUSED(ms_shape_create("terrain",
                                      "{\"heights\": [[0, 1], [0, 1]], "
                                      "\"png\": \"a.png\"}",
                                      &bad),
                      MS_ERR_INVALID_ARGUMENT, "both");
    MS_ASSERT_REFUSED(ms_shape_create("terrain", "{\"size\": [1, -1]}", &bad),
                      MS_ERR_INVALID_ARGUMENT, "size[1]");
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST

START_TEST(every_shape_has_working_defaults)
{
    const char *kinds[] = {"plane", "sphere", "box", "capsule", "glass", "terrain"};
    for (int k = 0; k < 6; ++k) {
        ms_shape *s = make(kinds[k], NULL);
        ck_assert_str_eq(ms_shape_kind(s), kinds[k]);
        float lo[3], hi[3], n[3];
        ms_shape_bounds(s, lo, hi);
        for (int a = 0; a < 3; ++a)
            ck_assert(lo[a] <= hi[a]);
        /* a point far above is outside with an upward-ish normal */
        float d = ms_shape_distance(s, (float[3]){0.01f, 0.02f, 50}, n);
        ck_assert_msg(d > 40 && n[2] > 0.9f, "%s: d %g n %g", kinds[k], d, n[2]);
        ck_assert_double_lt(fabs(len3(n) - 1), 1e-5);
        ms_shape_destroy(s);
        s = make(kinds[k], "{}");
        ms_shape_destroy(s);
    }
}
END_TEST

static Suite *shapes_suite(void)
{
    Suite *s = suite_create("shapes");
    TCase *tc = tcase_create("basic");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, sphere_matches_closed_form);
    tcase_add_test(tc, box_matches_closed_form_inside_outside_edges_corners);
    tcase_add_test(tc, rounded_box_distance_and_gradient);
    tcase_add_test(tc, box_normals_are_continuous_across_edges);
    tcase_add_test(tc, plane_matches_closed_form);
    tcase_add_test(tc, pose_translates_and_moves);
    tcase_add_test(tc, bad_parameters_name_the_key);
    tcase_add_test(tc, footprints_match_analytic_areas);
    tcase_add_test(tc, depth_over_a_submerged_sphere);
    suite_add_tcase(s, tc);
    TCase *more = tcase_create("more");
    tcase_set_timeout(more, 60);
    tcase_add_test(more, capsule_matches_closed_form);
    tcase_add_test(more, glass_matches_closed_form);
    tcase_add_test(more, glass_normals_are_continuous_over_rim_and_corners);
    tcase_add_test(more, glass_footprint_and_depth);
    tcase_add_test(more, capsule_footprint_and_marched_depth);
    tcase_add_test(more, terrain_from_heights_matches_a_plane);
    tcase_add_test(more, terrain_from_png);
    tcase_add_test(more, every_shape_has_working_defaults);
    tcase_add_test(more, orientation_turns_distance_normal_velocity_and_bounds);
    suite_add_tcase(s, more);
    return s;
}

int main(void)
{
    return ms_test_run(shapes_suite());
}
