/* Waves carried by the flow (lib/surface/current.c): a packet on a uniform
 * current U travels at c + U, a fixed-frequency source's wavelength is
 * Doppler-shifted to 2 pi (c +- U) / omega down- and upstream, a current
 * of zero changes no byte, shear damps at kappa |S|, and bad values are
 * refused with the value and the bound. In a sim (surface.advect): a
 * scene that does not ask pays no byte and no step and keeps its bytes,
 * and a pool at rest with the effect on stays at rest. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "surface/surface_internal.h"

static const double PI = 3.14159265358979323846;

static ms_surface *make(int nx, int ny, float dx, float c, ms_boundary b)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = nx;
    d.ny = ny;
    d.dx = dx;
    d.wave_speed = c;
    d.damping = 1.0f;
    d.boundary = b;
    ms_surface *s = NULL;
    ms_status st = ms_surface_create(&d, &s);
    ck_assert_msg(st == MS_OK, "create: %s", ms_last_error());
    return s;
}

/* A uniform current (ux, uy) on every cell. */
static void uniform_current(ms_surface *s, float ux, float uy)
{
    int nx, ny;
    ms_surface_height(s, &nx, &ny);
    size_t n = (size_t)nx * ny;
    float *u = malloc(n * sizeof *u), *v = malloc(n * sizeof *v);
    for (size_t i = 0; i < n; ++i) {
        u[i] = ux;
        v[i] = uy;
    }
    ck_assert_msg(ms_surface_set_current(s, u, v) == MS_OK, "%s", ms_last_error());
    free(u);
    free(v);
}

/* The centroid (m) of f^2 along x over the cells [x0, x1) of row 0. */
static double centroid(const float *f, float dx, int x0, int x1)
{
    double m = 0, mx = 0;
    for (int x = x0; x < x1; ++x) {
        double w = (double)f[x] * f[x];
        m += w;
        mx += w * (x + 0.5) * dx;
    }
    return mx / m;
}

/* A packet at rest splits into halves running at +c and -c; on a current
 * U both are carried by U. Returns their speeds (m/s) from the centroids
 * after t seconds. The grid is periodic, long enough that the halves do
 * not meet, and 4 rows of identical cells (a 1D problem). */
static void packet_speeds(float U, double t, double *right, double *left)
{
    const int nx = 1024, ny = 4;
    const float dx = 0.005f, c = 0.5f, x0 = 2.0f;
    const float lambda = 0.08f, sigma = 0.15f; /* m: 16 cells per wavelength */
    ms_surface *s = make(nx, ny, dx, c, MS_BOUNDARY_PERIODIC);
    float *h = calloc((size_t)nx * ny, sizeof *h);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double r = (x + 0.5) * dx - x0;
            h[(size_t)y * nx + x] =
                (float)(0.01 * exp(-r * r / (2.0 * sigma * sigma)) * cos(2 * PI * r / lambda));
        }
    ck_assert(ms_surface_set_height(s, h) == MS_OK);
    if (U != 0)
        uniform_current(s, U, 0);
    const int frames = (int)lround(t * 60);
    for (int i = 0; i < frames; ++i)
        ck_assert_msg(ms_surface_step(s, 1.0f / 60) == MS_OK, "%s", ms_last_error());
    const float *f = ms_surface_height(s, NULL, NULL);
    /* the halves lie either side of x0 + U t, the packet's middle */
    const int mid = (int)((x0 + U * t) / dx);
    *right = (centroid(f, dx, mid, nx) - x0) / t;
    *left = (centroid(f, dx, 0, mid) - x0) / t;
    ms_surface_destroy(s);
    free(h);
}

START_TEST(packet_on_current_travels_at_c_plus_u)
{
    const double t = 2.0, c = 0.5;
    double r0, l0;
    packet_speeds(0.0f, t, &r0, &l0);
    for (int k = 0; k < 2; ++k) {
        const float U = k ? -0.15f : 0.2f;
        double r, l;
        packet_speeds(U, t, &r, &l);
        /* against the theory c + U within 2 % of c, and against the same
         * grid's still-water speed (its own dispersion at 16 cells per
         * wavelength taken out) within 1 % of c */
        ck_assert_msg(fabs(r - (c + U)) < 0.02 * c && fabs(l - (-c + U)) < 0.02 * c,
                      "U %g: packets at %g and %g m/s, theory %g and %g", (double)U, r, l, c + U,
                      -c + U);
        ck_assert_msg(fabs((r - r0) - U) < 0.01 * c && fabs((l - l0) - U) < 0.01 * c,
                      "U %g: the current added %g and %g m/s", (double)U, r - r0, l - l0);
    }
}
END_TEST

