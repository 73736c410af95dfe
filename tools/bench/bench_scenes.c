/* Scene benchmark: each scene of DESIGN 8 (the paper's Table 1) and its
 * _x10 variant, simulated headless (no rendering) with 1 and 2 threads.
 * Prints frames per second (median and spread over repeats of a fixed
 * number of frames), the per-stage split in ms per frame, the paper's
 * Table 1 figure beside it, the 2-thread speed-up, and the memory
 * bandwidth measured in the same run with the bound it puts on the wave
 * side of a frame. Writes <csv-dir>/scenes.csv.
 *
 *   bench_scenes [--csv-dir DIR] [--quick] [--scenes fig1,fig1_x10] [--data DIR]
 *                [--frames N] [--repeats R]
 *
 * The first three frames are skipped (the first step only primes the
 * pipeline); then `repeats` runs of `frames` frames each are timed, the
 * same frames for 1 and 2 threads, whose repeats alternate (x2pair: the
 * median of each pair's ratio). Without --frames, the frames per repeat
 * are chosen once per scene (from the 1-thread warm-up) so that a repeat
 * lasts about 0.4 s (0.05 s with --quick). */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

typedef struct {
    const char *name;
    double paper_fps; /* Table 1, with rendering at 950 x 950; 0 = none */
} scene_row;

static const scene_row rows[] = {
    {"fig1", 30},   {"fig1_x10", 0},  {"fig3", 46},  {"fig3_x10", 0},
    {"fig4c", 102}, {"fig4c_x10", 0}, {"fig9a", 85}, {"fig9a_x10", 0},
    {"fig9b", 93},  {"fig9b_x10", 0}, {"fig10", 75}, {"fig10_x10", 0},
};

/* Bytes the wave side moves per cell when nothing stays in cache: a
 * leapfrog step reads h, v, a, delta and writes v, h (24 B); combining
 * reads the wave field and writes the sum (8 B, the SPH rows stay cached). */
#define WAVE_BYTES_PER_CELL_STEP 24.0
#define COMBINE_BYTES_PER_CELL 8.0

typedef struct {
    double fps[64], ms[5][64]; /* per repeat: frames/s; ms/frame of total + 4 stages */
    int frames, repeats, n_time, particles;
    ms_sim_info info;
} result;

/* A sim of the scene with `threads`, past its warm-up (the priming step
 * and two more); *per_frame: s per warm-up frame. */
static ms_sim *warm_sim(const ms_scene *sc, int threads, double *per_frame)
{
    ms_sim *sim;
    if (ms_sim_create_from_scene(sc, threads, &sim) != MS_OK) {
        fprintf(stderr, "bench_scenes: %s: %s\n", ms_scene_name(sc), ms_last_error());
        return NULL;
    }
    const float dt = ms_scene_frame_dt(sc);
    double t0 = bench_now();
    for (int i = 0; i < 3; ++i)
        if (ms_sim_step(sim, dt) != MS_OK) {
            fprintf(stderr, "bench_scenes: %s: %s\n", ms_scene_name(sc), ms_last_error());
            ms_sim_destroy(sim);
            return NULL;
        }
    *per_frame = (bench_now() - t0) / 3;
    return sim;
}

/* Repeat r of `out->frames` frames of sim. */
static int repeat(ms_sim *sim, const ms_scene *sc, int r, result *out)
{
    const float dt = ms_scene_frame_dt(sc);
    ms_stats a = ms_stats_init(), b = ms_stats_init();
    ms_sim_get_stats(sim, &a);
    double s0 = bench_now();
    for (int f = 0; f < out->frames; ++f)
        if (ms_sim_step(sim, dt) != MS_OK) {
            fprintf(stderr, "bench_scenes: %s: %s\n", ms_scene_name(sc), ms_last_error());
            return 1;
        }
    double secs = bench_now() - s0;
    ms_sim_get_stats(sim, &b);
    const int frames = out->frames;
    out->fps[r] = frames / secs;
    out->ms[0][r] = secs * 1e3 / frames;
    out->ms[1][r] = (b.volume_ms - a.volume_ms) / frames;
    out->ms[2][r] = (b.extract_ms - a.extract_ms) / frames;
    out->ms[3][r] = (b.surface_ms - a.surface_ms) / frames;
    out->ms[4][r] = (b.combine_ms - a.combine_ms) / frames;
    out->n_time = b.n_time;
    return 0;
}

