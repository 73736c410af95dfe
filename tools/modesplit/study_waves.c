/* Study 1, waves (eq. 2), against analytic answers:
 *  - the (2, 1) standing mode of a 1 m x 1 m reflecting basin, whose
 *    angular frequency is c pi sqrt(2^2 + 1^2) (separation of variables):
 *    its error against cells per wavelength (second order expected) and
 *    against the Courant number c dt / dx;
 *  - the speed of the leading crest of a ring wave from a drop, against c;
 *  - a packet carried by a uniform current U (ms_surface_set_current)
 *    against c + U;
 *  - the paper's non-dispersive model against real water, whose phase speed
 *    is sqrt((g k + sigma k^3 / rho) tanh(k d)) / k (linear capillary-
 *    gravity waves), at a given depth d.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"

#define PI 3.14159265358979323846

static const char wave_scene[] =
    "{\"name\": \"accuracy-waves\", \"frame_dt\": 0.01,"
    " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
    " \"surface\": {\"cells\": [64, 64], \"wave_speed\": 1.0, \"damping\": 1.0,"
    "              \"boundary\": \"reflect\"}}";

/* The scene's surface, built through --set overrides as `modesplit run`
 * builds its own; *sim owns it (acc_free). */
static ms_surface *wave_surface(const char *json, const char *const *sets, ms_scene **sc,
                                ms_sim **sim)
{
    if (acc_sim(json, sets, sc, sim) != MS_OK)
        return NULL;
    return ms_sim_surface(*sim);
}

/* Measured angular frequency (rad/s) of the (2, 1) mode on an N x N grid
 * at Courant number cr, from the zero crossings of the mode's amplitude;
 * *ms_step and *ms_per_s the cost of the wave steps alone. */
/* The mode's angular frequency into *omega, its costs into r's cost fields. */
static int standing_mode(int N, double cr, double *omega, acc_row *r)
{
    char cells[64];
    snprintf(cells, sizeof cells, "surface.cells=[%d,%d]", N, N);
    const char *sets[] = {cells, NULL};
    ms_sim *sim;
    ms_scene *sc;
    ms_surface *s = wave_surface(wave_scene, sets, &sc, &sim);
    if (!s)
        return -1;
    const int m = 2, n = 1;
    const double c = 1.0, dx = 1.0 / N;
    float *f = malloc((size_t)N * N * sizeof *f);
    double norm = 0;
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x) {
            double v = cos(m * PI * (x + 0.5) * dx) * cos(n * PI * (y + 0.5) * dx);
            f[y * N + x] = (float)v;
            norm += v * v;
        }
    ms_surface_set_height(s, f);
    const double w_exact = c * PI * sqrt(m * m + n * n);
    const float dt = (float)(cr * dx / c);
    const int steps = (int)ceil(4.5 * 2 * PI / w_exact / dt);
    double prev = 1.0, t_first = -1, t_last = -1;
    acc_timer tm = {0};
    int crossings = 0, rc = 0;
    for (int k = 1; k <= steps; ++k) {
        acc_tic(&tm);
        ms_status sst = ms_surface_step(s, dt);
        acc_toc(&tm);
        if (sst != MS_OK) {
            tool_error("accuracy: waves: %s", ms_last_error());
            rc = -1;
            break;
        }
        const float *h = ms_surface_height(s, NULL, NULL);
        double a = 0;
        for (int i = 0; i < N * N; ++i)
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
    free(f);
    acc_free(sc, sim);
    if (rc == 0 && crossings < 2) {
        tool_error("accuracy: waves: the mode did not oscillate on %d^2", N);
        return -1;
    }
    *omega = PI * (crossings - 1) / (t_last - t_first);
    r->ms_per_step = 1e3 * tm.wall / steps;
    r->ms_per_s = 1e3 * tm.wall / (steps * (double)dt);
    r->cpu_ms_per_step = 1e3 * tm.cpu / steps;
    r->cpu_ms_per_s = 1e3 * tm.cpu / (steps * (double)dt);
    return rc;
}