/* The mean distance (m) between zero crossings of row 0 over [a, b) m,
 * times 2: the wavelength. */
static double wavelength(const float *f, float dx, double a, double b)
{
    int x0 = (int)(a / dx), x1 = (int)(b / dx);
    double first = -1, last = -1;
    int n = 0;
    for (int x = x0; x < x1; ++x)
        if ((f[x] < 0) != (f[x + 1] < 0)) {
            double z = (x + 0.5 + f[x] / (f[x] - f[x + 1])) * dx;
            if (first < 0)
                first = z;
            last = z;
            n++;
        }
    ck_assert_msg(n >= 6, "only %d zero crossings in [%g, %g] m", n, a, b);
    return 2 * (last - first) / (n - 1);
}

/* A line source of fixed frequency omega at x_s on a current U (forced
 * through ms_surface_excite each step): downstream its waves are
 * 2 pi (c + U) / omega long, upstream 2 pi (c - U) / omega. */
START_TEST(source_on_current_is_doppler_shifted)
{
    const int nx = 1024, ny = 4;
    const float dx = 0.005f, c = 0.5f, U = 0.2f, xs = 2.0f;
    const double omega = 2 * PI * c / 0.2; /* rad/s: 0.2 m waves on still water */
    const float dt = 0.005f;               /* s, one sub-step (Courant 0.5) */
    /* reflecting ends, far enough that nothing they return reaches the
     * windows in the time run (an absorbing edge's sponge would fill the
     * four rows) */
    ms_surface *s = make(nx, ny, dx, c, MS_BOUNDARY_REFLECT);
    uniform_current(s, U, 0);
    float *g = calloc((size_t)nx * ny, sizeof *g), *e = calloc((size_t)nx * ny, sizeof *e);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double r = ((x + 0.5) * dx - xs) / 0.02;
            g[(size_t)y * nx + x] = (float)exp(-0.5 * r * r);
        }
    /* 6 s: the waves have filled both windows; the downstream end returns
     * them at c - U, into the window after 9.9 s, the upstream one after
     * 6.7 s */
    const int steps = (int)lround(6.0 / dt);
    for (int i = 0; i < steps; ++i) {
        double t = i * (double)dt, ramp = t < 1 ? t : 1.0;
        float a = (float)(1e-2 * ramp * sin(omega * t) * dt);
        for (size_t k = 0; k < (size_t)nx * ny; ++k)
            e[k] = a * g[k];
        ck_assert(ms_surface_excite(s, e, 1.0f) == MS_OK);
        ck_assert_msg(ms_surface_step(s, dt) == MS_OK, "%s", ms_last_error());
    }
    const float *f = ms_surface_height(s, NULL, NULL);
    double down = wavelength(f, dx, xs + 0.2, xs + 1.5), up = wavelength(f, dx, xs - 0.8, xs - 0.2);
    double down_th = 2 * PI * (c + U) / omega, up_th = 2 * PI * (c - U) / omega;
    /* 3 %: the 5-point Laplacian's own lag at 12 cells per wavelength
     * upstream is ~1 % */
    ck_assert_msg(fabs(down / down_th - 1) < 0.03 && fabs(up / up_th - 1) < 0.03,
                  "wavelengths %g m downstream (theory %g), %g m upstream (theory %g)", down,
                  down_th, up, up_th);
    ms_surface_destroy(s);
    free(g);
    free(e);
}
END_TEST

/* A drop on a reflecting basin: no current, a current of zero set, and one
 * set and taken away again give the same bytes. */
