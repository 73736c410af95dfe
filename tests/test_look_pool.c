/* The pool's look. The liquid stays inside its pool (fig4c): in the dam break of
 * Fig. 4c (domain 1 x 1 x 0.5 m, the fill 0.44 m high) the liquid runs up
 * the right wall to the domain's top, higher than the rim the renderer
 * used to put just above still water (0.18 m + 5 cm), and it was drawn
 * over the deck beyond the rim. From an eye above the rim, everything
 * inside the pool below its rim is seen through the pool's opening, so a
 * liquid that stays in its pool changes only pixels inside the opening's
 * projection. The case draws a run-up field and a flat one with the same
 * camera and asks that no pixel outside the opening differs.
 * MS_LOOK_DUMP=DIR writes the pictures as PNGs to look at. */
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

#define N 50  /* field cells per side: fig4c's SPH field */
#define W 160 /* image side */
#define PI 3.14159265358979

/* fig4c's domain and fill, no surface section */
static const char *const dam =
    "{\"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
    " \"volume\": {\"spacing\": 0.044, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 1, 0.44]}],"
    "   \"field\": [50, 50]}}";

static void sub3(const float a[3], const float b[3], double o[3])
{
    for (int k = 0; k < 3; ++k)
        o[k] = (double)a[k] - b[k];
}

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static void unit3(double v[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; ++k)
        v[k] /= n;
}

/* World point p in pixels (column, row from the top) of d's W x W camera
 * (gluLookAt + gluPerspective, square image). */
static void project(const ms_renderer_desc *d, const float p[3], double *col, double *row)
{
    double f[3], s[3], u[3], v[3], up[3] = {d->up[0], d->up[1], d->up[2]};
    sub3(d->target, d->eye, f);
    unit3(f);
    cross3(f, up, s);
    unit3(s);
    cross3(s, f, u);
    sub3(p, d->eye, v);
    const double z = v[0] * f[0] + v[1] * f[1] + v[2] * f[2];
    const double t = tan(0.5 * d->fov * PI / 180.0);
    const double nx = (v[0] * s[0] + v[1] * s[1] + v[2] * s[2]) / (z * t);
    const double ny = (v[0] * u[0] + v[1] * u[1] + v[2] * u[2]) / (z * t);
    *col = 0.5 * (nx + 1) * W;
    *row = 0.5 * (1 - ny) * W;
}

/* The distance (pixels) by which pixel centre (x, y) lies outside the
 * convex quad q (negative inside). */
static double outside_quad(double q[4][2], double x, double y)
{
    double worst = -1e9;
    /* orientation of the quad */
    const double area =
        (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    for (int k = 0; k < 4; ++k) {
        const double *a = q[k], *b = q[(k + 1) % 4];
        double ex = b[0] - a[0], ey = b[1] - a[1], len = sqrt(ex * ex + ey * ey);
        double c = (ex * (y - a[1]) - ey * (x - a[0])) / len; /* > 0: left of a->b */
        double out = area > 0 ? -c : c;
        worst = out > worst ? out : worst;
    }
    return worst;
}

/* A dam break's run-up against the right wall (x = 1): 0.1 m of liquid,
 * rising to 0.5 m, the domain's top, at the wall. */
static float *run_up(void)
{
    float *h = field(N, 0.1f);
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            float x = ((float)i + 0.5f) / N, y = ((float)j + 0.5f) / N;
            h[j * N + i] += 0.4f * expf(-(1 - x) * (1 - x) / (2 * 0.08f * 0.08f)) *
                            (0.8f + 0.2f * cosf(12 * y));
        }
    return h;
}

