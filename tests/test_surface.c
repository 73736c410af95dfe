/* The surface solver (paper 3.2, eq. 2): convergence to the analytic
 * standing mode, conservation, stability at the CFL limit, obstacles,
 * absorbing and periodic edges, speed and damping maps, drops, rain,
 * disturbers, and every refusal. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "surface/surface_internal.h"

static const double PI = 3.14159265358979323846;

static ms_surface *make(int nx, int ny, float dx, float c, float damping, ms_boundary b)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = nx;
    d.ny = ny;
    d.dx = dx;
    d.wave_speed = c;
    d.damping = damping;
    d.boundary = b;
    ms_surface *s = NULL;
    ms_status st = ms_surface_create(&d, &s);
    ck_assert_msg(st == MS_OK, "create: %s", ms_last_error());
    return s;
}

static double mean_height(const ms_surface *s)
{
    int nx, ny;
    const float *h = ms_surface_height(s, &nx, &ny);
    double sum = 0;
    for (int i = 0; i < nx * ny; ++i)
        sum += h[i];
    return sum / (nx * ny);
}

static double max_abs(const ms_surface *s)
{
    int nx, ny;
    const float *h = ms_surface_height(s, &nx, &ny);
    double m = 0;
    for (int i = 0; i < nx * ny; ++i) {
        ck_assert_msg(isfinite(h[i]), "height[%d] is %g", i, (double)h[i]);
        m = fmax(m, fabs(h[i]));
    }
    return m;
}

static double energy_in(const ms_surface *s, int x0, int x1, int y0, int y1)
{
    return ms_surface_energy_region(s, x0, x1, y0, y1);
}

/* ---- refusals ---------------------------------------------------------- */

START_TEST(create_refuses_bad_descs)
{
    ms_surface *s = (ms_surface *)0x1;
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = 1;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "nx 1");
    ck_assert_ptr_null(s);
    d = ms_surface_desc_default();
    d.ny = 20000;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "16384");
    d = ms_surface_desc_default();
    d.dx = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "dx 0");
    d.dx = NAN;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "dx nan");
    d = ms_surface_desc_default();
    d.wave_speed = -1;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "wave_speed -1");
    d.wave_speed = INFINITY;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "wave_speed inf");
    d = ms_surface_desc_default();
    d.damping = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "(0, 1]");
    d.damping = 1.5f;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "damping 1.5");
    d = ms_surface_desc_default();
    d.boundary = (ms_boundary)7;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "boundary 7");
    d = ms_surface_desc_default();
    d.max_substeps = 0;
    MS_ASSERT_REFUSED(ms_surface_create(&d, &s), MS_ERR_INVALID_ARGUMENT, "max_substeps 0");
    MS_ASSERT_REFUSED(ms_surface_create(NULL, &s), MS_ERR_INVALID_ARGUMENT, "desc");
    MS_ASSERT_REFUSED(ms_surface_create(&d, NULL), MS_ERR_INVALID_ARGUMENT, "out");
}
END_TEST