START_TEST(zero_current_changes_no_byte)
{
    float *out[3];
    int nx = 96, ny = 80;
    for (int k = 0; k < 3; ++k) {
        ms_surface *s = make(nx, ny, 0.01f, 0.5f, MS_BOUNDARY_REFLECT);
        ck_assert(ms_surface_add_drop(s, 0.4f, 0.3f, 0.05f, 0.01f) == MS_OK);
        if (k >= 1)
            uniform_current(s, 0, 0);
        if (k == 2) {
            uniform_current(s, 0.3f, 0.1f);
            ck_assert(ms_surface_set_current(s, NULL, NULL) == MS_OK);
        }
        for (int i = 0; i < 90; ++i)
            ck_assert(ms_surface_step(s, 1.0f / 60) == MS_OK);
        out[k] = malloc((size_t)nx * ny * sizeof(float));
        memcpy(out[k], ms_surface_height(s, NULL, NULL), (size_t)nx * ny * sizeof(float));
        ms_surface_info info = ms_surface_info_init();
        ms_surface_get_info(s, &info);
        if (k == 2) { /* the current's planes are freed with it */
            ms_surface_info i0 = ms_surface_info_init();
            ms_surface *t = make(nx, ny, 0.01f, 0.5f, MS_BOUNDARY_REFLECT);
            ms_surface_get_info(t, &i0);
            ck_assert_uint_eq(info.bytes, i0.bytes);
            ms_surface_destroy(t);
        }
        ms_surface_destroy(s);
    }
    ck_assert(memcmp(out[0], out[1], (size_t)nx * ny * sizeof(float)) == 0);
    ck_assert(memcmp(out[0], out[2], (size_t)nx * ny * sizeof(float)) == 0);
    for (int k = 0; k < 3; ++k)
        free(out[k]);
}
END_TEST

/* A basin at rest under a sheared current stays at rest (nothing to
 * carry, nothing to damp). */
START_TEST(still_water_on_a_current_stays_still)
{
    const int nx = 64, ny = 64;
    ms_surface *s = make(nx, ny, 0.01f, 0.5f, MS_BOUNDARY_REFLECT);
    float *u = malloc((size_t)nx * ny * sizeof *u), *v = malloc((size_t)nx * ny * sizeof *v);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            u[(size_t)y * nx + x] = 0.3f * sinf(0.2f * y);
            v[(size_t)y * nx + x] = 0.2f * cosf(0.15f * x);
        }
    ck_assert(ms_surface_set_current(s, u, v) == MS_OK);
    for (int i = 0; i < 600; ++i)
        ck_assert(ms_surface_step(s, 1.0f / 60) == MS_OK);
    const float *f = ms_surface_height(s, NULL, NULL);
    for (int i = 0; i < nx * ny; ++i)
        ck_assert_msg(f[i] == 0.0f, "cell %d at %g m", i, (double)f[i]);
    ck_assert(ms_surface_energy(s) == 0.0);
    ms_surface_destroy(s);
    free(u);
    free(v);
}
END_TEST

/* A standing wave under a current of uniform shear u_x = S y (|S| = S):
 * its energy decays at gamma = kappa S on top of the undamped basin's,
 * and with kappa = 0 not at all. */
START_TEST(shear_damps_at_kappa_times_strain_rate)
{
    const int nx = 64, ny = 64;
    const float dx = 0.01f, S = 0.5f; /* 1/s */
    double e_end[2];
    float kappa = 0;
    for (int k = 0; k < 2; ++k) {
        ms_surface_desc d = ms_surface_desc_default();
        d.nx = nx;
        d.ny = ny;
        d.dx = dx;
        d.damping = 1.0f;
        if (k == 0)
            d.turbulence_damping = 0;
        kappa = d.turbulence_damping;
        ms_surface *s = NULL;
        ck_assert(ms_surface_create(&d, &s) == MS_OK);
        float *h = malloc((size_t)nx * ny * sizeof *h), *u = malloc((size_t)nx * ny * sizeof *u),
              *v = calloc((size_t)nx * ny, sizeof *v);
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                /* the basin's lowest mode in y: the shear carries it along
                 * its crests, which leaves it as it is */
                h[(size_t)y * nx + x] = 0.01f * cosf((float)PI * (y + 0.5f) / ny);
                u[(size_t)y * nx + x] = S * ((y + 0.5f) * dx - 0.5f * ny * dx);
            }
        ck_assert(ms_surface_set_height(s, h) == MS_OK);
        ck_assert(ms_surface_set_current(s, u, v) == MS_OK);
        double e0 = ms_surface_energy(s);
        for (int i = 0; i < 120; ++i)
            ck_assert(ms_surface_step(s, 1.0f / 60) == MS_OK);
        e_end[k] = ms_surface_energy(s) / e0;
        ms_surface_destroy(s);
        free(h);
        free(u);
        free(v);
    }
    /* 2 s: exp(-kappa S t) = 0.32 for kappa 1.14; the energy of a damped
     * oscillator falls at gamma averaged over its phase, so within 10 % */
    const double want = exp(-kappa * S * 2.0);
    ck_assert_msg(fabs(e_end[0] - 1) < 0.02, "no damping: energy ratio %g", e_end[0]);
    ck_assert_msg(fabs(e_end[1] / want - 1) < 0.1, "kappa %g: energy ratio %g, want %g",
                  (double)kappa, e_end[1], want);
}
END_TEST

