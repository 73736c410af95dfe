/* Study 2, SPH (eqs. 9-14), against experiment and hydrostatics:
 *  - the dam break of Martin & Moyce (1952): a column a wide and 2a high
 *    released at the end of a tank (a quasi-2D slab four particles thick);
 *    the surge front Z = x / a against T = t sqrt(2 g / a) over their 15
 *    points (their Table 2), and the residual column H = height / 2a at the
 *    wall against tau = t sqrt(g / a) (Table 6), each as the RMS of the
 *    relative error; against the particle count,
 *    the pressure law / solver, the sound speed and the time-step factor;
 *  - a column at rest: the pressure profile against rho0 g d (not for
 *    DFSPH, see study_sph_rest), the maximum compression (all particles)
 *    and the mean compression of the interior against g H / (2 c^2).
 * A solver that this build refuses (MS_ERR_UNSUPPORTED) is noted in the
 * report, not hidden.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"

/* Martin & Moyce (1952), n^2 = 2 (column 2a high, a wide): T, Z */
static const double mm[15][2] = {{0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67},
                                 {1.63, 1.89}, {1.83, 2.11}, {1.98, 2.33}, {2.20, 2.56},
                                 {2.32, 2.78}, {2.51, 3.00}, {2.65, 3.22}, {2.83, 3.44},
                                 {2.98, 3.67}, {3.11, 3.89}, {3.33, 4.11}};

/* Martin & Moyce (1952), Table 6, n^2 = 2: the residual column at the
 * wall, tau = t sqrt(g / a), H = height / (2 a). Their first 13 points
 * (tau <= 3.06, t <= 0.31 s for a = 0.1 m): the later ones, down to
 * H = 0.06 at tau = 7.4, would more than double every run. */
#define MM_H 13
static const double mmh[MM_H][2] = {{0.56, 0.94}, {0.77, 0.89}, {0.93, 0.83}, {1.08, 0.78},
                                    {1.28, 0.72}, {1.46, 0.67}, {1.66, 0.61}, {1.84, 0.56},
                                    {2.00, 0.50}, {2.21, 0.44}, {2.45, 0.39}, {2.70, 0.33},
                                    {3.06, 0.28}};

static const char *const law_names[] = {"ideal_gas", "tait", "dfsph"};

typedef struct dam_cfg {
    double spacing; /* m */
    int law;        /* index into law_names */
    double sound;   /* m/s: Tait's c0, or sqrt(k) of the ideal gas */
    double courant; /* 0: the default */
    double dfsph;   /* DFSPH's volume.max_density_error; 0: the default */
} dam_cfg;

/* y of a curve sampled at t[0..m-1] (t[0] = 0, the release) at x, linear
 * between samples; before the release the column is at rest (y[0]), past
 * the last sample the last value (the runs cover every shift searched). */
