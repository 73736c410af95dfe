/* The report of `modesplit accuracy`: accuracy.md (one table per study,
 * observed orders, Pareto fronts) and accuracy.gp, a gnuplot script (with
 * the .dat files it reads) that draws, per study, the error against the
 * cost on log-log axes (one curve per knob) and the Pareto chart of every
 * configuration. gnuplot draws the PNGs; a user may restyle the script.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "accuracy.h"

#define MAXK 64

/* The (knob, metric) pairs whose theory gives an order of convergence
 * (the value is a resolution: error ~ value^-p). Only the standing-mode
 * frequency against cells per wavelength has one: the scheme is second
 * order in space and in time at a fixed Courant number (its phase error is
 * (k dx)^2 (1 - C^2) / 24). The other knobs have none: the Courant number
 * changes that error by (1 - C^2), not as a power; the ring front is read
 * from a drop of finite width; SPH at a fixed h / spacing is not a
 * convergent discretisation of the dam break; extraction and coupling
 * errors are set by the particles, not by the field. */
static double theory_order(const char *study, const char *knob, const char *metric)
{
    if (!strcmp(study, "waves") && !strcmp(knob, "cells_per_wavelength") &&
        strstr(metric, "standing-mode frequency"))
        return 2;
    return NAN;
}

/* Cost of a row on the study's cost axis: ms per simulated second when
 * every row of the study has it, else ms per step (extraction: one call,
 * coupler: one frame). */
static int study_uses_per_s(const acc_row *rows, int n, const char *study)
{
    for (int i = 0; i < n; ++i)
        if (!strcmp(rows[i].study, study) && !isfinite(rows[i].ms_per_s))
            return 0;
    return 1;
}

static double cost(const acc_row *r, int per_s)
{
    return per_s ? r->ms_per_s : r->ms_per_step;
}

/* Minus the least-squares slope of log(error) against log(value) over
 * the rows of (study, knob, metric); the fitted range and point count
 * when asked; NAN when < 2 points. */
static double order_of(const acc_row *rows, int n, const char *study, const char *knob,
                       const char *metric, double *lo, double *hi, int *points)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0, vlo = INFINITY, vhi = -INFINITY;
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const acc_row *r = &rows[i];
        if (strcmp(r->study, study) || strcmp(r->knob, knob) || strcmp(r->metric, metric) ||
            !(r->value > 0) || !(r->error > 0))
            continue;
        double x = log(r->value), y = log(r->error);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        vlo = fmin(vlo, r->value);
        vhi = fmax(vhi, r->value);
        ++m;
    }
    if (lo)
        *lo = vlo;
    if (hi)
        *hi = vhi;
    if (points)
        *points = m;
    if (m < 2)
        return NAN;
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

double acc_order(const acc_row *rows, int n, const char *study, const char *knob)
{
    for (int i = 0; i < n; ++i) /* the knob's first metric */
        if (!strcmp(rows[i].study, study) && !strcmp(rows[i].knob, knob))
            return order_of(rows, n, study, knob, rows[i].metric, NULL, NULL, NULL);
    return NAN;
}

/* Row i is on the Pareto front of its study: its metric is the study's
 * first, and no other configuration of the study with that metric is at
 * most as costly and at most as wrong, and better in one. */
static int on_front(const acc_row *rows, int n, int i, int per_s)
{
    double ci = cost(&rows[i], per_s), ei = rows[i].error;
    if (!isfinite(ci))
        return 0;
    for (int j = 0; j < n; ++j) /* the study's first metric */
        if (!strcmp(rows[j].study, rows[i].study)) {
            if (strcmp(rows[j].metric, rows[i].metric))
                return 0;
            break;
        }
    for (int j = 0; j < n; ++j) {
        if (j == i || strcmp(rows[j].study, rows[i].study) ||
            strcmp(rows[j].metric, rows[i].metric))
            continue;
        double cj = cost(&rows[j], per_s), ej = rows[j].error;
        if (cj <= ci && ej <= ei && (cj < ci || ej < ei))
            return 0;
    }
    return 1;
}

