/* Extraction benchmark (eqs. 16-18, issue 12's goal: < 0.3 ms a frame on
 * fig1): ms per ms_volume_extract_height call of a scene's volume after
 * 60 frames of the scene (the liquid in motion), at the scene's field
 * size, with 1 and 2 volume threads. Median and 10th/90th percentiles of
 * the repeats; cpu_ms, the calling thread's CPU time per call (the cost
 * of a 1-thread call on a loaded machine; with 2 threads the workers'
 * share is not in it); and "sim", the sim's own extract_ms per frame over 30 frames
 * (phase A with its neighbour recount, the particle copy, phase B; the
 * mean, one run). Each case runs twice, interleaved repeat by repeat:
 * with the candidate gather in C (c406aeb's code path, the reference) and
 * with the AVX-512 gather when the CPU has it (issue 12); the same bytes,
 * compared here. "x" is the C median over the AVX-512 median. Writes
 * <csv-dir>/extract.csv (column gather: c or avx512).
 *
 *   bench_extract [--csv-dir DIR] [--quick] [--data DIR] [--scenes fig1,fig10] */
#include "bench_common.h"
#include "modesplit/modesplit.h"
#include "volume/volume_internal.h"

/* s of CPU time of the calling thread: on a loaded machine the cost of a
 * 1-thread call, which wall-clock time is not */
static double thread_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *const scenes[] = {"fig1", "fig1_x10", "fig10"};

static const char *arg_value(int argc, char **argv, const char *key, const char *def)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], key) == 0)
            return argv[i + 1];
    return def;
}