static double trace_at(const double *t, const double *y, int m, double x)
{
    if (x <= t[0])
        return y[0];
    int lo = 0, hi = m - 1;
    if (x >= t[hi])
        return y[hi];
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (t[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return y[lo] + (y[hi] - y[lo]) * (x - t[lo]) / (t[hi] - t[lo]);
}

/* RMS of the relative error of y(T - t0) against the points ref[k] = (T, Y). */
static double trace_rms(const double *t, const double *y, int m, const double (*ref)[2], int nref,
                        double t0)
{
    double e2 = 0;
    for (int k = 0; k < nref; ++k) {
        double e = (trace_at(t, y, m, ref[k][0] - t0) - ref[k][1]) / ref[k][1];
        e2 += e * e;
    }
    return sqrt(e2 / nref);
}

/* The time shift t0 in [-SHIFT_MAX, SHIFT_MAX] (dimensionless time, steps
 * of 0.001) whose y(T - t0) lies closest to the points, and that RMS.
 * A constant lag is what a release that is not instantaneous (the
 * experiment's gate or diaphragm) would leave: the shifted error is what
 * remains of the shape. */
#define SHIFT_MAX 0.5
static double best_shift(const double *t, const double *y, int m, const double (*ref)[2], int nref,
                         double *rms)
{
    double best = 0, br = INFINITY;
    for (int i = -500; i <= 500; ++i) {
        double t0 = 0.001 * i, r = trace_rms(t, y, m, ref, nref, t0);
        if (r < br) {
            br = r;
            best = t0;
        }
    }
    *rms = br;
    return best;
}

/* Least-squares slope dy/dT over the samples with lo <= T <= hi. */
static double slope(const double *t, const double *y, int m, double lo, double hi)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int k = 0;
    for (int i = 0; i < m; ++i)
        if (t[i] >= lo && t[i] <= hi) {
            sx += t[i];
            sy += y[i];
            sxx += t[i] * t[i];
            sxy += t[i] * y[i];
            ++k;
        }
    return k > 1 ? (k * sxy - sx * sy) / (k * sxx - sx * sx) : NAN;
}

/* The late front: Martin & Moyce's points from T = 2.5 on (their last
 * six, up to Z = 4.11, before the far wall at Z = 5). Ritter's inviscid
 * shallow-water solution runs its front at 2 sqrt(g H0) with H0 = 2a, in
 * these units dZ/dT = 2 sqrt(2 g a) / (a sqrt(2 g / a)) = 2. */
#define LATE_T 2.5
#define RITTER 2.0

/* Row r again with another metric, error and reference; 0 on success. */
static int add_metric(acc_ctx *c, acc_row *r, const char *metric, double error, double reference)
{
    snprintf(r->metric, sizeof r->metric, "%s", metric);
    r->error = error;
    r->reference = reference;
    return acc_add(c, r);
}

/* The dam break of cfg; 1 when the build refuses the solver (nothing
 * added), 0 with rows added, -1 on a failure. Rows: the front Z(T) and the
 * column H(tau) RMS errors against Martin & Moyce (1952); the same after
 * the best time shift of each (and that shift for the front); the late
 * front speed over Ritter's; the largest compression. */
static int dam_break(acc_ctx *c, const char *knob, double value, const dam_cfg *cfg)
{
    const double a = 0.1, s = cfg->spacing, g = 9.81;
    char json[1024], law[64], snd[64], cou[64], lim[64];
    snprintf(json, sizeof json,
             "{\"name\": \"accuracy-dam-break\", \"frame_dt\": 0.002, \"threads\": 1,"
             " \"domain\": {\"min\": [0, 0, 0], \"max\": [%.9g, %.9g, %.9g]},"
             " \"volume\": {\"spacing\": %.9g, \"smoothing_length\": %.9g, \"viscosity\": 1.0,"
             "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [%.9g, %.9g, %.9g]}]}}",
             5 * a, 4 * s, 2.5 * a, s, 2 * s, a, 4 * s, 2 * a);
    snprintf(law, sizeof law, "volume.pressure=%s", law_names[cfg->law]);
    if (cfg->law == 0)
        snprintf(snd, sizeof snd, "volume.gas_constant=%.9g", cfg->sound * cfg->sound);
    else
        snprintf(snd, sizeof snd, "volume.sound_speed=%.9g", cfg->sound);
    snprintf(cou, sizeof cou, "volume.courant=%.9g", cfg->courant > 0 ? cfg->courant : 0.4);
    snprintf(lim, sizeof lim, "volume.max_density_error=%.9g", cfg->dfsph);
    const char *sets[] = {law, snd, cou, cfg->dfsph > 0 ? lim : NULL, NULL};
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    ms_status st = acc_sim(json, sets, &sc, &sim);
    if (st == MS_ERR_UNSUPPORTED) {
        char line[600];
        snprintf(line, sizeof line, "%s", ms_last_error());
        acc_note(c, "- sph: pressure solver `%s` is not in this build (%s): no %s row.",
                 law_names[cfg->law], line, knob);
        return 1;
    }
    if (st != MS_OK)
        return -1;
    ms_volume *v = ms_sim_volume(sim);
    int n = ms_volume_count(v);
    /* frames of 2 ms up to the 2 s guard, and the column at rest */
    enum { FRAMES = 1002 };
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    double *tr = malloc(sizeof(double) * 4 * FRAMES);
    if (!p || !tr) {
        free(p);
        free(tr);
        acc_free(sc, sim);
        tool_error("accuracy: dam break: out of memory");
        return -1;
    }
    /* the traces: T and Z(T), tau and H(tau), from the column at rest */
    double *tT = tr, *tZ = tr + FRAMES, *tt = tr + 2 * FRAMES, *tH = tr + 3 * FRAMES;
    tT[0] = tt[0] = 0;
    tZ[0] = tH[0] = 1;
    int m = 1, rc = 0;
    const double tscale = sqrt(2.0 * g / a), hscale = sqrt(g / a);
    double maxc = 0;
    acc_timer tm = {0};
    /* until both curves pass their last point by the largest shift */
    while (tT[m - 1] < mm[14][0] + SHIFT_MAX || tt[m - 1] < mmh[MM_H - 1][0] + SHIFT_MAX) {
        ms_status sst = acc_step(&tm, sim, 0.002f);
        if (sst != MS_OK) {
            tool_error("accuracy: dam break: %s", ms_last_error());
            rc = -1;
            break;
        }
        ms_volume_get_particles(v, p, NULL);
        /* the front: the farthest particle; the column: the highest of
         * the layer at the wall (x < s, its centres at s / 2) */
        double xf = 0, zc = 0;
        for (int i = 0; i < n; ++i) {
            xf = fmax(xf, p[3 * i]);
            if (p[3 * i] < s)
                zc = fmax(zc, p[3 * i + 2]);
        }
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(v, &in);
        maxc = fmax(maxc, in.max_density_error);
        if (m == FRAMES) {
            tool_error("accuracy: dam break: the front never reached Z = 4.11");
            rc = -1;
            break;
        }
        tT[m] = in.time * tscale;
        tZ[m] = (xf + 0.5 * s) / a;
        tt[m] = in.time * hscale;
        tH[m] = (zc + 0.5 * s) / (2 * a);
        ++m;
    }
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    free(p);
    acc_free(sc, sim);
    if (rc != 0) {
        free(tr);
        return rc;
    }
    /* the curves of the runs at the law's defaults, for the overlay plots
     * against Martin & Moyce's points (every other frame, 4 ms) */
    if (!strncmp(knob, "law_", 4)) {
        static const char *const names[] = {"ideal gas", "Tait", "DFSPH"};
        acc_trace(c, "# front Z(T): %s, %d particles\n", names[cfg->law], n);
        for (int i = 0; i < m; i += 2)
            acc_trace(c, "%.4f %.4f\n", tT[i], tZ[i]);
        acc_trace(c, "\n\n# column H(tau): %s, %d particles\n", names[cfg->law], n);
        for (int i = 0; i < m; i += 2)
            acc_trace(c, "%.4f %.4f\n", tt[i], tH[i]);
        acc_trace(c, "\n\n");
    }
    /* the errors: Z(T) and H(tau) interpolated linearly between frames */
    double ez = trace_rms(tT, tZ, m, mm, 15, 0), eh = trace_rms(tt, tH, m, mmh, MM_H, 0);
    double ez0, eh0, t0 = best_shift(tT, tZ, m, mm, 15, &ez0),
                     h0 = best_shift(tt, tH, m, mmh, MM_H, &eh0);
    double late = slope(tT, tZ, m, LATE_T, mm[14][0]);
    /* the experiment's own late slope: its points from LATE_T on */
    double xs[15], ys[15];
    int nl = 0;
    for (int k = 0; k < 15; ++k)
        if (mm[k][0] >= LATE_T) {
            xs[nl] = mm[k][0];
            ys[nl++] = mm[k][1];
        }
    double late_exp = slope(xs, ys, nl, LATE_T, mm[14][0]);
    /* the signed error at each of their points: the shape of the gap */
    char shape[256] = "";
    for (int k = 0; k < 15; k += 2) {
        size_t u = strlen(shape);
        snprintf(shape + u, sizeof shape - u, "%s%+.1f", k ? " " : "",
                 100 * (trace_at(tT, tZ, m, mm[k][0]) - mm[k][1]) / mm[k][1]);
    }
    /* a note per run of the particle and law knobs (the others vary
     * what does not move the front) */
    if (!strcmp(knob, "particles") || !strncmp(knob, "law_", 4))
        acc_note(c,
                 "- dam break, %s, %s c=%g m/s, courant %g, %d particles: Z_sim - Z_exp at T = "
                 "0.41, 1.19, 1.63, 1.98, 2.32, 2.65, 2.98, 3.33: %s %%; best time shift T0 = "
                 "%.3f (%.1f ms), after it %.1f %% RMS (%.1f %% without); late front dZ/dT %.2f "
                 "(experiment %.2f, Ritter 2); column H: shift %.3f, %.1f %% RMS after it "
                 "(%.1f %% without).",
                 knob, law_names[cfg->law], cfg->sound, cfg->courant > 0 ? cfg->courant : 0.4, n,
                 shape, t0, 1e3 * t0 / tscale, 100 * ez0, 100 * ez, late, late_exp, h0, 100 * eh0,
                 100 * eh);
    free(tr);
    acc_row r = {.value = value < 0 ? n : value,
                 .ms_per_s = 1e3 * tm.wall / in.time,
                 .ms_per_step = 1e3 * tm.wall / in.substeps,
                 .cpu_ms_per_s = 1e3 * tm.cpu / in.time,
                 .cpu_ms_per_step = 1e3 * tm.cpu / in.substeps,
                 .size = n,
                 .threads = 1};
    snprintf(r.study, sizeof r.study, "sph");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    /* the settings only (the check of the committed study finds a row by
     * them): what the run gave is in the metrics */
    if (cfg->law == 2)
        snprintf(r.config, sizeof r.config, "dfsph max density error %g, courant %g, %d particles",
                 cfg->dfsph > 0 ? cfg->dfsph : 0.001, cfg->courant > 0 ? cfg->courant : 0.4, n);
    else
        snprintf(r.config, sizeof r.config, "%s c=%g m/s, courant %g, %d particles",
                 law_names[cfg->law], cfg->sound, cfg->courant > 0 ? cfg->courant : 0.4, n);
    const double zref = 4.11, href = mmh[MM_H - 1][1];
    if (add_metric(c, &r, "dam-break front Z rel. RMS error", ez, zref) ||
        add_metric(c, &r, "dam-break column H rel. RMS error", eh, href) ||
        /* the compression the run reached: weakly compressible SPH's price */
        add_metric(c, &r, "dam-break max compression", maxc, 0) ||
        add_metric(c, &r, "dam-break front Z RMS error after time shift", ez0, zref) ||
        /* positive: the simulated front runs ahead of the experiment's */
        add_metric(c, &r, "dam-break front Z best time shift T0", t0, 0) ||
        add_metric(c, &r, "dam-break column H RMS error after time shift", eh0, href) ||
        /* against Ritter's inviscid 2; the reference: the experiment's ratio */
        add_metric(c, &r, "dam-break late front dZ/dT / Ritter speed", late / RITTER,
                   late_exp / RITTER))
        return -1;
    return 0;
}

int study_sph_particles(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    /* 4 layers thick: 800, ~1.6k, 3.2k, ~6.5k particles (12.8k and ~25k:
     * study_sph_particles_25k) */
    static const double full[] = {0.01, 0.007, 0.005, 0.0035}, quick[] = {0.01, 0.007};
    const double *sp = c->quick ? quick : full;
    int n = c->quick ? 2 : 4;
    for (int i = 0; i < n; ++i) {
        dam_cfg cfg = {.spacing = sp[i], .law = 1, .sound = 20};
        if (dam_break(c, "particles", -1, &cfg) < 0) /* value: the count */
            return -1;
    }
    return 0;
}

/* The same knob at ~51k and at ~64k particles (4 * 0.02 m^2 / s^2 of
 * them), a case each: each takes about as long as every other case
 * together, so `--jobs` runs them beside the rest. --quick: one 800
 * particle run, so the cases are exercised. */
static int particles_at(acc_ctx *c, double spacing)
{
    c->cost_method = ACC_BY_FRAME;
    dam_cfg cfg = {.spacing = c->quick ? 0.01 : spacing, .law = 1, .sound = 20};
    return dam_break(c, "particles", -1, &cfg) < 0 ? -1 : 0; /* value: the count */
}

/* 12.8k and ~25k particles: a case of their own, beside the rest, as the
 * two below. */
int study_sph_particles_25k(acc_ctx *c)
{
    if (c->quick)
        return particles_at(c, 0.01);
    return particles_at(c, 0.0025) != 0 ? -1 : particles_at(c, 0.00177);
}

int study_sph_particles_51k(acc_ctx *c)
{
    return particles_at(c, 0.00125);
}

int study_sph_particles_64k(acc_ctx *c)
{
    return particles_at(c, 0.001118);
}

/* The particle counts of the solver sweeps: 4 layers thick, 800, ~1.6k
 * and 3.2k particles; --quick runs the first, at the same settings. */
static const double sweep_spacing[] = {0.01, 0.007, 0.005};
#define SWEEP_COUNTS(c) ((c)->quick ? 1 : 3)

int study_sph_laws(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    /* the experiment's points first: the overlay plots' blocks 0 and 1 */
    acc_trace(c, "# front Z(T): Martin & Moyce (1952)\n");
    for (int k = 0; k < 15; ++k)
        acc_trace(c, "%.2f %.2f\n", mm[k][0], mm[k][1]);
    acc_trace(c, "\n\n# column H(tau): Martin & Moyce (1952)\n");
    for (int k = 0; k < MM_H; ++k)
        acc_trace(c, "%.2f %.2f\n", mmh[k][0], mmh[k][1]);
    acc_trace(c, "\n\n");
    for (int i = 0; i < SWEEP_COUNTS(c); ++i)
        for (int law = 0; law < 3; ++law) {
            dam_cfg cfg = {.spacing = sweep_spacing[i], .law = law, .sound = 20};
            if (dam_break(c,
                          law == 0   ? "law_ideal_gas"
                          : law == 1 ? "law_tait"
                                     : "law_dfsph",
                          law, &cfg) < 0)
                return -1;
        }
    return 0;
}

/* The stiffness of the weakly compressible laws: Tait's c0 and the ideal
 * gas's sqrt(k); compression ~ g H / c^2 against a time step ~ h / c. */
int study_sph_sound(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {10, 15, 20, 30, 40}, quick[] = {10, 40};
    const double *cs = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int law = 0; law < 2; ++law)
        for (int k = 0; k < SWEEP_COUNTS(c); ++k)
            for (int i = 0; i < n; ++i) {
                dam_cfg cfg = {.spacing = sweep_spacing[k], .law = law, .sound = cs[i]};
                if (dam_break(c, law ? "sound_speed_tait" : "sound_speed_ideal_gas", cs[i], &cfg) <
                    0)
                    return -1;
            }
    return 0;
}

