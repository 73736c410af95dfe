/* Pressure-law benchmark on the shipped scenes: each real-time
 * scene with a volume, run whole (volume, extraction, waves, combine; no
 * rendering) on 1 thread under each pressure law, the laws' repeats
 * interleaved (ideal gas, Tait, DFSPH, ideal gas, ...) so a busy minute of
 * a shared machine slows all alike. The issue asks that a scene switch to
 * DFSPH where it is faster at equal or better accuracy: this prints, per
 * scene and law, frames/s (median and spread), the volume's ms a frame,
 * SPH sub-steps and DFSPH solver iterations a frame, and the liquid's
 * compression (max rho/rho0 - 1 over the particles, its median over the
 * frames and its largest), and each law's speed over the scene's own law.
 * Writes <csv-dir>/laws.csv.
 *
 *   bench_laws [--csv-dir DIR] [--quick] [--scenes fig1,fig4c] [--data DIR]
 *              [--repeats R]
 *
 * Each sim first runs three frames (priming); frames per repeat are chosen
 * from the scene's own law so that one of its repeats lasts about 0.3 s
 * (0.04 s with --quick), the same for every law. */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

static const char *const scenes[] = {"fig1",     "fig4c",     "fig9a",    "fig9b",
                                     "fig10",    "default",   "glass",    "stir",
                                     "fig1_x10", "fig4c_x10", "fig10_x10"};
static const char *const laws[] = {"ideal_gas", "tait", "dfsph"};
#define NLAWS 3
#define MAX_REPEATS 64
#define MAX_FRAMES 4000

typedef struct {
    ms_scene *scene; /* outlives the sim (sim.h) */
    ms_sim *sim;
    double fps[MAX_REPEATS];
    double volume_ms, frames_run;
    long substeps, iterations;
    double *compression; /* max rho/rho0 - 1 after each timed frame */
    int n_compression;
    int particles;
} law_run;

/* The scene's own law: the value of its "pressure" key (the scene format
 * has one, in its volume section), ideal gas when it has none. */
static int scene_law(const char *path)
{
    ms_scene *sc;
    if (ms_scene_load(path, &sc) != MS_OK)
        return -1;
    const char *p = strstr(ms_scene_text(sc), "\"pressure\"");
    int law = 0;
    if (p) {
        p += strlen("\"pressure\"");
        while (*p == ' ' || *p == ':' || *p == '\n' || *p == '\t' || *p == '"')
            ++p;
        for (int k = 0; k < NLAWS; ++k)
            if (strncmp(p, laws[k], strlen(laws[k])) == 0 && p[strlen(laws[k])] == '"')
                law = k;
    }
    ms_scene_destroy(sc);
    return law;
}

static ms_volume_info volume_info(ms_sim *sim)
{
    ms_volume_info in = ms_volume_info_init();
    ms_volume *v = ms_sim_volume(sim);
    if (v)
        ms_volume_get_info(v, &in);
    return in;
}

/* The sim of scene `path` under law k, past three priming frames;
 * *per_frame: s a priming frame. */
static int open_law(const char *path, int k, law_run *run, double *per_frame)
{
    char set[64];
    snprintf(set, sizeof set, "volume.pressure=%s", laws[k]);
    const char *overrides[1] = {set};
    if (ms_scene_load_with_overrides(path, 1, overrides, &run->scene) != MS_OK ||
        ms_sim_create_from_scene(run->scene, 1, &run->sim) != MS_OK)
        return -1;
    const float dt = ms_scene_frame_dt(run->scene);
    double t0 = bench_now();
    for (int f = 0; f < 3; ++f)
        if (ms_sim_step(run->sim, dt) != MS_OK)
            return -1;
    *per_frame = (bench_now() - t0) / 3;
    return 0;
}

static int timed_frames(law_run *run, float dt, int frames, int r)
{
    ms_stats a = ms_stats_init(), b = ms_stats_init();
    ms_sim_get_stats(run->sim, &a);
    ms_volume_info ia = volume_info(run->sim);
    double compute = 0.0;
    for (int f = 0; f < frames; ++f) {
        double s0 = bench_now();
        if (ms_sim_step(run->sim, dt) != MS_OK)
            return -1;
        compute += bench_now() - s0;
        /* reading the compression is outside the timed step */
        run->compression[run->n_compression++] = volume_info(run->sim).max_density_error;
    }
    ms_sim_get_stats(run->sim, &b);
    ms_volume_info ib = volume_info(run->sim);
    run->fps[r] = frames / compute;
    run->volume_ms += b.volume_ms - a.volume_ms;
    run->frames_run += frames;
    run->substeps += ib.substeps - ia.substeps;
    run->iterations += (ib.density_iterations_total - ia.density_iterations_total) +
                       (ib.divergence_iterations_total - ia.divergence_iterations_total);
    run->particles = ib.count;
    return 0;
}

