/* What carrying the waves on the flow costs (surface.advect,
 * ms_surface_set_current), CPU time, 1 thread, the runs with and without
 * it interleaved repeat by repeat:
 *
 *  - a surface alone at fig10's 200^2 and fig1's 400^2 grid (c = 0.2 m/s
 *    over 1 m, 1/60 s frames): ms a frame without a current, and with a
 *    sheared current set every frame, as the sim sets it;
 *  - the river scene (data/scenes/river.json) as shipped and with
 *    surface.advect=false: ms a frame of the whole sim.
 *
 * Writes <csv-dir>/current.csv.
 *
 *   bench_current [--csv-dir DIR] [--quick] [--data DIR] */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int fail(const char *what)
{
    fprintf(stderr, "bench_current: %s: %s\n", what, ms_last_error());
    return 1;
}

static void row(FILE *csv, const char *machine, const char *commit, const char *what,
                const char *grid, const char *config, double *t, int reps)
{
    bench_stats st = bench_summarise(t, reps);
    printf("%-8s %9s %-22s %9.3f [%7.3f, %7.3f]\n", what, grid, config, st.median, st.p10, st.p90);
    fprintf(csv, "%s,%s,1,%s,%s,%s,%.4f,%.4f,%.4f,%d\n", commit, machine, what, grid, config,
            st.median, st.p10, st.p90, reps);
}

static int surface_part(FILE *csv, const char *machine, const char *commit, int quick)
{
    static const int sizes[2] = {200, 400};
    const int reps = quick ? 3 : 9, frames = quick ? 10 : 30;
    for (int k = 0; k < 2; ++k) {
        const int n = sizes[k];
        ms_surface *s[2];
        float *u = malloc((size_t)n * n * sizeof *u), *v = malloc((size_t)n * n * sizeof *v);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                /* a current round the pool, 0.1 m/s at its rim: it shears */
                const float px = (x + 0.5f) / n - 0.5f, py = (y + 0.5f) / n - 0.5f;
                u[(size_t)y * n + x] = -0.2f * py;
                v[(size_t)y * n + x] = 0.2f * px;
            }
        for (int m = 0; m < 2; ++m) {
            ms_surface_desc d = ms_surface_desc_default();
            d.nx = d.ny = n;
            d.dx = 1.0f / n;
            d.wave_speed = 0.2f;
            d.damping = 0.8f;
            if (ms_surface_create(&d, &s[m]) != MS_OK)
                return fail("surface");
            for (int i = 0; i < 10; ++i)
                ms_surface_add_drop(s[m], 0.1f + 0.08f * i, 0.2f + 0.06f * i, 0.03f, 0.005f);
            ms_surface_step(s[m], 1.0f / 60); /* warm-up */
        }
        double t[2][32];
        for (int r = 0; r < reps; ++r)
            for (int m = 0; m < 2; ++m) {
                double t0 = cpu_now();
                for (int f = 0; f < frames; ++f) {
                    if (m && ms_surface_set_current(s[m], u, v) != MS_OK)
                        return fail("set_current");
                    if (ms_surface_step(s[m], 1.0f / 60) != MS_OK)
                        return fail("step");
                }
                t[m][r] = (cpu_now() - t0) * 1e3 / frames;
            }
        char grid[32];
        snprintf(grid, sizeof grid, "%dx%d", n, n);
        row(csv, machine, commit, "surface", grid, "no current", t[0], reps);
        row(csv, machine, commit, "surface", grid, "current", t[1], reps);
        for (int m = 0; m < 2; ++m)
            ms_surface_destroy(s[m]);
        free(u);
        free(v);
    }
    return 0;
}

static int river_part(FILE *csv, const char *machine, const char *commit, int quick,
                      const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/river.json", dir);
    static const char *const off[] = {"surface.advect=false"};
    ms_scene *sc[2];
    ms_sim *sim[2];
    for (int m = 0; m < 2; ++m) {
        if (ms_scene_load_with_overrides(path, m ? 0 : 1, off, &sc[m]) != MS_OK)
            return fail(path);
        if (ms_sim_create_from_scene(sc[m], 1, &sim[m]) != MS_OK)
            return fail("river");
        for (int f = 0; f < 3; ++f) /* the priming step and two more */
            if (ms_sim_step(sim[m], ms_scene_frame_dt(sc[m])) != MS_OK)
                return fail("river");
    }
    const int reps = quick ? 3 : 9, frames = quick ? 10 : 30;
    double t[2][32];
    for (int r = 0; r < reps; ++r)
        for (int m = 0; m < 2; ++m) {
            double t0 = cpu_now();
            for (int f = 0; f < frames; ++f)
                if (ms_sim_step(sim[m], ms_scene_frame_dt(sc[m])) != MS_OK)
                    return fail("river");
            t[m][r] = (cpu_now() - t0) * 1e3 / frames;
        }
    ms_sim_info info = ms_sim_info_init();
    ms_sim_get_info(sim[1], &info);
    char grid[32];
    snprintf(grid, sizeof grid, "%dx%d", info.surface_nx, info.surface_ny);
    row(csv, machine, commit, "river", grid, "advect false", t[0], reps);
    row(csv, machine, commit, "river", grid, "advect true", t[1], reps);
    for (int m = 0; m < 2; ++m) {
        ms_sim_destroy(sim[m]);
        ms_scene_destroy(sc[m]);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_current [--csv-dir DIR] [--quick] [--data DIR]\n"
                   "CPU ms a frame of the waves with and without a current (200^2, 400^2),\n"
                   "and of the river scene with surface.advect true and false, interleaved,\n"
                   "1 thread; writes DIR/current.csv (default DIR: bench).\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "current.csv",
                               "commit,machine,threads,case,grid,config,cpu_ms_per_frame_median,"
                               "cpu_ms_per_frame_p10,cpu_ms_per_frame_p90,repeats");
    if (!csv)
        return 1;
    printf("waves carried by the flow: CPU ms a frame (1/60 s), median [p10, p90], 1 thread\n");
    printf("machine: %s; commit %s\n", machine, commit);
    int rc = surface_part(csv, machine, commit, quick);
    if (rc == 0)
        rc = river_part(csv, machine, commit, quick,
                        bench_arg_value(argc, argv, "--data", "data/scenes"));
    fclose(csv);
    return rc;
}
