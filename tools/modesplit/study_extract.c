/* Study 3, height-field extraction (eqs. 16-18), on liquid shapes whose
 * surface is known:
 *  - a flat layer at rest: its level is the filled volume over the area;
 *  - a layer at rest in a box accelerating at a along x: in the box's frame
 *    gravity is (-a, 0, -g), and the surface is the plane
 *    z = level - (a / g) (x - L / 2) (its volume unchanged);
 *  - a settled column, 1.4 times as high as it is wide: its level is again
 *    volume over area;
 * each level lowered by the hydrostatic compression the pressure law needs
 * to hold the liquid up (surface_at: 0.10 spacings for the column, 0.014
 * for the layers), which is physics, not an extraction error. The notes
 * split what remains between the volume solver (its top particles) and
 * the extraction (its field against those particles);
 * against the field resolution (cells per side) and the eq. 18 smoothing
 * passes. The error is the RMS over every column, in particle spacings;
 * the cost is one extraction.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"

/* A shape: a box L wide (both sides) filled FILL high, settled 1.5 s
 * under gravity (-gx, 0, -g). */
typedef struct ext_shape {
    const char *name;
    double L, fill, top;    /* m: box side, fill height, domain height */
    double gx;              /* m/s^2 */
    double spacing, coarse; /* m: the fine and the coarse particle spacing */
} ext_shape;

/* The settled liquid of sh; NULL after printing. A tilted surface is laid
 * as a staircase of one-spacing slabs along x, each filled to the plane
 * at its centre (rounded to whole layers), so the liquid starts at rest
 * in its final shape. Filled flat and left to find the slope, it sloshed
 * (the box's lowest mode, ~0.9 s) long after the 1.5 s of settling: the
 * top particles' slope swung between -0.25 and -0.15 around the -0.2 of
 * the plane at 0.3 s intervals, and the field was off by 0.55 to 0.66
 * spacings, more on finer fields, which resolved the sloshing surface
 * that coarse ones averaged (measured at 14.4k particles). */
static ms_sim *settle(const ext_shape *sh, double spacing, ms_scene **sc)
{
    const double L = sh->L, FILL = sh->fill, gx = sh->gx, slope = -gx / 9.81;
    char json[8192], fills[6144] = "", grav[96];
    int slabs = gx != 0 ? (int)floor(L / spacing + 1e-6) : 1;
    if (slabs > 64) /* the scene's limit on fill boxes */
        slabs = 64;
    for (int i = 0; i < slabs; ++i) {
        double x0 = L * i / slabs, x1 = L * (i + 1) / slabs, xc = 0.5 * (x0 + x1);
        double z =
            gx != 0 ? spacing * floor((FILL + slope * (xc - 0.5 * L)) / spacing + 0.5) : FILL;
        size_t used = strlen(fills);
        snprintf(fills + used, sizeof fills - used,
                 "%s{\"min\": [%.9g, 0, 0], \"max\": [%.9g, %.9g, %.9g]}", i ? ", " : "", x0, x1, L,
                 z);
    }
    snprintf(json, sizeof json,
             "{\"name\": \"accuracy-extract\", \"frame_dt\": 0.02, \"threads\": 1,"
             " \"domain\": {\"min\": [0, 0, 0], \"max\": [%g, %g, %g]},"
             " \"volume\": {\"spacing\": %.9g, \"smoothing_length\": %.9g, \"viscosity\": 20.0,"
             "   \"fill\": [%s]}}",
             L, L, sh->top, spacing, 2 * spacing, fills);
    snprintf(grav, sizeof grav, "volume.gravity=[%.9g,0,-9.81]", -gx);
    const char *sets[] = {grav, NULL};
    ms_sim *sim = NULL;
    ms_status st = acc_sim(json, sets, sc, &sim);
    if (st != MS_OK)
        return NULL;
    for (int f = 0; st == MS_OK && f < 75; ++f)
        st = ms_sim_step(sim, 0.02f);
    if (st != MS_OK) {
        tool_error("accuracy: extract: %s", ms_last_error());
        acc_free(*sc, sim);
        return NULL;
    }
    return sim;
}