/* Runs one scene with 1 and 2 threads, their repeats interleaved (1, 2,
 * 1, 2, ...), so that a busy minute of a shared
 * machine slows both alike and the ratio stays fair: run one after the
 * other, a minute when another process held a core slowed only the
 * 2-thread run. Frames per repeat chosen from the 1-thread warm-up
 * (frames_hint 0) so a repeat lasts about `target` seconds; the two sims
 * take the same frames. */
static int run_pair(const ms_scene *sc, int frames_hint, int repeats, double target, result out[2])
{
    ms_sim *sim[2] = {NULL, NULL};
    double per_frame[2] = {0, 0};
    int failed = 0;
    for (int t = 0; t < 2 && !failed; ++t)
        failed = !(sim[t] = warm_sim(sc, t + 1, &per_frame[t]));
    int frames = frames_hint;
    if (frames <= 0)
        frames = (int)fmax(5, fmin(400, round(target / fmax(per_frame[0], 1e-6))));
    for (int t = 0; t < 2; ++t) {
        out[t].frames = frames;
        out[t].repeats = repeats;
    }
    for (int r = 0; r < repeats && !failed; ++r)
        for (int t = 0; t < 2 && !failed; ++t)
            failed = repeat(sim[t], sc, r, &out[t]);
    for (int t = 0; t < 2; ++t)
        if (sim[t]) {
            out[t].info = ms_sim_info_init();
            ms_sim_get_info(sim[t], &out[t].info);
            out[t].particles = out[t].info.particles;
            ms_sim_destroy(sim[t]);
        }
    return failed;
}