START_TEST(bad_currents_and_descs_are_refused)
{
    ms_surface *s = make(8, 8, 0.01f, 0.5f, MS_BOUNDARY_REFLECT);
    float u[64] = {0}, v[64] = {0};
    ck_assert_int_eq(ms_surface_set_current(s, u, NULL), MS_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(ms_last_error(), "both ux and uy"));
    u[9] = NAN;
    ck_assert_int_eq(ms_surface_set_current(s, u, v), MS_ERR_INVALID_ARGUMENT);
    ck_assert(strstr(ms_last_error(), "cell 9"));
    u[9] = 0;
    v[3] = 150.0f;
    ck_assert_int_eq(ms_surface_set_current(s, u, v), MS_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(ms_last_error(), "150") && strstr(ms_last_error(), "100 m/s"), "%s",
                  ms_last_error());
    ck_assert_int_eq(ms_surface_set_current(NULL, u, v), MS_ERR_INVALID_ARGUMENT);
    /* a current too fast for max_substeps advections of a cell */
    ms_surface_destroy(s);
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = 8;
    d.max_substeps = 2;
    ck_assert(ms_surface_create(&d, &s) == MS_OK);
    for (int i = 0; i < 64; ++i)
        u[i] = 50.0f, v[i] = 0;
    ck_assert(ms_surface_set_current(s, u, v) == MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 0.001f), MS_ERR_UNSTABLE);
    ck_assert_msg(strstr(ms_last_error(), "max_substeps 2"), "%s", ms_last_error());
    ms_surface_destroy(s);
    d = ms_surface_desc_default();
    d.advect = 2;
    ck_assert_int_eq(ms_surface_desc_check(&d), MS_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(ms_last_error(), "advect 2") && strstr(ms_last_error(), "[0, 1]"), "%s",
                  ms_last_error());
    d = ms_surface_desc_default();
    d.turbulence_damping = -1;
    ck_assert_int_eq(ms_surface_desc_check(&d), MS_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(ms_last_error(), "turbulence_damping") && strstr(ms_last_error(), "100"),
                  "%s", ms_last_error());
}
END_TEST

/* ---- in a sim: surface.advect ------------------------------------------------ */

static ms_scene *scene(const char *text)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return sc;
}

static ms_sim *sim_of(const ms_scene *sc, int threads)
{
    ms_sim *sim = NULL;
    ck_assert_msg(ms_sim_create_from_scene(sc, threads, &sim) == MS_OK, "%s", ms_last_error());
    return sim;
}

static void steps(ms_sim *sim, int n)
{
    for (int i = 0; i < n; ++i)
        ck_assert_msg(ms_sim_step(sim, 1.0f / 60) == MS_OK, "frame %d: %s", i, ms_last_error());
}

#define POOL                                                                                \
    "{\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.3]},"                          \
    " \"volume\": {\"spacing\": 0.04, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.2, 0.4, " \
    "0.12]}], \"field\": [16, 16]},"                                                        \
    " \"coupling\": {\"surface_from_volume\": 0.05, \"volume_from_surface\": 0.3},"         \
    " \"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.3, \"damping\": 0.9%s}}"

/* A scene that does not name surface.advect, or sets it false, pays no
 * byte and no step and gives the same bytes; with it the sim holds exactly
 * the flow, its averaging, the current and its walls on the wave grid and
 * the surface's five planes, takes the same wave steps, and the dam break's flow moves
 * the waves. */
