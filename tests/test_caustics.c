/* The caustics light map (paper section 3.6), traced on the CPU by Snell's
 * law: flat water lights the floor evenly, a lens-shaped bump focuses
 * light and conserves it, a dip spreads it and the intensity scales the
 * contrast. No GL needed (split from test_render.c). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "render/render_internal.h"
#include "support.h"
#include "support_render.h"

#define N 64 /* field cells per side */

/* ---- the caustics light map (CPU: no GL needed) ------------------------- */

static ms_caustics_desc caustics_desc(int n, float lx, float ly)
{
    ms_caustics_desc d = {
        .pool = {0, 0, 1, 1}, .floor_z = 0, .ior = 1.333f, .intensity = 1, .resolution = n};
    double l = sqrt((double)lx * lx + (double)ly * ly + 1);
    d.light_dir[0] = (float)(lx / l);
    d.light_dir[1] = (float)(ly / l);
    d.light_dir[2] = (float)(-1 / l);
    return d;
}

static double map_mean(const float *m, int n)
{
    double s = 0;
    for (int i = 0; i < n * n; ++i)
        s += m[i];
    return s / ((double)n * n);
}

START_TEST(flat_water_lights_the_floor_evenly)
{
    /* vertical light: exactly 1 everywhere; oblique light: 1 away from the
     * walls (the strip in the walls' shadow gets none; light is lost into
     * the far walls) */
    const int n = 96;
    float *h = field(N, 0.25f);
    ms_grid g = grid(N);
    ms_caustics c = {0};
    ms_caustics_desc d = caustics_desc(n, 0, 0);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    for (int i = 0; i < n * n; ++i)
        ck_assert_msg(fabsf(c.map[i] - 1) < 1e-4f, "texel %d: %g", i, (double)c.map[i]);
    d = caustics_desc(n, 0.3f, 0.2f);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    /* refracted: tan t = sin(i)/n / cos t; shift = depth * tan t, per axis */
    double sin_i = sqrt(0.13 / 1.13), sin_t = sin_i / 1.333,
           tan_t = sin_t / sqrt(1 - sin_t * sin_t);
    double shift = 0.25 * tan_t; /* m, along (0.3, 0.2) / |.| */
    int lost_x = (int)ceil(shift * 0.3 / sqrt(0.13) * n) + 2,
        lost_y = (int)ceil(shift * 0.2 / sqrt(0.13) * n) + 2;
    for (int j = lost_y; j < n - 2; ++j)
        for (int i = lost_x; i < n - 2; ++i)
            ck_assert_msg(fabsf(c.map[j * n + i] - 1) < 1e-4f, "texel (%d, %d): %g", i, j,
                          (double)c.map[j * n + i]);
    ck_assert_float_lt(c.map[0], 0.05f); /* the corner towards the light is in shadow */
    ms_caustics_free(&c);
    free(h);
}
END_TEST

/* A lens: a paraboloidal cap of radius rho (m) and curvature radius R (m)
 * at (x, y), h += (rho^2 - r^2) / (2 R) for r < rho. */
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

/* Peak and mean of the light map, and the light at the centre, under a
 * lens of curvature radius R over water `depth` deep (below its rim). */
static void lens(float depth, float R, float rho, double *peak, double *mean, double *centre)
{
    const int n = 128, fn = 128;
    float *h = field(fn, depth);
    add_cap(h, fn, 0.5f, 0.5f, R, rho);
    ms_grid g = grid(fn);
    ms_caustics c = {0};
    ms_caustics_desc d = caustics_desc(n, 0, 0);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    *peak = 0;
    for (int i = 0; i < n * n; ++i)
        *peak = MS_MAX(*peak, c.map[i]);
    *mean = map_mean(c.map, n);
    *centre =
        0.25 * (c.map[63 * n + 63] + c.map[63 * n + 64] + c.map[64 * n + 63] + c.map[64 * n + 64]);
    ms_caustics_free(&c);
    free(h);
}

