/* `modesplit accuracy`: validation studies against analytic and
 * experimental references, side by side with what each setting costs.
 *
 * cmd_accuracy.c: options, the case list, --jobs / --case / --merge, the
 *                 CSV; accuracy_report.c: the tables (accuracy.md), orders,
 *                 Pareto fronts and the gnuplot script; study_*.c: one
 *                 study each. Every case is built from a scene text and
 *                 `--set` overrides (ms_scene_parse_with_overrides), the
 *                 mechanism `modesplit run --set` uses, and run through the
 *                 public API only.
 */
#ifndef MS_TOOL_ACCURACY_H
#define MS_TOOL_ACCURACY_H

#include <stdio.h>

#include "tool.h"

/* One run of one configuration: a row of accuracy.csv. */
typedef struct acc_row {
    char study[24];         /* waves, water, sph, extract, coupler */
    char knob[32];          /* what was varied: cells, courant, particles, ... */
    double value;           /* the knob's value (its unit in the knob's name) */
    char config[96];        /* the configuration in words ("tait c0=20 m/s") */
    char metric[48];        /* what the error measures */
    double error;           /* that error (relative unless the metric says) */
    double reference;       /* the reference value it was measured against */
    double ms_per_s;        /* ms of wall clock per simulated second (NAN: n/a) */
    double ms_per_step;     /* ms of wall clock per step (wave step, SPH step, extraction) */
    double cpu_ms_per_s;    /* ms of CPU time (every thread of the work) per simulated s */
    double cpu_ms_per_step; /* the same per step: the costs the report plots */
    double size;            /* cells or particles */
    int threads;
    char cost_method[64]; /* how the cpu_ms_* were measured (acc_ctx's when "") */
    char machine[256];    /* as read from a part ("": this run's) */
    char commit[128];     /* as read from a part ("": this run's) */
} acc_row;

typedef struct acc_ctx {
    int quick;
    const char *cost_method; /* the case's, into each row acc_add takes (accuracy.h) */
    acc_row *rows;
    int nrows, cap;
    char note[16384]; /* notes for accuracy.md: solvers not in this build, ... */
    char *trace;      /* curves for the overlay plots (acc_trace), NULL: none */
    size_t trace_len, trace_cap;
} acc_ctx;

/* Append text to the case's curves: gnuplot data blocks ("# title" line,
 * "x y" lines, two blank lines), written to the part's NAME.trace and
 * merged into DIR/STUDY_trace.dat by --merge. */
void acc_trace(acc_ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The cost of a piece of work, wall clock and CPU time. The CPU time is
 * the calling thread's (CLOCK_THREAD_CPUTIME_ID): every case runs its sim
 * with one thread, which the library runs on the caller, so that is all
 * the work's time and nothing else's. acc_tic / acc_toc add one timing of
 * the work; acc_step and acc_repeat time a piece of work acc_repeats
 * times and add the cheapest (acc_step from a snapshot of the sim, so the
 * sim ends as one step would leave it). Other work on a loaded machine
 * still inflates a thread's CPU time (its caches flushed, a busy
 * sibling hyperthread); the least of a few repeats close in time is what
 * the work costs when that interference is least, and a first run's
 * warm-up (cold caches, first-touch allocations) is not counted.
 * --quick times once (acc_repeats 1): its rows check errors against the
 * committed study's (make check-accuracy, test_accuracy), and no cost of
 * its rows is compared or quoted, so the repeats would only triple its
 * time. The errors do not depend on the count (every repeat starts from
 * the same state and gives the same bytes). */
#define ACC_REPEATS 3
extern int acc_repeats;
/* The cost_method column of the rows, as each case's study sets it: a
 * format whose %s acc_add fills with how the repeats were taken. */
#define ACC_BY_FRAME "thread CPU time; each frame %s"
#define ACC_BY_RUN "thread CPU time; %s of the run"
#define ACC_BY_BLOCK "thread CPU time; each 16 steps %s"
#define ACC_BY_CALL "thread CPU time; the median of 5 calls"
typedef struct acc_timer {
    double wall, cpu;   /* s, summed over the timings */
    double wall0, cpu0; /* the open timing's start */
} acc_timer;
void acc_tic(acc_timer *t);
void acc_toc(acc_timer *t);
/* ms_sim_step(sim, dt) timed as above; the snapshot and the restores are
 * not timed. */
ms_status acc_step(acc_timer *t, ms_sim *sim, float dt);
/* The least of acc_repeats timings of work(arg) added to t: work whose
 * cost does not depend on the state it leaves (a block of wave steps); the
 * first failure's status, or MS_OK. */
ms_status acc_repeat(acc_timer *t, ms_status (*work)(void *), void *arg);

/* Append a row; 0 on success. */
int acc_add(acc_ctx *c, const acc_row *r);
/* Append a line to the notes. */
void acc_note(acc_ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A scene from its JSON text and --set overrides ("KEY=VALUE", NULL
 * ended); NULL after printing the error. */
ms_scene *acc_scene(const char *json, const char *const *sets);
/* A sim (1 thread) of that scene. The scene must outlive the sim: both are
 * freed by acc_free. MS_ERR_UNSUPPORTED is returned quietly (the study
 * notes it); other failures print. */
ms_status acc_sim(const char *json, const char *const *sets, ms_scene **sc, ms_sim **sim);
void acc_free(ms_scene *sc, ms_sim *sim);

/* One study case: rows into c; 0 on success, else prints and returns -1. */
typedef int acc_case_fn(acc_ctx *c);
int study_waves_cells(acc_ctx *c);
int study_waves_courant(acc_ctx *c);
int study_waves_ring(acc_ctx *c);
int study_waves_current(acc_ctx *c);
int study_water_dispersion(acc_ctx *c);
int study_sph_particles(acc_ctx *c);
int study_sph_particles_25k(acc_ctx *c);
int study_sph_particles_51k(acc_ctx *c);
int study_sph_particles_64k(acc_ctx *c);
int study_sph_laws(acc_ctx *c);
int study_sph_sound(acc_ctx *c);
int study_sph_dfsph(acc_ctx *c);
int study_sph_courant(acc_ctx *c);
int study_sph_rest(acc_ctx *c);
int study_sph_rest_sound(acc_ctx *c);
int study_sph_rest_dfsph(acc_ctx *c);
int study_sph_rest_courant(acc_ctx *c);
int study_water_models(acc_ctx *c);
int study_extract_flat(acc_ctx *c);
int study_extract_tilted(acc_ctx *c);
int study_extract_column(acc_ctx *c);
int study_coupler(acc_ctx *c);

/* The report from rows: DIR/accuracy.md, DIR/accuracy.gp (+ the .dat files
 * it reads) and, when gnuplot runs, the PNG plots in DIR: per study one
 * cost plot per metric (STUDY_cost.png for the first, STUDY_cost_SLUG.png
 * for the others), the Pareto charts and, when traces > 0 (the blocks of
 * DIR/sph_trace.dat), the dam break's curves over the experiment's points.
 * 0 on success. */
int acc_report(const char *dir, const acc_row *rows, int n, const char *notes, const char *machine,
               const char *commit, int traces, int *plotted);
/* Observed order: minus the least-squares slope of log(error) against
 * log(value) over the rows of (study, knob) with the knob's first metric
 * (accuracy.md gives it per knob and metric, only where theory gives an
 * order); NAN when < 2 points. */
double acc_order(const acc_row *rows, int n, const char *study, const char *knob);

#endif