static int studies(const acc_row *rows, int n, const char **names)
{
    int k = 0;
    for (int i = 0; i < n; ++i) {
        int seen = 0;
        for (int j = 0; j < k; ++j)
            seen |= !strcmp(names[j], rows[i].study);
        if (!seen && k < MAXK)
            names[k++] = rows[i].study;
    }
    return k;
}

static int knobs(const acc_row *rows, int n, const char *study, const char **names)
{
    int k = 0;
    for (int i = 0; i < n; ++i) {
        if (strcmp(rows[i].study, study))
            continue;
        int seen = 0;
        for (int j = 0; j < k; ++j)
            seen |= !strcmp(names[j], rows[i].knob);
        if (!seen && k < MAXK)
            names[k++] = rows[i].knob;
    }
    return k;
}

static void fmt_num(char *buf, size_t size, double v)
{
    if (isfinite(v))
        snprintf(buf, size, "%.3g", v);
    else
        snprintf(buf, size, "–");
}

/* The metrics of a study, in the order their first rows come. */
static int metrics(const acc_row *rows, int n, const char *study, const char **names)
{
    int k = 0;
    for (int i = 0; i < n; ++i) {
        if (strcmp(rows[i].study, study))
            continue;
        int seen = 0;
        for (int j = 0; j < k; ++j)
            seen |= !strcmp(names[j], rows[i].metric);
        if (!seen && k < MAXK)
            names[k++] = rows[i].metric;
    }
    return k;
}

/* Rows of (study, knob, metric): the points of one curve. */
static int has_rows(const acc_row *rows, int n, const char *study, const char *knob,
                    const char *metric)
{
    for (int i = 0; i < n; ++i)
        if (!strcmp(rows[i].study, study) && !strcmp(rows[i].knob, knob) &&
            !strcmp(rows[i].metric, metric))
            return 1;
    return 0;
}

/* The stem of the files of a study's metric m (0: the study's first,
 * STUDY_cost.png / STUDY.dat; then STUDY_cost_SLUG.png / STUDY_SLUG.dat,
 * the slug the metric in lower-case letters, digits and '_'). */