static int mode_row(acc_ctx *c, const char *knob, double value, int N, double cr)
{
    double w = NAN;
    acc_row r = {.value = value, .size = (double)N * N, .threads = 1};
    /* the run acc_repeats times (its steps change what they time, so the
     * whole run is the repeat): the same frequency each time, the least
     * cost (accuracy.h) */
    for (int k = 0; k < acc_repeats; ++k) {
        double wk;
        acc_row rk = r;
        if (standing_mode(N, cr, &wk, &rk) != 0)
            return -1;
        if (k > 0 && wk != w) {
            tool_error("accuracy: waves: %dx%d gave %.17g rad/s, then %.17g", N, N, w, wk);
            return -1;
        }
        w = wk;
        if (k == 0 || rk.cpu_ms_per_step < r.cpu_ms_per_step) {
            r.cpu_ms_per_step = rk.cpu_ms_per_step;
            r.cpu_ms_per_s = rk.cpu_ms_per_s;
        }
        if (k == 0 || rk.ms_per_step < r.ms_per_step) {
            r.ms_per_step = rk.ms_per_step;
            r.ms_per_s = rk.ms_per_s;
        }
    }
    const double w_exact = PI * sqrt(5.0);
    r.error = fabs(w - w_exact) / w_exact;
    r.reference = w_exact;
    snprintf(r.study, sizeof r.study, "waves");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    snprintf(r.config, sizeof r.config, "%dx%d cells, Courant %.2f", N, N, cr);
    snprintf(r.metric, sizeof r.metric, "standing-mode frequency rel. error");
    return acc_add(c, &r);
}

int study_waves_cells(acc_ctx *c)
{
    c->cost_method = ACC_BY_RUN;
    /* the (2, 1) mode's wavelength is 2 pi / (pi sqrt 5) = 0.894 m */
    static const int full[] = {64, 128, 256, 512, 1024}, quick[] = {64, 128, 256};
    const int *N = c->quick ? quick : full;
    int n = c->quick ? 3 : 5;
    for (int i = 0; i < n; ++i)
        if (mode_row(c, "cells_per_wavelength", N[i] * 2.0 / sqrt(5.0), N[i], 0.5) != 0)
            return -1;
    return 0;
}

int study_waves_courant(acc_ctx *c)
{
    c->cost_method = ACC_BY_RUN;
    static const double full[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7}, quick[] = {0.1, 0.4, 0.7};
    const double *cr = c->quick ? quick : full;
    int n = c->quick ? 3 : 7, N = 128;
    for (int i = 0; i < n; ++i)
        if (mode_row(c, "courant", cr[i], N, cr[i]) != 0)
            return -1;
    return 0;
}

/* Radius (m) of the highest point along the ray y = centre, x > centre,
 * refined by a parabola through the three cells around it. */
static double crest_radius(const float *h, int N, double dx)
{
    int y = N / 2, best = N / 2 + 1;
    for (int x = N / 2 + 1; x < N - 1; ++x)
        if (h[y * N + x] > h[y * N + best])
            best = x;
    double a = h[y * N + best - 1], b = h[y * N + best], d = h[y * N + best + 1];
    double den = a - 2 * b + d, off = den < 0 ? 0.5 * (a - d) / den : 0;
    return (best + 0.5 + off) * dx - 0.5 * N * dx;
}

/* The crest's speed (m/s) of a ring from a drop on an N x N grid over
 * 2 m, read between t = 0.3 and 0.7 s; the wave steps' cost into *tm,
 * their count and the time simulated into *steps and *t. */
static int ring_speed(int N, double *speed, acc_timer *tm, long *steps, double *t)
{
    static const char ring_scene[] =
        "{\"name\": \"accuracy-ring\", \"frame_dt\": 0.01,"
        " \"domain\": {\"min\": [0, 0, 0], \"max\": [2, 2, 0.5]},"
        " \"surface\": {\"cells\": [64, 64], \"wave_speed\": 1.0, \"damping\": 1.0,"
        "              \"boundary\": \"absorb\"}}";
    char cells[64];
    snprintf(cells, sizeof cells, "surface.cells=[%d,%d]", N, N);
    const char *sets[] = {cells, NULL};
    ms_sim *sim;
    ms_scene *sc;
    ms_surface *s = wave_surface(ring_scene, sets, &sc, &sim);
    if (!s)
        return -1;
    const double dx = 2.0 / N, c0 = 1.0;
    /* a drop 0.1 m wide: resolved by 6 cells on the coarsest grid */
    ms_surface_add_drop(s, 1.0f, 1.0f, 0.1f, 0.01f);
    const float dt = (float)(0.5 * dx / c0);
    double r1 = NAN, t1 = 0.3, t2 = 0.7;
    *t = 0;
    *steps = 0;
    while (*t < t2 + 0.5 * dt) {
        acc_tic(tm);
        ms_status sst = ms_surface_step(s, dt);
        acc_toc(tm);
        if (sst != MS_OK) {
            tool_error("accuracy: ring: %s", ms_last_error());
            acc_free(sc, sim);
            return -1;
        }
        ++*steps;
        *t = *steps * (double)dt;
        if (isnan(r1) && *t >= t1) {
            t1 = *t;
            r1 = crest_radius(ms_surface_height(s, NULL, NULL), N, dx);
        }
    }
    t2 = *t;
    double r2 = crest_radius(ms_surface_height(s, NULL, NULL), N, dx);
    acc_free(sc, sim);
    *speed = (r2 - r1) / (t2 - t1);
    return 0;
}

