/* The look of the scene's objects: an obstacle under the water
 * is seen through it, refracted (Snell's law makes it look nearer and so
 * larger from above), and an obstacle standing out of the water is seen
 * in its reflection, at the mirror image of its footprint. Each case draws
 * the same flat field with and without the objects and measures where the
 * pictures differ. MS_LOOK_DUMP=DIR writes the pictures as PNGs to look at. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "support_render.h"

#define REQUIRE_GL()                                                   \
    do {                                                               \
        if (!MS_HAVE_GL)                                               \
            MS_SKIP("built without OSMesa and EGL: nothing can draw"); \
    } while (0)

#define N 64  /* field cells per side */
#define W 128 /* image side */
#define PI 3.14159265358979

static ms_scene *parse_ok(const char *text)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return sc;
}

/* The scene's desc at W x W with the given camera. */
static ms_renderer_desc camera_desc(const ms_scene *sc, const float eye[3], const float target[3],
                                    float fov)
{
    ms_renderer_desc d = ms_renderer_desc_default();
    ms_status st = ms_renderer_desc_from_scene(sc, &d);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    d.width = d.height = W;
    d.caustics_resolution = 128;
    const float up[3] = {0, 0, 1}, north[3] = {0, 1, 0};
    memcpy(d.eye, eye, sizeof d.eye);
    memcpy(d.target, target, sizeof d.target);
    /* looking straight down, +y is up in the image */
    const int down = fabsf(eye[0] - target[0]) + fabsf(eye[1] - target[1]) < 1e-6f;
    memcpy(d.up, down ? north : up, sizeof d.up);
    d.fov = fov;
    return d;
}

/* The picture of the still water (level above the floor) of d's pool,
 * drawn with the scene's objects (sc) or without (NULL); a copy. */
