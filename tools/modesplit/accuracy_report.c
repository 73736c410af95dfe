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

/* Cost of a row on the study's cost axis, in CPU time (the wall clock a
 * loaded machine inflates is in the CSV beside it): ms per simulated
 * second when every row of the study has it, else ms per step
 * (extraction: one call, coupler: one frame). */
static int study_uses_per_s(const acc_row *rows, int n, const char *study)
{
    for (int i = 0; i < n; ++i)
        if (!strcmp(rows[i].study, study) && !isfinite(rows[i].cpu_ms_per_s))
            return 0;
    return 1;
}

static double cost(const acc_row *r, int per_s)
{
    return per_s ? r->cpu_ms_per_s : r->cpu_ms_per_step;
}

/* The Pareto charts: per study the metric that trades against cost and,
 * where a study mixes test shapes, one chart per shape (the rows whose
 * knob starts with prefix). A study not listed gets one chart of its
 * first metric, STUDY_pareto.png. The SPH dam break's front is not one:
 * its error is a start lag that sits at 8-12 % at every cost. */
typedef struct pareto_spec {
    const char *study, *metric, *prefix, *stem;
} pareto_spec;
static const pareto_spec pareto_specs[] = {
    {"sph", "dam-break column H rel. RMS error", "", "sph_pareto"},
    {"sph", "dam-break max compression", "", "sph_pareto_compression"},
    {"extract", "height RMS error in spacings", "flat", "extract_pareto_flat"},
    {"extract", "height RMS error in spacings", "tilted", "extract_pareto_tilted"},
    {"extract", "height RMS error in spacings", "column", "extract_pareto_column"},
};
#define NSPECS ((int)(sizeof pareto_specs / sizeof pareto_specs[0]))

/* The specs of a study into out (the default one in *dflt when it has
 * none listed); their count. */
static int specs_of(const char *study, const char *first_metric, pareto_spec *dflt,
                    const pareto_spec **out)
{
    int k = 0;
    for (int i = 0; i < NSPECS; ++i)
        if (!strcmp(pareto_specs[i].study, study))
            out[k++] = &pareto_specs[i];
    if (k == 0) {
        static char stems[MAXK][48];
        static int used;
        char *stem = stems[used++ % MAXK];
        snprintf(stem, 48, "%s_pareto", study);
        *dflt = (pareto_spec){study, first_metric, "", stem};
        out[k++] = dflt;
    }
    return k;
}