START_TEST(absent_advect_costs_nothing)
{
    char text[1024];
    ms_scene *sc[3];
    static const char *const extra[] = {"", ", \"advect\": false", ", \"advect\": true"};
    ms_sim *sim[3];
    ms_stats st[3];
    for (int k = 0; k < 3; ++k) {
        snprintf(text, sizeof text, POOL, extra[k]);
        sc[k] = scene(text);
        sim[k] = sim_of(sc[k], 1);
        steps(sim[k], 30);
        st[k] = ms_stats_init();
        ms_sim_get_stats(sim[k], &st[k]);
    }
    int nx, ny;
    const size_t ns = 64 * 64, nf = 16 * 16;
    const float *h0 = ms_sim_height(sim[0], &nx, &ny);
    ck_assert(memcmp(h0, ms_sim_height(sim[1], NULL, NULL), ns * sizeof(float)) == 0);
    ck_assert(memcmp(h0, ms_sim_height(sim[2], NULL, NULL), ns * sizeof(float)) != 0);
    ck_assert_uint_eq(st[0].bytes, st[1].bytes);
    ck_assert_uint_eq(st[0].effects_bytes, 0);
    ck_assert_uint_eq(st[1].effects_bytes, 0);
    ck_assert_int_eq(st[0].surface_steps, st[1].surface_steps);
    ck_assert_int_eq(st[0].surface_steps, st[2].surface_steps);
    /* the flow (2 slots of vx, vy per field cell, a count per cell), its
     * averaging (4 per cell), ux, uy and the walls per wave cell, and a
     * row's distances to a wall */
    ck_assert_uint_eq(st[2].effects_bytes, (9 * nf + 3 * ns + 64) * sizeof(float));
    const ms_surface *s = ms_sim_surface(sim[2]);
    ck_assert_uint_eq(st[2].surface_bytes - st[0].surface_bytes, 5 * s->plane * sizeof(float));
    for (int k = 0; k < 3; ++k) {
        ms_sim_destroy(sim[k]);
        ms_scene_destroy(sc[k]);
    }
    /* without a volume there is no flow to carry the waves */
    const char *dry = "{\"surface\": {\"cells\": [8, 8], \"advect\": true}}";
    ms_scene *bad = NULL;
    ck_assert_int_eq(ms_scene_parse(dry, strlen(dry), &bad), MS_ERR_INVALID_ARGUMENT);
    ck_assert_msg(strstr(ms_last_error(), "surface.advect") && strstr(ms_last_error(), "volume"),
                  "%s", ms_last_error());
}
END_TEST

/* A pool at rest with surface.advect stays at rest: the still pool of the
 * stability suite (2000 particles, 50 x 50 field, 200 x 200 waves, both
 * couplings) for 30 s, with the bounds of its 10-minute run checked each
 * second after the lattice settles (3 s): no cell under 0.9 of the
 * settled level, the mean within 1 %, spread under 10 mm; and the waves
 * no rougher than without the effect (their rms within 20 % of it, or
 * under 0.1 mm). */