/* DFSPH's own knob: the average density error its pressure solve stops
 * at (volume.max_density_error, default 0.1 %). */
int study_sph_dfsph(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {0.01, 0.003, 0.001, 0.0003}, quick[] = {0.01, 0.001};
    const double *es = c->quick ? quick : full;
    int n = c->quick ? 2 : 4;
    for (int k = 0; k < SWEEP_COUNTS(c); ++k)
        for (int i = 0; i < n; ++i) {
            dam_cfg cfg = {.spacing = sweep_spacing[k], .law = 2, .sound = 20, .dfsph = es[i]};
            if (dam_break(c, "max_density_error_dfsph", es[i], &cfg) < 0)
                return -1;
        }
    return 0;
}

/* The time-step factor of every law, at 800 and 3.2k particles. */
int study_sph_courant(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {0.1, 0.2, 0.3, 0.4, 0.5}, quick[] = {0.2, 0.5};
    static const double spacing[] = {0.01, 0.005};
    static const char *const knob[] = {"courant_ideal_gas", "courant_tait", "courant_dfsph"};
    const double *cr = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int law = 0; law < 3; ++law)
        for (int k = 0; k < (c->quick ? 1 : 2); ++k)
            for (int i = 0; i < n; ++i) {
                if (c->quick && law != 1)
                    continue;
                dam_cfg cfg = {.spacing = spacing[k], .law = law, .sound = 20, .courant = cr[i]};
                if (dam_break(c, knob[law], cr[i], &cfg) < 0)
                    return -1;
            }
    return 0;
}