START_TEST(a_run_up_against_the_wall_stays_inside_the_pool)
{
    REQUIRE_GL();
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_parse(dam, strlen(dam), &sc) == MS_OK, "%s", ms_last_error());
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_msg(ms_renderer_desc_from_scene(sc, &d) == MS_OK, "%s", ms_last_error());
    d.width = d.height = W;
    /* fig4c's view: from the front, above the domain's top */
    const float eye[3] = {0.5f, -0.6f, 1.1f}, target[3] = {0.5f, 0.5f, 0.1f}, up[3] = {0, 0, 1};
    memcpy(d.eye, eye, sizeof eye);
    memcpy(d.target, target, sizeof target);
    memcpy(d.up, up, sizeof up);
    d.fov = 50;
    ms_grid g = {N, N, 1.0f / N, 1.0f / N, {0, 0}};
    float *flat = field(N, 0.1f), *high = run_up();
    ms_renderer *a = NULL, *b = NULL;
    ms_status st = ms_renderer_create_desc(&d, &a);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    ck_assert_int_eq(ms_renderer_create_desc(&d, &b), MS_OK);
    ck_assert_int_eq(ms_renderer_draw_scene_field(a, sc, flat, &g, 0.0), MS_OK);
    ck_assert_int_eq(ms_renderer_draw_scene_field(b, sc, high, &g, 0.0), MS_OK);
    ms_test_dump_png(a, "pool_flat");
    ms_test_dump_png(b, "pool_run_up");
    /* the pool's opening at its rim, projected */
    const float rim = d.pool_max[2];
    const float corner[4][3] = {{d.pool_min[0], d.pool_min[1], rim},
                                {d.pool_max[0], d.pool_min[1], rim},
                                {d.pool_max[0], d.pool_max[1], rim},
                                {d.pool_min[0], d.pool_max[1], rim}};
    double q[4][2];
    for (int k = 0; k < 4; ++k)
        project(&d, corner[k], &q[k][0], &q[k][1]);
    const unsigned char *pa = ms_renderer_pixels(a, NULL, NULL),
                        *pb = ms_renderer_pixels(b, NULL, NULL);
    int beyond = 0, inside = 0;
    double farthest = 0;
    for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x) {
            const size_t i = ((size_t)y * W + (size_t)x) * 4;
            int diff = 0;
            for (int c = 0; c < 3; ++c)
                diff = abs((int)pa[i + c] - (int)pb[i + c]) > diff
                           ? abs((int)pa[i + c] - (int)pb[i + c])
                           : diff;
            if (diff <= 8)
                continue;
            const double out = outside_quad(q, x + 0.5, y + 0.5);
            if (out > 1.5) { /* a pixel's rasterisation slack at the rim's edge */
                ++beyond;
                farthest = out > farthest ? out : farthest;
            } else {
                ++inside;
            }
        }
    /* the run-up is seen (the case measures something) ... */
    ck_assert_msg(inside > W * W / 50, "the run-up changed only %d pixels inside the pool", inside);
    /* ... and never beyond the pool's rim, over the deck */
    ck_assert_msg(beyond == 0,
                  "%d liquid pixels drawn beyond the pool's rim (%.2f m high), up to %.1f pixels "
                  "out, over the deck",
                  beyond, rim, farthest);
    /* the rim goes up to the domain's top, which the run-up reaches */
    ck_assert_float_eq_tol(rim, 0.5f, 1e-6f);
    ms_renderer_destroy(a);
    ms_renderer_destroy(b);
    free(flat);
    free(high);
    ms_scene_destroy(sc);
}
END_TEST

/* The luma's standard deviation over the band of the picture in front of
 * stir's paddle (rows 3/5 to 4/5, the middle half of the columns): the
 * floor's grout lines seen through the water. */
static double band_contrast(const ms_renderer *r)
{
    const unsigned char *p = ms_renderer_pixels(r, NULL, NULL);
    double s = 0, s2 = 0;
    long n = 0;
    for (int y = 3 * W / 5; y < 4 * W / 5; ++y)
        for (int x = W / 4; x < 3 * W / 4; ++x, ++n) {
            const size_t i = ((size_t)y * W + (size_t)x) * 4;
            const double l = 0.2126 * p[i] + 0.7152 * p[i + 1] + 0.0722 * p[i + 2];
            s += l;
            s2 += l * l;
        }
    return sqrt(fmax(s2 / n - (s / n) * (s / n), 0.0));
}

/* The stirred pool (data/scenes/stir.json) is seen through to its floor:
 * after 10 s of the paddle, the tiles in front of it keep most of the
 * contrast they have under still water. The scene looks its refraction up
 * through the point the refracted ray meets (the water shader's parallax
 * 1), so a slope bends it by the water's 12 cm, not by the eye's 1.5 m:
 * looked up along the ray's direction (parallax 0), the churned surface
 * (slopes of 0.12 rms) scrambles the grout into a flat blue, 0.41 of the
 * still contrast at 10 s here; 0.96 at 512 x 512 with parallax 1. */
START_TEST(a_stirred_pool_shows_its_floor)
{
    REQUIRE_GL();
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load("data/scenes/stir.json", &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_msg(ms_sim_create_from_scene(sc, 1, &sim) == MS_OK, "%s", ms_last_error());
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    d.width = d.height = W;
    ms_renderer *r = NULL;
    st = ms_renderer_create_desc(&d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
    ck_assert_int_eq(ms_renderer_draw(r, sim), MS_OK);
    const double still = band_contrast(r);
    for (int f = 1; f < 600; ++f)
        ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
    ck_assert_int_eq(ms_renderer_draw(r, sim), MS_OK);
    ms_test_dump_png(r, "stir_10s");
    const double stirred = band_contrast(r);
    ck_assert_msg(still > 4.0, "still water shows no floor: contrast %.2f", still);
    ck_assert_msg(stirred > 0.7 * still,
                  "the stirred pool hides its floor: contrast %.2f, %.2f under still water",
                  stirred, still);
    ms_renderer_destroy(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *look_suite(void)
{
    Suite *s = suite_create("look_pool");
    TCase *tc = tcase_create("look_pool");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, a_run_up_against_the_wall_stays_inside_the_pool);
    tcase_add_test(tc, a_stirred_pool_shows_its_floor);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(look_suite());
}