START_TEST(pool_at_rest_with_advect_stays_at_rest)
{
    static const char pool[] =
        "{\"frame_dt\": 0.016667,"
        " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
        " \"volume\": {\"spacing\": 0.05, \"gas_constant\": 100, \"viscosity\": 0.5,"
        "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [1, 1, 0.25]}], \"field\": [50, 50]},"
        " \"surface\": {\"cells\": [200, 200], \"wave_speed\": 0.2, \"damping\": 0.8%s},"
        " \"coupling\": {\"n_time\": 0, \"surface_from_volume\": 0.05,"
        "   \"volume_from_surface\": 0.3}}";
    char text[1024];
    double rms[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        snprintf(text, sizeof text, pool, k ? ", \"advect\": true" : "");
        ms_scene *sc = scene(text);
        ms_sim *sim = sim_of(sc, 1);
        double level = 0;
        for (int sec = 1; sec <= 30; ++sec) {
            steps(sim, 60);
            int nx, ny;
            const float *h = ms_sim_height(sim, &nx, &ny);
            double lo = 1e9, hi = -1e9, mean = 0;
            for (int i = 0; i < nx * ny; ++i) {
                lo = fmin(lo, h[i]);
                hi = fmax(hi, h[i]);
                mean += h[i] / (double)(nx * ny);
            }
            if (sec < 3)
                continue;
            if (sec == 3)
                level = mean;
            ck_assert_msg(lo >= 0.9 * level && fabs(mean - level) <= 0.01 * level &&
                              hi - lo <= 0.010,
                          "advect %d, t = %d s: lowest %.4f m, mean %.4f m, spread %.4f m "
                          "(settled level %.4f m)",
                          k, sec, lo, mean, hi - lo, level);
            const float *w = ms_sim_surface_height(sim, &nx, &ny);
            double r = 0;
            for (int i = 0; i < nx * ny; ++i)
                r += (double)w[i] * w[i] / (double)(nx * ny);
            rms[k] = fmax(rms[k], sqrt(r));
        }
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
    printf("still pool, 30 s: the waves' highest rms %.3g m with advect, %.3g m without\n", rms[1],
           rms[0]);
    ck_assert_msg(rms[1] <= fmax(1.2 * rms[0], 1e-4),
                  "the waves' highest rms: %.3g m with advect, %.3g m without", rms[1], rms[0]);
}
END_TEST

/* The river (surface.advect) gives the same bytes with 1 and 2 threads,
 * and a sim restored from a snapshot taken at frame 20 continues to the
 * same bytes as one never stopped (the flow the current comes from is in
 * the snapshot). */
START_TEST(river_same_bytes_threads_and_resume)
{
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_load("data/scenes/river.json", &sc) == MS_OK, "%s", ms_last_error());
    ms_sim *one = sim_of(sc, 1), *two = sim_of(sc, 2), *back = sim_of(sc, 1);
    steps(one, 20);
    steps(two, 20);
    size_t size = 0, wrote = 0;
    ck_assert(ms_sim_snapshot_size(one, &size) == MS_OK);
    void *buf = malloc(size);
    ck_assert(ms_sim_snapshot(one, buf, size, &wrote) == MS_OK);
    ck_assert_msg(ms_sim_restore(back, buf, wrote) == MS_OK, "%s", ms_last_error());
    steps(one, 40);
    steps(two, 40);
    steps(back, 40);
    int nx, ny;
    const float *h = ms_sim_height(one, &nx, &ny);
    const size_t bytes = (size_t)nx * ny * sizeof(float);
    ck_assert_msg(memcmp(h, ms_sim_height(two, NULL, NULL), bytes) == 0, "1 and 2 threads differ");
    ck_assert_msg(memcmp(h, ms_sim_height(back, NULL, NULL), bytes) == 0,
                  "the restored sim differs");
    free(buf);
    ms_sim_destroy(one);
    ms_sim_destroy(two);
    ms_sim_destroy(back);
    ms_scene_destroy(sc);
}
END_TEST

/* Waves carried by the river's current do not feed on its walls: after 5
 * s of the river scene (the pump has the channel flowing, up to ~0.5 m/s
 * near it), the current the sim hands the waves has no component through
 * a wall (at a cell next to the island or the pool's edge, the normal
 * component is under 5 % of the fastest cell: the ramp over h leaves 2.5
 * %), it still runs along the walls (along the island's south side at
 * least a quarter of the south reach's mean speed), and waves carried by
 * that current held frozen on the surface alone, with the scene's
 * obstacle and damping, lose energy: over 10 s their energy falls at
 * least tenfold (eq. 2's damping alone: 0.8 per second of velocity). A
 * current through the walls made them grow instead (14x in amplitude
 * every 2 s at the island's west wall, measured on the current at 20 s). */
