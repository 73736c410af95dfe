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
static const double mm[15][2] = {
    {0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89},
    {1.83, 2.11}, {1.98, 2.33}, {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00},
    {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}, {3.11, 3.89}, {3.33, 4.11}};

/* Martin & Moyce (1952), Table 6, n^2 = 2: the residual column at the
 * wall, tau = t sqrt(g / a), H = height / (2 a). Their first 13 points
 * (tau <= 3.06, t <= 0.31 s for a = 0.1 m): the later ones, down to
 * H = 0.06 at tau = 7.4, would more than double every run. */
#define MM_H 13
static const double mmh[MM_H][2] = {
    {0.56, 0.94}, {0.77, 0.89}, {0.93, 0.83}, {1.08, 0.78}, {1.28, 0.72},
    {1.46, 0.67}, {1.66, 0.61}, {1.84, 0.56}, {2.00, 0.50}, {2.21, 0.44},
    {2.45, 0.39}, {2.70, 0.33}, {3.06, 0.28}};

static const char *const law_names[] = {"ideal_gas", "tait", "dfsph"};

typedef struct dam_cfg {
    double spacing;  /* m */
    int law;         /* index into law_names */
    double sound;    /* m/s: Tait's c0, or sqrt(k) of the ideal gas */
    double courant;  /* 0: the default */
} dam_cfg;

/* The dam break of cfg; 1 when the build refuses the solver (nothing
 * added), 0 with a row added, -1 on a failure. */
static int dam_break(acc_ctx *c, const char *knob, double value, const dam_cfg *cfg)
{
    const double a = 0.1, s = cfg->spacing, g = 9.81;
    char json[1024], law[64], snd[64], cou[64];
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
    const char *sets[] = {law, snd, cou, NULL};
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
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    const double tscale = sqrt(2.0 * g / a), hscale = sqrt(g / a);
    double err2 = 0, tprev = 0, zprev = 1, wall = 0, maxc = 0;
    double herr2 = 0, hprev = 1;
    int k = 0, kh = 0, rc = 0;
    long frames = 0;
    while (k < 15 || kh < MM_H) {
        double w0 = tool_now();
        if (ms_sim_step(sim, 0.002f) != MS_OK) {
            tool_error("accuracy: dam break: %s", ms_last_error());
            rc = -1;
            break;
        }
        wall += tool_now() - w0;
        ++frames;
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
        double t = in.time * tscale, zf = (xf + 0.5 * s) / a;
        while (k < 15 && t >= mm[k][0]) {
            double zi = zprev + (zf - zprev) * (mm[k][0] - tprev) / (t - tprev);
            double e = (zi - mm[k][1]) / mm[k][1];
            err2 += e * e;
            k++;
        }
        /* H(tau), interpolated like Z(T); both start from the frame
         * before, the first from the column at rest (H = 1 at tau = 0) */
        double tau = in.time * hscale, hc = (zc + 0.5 * s) / (2 * a);
        double tauprev = tprev / tscale * hscale;
        while (kh < MM_H && tau >= mmh[kh][0]) {
            double hi = hprev + (hc - hprev) * (mmh[kh][0] - tauprev) / (tau - tauprev);
            double e = (hi - mmh[kh][1]) / mmh[kh][1];
            herr2 += e * e;
            kh++;
        }
        hprev = hc;
        tprev = t;
        zprev = zf;
        if (in.time > 2.0) {
            tool_error("accuracy: dam break: the front never reached Z = 4.11");
            rc = -1;
            break;
        }
    }
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    free(p);
    acc_free(sc, sim);
    if (rc != 0)
        return rc;
    acc_row r = {.value = value < 0 ? n : value, .error = sqrt(err2 / 15), .reference = 4.11,
                 .ms_per_s = 1e3 * wall / in.time, .ms_per_step = 1e3 * wall / in.substeps,
                 .size = n, .threads = 1};
    snprintf(r.study, sizeof r.study, "sph");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    snprintf(r.config, sizeof r.config, "%s c=%g m/s, courant %g, %d particles, %ld substeps",
             law_names[cfg->law], cfg->sound, cfg->courant > 0 ? cfg->courant : 0.4, n,
             in.substeps);
    snprintf(r.metric, sizeof r.metric, "dam-break front Z rel. RMS error");
    if (acc_add(c, &r) != 0)
        return -1;
    r.error = sqrt(herr2 / MM_H);
    r.reference = mmh[MM_H - 1][1];
    snprintf(r.metric, sizeof r.metric, "dam-break column H rel. RMS error");
    if (acc_add(c, &r) != 0)
        return -1;
    /* the compression the run reached: weakly compressible SPH's own price */
    r.error = maxc;
    r.reference = 0;
    snprintf(r.metric, sizeof r.metric, "dam-break max compression");
    return acc_add(c, &r);
}