/* Pressure at rest, from the particles: the density of eq. 9 with the
 * spiky kernel of eq. 11 (the library's default density kernel, Mueller et
 * al. 2003: W = 15 / (pi h^6) (h - r)^3), summed here from the public
 * positions and mass, and the pressure law of the run. Only particles at
 * least h from every wall and from the free surface count (there the sum
 * is complete without the walls' share). Slab averages against rho0 g d.
 *
 * Averaged over a window of samples, not read once: a column "at rest"
 * still rings in its vertical breathing mode (period 4 H / c, 56 ms here,
 * hardly damped by eq. 14's viscosity, which acts on velocity differences
 * only). Measured (ideal gas, 1400 particles, frames 90 to 100 of 20 ms):
 * the mean vertical velocity swings by +-2.4 cm/s and a single snapshot's
 * pressure slope dp/dd by 0.74 to 1.31 rho0 g (rho0 c u = 36 % of
 * rho0 g H), while their mean is 1.01: a snapshot's error was the phase of
 * that mode at 1.5 s, not the pressure law's. */
typedef struct rest_acc {
    double ps[64], ds[64]; /* pressure and depth sums per slab of h / 2 */
    long cnt[64];
    double sum_c; /* compression rho/rho0 - 1 summed over the samples */
    long m;
    double slope_lo, slope_hi; /* one sample's fitted dp/dd / (rho0 g): the range */
    double vz_max;             /* the largest |mean vertical velocity| of a sample */
    double top;                /* the free surface, summed over the samples */
    int samples;
} rest_acc;

