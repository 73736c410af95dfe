/* Spray benchmark: what spray and foam (effects.spray, lib/sim/spray.c)
 * cost a frame and how many droplets fly, on fig1 and fig10 with spray
 * turned on (effects.spray at its defaults) and on the scenes that ship
 * with it (pour, boat, stir), headless, one thread. Per scene: droplets in
 * flight (mean and most), droplets emitted a frame, the spray's ms a
 * frame (ms_stats.spray_ms) and its share of the frame measured in the
 * same run, and for fig1 and fig10 the whole frame without spray, the two
 * runs' frames alternating in blocks so a busy machine slows both alike.
 * Writes <csv-dir>/spray.csv.
 *
 *   bench_spray [--csv-dir DIR] [--quick] [--scenes fig1,pour] [--data DIR] [--frames N]
 *
 * The frames are the scene's first N (default 240, the first 4 s: the
 * pour's splash and the stir's start are in them; 60 with --quick). */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

typedef struct {
    const char *name;
    int add_spray; /* 1: the scene has none; turned on at its defaults */
} spray_row;

static const spray_row rows[] = {
    {"fig1", 1}, {"fig10", 1}, {"pour", 0}, {"boat", 0}, {"stir", 0},
};

#define BLOCK 20 /* frames per block of the alternation */

static ms_scene *load(const char *dir, const char *name, int spray)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s.json", dir, name);
    const char *sets[] = {"effects.spray={}"};
    ms_scene *sc = NULL;
    if (ms_scene_load_with_overrides(path, spray ? 1 : 0, sets, &sc) != MS_OK) {
        fprintf(stderr, "bench_spray: %s: %s\n", name, ms_last_error());
        return NULL;
    }
    return sc;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_spray [--csv-dir DIR] [--quick] [--scenes fig1,pour] [--data "
                   "DIR] [--frames N]\n"
                   "Spray and foam's cost a frame and droplets in flight on fig1 and fig10 with\n"
                   "spray and on pour, boat and stir, one thread; writes DIR/spray.csv.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const char *dir = bench_arg_value(argc, argv, "--data", "data/scenes");
    const char *only = bench_arg_value(argc, argv, "--scenes", NULL);
    int frames = atoi(bench_arg_value(argc, argv, "--frames", quick ? "60" : "240"));
    frames = frames < BLOCK ? BLOCK : frames / BLOCK * BLOCK;
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    printf("spray: the first %d frames of each scene, 1 thread, headless\n", frames);
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%-6s %9s %6s %9s %9s %9s %7s | %9s %7s\n", "scene", "particles", "mean", "most",
           "emit/fr", "spray_ms", "share", "ms/fr", "no_spray");
    FILE *csv = bench_csv_open(
        bench_csv_dir(argc, argv), "spray.csv",
        "commit,machine,scene,threads,particles,budget,frames,droplets_mean,droplets_most,"
        "emitted_per_frame,spray_ms_per_frame,frame_ms_per_frame,spray_share,"
        "frame_ms_per_frame_without_spray");
    if (!csv)
        return 1;
    int failed = 0;
    for (size_t k = 0; k < sizeof rows / sizeof *rows; ++k) {
        if (!bench_wanted(only, rows[k].name))
            continue;
        ms_scene *sc = load(dir, rows[k].name, rows[k].add_spray);
        ms_scene *plain = rows[k].add_spray ? load(dir, rows[k].name, 0) : NULL;
        ms_sim *sim = NULL, *ref = NULL;
        if (!sc || (rows[k].add_spray && !plain) ||
            ms_sim_create_from_scene(sc, 1, &sim) != MS_OK ||
            (plain && ms_sim_create_from_scene(plain, 1, &ref) != MS_OK)) {
            fprintf(stderr, "bench_spray: %s: %s\n", rows[k].name, ms_last_error());
            failed = 1;
        }
        const float dt = sc ? ms_scene_frame_dt(sc) : 0;
        double in_flight = 0, ref_ms = 0;
        int most = 0;
        for (int f = 0; !failed && f < frames; f += BLOCK) {
            for (int b = 0; b < BLOCK && !failed; ++b) {
                failed = ms_sim_step(sim, dt) != MS_OK;
                int n = 0;
                ms_sim_spray(sim, &n);
                in_flight += n;
                most = n > most ? n : most;
            }
            const double t0 = bench_now();
            for (int b = 0; ref && b < BLOCK && !failed; ++b)
                failed = ms_sim_step(ref, dt) != MS_OK;
            ref_ms += (bench_now() - t0) * 1e3;
        }
        if (failed) {
            fprintf(stderr, "bench_spray: %s: %s\n", rows[k].name, ms_last_error());
        } else {
            ms_stats st = ms_stats_init();
            ms_sim_get_stats(sim, &st);
            ms_sim_info in = ms_sim_info_init();
            ms_sim_get_info(sim, &in);
            const double spray_ms = st.spray_ms / frames, frame_ms = st.total_ms / frames;
            const double without = ref ? ref_ms / frames : NAN;
            printf("%-6s %9d %6.0f %9d %9.1f %9.3f %6.1f%% | %9.2f %7.2f\n", rows[k].name,
                   in.particles, in_flight / frames, most, (double)st.spray_emitted / frames,
                   spray_ms, 100 * spray_ms / frame_ms, frame_ms, without);
            fprintf(csv, "%s,%s,%s,1,%d,%d,%d,%.1f,%d,%.2f,%.4f,%.4f,%.4f,%.4f\n", commit, machine,
                    rows[k].name, in.particles, in.spray_budget, frames, in_flight / frames, most,
                    (double)st.spray_emitted / frames, spray_ms, frame_ms, spray_ms / frame_ms,
                    without);
            fflush(stdout);
        }
        ms_sim_destroy(sim);
        ms_sim_destroy(ref);
        ms_scene_destroy(sc);
        ms_scene_destroy(plain);
    }
    fclose(csv);
    printf("columns: droplets in flight (mean, most), droplets emitted a frame, the spray's ms "
           "a frame (emission, flight, foam: ms_stats.spray_ms) and its share of the frame in "
           "the same run; ms/fr: the whole frame; no_spray: the same scene without spray, its "
           "frames alternating with the other's in blocks of %d (fig1, fig10).\n",
           BLOCK);
    return failed;
}
