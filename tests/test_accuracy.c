/* `modesplit accuracy`, driven as a user would: --quick writes the CSV,
 * the tables, the gnuplot script and the plots, and its numbers show what
 * theory says they must (errors fall as cost rises; second-order waves);
 * --jobs, --case and --merge give the same files; bad options are refused. */
#include <check.h>
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support.h"

static char dir[256];

static void make_dir(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(dir, sizeof dir, "%s/ms_accuracy_XXXXXX", base && base[0] ? base : "/tmp");
    ck_assert_ptr_nonnull(mkdtemp(dir));
}

static void remove_dir(void)
{
    char cmd[400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    ck_assert_int_eq(system(cmd), 0);
}

/* Run the tool with args; its stdout+stderr in out; the exit status. */
static int tool(const char *args, char *out, size_t size)
{
    const char *b = getenv("MS_TEST_BUILD");
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s/bin/modesplit %s 2>&1", b && b[0] ? b : "build", args);
    FILE *p = popen(cmd, "r");
    ck_assert_ptr_nonnull(p);
    size_t got = fread(out, 1, size - 1, p);
    out[got] = '\0';
    while (fread(cmd, 1, sizeof cmd, p) > 0)
        ;
    int rc = pclose(p);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

typedef struct row {
    char study[32], knob[48], metric[64];
    double value, error, reference, ms_per_s, ms_per_step, size;
} row;

static int read_rows(const char *path, row *rows, int max)
{
    FILE *f = fopen(path, "r");
    ck_assert_msg(f != NULL, "%s missing", path);
    char line[4096];
    ck_assert_ptr_nonnull(fgets(line, sizeof line, f));
    ck_assert_msg(strstr(line, ",cpu_ms_per_simulated_s,cpu_ms_per_step,wall_ms_per_simulated_s,"
                               "wall_ms_per_step,") &&
                      strstr(line, ",cost_method,") && strstr(line, "machine") &&
                      strstr(line, "commit"),
                  "header: %s", line);
    int n = 0;
    while (n < max && fgets(line, sizeof line, f)) {
        /* study,knob,value,"config","metric",error,reference,ms/s,ms/step,... */
        row *r = &rows[n];
        char *p = line, *q;
        q = strchr(p, ',');
        *q = '\0';
        snprintf(r->study, sizeof r->study, "%.31s", p);
        p = q + 1;
        q = strchr(p, ',');
        *q = '\0';
        snprintf(r->knob, sizeof r->knob, "%.47s", p);
        p = q + 1;
        r->value = strtod(p, &p);
        p = strchr(p + 2, '"') + 3; /* past the config */
        q = strchr(p, '"');
        *q = '\0';
        snprintf(r->metric, sizeof r->metric, "%.63s", p);
        p = q + 2;
        r->error = strtod(p, &p);
        r->reference = strtod(p + 1, &p);
        r->ms_per_s = strtod(p + 1, &p);    /* CPU time */
        r->ms_per_step = strtod(p + 1, &p); /* CPU time */
        strtod(p + 1, &p);                  /* wall clock per simulated s */
        strtod(p + 1, &p);                  /* wall clock per step */
        r->size = strtod(p + 1, &p);        /* cells or particles */
        ++n;
    }
    fclose(f);
    return n;
}

/* The rows of (study, knob, metric) in the file's order. */
static int select_rows(const row *rows, int n, const char *study, const char *knob,
                       const char *metric, const row **out)
{
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (!strcmp(rows[i].study, study) && !strcmp(rows[i].knob, knob) &&
            strstr(rows[i].metric, metric))
            out[m++] = &rows[i];
    return m;
}

static int exists(const char *name)
{
    char p[512];
    struct stat sb;
    snprintf(p, sizeof p, "%s/%s", dir, name);
    return stat(p, &sb) == 0 && sb.st_size > 0;
}

START_TEST(quick_study_writes_everything_and_shows_the_theory)
{
    make_dir();
    char args[512], out[1 << 16];
    snprintf(args, sizeof args, "accuracy --quick --out '%s'", dir);
    int rc = tool(args, out, sizeof out);
    ck_assert_msg(rc == 0, "accuracy --quick exited %d: %s", rc, out);
    ck_assert(exists("accuracy.csv"));
    ck_assert(exists("accuracy.md"));
    ck_assert(exists("accuracy.gp"));
    char path[512];
    snprintf(path, sizeof path, "%s/accuracy.csv", dir);
    static row rows[1000];
    int n = read_rows(path, rows, 1000);
    ck_assert_int_ge(n, 40);
    const row *sel[64];

    /* waves: second order in space (and time at a fixed Courant number) */
    int m = select_rows(rows, n, "waves", "cells_per_wavelength", "frequency", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 0; i + 1 < m; ++i) {
        double order =
            log(sel[i]->error / sel[i + 1]->error) / log(sel[i + 1]->value / sel[i]->value);
        ck_assert_msg(order >= 1.9, "wave order %.3f between %.1f and %.1f cells per wavelength",
                      order, sel[i]->value, sel[i + 1]->value);
        /* the cost columns (CPU time) vary with the machine and its
         * load: a test asserts the work (cells) and that a cost was
         * measured, never how long it took */
        ck_assert_msg(sel[i + 1]->size > sel[i]->size && sel[i + 1]->ms_per_step > 0 &&
                          sel[i + 1]->ms_per_s > 0,
                      "a finer grid has more cells and a measured cost");
    }
    /* the ring front speed approaches c as the drop is resolved */
    m = select_rows(rows, n, "waves", "ring_cells_per_drop_radius", "front", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 0; i + 1 < m; ++i)
        ck_assert_msg(sel[i + 1]->error < sel[i]->error, "ring front error %.4f then %.4f",
                      sel[i]->error, sel[i + 1]->error);
    ck_assert_msg(sel[m - 1]->error < 0.01, "ring front speed off by %.4f", sel[m - 1]->error);
    /* real water: the model holds for long waves at depth 0.02 m, departs for ripples */
    m = select_rows(rows, n, "water", "lambda_m_depth_0.02m", "phase", sel);
    ck_assert_int_ge(m, 5);
    ck_assert_msg(sel[m - 1]->error < 0.01, "10 m waves at 0.02 m: %.4f", sel[m - 1]->error);
    ck_assert_msg(sel[0]->error > 0.3, "1 mm ripples: %.4f", sel[0]->error);
    /* every surface model simulated against real water at the same depths:
     * the dispersive model within 0.2 % at every wavelength (its sigma / rho
     * 7.28e-5 against water's 7.295e-5 leaves up to 0.1 % at 1 mm, 1e-6 at
     * 1 m measured), eq. 2 within 0.3 % of its own formula (its grid at 32
     * cells per wavelength), so 35 % off at 1 mm and 0.2 m deep; each model
     * with its cost per cell per step on a 256^2 grid */
    static const char *const depth_metric[] = {"simulated phase speed rel. error, depth 0.02 m",
                                               "simulated phase speed rel. error, depth 0.1 m",
                                               "simulated phase speed rel. error, depth 1 m"};
    const row *eq2[64];
    for (int d = 0; d < 3; ++d) {
        m = select_rows(rows, n, "water", "lambda_m_model_dispersive", depth_metric[d], sel);
        ck_assert_int_ge(m, 5);
        for (int i = 0; i < m; ++i)
            ck_assert_msg(sel[i]->error < 0.002 && sel[i]->size == 65536 && sel[i]->ms_per_step > 0,
                          "dispersive, %s: %.2e at %g m", depth_metric[d], sel[i]->error,
                          sel[i]->value);
        int m2 = select_rows(rows, n, "water", "lambda_m_model_wave", depth_metric[d], eq2);
        ck_assert_int_eq(m2, m);
        ck_assert_msg(eq2[0]->size == 65536 && eq2[0]->ms_per_step > 0, "eq. 2: no cost");
    }
    m = select_rows(rows, n, "water", "lambda_m_depth_0.02m", "phase", sel);
    int m2 = select_rows(rows, n, "water", "lambda_m_model_wave", depth_metric[0], eq2);
    ck_assert_int_eq(m, m2);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(fabs(eq2[i]->value - sel[i]->value) < 1e-9 * sel[i]->value &&
                          fabs((1 + eq2[i]->error) / (1 + sel[i]->error) - 1) < 0.003,
                      "eq. 2 simulated %.4f, its formula %.4f at %g m", eq2[i]->error,
                      sel[i]->error, sel[i]->value);

    /* SPH: the dam break follows Martin & Moyce within 15 % (RMS) for every
     * solver this build has; a solver it lacks is noted, not hidden */
    static const char *const laws[] = {"law_ideal_gas", "law_tait", "law_dfsph"};
    snprintf(path, sizeof path, "%s/accuracy.md", dir);
    FILE *md = fopen(path, "r");
    static char text[1 << 18];
    size_t len = fread(text, 1, sizeof text - 1, md);
    text[len] = '\0';
    fclose(md);
    for (int k = 0; k < 3; ++k) {
        m = select_rows(rows, n, "sph", laws[k], "front Z rel.", sel);
        if (m == 0) {
            ck_assert_msg(strstr(text, "is not in this build"), "%s: no row and no note", laws[k]);
            continue;
        }
        ck_assert_int_eq(m, 1);
        ck_assert_msg(sel[0]->error < 0.15, "%s: front RMS %.3f", laws[k], sel[0]->error);
        double ez = sel[0]->error;
        /* the front runs ahead of the experiment by a lag, not a speed:
         * shifted by its best T0 (0.18 to 0.21 measured, positive: the
         * simulation ahead), the error falls to a third (2.5 to 2.9 %
         * measured against 8.5 to 12 % unshifted) */
        m = select_rows(rows, n, "sph", laws[k], "best time shift", sel);
        ck_assert_int_eq(m, 1);
        ck_assert_msg(sel[0]->error > 0.05 && sel[0]->error < 0.4, "%s: front shift T0 %.3f",
                      laws[k], sel[0]->error);
        m = select_rows(rows, n, "sph", laws[k], "front Z RMS error after time shift", sel);
        ck_assert_int_eq(m, 1);
        ck_assert_msg(sel[0]->error < 0.05 && sel[0]->error < 0.5 * ez,
                      "%s: front RMS %.3f after the shift, %.3f before", laws[k], sel[0]->error,
                      ez);
        /* late, the front is slower than Ritter's inviscid shallow-water
         * front 2 sqrt(g 2a) (dZ/dT = 2) and about as fast as the
         * experiment's (0.69 of it; 0.73 to 0.74 measured) */
        m = select_rows(rows, n, "sph", laws[k], "Ritter", sel);
        ck_assert_int_eq(m, 1);
        ck_assert_msg(sel[0]->error > 0.6 && sel[0]->error < 0.9, "%s: late front %.3f of Ritter's",
                      laws[k], sel[0]->error);
        ck_assert_msg(fabs(sel[0]->reference - 0.689) < 0.01, "the experiment's late slope %.3f",
                      sel[0]->reference);
        /* and the residual column at the wall, H(tau) of their Table 6,
         * within 25 % RMS at 800 particles (0.07 to 0.15 measured) */
        m = select_rows(rows, n, "sph", laws[k], "column H rel.", sel);
        ck_assert_int_eq(m, 1);
        ck_assert_msg(sel[0]->error < 0.25, "%s: column H RMS %.3f", laws[k], sel[0]->error);
    }
    /* the hydrostatic pressure at rest, averaged over 0.5 s of the column's
     * breathing mode, is rho0 g d within 10 % RMS (5.5 to 6.3 % measured
     * at 175 particles, 3 of them interior) and within 4 % at 1400 (1.3 to
     * 1.6 %; a single snapshot was 10 to 16 % off) */
    static const char *const rest_laws[] = {"rest_particles_ideal_gas", "rest_particles_tait"};
    for (int k = 0; k < 2; ++k) {
        m = select_rows(rows, n, "sph", rest_laws[k], "hydrostatic", sel);
        ck_assert_int_ge(m, 2);
        for (int i = 0; i < m; ++i)
            ck_assert_msg(sel[i]->error < 0.1, "%s: hydrostatic RMS %.3f", rest_laws[k],
                          sel[i]->error);
        ck_assert_msg(sel[m - 1]->error < 0.04, "%s: hydrostatic RMS %.3f at %.0f particles",
                      rest_laws[k], sel[m - 1]->error, sel[m - 1]->value);
    }
    /* the figures a user would quote, written from the rows */
    ck_assert_ptr_nonnull(strstr(text, "## Figures to quote"));
    ck_assert_ptr_nonnull(strstr(text, "front Z(T) RMS error against Martin & Moyce: "));
    ck_assert_ptr_nonnull(strstr(text, "- the same after the best time shift: "));
    ck_assert_ptr_nonnull(strstr(text, "standing-mode frequency error: "));
    /* the compression at rest that holds the column up: hydrostatics
     * gives a mean of g H / (2 c^2) = 0.0034 for the weakly compressible
     * laws (0.0026 to 0.0058 measured at 175 and 1400 particles); DFSPH
     * keeps under a percent at every particle */
    m = select_rows(rows, n, "sph", "rest_particles_tait", "mean compression", sel);
    ck_assert_int_ge(m, 2);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(sel[i]->error > 0.5 * 0.0034 && sel[i]->error < 2 * 0.0034,
                      "tait: mean compression %.4f at rest", sel[i]->error);
    m = select_rows(rows, n, "sph", "rest_particles_dfsph", "max compression", sel);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(sel[i]->error < 0.01, "dfsph: max compression %.4f at rest", sel[i]->error);
    /* at rest against the stiffness: the mean compression of the weakly
     * compressible laws is g H / (2 c^2) within 2x at every sound speed
     * (10 to 40 m/s: 0.98 to 1.15 of it measured at 175 particles), so
     * less for a stiffer law; DFSPH under 1 % at every max_density_error */
    static const char *const rest_sound[] = {"rest_sound_speed_ideal_gas", "rest_sound_speed_tait"};
    for (int k = 0; k < 2; ++k) {
        m = select_rows(rows, n, "sph", rest_sound[k], "mean compression", sel);
        ck_assert_int_ge(m, 2);
        for (int i = 0; i < m; ++i)
            ck_assert_msg(sel[i]->error > 0.5 * sel[i]->reference &&
                              sel[i]->error < 2 * sel[i]->reference,
                          "%s: mean compression %.4f at c = %g m/s, hydrostatics %.4f",
                          rest_sound[k], sel[i]->error, sel[i]->value, sel[i]->reference);
    }
    m = select_rows(rows, n, "sph", "rest_max_density_error_dfsph", "max compression", sel);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(sel[i]->error < 0.01, "dfsph: max compression %.4f at rest at %g",
                      sel[i]->error, sel[i]->value);
    /* extraction: a flat layer extracts flat within 3 % of a spacing
     * against its level lowered by its hydrostatic compression (0.002 to
     * 0.019 measured; without that lowering the error would be 0.005 more) */
    m = select_rows(rows, n, "extract", "flat_field_cells", "height", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(sel[i]->error < 0.03, "flat layer: %.3f spacings", sel[i]->error);
    /* a settled column 1.4 times as high as wide: within 3 % too (0.001 to
     * 0.005 measured); volume / area alone is 0.048 spacings higher */
    m = select_rows(rows, n, "extract", "column_field_cells", "height", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 0; i < m; ++i)
        ck_assert_msg(sel[i]->error < 0.03, "settled column: %.3f spacings", sel[i]->error);
    ck_assert_ptr_nonnull(strstr(text, "extract column: the known surface is"));
    /* the tilted layer (slope 0.2), laid at rest in its shape: the error
     * falls as the field resolves the slope (0.23, 0.10, 0.07 spacings
     * measured at 8, 16, 32 cells) */
    m = select_rows(rows, n, "extract", "tilted_field_cells", "height", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 0; i + 1 < m; ++i)
        ck_assert_msg(sel[i + 1]->error < sel[i]->error, "tilted layer: %.3f then %.3f spacings",
                      sel[i]->error, sel[i + 1]->error);
    ck_assert_msg(sel[m - 1]->error < 0.15, "tilted layer: %.3f spacings", sel[m - 1]->error);
    /* the coupler: with N_surf = 1 the combined field holds nothing below
     * the SPH cell; each doubling of the wave grid resolves one more band
     * of scales, so the band spectrum's distance from the reference falls
     * (32 % at N_surf 2, 11 % at 4 measured), and a band the grid
     * resolves is within 20 % of the reference's (5 to 7 % measured) */
    m = select_rows(rows, n, "coupler", "n_surf", "spectrum", sel);
    ck_assert_int_ge(m, 3);
    ck_assert_msg(sel[0]->value == 1 && sel[0]->error == 1, "N_surf %.0f: %.3f", sel[0]->value,
                  sel[0]->error);
    for (int i = 1; i < m; ++i) {
        ck_assert_msg(sel[i]->error < 0.5, "N_surf %.0f misses %.0f %% of the spectrum",
                      sel[i]->value, 100 * sel[i]->error);
        ck_assert_msg(sel[i]->error < sel[i - 1]->error, "N_surf %.0f: %.3f, N_surf %.0f: %.3f",
                      sel[i - 1]->value, sel[i - 1]->error, sel[i]->value, sel[i]->error);
    }
    m = select_rows(rows, n, "coupler", "n_surf", "energy at 1-2 cm", sel);
    ck_assert_int_ge(m, 3);
    for (int i = 1; i < m; ++i)
        ck_assert_msg(sel[i]->error < 0.2, "N_surf %.0f: the 1-2 cm band %.3f off", sel[i]->value,
                      sel[i]->error);
    /* orders only where theory gives one, per knob and metric, with the
     * fitted range; no power fitted to a knob without one */
    ck_assert_ptr_nonnull(strstr(text, "- cells_per_wavelength, standing-mode frequency rel. "
                                       "error: observed order"));
    ck_assert_ptr_nonnull(strstr(text, "over 3 points"));
    ck_assert_ptr_null(strstr(text, "- particles, "));
    ck_assert_ptr_null(strstr(text, "no theoretical order"));
    ck_assert_ptr_nonnull(strstr(text, "Machine:"));

    /* the plots, drawn by gnuplot from the script beside the CSV */
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        remove_dir();
        MS_SKIP("gnuplot is not installed (Debian: gnuplot-nox): no plots to check");
    }
    /* one cost plot per metric, each titled and labelled with it */
    static const char *const pngs[] = {
        "waves_cost.png",
        "waves_cost_ring_front_speed_rel_error.png",
        "waves_pareto.png",
        "water_error.png",
        "sph_cost.png",
        "sph_cost_dam_break_column_h_rel_rms_error.png",
        "sph_cost_hydrostatic_pressure_rms_rho0_g_h.png",
        "sph_cost_mean_compression_at_rest_interior.png",
        "sph_pareto.png",
        "sph_pareto_compression.png",
        "sph_solvers_compression.png",
        "sph_solvers_rest_compression.png",
        "water_error_simulated_phase_speed_rel_error_depth_0_1_m.png",
        "extract_cost.png",
        "extract_pareto_flat.png",
        "coupler_cost.png",
        "coupler_pareto.png"};
    for (size_t i = 0; i < sizeof pngs / sizeof pngs[0]; ++i)
        ck_assert_msg(exists(pngs[i]), "%s missing", pngs[i]);
    snprintf(path, sizeof path, "%s/accuracy.gp", dir);
    FILE *gp = fopen(path, "r");
    len = fread(text, 1, sizeof text - 1, gp);
    text[len] = '\0';
    fclose(gp);
    const char *at = strstr(text, "set output 'sph_cost_dam_break_column_h_rel_rms_error.png'\n");
    ck_assert_ptr_nonnull(at);
    /* the axes (log or linear) and the title follow the output */
    ck_assert_ptr_nonnull(strstr(at, "set title 'sph: dam-break column H rel. RMS error against "
                                     "cost"));
    /* the metric with its unit, the cost in CPU time */
    ck_assert_ptr_nonnull(strstr(at, "set ylabel 'dam-break column H rel. RMS error (relative, "
                                     "0.01 = 1 %)'"));
    ck_assert_ptr_nonnull(strstr(at, "set xlabel 'cost: CPU time per simulated second"));
    remove_dir();
}
END_TEST

static int path_exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

START_TEST(jobs_case_and_merge_give_the_same_rows)
{
    make_dir();
    char args[1024], out[1 << 14];
    snprintf(args, sizeof args, "accuracy --quick --jobs --out '%s'", dir);
    ck_assert_int_eq(tool(args, out, sizeof out), 0);
    int lines = 0;
    for (char *p = out; (p = strstr(p, "--case ")) != NULL; ++p)
        ++lines;
    ck_assert_int_eq(lines, 22); /* one a case */
    ck_assert_ptr_nonnull(strstr(out, "--case water-dispersion --out"));
    ck_assert_ptr_nonnull(strstr(out, "/parts'"));
    /* two cheap cases by hand, as GNU parallel would run them, then merge */
    snprintf(args, sizeof args, "accuracy --quick --case water-dispersion --out '%s/parts'", dir);
    ck_assert_int_eq(tool(args, out, sizeof out), 0);
    snprintf(args, sizeof args, "accuracy --quick --case waves-cells --out '%s/parts'", dir);
    ck_assert_int_eq(tool(args, out, sizeof out), 0);
    /* one of the extraction's three test shapes: the plots of the other
     * two have no rows, and are left out rather than stop gnuplot */
    snprintf(args, sizeof args, "accuracy --quick --case extract-flat --out '%s/parts'", dir);
    ck_assert_int_eq(tool(args, out, sizeof out), 0);
    snprintf(args, sizeof args, "accuracy --merge '%s/parts' --out '%s'", dir, dir);
    ck_assert_msg(tool(args, out, sizeof out) == 0, "%s", out);
    ck_assert_msg(!strstr(out, "gnuplot failed"), "%s", out);
    char path[512];
    if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        snprintf(path, sizeof path, "%s/extract_pareto_flat.png", dir);
        ck_assert_msg(path_exists(path), "no plot of the merged extraction rows: %s", out);
        snprintf(path, sizeof path, "%s/extract_pareto_tilted.png", dir);
        ck_assert_msg(!path_exists(path), "a plot of no rows: %s", path);
    }
    snprintf(path, sizeof path, "%s/accuracy.csv", dir);
    static row rows[200];
    int n = read_rows(path, rows, 200);
    ck_assert_int_eq(n, 27 + 3 + 6);
    snprintf(path, sizeof path, "%s/accuracy.md", dir);
    FILE *f = fopen(path, "r");
    char text[1 << 15];
    size_t len = fread(text, 1, sizeof text - 1, f);
    text[len] = '\0';
    fclose(f);
    ck_assert_ptr_nonnull(strstr(text, "3 of 22 cases"));
    remove_dir();
}
END_TEST

START_TEST(bad_options_are_refused)
{
    char out[4096];
    ck_assert_int_eq(tool("accuracy --case nonsense", out, sizeof out), 2);
    ck_assert_ptr_nonnull(strstr(out, "allowed: waves-cells"));
    ck_assert_int_eq(tool("accuracy --jobs --merge x", out, sizeof out), 2);
    ck_assert_ptr_nonnull(strstr(out, "one of"));
    ck_assert_int_eq(tool("accuracy --bogus", out, sizeof out), 2);
    /* two cases in one run are refused, not run as the last one alone: a
     * case's part is its own process's (its costs measured with the
     * machine to itself), and --jobs lists a line per case to run them */
    ck_assert_int_eq(tool("accuracy --case waves-cells --case water-dispersion --out "
                          "/tmp/ms_acc_two_cases",
                          out, sizeof out),
                     2);
    ck_assert_msg(strstr(out, "--case water-dispersion after --case waves-cells: one case a run"),
                  "%s", out);
    struct stat sb;
    ck_assert_int_ne(stat("/tmp/ms_acc_two_cases", &sb), 0);
    ck_assert_int_eq(
        tool("accuracy --merge /nonexistent/parts --out /tmp/ms_acc_none", out, sizeof out), 1);
    ck_assert_ptr_nonnull(strstr(out, "no part"));
}
END_TEST

/* ---- part files and paths are untrusted: no shell, no escape from --out ---- */

/* Run the tool with argv (no shell between: the arguments are as given);
 * its output in out; the exit status. */
static int tool_argv(const char *const *args, char *out, size_t size)
{
    char log[400];
    snprintf(log, sizeof log, "%s.log", dir);
    int status = ms_test_run_tool(args, log, log);
    FILE *f = fopen(log, "r");
    size_t got = f ? fread(out, 1, size - 1, f) : 0;
    out[got] = '\0';
    if (f)
        fclose(f);
    unlink(log);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* A part of one real case (water-dispersion, the cheapest) in dir/parts:
 * its header and first line1, to forge rows from. */
static void real_part(char *header, char *line1, size_t size)
{
    char out[1 << 14], parts[400], path[500];
    snprintf(parts, sizeof parts, "%s/parts", dir);
    const char *a[] = {"accuracy", "--quick", "--case", "water-dispersion", "--out", parts, NULL};
    ck_assert_msg(tool_argv(a, out, sizeof out) == 0, "%s", out);
    snprintf(path, sizeof path, "%s/water-dispersion.csv", parts);
    FILE *f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_ptr_nonnull(fgets(header, (int)size, f));
    ck_assert_ptr_nonnull(fgets(line1, (int)size, f));
    fclose(f);
}

/* dir/parts/water-dispersion.csv: header, then line1 with its first field
 * (the study) replaced by study and, if metric is not NULL, its fifth
 * (the metric, quoted in the CSV) by metric. */
static void forge_part(const char *header, const char *line1, const char *study, const char *metric)
{
    char path[500];
    snprintf(path, sizeof path, "%s/parts/water-dispersion.csv", dir);
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(header, f);
    const char *rest = strchr(line1, ','); /* ,knob,value,"config","metric",... */
    if (!metric) {
        fprintf(f, "%s%s", study, rest);
    } else {
        const char *m0 = strchr(strchr(strchr(rest + 1, ',') + 1, '"') + 1, '"') + 2;
        const char *m1 = strchr(m0 + 1, '"');
        fprintf(f, "%s%.*s\"%s%s", study, (int)(m0 - rest), rest, metric, m1);
    }
    fclose(f);
}

START_TEST(merge_refuses_study_names_that_are_not_names)
{
    make_dir();
    char header[4096], line1[4096], out[1 << 14], parts[400], report[400], pwned[500];
    real_part(header, line1, sizeof header);
    snprintf(parts, sizeof parts, "%s/parts", dir);
    snprintf(report, sizeof report, "%s/report/deep", dir);
    snprintf(pwned, sizeof pwned, "%s/PWNED", dir);
    char cmd_study[600];
    snprintf(cmd_study, sizeof cmd_study, "x`touch %s`", pwned);
    const char *const hostile[] = {cmd_study,
                                   "../../escape",
                                   "a'b",
                                   "a\"b",
                                   "x/y",
                                   "",
                                   "waves_and_a_name_longer_than_its_field"};
    for (size_t i = 0; i < sizeof hostile / sizeof hostile[0]; ++i) {
        forge_part(header, line1, hostile[i], NULL);
        const char *a[] = {"accuracy", "--merge", parts, "--out", report, NULL};
        ck_assert_int_eq(tool_argv(a, out, sizeof out), 1);
        ck_assert_msg(strstr(out, "water-dispersion.csv:2: study \"") &&
                          strstr(out, "allowed: a letter, then letters, digits"),
                      "%s", out);
        ck_assert_msg(!path_exists(pwned), "study %s ran a command", hostile[i]);
        /* nothing written: not under --out, not beside it */
        ck_assert(!path_exists(report));
        char esc[500];
        snprintf(esc, sizeof esc, "%s/escape.dat", dir);
        ck_assert(!path_exists(esc));
    }
    remove_dir();
}
END_TEST

/* Text fields (a metric) may hold quotes and backquotes: the plot script
 * has them only inside single quotes, where gnuplot runs nothing. */
START_TEST(plot_script_runs_nothing_from_a_part)
{
    make_dir();
    char header[4096], line1[4096], out[1 << 14], parts[400], pwned[500], metric[800];
    real_part(header, line1, sizeof header);
    snprintf(parts, sizeof parts, "%s/parts", dir);
    snprintf(pwned, sizeof pwned, "%s/PWNED", dir);
    /* gnuplot runs in dir: a command would make dir/PWNED */
    snprintf(metric, sizeof metric, "err `touch PWNED` it's @x");
    forge_part(header, line1, "water", metric);
    const char *a[] = {"accuracy", "--merge", parts, "--out", dir, NULL};
    ck_assert_msg(tool_argv(a, out, sizeof out) == 0, "%s", out);
    ck_assert_msg(!path_exists(pwned), "gnuplot ran a command from the part");
    char path[500], text[1 << 15];
    snprintf(path, sizeof path, "%s/accuracy.gp", dir);
    FILE *gp = fopen(path, "r");
    ck_assert_ptr_nonnull(gp);
    size_t len = fread(text, 1, sizeof text - 1, gp);
    text[len] = '\0';
    fclose(gp);
    /* the one line with the metric: a single-quoted string, its quote doubled */
    char want[900];
    snprintf(want, sizeof want,
             "set ylabel 'err `touch PWNED` it''s @x (relative, 0.01 = 1 %%)'\n");
    ck_assert_msg(strstr(text, want) != NULL, "%s", text);
    ck_assert_ptr_null(strstr(text, "\"err"));
    if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        snprintf(path, sizeof path, "%s/water_error.png", dir);
        ck_assert_msg(path_exists(path), "gnuplot drew no plot: %s", out);
    }
    remove_dir();
}
END_TEST

/* A part that is a FIFO (the open would block for good) or a link to
 * /dev/zero (its trace would be copied until the disk is full) is refused
 * by name; the case's time-out catches a hang. */
START_TEST(merge_refuses_parts_that_are_not_regular_files)
{
    make_dir();
    char header[4096], line1[4096], out[1 << 14], parts[400], path[500];
    real_part(header, line1, sizeof header);
    snprintf(parts, sizeof parts, "%s/parts", dir);
    static const char *const kinds[3] = {"csv", "notes", "trace"};
    for (int k = 0; k < 3; ++k) {
        forge_part(header, line1, "water", NULL);
        snprintf(path, sizeof path, "%s/water-dispersion.%s", parts, kinds[k]);
        remove(path);
        if (k == 0)
            ck_assert_int_eq(mkfifo(path, 0600), 0);
        else
            ck_assert_int_eq(symlink("/dev/zero", path), 0);
        const char *a[] = {"accuracy", "--merge", parts, "--out", dir, NULL};
        ck_assert_int_eq(tool_argv(a, out, sizeof out), 1);
        ck_assert_msg(strstr(out, "cannot read the part") && strstr(out, path) &&
                          strstr(out, "not a regular file"),
                      "%s", out);
        remove(path);
    }
    remove_dir();
}
END_TEST

/* An --out with quotes and a command in it reaches no shell: the merge
 * writes into that very directory, and --jobs prints lines a shell reads
 * back as the same words. */
START_TEST(out_with_quotes_reaches_no_shell)
{
    make_dir();
    char header[4096], line1[4096], out[1 << 14], parts[400], odd[1200], pwned[500];
    real_part(header, line1, sizeof header);
    snprintf(parts, sizeof parts, "%s/parts", dir);
    snprintf(pwned, sizeof pwned, "%s/PWNED", dir);
    snprintf(odd, sizeof odd, "%s/a'; touch %s; echo '", dir, pwned);
    const char *a[] = {"accuracy", "--merge", parts, "--out", odd, NULL};
    ck_assert_msg(tool_argv(a, out, sizeof out) == 0, "%s", out);
    ck_assert(!path_exists(pwned));
    char path[1400];
    snprintf(path, sizeof path, "%s/accuracy.md", odd);
    ck_assert(path_exists(path));
    if (system("command -v gnuplot >/dev/null 2>&1") == 0) {
        snprintf(path, sizeof path, "%s/water_error.png", odd);
        ck_assert_msg(path_exists(path), "%s", out);
    }
    /* --jobs: each line, read by sh, gives --out exactly */
    const char *j[] = {"accuracy", "--jobs", "--out", odd, NULL};
    ck_assert_int_eq(tool_argv(j, out, sizeof out), 0);
    char *line = strtok(out, "\n");
    ck_assert_ptr_nonnull(line);
    char script[2000], words[400];
    snprintf(words, sizeof words, "%s.words", dir);
    snprintf(script, sizeof script,
             "eval \"set -- $1\"; shift $(($# - 1)); printf '%%s' \"$1\" > '%s'", words);
    const char *sh[] = {"/bin/sh", "-c", script, "sh", line, NULL};
    pid_t pid = fork();
    if (pid == 0) {
        execv(sh[0], (char *const *)sh);
        _exit(127);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    ck_assert(!path_exists(pwned));
    FILE *f = fopen(words, "r");
    ck_assert_ptr_nonnull(f);
    char got[1400];
    size_t n = fread(got, 1, sizeof got - 1, f);
    got[n] = '\0';
    fclose(f);
    unlink(words);
    snprintf(path, sizeof path, "%s/parts", odd);
    ck_assert_str_eq(got, path);
    remove_dir();
}
END_TEST

static Suite *accuracy_suite(void)
{
    Suite *s = suite_create("accuracy");
    TCase *t = tcase_create("accuracy");
    /* --quick: ~30 s of one core; 268 s of wall clock under a load of 20 on
     * 2 cores, when 240 s timed out: a guard against a hang, not a bound */
    tcase_set_timeout(t, 600);
    tcase_add_test(t, quick_study_writes_everything_and_shows_the_theory);
    tcase_add_test(t, jobs_case_and_merge_give_the_same_rows);
    tcase_add_test(t, bad_options_are_refused);
    tcase_add_test(t, merge_refuses_study_names_that_are_not_names);
    tcase_add_test(t, plot_script_runs_nothing_from_a_part);
    tcase_add_test(t, out_with_quotes_reaches_no_shell);
    tcase_add_test(t, merge_refuses_parts_that_are_not_regular_files);
    suite_add_tcase(s, t);
    return s;
}

int main(void)
{
    return ms_test_run(accuracy_suite());
}