START_TEST(river_current_stops_at_walls)
{
    ms_scene *sc = NULL;
    ck_assert_msg(ms_scene_load("data/scenes/river.json", &sc) == MS_OK, "%s", ms_last_error());
    ms_sim *sim = sim_of(sc, 1);
    steps(sim, 300);
    const ms_surface *s = ms_sim_surface(sim);
    const int nx = s->nx, ny = s->ny;
    const size_t n = (size_t)nx * ny;
    float *u = malloc(n * sizeof *u), *v = malloc(n * sizeof *v);
    unsigned char *solid = malloc(n);
    ck_assert_ptr_nonnull(s->cur_u);
    ck_assert_ptr_nonnull(s->solid);
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const size_t i = ms_surface_at(s, x, y), o = (size_t)y * nx + x;
            u[o] = s->cur_u[i];
            v[o] = s->cur_v[i];
            solid[o] = s->solid[i];
        }
    const float umax = s->cur_max;
    ck_assert_msg(umax > 0.1f, "the pump drives only %g m/s", (double)umax);
    double along = 0, reach = 0;
    int n_along = 0, n_reach = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            const size_t o = (size_t)y * nx + x;
            if (solid[o])
                continue;
            const int wx = x == 0 || x == nx - 1 || solid[o - 1] || solid[o + 1];
            const int wy = y == 0 || y == ny - 1 || solid[o - nx] || solid[o + nx];
            ck_assert_msg(!wx || fabsf(u[o]) < 0.05f * umax,
                          "cell (%d, %d) beside a wall along x: u %g m/s (fastest %g)", x, y,
                          (double)u[o], (double)umax);
            ck_assert_msg(!wy || fabsf(v[o]) < 0.05f * umax,
                          "cell (%d, %d) beside a wall along y: v %g m/s (fastest %g)", x, y,
                          (double)v[o], (double)umax);
            /* the south reach (y < 0.3 m) between x = 0.5 and 1.5 m */
            const float px = (x + 0.5f) * s->desc.dx, py = (y + 0.5f) * s->desc.dx;
            if (px > 0.5f && px < 1.5f && py < 0.3f) {
                reach += fabsf(u[o]);
                n_reach++;
                if (!solid[o + nx] && solid[o + 2 * nx]) { /* the row below the island */
                    along += fabsf(u[o]);
                    n_along++;
                }
            }
        }
    ck_assert_int_gt(n_along, 0);
    along /= n_along;
    reach /= n_reach;
    ck_assert_msg(along > 0.25 * reach, "along the island %g m/s, the reach's mean %g m/s", along,
                  reach);
    /* the frozen current on the surface alone */
    ms_surface *lone = NULL;
    ms_surface_desc d = ms_surface_get_desc(s);
    ck_assert(ms_surface_create(&d, &lone) == MS_OK);
    ck_assert(ms_surface_set_obstacle_mask(lone, solid) == MS_OK);
    for (int k = 0; k < 20; ++k)
        ck_assert(ms_surface_add_drop(lone, 0.1f + 0.09f * k, k % 2 ? 0.15f : 0.85f, 0.02f,
                                      0.002f) == MS_OK);
    ck_assert(ms_surface_set_current(lone, u, v) == MS_OK);
    double e1 = 0;
    for (int f = 1; f <= 600; ++f) {
        ck_assert_msg(ms_surface_step(lone, 1.0f / 60) == MS_OK, "%s", ms_last_error());
        if (f == 60)
            e1 = ms_surface_energy(lone);
    }
    const double e10 = ms_surface_energy(lone);
    printf("river at 5 s: fastest current %.3f m/s, along the island %.3f m/s (reach %.3f); "
           "carried waves' energy %.3g at 1 s, %.3g at 10 s\n",
           (double)umax, along, reach, e1, e10);
    ck_assert_msg(e1 > 0 && e10 < 0.1 * e1, "carried waves' energy %g at 1 s, %g at 10 s", e1, e10);
    ms_surface_destroy(lone);
    free(u);
    free(v);
    free(solid);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("current");
    TCase *acc = tcase_create("accuracy");
    tcase_set_timeout(acc, 120);
    tcase_add_test(acc, packet_on_current_travels_at_c_plus_u);
    tcase_add_test(acc, source_on_current_is_doppler_shifted);
    tcase_add_test(acc, shear_damps_at_kappa_times_strain_rate);
    suite_add_tcase(s, acc);
    TCase *still = tcase_create("still");
    tcase_set_timeout(still, 60);
    tcase_add_test(still, zero_current_changes_no_byte);
    tcase_add_test(still, still_water_on_a_current_stays_still);
    tcase_add_test(still, bad_currents_and_descs_are_refused);
    suite_add_tcase(s, still);
    TCase *sim = tcase_create("sim");
    tcase_set_timeout(sim, 600);
    tcase_add_test(sim, absent_advect_costs_nothing);
    tcase_add_test(sim, pool_at_rest_with_advect_stays_at_rest);
    tcase_add_test(sim, river_same_bytes_threads_and_resume);
    tcase_add_test(sim, river_current_stops_at_walls);
    suite_add_tcase(s, sim);
    return ms_test_run(s);
}