START_TEST(a_lens_shaped_bump_focuses_light_and_conserves_it)
{
    /* A convex cap is a lens: curvature radius R focuses parallel light at
     * f = n R / (n - 1) below it (refraction at one surface, paraxial).
     * R = 0.16 m: f = 0.64 m. The light of the cap's area pi rho^2 reaches
     * the floor through a disc (1 - z / f) times as wide at depth z: at
     * f / 4 the centre gets 1 / (3/4)^2 = 1.78 times the light; at the
     * focus it is gathered into a spot; at 3 f the rays have crossed and
     * spread over twice the cap's width (a quarter of the light each, but
     * the rays from the cap's rim, where the grid smooths the kink, land
     * in between, so only "far dimmer than the focus" is asserted). */
    const float R = 0.16f, rho = 0.06f, n = 1.333f;
    const float f = n * R / (n - 1);
    double peak_f, mean_f, c_f, peak_near, mean_near, c_near, peak_far, mean_far, c_far;
    lens(f, R, rho, &peak_f, &mean_f, &c_f);
    lens(f / 4, R, rho, &peak_near, &mean_near, &c_near);
    lens(3 * f, R, rho, &peak_far, &mean_far, &c_far);
    ck_assert_msg(c_f > 10.0, "centre at the focus %g", c_f);
    ck_assert_msg(fabs(c_near - 1.78) < 0.15, "centre at f/4 %g, expected 1.78", c_near);
    ck_assert_msg(c_far < 0.1 * c_f, "centre at 3f %g, at f %g", c_far, c_f);
    ck_assert_msg(peak_f > peak_near && peak_f > peak_far, "peaks %g %g %g", peak_near, peak_f,
                  peak_far);
    /* the light is only moved: the mean stays 1 up to the slopes' extra
     * Fresnel reflection (under 1 % for these slopes) */
    ck_assert_msg(fabs(mean_f - 1) < 0.01, "mean at f %g", mean_f);
    ck_assert_msg(fabs(mean_near - 1) < 0.01, "mean at f/4 %g", mean_near);
    ck_assert_msg(fabs(mean_far - 1) < 0.01, "mean at 3f %g", mean_far);
    ck_assert_double_le(mean_f, 1.0 + 1e-6);
}
END_TEST

START_TEST(a_dip_spreads_light_and_intensity_scales_contrast)
{
    const int n = 128;
    float *h = field(n, 0.3f);
    add_bump(h, n, 0.5f, 0.5f, -0.01f, 0.04f);
    ms_grid g = grid(n);
    ms_caustics c = {0};
    ms_caustics_desc d = caustics_desc(n, 0, 0);
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    double centre = c.map[64 * n + 64], far = c.map[10 * n + 10];
    ck_assert_msg(centre < 0.8, "centre under a dip %g", centre);
    ck_assert_double_eq_tol(far, 1.0, 1e-4);
    /* intensity k: 1 + k (E - 1) */
    d.intensity = 0.5f;
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_double_eq_tol(c.map[64 * n + 64], 1 + 0.5 * (centre - 1), 1e-4);
    d.intensity = 0;
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_double_eq_tol(c.map[64 * n + 64], 1.0, 1e-6);
    /* the sun under the horizon: no light on the floor */
    d.intensity = 1;
    d.light_dir[0] = 0, d.light_dir[1] = 0, d.light_dir[2] = 1;
    ck_assert_int_eq(ms_caustics_trace(&c, &d, h, &g), MS_OK);
    ck_assert_double_eq_tol(map_mean(c.map, n), 0.0, 1e-9);
    ms_caustics_free(&c);
    free(h);
}
END_TEST

static Suite *caustics_suite(void)
{
    Suite *s = suite_create("caustics");
    TCase *tc = tcase_create("caustics");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, flat_water_lights_the_floor_evenly);
    tcase_add_test(tc, a_lens_shaped_bump_focuses_light_and_conserves_it);
    tcase_add_test(tc, a_dip_spreads_light_and_intensity_scales_contrast);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(caustics_suite());
}
