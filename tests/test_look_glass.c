/* The look of the water in a glass (data/scenes/glass.json): the
 * liquid's surface reaches the glass's inner wall at the liquid's level and
 * stops there, the column of water is seen through the glass down to the
 * glass's floor, and no refraction lookup through a steep side shows the
 * beige-yellow deck. Each case steps the scene 60 frames (the glass has
 * moved 10 cm), draws the sim's fields and the same scene with a dry
 * field at the same time, and measures where the two pictures differ:
 * that is where liquid is drawn. MS_LOOK_DUMP=DIR writes the pictures. */
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

#define W 240 /* image side */
#define FRAMES 60
#define PI 3.14159265358979
/* data/scenes/glass.json: the glass (radius 7 cm, wall 1 cm, floor 1 cm)
 * on its path from (0.13, 0.2) along +x at 0.2 m/s from t = 0.5 s */
#define R_IN 0.06
#define R_OUT 0.07
#define GLASS_FLOOR 0.01

typedef struct glass_pictures {
    unsigned char *wet, *dry; /* W x W RGBA, top row first */
    float centre[2];          /* the glass's axis, world (m) */
    float level;              /* m, world: the liquid's mean height near the axis */
} glass_pictures;

static unsigned char *copy_pixels(const ms_renderer *r)
{
    unsigned char *p = malloc((size_t)W * W * 4);
    ck_assert_ptr_nonnull(p);
    memcpy(p, ms_renderer_pixels(r, NULL, NULL), (size_t)W * W * 4);
    return p;
}

/* The glass scene after FRAMES frames, drawn wet and dry with shader;
 * top_down: a camera 2 m straight over the glass (1 mm a pixel at the
 * water), else the scene's camera. Where the liquid is measured, it is
 * drawn as milk: clear water over the tiles' dark grout looks as the dry
 * grout does, and would count as no liquid. */
static glass_pictures draw_glass(int top_down, const char *shader, const char *name)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load("data/scenes/glass.json", &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    st = ms_sim_create_from_scene(sc, 1, &sim);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    const float dt = ms_scene_frame_dt(sc);
    for (int f = 0; f < FRAMES; ++f)
        ck_assert_int_eq(ms_sim_step(sim, dt), MS_OK);
    glass_pictures g;
    const double t = ms_sim_time(sim);
    g.centre[0] = (float)(0.13 + 0.2 * (t - 0.5));
    g.centre[1] = 0.2f;
    ck_assert(t > 0.9 && t < 1.2); /* still on the path's first leg */
    /* the level: the combined field's mean within 3 cm of the axis */
    int nx = 0, ny = 0;
    const float *h = ms_sim_height(sim, &nx, &ny);
    ms_grid grid;
    ck_assert_int_eq(ms_sim_field_grid(sim, MS_FIELD_COMBINED, &grid), MS_OK);
    double sum = 0;
    int n = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const double x = grid.origin[0] + (i + 0.5) * grid.dx - g.centre[0];
            const double y = grid.origin[1] + (j + 0.5) * grid.dy - g.centre[1];
            if (x * x + y * y < 0.03 * 0.03)
                sum += h[(size_t)j * nx + i], ++n;
        }
    ck_assert_int_gt(n, 100);
    g.level = (float)(sum / n);
    /* 648 cm^3 of water over the glass's 113 cm^2 floor at 1 cm: ~6.7 cm */
    ck_assert_msg(g.level > 0.055 && g.level < 0.08, "level %g m", (double)g.level);

    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    d.width = d.height = W;
    if (strcmp(d.shader, shader)) {
        d.shader = shader;
        d.shader_params = NULL; /* the scene's are its own shader's */
    }
    if (top_down) {
        const float eye[3] = {g.centre[0], g.centre[1], 2.0f};
        const float target[3] = {g.centre[0], g.centre[1], 0.0f}, north[3] = {0, 1, 0};
        memcpy(d.eye, eye, sizeof eye);
        memcpy(d.target, target, sizeof target);
        memcpy(d.up, north, sizeof north);
        d.fov = 6.0f;
    }
    ms_renderer *r = NULL;
    st = ms_renderer_create_desc(&d, &r);
    ck_assert_msg(st == MS_OK, "%s: %s", ms_status_name(st), ms_last_error());
    st = ms_renderer_draw(r, sim);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    char what[64];
    snprintf(what, sizeof what, "%s_wet", name);
    ms_test_dump_png(r, what);
    g.wet = copy_pixels(r);
    float *zero = calloc((size_t)nx * ny, sizeof *zero);
    ck_assert_ptr_nonnull(zero);
    st = ms_renderer_draw_scene_field(r, sc, zero, &grid, t);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    snprintf(what, sizeof what, "%s_dry", name);
    ms_test_dump_png(r, what);
    g.dry = copy_pixels(r);
    free(zero);
    ms_renderer_destroy(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    return g;
}

/* Liquid is drawn at pixel k: the wet and dry pictures differ there. */
static int liquid(const glass_pictures *g, size_t k)
{
    int s = 0;
    for (int c = 0; c < 3; ++c)
        s += abs((int)g->wet[4 * k + c] - (int)g->dry[4 * k + c]);
    return s > 12;
}

/* Seen from straight above: every pixel over the glass's cavity (its
 * ray meets the water's level inside R_IN - 2 mm) shows liquid, and none
 * from R_IN + 2 mm out to 2 cm past the glass does. Before the fill and
 * the cut (glass_fill.c): 0.9909 of the cavity (the surface sloped to the
 * floor short of the wall) and 0.0177 of the ring (the slope ran on over
 * the wall); after: 1.0000 and 0.0000. */