int study_sph_particles(acc_ctx *c)
{
    /* 4 layers thick: 800, ~1.6k, 3.2k, ~6.5k, 12.8k, ~25k particles */
    static const double full[] = {0.01, 0.007, 0.005, 0.0035, 0.0025, 0.00177},
                        quick[] = {0.01, 0.007};
    const double *sp = c->quick ? quick : full;
    int n = c->quick ? 2 : 6;
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
    dam_cfg cfg = {.spacing = c->quick ? 0.01 : spacing, .law = 1, .sound = 20};
    return dam_break(c, "particles", -1, &cfg) < 0 ? -1 : 0; /* value: the count */
}

int study_sph_particles_51k(acc_ctx *c)
{
    return particles_at(c, 0.00125);
}

int study_sph_particles_64k(acc_ctx *c)
{
    return particles_at(c, 0.001118);
}

int study_sph_laws(acc_ctx *c)
{
    for (int law = 0; law < 3; ++law) {
        dam_cfg cfg = {.spacing = c->quick ? 0.01 : 0.005, .law = law, .sound = 20};
        if (dam_break(c, law == 0 ? "law_ideal_gas" : law == 1 ? "law_tait" : "law_dfsph", law,
                      &cfg) < 0)
            return -1;
    }
    return 0;
}

int study_sph_sound(acc_ctx *c)
{
    static const double full[] = {10, 15, 20, 30, 40}, quick[] = {10, 40};
    const double *cs = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int law = 0; law < 2; ++law)
        for (int i = 0; i < n; ++i) {
            dam_cfg cfg = {.spacing = c->quick ? 0.01 : 0.005, .law = law, .sound = cs[i]};
            if (dam_break(c, law ? "sound_speed_tait" : "sound_speed_ideal_gas", cs[i], &cfg) < 0)
                return -1;
        }
    return 0;
}

