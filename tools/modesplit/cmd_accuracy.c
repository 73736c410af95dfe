/* modesplit accuracy [--quick] [--out DIR] [--jobs] [--case NAME] [--merge DIR]:
 * the validation studies (accuracy.h) and what each setting costs.
 *
 * Without --case or --merge every case runs here, writing its part to
 * DIR/parts/NAME.csv, and the parts are then merged as --merge does: one
 * code path, so a study split over GNU parallel or a Slurm array gives the
 * same files as one run on one machine. --jobs prints the command of each
 * case, one a line.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "accuracy.h"

static const struct {
    const char *name;
    acc_case_fn *fn;
} cases[] = {
    {"waves-cells", study_waves_cells},
    {"waves-courant", study_waves_courant},
    {"waves-ring", study_waves_ring},
    {"waves-current", study_waves_current},
    {"water-dispersion", study_water_dispersion},
    {"water-models", study_water_models},
    {"sph-particles", study_sph_particles},
    {"sph-particles-25k", study_sph_particles_25k},
    {"sph-particles-51k", study_sph_particles_51k},
    {"sph-particles-64k", study_sph_particles_64k},
    {"sph-laws", study_sph_laws},
    {"sph-sound", study_sph_sound},
    {"sph-dfsph", study_sph_dfsph},
    {"sph-courant", study_sph_courant},
    {"sph-rest", study_sph_rest},
    {"sph-rest-sound", study_sph_rest_sound},
    {"sph-rest-dfsph", study_sph_rest_dfsph},
    {"sph-rest-courant", study_sph_rest_courant},
    {"extract-flat", study_extract_flat},
    {"extract-tilted", study_extract_tilted},
    {"extract-column", study_extract_column},
    {"coupler", study_coupler},
};
#define NCASES ((int)(sizeof cases / sizeof cases[0]))

/* cpu_ms_*: CPU time of the process (every thread of the work summed,
 * acc_timer); wall_ms_*: wall clock of the same work. */
static const char csv_header[] =
    "study,knob,value,config,metric,error,reference,cpu_ms_per_simulated_s,cpu_ms_per_step,"
    "wall_ms_per_simulated_s,wall_ms_per_step,cells_or_particles,threads,cost_method,machine,"
    "commit\n";
#define NFIELDS 16

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void acc_tic(acc_timer *t)
{
    t->wall0 = tool_now();
    t->cpu0 = cpu_now();
}

void acc_toc(acc_timer *t)
{
    t->cpu += cpu_now() - t->cpu0;
    t->wall += tool_now() - t->wall0;
}

int acc_repeats = ACC_REPEATS;

ms_status acc_repeat(acc_timer *t, ms_status (*work)(void *), void *arg)
{
    double cpu = INFINITY, wall = INFINITY;
    for (int k = 0; k < acc_repeats; ++k) {
        acc_timer one = {0};
        acc_tic(&one);
        ms_status st = work(arg);
        acc_toc(&one);
        if (st != MS_OK)
            return st;
        cpu = fmin(cpu, one.cpu);
        wall = fmin(wall, one.wall);
    }
    t->cpu += cpu;
    t->wall += wall;
    return MS_OK;
}

/* The snapshot acc_step restores from: one case a process and one thread,
 * so one buffer, grown as the sim's blob grows (particles added). */
static unsigned char *snap;
static size_t snap_cap;