static int by_z(const void *a, const void *b)
{
    float za = ((const float *)a)[2], zb = ((const float *)b)[2];
    return (za > zb) - (za < zb);
}

/* One sample of the column into o: p and u are scratch of 3 n floats. */
static void rest_sample(ms_volume *v, int law, double h, double cs, float *p, float *u, rest_acc *o)
{
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    int n = ms_volume_count(v);
    ms_volume_get_particles(v, p, u);
    const double rho0 = 1000, g = 9.81, W0 = 15.0 / (3.14159265358979323846 * pow(h, 6));
    double level = 0, vz = 0;
    for (int i = 0; i < n; ++i) {
        level = fmax(level, p[3 * i + 2]);
        vz += u[3 * i + 2];
    }
    vz /= n;
    /* sorted by height, each particle sums only the window |dz| < h */
    qsort(p, (size_t)n, 3 * sizeof(float), by_z);
    /* the free surface: half a spacing above the top layer of particles */
    double top = level + 0.5 * h / 2;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int lo = 0, k = 0;
    for (int i = 0; i < n; ++i) {
        const float *a = p + 3 * i;
        while (p[3 * lo + 2] < a[2] - h)
            ++lo;
        if (a[0] < h || a[0] > 0.2 - h || a[1] < h || a[1] > 0.2 - h || a[2] < h ||
            a[2] > level - h)
            continue;
        double rho = 0;
        for (int j = lo; j < n && p[3 * j + 2] < a[2] + h; ++j) {
            double dx = a[0] - p[3 * j], dy = a[1] - p[3 * j + 1], dz = a[2] - p[3 * j + 2];
            double r = sqrt(dx * dx + dy * dy + dz * dz);
            if (r < h)
                rho += in.particle_mass * W0 * (h - r) * (h - r) * (h - r);
        }
        double pr =
            law == 0 ? cs * cs * (rho - rho0) : rho0 * cs * cs / 7 * (pow(rho / rho0, 7) - 1);
        int b = (int)(a[2] / (0.5 * h));
        if (b >= 64)
            continue;
        double d = top - a[2], y = pr / (rho0 * g);
        o->ps[b] += pr;
        o->ds[b] += d;
        o->cnt[b]++;
        o->sum_c += rho / rho0 - 1;
        o->m++;
        sx += d;
        sy += y;
        sxx += d * d;
        sxy += d * y;
        ++k;
    }
    if (k > 1) {
        double sl = (k * sxy - sx * sy) / (k * sxx - sx * sx);
        o->slope_lo = o->samples ? fmin(o->slope_lo, sl) : sl;
        o->slope_hi = o->samples ? fmax(o->slope_hi, sl) : sl;
    }
    o->vz_max = fmax(o->vz_max, fabs(vz));
    o->top += top;
    o->samples++;
}

