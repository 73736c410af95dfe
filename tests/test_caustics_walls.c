/* Caustics on the pool's walls (section 3.6 traces the floor only):
 * light that the refracted sun carries past the floor's edge lands on the
 * walls facing the sun, at the irradiance Snell's law gives a vertical
 * wall, none on the walls in shadow; floor and walls together keep all the
 * light the surface lets in (before, the walls' share was lost); a lens
 * by a wall focuses light on it. No GL needed. */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "render/render_internal.h"
#include "support.h"
#include "support_render.h"

#define N 128   /* field cells per side */
#define RES 128 /* light map texels per side */
#define DEPTH 0.25f

static ms_caustics_desc walls_desc(float lx, float ly)
{
    ms_caustics_desc d = {.pool = {0, 0, 1, 1},
                          .floor_z = 0,
                          .ior = 1.333f,
                          .intensity = 1,
                          .resolution = RES,
                          .depth = DEPTH};
    const double l = sqrt((double)lx * lx + (double)ly * ly + 1);
    d.light_dir[0] = (float)(lx / l);
    d.light_dir[1] = (float)(ly / l);
    d.light_dir[2] = (float)(-1 / l);
    return d;
}

/* The refracted sun of flat water (Snell's law, vector form). */
static void refracted(const ms_caustics_desc *d, double t[3])
{
    const double eta = 1.0 / d->ior, cosi = -d->light_dir[2];
    const double k = 1 - eta * eta * (1 - cosi * cosi);
    for (int a = 0; a < 3; ++a)
        t[a] = eta * d->light_dir[a] + (a == 2 ? eta * cosi - sqrt(k) : 0);
}

/* Mean of strip s's texels in columns [u0, u1) and rows [v0, v1). */
static double strip_mean(const ms_caustics *c, int s, int u0, int u1, int v0, int v1)
{
    double sum = 0;
    for (int v = v0; v < v1; ++v)
        for (int u = u0; u < u1; ++u)
            sum += c->walls[((size_t)s * c->wall_rows + (size_t)v) * c->n + (size_t)u];
    return sum / ((double)(u1 - u0) * (v1 - v0));
}

/* The light the floor and the walls hold, in floor texels of flat water. */
static double total_light(const ms_caustics *c, const ms_caustics_desc *d)
{
    double floor = 0, walls = 0;
    for (int i = 0; i < c->n * c->n; ++i)
        floor += c->map[i];
    const double floor_texel = (d->pool[2] / c->n) * (d->pool[3] / c->n);
    const double wall_texel[4] = {
        d->pool[3] / c->n * d->depth / c->wall_rows, d->pool[3] / c->n * d->depth / c->wall_rows,
        d->pool[2] / c->n * d->depth / c->wall_rows, d->pool[2] / c->n * d->depth / c->wall_rows};
    for (int s = 0; s < 4; ++s)
        walls += strip_mean(c, s, 0, c->n, 0, c->wall_rows) * c->n * c->wall_rows * wall_texel[s] /
                 floor_texel;
    return floor + walls;
}

START_TEST(flat_water_lights_the_walls_facing_the_sun)
{
    float *h = field(N, DEPTH);
    ms_grid g = grid(N);
    ms_caustics c = {0};
    ms_caustics_desc d = walls_desc(0.3f, 0.2f);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_int_ge(c.wall_rows, 4);
    double t[3];
    refracted(&d, t);
    /* irradiance on a wall over the floor's: |t_x| / |t_z| (the +x wall),
     * |t_y| / |t_z| (the +y wall); away from the corners and the strips'
     * top and bottom rows (the blur's edges) */
    const int u0 = RES / 4, u1 = 3 * RES / 4, v0 = 1, v1 = c.wall_rows - 1;
    const double px = strip_mean(&c, 1, u0, u1, v0, v1), py = strip_mean(&c, 3, u0, u1, v0, v1);
    const double want_x = fabs(t[0] / t[2]), want_y = fabs(t[1] / t[2]);
    ck_assert_msg(fabs(px / want_x - 1) < 0.03, "the +x wall gets %.4f, Snell says %.4f", px,
                  want_x);
    ck_assert_msg(fabs(py / want_y - 1) < 0.03, "the +y wall gets %.4f, Snell says %.4f", py,
                  want_y);
    /* the walls the sun's light travels away from get none */
    ck_assert_msg(strip_mean(&c, 0, 0, RES, 0, c.wall_rows) < 1e-6 &&
                      strip_mean(&c, 2, 0, RES, 0, c.wall_rows) < 1e-6,
                  "a wall in shadow is lit");
    /* all the light that enters lands on the floor or a wall */
    const double total = total_light(&c, &d);
    ck_assert_msg(fabs(total / (RES * RES) - 1) < 0.01,
                  "floor and walls hold %.4f of the light that enters", total / (RES * RES));
    /* no walls traced without a depth */
    d.depth = 0;
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_int_eq(c.wall_rows, 0);
    ms_caustics_free(&c);
    free(h);
}
END_TEST

START_TEST(a_lens_by_a_wall_focuses_light_on_it_and_light_is_kept)
{
    float *h = field(N, DEPTH);
    ms_grid g = grid(N);
    ms_caustics c = {0};
    ms_caustics_desc d = walls_desc(0.5f, 0.0f);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    const double flat = strip_mean(&c, 1, RES / 2 - 2, RES / 2 + 2, 1, c.wall_rows - 1);
    /* a converging bump 6 cm from the +x wall, on the wall's centre line */
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            const float x = ((float)i + 0.5f) / N - 0.94f, y = ((float)j + 0.5f) / N - 0.5f;
            const float r2 = x * x + y * y, rho = 0.05f;
            if (r2 < rho * rho)
                h[j * N + i] += (rho * rho - r2) / (2 * 0.15f);
        }
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    float peak = 0;
    for (int v = 0; v < c.wall_rows; ++v)
        for (int u = 0; u < RES; ++u)
            peak = fmaxf(peak, c.walls[((size_t)1 * c.wall_rows + (size_t)v) * RES + (size_t)u]);
    ck_assert_msg(peak > 2 * flat, "the lens brightens the wall to %.3f only (flat %.3f)",
                  (double)peak, flat);
    /* the slopes reflect a little more: within 2 % of all the light */
    const double total = total_light(&c, &d);
    ck_assert_msg(fabs(total / (RES * RES) - 1) < 0.02, "floor and walls hold %.4f of the light",
                  total / (RES * RES));
    ms_caustics_free(&c);
    free(h);
}
END_TEST

static Suite *walls_suite(void)
{
    Suite *s = suite_create("caustics_walls");
    TCase *tc = tcase_create("caustics_walls");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, flat_water_lights_the_walls_facing_the_sun);
    tcase_add_test(tc, a_lens_by_a_wall_focuses_light_on_it_and_light_is_kept);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(walls_suite());
}