START_TEST(step_refuses_bad_dt_and_unreachable_stability)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = 32;
    d.dx = 0.01f;
    d.wave_speed = 40.0f;
    d.max_substeps = 1000;
    ms_surface *s;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    MS_ASSERT_REFUSED(ms_surface_step(s, NAN), MS_ERR_INVALID_ARGUMENT, "dt nan");
    MS_ASSERT_REFUSED(ms_surface_step(s, -1), MS_ERR_INVALID_ARGUMENT, "[0, 10]");
    MS_ASSERT_REFUSED(ms_surface_step(s, 100), MS_ERR_INVALID_ARGUMENT, "dt 100");
    /* 40 m/s on 1 cm cells needs dt <= 0.7 * 0.01 / 40 = 1.75e-4 s: one
     * second would take 5715 sub-steps, over the limit of 1000 */
    MS_ASSERT_REFUSED(ms_surface_step(s, 1.0f), MS_ERR_UNSTABLE, "needs dt <= 0.000175 s");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "max_substeps 1000"));
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "wave_speed 40 m/s"));
    /* the handle is still usable, and nothing moved */
    ck_assert_int_eq(ms_surface_step(s, 0.1f), MS_OK);
    ck_assert_double_eq(max_abs(s), 0.0);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(inputs_are_refused_with_the_value)
{
    ms_surface *s = make(16, 8, 0.1f, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    float *f = calloc(16 * 8, sizeof *f);
    MS_ASSERT_REFUSED(ms_surface_add_drop(s, NAN, 0, 0.1f, 1), MS_ERR_INVALID_ARGUMENT, "x");
    MS_ASSERT_REFUSED(ms_surface_add_drop(s, 0.5f, 0.5f, 0, 1), MS_ERR_INVALID_ARGUMENT,
                      "radius 0");
    MS_ASSERT_REFUSED(ms_surface_add_drop(s, 0.5f, 0.5f, 50, 1), MS_ERR_INVALID_ARGUMENT,
                      "grid's extent");
    MS_ASSERT_REFUSED(ms_surface_add_drop(s, 0.5f, 0.5f, 0.1f, INFINITY), MS_ERR_INVALID_ARGUMENT,
                      "amplitude");
    f[37] = NAN;
    MS_ASSERT_REFUSED(ms_surface_set_height(s, f), MS_ERR_INVALID_ARGUMENT, "h[37]");
    MS_ASSERT_REFUSED(ms_surface_excite(s, f, 1), MS_ERR_INVALID_ARGUMENT, "dh[37]");
    MS_ASSERT_REFUSED(ms_surface_set_height(s, NULL), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_surface_set_speed_map(s, f), MS_ERR_INVALID_ARGUMENT, "speed map[37]");
    f[37] = -2;
    MS_ASSERT_REFUSED(ms_surface_set_speed_map(s, f), MS_ERR_INVALID_ARGUMENT, ">= 0");
    for (int i = 0; i < 16 * 8; ++i)
        f[i] = 0.5f;
    f[5] = 0;
    MS_ASSERT_REFUSED(ms_surface_set_damping_map(s, f), MS_ERR_INVALID_ARGUMENT, "damping map[5]");
    f[5] = 1.01f;
    MS_ASSERT_REFUSED(ms_surface_set_damping_map(s, f), MS_ERR_INVALID_ARGUMENT, "(0, 1]");
    ms_rain rain = {.size = sizeof(ms_rain), .rate = -1, .radius = 0.1f, .amplitude = 0.01f};
    MS_ASSERT_REFUSED(ms_surface_set_rain(s, &rain), MS_ERR_INVALID_ARGUMENT, "rain rate -1");
    rain.rate = 10;
    rain.radius = 0;
    MS_ASSERT_REFUSED(ms_surface_set_rain(s, &rain), MS_ERR_INVALID_ARGUMENT, "rain radius");
    ms_disturber_desc b = {
        .size = sizeof(ms_disturber_desc), .x = 0.5f, .y = 0.5f, .radius = 0.01f, .depth = 0.01f};
    int id;
    MS_ASSERT_REFUSED(ms_surface_add_disturber(s, &b, &id), MS_ERR_INVALID_ARGUMENT,
                      "disturber radius 0.01");
    b.radius = 0.2f;
    b.vx = NAN;
    MS_ASSERT_REFUSED(ms_surface_add_disturber(s, &b, &id), MS_ERR_INVALID_ARGUMENT,
                      "disturber vx");
    MS_ASSERT_REFUSED(ms_surface_move_disturber(s, 99, 0, 0, 0, 0), MS_ERR_INVALID_ARGUMENT,
                      "id 99");
    b.vx = 0;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    float path[4] = {0, 0, 1, NAN};
    MS_ASSERT_REFUSED(ms_surface_set_disturber_path(s, id, 2, path, 1, 0), MS_ERR_INVALID_ARGUMENT,
                      "path point 1");
    MS_ASSERT_REFUSED(ms_surface_set_disturber_path(s, id, 0, path, 1, 0), MS_ERR_INVALID_ARGUMENT,
                      "npoints 0");
    MS_ASSERT_REFUSED(ms_surface_remove_disturber(s, id + 1), MS_ERR_INVALID_ARGUMENT, "id");
    float depth[2] = {1, NAN}, c[2];
    MS_ASSERT_REFUSED(ms_surface_speed_from_depth(depth, 2, 9.81f, c), MS_ERR_INVALID_ARGUMENT,
                      "depth[1]");
    MS_ASSERT_REFUSED(ms_surface_speed_from_depth(depth, 1, 0, c), MS_ERR_INVALID_ARGUMENT,
                      "gravity 0");
    /* after every refusal the handle still steps */
    ck_assert_int_eq(ms_surface_step(s, 0.05f), MS_OK);
    free(f);
    ms_surface_destroy(s);
}
END_TEST

/* ---- accuracy ---------------------------------------------------------- */

/* Angular frequency of the (m, n) standing mode of a Lx x Ly reflecting
 * basin with N cells per metre, measured from the zero crossings of the
 * mode's amplitude (linear interpolation is exact to third order there,
 * where the cosine has no curvature). */
static double measured_omega(double lx, double ly, int m, int n, int N, double c)
{
    int nx = (int)lround(lx * N), ny = (int)lround(ly * N);
    float dx = (float)(1.0 / N);
    ms_surface *s = make(nx, ny, dx, (float)c, 1.0f, MS_BOUNDARY_REFLECT);
    float *f = malloc((size_t)nx * ny * sizeof *f);
    double norm = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double v = cos(m * PI * (x + 0.5) * dx / lx) * cos(n * PI * (y + 0.5) * dx / ly);
            f[y * nx + x] = (float)v;
            norm += v * v;
        }
    ck_assert_int_eq(ms_surface_set_height(s, f), MS_OK);
    const double omega = c * PI * sqrt(pow(m / lx, 2) + pow(n / ly, 2));
    const float dt = 0.5f * dx / (float)c; /* Courant 0.5: one sub-step a call */
    const int steps = (int)ceil(4.5 * 2 * PI / omega / dt);
    double prev = 1.0, t_first = -1, t_last = -1;
    int crossings = 0;
    for (int k = 1; k <= steps; ++k) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        const float *h = ms_surface_height(s, NULL, NULL);
        double a = 0;
        for (int i = 0; i < nx * ny; ++i)
            a += (double)h[i] * f[i];
        a /= norm;
        if ((prev > 0) != (a > 0)) {
            double t = (k - 1 + prev / (prev - a)) * (double)dt;
            if (t_first < 0)
                t_first = t;
            t_last = t;
            ++crossings;
        }
        prev = a;
    }
    ck_assert_int_ge(crossings, 8);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    ck_assert_int_eq(info.substeps, steps);
    free(f);
    ms_surface_destroy(s);
    return PI * (crossings - 1) / (t_last - t_first);
}

static void check_second_order(double lx, double ly, int m, int n)
{
    const double c = 1.0;
    const double omega = c * PI * sqrt(pow(m / lx, 2) + pow(n / ly, 2));
    const int N[4] = {16, 32, 64, 128};
    double err[4];
    for (int k = 0; k < 4; ++k)
        err[k] = fabs(measured_omega(lx, ly, m, n, N[k], c) - omega) / omega;
    for (int k = 0; k + 1 < 4; ++k) {
        double order = log2(err[k] / err[k + 1]);
        ck_assert_msg(order > 1.85 && order < 2.15,
                      "order %.3f between N=%d (err %.3e) and N=%d (err %.3e)", order, N[k], err[k],
                      N[k + 1], err[k + 1]);
    }
    ck_assert_msg(err[3] < 1e-3, "relative error %.3e at N=128", err[3]);
}

START_TEST(standing_mode_converges_2nd_order)
{
    check_second_order(1.0, 1.0, 2, 1);
}
END_TEST

START_TEST(standing_mode_converges_2nd_order_on_a_rectangle)
{
    check_second_order(1.0, 0.75, 1, 2);
}
END_TEST