static unsigned char *picture(const ms_renderer_desc *d, const ms_scene *sc, const char *name)
{
    ms_renderer *r = NULL;
    ms_status st = ms_renderer_create_desc(d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    float *h = field(N, d->water_level - d->pool_min[2]);
    ms_grid g = {N,
                 N,
                 (d->pool_max[0] - d->pool_min[0]) / N,
                 (d->pool_max[1] - d->pool_min[1]) / N,
                 {d->pool_min[0], d->pool_min[1]}};
    st = sc ? ms_renderer_draw_scene_field(r, sc, h, &g, 0.0)
            : ms_renderer_draw_field(r, h, &g, 0.0);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    ms_test_dump_png(r, name);
    unsigned char *copy = malloc((size_t)W * W * 4);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    ms_renderer_destroy(r);
    free(h);
    return copy;
}

/* Sum over RGB of |a - b| at pixel (x, y), top row first. */
static int pixel_diff(const unsigned char *a, const unsigned char *b, int x, int y)
{
    int s = 0;
    for (int k = 0; k < 3; ++k)
        s += abs((int)a[((size_t)y * W + x) * 4 + k] - (int)b[((size_t)y * W + x) * 4 + k]);
    return s;
}

/* Mean of pixel_diff over the (2 half + 1)^2 window at (cx, cy). */
static double window_diff(const unsigned char *a, const unsigned char *b, int cx, int cy, int half)
{
    double sum = 0;
    int n = 0;
    for (int y = cy - half; y <= cy + half; ++y)
        for (int x = cx - half; x <= cx + half; ++x, ++n)
            sum += pixel_diff(a, b, x, y);
    return sum / n;
}

/* Where world point p lands in d's picture (pixel column, row from the
 * top); 0 if behind the eye. */
static int project(const ms_renderer_desc *d, const float p[3], double *col, double *row)
{
    return ms_test_project(d, p, W, W, col, row);
}

/* A sphere of radius 15 cm in a pool 1 m deep, its centre 70 cm under the
 * water, seen from 30 cm above the water. */
START_TEST(an_obstacle_under_the_water_is_seen_refracted)
{
    REQUIRE_GL();
    ms_scene *sc =
        parse_ok("{\"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 1]},"
                 " \"surface\": {\"cells\": [64, 64], \"level\": 0.9},"
                 " \"obstacles\": [{\"shape\": \"sphere\", \"params\": {\"radius\": 0.15},"
                 "   \"position\": [0.5, 0.5, 0.2]}]}");
    const float R = 0.15f, zc = 0.2f, H = 0.3f;
    ms_renderer_desc probe =
        camera_desc(sc, (float[3]){0.5f, 0.5f, 2}, (float[3]){0.5f, 0.5f, 0}, 60);
    const float L = probe.water_level;
    ck_assert_float_eq_tol(L, 0.9f, 1e-6f);
    ms_renderer_desc d =
        camera_desc(sc, (float[3]){0.5f, 0.5f, L + H}, (float[3]){0.5f, 0.5f, L}, 60);
    unsigned char *plain = picture(&d, NULL, "under_plain");
    unsigned char *with = picture(&d, sc, "under_sphere");
    /* the sphere's centre: changed (the pool's floor was there) */
    const double centre = window_diff(with, plain, W / 2, W / 2, 2);
    ck_assert_msg(centre > 30,
                  "the sphere under the water changes its centre by %.1f only "
                  "(hidden by the surface?)",
                  centre);
    /* far from it: the same picture */
    const double away = window_diff(with, plain, W / 8, W / 8, 4);
    ck_assert_msg(away < 3, "the pool's corner changed by %.1f", away);
    /* its width on the centre row: the columns that changed */
    int c0 = W, c1 = -1;
    for (int x = 0; x < W; ++x)
        if (pixel_diff(with, plain, x, W / 2) > 24)
            c0 = x < c0 ? x : c0, c1 = x;
    const double seen = c1 - c0 + 1;
    /* seen without water the sphere's outline is R/(H + D) wide (D its
     * centre's depth), through the water R/(H + D/n) (paraxial Snell) */
    const double t = tan(30.0 * PI / 180.0), n = 1.333, D = L - zc;
    const double dry = 2 * R / ((H + D) * t) * (0.5 * W),
                 wet = 2 * R / ((H + D / n) * t) * (0.5 * W);
    ck_assert_msg(fabs(seen - wet) < 3 && seen > dry + 2,
                  "the sphere is %.0f pixels wide; refracted it should be %.1f (%.1f without "
                  "the water)",
                  seen, wet, dry);
    free(with);
    free(plain);
    ms_scene_destroy(sc);
}
END_TEST

/* A slab of stone standing out of the water at the far side of the pool,
 * seen from the near side: the water in front of it mirrors it. */
START_TEST(an_obstacle_above_the_water_is_seen_in_its_reflection)
{
    REQUIRE_GL();
    ms_scene *sc =
        parse_ok("{\"surface\": {\"cells\": [64, 64], \"level\": 0.25},"
                 " \"obstacles\": [{\"shape\": \"box\", \"params\": {\"size\": [0.4, 0.1, 0.8]},"
                 "   \"position\": [0.5, 0.85, 0.4]}]}");
    ms_renderer_desc probe =
        camera_desc(sc, (float[3]){0.5f, 0.5f, 1}, (float[3]){0.5f, 0.5f, 0}, 45);
    const float L = probe.water_level;
    ms_renderer_desc d =
        camera_desc(sc, (float[3]){0.5f, -0.3f, L + 0.45f}, (float[3]){0.5f, 0.55f, L}, 50);
    d.shader = "oil"; /* reflection only: nothing under the water to confuse it */
    unsigned char *plain = picture(&d, NULL, "above_plain");
    unsigned char *with = picture(&d, sc, "above_box");
    /* the mirror image of the slab's front face 15 cm over the water */
    const float face[3] = {0.5f, 0.8f, L + 0.15f}, mirror[3] = {0.5f, 0.8f, L - 0.15f};
    double fc, fr, mc, mr;
    ck_assert(project(&d, face, &fc, &fr) && project(&d, mirror, &mc, &mr));
    const int mx = (int)lround(mc), my = (int)lround(mr);
    ck_assert_msg(my > fr + 8 && my < W - 4, "the mirror image (row %d) is not below the slab", my);
    const double reflected = window_diff(with, plain, mx, my, 2);
    ck_assert_msg(reflected > 12,
                  "the water in front of the slab changed by %.1f only "
                  "(no reflection?)",
                  reflected);
    /* beside the mirror image (its width is 0.4 m: 0.35 m to the side),
     * the same water */
    const float side[3] = {0.15f, 0.8f, L - 0.15f};
    double sc_, sr;
    ck_assert(project(&d, side, &sc_, &sr));
    const double beside = window_diff(with, plain, (int)lround(sc_), (int)lround(sr), 2);
    ck_assert_msg(beside < 3, "the water beside the reflection changed by %.1f", beside);
    free(with);
    free(plain);
    ms_scene_destroy(sc);
}
END_TEST

/* The objects move every frame and the environment is redrawn only where
 * they were and are: after a move, the picture is the one a fresh
 * renderer draws (the mipmap levels remade over the rectangle may round
 * a level apart from glGenerateMipmap's). */
START_TEST(a_moving_obstacle_leaves_no_trace_in_the_environment)
{
    REQUIRE_GL();
    ms_scene *sc = parse_ok(
        "{\"surface\": {\"cells\": [64, 64], \"level\": 0.28},"
        " \"obstacles\": [{\"shape\": \"sphere\", \"params\": {\"radius\": 0.08},"
        "   \"path\": {\"points\": [[0.3, 0.3, 0.1], [0.7, 0.7, 0.1]], \"speed\": 0.2}},"
        "  {\"shape\": \"box\", \"params\": {\"size\": [0.1, 0.1, 0.5]},"
        "   \"path\": {\"points\": [[0.2, 0.8, 0.25], [0.8, 0.8, 0.25]], \"speed\": 0.2}}]}");
    ms_renderer_desc probe =
        camera_desc(sc, (float[3]){0.5f, 0.5f, 2}, (float[3]){0.5f, 0.5f, 0}, 45);
    const float L = probe.water_level;
    ms_renderer_desc d =
        camera_desc(sc, (float[3]){0.5f, -0.4f, L + 0.7f}, (float[3]){0.5f, 0.5f, L}, 50);
    ms_renderer *r = NULL;
    ms_status st = ms_renderer_create_desc(&d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    float *h = field(N, L - d.pool_min[2]);
    ms_grid g = {N, N, 1.0f / N, 1.0f / N, {0, 0}};
    const double times[3] = {0.0, 1.5, 2.5};
    for (int k = 0; k < 3; ++k) {
        st = ms_renderer_draw_scene_field(r, sc, h, &g, times[k]);
        ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    }
    ms_test_dump_png(r, "moved");
    /* a fresh renderer's picture of the last time */
    ms_renderer *fresh = NULL;
    ck_assert_int_eq(ms_renderer_create_desc(&d, &fresh), MS_OK);
    ck_assert_int_eq(ms_renderer_draw_scene_field(fresh, sc, h, &g, times[2]), MS_OK);
    const unsigned char *a = ms_renderer_pixels(r, NULL, NULL);
    const unsigned char *b = ms_renderer_pixels(fresh, NULL, NULL);
    int worst = 0;
    for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t i = ((size_t)y * W + (size_t)x) * 4 + (size_t)c;
                worst = abs((int)a[i] - (int)b[i]) > worst ? abs((int)a[i] - (int)b[i]) : worst;
            }
    ck_assert_msg(worst <= 2, "after moving, a pixel differs from a fresh picture by %d levels",
                  worst);
    /* and the move showed: the first picture differs from the last */
    ms_renderer *first = NULL;
    ck_assert_int_eq(ms_renderer_create_desc(&d, &first), MS_OK);
    ck_assert_int_eq(ms_renderer_draw_scene_field(first, sc, h, &g, times[0]), MS_OK);
    const double moved =
        window_diff(ms_renderer_pixels(first, NULL, NULL), b, W / 2, W / 2, W / 2 - 1);
    ck_assert_msg(moved > 1, "moving the obstacles changed the picture by %.2f only", moved);
    ms_renderer_destroy(first);
    ms_renderer_destroy(fresh);
    ms_renderer_destroy(r);
    free(h);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *look_suite(void)
{
    Suite *s = suite_create("look_objects");
    TCase *tc = tcase_create("look_objects");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, an_obstacle_under_the_water_is_seen_refracted);
    tcase_add_test(tc, an_obstacle_above_the_water_is_seen_in_its_reflection);
    tcase_add_test(tc, a_moving_obstacle_leaves_no_trace_in_the_environment);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(look_suite());
}