int study_waves_ring(acc_ctx *c)
{
    c->cost_method = ACC_BY_RUN;
    static const int full[] = {128, 256, 512, 1024}, quick[] = {128, 256, 512};
    const int *Ns = c->quick ? quick : full;
    int n = c->quick ? 3 : 4;
    for (int i = 0; i < n; ++i) {
        int N = Ns[i];
        const double dx = 2.0 / N, c0 = 1.0;
        double speed = NAN, t = 0, cpu = INFINITY, wall = INFINITY;
        long steps = 0;
        /* the run acc_repeats times, the least cost (as mode_row) */
        for (int k = 0; k < acc_repeats; ++k) {
            acc_timer tm = {0};
            double sk;
            if (ring_speed(N, &sk, &tm, &steps, &t) != 0)
                return -1;
            if (k > 0 && sk != speed) {
                tool_error("accuracy: ring: %dx%d gave %.17g m/s, then %.17g", N, N, speed, sk);
                return -1;
            }
            speed = sk;
            cpu = fmin(cpu, tm.cpu);
            wall = fmin(wall, tm.wall);
        }
        acc_row r = {.value = 0.1 / dx,
                     .error = fabs(speed - c0) / c0,
                     .reference = c0,
                     .ms_per_s = 1e3 * wall / t,
                     .ms_per_step = 1e3 * wall / steps,
                     .cpu_ms_per_s = 1e3 * cpu / t,
                     .cpu_ms_per_step = 1e3 * cpu / steps,
                     .size = (double)N * N,
                     .threads = 1};
        snprintf(r.study, sizeof r.study, "waves");
        snprintf(r.knob, sizeof r.knob, "ring_cells_per_drop_radius");
        snprintf(r.config, sizeof r.config, "%dx%d cells over 2 m", N, N);
        snprintf(r.metric, sizeof r.metric, "ring front speed rel. error");
        if (acc_add(c, &r) != 0)
            return -1;
    }
    return 0;
}

int study_water_dispersion(acc_ctx *c)
{
    /* eq. 2 with the shallow-water speed of the library's depth map
     * (ms_surface_speed_from_depth) against linear capillary-gravity waves
     * of real water at 20 C: sigma 0.0728 N/m, rho 998 kg/m^3 */
    static const float depths[] = {0.02f, 0.1f, 1.0f};
    const double g = 9.81, sigma = 0.0728, rho = 998.0;
    int npts = c->quick ? 9 : 41;
    for (int di = 0; di < 3; ++di) {
        float cm = 0;
        if (ms_surface_speed_from_depth(&depths[di], 1, (float)g, &cm) != MS_OK) {
            tool_error("accuracy: water: %s", ms_last_error());
            return -1;
        }
        for (int i = 0; i < npts; ++i) {
            double lambda = 1e-3 * pow(1e4, (double)i / (npts - 1)); /* 1 mm .. 10 m */
            double k = 2 * PI / lambda;
            double creal = sqrt((g * k + sigma * k * k * k / rho) * tanh(k * depths[di])) / k;
            acc_row r = {.value = lambda,
                         .error = fabs(cm - creal) / creal,
                         .reference = creal,
                         .ms_per_s = NAN,
                         .ms_per_step = NAN,
                         .cpu_ms_per_s = NAN,
                         .cpu_ms_per_step = NAN,
                         .size = NAN,
                         .threads = 1};
            snprintf(r.study, sizeof r.study, "water");
            snprintf(r.knob, sizeof r.knob, "lambda_m_depth_%.3gm", (double)depths[di]);
            snprintf(r.config, sizeof r.config, "depth %g m", depths[di]);
            snprintf(r.metric, sizeof r.metric, "phase speed rel. error vs real water");
            if (acc_add(c, &r) != 0)
                return -1;
        }
    }
    return 0;
}

