/* The volume's instruction-set paths side by side: the 32k dam break
 * (bench_volume's scene, the ideal gas and DFSPH) and the fig1_x10 scene
 * on every path this CPU runs (ms_get_build_info), in one process, one
 * thread. Each path has its own volume (or sim) of the same scene; the
 * repeats take one sub-step (a frame for the scene) of each path in turn,
 * the first path rotating, timed by thread CPU, so every path sees the
 * same load. All paths give the same bytes, so they do the same work
 * step for step. Prints the medians and each path's ratio to the widest;
 * writes paths.csv, the path in every row. */
#include <math.h>
#include <string.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

enum { MAX_PATHS = 5, MAX_REPS = 64 };

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void check(ms_status st, const char *what)
{
    if (st != MS_OK) {
        fprintf(stderr, "bench_paths: %s: %s\n", what, ms_last_error());
        exit(1);
    }
}

/* bench_volume's dam break: a column a x a x 2a in a 4a x a x 2.2a tank. */
static ms_volume *dam_break(int target, ms_pressure law)
{
    const float a = 0.5f;
    const float s = a * cbrtf(2.0f / (float)target);
    ms_volume_desc d = ms_volume_desc_default();
    d.domain_max[0] = 4.0f * a;
    d.domain_max[1] = a;
    d.domain_max[2] = 2.2f * a;
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    d.max_particles = 2 * target;
    d.pressure = law;
    ms_volume *v;
    check(ms_volume_create(&d, &v), "dam break");
    check(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){a, a, 2.0f * a}), "fill");
    return v;
}

/* One sub-step at half the largest stable dt, thread CPU seconds. */
static double one_substep(ms_volume *v)
{
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    const double t0 = cpu_now();
    check(ms_volume_step(v, 0.5f * in.max_dt), "step");
    return cpu_now() - t0;
}

typedef struct paths {
    int n;
    char name[MAX_PATHS][16];
} paths;

/* The paths this CPU runs, narrowest first (the last is the widest). */
static paths paths_here(void)
{
    ms_build_info b;
    check(ms_get_build_info(&b), "build info");
    paths p = {0};
    char list[128];
    snprintf(list, sizeof list, "%s", b.paths_cpu);
    for (char *tok = strtok(list, " "); tok && p.n < MAX_PATHS; tok = strtok(NULL, " "))
        snprintf(p.name[p.n++], sizeof p.name[0], "%s", tok);
    return p;
}

static void use_path(const char *name)
{
    setenv("MODESPLIT_ISA", name, 1);
}

static void report(FILE *csv, const char *commit, const char *machine, const paths *p,
                   const char *scene, const char *unit, int count, int reps,
                   double t[MAX_PATHS][MAX_REPS])
{
    bench_stats st[MAX_PATHS];
    for (int k = 0; k < p->n; ++k)
        st[k] = bench_summarise(t[k], reps);
    const double widest = st[p->n - 1].median;
    for (int k = 0; k < p->n; ++k) {
        printf("%-22s %-7s %8.3f %8.3f %8.3f %7.2fx\n", scene, p->name[k], st[k].median, st[k].p10,
               st[k].p90, st[k].median / widest);
        fprintf(csv, "%s,%s,%s,%s,%s,%d,%d,%.4f,%.4f,%.4f,%.3f\n", commit, machine, p->name[k],
                scene, unit, count, reps, st[k].median, st[k].p10, st[k].p90,
                st[k].median / widest);
    }
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_paths [--csv-dir DIR] [--quick]\n"
                   "the 32k dam break (ideal gas, DFSPH) and fig1_x10 on every SIMD path this\n"
                   "CPU runs, interleaved in one process; writes DIR/paths.csv.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const int reps = quick ? 3 : 31;
    char machine[256], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    const paths p = paths_here();
    printf("paths: the same scene on each SIMD path, one thread, thread CPU, interleaved\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%-22s %-7s %8s %8s %8s %8s\n", "scene", "path", "median", "p10", "p90", "/widest");
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "paths.csv",
                               "commit,machine,path,scene,unit,particles,repeats,"
                               "ms_median,ms_p10,ms_p90,ratio_to_widest");
    if (!csv)
        return 1;
    static double t[MAX_PATHS][MAX_REPS];
    const ms_pressure laws[2] = {MS_PRESSURE_IDEAL_GAS, MS_PRESSURE_DFSPH};
    const char *const law_names[2] = {"dam32k_ideal_gas", "dam32k_dfsph"};
    for (int l = 0; l < 2; ++l) {
        ms_volume *v[MAX_PATHS];
        for (int k = 0; k < p.n; ++k) {
            use_path(p.name[k]);
            v[k] = dam_break(32768, laws[l]);
            for (int w = 0; w < 20; ++w) /* warm-up: lists grown, column moving */
                one_substep(v[k]);
        }
        for (int r = 0; r < reps; ++r)
            for (int o = 0; o < p.n; ++o) {
                const int k = (o + r) % p.n;
                t[k][r] = 1e3 * one_substep(v[k]);
            }
        report(csv, commit, machine, &p, law_names[l], "ms_per_substep", ms_volume_count(v[0]),
               reps, t);
        for (int k = 0; k < p.n; ++k)
            ms_volume_destroy(v[k]);
    }
    /* fig1_x10: frames of the scene's sim (waves and liquid), one thread */
    const char *file = bench_arg_value(argc, argv, "--scene", "data/scenes/fig1_x10.json");
    ms_scene *sc;
    check(ms_scene_load(file, &sc), file);
    ms_sim *sim[MAX_PATHS];
    const float dt = ms_scene_frame_dt(sc);
    for (int k = 0; k < p.n; ++k) {
        use_path(p.name[k]);
        check(ms_sim_create_from_scene(sc, 1, &sim[k]), "sim");
        for (int w = 0; w < (quick ? 2 : 10); ++w)
            check(ms_sim_step(sim[k], dt), "sim step");
    }
    for (int r = 0; r < reps; ++r)
        for (int o = 0; o < p.n; ++o) {
            const int k = (o + r) % p.n;
            const double t0 = cpu_now();
            check(ms_sim_step(sim[k], dt), "sim step");
            t[k][r] = 1e3 * (cpu_now() - t0);
        }
    report(csv, commit, machine, &p, "fig1_x10", "ms_per_frame", 0, reps, t);
    for (int k = 0; k < p.n; ++k)
        ms_sim_destroy(sim[k]);
    ms_scene_destroy(sc);
    unsetenv("MODESPLIT_ISA");
    fclose(csv);
    printf("wrote %s/paths.csv\n", bench_csv_dir(argc, argv));
    return 0;
}
