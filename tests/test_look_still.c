/* What a person sees of a pool left alone: fig1's pool without the
 * pointer (2000 particles, 50 x 50 SPH field under a 200 x 200 wave grid,
 * both couplings), run for 30 simulated seconds and drawn by the water
 * shader, against the same pool drawn as a flat sheet of water at the
 * run's mean level with the same camera. Inside the water's outline (the
 * pool's opening at the water level, as projected by the camera) the
 * frame must show:
 *  - no backdrop through the water: a hole to the floor or a slope steep
 *    enough to refract past the pool shows the sky and grass of the
 *    cubemap; no pixel may be further from the flat picture than
 *    FAR_APART (8-bit, summed over RGB), and the mean difference stays
 *    under MEAN_APART;
 *  - no clipped pixel the flat picture does not have (a channel at 0 or
 *    255);
 *  - no speckle: the high-frequency energy (mean |discrete Laplacian| of
 *    the luminance over the outline) at most SPECKLE_FACTOR times the flat
 *    picture's (tiles and caustic-free refraction of a flat sheet give its
 *    own).
 * The bounds hold the pictures of 30 s with room: measured below.
 * MS_LOOK_DUMP=DIR writes both pictures as PNGs to look at. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "support_render.h"

#define W 256
#define FAR_APART 150
#define MEAN_APART 12.0
#define SPECKLE_FACTOR 1.5

static const char still_pool[] =
    "{\"name\": \"still_pool\", \"frame_dt\": 0.016667, \"duration\": 30,"
    " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
    " \"volume\": {\"spacing\": 0.05, \"gas_constant\": 100, \"viscosity\": 0.5,"
    "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [1, 1, 0.25]}], \"field\": [50, 50]},"
    " \"surface\": {\"cells\": [200, 200], \"wave_speed\": 0.2, \"damping\": 0.8},"
    " \"coupling\": {\"n_time\": 0, \"surface_from_volume\": 0.05, \"volume_from_surface\": 0.3},"
    " \"render\": {\"width\": 256, \"height\": 256, \"shader\": \"water\", \"cubemap\": "
    "\"builtin\"}}";

/* The distance (pixels) by which (x, y) lies outside the convex quad q
 * (negative inside). */