/* A packet at rest on a periodic strip (1024 x 4 cells of 5 mm, c = 0.5
 * m/s, 16 cells per wavelength) splits into halves at +c and -c; on a
 * uniform current U both are carried: the downstream half's centroid (of
 * f^2) runs at c + U. Rows: its error against c + U (the grid's own
 * dispersion at 16 cells included), and the speed the current added
 * against U (the grid's dispersion taken out by the U = 0 run). */
static int packet_speed(double U, double *speed, acc_timer *tm, long *frames)
{
    const int nx = 1024, ny = 4;
    const float dx = 0.005f, x0 = 2.0f;
    const double t = 2.0, sigma = 0.15, lambda = 0.08;
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = nx;
    d.ny = ny;
    d.dx = dx;
    d.wave_speed = 0.5f;
    d.damping = 1.0f;
    d.boundary = MS_BOUNDARY_PERIODIC;
    ms_surface *s = NULL;
    float *h = calloc((size_t)nx * ny, sizeof *h), *u = calloc((size_t)nx * ny, sizeof *u),
          *v = calloc((size_t)nx * ny, sizeof *v);
    int rc = -1;
    if (!h || !u || !v || ms_surface_create(&d, &s) != MS_OK)
        goto done;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double r = (x + 0.5) * dx - x0;
            h[(size_t)y * nx + x] =
                (float)(0.01 * exp(-r * r / (2 * sigma * sigma)) * cos(2 * PI * r / lambda));
            u[(size_t)y * nx + x] = (float)U;
        }
    if (ms_surface_set_height(s, h) != MS_OK ||
        (U != 0 && ms_surface_set_current(s, u, v) != MS_OK))
        goto done;
    const int n = (int)lround(t * 60);
    for (int i = 0; i < n; ++i) {
        acc_tic(tm);
        ms_status st = ms_surface_step(s, 1.0f / 60);
        acc_toc(tm);
        if (st != MS_OK)
            goto done;
    }
    *frames += n;
    const float *f = ms_surface_height(s, NULL, NULL);
    double m = 0, mx = 0;
    for (int x = (int)((x0 + U * t) / dx); x < nx; ++x) {
        m += (double)f[x] * f[x];
        mx += (double)f[x] * f[x] * (x + 0.5) * dx;
    }
    *speed = (mx / m - x0) / t;
    rc = 0;
done:
    if (rc)
        tool_error("accuracy: current: %s", ms_last_error());
    ms_surface_destroy(s);
    free(h);
    free(u);
    free(v);
    return rc;
}

int study_waves_current(acc_ctx *c)
{
    static const double Us[] = {-0.3, -0.15, 0.1, 0.2, 0.3}; /* m/s */
    const double c0 = 0.5;
    double still;
    acc_timer t0 = {0};
    long f0 = 0;
    if (packet_speed(0, &still, &t0, &f0) != 0)
        return -1;
    for (int i = 0; i < (int)(sizeof Us / sizeof Us[0]); ++i) {
        const double U = Us[i];
        double speed;
        acc_timer tm = {0};
        long frames = 0;
        if (packet_speed(U, &speed, &tm, &frames) != 0)
            return -1;
        for (int k = 0; k < 2; ++k) {
            acc_row r = {.value = U / c0,
                         .error = k ? fabs((speed - still) - U) / fabs(U)
                                    : fabs(speed - (c0 + U)) / (c0 + U),
                         .reference = k ? U : c0 + U,
                         .ms_per_s = 1e3 * tm.wall / (frames / 60.0),
                         .ms_per_step = 1e3 * tm.wall / frames,
                         .cpu_ms_per_s = 1e3 * tm.cpu / (frames / 60.0),
                         .cpu_ms_per_step = 1e3 * tm.cpu / frames,
                         .size = 1024.0 * 4,
                         .threads = 1};
            snprintf(r.study, sizeof r.study, "waves");
            snprintf(r.knob, sizeof r.knob, "current_u_over_c");
            snprintf(r.config, sizeof r.config,
                     "1024x4 cells of 5 mm, c 0.5 m/s, 16 cells a wavelength, 1/60 s steps");
            snprintf(r.metric, sizeof r.metric,
                     k ? "speed added by the current vs U" : "packet speed rel. error vs c + U");
            if (acc_add(c, &r) != 0)
                return -1;
        }
    }
    acc_note(c,
             "- current: the packet's still-water speed is %.4f m/s (c = 0.5 m/s, 16 cells a "
             "wavelength): the rows' error against c + U holds that lag of the grid; the speed "
             "added by the current is measured against it.",
             still);
    return 0;
}