/* The RMS over the slabs of (mean p - rho0 g mean d) / (rho0 g H). */
static double rest_error(const rest_acc *o, double H)
{
    const double rho0 = 1000, g = 9.81;
    double e2 = 0;
    int nb = 0;
    for (int b = 0; b < 64; ++b) {
        if (!o->cnt[b])
            continue;
        double want = rho0 * g * o->ds[b] / o->cnt[b], got = o->ps[b] / o->cnt[b];
        e2 += (got - want) * (got - want);
        ++nb;
    }
    return nb ? sqrt(e2 / nb) / (rho0 * g * H) : NAN;
}

/* A column at rest: the settings of one run. */
typedef struct rest_cfg {
    double spacing; /* m */
    int law;        /* index into law_names */
    double sound;   /* m/s: Tait's c0, or sqrt(k) of the ideal gas */
    double courant; /* 0: the default 0.4 */
    double dfsph;   /* DFSPH's volume.max_density_error; 0: the default */
} rest_cfg;

/* A column H high at rest for 1.5 s, then sampled every 5 ms for 0.5 s
 * (nine periods of its breathing mode): hydrostatic pressure and the
 * compression it costs, against rho0 g d and g d / c^2. The cost is that
 * of the 0.5 s at rest (the settling from the filled lattice is not
 * timed). Rows under knob, its value (< 0: the particle count); 1 when
 * the build refuses the solver (noted once, nothing added), 0 with rows
 * added, -1 on a failure. */