int study_sph_courant(acc_ctx *c)
{
    static const double full[] = {0.1, 0.2, 0.3, 0.4, 0.5}, quick[] = {0.2, 0.5};
    const double *cr = c->quick ? quick : full;
    int n = c->quick ? 2 : 5;
    for (int i = 0; i < n; ++i) {
        dam_cfg cfg = {.spacing = c->quick ? 0.01 : 0.005, .law = 1, .sound = 20,
                       .courant = cr[i]};
        if (dam_break(c, "courant", cr[i], &cfg) < 0)
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
 */
typedef struct rest_result {
    double p_err;        /* RMS of (p - rho0 g d) / (rho0 g H) over the slabs */
    double mean_c, max_c; /* mean and max compression rho/rho0 - 1 of those particles */
} rest_result;

static void rest_pressure(ms_volume *v, int law, double h, double H, double cs, rest_result *o)
{
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume_get_particles(v, p, NULL);
    const double rho0 = 1000, g = 9.81, W0 = 15.0 / (3.14159265358979323846 * pow(h, 6));
    double level = 0;
    for (int i = 0; i < n; ++i)
        level = fmax(level, p[3 * i + 2]);
    enum { SLABS = 64 };
    double ps[SLABS] = {0}, ds[SLABS] = {0}, sum_c = 0, max_c = 0;
    int cnt[SLABS] = {0}, m = 0;
    for (int i = 0; i < n; ++i) {
        const float *a = p + 3 * i;
        if (a[0] < h || a[0] > 0.2 - h || a[1] < h || a[1] > 0.2 - h || a[2] < h ||
            a[2] > level - h)
            continue;
        double rho = 0;
        for (int j = 0; j < n; ++j) {
            double dx = a[0] - p[3 * j], dy = a[1] - p[3 * j + 1], dz = a[2] - p[3 * j + 2];
            double r = sqrt(dx * dx + dy * dy + dz * dz);
            if (r < h)
                rho += in.particle_mass * W0 * (h - r) * (h - r) * (h - r);
        }
        double pr = law == 0 ? cs * cs * (rho - rho0)
                             : rho0 * cs * cs / 7 * (pow(rho / rho0, 7) - 1);
        int b = (int)(a[2] / (0.5 * h));
        if (b >= SLABS)
            continue;
        ps[b] += pr;
        ds[b] += a[2];
        cnt[b]++;
        sum_c += rho / rho0 - 1;
        max_c = fmax(max_c, rho / rho0 - 1);
        ++m;
    }
    /* the free surface: half a spacing above the top layer of particles */
    double top = level + 0.5 * h / 2, e2 = 0;
    int nb = 0;
    for (int b = 0; b < SLABS; ++b) {
        if (!cnt[b])
            continue;
        double z = ds[b] / cnt[b], want = rho0 * g * (top - z), got = ps[b] / cnt[b];
        e2 += (got - want) * (got - want);
        ++nb;
    }
    o->p_err = nb ? sqrt(e2 / nb) / (rho0 * g * H) : NAN;
    o->mean_c = m ? sum_c / m : NAN;
    o->max_c = max_c;
    free(p);
}

/* A column H high at rest for 1.5 s: hydrostatic pressure and the
 * compression it costs, against rho0 g d and g d / c^2. */
int study_sph_rest(acc_ctx *c)
{
    static const double full[] = {0.04, 0.02, 0.0133, 0.01}, quick[] = {0.04, 0.02};
    const double *sp = c->quick ? quick : full;
    int n = c->quick ? 2 : 4;
    for (int law = 0; law < 3; ++law)
        for (int i = 0; i < n; ++i) {
            const double s = sp[i], H = 0.28, cs = 20, g = 9.81;
            char json[1024], lawset[64];
            snprintf(json, sizeof json,
                     "{\"name\": \"accuracy-rest\", \"frame_dt\": 0.02, \"threads\": 1,"
                     " \"domain\": {\"min\": [0, 0, 0], \"max\": [0.2, 0.2, 0.4]},"
                     " \"volume\": {\"spacing\": %.9g, \"smoothing_length\": %.9g,"
                     "   \"viscosity\": 5.0, \"gas_constant\": %.9g, \"sound_speed\": %.9g,"
                     "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.2, 0.2, %.9g]}]}}",
                     s, 2 * s, cs * cs, cs, H);
            snprintf(lawset, sizeof lawset, "volume.pressure=%s", law_names[law]);
            const char *sets[] = {lawset, NULL};
            ms_scene *sc = NULL;
            ms_sim *sim = NULL;
            ms_status st = acc_sim(json, sets, &sc, &sim);
            if (st == MS_ERR_UNSUPPORTED) {
                if (i == 0)
                    acc_note(c, "- sph: pressure solver `%s` is not in this build: no rest rows.",
                             law_names[law]);
                break;
            }
            if (st != MS_OK)
                return -1;
            ms_volume *v = ms_sim_volume(sim);
            double wall = 0;
            for (int f = 0; f < 75; ++f) {
                double w0 = tool_now();
                if (ms_sim_step(sim, 0.02f) != MS_OK) {
                    tool_error("accuracy: rest: %s", ms_last_error());
                    acc_free(sc, sim);
                    return -1;
                }
                wall += tool_now() - w0;
            }
            ms_volume_info in = ms_volume_info_init();
            ms_volume_get_info(v, &in);
            rest_result rr;
            rest_pressure(v, law, 2 * s, H, cs, &rr);
            acc_free(sc, sim);
            acc_row r = {.value = in.count, .error = rr.p_err, .reference = 1000 * g * H,
                         .ms_per_s = 1e3 * wall / in.time,
                         .ms_per_step = 1e3 * wall / in.substeps, .size = in.count,
                         .threads = 1};
            snprintf(r.study, sizeof r.study, "sph");
            snprintf(r.knob, sizeof r.knob, "rest_particles_%s", law_names[law]);
            snprintf(r.config, sizeof r.config,
                     "%s, spacing %g m, compression mean %.4f max %.4f (g H / c^2 = %.4f)",
                     law_names[law], s, rr.mean_c, rr.max_c, g * H / (cs * cs));
            snprintf(r.metric, sizeof r.metric, "hydrostatic pressure RMS / (rho0 g H)");
            /* DFSPH solves for its pressure, no law of the density gives
             * it, and the public API has no particle pressure: a pressure
             * from its density would only restate its compression */
            if (law != 2 && acc_add(c, &r) != 0)
                return -1;
            /* the references: hydrostatics of the law; DFSPH's is its
             * target, no compression */
            r.error = in.max_density_error;
            r.reference = law == 2 ? 0 : g * H / (cs * cs);
            snprintf(r.metric, sizeof r.metric, "max compression at rest (all particles)");
            if (acc_add(c, &r) != 0)
                return -1;
            /* the average (eq. 9's density, particles h from walls and
             * surface): hydrostatics gives g H / (2 c^2) over the column */
            r.error = rr.mean_c;
            r.reference = law == 2 ? 0 : g * H / (2 * cs * cs);
            snprintf(r.metric, sizeof r.metric, "mean compression at rest (interior)");
            if (acc_add(c, &r) != 0)
                return -1;
        }
    return 0;
}