/* Each surface model the library has against real water, simulated: the
 * phase speed omega / k of the standing mode of a 64 x 4 reflecting basin
 * whose wavelength lambda is 32 cells (cos(4 pi (x + 1/2) / 64) along x),
 * measured from the zero crossings of its amplitude over 4.5 periods, at a
 * uniform depth d (wave_speed sqrt(g d), as ms_surface_speed_from_depth
 * sets it). Eq. 2's error is its model's (every wavelength at sqrt(g d))
 * plus its grid's, (k dx)^2 (1 - C^2) / 24 < 0.1 % at 32 cells; the
 * dispersive model's (the Airy relation with capillarity, its desc's
 * defaults g 9.81 and sigma / rho 7.28e-5 m^3/s^2) is float round-off and
 * the 0.2 % between that sigma / rho and real water's 7.295e-5. The surface
 * is made from its desc (the public API): the case needs no sim. */
#define WM_CELLS 64
#define WM_MODE 4 /* WM_CELLS * 2 / WM_MODE = 32 cells per wavelength */

static ms_surface *model_surface(ms_surface_model model, int nx, int ny, double dx, double depth)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = nx;
    d.ny = ny;
    d.dx = (float)dx;
    d.wave_speed = (float)sqrt(9.81 * depth);
    d.damping = 1.0f;
    d.boundary = MS_BOUNDARY_REFLECT;
    d.model = model;
    d.max_substeps = 10000000;
    ms_surface *s = NULL;
    if (ms_surface_create(&d, &s) != MS_OK) {
        tool_error("accuracy: water models: %s", ms_last_error());
        return NULL;
    }
    return s;
}

/* The model's angular frequency of that mode (rad/s) into *omega; omega_guess
 * sets the sampling (40 samples a period). */