static int in_spec(const acc_row *r, const pareto_spec *p)
{
    return !strcmp(r->study, p->study) && !strcmp(r->metric, p->metric) &&
           !strncmp(r->knob, p->prefix, strlen(p->prefix));
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

/* Row i is on the Pareto front of spec p: no other row of p is at most
 * as costly and at most as wrong, and better in one. */
static int on_front(const acc_row *rows, int n, int i, int per_s, const pareto_spec *p)
{
    double ci = cost(&rows[i], per_s), ei = rows[i].error;
    if (!in_spec(&rows[i], p) || !isfinite(ci) || !isfinite(ei))
        return 0;
    for (int j = 0; j < n; ++j) {
        if (j == i || !in_spec(&rows[j], p))
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
        return "cost: CPU time per simulated second (ms, 1 thread)";
    return !strcmp(study, "coupler") ? "cost: CPU time of the wave stages per frame (ms, 1 thread)"
                                     : "cost: CPU time per extraction call (ms, 1 thread)";
}

/* A metric with its unit, for an axis. */
static void metric_label(char *buf, size_t size, const char *metric)
{
    const char *unit = "relative, 0.01 = 1 %";
    if (strstr(metric, "in spacings"))
        unit = "particle spacings";
    else if (strstr(metric, "time shift T0"))
        unit = "T = t sqrt(2 g / a)";
    else if (strstr(metric, "Ritter"))
        unit = "ratio";
    else if (strstr(metric, "rho0 g H"))
        unit = "fraction of rho0 g H";
    snprintf(buf, size, "%s (%s)", metric, unit);
}

/* A knob as a legend names it. */
static void knob_label(char *buf, size_t size, const char *knob)
{
    static const struct {
        const char *knob, *label;
    } names[] = {
        {"cells_per_wavelength", "cells per wavelength"},
        {"courant", "Courant number"},
        {"ring_cells_per_drop_radius", "cells per drop radius"},
        {"particles", "Tait c0 = 20 m/s, by particle count"},
        {"law_ideal_gas", "ideal gas sqrt(k) = 20 m/s, by particle count"},
        {"law_tait", "Tait c0 = 20 m/s, by particle count"},
        {"law_dfsph", "DFSPH 0.1 %, by particle count"},
        {"sound_speed_ideal_gas", "ideal gas: sqrt(k) (m/s)"},
        {"sound_speed_tait", "Tait: sound speed c0 (m/s)"},
        {"max_density_error_dfsph", "DFSPH: max density error"},
        {"courant_ideal_gas", "ideal gas: Courant factor"},
        {"courant_tait", "Tait: Courant factor"},
        {"courant_dfsph", "DFSPH: Courant factor"},
        {"rest_particles_ideal_gas", "ideal gas at rest, by particle count"},
        {"rest_particles_tait", "Tait at rest, by particle count"},
        {"rest_particles_dfsph", "DFSPH at rest, by particle count"},
        {"rest_sound_speed_ideal_gas", "ideal gas at rest: sqrt(k) (m/s)"},
        {"rest_sound_speed_tait", "Tait at rest: sound speed c0 (m/s)"},
        {"rest_max_density_error_dfsph", "DFSPH at rest: max density error"},
        {"rest_courant_ideal_gas", "ideal gas at rest: Courant factor"},
        {"rest_courant_tait", "Tait at rest: Courant factor"},
        {"rest_courant_dfsph", "DFSPH at rest: Courant factor"},
        {"lambda_m_model_wave", "eq. 2 (surface.model wave)"},
        {"lambda_m_model_dispersive", "dispersive (surface.model dispersive)"},
        {"n_surf", "N_surf (wave cells per SPH cell)"},
        {"n_time", "N_time (wave steps per SPH step)"},
        {"two_way_gain", "two-way coupling gain"},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (!strcmp(knob, names[i].knob)) {
            snprintf(buf, size, "%s", names[i].label);
            return;
        }
    /* extraction: SHAPE[_fine]_field_cells, SHAPE[_fine]_smoothing_passes */
    snprintf(buf, size, "%s", knob);
    for (char *p = buf; *p; ++p)
        if (*p == '_')
            *p = ' ';
}

/* The curves of a plot: a knob's rows, split by particle count when the
 * knob was swept at several (several values at one size). */
typedef struct curve {
    const char *knob;
    double size; /* NAN: every size */
} curve;

static int split_by_size(const acc_row *rows, int n, const char *study, const char *knob,
                         const char *metric)
{
    int sizes = 0; /* more than one particle / cell count */
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            sizes |= !strcmp(rows[i].study, study) && !strcmp(rows[i].knob, knob) &&
                     !strcmp(rows[i].metric, metric) && !strcmp(rows[j].study, study) &&
                     !strcmp(rows[j].knob, knob) && !strcmp(rows[j].metric, metric) &&
                     rows[i].size != rows[j].size;
    for (int i = 0; sizes && i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (!strcmp(rows[i].study, study) && !strcmp(rows[i].knob, knob) &&
                !strcmp(rows[i].metric, metric) && !strcmp(rows[j].study, study) &&
                !strcmp(rows[j].knob, knob) && !strcmp(rows[j].metric, metric) &&
                rows[i].size == rows[j].size && rows[i].value != rows[j].value)
                return 1;
    return 0;
}

static int curves_of(const acc_row *rows, int n, const char *study, const char *metric, curve *out,
                     int max)
{
    const char *kn[MAXK];
    int nk = knobs(rows, n, study, kn), m = 0;
    for (int k = 0; k < nk; ++k) {
        if (!has_rows(rows, n, study, kn[k], metric))
            continue;
        if (!split_by_size(rows, n, study, kn[k], metric)) {
            if (m < max)
                out[m++] = (curve){kn[k], NAN};
            continue;
        }
        for (int i = 0; i < n; ++i) {
            const acc_row *r = &rows[i];
            if (strcmp(r->study, study) || strcmp(r->knob, kn[k]) || strcmp(r->metric, metric))
                continue;
            int seen = 0;
            for (int j = 0; j < m; ++j)
                seen |= out[j].knob == kn[k] && out[j].size == r->size;
            if (!seen && m < max)
                out[m++] = (curve){kn[k], r->size};
        }
    }
    return m;
}

static int in_curve(const acc_row *r, const char *study, const char *metric, const curve *cv)
{
    return !strcmp(r->study, study) && !strcmp(r->knob, cv->knob) && !strcmp(r->metric, metric) &&
           (isnan(cv->size) || r->size == cv->size);
}

/* A point's label: the knob's value, or the particle / cell count when
 * the curve runs over that count. */
static void point_label(char *buf, size_t size, const acc_row *r, const curve *cv, int by_count)
{
    (void)cv;
    if (by_count)
        snprintf(buf, size, r->size >= 1e4 ? "%.0fk" : "%.0f",
                 r->size >= 1e4 ? r->size / 1e3 : r->size);
    else
        snprintf(buf, size, "%g", r->value);
}

/* The knob's rows run over the particle / cell count: its value is the
 * count, or one value at every count (a law at several counts). */
static int runs_by_count(const acc_row *rows, int n, const char *study, const curve *cv,
                         const char *metric)
{
    int eq = 1, same = 1, first = -1;
    for (int i = 0; i < n; ++i)
        if (in_curve(&rows[i], study, metric, cv)) {
            eq &= rows[i].value == rows[i].size;
            if (first < 0)
                first = i;
            else
                same &= rows[i].value == rows[first].value;
        }
    return (eq || same) && strcmp(study, "waves") != 0 && strstr(cv->knob, "field_cells") == NULL;
}

/* Axes: log where the plotted range spans a decade or more, else linear. */
static void gp_axes(FILE *gp, double xlo, double xhi, double ylo, double yhi)
{
    fprintf(gp, "\n%s x\n%s y\n", xlo > 0 && xhi >= 10 * xlo ? "set logscale" : "unset logscale",
            ylo > 0 && yhi >= 10 * ylo ? "set logscale" : "unset logscale");
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
    {"waves", "current_u_over_c", "packet speed rel. error vs c + U",
     "waves on a uniform current U, packet speed error against c + U", "U / c", 0, 1, "", NULL},
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
    {"sph", "law_ideal_gas", "dam-break column H rel. RMS error", "column H error, ideal gas",
     "particles", 1, 1, "", NULL},
    {"sph", "law_tait", "dam-break column H rel. RMS error", "column H error, Tait", "particles", 1,
     1, "", NULL},
    {"sph", "law_dfsph", "dam-break column H rel. RMS error", "column H error, DFSPH", "particles",
     1, 1, "", NULL},
    {"sph", "law_ideal_gas", "dam-break max compression", "max compression, ideal gas", "particles",
     1, 1, "", NULL},
    {"sph", "law_tait", "dam-break max compression", "max compression, Tait", "particles", 1, 1, "",
     NULL},
    {"sph", "law_dfsph", "dam-break max compression", "max compression, DFSPH", "particles", 1, 1,
     "", NULL},
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
    {"coupler", "n_surf", "sub-SPH-cell spectrum rel. error",
     "coupler, the band spectrum below the SPH cell against the N_surf 16 reference", "N_surf", 0,
     1, "", NULL},
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
            fprintf(f, "## Figures to quote\n\nWritten from the rows below (costs: CPU time "
                       "of one thread of the machine above).\n\n");
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

/* Row i is on a Pareto front of its study. */
static int front_any(const acc_row *rows, int n, int i, int per_s)
{
    const char *ms[MAXK];
    metrics(rows, n, rows[i].study, ms);
    pareto_spec dflt;
    const pareto_spec *sp[NSPECS + 1];
    int np = specs_of(rows[i].study, ms[0], &dflt, sp);
    for (int k = 0; k < np; ++k)
        if (on_front(rows, n, i, per_s, sp[k]))
            return 1;
    return 0;
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
            "every case's is in the notes and in the CSV's machine column). Commit: %s.\n\n"
            "Costs are CPU time: the CPU time of the thread that did the work "
            "(CLOCK_THREAD_CPUTIME_ID; every case runs its sim with one thread, on the "
            "caller), read around the library calls the case times (the CSV's cpu_ms_* "
            "columns; its cost_method column says how each row's was taken). A loaded "
            "machine inflates the wall clock (the wall_ms_* columns) most, but a thread's "
            "CPU time too (caches flushed by other work, a busy sibling hyperthread), so "
            "each piece of work is timed 3 times close together and the least counts: every "
            "SPH frame (dam break, column at rest, coupler) is run 3 times from a snapshot "
            "of the sim (ms_sim_restore: the same bytes, so the errors are those of one "
            "run); a wave run 3 times whole; a surface model's cost per cell 3 times per 16 "
            "steps; an extraction call is the median of 5. The first, cold run of each is "
            "thus not counted. The errors do not depend on the load: `make check` compares "
            "the quick study's rows with these.\n\n"
            "Orders of convergence are given only where theory gives one (the waves' "
            "standing-mode frequency against cells per wavelength), fitted per knob and "
            "metric over the range stated. The Pareto column marks the rows no other "
            "configuration beats on both cost and error, on the metric that trades: the "
            "residual column H(tau) and the max compression for the SPH dam break (its "
            "front's error is a start lag that no setting removes), one test shape at a "
            "time for the extraction, the first metric for the others.\n\n",
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
        if (plots && water) {
            fprintf(f,
                    "![%s](%s_error.png)\n\n- `%s_error.png`: %s against wavelength, one "
                    "curve per depth.\n",
                    st[s], st[s], st[s], ms[0]);
            for (int m = 1; m < nm; ++m) {
                char stem[256];
                metric_stem(stem, sizeof stem, st[s], m, ms[m], "_error");
                fprintf(f,
                        "- `%s.png`: %s against wavelength, one curve per surface model, its "
                        "CPU time per cell per step in the legend.\n",
                        stem, ms[m]);
            }
            fputs("\n", f);
        } else if (plots) {
            char stem[256];
            for (int m = 0; m < nm; ++m) {
                metric_stem(stem, sizeof stem, st[s], m, ms[m], "_cost");
                fprintf(f, "![%s: %s](%s.png) ", st[s], ms[m], stem);
            }
            pareto_spec dflt;
            const pareto_spec *sp[NSPECS + 1];
            int np = specs_of(st[s], ms[0], &dflt, sp);
            for (int k = 0; k < np; ++k)
                fprintf(f, "![%s: %s](%s.png) ", st[s], sp[k]->metric, sp[k]->stem);
            if (!strcmp(st[s], "sph"))
                fprintf(f, "![sph: compression by solver](sph_solvers_compression.png) "
                           "![sph: column by solver](sph_solvers_column.png) "
                           "![sph: compression at rest by solver]"
                           "(sph_solvers_rest_compression.png)");
            fprintf(f, "\n\n");
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
            for (int k = 0; k < np; ++k)
                fprintf(f,
                        "- `%s.png`: %s of every configuration%s%s against its cost; the line "
                        "joins the Pareto front.\n",
                        sp[k]->stem, sp[k]->metric, sp[k]->prefix[0] ? " of knobs " : "",
                        sp[k]->prefix);
            if (!strcmp(st[s], "sph"))
                fprintf(f, "- `sph_solvers_compression.png`, `sph_solvers_column.png`: the dam "
                           "break's max compression and residual-column error against cost, "
                           "every configuration of each solver and its front; "
                           "`sph_solvers_rest_compression.png` the same for the column at "
                           "rest's max compression.\n");
            fprintf(f, "\n");
        }
        fprintf(f,
                "| knob | value | configuration | metric | error | %s | CPU ms per step | "
                "cells/particles | Pareto |\n|---|---|---|---|---|---|---|---|---|\n",
                per_s ? "CPU ms per simulated s" : "CPU ms per simulated s (n/a)");
        for (int i = 0; i < n; ++i) {
            const acc_row *r = &rows[i];
            if (strcmp(r->study, st[s]))
                continue;
            char a[32], b[32], c[32], d[32];
            fmt_num(a, sizeof a, r->error);
            fmt_num(b, sizeof b, r->cpu_ms_per_s);
            fmt_num(c, sizeof c, r->cpu_ms_per_step);
            fmt_num(d, sizeof d, r->size);
            fprintf(f, "| %s | %.4g | %s | %s | %s | %s | %s | %s | %s |\n", r->knob, r->value,
                    r->config, r->metric, a, b, c, d,
                    !water && front_any(rows, n, i, per_s) ? "**yes**" : "");
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

/* A configuration as a point's label: for the SPH dam break the solver,
 * the swept setting (c = sound speed, e = DFSPH's max density error, C =
 * Courant factor) and the particle count; else knob=value. */
static void config_label(char *buf, size_t size, const acc_row *r, int with_solver)
{
    const char *k = r->knob;
    if (strcmp(r->study, "sph") != 0) {
        snprintf(buf, size, "%s=%g", k, r->value);
        return;
    }
    const char *solver = !strncmp(r->config, "ideal_gas", 9) ? "ideal gas "
                         : !strncmp(r->config, "tait", 4)    ? "Tait "
                         : !strncmp(r->config, "dfsph", 5)   ? "DFSPH "
                                                             : "";
    const char *sym = strstr(k, "sound")     ? "c="
                      : strstr(k, "density") ? "e="
                      : strstr(k, "courant") ? "C="
                                             : NULL;
    char count[32];
    snprintf(count, sizeof count, r->size >= 1e4 ? "%.0fk p" : "%.0f p",
             r->size >= 1e4 ? r->size / 1e3 : r->size);
    if (sym)
        snprintf(buf, size, "%s%s%g, %s", with_solver ? solver : "", sym, r->value, count);
    else
        snprintf(buf, size, "%s%s", with_solver ? solver : "", count);
}

/* The Pareto chart of spec p: every row of it, the front joined and
 * labelled with its knobs' values; dat and script lines. */
static int write_pareto(FILE *gp, const char *dir, const acc_row *rows, int n, int per_s,
                        const pareto_spec *p)
{
    char path[1200], dat[300], out[300], ylabel[160];
    snprintf(dat, sizeof dat, "%s.dat", p->stem);
    snprintf(out, sizeof out, "%s.png", p->stem);
    snprintf(path, sizeof path, "%s/%s", dir, dat);
    FILE *d = fopen(path, "w");
    if (!d) {
        tool_error("accuracy: cannot write %s", path);
        return -1;
    }
    double xlo = INFINITY, xhi = 0, ylo = INFINITY, yhi = 0;
    fprintf(d, "# every configuration (%s): cost error label\n", p->metric);
    for (int i = 0; i < n; ++i)
        if (in_spec(&rows[i], p)) {
            double c = cost(&rows[i], per_s), e = rows[i].error;
            fprintf(d, "%.6g %.6g \"%s=%g\"\n", c, e, rows[i].knob, rows[i].value);
            if (c > 0 && e > 0) {
                xlo = fmin(xlo, c);
                xhi = fmax(xhi, c);
                ylo = fmin(ylo, e);
                yhi = fmax(yhi, e);
            }
        }
    fprintf(d, "\n\n# the front, by cost\n");
    double last = -1;
    for (;;) {
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (on_front(rows, n, i, per_s, p) && cost(&rows[i], per_s) > last &&
                (best < 0 || cost(&rows[i], per_s) < cost(&rows[best], per_s)))
                best = i;
        if (best < 0)
            break;
        last = cost(&rows[best], per_s);
        char label[96];
        config_label(label, sizeof label, &rows[best], 1);
        fprintf(d, "%.6g %.6g \"%s\"\n", last, rows[best].error, label);
    }
    fclose(d);
    /* a partial merge (--case) may hold none of the spec's rows: no plot,
     * where gnuplot would stop the whole script on an empty range */
    if (!(xhi > 0)) {
        remove(path);
        return 0;
    }
    char title[256];
    snprintf(title, sizeof title, "%s: %s, every configuration;", p->study, p->metric);
    fputs("set output ", gp);
    gp_string(gp, out);
    gp_axes(gp, xlo, xhi, ylo, yhi);
    fputs("set title ", gp);
    gp_string(gp, title);
    fputs(" . \"\\n\" . 'the line joins the Pareto front; ", gp);
    fputs(!strcmp(p->study, "sph") ? "c sound speed, e max density error, C Courant factor, "
                                     "p particles'\nset xlabel "
                                   : "labels: knob=value'\nset xlabel ",
          gp);
    gp_string(gp, cost_label(rows, n, p->study));
    metric_label(ylabel, sizeof ylabel, p->metric);
    fputs("\nset ylabel ", gp);
    gp_string(gp, ylabel);
    fputs("\nplot ", gp);
    gp_string(gp, dat);
    fputs(" index 0 using 1:2 with points pt 6 title 'configuration', \\\n     ", gp);
    gp_string(gp, dat);
    fputs(" index 1 using 1:2 with linespoints lw 2 pt 7 title 'Pareto front', \\\n     ", gp);
    gp_string(gp, dat);
    fputs(" index 1 using 1:2:3 with labels offset 1,0.7 left font ',8' notitle\n", gp);
    return 0;
}

/* The dam break's rows of one metric by solver: per solver every
 * configuration (each knob it was swept over) and its Pareto front,
 * labelled; the plot a user reads "for 0.1 % compression DFSPH costs X,
 * Tait Y" from. */
static int write_solvers(FILE *gp, const char *dir, const acc_row *rows, int n, const char *metric,
                         const char *stem, const char *what)
{
    static const char *const solver[] = {"ideal_gas", "tait", "dfsph"};
    static const char *const names[] = {"ideal gas", "Tait", "DFSPH"};
    char path[1200], dat[300], out[300], ylabel[160];
    snprintf(dat, sizeof dat, "%s.dat", stem);
    snprintf(out, sizeof out, "%s.png", stem);
    snprintf(path, sizeof path, "%s/%s", dir, dat);
    FILE *d = fopen(path, "w");
    if (!d) {
        tool_error("accuracy: cannot write %s", path);
        return -1;
    }
    double xlo = INFINITY, xhi = 0, ylo = INFINITY, yhi = 0;
    int have[3] = {0, 0, 0};
    for (int s = 0; s < 3; ++s) {
        char tag[32];
        snprintf(tag, sizeof tag, "%s ", solver[s]);
        pareto_spec p = {"sph", metric, "", stem};
        fprintf(d, "# %s: every configuration, cost error\n", names[s]);
        for (int i = 0; i < n; ++i)
            if (in_spec(&rows[i], &p) && !strncmp(rows[i].config, tag, strlen(tag)) &&
                cost(&rows[i], 1) > 0 && rows[i].error > 0) {
                fprintf(d, "%.6g %.6g\n", cost(&rows[i], 1), rows[i].error);
                xlo = fmin(xlo, cost(&rows[i], 1));
                xhi = fmax(xhi, cost(&rows[i], 1));
                ylo = fmin(ylo, rows[i].error);
                yhi = fmax(yhi, rows[i].error);
                have[s] = 1;
            }
        if (!have[s])
            fprintf(d, "nan nan\n");
        fprintf(d, "\n\n# %s: its front, cost error label\n", names[s]);
        double last = -1, best_e = INFINITY;
        for (;;) { /* by cost, each point less wrong than every cheaper one */
            int best = -1;
            for (int i = 0; i < n; ++i)
                if (in_spec(&rows[i], &p) && !strncmp(rows[i].config, tag, strlen(tag)) &&
                    cost(&rows[i], 1) > last && rows[i].error > 0 &&
                    (best < 0 || cost(&rows[i], 1) < cost(&rows[best], 1)))
                    best = i;
            if (best < 0)
                break;
            last = cost(&rows[best], 1);
            if (rows[best].error >= best_e)
                continue;
            best_e = rows[best].error;
            char label[96];
            config_label(label, sizeof label, &rows[best], 0);
            fprintf(d, "%.6g %.6g \"%s\"\n", last, rows[best].error, label);
        }
        if (!have[s])
            fprintf(d, "nan nan \"\"\n");
        fprintf(d, "\n\n");
    }
    fclose(d);
    char title[256];
    snprintf(title, sizeof title, "%s: %s against cost, every configuration per solver;", what,
             metric);
    fputs("set output ", gp);
    gp_string(gp, out);
    gp_axes(gp, xlo, xhi, ylo, yhi);
    fputs("set title ", gp);
    gp_string(gp, title);
    fputs(" . \"\\n\" . 'lines: each solver''s front; c sound speed, e max density error, C "
          "Courant factor, p particles'\nset xlabel ",
          gp);
    gp_string(gp, cost_label(rows, n, "sph"));
    metric_label(ylabel, sizeof ylabel, metric);
    fputs("\nset ylabel ", gp);
    gp_string(gp, ylabel);
    fputs("\nplot ", gp);
    for (int s = 0; s < 3; ++s) {
        fprintf(gp, "%s", s ? ", \\\n     " : "");
        gp_string(gp, dat);
        fprintf(gp, " index %d using 1:2 with points pt 6 lc %d title '%s, every configuration'",
                2 * s, s + 1, names[s]);
        fputs(", \\\n     ", gp);
        gp_string(gp, dat);
        fprintf(gp, " index %d using 1:2 with linespoints lw 2 pt 7 lc %d title '%s, front'",
                2 * s + 1, s + 1, names[s]);
        fputs(", \\\n     ", gp);
        gp_string(gp, dat);
        fprintf(gp,
                " index %d using 1:2:3 with labels offset 0.8,0.6 left font ',7' tc lt %d "
                "notitle",
                2 * s + 1, s + 1);
    }
    fputs("\n", gp);
    return 0;
}

/* The dam break's curves over Martin & Moyce's points: the blocks of
 * DIR/sph_trace.dat ("# front Z(T): WHO" or "# column H(tau): WHO"),
 * the experiment's drawn as points, the runs' as lines. */
static int write_overlays(FILE *gp, const char *dir)
{
    char path[1200], line[512];
    snprintf(path, sizeof path, "%s/sph_trace.dat", dir);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    static char title[256][160];
    int nb = 0;
    while (fgets(line, sizeof line, f) && nb < 256)
        if (line[0] == '#') {
            line[strcspn(line, "\n")] = '\0';
            snprintf(title[nb++], sizeof title[0], "%.159s", line + 2);
        }
    fclose(f);
    static const struct {
        const char *prefix, *png, *title, *xlabel, *ylabel;
    } plot[] = {
        {"front Z(T): ", "sph_front_overlay.png",
         "dam break, surge front: simulated Z(T) at each solver's defaults against Martin & "
         "Moyce (1952)",
         "T = t sqrt(2 g / a)", "Z = front x / a"},
        {"column H(tau): ", "sph_column_overlay.png",
         "dam break, residual column at the wall: simulated H(tau) against Martin & Moyce "
         "(1952)",
         "tau = t sqrt(g / a)", "H = height / 2a"},
    };
    for (int p = 0; p < 2; ++p) {
        fputs("set output ", gp);
        gp_string(gp, plot[p].png);
        fputs("\nunset logscale x\nunset logscale y\nset title ", gp);
        gp_string(gp, plot[p].title);
        fputs("\nset xlabel ", gp);
        gp_string(gp, plot[p].xlabel);
        fputs("\nset ylabel ", gp);
        gp_string(gp, plot[p].ylabel);
        fputs("\nplot ", gp);
        int first = 1, lc = 0;
        size_t pl = strlen(plot[p].prefix);
        for (int b = 0; b < nb; ++b) {
            if (strncmp(title[b], plot[p].prefix, pl))
                continue;
            int exp = strstr(title[b], "Martin") != NULL;
            fputs(first ? "" : ", \\\n     ", gp);
            if (exp)
                fprintf(gp,
                        "'sph_trace.dat' index %d using 1:2 with points pt 5 ps 1.3 "
                        "lc rgb 'black' title ",
                        b);
            else /* a colour per solver, a dash per particle count */
                fprintf(gp,
                        "'sph_trace.dat' index %d using 1:2 with lines lw 1.5 dt %d lc %d "
                        "title ",
                        b, 1 + lc / 3, 1 + lc % 3),
                    ++lc;
            gp_string(gp, title[b] + pl);
            first = 0;
        }
        fputs("\n", gp);
    }
    return 0;
}

static int write_plots(const char *dir, const acc_row *rows, int n, const char *commit, int traces)
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
          "set terminal pngcairo noenhanced size 1100,700 font 'sans,11'\n"
          "set format xy '%g'\nset grid\nset key outside right\n",
          gp);
    const char *st[MAXK];
    int ns = studies(rows, n, st);
    for (int s = 0; s < ns; ++s) {
        int per_s = study_uses_per_s(rows, n, st[s]);
        int water = !strcmp(st[s], "water");
        const char *ms[MAXK];
        int nm = metrics(rows, n, st[s], ms);
        /* one plot per metric: its rows against cost (water: against the
         * wavelength), one curve per knob (and particle count) */
        for (int m = 0; m < nm; ++m) {
            curve cv[MAXK];
            int nc = curves_of(rows, n, st[s], ms[m], cv, MAXK);
            metric_stem(stem, sizeof stem, st[s], m, ms[m], "");
            snprintf(path, sizeof path, "%s/%s.dat", dir, stem);
            FILE *d = fopen(path, "w");
            if (!d) {
                tool_error("accuracy: cannot write %s", path);
                fclose(gp);
                return -1;
            }
            double xlo = INFINITY, xhi = 0, ylo = INFINITY, yhi = 0;
            for (int k = 0; k < nc; ++k) {
                int by_count = runs_by_count(rows, n, st[s], &cv[k], ms[m]);
                fprintf(d, "# %s, %s: %s error value label\n", cv[k].knob, ms[m],
                        water ? "wavelength" : "cost");
                for (int i = 0; i < n; ++i)
                    if (in_curve(&rows[i], st[s], ms[m], &cv[k])) {
                        double x = water ? rows[i].value : cost(&rows[i], per_s), y = rows[i].error;
                        char label[32];
                        point_label(label, sizeof label, &rows[i], &cv[k], by_count);
                        fprintf(d, "%.6g %.6g %.6g \"%s\"\n", x, y, rows[i].value, label);
                        if (x > 0 && y > 0) {
                            xlo = fmin(xlo, x);
                            xhi = fmax(xhi, x);
                            ylo = fmin(ylo, y);
                            yhi = fmax(yhi, y);
                        }
                    }
                fprintf(d, "\n\n");
            }
            fclose(d);
            char ylabel[160];
            metric_label(ylabel, sizeof ylabel, ms[m]);
            /* names from the parts only as gp_string writes them */
            if (water && m == 0) {
                snprintf(png, sizeof png, "%s_error.png", st[s]);
                fputs("set output ", gp);
                gp_string(gp, png);
                gp_axes(gp, xlo, xhi, ylo, yhi);
                fputs("set title 'water: the paper''s non-dispersive eq. 2 against real "
                      "capillary-gravity waves, one curve per depth'\n"
                      "set xlabel 'wavelength (m)'\nset ylabel ",
                      gp);
                gp_string(gp, ylabel);
            } else if (water) {
                /* the simulated models at one depth (the metric names it) */
                char title[256];
                const char *dep = strstr(ms[m], "depth ");
                metric_stem(png, sizeof png, st[s], m, ms[m], "_error");
                strncat(png, ".png", sizeof png - strlen(png) - 1);
                snprintf(title, sizeof title,
                         "water at %s: each surface model's phase speed (simulated) against "
                         "real water",
                         dep ? dep : ms[m]);
                fputs("set output ", gp);
                gp_string(gp, png);
                gp_axes(gp, xlo, xhi, ylo, yhi);
                fputs("set title ", gp);
                gp_string(gp, title);
                fputs(" . \"\\n\" . '32 cells per wavelength; legend: CPU time per cell "
                      "per sub-step (256x256, 1 thread)'\nset xlabel 'wavelength (m)'\nset "
                      "ylabel ",
                      gp);
                gp_string(gp, ylabel);
            } else {
                char title[256];
                metric_stem(png, sizeof png, st[s], m, ms[m], "_cost");
                strncat(png, ".png", sizeof png - strlen(png) - 1);
                snprintf(title, sizeof title, "%s: %s against cost, one curve per knob", st[s],
                         ms[m]);
                fputs("set output ", gp);
                gp_string(gp, png);
                gp_axes(gp, xlo, xhi, ylo, yhi);
                fputs("set title ", gp);
                gp_string(gp, title);
                fputs(" . \"\\n\" . 'labels: the knob''s value, or the particle or cell count "
                      "where the curve runs over it'\nset xlabel ",
                      gp);
                gp_string(gp, cost_label(rows, n, st[s]));
                fputs("\nset ylabel ", gp);
                gp_string(gp, ylabel);
            }
            fprintf(gp, "\nplot ");
            for (int k = 0; k < nc; ++k) {
                char dat[300], name[160], kl[120];
                snprintf(dat, sizeof dat, "%s.dat", stem);
                knob_label(kl, sizeof kl, cv[k].knob);
                double per_cell = NAN; /* water: the model's ns per cell per step */
                for (int i = 0; water && i < n && isnan(per_cell); ++i)
                    if (in_curve(&rows[i], st[s], ms[m], &cv[k]) && rows[i].size > 0)
                        per_cell = 1e6 * rows[i].cpu_ms_per_step / rows[i].size;
                if (water && isfinite(per_cell))
                    snprintf(name, sizeof name, "%s: %.3g ns per cell per step", kl, per_cell);
                else if (isnan(cv[k].size) || water)
                    snprintf(name, sizeof name, "%s", kl);
                else
                    snprintf(name, sizeof name, "%s, %.0f %s", kl, cv[k].size,
                             !strcmp(st[s], "sph") ? "particles" : "cells");
                fputs(k ? ", \\\n     " : "", gp);
                gp_string(gp, dat);
                fprintf(gp, " index %d using 1:2 with linespoints pt 7 lc %d title ", k, k + 1);
                gp_string(gp, name);
                if (!water) {
                    fputs(", \\\n     ", gp);
                    gp_string(gp, dat);
                    fprintf(gp,
                            " index %d using 1:2:4 with labels offset 0.6,0.5 left font ',7' "
                            "tc lt %d notitle",
                            k, k + 1);
                }
            }
            fprintf(gp, "\n");
        }
        if (water)
            continue;
        pareto_spec dflt;
        const pareto_spec *sp[NSPECS + 1];
        int np = specs_of(st[s], ms[0], &dflt, sp);
        for (int k = 0; k < np; ++k)
            if (write_pareto(gp, dir, rows, n, per_s, sp[k]) != 0) {
                fclose(gp);
                return -1;
            }
        if (!strcmp(st[s], "sph") &&
            (write_solvers(gp, dir, rows, n, "dam-break max compression", "sph_solvers_compression",
                           "dam break") != 0 ||
             write_solvers(gp, dir, rows, n, "dam-break column H rel. RMS error",
                           "sph_solvers_column", "dam break") != 0 ||
             write_solvers(gp, dir, rows, n, "max compression at rest (all particles)",
                           "sph_solvers_rest_compression", "column at rest") != 0)) {
            fclose(gp);
            return -1;
        }
    }
    if (traces > 0)
        write_overlays(gp, dir);
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
               const char *commit, int traces, int *plotted)
{
    *plotted = 0;
    if (write_plots(dir, rows, n, commit, traces) != 0)
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