/* The known surface: the plane z = level + slope (x - L / 2), level the
 * particles' volume at rest density (spacing^3 each, as the fill boxes
 * lay them) over the area, lowered by the compression the pressure law
 * must have to hold the liquid up. At rest, p = rho g d at a depth d below
 * the surface (also in the accelerating box: the surface is an isobar, a
 * plane of slope -a / g), and both weakly compressible laws give
 * rho / rho0 - 1 = g d / c^2 to first order (ideal gas: c^2 = k; Tait:
 * c0^2). A column h high then holds the mass of h + g h^2 / (2 c^2) at
 * rest density, so the plane sinks by delta = g <h^2> / (2 c^2), the mean
 * over the area (flat: H g H / (2 c^2)). DFSPH keeps its compression under
 * max_density_error (0.1 %): no correction. First order in g H / c^2
 * (0.7 % at most here): the next term is under 0.002 spacings. */
static double surface_at(const ms_volume *v, double L, double slope, double spacing, double x)
{
    ms_volume_desc d = ms_volume_get_desc(v);
    const double level0 = ms_volume_count(v) * spacing * spacing * spacing / (L * L);
    double c2 = d.pressure == MS_PRESSURE_IDEAL_GAS ? d.gas_constant
                : d.pressure == MS_PRESSURE_TAIT    ? (double)d.sound_speed * d.sound_speed
                                                    : INFINITY;
    /* <h0^2> over x of the uncompressed plane: level0^2 + slope^2 L^2 / 12 */
    double h2 = level0 * level0 + slope * slope * L * L / 12, g = -d.gravity[2];
    return level0 - g * h2 / (2 * c2) + slope * (x - 0.5 * L);
}

/* RMS (in spacings) of the extracted field against the known plane, and
 * the median time of one extraction (ms). */
static int measure(ms_volume *v, int R, double L, double slope, double spacing, double *rms,
                   double *ms, double *cpu_ms)
{
    float *h = malloc(sizeof(float) * (size_t)R * R);
    double t[5], u[5];
    for (int rep = 0; rep < 5; ++rep) {
        acc_timer tm = {0};
        acc_tic(&tm);
        ms_status st = ms_volume_extract_height(v, R, R, h);
        acc_toc(&tm);
        if (st != MS_OK) {
            tool_error("accuracy: extract: %s", ms_last_error());
            free(h);
            return -1;
        }
        t[rep] = tm.wall;
        u[rep] = tm.cpu;
    }
    for (int i = 1; i < 5; ++i) /* medians of 5 */
        for (int j = i; j > 0 && t[j] < t[j - 1]; --j) {
            double x = t[j];
            t[j] = t[j - 1];
            t[j - 1] = x;
        }
    for (int i = 1; i < 5; ++i)
        for (int j = i; j > 0 && u[j] < u[j - 1]; --j) {
            double x = u[j];
            u[j] = u[j - 1];
            u[j - 1] = x;
        }
    double e2 = 0;
    for (int y = 0; y < R; ++y)
        for (int x = 0; x < R; ++x) {
            double d = h[y * R + x] - surface_at(v, L, slope, spacing, (x + 0.5) * L / R);
            e2 += d * d;
        }
    free(h);
    *rms = sqrt(e2 / ((double)R * R)) / spacing;
    *ms = 1e3 * t[2];
    *cpu_ms = 1e3 * u[2];
    return 0;
}

/* Where an error comes from, in spacings (signed, mean over the particle
 * columns, one spacing square each): the top particle of each column (measured along the plane:
 * z - slope (x - L / 2)) plus the half spacing the extraction puts the
 * surface above it, against the known plane (the volume solver's share:
 * compression beyond g d / c^2, a layer lost) and the extracted field
 * (32 x 32) against those particles (the extraction's own share). */