int main(int argc, char **argv)
{
    if (bench_help(
            argc, argv,
            "usage: bench_laws [--csv-dir DIR] [--quick] [--scenes fig1,fig4c] [--data DIR]\n"
            "                  [--repeats R]\n"
            "The shipped real-time scenes with a volume, 1 thread, simulation only, under\n"
            "the ideal gas, Tait and DFSPH laws (repeats interleaved): frames/s, volume ms,\n"
            "sub-steps and solver iterations a frame, compression; writes DIR/laws.csv.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const char *dir = bench_arg_value(argc, argv, "--data", "data/scenes");
    const char *only = bench_arg_value(argc, argv, "--scenes", NULL);
    const int repeats = (int)fmax(
        1, fmin(MAX_REPEATS, atoi(bench_arg_value(argc, argv, "--repeats", quick ? "2" : "5"))));
    const double target = quick ? 0.04 : 0.3;
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    printf("laws: shipped scenes, 1 thread, simulation only; frames/s median [p10, p90] over %d "
           "repeats, the laws interleaved\nmachine: %s; commit %s\n",
           repeats, machine, commit);
    printf("%-10s %-9s %6s %6s %8s %8s %8s %8s %8s %8s %9s %9s %7s\n", "scene", "law", "parts",
           "frames", "fps", "p10", "p90", "vol ms", "substep", "iters", "compr med", "compr max",
           "x own");
    FILE *csv = bench_csv_open(
        bench_csv_dir(argc, argv), "laws.csv",
        "commit,machine,scene,law,scene_law,threads,particles,frames_per_repeat,repeats,"
        "fps_median_per_s,fps_p10_per_s,fps_p90_per_s,volume_ms_per_frame,substeps_per_frame,"
        "iterations_per_frame,max_compression_median,max_compression_max,fps_over_scene_law");
    if (!csv)
        return 1;
    int failed = 0;
    for (size_t s = 0; s < sizeof scenes / sizeof *scenes; ++s) {
        if (!bench_wanted(only, scenes[s]))
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.json", dir, scenes[s]);
        const int own = scene_law(path);
        static law_run run[NLAWS];
        memset(run, 0, sizeof run);
        double per_frame[NLAWS] = {0};
        int bad = own < 0;
        for (int k = 0; k < NLAWS && !bad; ++k)
            bad = open_law(path, k, &run[k], &per_frame[k]) != 0;
        const int frames =
            bad ? 0 : (int)fmax(3, fmin(MAX_FRAMES / repeats, round(target / per_frame[own])));
        for (int k = 0; k < NLAWS && !bad; ++k)
            bad = !(run[k].compression = malloc(sizeof(double) * (size_t)(frames * repeats)));
        const float dt = bad ? 0.0f : ms_scene_frame_dt(run[0].scene);
        for (int r = 0; r < repeats && !bad; ++r)
            for (int k = 0; k < NLAWS && !bad; ++k)
                bad = timed_frames(&run[k], dt, frames, r) != 0;
        if (bad) {
            fprintf(stderr, "bench_laws: %s: %s\n", scenes[s], ms_last_error());
            failed = 1;
        }
        const double own_fps = bad ? 0.0 : bench_summarise(run[own].fps, repeats).median;
        for (int k = 0; k < NLAWS && !bad; ++k) {
            double fps_copy[MAX_REPEATS];
            memcpy(fps_copy, run[k].fps, sizeof(double) * (size_t)repeats);
            bench_stats fps = bench_summarise(fps_copy, repeats);
            bench_stats comp = bench_summarise(run[k].compression, run[k].n_compression);
            double comp_max = run[k].compression[run[k].n_compression - 1]; /* sorted */
            double vol = run[k].volume_ms / run[k].frames_run;
            double sub = run[k].substeps / run[k].frames_run;
            double it = run[k].iterations / run[k].frames_run;
            double over = own_fps > 0 ? fps.median / own_fps : 0.0;
            printf("%-10s %-9s %6d %6d %8.1f %8.1f %8.1f %8.3f %8.2f %8.2f %8.3f %% %8.3f %% "
                   "%7.3f\n",
                   scenes[s], laws[k], run[k].particles, frames, fps.median, fps.p10, fps.p90, vol,
                   sub, it, 100.0 * comp.median, 100.0 * comp_max, over);
            fprintf(csv, "%s,%s,%s,%s,%s,1,%d,%d,%d,%.3f,%.3f,%.3f,%.4f,%.3f,%.3f,%.6f,%.6f,%.3f\n",
                    commit, machine, scenes[s], laws[k], laws[own], run[k].particles, frames,
                    repeats, fps.median, fps.p10, fps.p90, vol, sub, it, comp.median, comp_max,
                    over);
            fflush(stdout);
        }
        for (int k = 0; k < NLAWS; ++k) {
            free(run[k].compression);
            if (run[k].sim)
                ms_sim_destroy(run[k].sim);
            if (run[k].scene)
                ms_scene_destroy(run[k].scene);
        }
    }
    fclose(csv);
    printf("columns: vol ms = the volume's ms a frame (SPH + interaction); substep = SPH "
           "sub-steps a frame; iters = DFSPH's density + divergence iterations a frame; compr = "
           "max rho/rho0 - 1 over the particles after each frame (median over the frames, and "
           "the largest); x own = frames/s over the scene's own law.\n");
    return failed;
}
