/* The report of `modesplit accuracy`: accuracy.md (one table per study,
 * observed orders, Pareto fronts) and accuracy.gp, a gnuplot script (with
 * the .dat files it reads) that draws, per study, the error against the
 * cost on log-log axes (one curve per knob) and the Pareto chart of every
 * configuration. gnuplot draws the PNGs; a user may restyle the script.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accuracy.h"

#define MAXK 64

/* Knobs whose theory gives an order of convergence (the value is a
 * resolution: error ~ value^-p). */
static double theory_order(const char *study, const char *knob)
{
    if (!strcmp(study, "waves") && !strcmp(knob, "cells_per_wavelength"))
        return 2; /* second-order central differences in space and time */
    return NAN;
}

/* The metric a (study, knob) curve plots: that of its first row. */
static int is_primary(const acc_row *rows, int n, int i)
{
    for (int j = 0; j < n; ++j)
        if (!strcmp(rows[j].study, rows[i].study) && !strcmp(rows[j].knob, rows[i].knob))
            return !strcmp(rows[j].metric, rows[i].metric);
    return 0;
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

double acc_order(const acc_row *rows, int n, const char *study, const char *knob)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const acc_row *r = &rows[i];
        if (strcmp(r->study, study) || strcmp(r->knob, knob) || !is_primary(rows, n, i) ||
            !(r->value > 0) || !(r->error > 0))
            continue;
        double x = log(r->value), y = log(r->error);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++m;
    }
    if (m < 2)
        return NAN;
    return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/* Row i is on the Pareto front of its study: no other configuration of
 * the study (primary metrics) is at most as costly and at most as wrong,
 * and better in one. */