static void diagnose(acc_ctx *c, ms_volume *v, const char *name, double L, double slope,
                     double spacing)
{
    enum { R = 32 };
    const int C = (int)(L / spacing + 0.5);
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *h = malloc(sizeof(float) * R * R);
    double *top = malloc(sizeof(double) * (size_t)C * C);
    for (int k = 0; top && k < C * C; ++k)
        top[k] = -INFINITY;
    if (!p || !h || !top || ms_volume_get_particles(v, p, NULL) != MS_OK ||
        ms_volume_extract_height(v, R, R, h) != MS_OK) {
        free(p);
        free(h);
        free(top);
        return;
    }
    for (int i = 0; i < n; ++i) {
        int cx = (int)(p[3 * i] / L * C), cy = (int)(p[3 * i + 1] / L * C);
        cx = cx < 0 ? 0 : cx >= C ? C - 1 : cx;
        cy = cy < 0 ? 0 : cy >= C ? C - 1 : cy;
        top[cy * C + cx] = fmax(top[cy * C + cx], p[3 * i + 2] - slope * (p[3 * i] - 0.5 * L));
    }
    double solver = 0, ext = 0, at_mid = surface_at(v, L, slope, spacing, 0.5 * L);
    int m = 0;
    for (int k = 0; k < C * C; ++k)
        if (isfinite(top[k])) {
            solver += top[k] + 0.5 * spacing - at_mid;
            ++m;
        }
    solver /= m > 0 ? m : 1;
    /* the field against the particles: the field's mean along the plane
     * minus the particles' (both measured from the same plane) */
    for (int y = 0; y < R; ++y)
        for (int x = 0; x < R; ++x)
            ext += h[y * R + x] - surface_at(v, L, slope, spacing, (x + 0.5) * L / R);
    ext /= R * R;
    ms_volume_desc d = ms_volume_get_desc(v);
    const double level0 = n * spacing * spacing * spacing / (L * L);
    if (slope != 0) { /* the top particles of a sloped lattice sit 0 to 1 spacing
                       * under the plane: no half-spacing rule to split by */
        acc_note(c,
                 "- extract %s: the known surface is %.3f spacings below volume / area (the "
                 "hydrostatic compression g <h^2> / (2 c^2)); the 32x32 field lies %+.3f "
                 "spacings from it on average; %d particles, h = %g spacings.",
                 name, (level0 - at_mid) / spacing, ext / spacing, n, d.smoothing_length / spacing);
    } else
        acc_note(c,
                 "- extract %s: the known surface is %.3f spacings below volume / area (the "
                 "hydrostatic compression g <h^2> / (2 c^2)); the top particles + s/2 lie %+.3f "
                 "spacings from it (the volume solver's share) and the 32x32 field %+.3f from "
                 "those particles (the extraction's share); %d particles, h = %g spacings.",
                 name, (level0 - at_mid) / spacing, solver / spacing, (ext - solver) / spacing, n,
                 d.smoothing_length / spacing);
    free(p);
    free(h);
    free(top);
}

static int row(acc_ctx *c, const char *knob, double value, const char *shape, int R, int smooth,
               double level, int count, double rms, double ms, double cpu_ms)
{
    acc_row r = {.value = value,
                 .error = rms,
                 .reference = level,
                 .ms_per_s = NAN,
                 .ms_per_step = ms,
                 .cpu_ms_per_s = NAN,
                 .cpu_ms_per_step = cpu_ms,
                 .size = (double)R * R,
                 .threads = 1};
    snprintf(r.study, sizeof r.study, "extract");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    snprintf(r.config, sizeof r.config, "%s, %dx%d field, %d smoothing passes, %d particles", shape,
             R, R, smooth, count);
    snprintf(r.metric, sizeof r.metric, "height RMS error in spacings");
    return acc_add(c, &r);
}

/* The settled particles of sim in a volume whose desc differs only in
 * smooth_steps (eq. 18 passes are fixed at creation). */
