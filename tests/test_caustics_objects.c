/* Caustics on the objects under the water (section 3.6 lights only the
 * floor): the tracer carries the light through the water at
 * heights between the floor and the surface too (ms_caustics.layers), and
 * the light at a height is the light a floor at that height would get; an
 * obstacle shades the floor where the refracted sun meets it first; drawn,
 * a submerged box's top takes the light a lens in the surface focuses onto
 * it, and the floor beside it lies in its shadow. MS_LOOK_DUMP=DIR writes
 * the pictures as PNGs to look at. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "render/render_internal.h"
#include "support.h"
#include "support_render.h"

#define N 128   /* field cells per side */
#define RES 128 /* light map texels per side */

static ms_caustics_desc desc(float lx, float depth, int layers)
{
    ms_caustics_desc d = {.pool = {0, 0, 1, 1},
                          .floor_z = 0,
                          .ior = 1.333f,
                          .intensity = 1,
                          .resolution = RES,
                          .depth = depth,
                          .layers = layers};
    const double l = sqrt((double)lx * lx + 1);
    d.light_dir[0] = (float)(lx / l);
    d.light_dir[2] = (float)(-1 / l);
    return d;
}

/* A lens: a paraboloidal cap of curvature radius R and radius rho (m) at
 * (x, y) on h (n x n over the unit pool). */
static void add_cap(float *h, int n, float x, float y, float R, float rho)
{
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float dx = ((float)i + 0.5f) / (float)n - x, dy = ((float)j + 0.5f) / (float)n - y;
            float r2 = dx * dx + dy * dy;
            if (r2 < rho * rho)
                h[j * n + i] += (rho * rho - r2) / (2 * R);
        }
}

/* The light map's texel over world point (x, y) of the unit pool. */
static float at(const float *m, double x, double y)
{
    return m[(size_t)(y * RES) * RES + (size_t)(x * RES)];
}

START_TEST(the_light_at_a_height_in_the_water_is_a_floor_at_that_height)
{
    /* rippled water 0.6 m deep, three layers at 0.15, 0.3 and 0.45 m; the
     * same surface over a floor raised to each layer's height gives that
     * layer's light as its floor map (the rays are straight under the
     * surface, so where they cross a plane does not depend on what lies
     * below it) */
    const float D = 0.6f;
    float *h = field(N, D);
    add_cap(h, N, 0.35f, 0.5f, 0.2f, 0.05f);
    add_bump(h, N, 0.6f, 0.3f, 0.004f, 0.03f);
    add_bump(h, N, 0.7f, 0.7f, -0.003f, 0.05f);
    ms_grid g = grid(N);
    ms_caustics c = {0};
    ms_caustics_desc d = desc(0.5f, D, 3);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_int_eq(c.nlayers, 3);
    const int ln = c.layer_n, slice = ln * ln; /* half the floor's resolution */
    ck_assert_int_eq(ln, RES / 2);
    float *raised = field(N, 0);
    for (int l = 0; l < 3; ++l) {
        const float z = D * (float)(l + 1) / 4;
        for (int i = 0; i < N * N; ++i)
            raised[i] = h[i] - z;
        ms_caustics floor = {0};
        ms_caustics_desc e = desc(0.5f, D - z, 0);
        e.resolution = ln;
        ck_assert_int_eq(ms_caustics_trace(&floor, &e, raised, &g), MS_OK);
        double worst = 0, peak = 0;
        for (int i = 0; i < slice; ++i) {
            worst = fmax(worst, fabs(c.layers[(size_t)(l + 1) * slice + i] - floor.map[i]));
            peak = fmax(peak, floor.map[i]);
        }
        ck_assert_msg(peak > 1.5, "layer %d: the lens focuses nothing (peak %g)", l, peak);
        ck_assert_msg(worst < 1e-3, "layer %d at %.2f m: %g from the floor's light there", l,
                      (double)z, worst);
        ms_caustics_free(&floor);
    }
    /* and the lens's light grows towards its focus (f = n R / (n - 1) =
     * 0.8 m along the ray): the peak rises layer by layer to the floor */
    double prev = 1;
    for (int l = 3; l >= 0; --l) { /* slice 0: the floor's, resampled */
        const float *m = c.layers + (size_t)l * slice;
        double peak = 0;
        for (int i = 0; i < slice; ++i)
            peak = fmax(peak, m[i]);
        ck_assert_msg(peak > prev, "the light at slice %d peaks at %g, above it %g", l, peak, prev);
        prev = peak;
    }
    ms_caustics_free(&c);
    free(raised);
    free(h);
}
END_TEST