ms_status acc_step(acc_timer *t, ms_sim *sim, float dt)
{
    size_t need = 0, got = 0;
    ms_status st = ms_sim_snapshot_size(sim, &need);
    if (st != MS_OK)
        return st;
    if (need > snap_cap) {
        unsigned char *b = realloc(snap, need);
        if (!b)
            return MS_ERR_OUT_OF_MEMORY;
        snap = b;
        snap_cap = need;
    }
    if ((st = ms_sim_snapshot(sim, snap, snap_cap, &got)) != MS_OK)
        return st;
    double cpu = INFINITY, wall = INFINITY;
    for (int k = 0; k < acc_repeats; ++k) {
        /* every repeat from the same state: the last leaves the sim as
         * one step would (ms_sim_restore: the same bytes) */
        if (k > 0 && (st = ms_sim_restore(sim, snap, got)) != MS_OK)
            return st;
        acc_timer one = {0};
        acc_tic(&one);
        st = ms_sim_step(sim, dt);
        acc_toc(&one);
        if (st != MS_OK)
            return st;
        cpu = fmin(cpu, one.cpu);
        wall = fmin(wall, one.wall);
    }
    t->cpu += cpu;
    t->wall += wall;
    return MS_OK;
}

int acc_add(acc_ctx *c, const acc_row *r)
{
    if (c->nrows == c->cap) {
        int ncap = c->cap ? 2 * c->cap : 64;
        acc_row *nr = realloc(c->rows, sizeof *nr * (size_t)ncap);
        if (!nr) {
            tool_error("accuracy: out of memory");
            return -1;
        }
        c->rows = nr;
        c->cap = ncap;
    }
    acc_row *d = &c->rows[c->nrows++];
    *d = *r;
    if (!d->cost_method[0]) {
        /* the study's format (accuracy.h) with how its repeats were taken;
         * a format without %s (ACC_BY_CALL) ignores it */
        char how[40];
        if (acc_repeats > 1)
            snprintf(how, sizeof how, "the least of %d repeats", acc_repeats);
        else
            snprintf(how, sizeof how, "one timing");
        if (!isfinite(r->cpu_ms_per_s) && !isfinite(r->cpu_ms_per_step))
            snprintf(d->cost_method, sizeof d->cost_method, "no cost: computed, not simulated");
        else if (!c->cost_method)
            snprintf(d->cost_method, sizeof d->cost_method, "thread CPU time");
        else
            snprintf(d->cost_method, sizeof d->cost_method, c->cost_method, how);
    }
    return 0;
}

void acc_note(acc_ctx *c, const char *fmt, ...)
{
    size_t used = strlen(c->note);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->note + used, sizeof c->note - used, fmt, ap);
    va_end(ap);
    used = strlen(c->note);
    if (used + 1 < sizeof c->note) {
        c->note[used] = '\n';
        c->note[used + 1] = '\0';
    }
}

void acc_trace(acc_ctx *c, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int need = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (need < 0)
        return;
    if (c->trace_len + (size_t)need + 1 > c->trace_cap) {
        size_t cap = 2 * (c->trace_len + (size_t)need + 1) + 4096;
        char *t = realloc(c->trace, cap);
        if (!t)
            return; /* the overlay loses a curve; the rows are whole */
        c->trace = t;
        c->trace_cap = cap;
    }
    va_start(ap, fmt);
    vsnprintf(c->trace + c->trace_len, c->trace_cap - c->trace_len, fmt, ap);
    va_end(ap);
    c->trace_len += (size_t)need;
}

ms_scene *acc_scene(const char *json, const char *const *sets)
{
    int n = 0;
    while (sets && sets[n])
        ++n;
    ms_scene *sc = NULL;
    if (ms_scene_parse_with_overrides(json, strlen(json), n, sets, &sc) != MS_OK) {
        tool_error("accuracy: %s", ms_last_error());
        return NULL;
    }
    return sc;
}

ms_status acc_sim(const char *json, const char *const *sets, ms_scene **sc, ms_sim **sim)
{
    *sim = NULL;
    *sc = acc_scene(json, sets);
    if (!*sc)
        return MS_ERR_INVALID_ARGUMENT;
    ms_status st = ms_sim_create_from_scene(*sc, 1, sim);
    if (st != MS_OK) {
        if (st != MS_ERR_UNSUPPORTED)
            tool_error("accuracy: %s", ms_last_error());
        ms_scene_destroy(*sc);
        *sc = NULL;
    }
    return st;
}

void acc_free(ms_scene *sc, ms_sim *sim)
{
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}