static ms_volume *with_smoothing(ms_volume *v, int smooth)
{
    ms_volume_desc d = ms_volume_get_desc(v);
    d.smooth_steps = smooth;
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)n), *u = malloc(sizeof(float) * 3 * (size_t)n);
    ms_volume *w = NULL;
    if (p && u && ms_volume_get_particles(v, p, u) == MS_OK && ms_volume_create(&d, &w) == MS_OK &&
        ms_volume_add_particles(w, n, p, u) != MS_OK) {
        ms_volume_destroy(w);
        w = NULL;
    }
    if (!w)
        tool_error("accuracy: extract: %s", ms_last_error());
    free(p);
    free(u);
    return w;
}

/* The rows of sh at spacing s under the name (the knobs' prefix). */
static int study_at(acc_ctx *c, const ext_shape *sh, double s, const char *name)
{
    ms_scene *sc = NULL;
    ms_sim *sim = settle(sh, s, &sc);
    if (!sim)
        return -1;
    ms_volume *v = ms_sim_volume(sim);
    int n = ms_volume_count(v), rc = 0;
    double slope = -sh->gx / 9.81, rms, ms, cpu; /* gravity (-gx, 0, -g): z falls along x */
    const double ref = surface_at(v, sh->L, slope, s, 0.5 * sh->L); /* the level mid-box */
    static const int full[] = {8, 16, 32, 64, 128}, quick[] = {8, 16, 32};
    const int *Rs = c->quick ? quick : full;
    char knob[32];
    snprintf(knob, sizeof knob, "%s_field_cells", name);
    for (int i = 0; i < (c->quick ? 3 : 5) && rc == 0; ++i) {
        rc = measure(v, Rs[i], sh->L, slope, s, &rms, &ms, &cpu);
        if (rc == 0)
            rc = row(c, knob, Rs[i], name, Rs[i], ms_volume_get_desc(v).smooth_steps, ref, n, rms,
                     ms, cpu);
    }
    static const int smooth[] = {0, 1, 2, 4, 8, 16};
    snprintf(knob, sizeof knob, "%s_smoothing_passes", name);
    for (int i = 0; i < (c->quick ? 3 : 6) && rc == 0; ++i) {
        ms_volume *w = with_smoothing(v, smooth[i]);
        if (!w) {
            rc = -1;
            break;
        }
        rc = measure(w, 32, sh->L, slope, s, &rms, &ms, &cpu);
        if (rc == 0)
            rc = row(c, knob, smooth[i], name, 32, smooth[i], ref, n, rms, ms, cpu);
        ms_volume_destroy(w);
    }
    if (rc == 0)
        diagnose(c, v, name, sh->L, slope, s);
    acc_free(sc, sim);
    return rc;
}

/* Each shape at the coarse spacing (SHAPE_*) and, but for --quick, at the
 * fine one (SHAPE_fine_*): --quick runs a subset of the full study's
 * cases at the same settings, so the check of the committed study can
 * compare its rows. */
static int study(acc_ctx *c, const ext_shape *sh)
{
    char fine[32];
    snprintf(fine, sizeof fine, "%s_fine", sh->name);
    if (study_at(c, sh, sh->coarse, sh->name) != 0)
        return -1;
    return c->quick ? 0 : study_at(c, sh, sh->spacing, fine);
}

int study_extract_flat(acc_ctx *c)
{
    c->cost_method = ACC_BY_CALL;
    const ext_shape sh = {"flat", 0.5, 0.12, 0.3, 0, 0.0125, 0.025};
    return study(c, &sh);
}

int study_extract_tilted(acc_ctx *c)
{
    c->cost_method = ACC_BY_CALL;
    /* a = 0.2 g: the surface rises 0.1 m across the 0.5 m box */
    const ext_shape sh = {"tilted", 0.5, 0.12, 0.3, 0.2 * 9.81, 0.0125, 0.025};
    return study(c, &sh);
}

int study_extract_column(acc_ctx *c)
{
    c->cost_method = ACC_BY_CALL;
    /* the settled column of the SPH rest study: 0.2 m square, 0.28 m high,
     * where weakly compressible SPH's hydrostatic compression (g H / c^2,
     * 0.7 % at 20 m/s) lowers the surface below volume / area */
    const ext_shape sh = {"column", 0.2, 0.28, 0.4, 0, 0.01, 0.02};
    return study(c, &sh);
}
