/* Study 4, the coupler (eqs. 19-20), on a fig1-like pool dragged round a
 * loop: what the wave grid (N_surf = wave cells / SPH field cells, eq. 20)
 * and the wave steps per SPH step (N_time, eq. 19) buy in resolved surface
 * detail, and what they and two-way coupling cost per frame.
 *
 * Detail is the energy of the combined field below the SPH cell scale: the
 * variance of the height inside each SPH field cell, averaged over the
 * cells (0 when the waves add nothing the SPH field cannot show). The
 * error is its relative difference from a fine reference run (the issue
 * allows a reference run here: no closed form exists for this flow).
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

typedef struct pool_run {
    double detail;                     /* m^2 */
    double ms_frame, ms_per_s;         /* wall clock */
    double cpu_ms_frame, cpu_ms_per_s; /* CPU time */
    long surface_steps;
} pool_run;

static int run_pool(const acc_ctx *c, const char *const *sets, pool_run *out)
{
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    ms_status st = acc_sim(pool, sets, &sc, &sim);
    if (st != MS_OK)
        return -1;
    (void)c; /* --quick runs fewer configurations, each as the full study does */
    const int frames = 180;
    acc_timer tm = {0};
    for (int f = 0; st == MS_OK && f < frames; ++f) {
        acc_tic(&tm);
        st = ms_sim_step(sim, 0.016667f);
        acc_toc(&tm);
    }
    if (st != MS_OK) {
        tool_error("accuracy: coupler: %s", ms_last_error());
        acc_free(sc, sim);
        return -1;
    }
    int nx, ny;
    const float *h = ms_sim_height(sim, &nx, &ny);
    int b = nx / FIELD; /* cells per SPH cell */
    double sum = 0;
    for (int J = 0; J < FIELD; ++J)
        for (int I = 0; I < FIELD; ++I) {
            double m = 0, m2 = 0;
            for (int y = J * b; y < (J + 1) * b; ++y)
                for (int x = I * b; x < (I + 1) * b; ++x) {
                    m += h[y * nx + x];
                    m2 += (double)h[y * nx + x] * h[y * nx + x];
                }
            m /= b * b;
            sum += fmax(m2 / (b * b) - m * m, 0);
        }
    out->detail = sum / (FIELD * FIELD);
    ms_stats s = ms_stats_init();
    ms_sim_get_stats(sim, &s);
    out->ms_frame = 1e3 * tm.wall / frames;
    out->ms_per_s = 1e3 * tm.wall / ms_sim_time(sim);
    out->cpu_ms_frame = 1e3 * tm.cpu / frames;
    out->cpu_ms_per_s = 1e3 * tm.cpu / ms_sim_time(sim);
    out->surface_steps = s.surface_steps;
    acc_free(sc, sim);
    return 0;
}

static int add(acc_ctx *c, const char *knob, double value, const char *config, const pool_run *p,
               const pool_run *ref, int cells)
{
    acc_row r = {.value = value,
                 .error = fabs(p->detail - ref->detail) / ref->detail,
                 .reference = ref->detail,
                 .ms_per_s = p->ms_per_s,
                 .ms_per_step = p->ms_frame,
                 .cpu_ms_per_s = p->cpu_ms_per_s,
                 .cpu_ms_per_step = p->cpu_ms_frame,
                 .size = (double)cells * cells,
                 .threads = 1};
    snprintf(r.study, sizeof r.study, "coupler");
    snprintf(r.knob, sizeof r.knob, "%s", knob);
    snprintf(r.config, sizeof r.config, "%s", config);
    snprintf(r.metric, sizeof r.metric, "sub-SPH-cell detail energy rel. error");
    return acc_add(c, &r);
}

int study_coupler(acc_ctx *c)
{
    const int ref_cells = 800;
    char cells[64], cfg[96];
    snprintf(cells, sizeof cells, "surface.cells=[%d,%d]", ref_cells, ref_cells);
    const char *rs[] = {cells, NULL};
    pool_run ref;
    if (run_pool(c, rs, &ref) != 0)
        return -1;
    if (!(ref.detail > 0)) {
        tool_error("accuracy: coupler: the reference run has no detail below the SPH cells");
        return -1;
    }
    acc_note(c, "- coupler: reference run %dx%d wave cells (N_surf %d), detail %.4g m^2.",
             ref_cells, ref_cells, ref_cells / FIELD, ref.detail);
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
    /* two-way coupling (3.5): its cost, on and off */
    static const double back[] = {0.0, 0.3};
    for (int i = 0; i < 2; ++i) {
        char vf[64];
        snprintf(vf, sizeof vf, "coupling.volume_from_surface=%g", back[i]);
        const char *sets[] = {"surface.cells=[200,200]", vf, NULL};
        pool_run p;
        if (run_pool(c, sets, &p) != 0)
            return -1;
        snprintf(cfg, sizeof cfg, "200x200 wave cells, volume_from_surface %g", back[i]);
        if (add(c, "two_way_gain", back[i], cfg, &p, &ref, 200) != 0)
            return -1;
    }
    return 0;
}