static int rest_run(acc_ctx *c, const char *knob, double value, const rest_cfg *cfg)
{
    const double s = cfg->spacing, H = 0.28, cs = cfg->sound, g = 9.81;
    const double cou = cfg->courant > 0 ? cfg->courant : 0.4;
    const double lim = cfg->dfsph > 0 ? cfg->dfsph : 0.001;
    const int law = cfg->law;
    char json[1024], lawset[64], couset[64], limset[64];
    snprintf(json, sizeof json,
             "{\"name\": \"accuracy-rest\", \"frame_dt\": 0.02, \"threads\": 1,"
             " \"domain\": {\"min\": [0, 0, 0], \"max\": [0.2, 0.2, 0.4]},"
             " \"volume\": {\"spacing\": %.9g, \"smoothing_length\": %.9g,"
             "   \"viscosity\": 5.0, \"gas_constant\": %.9g, \"sound_speed\": %.9g,"
             "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.2, 0.2, %.9g]}]}}",
             s, 2 * s, cs * cs, cs, H);
    snprintf(lawset, sizeof lawset, "volume.pressure=%s", law_names[law]);
    snprintf(couset, sizeof couset, "volume.courant=%.9g", cou);
    snprintf(limset, sizeof limset, "volume.max_density_error=%.9g", lim);
    const char *sets[] = {lawset, couset, law == 2 ? limset : NULL, NULL};
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    ms_status st = acc_sim(json, sets, &sc, &sim);
    if (st == MS_ERR_UNSUPPORTED) {
        acc_note(c, "- sph: pressure solver `%s` is not in this build: no %s rows.", law_names[law],
                 knob);
        return 1;
    }
    if (st != MS_OK)
        return -1;
    ms_volume *v = ms_sim_volume(sim);
    int np = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 6 * (size_t)np);
    rest_acc *ra = calloc(1, sizeof *ra);
    if (!p || !ra) {
        free(p);
        free(ra);
        acc_free(sc, sim);
        tool_error("accuracy: rest: out of memory");
        return -1;
    }
    acc_timer tm = {0};
    double t_rest = 0; /* s: the start of the timed window */
    long sub_rest = 0;
    /* 75 frames of 20 ms to settle, then 100 of 5 ms sampled and timed */
    for (int f = 0; f < 175; ++f) {
        if (f == 75) {
            ms_volume_info in = ms_volume_info_init();
            ms_volume_get_info(v, &in);
            t_rest = in.time;
            sub_rest = in.substeps;
        }
        ms_status sst = f < 75 ? ms_sim_step(sim, 0.02f) : acc_step(&tm, sim, 0.005f);
        if (sst != MS_OK) {
            tool_error("accuracy: rest: %s", ms_last_error());
            free(p);
            free(ra);
            acc_free(sc, sim);
            return -1;
        }
        if (f >= 75)
            rest_sample(v, law, 2 * s, cs, p, p + 3 * (size_t)np, ra);
    }
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    free(p);
    acc_free(sc, sim);
    double mean_c = ra->m ? ra->sum_c / (double)ra->m : NAN;
    double p_err = rest_error(ra, H);
    /* the column's height against hydrostatics: the height it lost (the
     * mean of the samples' surfaces against the filled height n s^3 /
     * area) beside what the law's compression g H / (2 c^2) asks and what
     * eq. 9's density shows; a note for the particle sweep only */
    double hf = np * s * s * s / (0.2 * 0.2), shrink = (hf - ra->top / ra->samples) / hf;
    if (!strncmp(knob, "rest_particles", 14)) {
        if (law == 2) /* no pressure law: its density and height only */
            acc_note(c,
                     "- rest, %s, %d particles: the column is %.2f %% shorter than filled; "
                     "the interior's eq. 9 compression is %.2f %% (target 0).",
                     law_names[law], np, 100 * shrink, 100 * mean_c);
        else
            acc_note(c,
                     "- rest, %s, %d particles: one 5 ms sample's pressure slope dp/dd is "
                     "%.2f to %.2f rho0 g (the breathing mode: mean vertical velocity up "
                     "to %.1f cm/s); averaged over 0.5 s the profile is %.1f %% RMS off "
                     "rho0 g d. The column is %.2f %% shorter than filled; the interior's "
                     "eq. 9 compression is %.2f %% (hydrostatics: %.2f %% for both).",
                     law_names[law], np, ra->slope_lo, ra->slope_hi, 100 * ra->vz_max, 100 * p_err,
                     100 * shrink, 100 * mean_c, 100 * g * H / (2 * cs * cs));
    }
    free(ra);
    const double window = in.time - t_rest;
    acc_row r = {.value = value < 0 ? in.count : value,
                 .error = p_err,
                 .reference = 1000 * g * H,
                 .ms_per_s = 1e3 * tm.wall / window,
                 .ms_per_step = 1e3 * tm.wall / (double)(in.substeps - sub_rest),
                 .cpu_ms_per_s = 1e3 * tm.cpu / window,
                 .cpu_ms_per_step = 1e3 * tm.cpu / (double)(in.substeps - sub_rest),
                 .size = in.count,
                 .threads = 1};
    snprintf(r.study, sizeof r.study, "sph");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    /* the settings only (the check of the committed study finds a row by
     * them): what the run gave is in the metrics */
    if (law == 2)
        snprintf(r.config, sizeof r.config,
                 "dfsph at rest, spacing %g m, max density error %g, courant %g", s, lim, cou);
    else
        snprintf(r.config, sizeof r.config,
                 "%s at rest, spacing %g m, c=%g m/s (g H / c^2 = %.4f), courant %g",
                 law_names[law], s, cs, g * H / (cs * cs), cou);
    snprintf(r.metric, sizeof r.metric, "hydrostatic pressure RMS / (rho0 g H)");
    /* DFSPH solves for its pressure, no law of the density gives it, and
     * the public API has no particle pressure: a pressure from its density
     * would only restate its compression */
    if (law != 2 && acc_add(c, &r) != 0)
        return -1;
    /* the references: hydrostatics of the law; DFSPH's is its target, no
     * compression */
    r.error = in.max_density_error;
    r.reference = law == 2 ? 0 : g * H / (cs * cs);
    snprintf(r.metric, sizeof r.metric, "max compression at rest (all particles)");
    if (acc_add(c, &r) != 0)
        return -1;
    /* the average (eq. 9's density, particles h from walls and surface,
     * over the samples): hydrostatics gives g H / (2 c^2) over the column */
    r.error = mean_c;
    r.reference = law == 2 ? 0 : g * H / (2 * cs * cs);
    snprintf(r.metric, sizeof r.metric, "mean compression at rest (interior)");
    return acc_add(c, &r) != 0 ? -1 : 0;
}