static int model_omega(ms_surface_model model, double lambda, double depth, double omega_guess,
                       double *omega)
{
    const int nx = WM_CELLS, ny = 4;
    const double dx = lambda * WM_MODE / (2.0 * WM_CELLS);
    ms_surface *s = model_surface(model, nx, ny, dx, depth);
    if (!s)
        return -1;
    float f[WM_CELLS * 4];
    double norm = 0;
    for (int y = 0; y < ny; ++y)
        for (int x = 0; x < nx; ++x) {
            double v = cos(WM_MODE * PI * (x + 0.5) / nx);
            f[y * nx + x] = (float)v;
            norm += v * v;
        }
    ms_surface_set_height(s, f);
    ms_surface_info info = ms_surface_info_init();
    ms_surface_get_info(s, &info);
    const float dt = (float)fmin(2 * PI / omega_guess / 40, info.max_dt);
    const int steps = (int)ceil(4.5 * 2 * PI / omega_guess / dt);
    double prev = 1.0, t_first = -1, t_last = -1;
    int crossings = 0;
    for (int i = 1; i <= steps; ++i) {
        if (ms_surface_step(s, dt) != MS_OK) {
            tool_error("accuracy: water models: %s", ms_last_error());
            ms_surface_destroy(s);
            return -1;
        }
        const float *h = ms_surface_height(s, NULL, NULL);
        double a = 0;
        for (int j = 0; j < nx * ny; ++j)
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
    ms_surface_destroy(s);
    if (crossings < 2) {
        tool_error("accuracy: water models: the mode at %g m did not oscillate", lambda);
        return -1;
    }
    *omega = PI * (crossings - 1) / (t_last - t_first);
    return 0;
}

/* ms_surface_step's cost for one model: a 256 x 256 grid of 1 cm cells at
 * the depth, stepped at its largest stable sub-step; blocks of 16
 * sub-steps, the least of acc_repeats (a step's cost does not depend on
 * the heights). Into r: CPU and wall ms per sub-step and per simulated
 * second, the cells. */
typedef struct model_block {
    ms_surface *s;
    float dt;
} model_block;

static ms_status model_steps(void *arg)
{
    const model_block *b = arg;
    for (int i = 0; i < 16; ++i) {
        ms_status st = ms_surface_step(b->s, b->dt);
        if (st != MS_OK)
            return st;
    }
    return MS_OK;
}

static int model_cost(ms_surface_model model, double depth, acc_row *r)
{
    const int N = 256;
    ms_surface *s = model_surface(model, N, N, 0.01, depth);
    if (!s)
        return -1;
    float *h = malloc(sizeof(float) * N * N);
    if (!h) {
        ms_surface_destroy(s);
        return -1;
    }
    for (int y = 0; y < N; ++y)
        for (int x = 0; x < N; ++x)
            h[y * N + x] =
                (float)(1e-3 * cos(3 * PI * (x + 0.5) / N) * cos(5 * PI * (y + 0.5) / N));
    ms_surface_set_height(s, h);
    free(h);
    ms_surface_info in0 = ms_surface_info_init(), in1 = ms_surface_info_init();
    ms_surface_get_info(s, &in0);
    model_block b = {s, in0.max_dt};
    acc_timer tm = {0};
    /* one block untimed first: the transforms' plans and the caches warm */
    ms_status st = model_steps(&b);
    ms_surface_get_info(s, &in0);
    for (int k = 0; st == MS_OK && k < 4; ++k)
        st = acc_repeat(&tm, model_steps, &b);
    ms_surface_get_info(s, &in1);
    ms_surface_destroy(s);
    if (st != MS_OK) {
        tool_error("accuracy: water models: %s", ms_last_error());
        return -1;
    }
    /* 4 blocks counted (the least of each block's repeats) */
    long sub = (in1.substeps - in0.substeps) / acc_repeats;
    double sim_s = (in1.time - in0.time) / acc_repeats;
    r->cpu_ms_per_step = 1e3 * tm.cpu / (double)sub;
    r->ms_per_step = 1e3 * tm.wall / (double)sub;
    r->cpu_ms_per_s = 1e3 * tm.cpu / sim_s;
    r->ms_per_s = 1e3 * tm.wall / sim_s;
    r->size = (double)N * N;
    return 0;
}

int study_water_models(acc_ctx *c)
{
    c->cost_method = ACC_BY_BLOCK;
    static const double depths[] = {0.02, 0.1, 1.0};
    static const ms_surface_model models[] = {MS_SURFACE_MODEL_WAVE, MS_SURFACE_MODEL_DISPERSIVE};
    static const char *const knob[] = {"lambda_m_model_wave", "lambda_m_model_dispersive"};
    const double g = 9.81, sigma = 0.0728, rho = 998.0, T = 7.28e-5; /* T: the desc's */
    int npts = c->quick ? 9 : 41;
    for (int di = 0; di < 3; ++di) {
        const double d = depths[di];
        for (int mi = 0; mi < 2; ++mi) {
            acc_row r = {.threads = 1};
            if (model_cost(models[mi], d, &r) != 0)
                return -1;
            snprintf(r.study, sizeof r.study, "water");
            snprintf(r.knob, sizeof r.knob, "%s", knob[mi]);
            char dep[16];
            snprintf(dep, sizeof dep, "%g", d);
            snprintf(r.metric, sizeof r.metric, "simulated phase speed rel. error, depth %.5s m",
                     dep);
            for (int i = 0; i < npts; ++i) {
                double lambda = 1e-3 * pow(1e4, (double)i / (npts - 1)); /* 1 mm .. 10 m */
                double k = 2 * PI / lambda;
                double creal = sqrt((g * k + sigma * k * k * k / rho) * tanh(k * d)) / k;
                double guess = mi ? sqrt((g * k + T * k * k * k) * tanh(k * d)) : k * sqrt(g * d);
                double w;
                if (model_omega(models[mi], lambda, d, guess, &w) != 0)
                    return -1;
                r.value = lambda;
                r.error = fabs(w / k - creal) / creal;
                r.reference = creal;
                snprintf(r.config, sizeof r.config, "%s, depth %g m, 32 cells per wavelength",
                         mi ? "dispersive" : "wave (eq. 2)", d);
                if (acc_add(c, &r) != 0)
                    return -1;
            }
        }
    }
    return 0;
}