/* The 12 triangles of the box lo..hi, 3 floats a vertex. */
static int box_triangles(const float lo[3], const float hi[3], float *out)
{
    static const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    int n = 0;
    for (int f = 0; f < 6; ++f) {
        static const int tri[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; ++k, ++n) {
            const int c = faces[f][tri[k]];
            out[3 * n] = c & 1 ? hi[0] : lo[0];
            out[3 * n + 1] = c & 2 ? hi[1] : lo[1];
            out[3 * n + 2] = c & 4 ? hi[2] : lo[2];
        }
    }
    return n;
}

START_TEST(an_obstacle_shades_the_floor_where_the_refracted_sun_meets_it_first)
{
    /* a box 20 cm square and 10 cm tall on the floor of flat water 25 cm
     * deep, the sun at 45 degrees along +x: refracted (Snell) it runs
     * tan t = 0.625 m across per m down, so the box's shadow reaches
     * 6.25 cm past its far side, and the light lost is that area */
    const float lo[3] = {0.4f, 0.4f, 0}, hi[3] = {0.6f, 0.6f, 0.1f};
    float tris[36 * 3];
    const int nv = box_triangles(lo, hi, tris);
    float *h = field(N, 0.25f);
    ms_grid g = grid(N);
    ms_caustics c = {0};
    ms_caustics_desc d = desc(1, 0.25f, 0);
    d.occluders = tris, d.occluder_verts = nv, d.occluder_stride = 3;
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_int_eq(c.shaded, 1);
    const double eta = 1 / 1.333, s = eta * sqrt(0.5), tan_t = s / sqrt(1 - s * s);
    ck_assert_float_eq_tol(tan_t, 0.625, 1e-3);
    ck_assert_msg(at(c.map, 0.5, 0.5) < 0.02, "under the box: %g", (double)at(c.map, 0.5, 0.5));
    ck_assert_msg(at(c.map, 0.64, 0.5) < 0.02, "in its shadow past it: %g",
                  (double)at(c.map, 0.64, 0.5));
    ck_assert_msg(fabs(at(c.map, 0.7, 0.5) - 1) < 0.02, "past the shadow: %g",
                  (double)at(c.map, 0.7, 0.5));
    ck_assert_msg(fabs(at(c.map, 0.35, 0.5) - 1) < 0.02, "before the box: %g",
                  (double)at(c.map, 0.35, 0.5));
    ck_assert_msg(fabs(at(c.map, 0.64, 0.3) - 1) < 0.02, "beside the shadow: %g",
                  (double)at(c.map, 0.64, 0.3));
    /* open: the light before the shadow, 1 there */
    ck_assert_msg(fabs(at(c.open, 0.5, 0.5) - 1) < 1e-4, "open light under the box: %g",
                  (double)at(c.open, 0.5, 0.5));
    double lost = 0;
    for (int i = 0; i < RES * RES; ++i)
        lost += c.open[i] - c.map[i];
    lost /= (double)RES * RES; /* m^2 of the unit pool */
    const double shadow = 0.2 * (0.2 + 0.1 * tan_t);
    ck_assert_msg(fabs(lost - shadow) < 0.06 * shadow, "light lost %g m^2, the shadow is %g m^2",
                  lost, shadow);
    ms_caustics_free(&c);
    free(h);
}
END_TEST

/* ---- drawn -------------------------------------------------------------- */

#define REQUIRE_GL()                                                   \
    do {                                                               \
        if (!MS_HAVE_GL)                                               \
            MS_SKIP("built without OSMesa and EGL: nothing can draw"); \
    } while (0)

#define W 160 /* image side */

/* A box 50 cm square whose top lies 30 cm under the still water (0.6 m
 * deep), seen from straight above, the sun at 45 degrees along +x. */
static const char box_scene[] =
    "{\"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 1]},"
    " \"surface\": {\"cells\": [128, 128], \"level\": 0.6},"
    " \"obstacles\": [{\"shape\": \"box\", \"params\": {\"size\": [0.5, 0.5, 0.3]},"
    "   \"position\": [0.5, 0.5, 0.15]}]}";

/* Linear light of the sRGB pixel (x, y)'s green, averaged over a 5 x 5
 * window. */
static double linear(const unsigned char *px, double x, double y)
{
    double sum = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            const int c = (int)lround(x) + dx, r = (int)lround(y) + dy;
            const double v = px[((size_t)r * W + (size_t)c) * 4 + 1] / 255.0;
            sum += v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
        }
    return sum / 25;
}