static int wanted(const char *list, const char *name)
{
    if (!list)
        return 1;
    size_t n = strlen(name);
    for (const char *p = list; *p;) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0)
            return 1;
        p += len + (e ? 1 : 0);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_extract [--csv-dir DIR] [--quick] [--data DIR] [--scenes a,b]\n"
                   "ms per height-field extraction (eqs. 16-18) of a scene's volume after 60\n"
                   "frames, 1 and 2 threads: median [p10, p90]. Writes extract.csv.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const char *dir = arg_value(argc, argv, "--data", "data/scenes");
    const char *only = arg_value(argc, argv, "--scenes", NULL);
    char machine[300], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    FILE *csv = bench_csv_open(
        bench_csv_dir(argc, argv), "extract.csv",
        "scene,threads,particles,nx,ny,ms_median,ms_p10,ms_p90,cpu_ms_median,sim_extract_ms,"
        "machine,"
        "commit,gather");
    if (!csv)
        return 1;
    printf("extract: ms per ms_volume_extract_height after 60 frames, median [p10, p90]\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%-10s %3s %6s %9s %7s %9s %9s %9s %9s %9s %6s\n", "scene", "thr", "parts", "field",
           "gather", "ms", "p10", "p90", "cpu_ms", "sim", "x");
    for (size_t s = 0; s < sizeof scenes / sizeof *scenes; ++s) {
        if (!wanted(only, scenes[s]))
            continue;
        char path[1024];
        snprintf(path, sizeof path, "%s/%s.json", dir, scenes[s]);
        ms_scene *sc;
        if (ms_scene_load(path, &sc) != MS_OK) {
            fprintf(stderr, "bench_extract: %s\n", ms_last_error());
            return 1;
        }
        for (int threads = 1; threads <= 2; ++threads) {
            ms_sim *sim;
            if (ms_sim_create_from_scene(sc, threads, &sim) != MS_OK) {
                fprintf(stderr, "bench_extract: %s: %s\n", scenes[s], ms_last_error());
                return 1;
            }
            const int frames = quick ? 10 : 60;
            for (int f = 0; f < frames; ++f)
                if (ms_sim_step(sim, ms_scene_frame_dt(sc)) != MS_OK) {
                    fprintf(stderr, "bench_extract: %s: %s\n", scenes[s], ms_last_error());
                    return 1;
                }
            /* the sim's own figure: extract_ms per frame (phase A, the
             * particle copy and phase B) over the next frames */
            ms_stats a = ms_stats_init(), b = ms_stats_init();
            ms_sim_get_stats(sim, &a);
            const int sframes = quick ? 5 : 30;
            for (int f = 0; f < sframes; ++f)
                if (ms_sim_step(sim, ms_scene_frame_dt(sc)) != MS_OK) {
                    fprintf(stderr, "bench_extract: %s: %s\n", scenes[s], ms_last_error());
                    return 1;
                }
            ms_sim_get_stats(sim, &b);
            const double sim_ms = (b.extract_ms - a.extract_ms) / sframes;
            int nx, ny;
            ms_sim_volume_height(sim, &nx, &ny);
            ms_volume *v = ms_sim_volume(sim);
            float *h = malloc((size_t)nx * ny * sizeof *h);
            if (!h)
                return 1;
            enum { REPEATS = 31 };
            /* the gathers to compare: C (the reference) and the best */
            const int best = ms_volume_pick_isa();
            const int isas[2] = {MS_VOLUME_ISA_C, best};
            const int nisa = best == MS_VOLUME_ISA_AVX512 ? 2 : 1;
            double t[2][REPEATS], tc[2][REPEATS];
            float *h2 = malloc((size_t)nx * ny * sizeof *h2);
            if (!h2)
                return 1;
            const int own = v->isa;
            int calls = 1;
            for (;;) { /* calls per repeat: a repeat lasts about 20 ms (4 ms quick) */
                double t0 = bench_now();
                for (int c = 0; c < calls; ++c)
                    ms_volume_extract_height(v, nx, ny, h);
                if (bench_now() - t0 > (quick ? 0.004 : 0.02) || calls > 100000)
                    break;
                calls *= 2;
            }
            const int repeats = quick ? 5 : REPEATS;
            for (int r = 0; r < repeats; ++r)
                for (int g = 0; g < nisa; ++g) { /* interleaved: the same minute */
                    v->isa = isas[g];
                    double t0 = bench_now(), c0 = thread_cpu_now();
                    for (int c = 0; c < calls; ++c)
                        ms_volume_extract_height(v, nx, ny, g ? h2 : h);
                    t[g][r] = (bench_now() - t0) * 1e3 / calls;
                    tc[g][r] = (thread_cpu_now() - c0) * 1e3 / calls;
                }
            v->isa = own;
            if (nisa == 2 && memcmp(h, h2, (size_t)nx * ny * sizeof *h) != 0) {
                fprintf(stderr, "bench_extract: %s: the AVX-512 gather's field differs from C's\n",
                        scenes[s]);
                return 1;
            }
            int n = 0;
            const float *pos[3];
            ms_sim_particles(sim, &n, pos, NULL);
            char field[32];
            snprintf(field, sizeof field, "%dx%d", nx, ny);
            double ref = 0.0;
            for (int g = 0; g < nisa; ++g) {
                bench_stats st = bench_summarise(t[g], repeats);
                bench_stats sc_ = bench_summarise(tc[g], repeats);
                const char *name = isas[g] == MS_VOLUME_ISA_AVX512 ? "avx512" : "c";
                if (g == 0)
                    ref = st.median;
                printf("%-10s %3d %6d %9s %7s %9.3f %9.3f %9.3f %9.3f %9.3f %6.2f\n", scenes[s],
                       threads, n, field, name, st.median, st.p10, st.p90, sc_.median, sim_ms,
                       ref / st.median);
                fprintf(csv, "%s,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%s,%s\n", scenes[s],
                        threads, n, nx, ny, st.median, st.p10, st.p90, sc_.median, sim_ms, machine,
                        commit, name);
            }
            free(h2);
            free(h);
            ms_sim_destroy(sim);
        }
        ms_scene_destroy(sc);
    }
    fclose(csv);
    return 0;
}