int main(int argc, char **argv)
{
    if (bench_help(
            argc, argv,
            "usage: bench_scenes [--csv-dir DIR] [--quick] [--scenes fig1,fig1_x10] [--data DIR]\n"
            "                    [--frames N] [--repeats R]\n"
            "Each scene of the paper's Table 1 and its _x10 variant, headless, with 1 and 2\n"
            "threads: frames/s (median, 10th-90th percentile), ms per frame per stage, the\n"
            "paper's figure; writes DIR/scenes.csv (default DIR: bench).\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const char *dir = bench_arg_value(argc, argv, "--data", "data/scenes");
    const char *only = bench_arg_value(argc, argv, "--scenes", NULL);
    const int repeats =
        (int)fmax(1, fmin(64, atoi(bench_arg_value(argc, argv, "--repeats", quick ? "3" : "7"))));
    const int frames_fixed = atoi(bench_arg_value(argc, argv, "--frames", "0"));
    const double target = quick ? 0.05 : 0.4; /* s per repeat */
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    const double gbps = bench_memcpy_gbps((size_t)256 << 20, quick ? 3 : 9);
    printf("scenes: simulation only (no rendering), frames/s median [p10, p90] over %d repeats\n",
           repeats);
    printf("machine: %s; commit %s; memcpy %.1f GB/s (read + write)\n", machine, commit, gbps);
    printf("paper: Table 1, dual-core Athlon 64 2.6 GHz, with rendering at 950x950\n");
    printf("%-10s %3s %6s %6s %9s %9s %9s %7s %6s | %7s %7s %7s %7s %7s | %7s %6s %6s\n", "scene",
           "thr", "frames", "n_time", "fps", "p10", "p90", "paper", "x2", "ms/fr", "volume",
           "extract", "waves", "combine", "bound", "parts", "x2pair");
    FILE *csv = bench_csv_open(
        bench_csv_dir(argc, argv), "scenes.csv",
        "commit,machine,scene,threads,particles,field_cells,wave_cells,n_time,frames_per_repeat,"
        "repeats,fps_median_per_s,fps_p10_per_s,fps_p90_per_s,ms_per_frame_median,"
        "volume_ms_per_frame,extract_ms_per_frame,surface_ms_per_frame,combine_ms_per_frame,"
        "speedup_vs_1_thread,paper_fps_per_s,memcpy_GBps,wave_bound_ms_per_frame,"
        "speedup_paired_median");
    if (!csv)
        return 1;
    int failed = 0;
    for (size_t k = 0; k < sizeof rows / sizeof *rows; ++k) {
        if (!bench_wanted(only, rows[k].name))
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.json", dir, rows[k].name);
        ms_scene *sc;
        if (ms_scene_load(path, &sc) != MS_OK) {
            fprintf(stderr, "bench_scenes: %s\n", ms_last_error());
            failed = 1;
            continue;
        }
        double fps1 = 0;
        static result pair[2];
        memset(pair, 0, sizeof pair);
        if (run_pair(sc, frames_fixed > 0 ? frames_fixed : 0, repeats, target, pair) != 0) {
            failed = 1;
            ms_scene_destroy(sc);
            continue;
        }
        /* the median of the repeats' own ratios: a repeat's pair ran
         * within a second of each other */
        double ratios[64];
        for (int r = 0; r < repeats; ++r)
            ratios[r] = pair[1].fps[r] / pair[0].fps[r];
        const double paired = bench_summarise(ratios, repeats).median;
        for (int threads = 1; threads <= 2; ++threads) {
            result res = pair[threads - 1];
            const int frames = res.frames;
            bench_stats fps = bench_summarise(res.fps, repeats);
            double med[5];
            for (int s = 0; s < 5; ++s)
                med[s] = bench_summarise(res.ms[s], repeats).median;
            if (threads == 1)
                fps1 = fps.median;
            double speedup = fps1 > 0 ? fps.median / fps1 : 0;
            double wave_cells = (double)res.info.surface_nx * res.info.surface_ny;
            double bound_ms = wave_cells *
                              (WAVE_BYTES_PER_CELL_STEP * res.n_time + COMBINE_BYTES_PER_CELL) /
                              (gbps * 1e9) * 1e3;
            char paper[16] = "-";
            if (rows[k].paper_fps > 0)
                snprintf(paper, sizeof paper, "%.0f", rows[k].paper_fps);
            printf("%-10s %3d %6d %6d %9.1f %9.1f %9.1f %7s %6.2f | %7.3f %7.3f %7.3f %7.3f "
                   "%7.3f | %7.3f %6d %6.2f\n",
                   rows[k].name, threads, frames, res.n_time, fps.median, fps.p10, fps.p90, paper,
                   speedup, med[0], med[1], med[2], med[3], med[4], bound_ms, res.particles,
                   threads == 2 ? paired : 1.0);
            fprintf(csv,
                    "%s,%s,%s,%d,%d,%d,%.0f,%d,%d,%d,%.3f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f,"
                    "%.3f,%.0f,%.2f,%.4f,%.3f\n",
                    commit, machine, rows[k].name, threads, res.particles,
                    res.info.field_nx * res.info.field_ny, wave_cells, res.n_time, frames, repeats,
                    fps.median, fps.p10, fps.p90, med[0], med[1], med[2], med[3], med[4], speedup,
                    rows[k].paper_fps, gbps, bound_ms, threads == 2 ? paired : 1.0);
            fflush(stdout);
        }
        ms_scene_destroy(sc);
    }
    fclose(csv);
    printf("columns: ms per frame of the whole step and of each stage (volume = interaction + "
           "SPH; extract = eqs. 16-18 + particle copy; waves = effects + coupling + N_time "
           "steps; combine = eq. 20 + floaters); with 2 threads the stages overlap. bound = the "
           "wave side's memory traffic at the measured bandwidth. x2 = frames/s over the "
           "1-thread run; x2pair = the median over repeats of each repeat's 2-thread over "
           "1-thread frames/s (the repeats of 1 and 2 threads alternate).\n");
    return failed;
}