/* ---- machine and commit, in every row ---- */

static void machine_text(char *buf, size_t size)
{
    char model[160] = "unknown CPU";
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (!strncmp(line, "model name", 10)) {
                char *p = strchr(line, ':');
                if (p) {
                    p += strspn(p + 1, " \t") + 1;
                    p[strcspn(p, "\n")] = '\0';
                    snprintf(model, sizeof model, "%s", p);
                }
                break;
            }
        fclose(f);
    }
    struct utsname u;
    const char *sys = uname(&u) == 0 ? u.release : "?";
    snprintf(buf, size, "%s; %ld cores; Linux %s", model, sysconf(_SC_NPROCESSORS_ONLN), sys);
    for (char *p = buf; *p; ++p)
        if (*p == '"' || *p == ',')
            *p = *p == ',' ? ';' : '\'';
}

/* The 1-minute load average (NAN when unknown): the costs of a case are
 * wall clock, which other work on the machine inflates; the report says
 * how loaded the machine was while each case ran. */
static double load_1min(void)
{
    double l = NAN;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = NAN;
        fclose(f);
    }
    return l;
}

static void commit_text(char *buf, size_t size)
{
    snprintf(buf, size, "unknown");
    FILE *p = popen("git describe --always --dirty 2>/dev/null", "r");
    if (!p)
        return;
    char line[128];
    if (fgets(line, sizeof line, p)) {
        line[strcspn(line, "\n")] = '\0';
        if (line[0])
            snprintf(buf, size, "%s", line);
    }
    pclose(p);
}

/* ---- CSV parts ---- */

static void csv_text(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; ++s)
        fputc(*s == '"' ? '\'' : *s, f);
    fputc('"', f);
}

