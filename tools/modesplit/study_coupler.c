/* Study 4, the coupler (eqs. 19-20), on a fig1-like pool dragged round a
 * loop: what the wave grid (N_surf = wave cells / SPH field cells, eq. 20)
 * and the wave steps per SPH step (N_time, eq. 19) buy in resolved surface
 * detail, and what they and two-way coupling cost per frame.
 *
 * Detail is the energy of the combined field below the SPH cell scale, per
 * band of scales (run_pool), averaged over the last 2 s; the error is the
 * relative L1 distance of that band spectrum from a fine reference run's
 * (no closed form exists for this flow).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"

#define FIELD 50 /* SPH field cells per side (X_SPH, Y_SPH of fig1) */

static const char pool[] =
    "{\"name\": \"accuracy-pool\", \"frame_dt\": 0.016667, \"threads\": 1,"
    " \"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
    " \"volume\": {\"spacing\": 0.05, \"gas_constant\": 100.0, \"viscosity\": 0.5,"
    "   \"fill\": [{\"min\": [0, 0, 0], \"max\": [1, 1, 0.25]}], \"field\": [50, 50]},"
    " \"surface\": {\"cells\": [400, 400], \"wave_speed\": 0.2, \"damping\": 0.8},"
    " \"coupling\": {\"n_time\": 0, \"surface_from_volume\": 0.05, \"volume_from_surface\": 0.3},"
    " \"effects\": {\"drag\": {\"path\": {\"points\": [[0.25, 0.25], [0.75, 0.3], [0.7, 0.75],"
    "   [0.3, 0.7]], \"speed\": 0.6, \"loop\": true, \"start\": 0.25},"
    "   \"radius\": 0.15, \"depth\": 0.1, \"strength\": 8.0}}}";

/* The combined field's energy per band of scales below the SPH cell
 * (1/FIELD m): band k holds what lies between blocks of 1/(FIELD 2^k) and
 * 1/(FIELD 2^(k+1)) m, the variance the finer block means add to the
 * coarser ones. A grid of N_surf = 2^j wave cells per SPH cell resolves
 * bands 0 to j-1; the reference (N_surf 16) all four. Averaged over
 * SAMPLES fields, one every 6 frames over the last 2 s: one frame's field
 * is the phase of the pool's sloshing at that instant, and under two-way
 * coupling the flow is chaotic, so a single snapshot moved by tens of
 * percent between runs that differed in the last bits. */
#define BANDS 4
#define FRAMES 180
#define SAMPLE_FROM 60
#define SAMPLE_EVERY 6

typedef struct pool_run {
    double band[BANDS];            /* m^2, time-averaged */
    double cpu_ms_frame, ms_frame; /* the whole frame: CPU, wall */
    double wave_cpu_ms, wave_ms;   /* the wave stages' share of a frame */
    double sim_s;
} pool_run;

/* Mean over the field of the squared block means of b x b cells. */
static double block_power(const float *h, int nx, int b)
{
    double sum = 0;
    int nb = nx / b;
    for (int J = 0; J < nb; ++J)
        for (int I = 0; I < nb; ++I) {
            double m = 0;
            for (int y = J * b; y < (J + 1) * b; ++y)
                for (int x = I * b; x < (I + 1) * b; ++x)
                    m += h[y * nx + x];
            m /= (double)b * b;
            sum += m * m;
        }
    return sum / ((double)nb * nb);
}