START_TEST(speed_from_depth_is_shallow_water)
{
    float depth[4] = {0.1f, 0.4f, 0.0f, -1.0f}, c[4];
    ck_assert_int_eq(ms_surface_speed_from_depth(depth, 4, 9.81f, c), MS_OK);
    ck_assert_float_eq_tol(c[0], sqrtf(0.981f), 1e-6f);
    ck_assert_float_eq_tol(c[1], 2 * sqrtf(0.981f), 1e-6f);
    ck_assert_float_eq(c[2], 0.0f);
    ck_assert_float_eq(c[3], 0.0f);
}
END_TEST

/* Time at which the pulse from a drop at x = 0.5 m peaks at x = 2.5 m in a
 * narrow channel of uniform depth. */
static double peak_arrival(float depth)
{
    const int nx = 400, ny = 4;
    ms_surface *s = make(nx, ny, 0.01f, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    float *d = malloc(nx * ny * sizeof *d), *c = malloc(nx * ny * sizeof *c);
    for (int i = 0; i < nx * ny; ++i)
        d[i] = depth;
    ck_assert_int_eq(ms_surface_speed_from_depth(d, nx * ny, 9.81f, c), MS_OK);
    ck_assert_int_eq(ms_surface_set_speed_map(s, c), MS_OK);
    float *f = calloc(nx * ny, sizeof *f);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double r = ((x + 0.5) * 0.01 - 0.5) / 0.05;
            f[y * nx + x] = (float)exp(-r * r);
        }
    ck_assert_int_eq(ms_surface_set_height(s, f), MS_OK);
    double best = -1, t_best = 0;
    const float dt = 0.002f;
    for (int k = 1; k < 2000; ++k) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        const float *h = ms_surface_height(s, NULL, NULL);
        if (h[250] > best) {
            best = h[250];
            t_best = k * dt;
        }
    }
    ck_assert_double_gt(best, 0.4); /* half the bump travels each way */
    free(d);
    free(c);
    free(f);
    ms_surface_destroy(s);
    return t_best;
}

START_TEST(wave_speed_follows_depth)
{
    /* c = sqrt(g d): 0.99 m/s at 10 cm, twice that at 40 cm */
    double t1 = peak_arrival(0.1f), t2 = peak_arrival(0.4f);
    double c1 = sqrt(9.81 * 0.1), c2 = sqrt(9.81 * 0.4);
    ck_assert_msg(fabs(t1 - 2.0 / c1) < 0.02 * 2.0 / c1, "t1 %g, expected %g", t1, 2.0 / c1);
    ck_assert_msg(fabs(t2 - 2.0 / c2) < 0.02 * 2.0 / c2, "t2 %g, expected %g", t2, 2.0 / c2);
}
END_TEST

/* ---- conservation and stability --------------------------------------- */

static void random_field(ms_surface *s, unsigned seed, float amplitude)
{
    int n = s->nx * s->ny;
    float *f = malloc(n * sizeof *f);
    ms_rng r;
    ms_rng_seed(&r, seed);
    for (int i = 0; i < n; ++i)
        f[i] = amplitude * (2 * ms_rng_uniform(&r) - 1);
    ck_assert_int_eq(ms_surface_set_height(s, f), MS_OK);
    free(f);
}