static int write_rows(const char *path, const acc_row *rows, int n, const char *machine,
                      const char *commit)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        tool_error("accuracy: cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    fputs(csv_header, f);
    for (int i = 0; i < n; ++i) {
        const acc_row *r = &rows[i];
        fprintf(f, "%s,%s,%.9g,", r->study, r->knob, r->value);
        csv_text(f, r->config);
        fputc(',', f);
        csv_text(f, r->metric);
        fprintf(f, ",%.6g,%.9g,%.6g,%.6g,%.6g,%.6g,%.9g,%d,", r->error, r->reference,
                r->cpu_ms_per_s, r->cpu_ms_per_step, r->ms_per_s, r->ms_per_step, r->size,
                r->threads);
        csv_text(f, r->cost_method);
        fputc(',', f);
        csv_text(f, r->machine[0] ? r->machine : machine);
        fputc(',', f);
        csv_text(f, r->commit[0] ? r->commit : commit);
        fputc('\n', f);
    }
    if (fclose(f) != 0) {
        tool_error("accuracy: cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

/* Split one CSV line (our own format: fields quoted when text) in place. */
static int split_csv(char *line, char **field, int max)
{
    int n = 0;
    char *p = line;
    while (n < max) {
        if (*p == '"') {
            field[n++] = ++p;
            p = strchr(p, '"');
            if (!p)
                return -1;
            *p++ = '\0';
        } else {
            field[n++] = p;
            p += strcspn(p, ",\n");
        }
        if (*p == ',')
            *p++ = '\0';
        else {
            *p = '\0';
            break;
        }
    }
    return n;
}

/* A study or knob name of a part: a letter, then letters, digits, '_',
 * '-' or '.', shorter than its field. They name output files (STUDY.dat,
 * STUDY_pareto.png under --out) and appear in the plot script, so a name
 * with a '/', "..", a quote or a backquote is refused, not cleaned. */
static int is_identifier(const char *s, size_t size)
{
    size_t n = strlen(s);
    if (n == 0 || n >= size || !((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z')))
        return 0;
    for (const char *p = s; *p; ++p)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '_' || *p == '-' || *p == '.'))
            return 0;
    return 1;
}

/* A text field of a part (metric, configuration, machine, commit): no
 * control character, and it fits its field. */
static int is_text(const char *s, size_t size)
{
    if (strlen(s) >= size)
        return 0;
    for (const unsigned char *p = (const unsigned char *)s; *p; ++p)
        if (*p < 0x20 || *p == 0x7f)
            return 0;
    return 1;
}

/* The refusal of a part's row with a field that is not allowed (0: none):
 * the field, its value (control characters as '?', cut at 60) and the
 * rule it broke. */
static int refuse_fields(const char *path, int lineno, char *const *fl)
{
    static const struct {
        int field, name; /* name: 1 = an identifier, 0 = text */
        size_t size;
        const char *what;
    } rule[] = {
        {0, 1, sizeof((acc_row *)0)->study, "study"},
        {1, 1, sizeof((acc_row *)0)->knob, "knob"},
        {3, 0, sizeof((acc_row *)0)->config, "config"},
        {4, 0, sizeof((acc_row *)0)->metric, "metric"},
        {13, 0, sizeof((acc_row *)0)->cost_method, "cost_method"},
        {14, 0, sizeof((acc_row *)0)->machine, "machine"},
        {15, 0, sizeof((acc_row *)0)->commit, "commit"},
    };
    for (size_t i = 0; i < sizeof rule / sizeof rule[0]; ++i) {
        const char *v = fl[rule[i].field];
        if (rule[i].name ? is_identifier(v, rule[i].size) : is_text(v, rule[i].size))
            continue;
        char shown[64];
        size_t k = 0;
        for (; v[k] && k < 60; ++k)
            shown[k] = (unsigned char)v[k] < 0x20 || v[k] == 0x7f ? '?' : v[k];
        shown[k] = '\0';
        if (rule[i].name)
            tool_error("accuracy: %s:%d: %s \"%s%s\" is refused; allowed: a letter, then "
                       "letters, digits, '_', '-' and '.', at most %zu characters",
                       path, lineno, rule[i].what, shown, v[k] ? "..." : "", rule[i].size - 1);
        else
            tool_error("accuracy: %s:%d: %s \"%s%s\" is refused; allowed: text without "
                       "control characters, at most %zu characters",
                       path, lineno, rule[i].what, shown, v[k] ? "..." : "", rule[i].size - 1);
        return 1;
    }
    return 0;
}

static int read_part(const char *path, acc_ctx *c, char *machine, char *commit, size_t size)
{
    const char *why;
    FILE *f = tool_fopen_regular(path, &why);
    if (!f && errno == ENOENT)
        return 1; /* a case that wrote nothing */
    if (!f) {
        tool_error("accuracy: cannot read the part %s: %s", path, why);
        return -1;
    }
    char line[4096];
    int rc = 0, lineno = 0;
    while (fgets(line, sizeof line, f)) {
        ++lineno;
        if (lineno == 1) {
            if (strcmp(line, csv_header) != 0) {
                tool_error("accuracy: %s: not a part of this accuracy study (header)", path);
                rc = -1;
                break;
            }
            continue;
        }
        char *fl[NFIELDS];
        acc_row r;
        memset(&r, 0, sizeof r);
        if (split_csv(line, fl, NFIELDS) != NFIELDS) {
            tool_error("accuracy: %s:%d: not %d fields", path, lineno, NFIELDS);
            rc = -1;
            break;
        }
        /* a newline ends the last field; fgets keeps it */
        fl[NFIELDS - 1][strcspn(fl[NFIELDS - 1], "\r\n")] = '\0';
        if (refuse_fields(path, lineno, fl)) {
            rc = -1;
            break;
        }
        snprintf(r.study, sizeof r.study, "%s", fl[0]);
        snprintf(r.knob, sizeof r.knob, "%s", fl[1]);
        r.value = strtod(fl[2], NULL);
        snprintf(r.config, sizeof r.config, "%s", fl[3]);
        snprintf(r.metric, sizeof r.metric, "%s", fl[4]);
        r.error = strtod(fl[5], NULL);
        r.reference = strtod(fl[6], NULL);
        r.cpu_ms_per_s = strtod(fl[7], NULL);
        r.cpu_ms_per_step = strtod(fl[8], NULL);
        r.ms_per_s = strtod(fl[9], NULL);
        r.ms_per_step = strtod(fl[10], NULL);
        r.size = strtod(fl[11], NULL);
        r.threads = atoi(fl[12]);
        snprintf(r.cost_method, sizeof r.cost_method, "%s", fl[13]);
        snprintf(machine, size, "%s", fl[14]);
        snprintf(commit, size, "%s", fl[15]);
        snprintf(r.machine, sizeof r.machine, "%s", fl[14]);
        snprintf(r.commit, sizeof r.commit, "%s", fl[15]);
        if (acc_add(c, &r) != 0) {
            rc = -1;
            break;
        }
    }
    fclose(f);
    return rc;
}

static int make_dir(const char *dir)
{
    char p[1024];
    snprintf(p, sizeof p, "%s", dir);
    for (char *s = p + 1; *s; ++s)
        if (*s == '/') {
            *s = '\0';
            mkdir(p, 0777);
            *s = '/';
        }
    if (mkdir(p, 0777) != 0 && errno != EEXIST) {
        tool_error("accuracy: cannot create %s: %s", dir, strerror(errno));
        return -1;
    }
    return 0;
}

/* s as one word of a POSIX shell line: in single quotes, a quote inside
 * as '\'' (the shell gives every other character inside as it is). */
static void shell_word(const char *s)
{
    putchar('\'');
    for (const char *p = s; *p; ++p)
        if (*p == '\'')
            fputs("'\\''", stdout);
        else
            putchar(*p);
    putchar('\'');
}

static int run_case(int k, int quick, const char *parts)
{
    acc_ctx c;
    memset(&c, 0, sizeof c);
    c.quick = quick;
    acc_repeats = quick ? 1 : ACC_REPEATS;
    double t0 = tool_now(), load0 = load_1min();
    fprintf(stderr, "accuracy: %s%s ...\n", cases[k].name, quick ? " (quick)" : "");
    int rc = cases[k].fn(&c);
    if (rc == 0) {
        char machine[256], commit[128], path[1200];
        machine_text(machine, sizeof machine);
        double load1 = load_1min();
        size_t used = strlen(machine);
        snprintf(machine + used, sizeof machine - used, "; load %.2f to %.2f", load0, load1);
        acc_note(&c,
                 "- load: case %s ran %.0f s with a 1-minute load average of %.2f at its start "
                 "and %.2f at its end on %ld cores.",
                 cases[k].name, tool_now() - t0, load0, load1, sysconf(_SC_NPROCESSORS_ONLN));
        commit_text(commit, sizeof commit);
        snprintf(path, sizeof path, "%s/%s.csv", parts, cases[k].name);
        rc = write_rows(path, c.rows, c.nrows, machine, commit);
        snprintf(path, sizeof path, "%s/%s.notes", parts, cases[k].name);
        FILE *f = rc == 0 ? fopen(path, "w") : NULL;
        if (f) {
            fputs(c.note, f);
            fclose(f);
        }
        snprintf(path, sizeof path, "%s/%s.trace", parts, cases[k].name);
        f = rc == 0 && c.trace_len ? fopen(path, "w") : NULL;
        if (f) {
            fputs(c.trace, f);
            fclose(f);
        }
        fprintf(stderr, "accuracy: %s: %d rows in %.1f s\n", cases[k].name, c.nrows,
                tool_now() - t0);
    }
    free(c.rows);
    free(c.trace);
    return rc;
}

/* The parts' curves (NAME.trace, each a case's gnuplot blocks) into
 * OUT/sph_trace.dat, in the cases' order; the number of blocks, 0 when
 * no part has any, -1 on an error. */
static int merge_traces(const char *parts, const char *out)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/sph_trace.dat", out);
    FILE *o = NULL;
    int blocks = 0;
    for (int k = 0; k < NCASES; ++k) {
        snprintf(path, sizeof path, "%s/%s.trace", parts, cases[k].name);
        const char *why;
        FILE *f = tool_fopen_regular(path, &why);
        if (!f && errno == ENOENT)
            continue;
        if (!f) {
            tool_error("accuracy: cannot read the part %s: %s", path, why);
            if (o)
                fclose(o);
            return -1;
        }
        if (!o) {
            snprintf(path, sizeof path, "%s/sph_trace.dat", out);
            o = fopen(path, "w");
            if (!o) {
                fclose(f);
                tool_error("accuracy: cannot write %s: %s", path, strerror(errno));
                return -1;
            }
        }
        char line[512];
        while (fgets(line, sizeof line, f)) {
            blocks += line[0] == '#';
            fputs(line, o);
        }
        fclose(f);
    }
    if (!o) { /* no curves: no stale file from an earlier run */
        snprintf(path, sizeof path, "%s/sph_trace.dat", out);
        remove(path);
    }
    return o && fclose(o) != 0 ? -1 : blocks;
}

static int merge(const char *parts, const char *out)
{
    acc_ctx c;
    memset(&c, 0, sizeof c);
    char machine[256] = "unknown", commit[128] = "unknown", path[1200];
    static char commits[NCASES][128]; /* each part's, "" when absent */
    int found = 0, rc = 0, mixed = 0;
    for (int k = 0; k < NCASES && rc == 0; ++k) {
        snprintf(path, sizeof path, "%s/%s.csv", parts, cases[k].name);
        int r = read_part(path, &c, machine, commit, sizeof commit);
        commits[k][0] = '\0';
        if (r < 0)
            rc = -1;
        else if (r == 0) {
            snprintf(commits[k], sizeof commits[k], "%s", commit);
            for (int j = 0; j < k; ++j)
                mixed |= commits[j][0] && strcmp(commits[j], commits[k]) != 0;
            ++found;
        }
        snprintf(path, sizeof path, "%s/%s.notes", parts, cases[k].name);
        const char *why;
        FILE *f = rc == 0 ? tool_fopen_regular(path, &why) : NULL;
        if (!f && rc == 0 && errno != ENOENT) {
            tool_error("accuracy: cannot read the part %s: %s", path, why);
            rc = -1;
        }
        if (f) {
            size_t used = strlen(c.note);
            size_t got = fread(c.note + used, 1, sizeof c.note - used - 1, f);
            c.note[used + got] = '\0';
            fclose(f);
        }
    }
    if (rc == 0 && found == 0) {
        tool_error("accuracy: --merge %s: no part (NAME.csv of a case) found", parts);
        rc = -1;
    }
    if (rc == 0 && found < NCASES)
        acc_note(&c, "- %d of %d cases in this report (the others were not run).", found, NCASES);
    /* parts from different commits (a case rerun after a change, the
     * others kept): the report says which is which, not one commit for all */
    if (rc == 0 && mixed) {
        acc_note(&c, "- the cases come from more than one commit (each row's is in the CSV):");
        for (int k = 0; k < NCASES; ++k)
            if (commits[k][0])
                acc_note(&c, "  - %s: %s", cases[k].name, commits[k]);
        snprintf(commit, sizeof commit, "several (see the notes)");
    }
    int plotted = 0;
    if (rc == 0)
        rc = make_dir(out);
    if (rc == 0) {
        snprintf(path, sizeof path, "%s/accuracy.csv", out);
        rc = write_rows(path, c.rows, c.nrows, machine, commit);
    }
    int traces = rc == 0 ? merge_traces(parts, out) : 0;
    if (traces < 0)
        rc = -1;
    if (rc == 0)
        rc = acc_report(out, c.rows, c.nrows, c.note, machine, commit, traces, &plotted);
    if (rc == 0)
        fprintf(stderr, "accuracy: wrote %s/accuracy.csv (%d rows), %s/accuracy.md%s\n", out,
                c.nrows, out, plotted ? " and the PNG plots" : " (no plots: see above)");
    free(c.rows);
    return rc;
}

int cmd_accuracy(int argc, char **argv)
{
    int quick = 0, jobs = 0, bad = 0;
    const char *out = "accuracy", *one = NULL, *parts = NULL;
    for (int i = 1; i < argc; ++i) {
        const char *v = NULL, *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            tool_command_usage(stdout, "accuracy");
            return EXIT_OK;
        } else if (!strcmp(a, "--quick")) {
            quick = 1;
        } else if (!strcmp(a, "--jobs")) {
            jobs = 1;
        } else if (tool_opt_value(argc, argv, &i, "--out", &v, &bad)) {
            if (bad || !*v) {
                tool_error("accuracy: --out needs a directory");
                return EXIT_USAGE;
            }
            out = v;
        } else if (tool_opt_value(argc, argv, &i, "--case", &v, &bad)) {
            if (bad)
                return EXIT_USAGE;
            if (one) {
                tool_error("accuracy: --case %s after --case %s: one case a run (--jobs "
                           "prints a line per case)",
                           v, one);
                return EXIT_USAGE;
            }
            one = v;
        } else if (tool_opt_value(argc, argv, &i, "--merge", &v, &bad)) {
            if (bad || !*v) {
                tool_error("accuracy: --merge needs the directory of the parts");
                return EXIT_USAGE;
            }
            parts = v;
        } else {
            tool_error("accuracy: unknown argument %s (see modesplit accuracy --help)", a);
            return EXIT_USAGE;
        }
    }
    if ((jobs != 0) + (one != NULL) + (parts != NULL) > 1) {
        tool_error("accuracy: give one of --jobs, --case and --merge");
        return EXIT_USAGE;
    }
    int k = -1;
    if (one) {
        for (int j = 0; j < NCASES; ++j)
            if (!strcmp(one, cases[j].name))
                k = j;
        if (k < 0) {
            char list[600] = "";
            for (int j = 0; j < NCASES; ++j) {
                strncat(list, cases[j].name, sizeof list - strlen(list) - 1);
                if (j + 1 < NCASES)
                    strncat(list, ", ", sizeof list - strlen(list) - 1);
            }
            tool_error("accuracy: --case %s is not a case; allowed: %s", one, list);
            return EXIT_USAGE;
        }
    }
    if (jobs) {
        char self[1024];
        ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
        if (n <= 0)
            snprintf(self, sizeof self, "modesplit");
        else
            self[n] = '\0';
        char pdir[1200];
        snprintf(pdir, sizeof pdir, "%s/parts", out);
        for (int j = 0; j < NCASES; ++j) {
            /* lines for a shell: every path quoted as one word */
            shell_word(self);
            printf(" accuracy%s --case %s --out ", quick ? " --quick" : "", cases[j].name);
            shell_word(pdir);
            putchar('\n');
        }
        return EXIT_OK;
    }
    if (parts)
        return merge(parts, out) == 0 ? EXIT_OK : EXIT_RUNTIME;
    if (k >= 0) /* one case: its part into DIR itself (DIR/parts of the merge) */
        return make_dir(out) == 0 && run_case(k, quick, out) == 0 ? EXIT_OK : EXIT_RUNTIME;
    char pdir[1200];
    snprintf(pdir, sizeof pdir, "%s/parts", out);
    if (make_dir(pdir) != 0)
        return EXIT_RUNTIME;
    double t0 = tool_now();
    for (int j = 0; j < NCASES; ++j)
        if (run_case(j, quick, pdir) != 0)
            return EXIT_RUNTIME;
    int rc = merge(pdir, out);
    fprintf(stderr, "accuracy: %d cases in %.1f s\n", NCASES, tool_now() - t0);
    return rc == 0 ? EXIT_OK : EXIT_RUNTIME;
}