static int on_front(const acc_row *rows, int n, int i, int per_s)
{
    double ci = cost(&rows[i], per_s), ei = rows[i].error;
    if (!isfinite(ci) || !is_primary(rows, n, i))
        return 0;
    for (int j = 0; j < n; ++j) {
        if (j == i || strcmp(rows[j].study, rows[i].study) || !is_primary(rows, n, j) ||
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
    fprintf(f, "# modesplit accuracy\n\nMachine: %s (the load of the last case merged; "
               "every case's is in the notes and in the CSV's machine column). Commit: %s. "
               "Wall-clock costs are of one thread on this machine: a load average above "
               "the core count means other work shared the cores and inflated them.\n\n",
            machine, commit);
    if (notes && notes[0])
        fprintf(f, "Notes:\n%s\n", notes);
    const char *st[MAXK];
    int ns = studies(rows, n, st);
    for (int s = 0; s < ns; ++s) {
        int per_s = study_uses_per_s(rows, n, st[s]);
        int water = !strcmp(st[s], "water");
        fprintf(f, "## %s\n\n", st[s]);
        if (plots)
            fprintf(f, water ? "![%s](%s_error.png)\n\n" : "![%s](%s_cost.png) ![%s pareto](%s_pareto.png)\n\n",
                    st[s], st[s], st[s], st[s]);
        fprintf(f, "| knob | value | configuration | metric | error | %s | ms per step | "
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
        const char *kn[MAXK];
        int nk = knobs(rows, n, st[s], kn);
        fprintf(f, "\n");
        for (int k = 0; k < nk; ++k) {
            double p = acc_order(rows, n, st[s], kn[k]), want = theory_order(st[s], kn[k]);
            if (isfinite(want))
                fprintf(f, "- %s: observed order %.2f (theory: %.0f).\n", kn[k], p, want);
            else if (isfinite(p) && !water)
                fprintf(f, "- %s: error ~ value^%.2f (no theoretical order).\n", kn[k], -p);
        }
        fprintf(f, "\n");
    }
    return fclose(f) == 0 ? 0 : -1;
}

static int write_plots(const char *dir, const acc_row *rows, int n, const char *commit)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/accuracy.gp", dir);
    FILE *gp = fopen(path, "w");
    if (!gp) {
        tool_error("accuracy: cannot write %s", path);
        return -1;
    }
    fprintf(gp, "# gnuplot script written by `modesplit accuracy` (commit %s); run it in this\n"
                "# directory: gnuplot accuracy.gp. Restyle freely.\n"
                "set terminal pngcairo noenhanced size 1000,650 font 'sans,11'\n"
                "set logscale xy\nset grid\nset key outside right\n",
            commit);
    const char *st[MAXK];
    int ns = studies(rows, n, st);
    for (int s = 0; s < ns; ++s) {
        int per_s = study_uses_per_s(rows, n, st[s]);
        int water = !strcmp(st[s], "water");
        const char *kn[MAXK];
        int nk = knobs(rows, n, st[s], kn);
        snprintf(path, sizeof path, "%s/%s.dat", dir, st[s]);
        FILE *d = fopen(path, "w");
        if (!d) {
            fclose(gp);
            return -1;
        }
        for (int k = 0; k < nk; ++k) {
            fprintf(d, "# %s: cost error value\n", kn[k]);
            for (int i = 0; i < n; ++i)
                if (!strcmp(rows[i].study, st[s]) && !strcmp(rows[i].knob, kn[k]) &&
                    is_primary(rows, n, i))
                    fprintf(d, "%.6g %.6g %.6g\n", water ? rows[i].value : cost(&rows[i], per_s),
                            rows[i].error, rows[i].value);
            fprintf(d, "\n\n");
        }
        fclose(d);
        const char *metric = "";
        for (int i = 0; i < n; ++i)
            if (!strcmp(rows[i].study, st[s])) {
                metric = rows[i].metric;
                break;
            }
        if (water) {
            fprintf(gp, "set output '%s_error.png'\nset title 'water: the paper''s non-dispersive "
                        "model (eq. 2) against real capillary-gravity waves'\n"
                        "set xlabel 'wavelength (m)'\nset ylabel 'phase speed rel. error'\n",
                    st[s]);
        } else {
            fprintf(gp, "set output '%s_cost.png'\nset title '%s: %s against cost'\n"
                        "set xlabel '%s'\nset ylabel 'error'\n",
                    st[s], st[s], metric,
                    per_s ? "cost (ms per simulated second)"
                          : !strcmp(st[s], "coupler") ? "cost (ms per frame)"
                                                       : "cost (ms per call)");
        }
        fprintf(gp, "plot ");
        for (int k = 0; k < nk; ++k)
            fprintf(gp, "%s'%s.dat' index %d using 1:2 with linespoints pt 7 title '%s'",
                    k ? ", \\\n     " : "", st[s], k, kn[k]);
        fprintf(gp, "\n");
        if (water)
            continue;
        /* the Pareto chart: every configuration, the front joined */
        snprintf(path, sizeof path, "%s/%s_pareto.dat", dir, st[s]);
        d = fopen(path, "w");
        if (!d) {
            fclose(gp);
            return -1;
        }
        fprintf(d, "# every configuration: cost error label\n");
        for (int i = 0; i < n; ++i)
            if (!strcmp(rows[i].study, st[s]) && is_primary(rows, n, i) &&
                !strcmp(rows[i].metric, metric))
                fprintf(d, "%.6g %.6g \"%s=%g\"\n", cost(&rows[i], per_s), rows[i].error,
                        rows[i].knob, rows[i].value);
        fprintf(d, "\n\n# the front, by cost\n");
        /* front points in increasing cost */
        double last = -1;
        for (;;) {
            int best = -1;
            for (int i = 0; i < n; ++i)
                if (!strcmp(rows[i].study, st[s]) && !strcmp(rows[i].metric, metric) &&
                    on_front(rows, n, i, per_s) && cost(&rows[i], per_s) > last &&
                    (best < 0 || cost(&rows[i], per_s) < cost(&rows[best], per_s)))
                    best = i;
            if (best < 0)
                break;
            last = cost(&rows[best], per_s);
            fprintf(d, "%.6g %.6g \"%s=%g\"\n", last, rows[best].error, rows[best].knob,
                    rows[best].value);
        }
        fclose(d);
        fprintf(gp, "set output '%s_pareto.png'\nset title '%s: every configuration; the "
                    "line joins those no other beats on both cost and error'\n"
                    "plot '%s_pareto.dat' index 0 using 1:2 with points pt 6 title 'configuration', \\\n"
                    "     '%s_pareto.dat' index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \\\n"
                    "     '%s_pareto.dat' index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle\n",
                st[s], st[s], st[s], st[s], st[s]);
    }
    return fclose(gp) == 0 ? 0 : -1;
}

int acc_report(const char *dir, const acc_row *rows, int n, const char *notes,
               const char *machine, const char *commit, int *plotted)
{
    *plotted = 0;
    if (write_plots(dir, rows, n, commit) != 0)
        return -1;
    char cmd[1400];
    int have = system("command -v gnuplot >/dev/null 2>&1") == 0;
    if (have) {
        snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot accuracy.gp", dir);
        if (system(cmd) != 0) {
            tool_error("accuracy: gnuplot failed on %s/accuracy.gp", dir);
            return -1;
        }
        *plotted = 1;
    } else {
        tool_error("accuracy: gnuplot not found (Debian: gnuplot-nox): wrote the CSV, the "
                   "tables and %s/accuracy.gp, but no PNG plots", dir);
    }
    return write_md(dir, rows, n, notes, machine, commit, *plotted);
}