START_TEST(white_noise_at_the_cfl_limit_conserves_energy)
{
    /* white noise excites the grid's fastest modes, the ones the CFL bound
     * is about; 20 000 steps at the largest stable step, undamped */
    ms_surface *s = make(64, 48, 0.01f, 1.0f, 1.0f, MS_BOUNDARY_REFLECT);
    random_field(s, 3, 0.01f);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    const float dt = info.max_dt;
    ck_assert_float_eq_tol(dt, 0.7f * 0.01f / 1.0f, 1e-9f);
    ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
    const double e0 = ms_surface_energy(s), m0 = mean_height(s);
    ck_assert_double_gt(e0, 0);
    double emin = e0, emax = e0;
    for (int k = 0; k < 20000; ++k) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        if (k % 100 == 0) {
            double e = ms_surface_energy(s);
            emin = fmin(emin, e);
            emax = fmax(emax, e);
        }
    }
    ms_surface_get_info(s, &info);
    ck_assert_int_eq(info.substeps, 20001); /* one sub-step a call: at the limit */
    ck_assert_double_lt(max_abs(s), 0.05);
    /* measured 1.6e-6 (float round-off of 20 000 leapfrog steps, whose
     * discrete energy is exact); a bound of 3x that fails a scheme that
     * leaks or gains energy at the CFL limit, which 1e-3 would not */
    ck_assert_msg((emax - emin) / e0 < 5e-6, "energy drifted %.3e", (emax - emin) / e0);
    /* The flux sums to zero exactly, so the mean moves by round-off only:
     * each step rounds every cell's velocity at ~eps |h| (white noise has
     * gradients as large as h), the errors add up as a random walk over the
     * cells and are integrated twice in time, which gives a drift of
     * eps |h| N^{3/2} / sqrt(cells) = 3.0e-5 here. */
    const double bound = 5.96e-8 * 0.01 * pow(20001, 1.5) / sqrt(64 * 48);
    ck_assert_msg(fabs(mean_height(s) - m0) < bound, "mean moved %.3e, round-off bound %.3e",
                  mean_height(s) - m0, bound);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(mean_height_is_conserved_with_drops_and_disturbers)
{
    ms_surface *s = make(96, 64, 0.01f, 0.6f, 1.0f, MS_BOUNDARY_REFLECT);
    ck_assert_int_eq(ms_surface_add_drop(s, 0.3f, 0.3f, 0.05f, 0.01f), MS_OK);
    ck_assert_int_eq(ms_surface_add_drop(s, 0.7f, 0.2f, 0.04f, -0.01f), MS_OK);
    const double m0 = mean_height(s);
    ms_disturber_desc b = {.size = sizeof(ms_disturber_desc),
                           .x = 0.2f,
                           .y = 0.3f,
                           .vx = 0.3f,
                           .vy = 0,
                           .radius = 0.04f,
                           .depth = 0.005f};
    int id;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    float path[6] = {0.2f, 0.3f, 0.7f, 0.3f, 0.5f, 0.5f};
    ck_assert_int_eq(ms_surface_set_disturber_path(s, id, 3, path, 0.4f, 1), MS_OK);
    for (int k = 0; k < 600; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_double_gt(max_abs(s), 1e-4);
    ck_assert_msg(fabs(mean_height(s) - m0) < 1e-8, "mean moved %.3e from %.3e",
                  mean_height(s) - m0, m0);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(long_run_with_rain_and_disturber_stays_bounded)
{
    /* 20 000 steps at the largest stable step, rain and a boat going round:
     * damping makes the energy settle; it must not grow */
    ms_surface *s = make(128, 128, 0.01f, 0.5f, 0.9f, MS_BOUNDARY_REFLECT);
    ms_rain rain = {.size = sizeof(ms_rain), .rate = 20, .radius = 0.03f, .amplitude = -0.004f};
    ck_assert_int_eq(ms_surface_set_rain(s, &rain), MS_OK);
    ms_disturber_desc b = {
        .size = sizeof(ms_disturber_desc), .x = 0.3f, .y = 0.3f, .radius = 0.05f, .depth = 0.004f};
    int id;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    float path[8] = {0.3f, 0.3f, 1.0f, 0.3f, 1.0f, 1.0f, 0.3f, 1.0f};
    ck_assert_int_eq(ms_surface_set_disturber_path(s, id, 4, path, 0.6f, 1), MS_OK);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    const float dt = info.max_dt;
    double quarter_max[4] = {0};
    for (int k = 0; k < 20000; ++k) {
        ck_assert_int_eq(ms_surface_step(s, dt), MS_OK);
        if (k % 50 == 0) {
            double e = ms_surface_energy(s);
            ck_assert(isfinite(e));
            quarter_max[k / 5000] = fmax(quarter_max[k / 5000], e);
        }
    }
    ms_surface_get_info(s, &info);
    ck_assert_int_gt(info.drops, 100);
    ck_assert_double_lt(max_abs(s), 0.05);
    ck_assert_double_gt(quarter_max[3], 0);
    ck_assert_msg(quarter_max[3] < 2 * quarter_max[1], "energy grew: %.3e then %.3e",
                  quarter_max[1], quarter_max[3]);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(damping_is_per_second_and_decays_energy)
{
    /* velocity kept per second 0.5 -> energy ~ 0.5^t, independent of how
     * finely the caller steps */
    double e_end[2];
    const float frame[2] = {1.0f / 30, 1.0f / 240};
    for (int k = 0; k < 2; ++k) {
        ms_surface *s = make(64, 64, 0.01f, 0.5f, 0.5f, MS_BOUNDARY_REFLECT);
        ck_assert_int_eq(ms_surface_add_drop(s, 0.32f, 0.32f, 0.08f, 0.01f), MS_OK);
        ck_assert_int_eq(ms_surface_step(s, frame[k]), MS_OK);
        const double e0 = ms_surface_energy(s);
        double prev = e0;
        int frames = (int)lroundf(2.0f / frame[k]) - 1;
        for (int f = 0; f < frames; ++f) {
            ck_assert_int_eq(ms_surface_step(s, frame[k]), MS_OK);
            double e = ms_surface_energy(s);
            ck_assert_msg(e <= prev * (1 + 1e-6), "energy rose from %.6e to %.6e", prev, e);
            prev = e;
        }
        e_end[k] = prev / e0;
        ck_assert_msg(e_end[k] > 0.18 && e_end[k] < 0.32, "E(2 s)/E0 = %.3f, expected ~0.25",
                      e_end[k]);
        ms_surface_destroy(s);
    }
    ck_assert_msg(fabs(e_end[0] - e_end[1]) < 0.02, "frame-rate dependent: %.4f vs %.4f", e_end[0],
                  e_end[1]);
}
END_TEST

START_TEST(damping_map_damps_only_where_it_says)
{
    /* left half strongly damped, right half not: a drop on the right keeps
     * its energy until the wave reaches the damped half */
    const int nx = 128, ny = 32;
    ms_surface *s = make(nx, ny, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    float *d = malloc(nx * ny * sizeof *d);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x)
            d[y * nx + x] = x < nx / 2 ? 0.01f : 1.0f;
    ck_assert_int_eq(ms_surface_set_damping_map(s, d), MS_OK);
    ck_assert_int_eq(ms_surface_add_drop(s, 1.0f, 0.16f, 0.05f, 0.01f), MS_OK);
    const float frame = 1.0f / 60;
    ck_assert_int_eq(ms_surface_step(s, frame), MS_OK);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 18; ++k) /* 0.3 s: the front moved 15 cm, not 36 */
        ck_assert_int_eq(ms_surface_step(s, frame), MS_OK);
    ck_assert_double_eq_tol(ms_surface_energy(s), e0, 1e-5 * e0);
    for (int k = 0; k < 240; ++k) /* 4 s: it has crossed the damped half */
        ck_assert_int_eq(ms_surface_step(s, frame), MS_OK);
    double e = ms_surface_energy(s);
    /* the undamped half keeps what it holds, the damped half loses it */
    ck_assert_msg(e > 0.05 * e0 && e < 0.5 * e0, "E(4.3 s)/E0 = %.3f", e / e0);
    free(d);
    ms_surface_destroy(s);
}
END_TEST

/* ---- obstacles and edges ----------------------------------------------- */

START_TEST(obstacle_wall_reflects_everything)
{
    const int nx = 128, ny = 64;
    ms_surface *s = make(nx, ny, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    unsigned char *mask = calloc(nx * ny, 1);
    for (int y = 0; y < ny; ++y)
        mask[y * nx + 64] = mask[y * nx + 65] = 1;
    ck_assert_int_eq(ms_surface_set_obstacle_mask(s, mask), MS_OK);
    ck_assert_int_eq(ms_surface_add_drop(s, 0.4f, 0.32f, 0.05f, 0.01f), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    const double e0 = ms_surface_energy(s);
    for (int k = 0; k < 180; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    /* the wave has hit the wall many times: nothing behind it, all in front */
    ck_assert_double_eq(energy_in(s, 66, nx, 0, ny), 0.0);
    double front = energy_in(s, 0, 64, 0, ny);
    ck_assert_msg(fabs(front - e0) < 1e-3 * e0, "front %.6e vs %.6e", front, e0);
    const float *h = ms_surface_height(s, NULL, NULL);
    for (int y = 0; y < ny; ++y)
        ck_assert_float_eq(h[y * nx + 64], 0.0f);
    free(mask);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(obstacle_casts_a_shadow)
{
    /* a plane wave from the left meets a block: the block's lee gets much
     * less energy than the same place without the block */
    const int nx = 200, ny = 100;
    double lee[2];
    for (int with = 0; with < 2; ++with) {
        ms_surface *s = make(nx, ny, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_ABSORB);
        float *f = calloc(nx * ny, sizeof *f);
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                double r = (x - 30) / 6.0;
                f[y * nx + x] = (float)(0.01 * exp(-r * r));
            }
        ck_assert_int_eq(ms_surface_set_height(s, f), MS_OK);
        if (with) {
            unsigned char *mask = calloc(nx * ny, 1);
            for (int y = 30; y < 70; ++y)
                for (int x = 80; x < 90; ++x)
                    mask[y * nx + x] = 1;
            ck_assert_int_eq(ms_surface_set_obstacle_mask(s, mask), MS_OK);
            free(mask);
        }
        ck_assert_int_eq(ms_surface_step(s, 1.4f), MS_OK); /* front at x ~ 100 cells */
        lee[with] = energy_in(s, 92, 110, 40, 60);
        free(f);
        ms_surface_destroy(s);
    }
    ck_assert_msg(lee[1] < 0.1 * lee[0], "lee energy %.3e with block, %.3e without", lee[1],
                  lee[0]);
}
END_TEST

static double energy_left_after_radial_wave(ms_boundary b)
{
    const int n = 200;
    ms_surface *s = make(n, n, 0.01f, 1.0f, 1.0f, b);
    ck_assert_int_eq(ms_surface_add_drop(s, 1.0f, 1.0f, 0.08f, 0.01f), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    const double e0 = ms_surface_energy(s);
    /* the front reaches the edges at 1 s and the corners at 1.41 s; by
     * 2.2 s anything reflected is back inside */
    for (int k = 0; k < 132; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    double e = ms_surface_energy(s);
    ms_surface_destroy(s);
    return e / e0;
}

START_TEST(absorbing_edge_returns_under_2_percent)
{
    double absorbed = energy_left_after_radial_wave(MS_BOUNDARY_ABSORB);
    double reflected = energy_left_after_radial_wave(MS_BOUNDARY_REFLECT);
    /* measured 0.91 % (Mur's first-order condition is exact at normal
     * incidence and reflects a little of the oblique part of a radial
     * front, the corners most); 2 % is about twice that */
    ck_assert_msg(absorbed < 0.02, "absorbing edge kept %.2f%% of the energy", 100 * absorbed);
    ck_assert_msg(fabs(reflected - 1) < 1e-3, "reflecting edge kept %.4f", reflected);
}
END_TEST

START_TEST(periodic_grid_wraps_and_conserves)
{
    const int n = 64;
    ms_surface *s = make(n, n, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_PERIODIC);
    /* a drop on the corner shows up on all four corners */
    ck_assert_int_eq(ms_surface_add_drop(s, 0.0f, 0.0f, 0.06f, 0.01f), MS_OK);
    const float *h = ms_surface_height(s, NULL, NULL);
    ck_assert_float_gt(h[0], 0.0f);
    ck_assert_float_eq(h[n - 1], h[0]);
    ck_assert_float_eq(h[(n - 1) * n], h[0]);
    ck_assert_float_eq(h[n * n - 1], h[0]);
    ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    const double e0 = ms_surface_energy(s), m0 = mean_height(s);
    for (int k = 0; k < 300; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_msg(fabs(ms_surface_energy(s) - e0) < 1e-4 * e0, "energy %.6e vs %.6e",
                  ms_surface_energy(s), e0);
    ck_assert_double_lt(fabs(mean_height(s) - m0), 1e-9);
    /* a drop centred on the seam stays mirror-symmetric about it: cell row
     * j and row n-1-j see the same waves (to round-off), so the seam is
     * invisible */
    h = ms_surface_height(s, NULL, NULL);
    double hmax = max_abs(s);
    for (int x = 0; x < n; ++x)
        ck_assert_double_lt(fabs(h[3 * n + x] - h[(n - 4) * n + x]), 1e-5 * hmax);
    ms_surface_destroy(s);
}
END_TEST

/* ---- drops, rain, disturbers ------------------------------------------- */

START_TEST(drop_is_smooth_and_keeps_its_volume)
{
    ms_surface *s = make(128, 128, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    /* a 10 cm drop: volume A pi R^2 (1/2 - 2/pi^2) of the raised cosine */
    ck_assert_int_eq(ms_surface_add_drop(s, 0.64f, 0.64f, 0.1f, 0.01f), MS_OK);
    double vol = mean_height(s) * 128 * 128 * 1e-4;
    double expect = 0.01 * PI * 0.01 * (0.5 - 2 / (PI * PI));
    ck_assert_msg(fabs(vol - expect) < 0.01 * expect, "volume %.4e vs %.4e", vol, expect);
    /* a drop far smaller than a cell is widened to 2 cells, same volume */
    ms_surface_destroy(s);
    s = make(128, 128, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    ck_assert_int_eq(ms_surface_add_drop(s, 0.645f, 0.645f, 0.002f, 0.5f), MS_OK);
    vol = mean_height(s) * 128 * 128 * 1e-4;
    expect = 0.5 * PI * 0.002 * 0.002 * (0.5 - 2 / (PI * PI));
    ck_assert_msg(fabs(vol - expect) < 0.05 * expect, "widened volume %.4e vs %.4e", vol, expect);
    int nx, ny;
    const float *h = ms_surface_height(s, &nx, &ny);
    int nonzero = 0;
    for (int i = 0; i < nx * ny; ++i)
        nonzero += h[i] != 0;
    ck_assert_int_ge(nonzero, 9); /* not a one-cell spike */
    ms_surface_destroy(s);
}
END_TEST

static void run_rain(uint64_t seed, float *out, ms_surface_info *info)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = 64;
    d.seed = seed;
    ms_surface *s;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ms_rain rain = {.size = sizeof(ms_rain), .rate = 50, .radius = 0.03f, .amplitude = -0.002f};
    ck_assert_int_eq(ms_surface_set_rain(s, &rain), MS_OK);
    for (int k = 0; k < 240; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    memcpy(out, ms_surface_height(s, NULL, NULL), 64 * 64 * sizeof *out);
    ms_surface_get_info(s, info);
    ms_surface_destroy(s);
}

START_TEST(rain_is_seeded_and_falls_at_its_rate)
{
    float a[64 * 64], b[64 * 64], c[64 * 64];
    ms_surface_info ia = ms_surface_info_init(), ib = ia, ic = ia;
    run_rain(5, a, &ia);
    run_rain(5, b, &ib);
    run_rain(6, c, &ic);
    ck_assert_int_eq(memcmp(a, b, sizeof a), 0);
    ck_assert_int_ne(memcmp(a, c, sizeof a), 0);
    /* 50 drops/m^2/s on 0.64^2 m^2 for 4 s: 81.9 expected, sd 9 */
    double expect = 50 * 0.64 * 0.64 * 4;
    ck_assert_msg(fabs(ia.drops - expect) < 4 * sqrt(expect), "%ld drops, expected %.1f", ia.drops,
                  expect);
}
END_TEST

START_TEST(no_rain_draws_no_random_numbers)
{
    ms_surface *s = make(32, 32, 0.01f, 0.5f, 0.9f, MS_BOUNDARY_REFLECT);
    ms_rng before = s->rng;
    ms_rain rain = {.size = sizeof(ms_rain), .rate = 10, .radius = 0.02f, .amplitude = 0.001f};
    ck_assert_int_eq(ms_surface_set_rain(s, &rain), MS_OK);
    ck_assert_int_eq(ms_surface_set_rain(s, NULL), MS_OK); /* off again */
    for (int k = 0; k < 60; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_int_eq(memcmp(&before, &s->rng, sizeof before), 0);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    ck_assert_int_eq(info.drops, 0);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(still_disturber_settles_into_its_dent)
{
    ms_surface *s = make(96, 96, 0.01f, 0.5f, 0.2f, MS_BOUNDARY_REFLECT);
    ms_disturber_desc b = {
        .size = sizeof(ms_disturber_desc), .x = 0.48f, .y = 0.48f, .radius = 0.1f, .depth = 0.01f};
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, NULL), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 8.0f), MS_OK);
    const float *h = ms_surface_height(s, NULL, NULL);
    /* f = -P plus the constant that keeps the volume: P = depth b(r/R), b
     * the raised cosine (1 + cos(pi r/R)) / 2; the four cells around the
     * centre lie r = sqrt(2) 0.005 m from it, so the dent there is
     * -0.01 b = -0.0098771 m below the lift at cell (5, 5), where P = 0. */
    double centre = 0.25 * (h[47 * 96 + 47] + h[47 * 96 + 48] + h[48 * 96 + 47] + h[48 * 96 + 48]);
    double lift = h[5 * 96 + 5];
    const double r = sqrt(2.0) * 0.005 / 0.1, dent = -0.01 * 0.5 * (1 + cos(PI * r));
    /* measured 1.1e-6 off (the ringing left after 8 s at damping 0.2/s and
     * the discrete Laplacian); 5e-6 is 4.5x that, a 5 % wrong dent is 5e-4 */
    ck_assert_msg(fabs(centre - lift - dent) < 5e-6, "dent %.7f m, analytic %.7f m", centre - lift,
                  dent);
    ck_assert_double_lt(fabs(mean_height(s)), 1e-9);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(moving_disturber_follows_its_path_and_leaves_a_wake)
{
    ms_surface *s = make(200, 100, 0.01f, 0.5f, 0.95f, MS_BOUNDARY_ABSORB);
    ms_disturber_desc b = {
        .size = sizeof(ms_disturber_desc), .x = 0.2f, .y = 0.5f, .radius = 0.04f, .depth = 0.005f};
    int id;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    float path[4] = {0.2f, 0.5f, 1.8f, 0.5f};
    ck_assert_int_eq(ms_surface_set_disturber_path(s, id, 2, path, 0.4f, 0), MS_OK);
    for (int k = 0; k < 150; ++k) /* 2.5 s at 0.4 m/s: 1 m */
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    float x, y;
    ck_assert_int_eq(ms_surface_disturber_position(s, id, &x, &y), MS_OK);
    ck_assert_float_eq_tol(x, 1.2f, 1e-3f);
    ck_assert_float_eq_tol(y, 0.5f, 1e-6f);
    /* waves behind the boat (x in 0.3..0.9 m), both sides of its track */
    double behind = energy_in(s, 30, 90, 55, 90), ahead = energy_in(s, 150, 190, 10, 90);
    ck_assert_double_gt(behind, 0);
    ck_assert_msg(behind > 10 * ahead, "wake %.3e, ahead %.3e", behind, ahead);
    /* a non-looping path stops at its end */
    for (int k = 0; k < 240; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_surface_disturber_position(s, id, &x, &y), MS_OK);
    ck_assert_float_eq_tol(x, 1.8f, 1e-4f);
    ck_assert_int_eq(ms_surface_remove_disturber(s, id), MS_OK);
    MS_ASSERT_REFUSED(ms_surface_disturber_position(s, id, &x, &y), MS_ERR_INVALID_ARGUMENT,
                      "no disturber");
    ms_surface_destroy(s);
}
END_TEST

/* The sim's N_time steps of one sub-step each run as one fused
 * sweep (ms_surface_step_calls); they must give the bytes and the clock of
 * the N_time calls, with a moving disturber, an absorbing edge, 1 to 11
 * calls (over the 8 steps a sweep fuses), and with rain (which falls
 * between the calls, so those calls are not fused). */
START_TEST(fused_step_calls_are_the_calls)
{
    for (int rain = 0; rain < 2; ++rain)
        for (int calls = 1; calls <= 11; calls += 2) {
            ms_surface *s[2];
            for (int q = 0; q < 2; ++q) {
                s[q] = make(61, 47, 0.01f, 0.5f, 0.9f, MS_BOUNDARY_ABSORB);
                ck_assert_int_eq(ms_surface_add_drop(s[q], 0.2f, 0.15f, 0.04f, 0.01f), MS_OK);
                ms_disturber_desc d = ms_disturber_desc_default();
                d.x = 0.3f;
                d.y = 0.2f;
                d.vx = 0.2f;
                d.radius = 0.05f;
                int id;
                ck_assert_int_eq(ms_surface_add_disturber(s[q], &d, &id), MS_OK);
                if (rain) {
                    ms_rain r = ms_rain_default();
                    r.rate = 400.0f;
                    ck_assert_int_eq(ms_surface_set_rain(s[q], &r), MS_OK);
                }
            }
            ms_surface_info i0 = ms_surface_info_init(), i1 = ms_surface_info_init();
            ms_surface_get_info(s[0], &i0);
            const float dt = 0.9f * i0.max_dt; /* s: one sub-step a call */
            for (int frame = 0; frame < 3; ++frame) {
                for (int c = 0; c < calls; ++c)
                    ck_assert_int_eq(ms_surface_step(s[0], dt), MS_OK);
                ck_assert_int_eq(ms_surface_step_calls(s[1], dt, calls), MS_OK);
            }
            const float *h0 = ms_surface_height(s[0], NULL, NULL);
            const float *h1 = ms_surface_height(s[1], NULL, NULL);
            ck_assert_msg(memcmp(h0, h1, sizeof *h0 * 61 * 47) == 0, "rain %d calls %d", rain,
                          calls);
            ms_surface_get_info(s[0], &i0);
            ms_surface_get_info(s[1], &i1);
            ck_assert(i0.time == i1.time && i0.substeps == i1.substeps && i0.drops == i1.drops);
            ck_assert(i0.time > 0 && (!rain || i0.drops > 1));
            ms_surface_destroy(s[0]);
            ms_surface_destroy(s[1]);
        }
    ms_surface *s = make(8, 8, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    MS_ASSERT_REFUSED(ms_surface_step_calls(s, 1e-3f, 0), MS_ERR_INVALID_ARGUMENT, "calls");
    ms_surface_destroy(s);
}
END_TEST

/* Where every cell has the same a and delta (no speed or damping
 * map, no obstacle, not absorbing), the interior rows are stepped with a0
 * and d0 in registers instead of the per-cell arrays: the same bits as the
 * arrays' rows, for reflecting and periodic edges, a moving disturber and
 * fused sweeps; a map or an obstacle turns it off, a snapshot's restore
 * makes the solver look again. */
START_TEST(uniform_rows_are_the_general_rows)
{
    static const ms_boundary edges[2] = {MS_BOUNDARY_REFLECT, MS_BOUNDARY_PERIODIC};
    for (int b = 0; b < 2; ++b) {
        ms_surface *s[2];
        for (int q = 0; q < 2; ++q) {
            s[q] = make(53, 41, 0.01f, 0.5f, 0.8f, edges[b]);
            ck_assert_int_eq(ms_surface_add_drop(s[q], 0.1f, 0.12f, 0.05f, 0.01f), MS_OK);
            ck_assert_int_eq(ms_surface_add_drop(s[q], 0.5f, 0.38f, 0.03f, -0.01f), MS_OK);
            ms_disturber_desc d = ms_disturber_desc_default();
            d.x = 0.2f;
            d.y = 0.3f;
            d.vx = 0.15f;
            int id;
            ck_assert_int_eq(ms_surface_add_disturber(s[q], &d, &id), MS_OK);
        }
        ms_surface_info info = ms_surface_info_init();
        ms_surface_get_info(s[0], &info);
        const float dt = 5.5f * info.max_dt; /* s: 6 sub-steps a call, fused */
        for (int q = 0; q < 2; ++q)
            ck_assert_int_eq(ms_surface_step(s[q], dt), MS_OK);
        ck_assert_int_eq(s[0]->uniform, 1);
        s[1]->uniform = 0; /* the arrays' rows (the coefficients stay for this dt) */
        for (int k = 0; k < 20; ++k)
            for (int q = 0; q < 2; ++q)
                ck_assert_int_eq(ms_surface_step(s[q], dt), MS_OK);
        ck_assert_int_eq(s[1]->uniform, 0);
        const float *h0 = ms_surface_height(s[0], NULL, NULL);
        const float *h1 = ms_surface_height(s[1], NULL, NULL);
        ck_assert_msg(memcmp(h0, h1, sizeof *h0 * 53 * 41) == 0, "edge %d", b);
        ck_assert(ms_surface_energy(s[0]) > 0);
        ms_surface_destroy(s[0]);
        ms_surface_destroy(s[1]);
    }
    /* an obstacle or a speed map: not uniform */
    ms_surface *s = make(20, 20, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    ck_assert_int_eq(ms_surface_step(s, 1e-3f), MS_OK);
    ck_assert_int_eq(s->uniform, 1);
    unsigned char mask[400] = {0};
    mask[210] = 1;
    ck_assert_int_eq(ms_surface_set_obstacle_mask(s, mask), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 1e-3f), MS_OK);
    ck_assert_int_eq(s->uniform, 0);
    ck_assert_int_eq(ms_surface_set_obstacle_mask(s, NULL), MS_OK);
    float c[400];
    for (int i = 0; i < 400; ++i)
        c[i] = i == 37 ? 0.4f : 0.5f;
    ck_assert_int_eq(ms_surface_set_speed_map(s, c), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 1e-3f), MS_OK);
    ck_assert_int_eq(s->uniform, 0);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(excite_sets_the_velocity)
{
    /* an impulse dh on a flat surface at rest gives kinetic energy
     * 1/2 (dh/dt)^2 dx^2, with dt the last sub-step, and no potential
     * energy yet (the staggered form pairs the new field with the old,
     * flat one) */
    ms_surface *s = make(32, 32, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    ck_assert_int_eq(ms_surface_step(s, 0.01f), MS_OK);
    float *dh = calloc(32 * 32, sizeof *dh);
    dh[16 * 32 + 16] = 1e-3f;
    ck_assert_int_eq(ms_surface_excite(s, dh, 2.0f), MS_OK);
    double v = 2e-3 / s->v_dt;
    double expect = 0.5 * v * v * 1e-4;
    ck_assert_double_eq_tol(ms_surface_energy(s), expect, 1e-6 * expect);
    free(dh);
    ms_surface_destroy(s);
}
END_TEST

START_TEST(info_reports_memory_and_time)
{
    ms_surface *s = make(100, 50, 0.01f, 0.5f, 1.0f, MS_BOUNDARY_REFLECT);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    ck_assert_uint_ge(info.bytes, 6 * 100 * 50 * sizeof(float));
    ck_assert_uint_lt(info.bytes, 8 * 112 * 52 * sizeof(float));
    ck_assert_float_eq(info.max_speed, 0.5f);
    ck_assert_int_eq(ms_surface_step(s, 0.25f), MS_OK);
    ms_surface_get_info(s, &info);
    ck_assert_double_eq_tol(info.time, 0.25, 1e-6);
    ck_assert_int_eq(info.substeps, (long)ceil(0.25 / (0.7 * 0.01 / 0.5)));
    ms_surface_desc d = ms_surface_get_desc(s);
    ck_assert_int_eq(d.nx, 100);
    ms_surface_destroy(s);
}
END_TEST

/* The sweep fuses up to 8 sub-steps (temporal blocking); it must give the
 * same bits as one sub-step per call, on every boundary, with a disturber
 * moving during the fused steps. */
static void run_fused(ms_boundary b, int fused, float *out)
{
    ms_surface *s = make(40, 24, 0.01f, 0.5f, 0.8f, b);
    ck_assert_int_eq(ms_surface_add_drop(s, 0.1f, 0.1f, 0.04f, 0.01f), MS_OK);
    ms_disturber_desc d = {.size = sizeof(ms_disturber_desc),
                           .x = 0.2f,
                           .y = 0.12f,
                           .vx = 0.3f,
                           .radius = 0.03f,
                           .depth = 0.003f};
    ck_assert_int_eq(ms_surface_add_disturber(s, &d, NULL), MS_OK);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    const float total = 19.5f * info.max_dt, sub = total / 20.0f;
    if (fused) {
        ck_assert_int_eq(ms_surface_step(s, total), MS_OK);
    } else {
        for (int k = 0; k < 20; ++k)
            ck_assert_int_eq(ms_surface_step(s, sub), MS_OK);
    }
    ms_surface_get_info(s, &info);
    ck_assert_int_eq(info.substeps, 20);
    memcpy(out, ms_surface_height(s, NULL, NULL), 40 * 24 * sizeof *out);
    ms_surface_destroy(s);
}

START_TEST(fused_substeps_give_the_same_bits)
{
    const ms_boundary bs[3] = {MS_BOUNDARY_REFLECT, MS_BOUNDARY_ABSORB, MS_BOUNDARY_PERIODIC};
    for (int k = 0; k < 3; ++k) {
        float a[40 * 24], b[40 * 24];
        run_fused(bs[k], 1, a);
        run_fused(bs[k], 0, b);
        ck_assert_msg(memcmp(a, b, sizeof a) == 0, "boundary %d differs", (int)bs[k]);
        double m = 0;
        for (int i = 0; i < 40 * 24; ++i)
            m = fmax(m, fabs(a[i]));
        ck_assert_double_gt(m, 1e-4);
    }
}
END_TEST

static Suite *surface_suite(void)
{
    Suite *s = suite_create("surface");
    TCase *refuse = tcase_create("refusals");
    tcase_set_timeout(refuse, 30);
    tcase_add_test(refuse, create_refuses_bad_descs);
    tcase_add_test(refuse, step_refuses_bad_dt_and_unreachable_stability);
    tcase_add_test(refuse, inputs_are_refused_with_the_value);
    suite_add_tcase(s, refuse);

    TCase *acc = tcase_create("accuracy");
    tcase_set_timeout(acc, 120);
    tcase_add_test(acc, standing_mode_converges_2nd_order);
    tcase_add_test(acc, standing_mode_converges_2nd_order_on_a_rectangle);
    tcase_add_test(acc, speed_from_depth_is_shallow_water);
    tcase_add_test(acc, wave_speed_follows_depth);
    suite_add_tcase(s, acc);

    TCase *stab = tcase_create("stability");
    tcase_set_timeout(stab, 120);
    tcase_add_test(stab, fused_substeps_give_the_same_bits);
    tcase_add_test(stab, white_noise_at_the_cfl_limit_conserves_energy);
    tcase_add_test(stab, mean_height_is_conserved_with_drops_and_disturbers);
    tcase_add_test(stab, long_run_with_rain_and_disturber_stays_bounded);
    tcase_add_test(stab, damping_is_per_second_and_decays_energy);
    tcase_add_test(stab, damping_map_damps_only_where_it_says);
    suite_add_tcase(s, stab);

    TCase *edges = tcase_create("obstacles_and_edges");
    tcase_set_timeout(edges, 120);
    tcase_add_test(edges, obstacle_wall_reflects_everything);
    tcase_add_test(edges, obstacle_casts_a_shadow);
    tcase_add_test(edges, absorbing_edge_returns_under_2_percent);
    tcase_add_test(edges, periodic_grid_wraps_and_conserves);
    suite_add_tcase(s, edges);

    TCase *fx = tcase_create("effects");
    tcase_set_timeout(fx, 60);
    tcase_add_test(fx, drop_is_smooth_and_keeps_its_volume);
    tcase_add_test(fx, rain_is_seeded_and_falls_at_its_rate);
    tcase_add_test(fx, no_rain_draws_no_random_numbers);
    tcase_add_test(fx, still_disturber_settles_into_its_dent);
    tcase_add_test(fx, moving_disturber_follows_its_path_and_leaves_a_wake);
    tcase_add_test(fx, excite_sets_the_velocity);
    tcase_add_test(fx, fused_step_calls_are_the_calls);
    tcase_add_test(fx, uniform_rows_are_the_general_rows);
    tcase_add_test(fx, info_reports_memory_and_time);
    suite_add_tcase(s, fx);
    return s;
}

int main(void)
{
    return ms_test_run(surface_suite());
}