START_TEST(seen_from_above_the_water_fills_the_glass_to_its_wall_and_stops_there)
{
    REQUIRE_GL();
    glass_pictures g = draw_glass(1, "milk", "glass_top");
    const double t = tan(0.5 * 6.0 * PI / 180.0), D = 2.0 - g.level;
    long in = 0, in_wet = 0, ring = 0, ring_wet = 0;
    for (int row = 0; row < W; ++row)
        for (int col = 0; col < W; ++col) {
            /* where the pixel's ray meets the plane of the level, from the axis */
            const double x = (2.0 * (col + 0.5) / W - 1) * t * D;
            const double y = (1 - 2.0 * (row + 0.5) / W) * t * D;
            const double rho = sqrt(x * x + y * y);
            const int wet = liquid(&g, (size_t)row * W + col);
            if (rho < R_IN - 0.002)
                ++in, in_wet += wet;
            else if (rho > R_IN + 0.002 && rho < R_OUT + 0.02)
                ++ring, ring_wet += wet;
        }
    const double covered = (double)in_wet / (double)in, spilled = (double)ring_wet / (double)ring;
    ck_assert_msg(in > 8000 && ring > 8000, "%ld cavity pixels, %ld ring pixels", in, ring);
    ck_assert_msg(covered >= 0.998, "liquid over %.4f of the cavity (want >= 0.998)", covered);
    if (getenv("MS_LOOK_DUMP"))
        printf("top: covered %.4f spilled %.4f (%ld, %ld pixels)\n", covered, spilled, in, ring);
    ck_assert_msg(spilled <= 0.002, "liquid over %.4f of the wall and beyond (want <= 0.002)",
                  spilled);
    free(g.wet);
    free(g.dry);
}
END_TEST

/* Seen with the scene's camera: the column of water (inside R_IN - 3 mm,
 * from 3 mm over the glass's floor to 3 mm under the level, its top
 * included) shows liquid wherever it lands; no liquid pixel has the
 * saturated warm hue of the deck (the yellow spots: refraction lookups
 * through steep sides that left the pool). Before: 0.903 of the column
 * (a blob on the glass's floor), 24 yellow pixels; after: 0.998, none. */
START_TEST(seen_from_the_scene_camera_the_glass_is_filled_without_yellow_spots)
{
    REQUIRE_GL();
    glass_pictures g = draw_glass(0, "milk", "glass_scene_milk");
    glass_pictures water = draw_glass(0, "water", "glass_scene");
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_load("data/scenes/glass.json", &sc), MS_OK);
    ms_renderer_desc d = ms_renderer_desc_default();
    ck_assert_int_eq(ms_renderer_desc_from_scene(sc, &d), MS_OK);
    ms_scene_destroy(sc);
    d.width = d.height = W;
    unsigned char *column = calloc((size_t)W * W, 1);
    ck_assert_ptr_nonnull(column);
    const double r = R_IN - 0.003, z0 = GLASS_FLOOR + 0.003, z1 = g.level - 0.003;
    for (int a = 0; a < 720; ++a)
        for (int s = 0; s <= 60; ++s) {
            const double ang = 2 * PI * a / 720.0, c = cos(ang), sn = sin(ang);
            /* the side from z0 to z1, and the top disc */
            const float side[3] = {(float)(g.centre[0] + r * c), (float)(g.centre[1] + r * sn),
                                   (float)(z0 + (z1 - z0) * s / 60.0)};
            const float top[3] = {(float)(g.centre[0] + r * c * s / 60.0),
                                  (float)(g.centre[1] + r * sn * s / 60.0), (float)z1};
            const float *pts[2] = {side, top};
            for (int k = 0; k < 2; ++k) {
                double col, row;
                if (ms_test_project(&d, pts[k], W, W, &col, &row) && col >= 0 && col < W &&
                    row >= 0 && row < W)
                    column[(size_t)row * W + (size_t)col] = 1;
            }
        }
    long in = 0, in_wet = 0, yellow = 0, wet = 0;
    for (size_t k = 0; k < (size_t)W * W; ++k) {
        const int l = liquid(&g, k);
        if (column[k])
            ++in, in_wet += l;
        if (!l)
            continue;
        ++wet;
        const int R = water.wet[4 * k], G = water.wet[4 * k + 1], B = water.wet[4 * k + 2];
        const int hi = R > G ? R : G, lo = B < (R < G ? R : G) ? B : (R < G ? R : G);
        /* warm (blue lowest) and saturated, not dark */
        if (B < R && B < G && hi > 100 && (hi - lo) > hi / 4)
            ++yellow;
    }
    ck_assert_msg(in > 2000, "%ld column pixels", in);
    const double covered = (double)in_wet / (double)in;
    ck_assert_msg(covered >= 0.98, "liquid over %.4f of the column (want >= 0.98)", covered);
    if (getenv("MS_LOOK_DUMP"))
        printf("scene: covered %.4f of %ld, yellow %ld of %ld\n", covered, in, yellow, wet);
    ck_assert_msg(yellow == 0, "%ld of %ld liquid pixels are saturated yellow", yellow, wet);
    free(column);
    free(g.wet);
    free(g.dry);
    free(water.wet);
    free(water.dry);
}
END_TEST

static Suite *look_suite(void)
{
    Suite *s = suite_create("look_glass");
    TCase *tc = tcase_create("look_glass");
    tcase_set_timeout(tc, 90);
    tcase_add_test(tc, seen_from_above_the_water_fills_the_glass_to_its_wall_and_stops_there);
    tcase_add_test(tc, seen_from_the_scene_camera_the_glass_is_filled_without_yellow_spots);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(look_suite());
}