static int run_pool(const acc_ctx *c, const char *const *sets, pool_run *out)
{
    (void)c; /* --quick runs fewer configurations, each as the full study does */
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    ms_status st = acc_sim(pool, sets, &sc, &sim);
    if (st != MS_OK)
        return -1;
    memset(out, 0, sizeof *out);
    acc_timer tm = {0};
    int samples = 0;
    for (int f = 0; st == MS_OK && f < FRAMES; ++f) {
        st = acc_step(&tm, sim, 0.016667f);
        if (st != MS_OK || f + 1 < SAMPLE_FROM || (f + 1 - SAMPLE_FROM) % SAMPLE_EVERY)
            continue;
        int nx, ny;
        const float *h = ms_sim_height(sim, &nx, &ny);
        int per = nx / FIELD; /* wave cells per SPH cell: N_surf */
        double prev = block_power(h, nx, per);
        for (int k = 0; k < BANDS; ++k) {
            int b = per >> (k + 1); /* blocks of 1 / (FIELD 2^(k+1)) m */
            if (b < 1)
                break; /* finer than this grid: nothing resolved */
            double p = block_power(h, nx, b);
            out->band[k] += p - prev;
            prev = p;
        }
        ++samples;
    }
    if (st != MS_OK) {
        tool_error("accuracy: coupler: %s", ms_last_error());
        acc_free(sc, sim);
        return -1;
    }
    for (int k = 0; k < BANDS; ++k)
        out->band[k] /= samples;
    ms_stats s = ms_stats_init();
    ms_sim_get_stats(sim, &s);
    /* the wave stages (waves, coupling into them, eq. 20's sum): their
     * share of the frame by the stage clocks, applied to its CPU time;
     * the SPH part is the same at every N_surf and would hide them */
    double share = s.total_ms > 0 ? (s.surface_ms + s.combine_ms) / s.total_ms : NAN;
    out->sim_s = ms_sim_time(sim);
    out->cpu_ms_frame = 1e3 * tm.cpu / FRAMES;
    out->ms_frame = 1e3 * tm.wall / FRAMES;
    out->wave_cpu_ms = share * out->cpu_ms_frame;
    out->wave_ms = (s.surface_ms + s.combine_ms) / FRAMES;
    acc_free(sc, sim);
    return 0;
}

static double total(const pool_run *p)
{
    double t = 0;
    for (int k = 0; k < BANDS; ++k)
        t += p->band[k];
    return t;
}

/* The band spectrum's relative L1 distance from the reference's. */
static double spectrum_error(const pool_run *p, const pool_run *ref)
{
    double e = 0;
    for (int k = 0; k < BANDS; ++k)
        e += fabs(p->band[k] - ref->band[k]);
    return e / total(ref);
}

static int add(acc_ctx *c, const char *knob, double value, const char *config, const pool_run *p,
               const pool_run *ref, int cells)
{
    double per_s = FRAMES / p->sim_s; /* frames per simulated second */
    acc_row r = {.value = value,
                 .error = spectrum_error(p, ref),
                 .reference = total(ref),
                 .ms_per_s = p->wave_ms * per_s,
                 .ms_per_step = p->wave_ms,
                 .cpu_ms_per_s = p->wave_cpu_ms * per_s,
                 .cpu_ms_per_step = p->wave_cpu_ms,
                 .size = (double)cells * cells,
                 .threads = 1};
    snprintf(r.study, sizeof r.study, "coupler");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    snprintf(r.config, sizeof r.config, "%s", config);
    snprintf(r.metric, sizeof r.metric, "sub-SPH-cell spectrum rel. error");
    if (acc_add(c, &r) != 0)
        return -1;
    if (strcmp(knob, "n_surf") != 0)
        return 0;
    /* per band: what each doubling of the grid adds (1 - resolved share) */
    for (int k = 0; k < BANDS; ++k) {
        double lo = 100.0 / (FIELD << (k + 1)), hi = 100.0 / (FIELD << k); /* cm */
        r.error = fabs(p->band[k] - ref->band[k]) / ref->band[k];
        r.reference = ref->band[k];
        snprintf(r.metric, sizeof r.metric, "energy at %.3g-%.3g cm rel. error", lo, hi);
        if (acc_add(c, &r) != 0)
            return -1;
    }
    acc_note(c,
             "- coupler, %s: bands 1-2, 0.5-1, 0.25-0.5, 0.125-0.25 cm hold %.3g, %.3g, %.3g, "
             "%.3g m^2 (reference %.3g, %.3g, %.3g, %.3g); the frame costs %.2f ms of CPU, "
             "%.2f of them the wave stages.",
             config, p->band[0], p->band[1], p->band[2], p->band[3], ref->band[0], ref->band[1],
             ref->band[2], ref->band[3], p->cpu_ms_frame, p->wave_cpu_ms);
    return 0;
}

