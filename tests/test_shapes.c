/* Collision shapes: distances and normals against closed forms at random
 * points (inside, outside, edges, corners), normals continuous across box
 * edges, footprints against analytic areas, depths, parameter refusals. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/internal.h"
#include "modesplit/modesplit.h"
#include "shape/shape.h"
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
                          "box %d offset %g: normals (%g %g %g) .. (%g %g %g)", b, e, n0[0],
                          n0[1], n0[2], n1[0], n1[1], n1[2]);
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

START_TEST(bad_parameters_name_the_key)
{
    ms_shape *s = (ms_shape *)&s;
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": -1}", &s),
                      MS_ERR_INVALID_ARGUMENT, "radius -1 m");
    ck_assert_ptr_null(s);
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": \"big\"}", &s), MS_ERR_PARSE,
                      "radius must be a number");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radus\": 1}", &s), MS_ERR_INVALID_ARGUMENT,
                      "unknown key \"radus\"");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "{\"radius\": 1", &s), MS_ERR_PARSE, "line 1");
    MS_ASSERT_REFUSED(ms_shape_create("sphere", "[1]", &s), MS_ERR_PARSE, "JSON object");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"size\": [1, 2]}", &s), MS_ERR_PARSE,
                      "size must be an array of 3");
    MS_ASSERT_REFUSED(ms_shape_create("box", "{\"size\": [1, 0, 1]}", &s),
                      MS_ERR_INVALID_ARGUMENT, "size[1] 0 m");
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
    MS_ASSERT_REFUSED(ms_shape_footprint(s, &g, NAN, mask), MS_ERR_INVALID_ARGUMENT,
                      "water level");
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
                ck_assert_msg(fabs(depth[j * g.nx + i] - want) < 2e-5, "mode %d cell %d %d: %g != %g",
                              mode, i, j, depth[j * g.nx + i], want);
            }
        ck_assert_int_gt(over, 1000);
        free(depth);
        s->vt = keep;
    }
    ms_shape_destroy(s);
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
    return s;
}

int main(void)
{
    return ms_test_run(shapes_suite());
}