/* The column at rest against the particle count (175 to 11.2k), each law
 * at c = 20 m/s and its defaults. */
int study_sph_rest(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {0.04, 0.02, 0.0133, 0.01}, quick[] = {0.04, 0.02};
    static const char *const knob[] = {"rest_particles_ideal_gas", "rest_particles_tait",
                                       "rest_particles_dfsph"};
    const double *sp = c->quick ? quick : full;
    int n = c->quick ? 2 : 4;
    for (int law = 0; law < 3; ++law)
        for (int i = 0; i < n; ++i) {
            rest_cfg cfg = {.spacing = sp[i], .law = law, .sound = 20};
            int rc = rest_run(c, knob[law], -1, &cfg);
            if (rc < 0)
                return -1;
            if (rc > 0)
                break;
        }
    return 0;
}

/* The at-rest particle counts of the knob sweeps: 175, ~700 and 1400
 * particles (each sweep's runs stay within a few CPU seconds); --quick
 * runs the first, at the same settings. */
static const double rest_spacing[] = {0.04, 0.025, 0.02};
#define REST_COUNTS(c) ((c)->quick ? 1 : 3)

/* The stiffness of the weakly compressible laws at rest: the compression
 * g H / (2 c^2) against a time step ~ h / c, as on the dam break. */
int study_sph_rest_sound(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {10, 15, 20, 30, 40}, quick[] = {10, 40};
    const double *cs = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int law = 0; law < 2; ++law)
        for (int k = 0; k < REST_COUNTS(c); ++k)
            for (int i = 0; i < n; ++i) {
                rest_cfg cfg = {.spacing = rest_spacing[k], .law = law, .sound = cs[i]};
                if (rest_run(c, law ? "rest_sound_speed_tait" : "rest_sound_speed_ideal_gas", cs[i],
                             &cfg) < 0)
                    return -1;
            }
    return 0;
}

/* DFSPH's own knob at rest: the average density error its solve stops at. */
int study_sph_rest_dfsph(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {0.01, 0.003, 0.001, 0.0003}, quick[] = {0.01, 0.001};
    const double *es = c->quick ? quick : full;
    int n = c->quick ? 2 : 4;
    for (int k = 0; k < REST_COUNTS(c); ++k)
        for (int i = 0; i < n; ++i) {
            rest_cfg cfg = {.spacing = rest_spacing[k], .law = 2, .sound = 20, .dfsph = es[i]};
            int rc = rest_run(c, "rest_max_density_error_dfsph", es[i], &cfg);
            if (rc < 0)
                return -1;
            if (rc > 0)
                return 0;
        }
    return 0;
}

/* The time-step factor of every law at rest. */
int study_sph_rest_courant(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    static const double full[] = {0.1, 0.2, 0.3, 0.4, 0.5}, quick[] = {0.2, 0.5};
    static const char *const knob[] = {"rest_courant_ideal_gas", "rest_courant_tait",
                                       "rest_courant_dfsph"};
    const double *cr = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int law = 0; law < 3; ++law) {
        int lacks = c->quick && law != 1; /* --quick: Tait only */
        for (int k = 0; k < REST_COUNTS(c) && !lacks; ++k)
            for (int i = 0; i < n && !lacks; ++i) {
                rest_cfg cfg = {
                    .spacing = rest_spacing[k], .law = law, .sound = 20, .courant = cr[i]};
                int rc = rest_run(c, knob[law], cr[i], &cfg);
                if (rc < 0)
                    return -1;
                lacks = rc > 0; /* the build lacks the solver: the next law */
            }
    }
    return 0;
}