int study_coupler(acc_ctx *c)
{
    c->cost_method = ACC_BY_FRAME;
    const int ref_cells = FIELD << BANDS; /* N_surf 16 */
    char cells[64], cfg[96];
    snprintf(cells, sizeof cells, "surface.cells=[%d,%d]", ref_cells, ref_cells);
    const char *rs[] = {cells, NULL};
    pool_run ref;
    if (run_pool(c, rs, &ref) != 0)
        return -1;
    for (int k = 0; k < BANDS; ++k)
        if (!(ref.band[k] > 0)) {
            tool_error("accuracy: coupler: the reference run has no energy in band %d", k);
            return -1;
        }
    acc_note(c,
             "- coupler: reference run %dx%d wave cells (N_surf %d), %.4g m^2 below the SPH "
             "cell, averaged over %d fields of its last 2 s.",
             ref_cells, ref_cells, ref_cells / FIELD, total(&ref),
             (FRAMES - SAMPLE_FROM) / SAMPLE_EVERY + 1);
    static const int full[] = {50, 100, 200, 400}, quick[] = {50, 100, 200};
    const int *ns = c->quick ? quick : full;
    for (int i = 0; i < (c->quick ? 3 : 4); ++i) {
        snprintf(cells, sizeof cells, "surface.cells=[%d,%d]", ns[i], ns[i]);
        const char *sets[] = {cells, NULL};
        pool_run p;
        if (run_pool(c, sets, &p) != 0)
            return -1;
        snprintf(cfg, sizeof cfg, "%dx%d wave cells, N_time derived", ns[i], ns[i]);
        if (add(c, "n_surf", ns[i] / FIELD, cfg, &p, &ref, ns[i]) != 0)
            return -1;
    }
    /* N_time at N_surf 4: 1 is the fewest the CFL bound allows here */
    static const int nt[] = {1, 2, 4, 8};
    for (int i = 0; i < (c->quick ? 2 : 4); ++i) {
        char ntime[64];
        snprintf(ntime, sizeof ntime, "coupling.n_time=%d", nt[i]);
        const char *sets[] = {"surface.cells=[200,200]", ntime, NULL};
        pool_run p;
        if (run_pool(c, sets, &p) != 0)
            return -1;
        snprintf(cfg, sizeof cfg, "200x200 wave cells, N_time %d", nt[i]);
        if (add(c, "n_time", nt[i], cfg, &p, &ref, 200) != 0)
            return -1;
    }
    /* two-way coupling (3.5): what it changes and costs, on and off */
    static const double back[] = {0.0, 0.3};
    pool_run two[2];
    for (int i = 0; i < 2; ++i) {
        char vf[64];
        snprintf(vf, sizeof vf, "coupling.volume_from_surface=%g", back[i]);
        const char *sets[] = {"surface.cells=[200,200]", vf, NULL};
        if (run_pool(c, sets, &two[i]) != 0)
            return -1;
        snprintf(cfg, sizeof cfg, "200x200 wave cells, volume_from_surface %g", back[i]);
        if (add(c, "two_way_gain", back[i], cfg, &two[i], &ref, 200) != 0)
            return -1;
    }
    acc_note(c,
             "- coupler: two-way coupling (volume_from_surface 0.3 against 0) moves the "
             "band spectrum at N_surf 4 by %.1f %% of its energy.",
             100 * spectrum_error(&two[1], &two[0]));
    return 0;
}