/* The picture of field h with the box, a copy. */
static unsigned char *picture(const ms_scene *sc, const float *h, const char *name)
{
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    d.width = d.height = W;
    d.caustics = 1;
    d.caustics_resolution = RES;
    d.light_dir[0] = 1, d.light_dir[1] = 0, d.light_dir[2] = -1;
    const float eye[3] = {0.5f, 0.5f, 2.0f}, target[3] = {0.5f, 0.5f, 0}, north[3] = {0, 1, 0};
    memcpy(d.eye, eye, sizeof eye);
    memcpy(d.target, target, sizeof target);
    memcpy(d.up, north, sizeof north);
    d.fov = 30;
    ms_renderer *r = NULL;
    ms_status st = ms_renderer_create_desc(&d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    ms_grid g = grid(N);
    st = ms_renderer_draw_scene_field(r, sc, h, &g, 0.0);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    const char *dir = getenv("MS_LOOK_DUMP");
    if (dir) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.png", dir, name);
        ck_assert_int_eq(ms_renderer_write_png(r, path), MS_OK);
    }
    unsigned char *copy = malloc((size_t)W * W * 4);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    ms_renderer_destroy(r);
    return copy;
}

/* Pixel column and row where the point (x, y) at height z under the
 * still water (0.6 m) is seen from the eye 1.4 m above it, through flat
 * water: the surface point P whose refracted ray (Snell) reaches it,
 * found by fixed-point iteration along the line from the view's centre. */
static void pixel(double x, double y, double z, double *col, double *row)
{
    const double H = 1.4, n = 1.333, dx = x - 0.5, dy = y - 0.5, far = sqrt(dx * dx + dy * dy);
    double p = far; /* P's distance from the centre */
    for (int k = 0; k < 50 && far > 0; ++k) {
        const double sin_i = p / sqrt(p * p + H * H), sin_t = sin_i / n;
        p = far - (0.6 - z) * sin_t / sqrt(1 - sin_t * sin_t);
    }
    const double scale = far > 0 ? p / far : 1;
    const double half = H * tan(15.0 * 3.14159265358979 / 180.0); /* m, at the surface */
    *col = 0.5 * W * (1 + dx * scale / half);
    *row = 0.5 * W * (1 - dy * scale / half);
}

START_TEST(a_submerged_box_takes_the_caustics_where_the_refracted_sun_meets_it)
{
    REQUIRE_GL();
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(box_scene, strlen(box_scene), &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    /* a lens (f = n R / (n - 1) = 0.8 m) at S = (0.32, 0.5): its light runs
     * 0.3 m down to the box's top at A = S + 0.3 tan t = (0.5075, 0.5) and
     * would reach the floor 0.19 m further on, under the box */
    float *flat = field(N, 0.6f), *lens = field(N, 0.6f);
    add_cap(lens, N, 0.32f, 0.5f, 0.2f, 0.05f);
    unsigned char *a = picture(sc, flat, "box_flat"), *b = picture(sc, lens, "box_lens");
    double col, row;
    pixel(0.5075, 0.5, 0.3, &col, &row);
    const double top_flat = linear(a, col, row), top_lens = linear(b, col, row);
    /* paraxially the lens gathers its light 1 / (1 - 0.354 / 0.8)^2 = 3.2
     * times over at A; the box's top takes 0.22 + 0.48 cos t focus of the
     * sky-lit stone: ~2.4 times the light, tone-mapped */
    ck_assert_msg(top_lens > 1.5 * top_flat,
                  "the box's top under the lens's light: %.4f, "
                  "under flat water %.4f",
                  top_lens, top_flat);
    /* the top away from the lens's light is as under flat water */
    pixel(0.65, 0.65, 0.3, &col, &row);
    ck_assert_msg(fabs(linear(b, col, row) - linear(a, col, row)) < 0.02 * linear(a, col, row),
                  "the box's top away from the lens: %.4f, flat %.4f", linear(b, col, row),
                  linear(a, col, row));
    /* the floor past the box's far side (x = 0.75 .. 0.94) in its shadow,
     * the floor as far along beside it in the sun */
    double sc_col, sc_row, lit_col, lit_row;
    pixel(0.85, 0.5, 0, &sc_col, &sc_row);
    pixel(0.85, 0.15, 0, &lit_col, &lit_row);
    const double shade = linear(a, sc_col, sc_row), sun = linear(a, lit_col, lit_row);
    ck_assert_msg(shade < 0.7 * sun, "the floor in the box's shadow %.4f, in the sun %.4f", shade,
                  sun);
    free(a);
    free(b);
    free(flat);
    free(lens);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *objects_suite(void)
{
    Suite *s = suite_create("caustics_objects");
    TCase *tc = tcase_create("caustics_objects");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, the_light_at_a_height_in_the_water_is_a_floor_at_that_height);
    tcase_add_test(tc, an_obstacle_shades_the_floor_where_the_refracted_sun_meets_it_first);
    tcase_add_test(tc, a_submerged_box_takes_the_caustics_where_the_refracted_sun_meets_it);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(objects_suite());
}