static void metric_stem(char *buf, size_t size, const char *study, int m, const char *metric,
                        const char *prefix)
{
    int used = snprintf(buf, size, "%s%s", study, prefix);
    if (m == 0 || used < 0 || (size_t)used >= size)
        return;
    size_t k = (size_t)used;
    int gap = 1;
    for (const char *p = metric; *p && k + 2 < size; ++p) {
        char ch = *p;
        if (ch >= 'A' && ch <= 'Z')
            ch = (char)(ch - 'A' + 'a');
        if ((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9')) {
            if (gap)
                buf[k++] = '_';
            buf[k++] = ch;
            gap = 0;
        } else
            gap = 1;
    }
    buf[k] = '\0';
}

static const char *cost_label(const acc_row *rows, int n, const char *study)
{
    if (study_uses_per_s(rows, n, study))
        return "cost: ms of wall clock per simulated second (1 thread)";
    return !strcmp(study, "coupler") ? "cost: ms of wall clock per frame (1 thread)"
                                     : "cost: ms of wall clock per extraction call (1 thread)";
}

/* "Figures to quote": the sentences a user would repeat ("dam-break front
 * error X % at 4k particles for Y s per simulated second"), written from
 * the rows, so a rerun of the study refreshes them. One line per (study,
 * knob, metric) below that has rows, its points in the CSV's order. */
static const struct quote {
    const char *study, *knob, *metric;
    const char *what; /* the line's lead */
    const char *unit; /* after the knob's value, or after the size when by_size */
    int by_size;      /* "at N particles" from the size, not the knob's value */
    int percent;      /* the error as a percentage; else as it is, with err_unit */
    const char *err_unit;
    const char *ref_word; /* non-NULL: the row's reference follows, after this word */
} quotes[] = {
    {"waves", "cells_per_wavelength", "standing-mode frequency rel. error",
     "waves, standing-mode frequency error", "cells per wavelength", 0, 0, "", NULL},
    {"waves", "ring_cells_per_drop_radius", "ring front speed rel. error",
     "waves, ring front speed error", "cells per drop radius", 0, 1, "", NULL},
    {"sph", "particles", "dam-break front Z rel. RMS error",
     "SPH dam break (Tait, c = 20 m/s), front Z(T) RMS error against Martin & Moyce", "particles",
     1, 1, "", NULL},
    {"sph", "particles", "dam-break front Z RMS error after time shift",
     "the same after the best time shift", "particles", 1, 1, "", NULL},
    {"sph", "particles", "dam-break front Z best time shift T0",
     "that shift (the simulated front is ahead by T0)", "particles", 1, 0, " T units", NULL},
    {"sph", "particles", "dam-break late front dZ/dT / Ritter speed",
     "late front speed dZ/dT (T >= 2.5) over Ritter's inviscid 2 sqrt(g 2a)", "particles", 1, 0, "",
     "the experiment's"},
    {"sph", "particles", "dam-break column H rel. RMS error",
     "SPH dam break, residual column H(tau) RMS error", "particles", 1, 1, "", NULL},
    {"sph", "law_ideal_gas", "dam-break front Z rel. RMS error", "front Z error, ideal gas",
     "particles", 1, 1, "", NULL},
    {"sph", "law_tait", "dam-break front Z rel. RMS error", "front Z error, Tait", "particles", 1,
     1, "", NULL},
    {"sph", "law_dfsph", "dam-break front Z rel. RMS error", "front Z error, DFSPH", "particles", 1,
     1, "", NULL},
    {"sph", "rest_particles_ideal_gas", "hydrostatic pressure RMS / (rho0 g H)",
     "SPH at rest, pressure profile RMS error over rho0 g H, ideal gas", "particles", 1, 1, "",
     NULL},
    {"sph", "rest_particles_tait", "hydrostatic pressure RMS / (rho0 g H)",
     "SPH at rest, pressure profile RMS error over rho0 g H, Tait", "particles", 1, 1, "", NULL},
    {"sph", "rest_particles_dfsph", "mean compression at rest (interior)",
     "SPH at rest, DFSPH's mean compression of the interior", "particles", 1, 1, "", NULL},
    {"extract", "flat_field_cells", "height RMS error in spacings",
     "extraction, flat layer, height error", "field cells a side", 0, 0, " spacings", NULL},
    {"extract", "tilted_field_cells", "height RMS error in spacings",
     "extraction, tilted layer, height error", "field cells a side", 0, 0, " spacings", NULL},
    {"extract", "column_field_cells", "height RMS error in spacings",
     "extraction, settled column, height error", "field cells a side", 0, 0, " spacings", NULL},
    {"coupler", "n_surf", "sub-SPH-cell detail energy rel. error",
     "coupler, detail below the SPH cell missing", "N_surf", 0, 1, "", NULL},
};

static void fmt_cost(char *buf, size_t size, double ms, int per_s)
{
    if (!isfinite(ms))
        snprintf(buf, size, "–");
    else if (per_s && ms >= 1000)
        snprintf(buf, size, "%.3g s per simulated s", ms / 1000);
    else
        snprintf(buf, size, "%.3g ms per %s", ms, per_s ? "simulated s" : "call");
}

static void write_quotes(FILE *f, const acc_row *rows, int n)
{
    int any = 0;
    for (size_t q = 0; q < sizeof quotes / sizeof quotes[0]; ++q) {
        const struct quote *Q = &quotes[q];
        if (!has_rows(rows, n, Q->study, Q->knob, Q->metric))
            continue;
        int per_s = study_uses_per_s(rows, n, Q->study), first = 1;
        if (!any)
            fprintf(f, "## Figures to quote\n\nWritten from the rows below (costs: one thread "
                       "of the machine above).\n\n");
        any = 1;
        fprintf(f, "- %s:", Q->what);
        for (int i = 0; i < n; ++i) {
            const acc_row *r = &rows[i];
            if (strcmp(r->study, Q->study) || strcmp(r->knob, Q->knob) ||
                strcmp(r->metric, Q->metric))
                continue;
            char e[64], c[48];
            if (Q->percent)
                snprintf(e, sizeof e, "%.3g %%", 100 * r->error);
            else
                snprintf(e, sizeof e, "%.3g%s", r->error, Q->err_unit);
            if (Q->ref_word) {
                size_t u = strlen(e);
                snprintf(e + u, sizeof e - u, " (%s %.3g)", Q->ref_word, r->reference);
            }
            fmt_cost(c, sizeof c, cost(r, per_s), per_s);
            fprintf(f, "%s %s at %.4g %s (%s)", first ? "" : ";", e,
                    Q->by_size ? r->size : r->value, Q->unit, c);
            first = 0;
        }
        double want = theory_order(Q->study, Q->knob, Q->metric);
        if (isfinite(want))
            fprintf(f, "; observed order %.2f (theory %.0f)",
                    order_of(rows, n, Q->study, Q->knob, Q->metric, NULL, NULL, NULL), want);
        fprintf(f, ".\n");
    }
    if (any)
        fprintf(f, "\n");
}

static int write_md(const char *dir, const acc_row *rows, int n, const char *notes,
                    const char *machine, const char *commit, int plots)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/accuracy.md", dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        tool_error("accuracy: cannot write %s", path);
        return -1;
    }
    fprintf(f,
            "# modesplit accuracy\n\nMachine: %s (the load of the last case merged; "
            "every case's is in the notes and in the CSV's machine column). Commit: %s. "
            "Wall-clock costs are of one thread on this machine: a load average above "
            "the core count means other work shared the cores and inflated them, so "
            "costs measured under load are noisy (compare them within a case, not across "
            "cases); the errors do not depend on the load.\n\n"
            "Orders of convergence are given only where theory gives one (the waves' "
            "standing-mode frequency against cells per wavelength), fitted per knob and "
            "metric over the range stated. The Pareto column marks, among the rows of a "
            "study's first metric, those no other configuration beats on both cost and "
            "error.\n\n",
            machine, commit);
    write_quotes(f, rows, n);
    if (notes && notes[0])
        fprintf(f, "Notes:\n%s\n", notes);
    const char *st[MAXK];
    int ns = studies(rows, n, st);
    for (int s = 0; s < ns; ++s) {
        int per_s = study_uses_per_s(rows, n, st[s]);
        int water = !strcmp(st[s], "water");
        const char *ms[MAXK], *kn[MAXK];
        int nm = metrics(rows, n, st[s], ms), nk = knobs(rows, n, st[s], kn);
        fprintf(f, "## %s\n\n", st[s]);
        if (!strcmp(st[s], "sph") &&
            has_rows(rows, n, "sph", "particles", "dam-break front Z best time shift T0"))
            fprintf(f, "How to read the dam break: the front Z(T) error is mostly a lag. The "
                       "simulated front runs ahead of Martin & Moyce's from T ~ 0.8 on (the "
                       "signed errors per point are in the notes), most at T ~ 1.2-1.4; its "
                       "late speed (T >= 2.5) is close to the experiment's, and both stay under "
                       "Ritter's inviscid shallow-water front 2 sqrt(g 2a) (the `Ritter speed` "
                       "rows). Shifted by one time T0 the curves agree within the `after time "
                       "shift` rows. The residual column H(tau) at the back wall needs a much "
                       "smaller shift than the front (the notes give both), so the lag is at "
                       "the front's tip: the measured front starts slower, as the SPH "
                       "literature reports and attributes to the release (the gate) and to "
                       "friction on the dry bed, neither of which the simulation has (an "
                       "instantaneous release, frictionless walls). A finer or less viscous "
                       "run is closer to the inviscid collapse and further ahead (T0 grows), "
                       "so the unshifted error grows with the particle count while the shifted "
                       "one levels off.\n\n"
                       "How to read the column at rest: the pressure profile is averaged over "
                       "0.5 s sampled every 5 ms, because the column keeps ringing in its "
                       "vertical breathing mode (period 4 H / c); the notes give one sample's "
                       "range of slopes and the height the column lost against what its law's "
                       "compression asks.\n\n");
        if (plots && water)
            fprintf(f,
                    "![%s](%s_error.png)\n\n- `%s_error.png`: %s against wavelength, one "
                    "curve per depth.\n\n",
                    st[s], st[s], st[s], ms[0]);
        else if (plots) {
            char stem[256];
            for (int m = 0; m < nm; ++m) {
                metric_stem(stem, sizeof stem, st[s], m, ms[m], "_cost");
                fprintf(f, "![%s: %s](%s.png) ", st[s], ms[m], stem);
            }
            fprintf(f, "![%s pareto](%s_pareto.png)\n\n", st[s], st[s]);
            for (int m = 0; m < nm; ++m) {
                metric_stem(stem, sizeof stem, st[s], m, ms[m], "_cost");
                fprintf(f, "- `%s.png`: %s against %s; one curve per knob (", stem, ms[m],
                        cost_label(rows, n, st[s]) + 6);
                int first = 1;
                for (int k = 0; k < nk; ++k)
                    if (has_rows(rows, n, st[s], kn[k], ms[m])) {
                        fprintf(f, "%s%s", first ? "" : ", ", kn[k]);
                        first = 0;
                    }
                fprintf(f, ")");
                /* log axes cannot show a value <= 0 (DFSPH's mean
                 * compression can be negative): say so, not drop it */
                int hidden = 0;
                for (int i = 0; i < n; ++i)
                    hidden += !strcmp(rows[i].study, st[s]) && !strcmp(rows[i].metric, ms[m]) &&
                              !(rows[i].error > 0 && cost(&rows[i], per_s) > 0);
                if (hidden)
                    fprintf(f,
                            "; %d row%s with a value <= 0 cannot be drawn on log axes: see "
                            "the table",
                            hidden, hidden > 1 ? "s" : "");
                fprintf(f, ".\n");
            }
            fprintf(f,
                    "- `%s_pareto.png`: %s of every configuration against its cost; the "
                    "line joins the Pareto front.\n\n",
                    st[s], ms[0]);
        }
        fprintf(f,
                "| knob | value | configuration | metric | error | %s | ms per step | "
                "cells/particles | Pareto |\n|---|---|---|---|---|---|---|---|---|\n",
                per_s ? "ms per simulated s" : "ms per simulated s (n/a)");
        for (int i = 0; i < n; ++i) {
            const acc_row *r = &rows[i];
            if (strcmp(r->study, st[s]))
                continue;
            char a[32], b[32], c[32], d[32];
            fmt_num(a, sizeof a, r->error);
            fmt_num(b, sizeof b, r->ms_per_s);
            fmt_num(c, sizeof c, r->ms_per_step);
            fmt_num(d, sizeof d, r->size);
            fprintf(f, "| %s | %.4g | %s | %s | %s | %s | %s | %s | %s |\n", r->knob, r->value,
                    r->config, r->metric, a, b, c, d,
                    !water && on_front(rows, n, i, per_s) ? "**yes**" : "");
        }
        fprintf(f, "\n");
        for (int k = 0; k < nk; ++k)
            for (int m = 0; m < nm; ++m) {
                double want = theory_order(st[s], kn[k], ms[m]), lo, hi;
                int pts;
                if (!isfinite(want) || !has_rows(rows, n, st[s], kn[k], ms[m]))
                    continue;
                double p = order_of(rows, n, st[s], kn[k], ms[m], &lo, &hi, &pts);
                fprintf(f,
                        "- %s, %s: observed order %.2f (theory: %.0f), the least-squares "
                        "slope of log error against log %s over %d points, %.4g to %.4g.\n",
                        kn[k], ms[m], p, want, kn[k], pts, lo, hi);
            }
        fprintf(f, "\n");
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* Text of a part file (a study, knob or metric name) as a gnuplot
 * string: single-quoted, because gnuplot runs `commands` in backquotes and
 * expands @macros anywhere on a line but inside single quotes; a quote
 * inside is doubled (gnuplot's escape there), a control character becomes
 * '?' (a line break would end the command). */
static void gp_string(FILE *gp, const char *text)
{
    fputc('\'', gp);
    for (const char *p = text; *p; ++p) {
        if (*p == '\'')
            fputs("''", gp);
        else
            fputc((unsigned char)*p < 0x20 || *p == 0x7f ? '?' : *p, gp);
    }
    fputc('\'', gp);
}

/* A comment line's text: only characters with no meaning to gnuplot. */
static void gp_comment_text(FILE *gp, const char *text)
{
    for (const char *p = text; *p; ++p) {
        const char c = *p;
        const int plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' || c == '+' ||
                          c == ' ';
        fputc(plain ? c : '?', gp);
    }
}

static int write_plots(const char *dir, const acc_row *rows, int n, const char *commit)
{
    char path[1200], stem[256], png[256];
    snprintf(path, sizeof path, "%s/accuracy.gp", dir);
    FILE *gp = fopen(path, "w");
    if (!gp) {
        tool_error("accuracy: cannot write %s", path);
        return -1;
    }
    fputs("# gnuplot script written by modesplit accuracy (commit ", gp);
    gp_comment_text(gp, commit);
    fputs("); run it in this\n"
          "# directory: gnuplot accuracy.gp. Restyle freely.\n"
          "set terminal pngcairo noenhanced size 1000,650 font 'sans,11'\n"
          "set logscale xy\nset format xy '%g'\nset grid\nset key outside right\n",
          gp);
    const char *st[MAXK];
    int ns = studies(rows, n, st);
    for (int s = 0; s < ns; ++s) {
        int per_s = study_uses_per_s(rows, n, st[s]);
        int water = !strcmp(st[s], "water");
        const char *kn[MAXK], *ms[MAXK];
        int nk = knobs(rows, n, st[s], kn), nm = metrics(rows, n, st[s], ms);
        /* one plot per metric: its rows against cost (water: against the
         * wavelength), one curve per knob that has the metric */
        for (int m = 0; m < nm; ++m) {
            metric_stem(stem, sizeof stem, st[s], m, ms[m], "");
            snprintf(path, sizeof path, "%s/%s.dat", dir, stem);
            FILE *d = fopen(path, "w");
            if (!d) {
                tool_error("accuracy: cannot write %s", path);
                fclose(gp);
                return -1;
            }
            int idx = 0;
            for (int k = 0; k < nk; ++k) {
                if (!has_rows(rows, n, st[s], kn[k], ms[m]))
                    continue;
                fprintf(d, "# %s, %s: %s error value\n", kn[k], ms[m],
                        water ? "wavelength" : "cost");
                for (int i = 0; i < n; ++i)
                    if (!strcmp(rows[i].study, st[s]) && !strcmp(rows[i].knob, kn[k]) &&
                        !strcmp(rows[i].metric, ms[m]))
                        fprintf(d, "%.6g %.6g %.6g\n",
                                water ? rows[i].value : cost(&rows[i], per_s), rows[i].error,
                                rows[i].value);
                fprintf(d, "\n\n");
                ++idx;
            }
            fclose(d);
            /* names from the parts only as gp_string writes them */
            if (water) {
                snprintf(png, sizeof png, "%s_error.png", st[s]);
                fputs("set output ", gp);
                gp_string(gp, png);
                fputs("\nset title 'water: the paper''s non-dispersive eq. 2 against real "
                      "capillary-gravity waves, one curve per depth'\n"
                      "set xlabel 'wavelength (m)'\nset ylabel ",
                      gp);
                gp_string(gp, ms[m]);
            } else {
                char title[256];
                metric_stem(png, sizeof png, st[s], m, ms[m], "_cost");
                strncat(png, ".png", sizeof png - strlen(png) - 1);
                snprintf(title, sizeof title, "%s: %s against cost, one curve per knob", st[s],
                         ms[m]);
                fputs("set output ", gp);
                gp_string(gp, png);
                fputs("\nset title ", gp);
                gp_string(gp, title);
                fputs("\nset xlabel ", gp);
                gp_string(gp, cost_label(rows, n, st[s]));
                fputs("\nset ylabel ", gp);
                gp_string(gp, ms[m]);
            }
            fprintf(gp, "\nplot ");
            idx = 0;
            for (int k = 0; k < nk; ++k)
                if (has_rows(rows, n, st[s], kn[k], ms[m])) {
                    char dat[300];
                    snprintf(dat, sizeof dat, "%s.dat", stem);
                    fputs(idx ? ", \\\n     " : "", gp);
                    gp_string(gp, dat);
                    fprintf(gp, " index %d using 1:2 with linespoints pt 7 title ", idx);
                    gp_string(gp, kn[k]);
                    ++idx;
                }
            fprintf(gp, "\n");
        }
        if (water)
            continue;
        /* the Pareto chart of the study's first metric: every
         * configuration, the front joined */
        const char *metric = ms[0];
        snprintf(path, sizeof path, "%s/%s_pareto.dat", dir, st[s]);
        FILE *d = fopen(path, "w");
        if (!d) {
            tool_error("accuracy: cannot write %s", path);
            fclose(gp);
            return -1;
        }
        fprintf(d, "# every configuration (%s): cost error label\n", metric);
        for (int i = 0; i < n; ++i)
            if (!strcmp(rows[i].study, st[s]) && !strcmp(rows[i].metric, metric))
                fprintf(d, "%.6g %.6g \"%s=%g\"\n", cost(&rows[i], per_s), rows[i].error,
                        rows[i].knob, rows[i].value);
        fprintf(d, "\n\n# the front, by cost\n");
        double last = -1;
        for (;;) {
            int best = -1;
            for (int i = 0; i < n; ++i)
                if (!strcmp(rows[i].study, st[s]) && on_front(rows, n, i, per_s) &&
                    cost(&rows[i], per_s) > last &&
                    (best < 0 || cost(&rows[i], per_s) < cost(&rows[best], per_s)))
                    best = i;
            if (best < 0)
                break;
            last = cost(&rows[best], per_s);
            fprintf(d, "%.6g %.6g \"%s=%g\"\n", last, rows[best].error, rows[best].knob,
                    rows[best].value);
        }
        fclose(d);
        /* the title's line break is a double-quoted "\n" of its own,
         * joined with gnuplot's string operator: no name from a part is
         * ever inside double quotes */
        char title[256], out[300], dat[300];
        snprintf(title, sizeof title, "%s: %s, every configuration;", st[s], metric);
        snprintf(out, sizeof out, "%s_pareto.png", st[s]);
        snprintf(dat, sizeof dat, "%s_pareto.dat", st[s]);
        fputs("set output ", gp);
        gp_string(gp, out);
        fputs("\nset title ", gp);
        gp_string(gp, title);
        fputs(" . \"\\n\" . 'the line joins those no other beats on both cost and error'\n"
              "set xlabel ",
              gp);
        gp_string(gp, cost_label(rows, n, st[s]));
        fputs("\nset ylabel ", gp);
        gp_string(gp, metric);
        fputs("\nplot ", gp);
        gp_string(gp, dat);
        fputs(" index 0 using 1:2 with points pt 6 title 'configuration', \\\n     ", gp);
        gp_string(gp, dat);
        fputs(" index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \\\n     ", gp);
        gp_string(gp, dat);
        fputs(" index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle\n", gp);
    }
    return fclose(gp) == 0 ? 0 : -1;
}

/* gnuplot accuracy.gp in dir, started without a shell (no path of ours is
 * ever parsed by one): 0 it drew, 1 there is no gnuplot, -1 it failed. */
static int run_gnuplot(const char *dir)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        if (chdir(dir) != 0)
            _exit(126);
        execlp("gnuplot", "gnuplot", "accuracy.gp", (char *)NULL);
        _exit(errno == ENOENT ? 127 : 126);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        return 1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : -1;
}

int acc_report(const char *dir, const acc_row *rows, int n, const char *notes, const char *machine,
               const char *commit, int *plotted)
{
    *plotted = 0;
    if (write_plots(dir, rows, n, commit) != 0)
        return -1;
    int drawn = run_gnuplot(dir);
    if (drawn < 0) {
        tool_error("accuracy: gnuplot failed on %s/accuracy.gp", dir);
        return -1;
    }
    if (drawn == 0) {
        *plotted = 1;
    } else {
        tool_error("accuracy: gnuplot not found (Debian: gnuplot-nox): wrote the CSV, the "
                   "tables and %s/accuracy.gp, but no PNG plots",
                   dir);
    }
    return write_md(dir, rows, n, notes, machine, commit, *plotted);
}