static double outside_quad(double q[4][2], double x, double y)
{
    double worst = -1e9;
    const double area =
        (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    for (int k = 0; k < 4; ++k) {
        const double *a = q[k], *b = q[(k + 1) % 4];
        const double ex = b[0] - a[0], ey = b[1] - a[1], len = sqrt(ex * ex + ey * ey);
        const double c = (ex * (y - a[1]) - ey * (x - a[0])) / len;
        const double out = area > 0 ? -c : c;
        worst = out > worst ? out : worst;
    }
    return worst;
}

static double luma(const unsigned char *p)
{
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

/* mean |4 L(x, y) - L(x +- 1, y) - L(x, y +- 1)| over the inside pixels */
static double speckle(const unsigned char *px, const unsigned char *in)
{
    double sum = 0.0;
    long n = 0;
    for (int y = 1; y < W - 1; ++y)
        for (int x = 1; x < W - 1; ++x) {
            if (!in[y * W + x])
                continue;
            const unsigned char *c = px + 4 * ((size_t)y * W + x);
            const double l =
                4 * luma(c) - luma(c - 4) - luma(c + 4) - luma(c - 4 * W) - luma(c + 4 * W);
            sum += fabs(l);
            n++;
        }
    return n ? sum / (double)n : 0.0;
}

START_TEST(a_still_pool_after_30_s_looks_like_still_water)
{
    if (!MS_HAVE_GL)
        MS_SKIP("built without OSMesa and EGL: nothing can draw");
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_parse(still_pool, strlen(still_pool), &sc) == MS_OK, "%s",
                  ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    for (int f = 0; f < 30 * 60; ++f)
        ck_assert_msg(ms_sim_step(sim, ms_scene_frame_dt(sc)) == MS_OK, "%s", ms_last_error());
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_msg(ms_renderer_desc_from_scene(sc, &d) == MS_OK, "%s", ms_last_error());
    ms_renderer *a = NULL, *b = NULL;
    ms_status st = ms_renderer_create_desc(&d, &a);
    if (st == MS_ERR_UNSUPPORTED)
        MS_SKIP("no GL context can be made here");
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ck_assert_int_eq(ms_renderer_create_desc(&d, &b), MS_OK);
    ck_assert_msg(ms_renderer_draw(a, sim) == MS_OK, "%s", ms_last_error());
    /* the flat sheet at the run's mean level */
    int nx, ny;
    const float *h = ms_sim_height(sim, &nx, &ny);
    double level = 0.0;
    for (int k = 0; k < nx * ny; ++k)
        level += h[k] / (double)(nx * ny);
    float *flat = field(nx, (float)level);
    ms_grid g;
    ck_assert_int_eq(ms_sim_field_grid(sim, MS_FIELD_COMBINED, &g), MS_OK);
    ck_assert_msg(ms_renderer_draw_scene_field(b, sc, flat, &g, ms_sim_time(sim)) == MS_OK, "%s",
                  ms_last_error());
    ms_test_dump_png(a, "still_pool_30s");
    ms_test_dump_png(b, "still_pool_flat");
    /* the water's outline: the opening at the water level, a cell in */
    double q[4][2];
    const float corners[4][2] = {{0.02f, 0.02f}, {0.98f, 0.02f}, {0.98f, 0.98f}, {0.02f, 0.98f}};
    for (int k = 0; k < 4; ++k) {
        const float p[3] = {corners[k][0], corners[k][1], (float)level};
        ck_assert(ms_test_project(&d, p, W, W, &q[k][0], &q[k][1]));
    }
    unsigned char *in = calloc(W * W, 1);
    ck_assert_ptr_nonnull(in);
    long inside = 0;
    for (int y = 0; y < W; ++y)
        for (int x = 0; x < W; ++x)
            if (outside_quad(q, x + 0.5, y + 0.5) < -1.0) {
                in[y * W + x] = 1;
                inside++;
            }
    ck_assert_int_gt(inside, W * W / 10);
    const unsigned char *pa = ms_renderer_pixels(a, NULL, NULL);
    const unsigned char *pb = ms_renderer_pixels(b, NULL, NULL);
    int far = 0, worst = 0, clipped = 0;
    double mean = 0.0;
    for (int k = 0; k < W * W; ++k) {
        if (!in[k])
            continue;
        int dsum = 0, clip_a = 0, clip_b = 0;
        for (int c = 0; c < 3; ++c) {
            dsum += abs((int)pa[4 * k + c] - (int)pb[4 * k + c]);
            clip_a |= pa[4 * k + c] == 0 || pa[4 * k + c] == 255;
            clip_b |= pb[4 * k + c] == 0 || pb[4 * k + c] == 255;
        }
        far += dsum > FAR_APART;
        worst = dsum > worst ? dsum : worst;
        clipped += clip_a && !clip_b;
        mean += dsum / (double)inside;
    }
    const double sa = speckle(pa, in), sb = speckle(pb, in);
    printf("still pool at 30 s: %ld pixels of water, mean |diff| %.2f, worst %d (RGB sum), %d "
           "clipped, speckle %.2f against the flat sheet's %.2f\n",
           inside, mean, worst, clipped, sa, sb);
    ck_assert_msg(far == 0,
                  "%d pixels of the water more than %d apart from flat water (the "
                  "worst %d): the backdrop shows through",
                  far, FAR_APART, worst);
    ck_assert_msg(mean <= MEAN_APART,
                  "the water is %.2f apart from flat water on average (at "
                  "most %.1f)",
                  mean, MEAN_APART);
    ck_assert_msg(clipped == 0, "%d clipped pixels in the water", clipped);
    ck_assert_msg(sa <= SPECKLE_FACTOR * sb,
                  "speckle: high-frequency energy %.2f, flat water "
                  "%.2f (at most %.1f x)",
                  sa, sb, SPECKLE_FACTOR);
    free(in);
    free(flat);
    ms_renderer_destroy(a);
    ms_renderer_destroy(b);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *look_still_suite(void)
{
    Suite *s = suite_create("look_still");
    TCase *tc = tcase_create("still");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, a_still_pool_after_30_s_looks_like_still_water);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(look_still_suite());
}
