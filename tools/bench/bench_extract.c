/* Extraction benchmark (eqs. 16-18): ms per ms_volume_extract_height call of a scene's volume after
 * 100 frames of the scene (the liquid in motion), at the scene's field
 * size, with 1 and 2 threads. With 2, a second thread of this program
 * lends itself to the volume's pool during the timed calls (as a 2-thread
 * sim's surface thread does while the volume steps, ms_vpool_help), so
 * phase B's columns run on both; without it the sim's pool has no
 * thread of its own outside a step and the call would run on one (the
 * 1-thread figure again).
 * Median and 10th/90th percentiles of
 * the repeats; cpu_ms, the calling thread's CPU time per call (the cost
 * of a 1-thread call on a loaded machine; with 2 threads the helper's
 * share is not in it); and "sim", the sim's own extract_ms per frame over 30 frames
 * (phase A with its neighbour recount, the particle copy, phase B; the
 * mean, one run). Each case runs twice, interleaved repeat by repeat,
 * both with the best gather of the CPU: the reference search (the column
 * search the band search replaced, ms_extract_snap.reference) and the band search (the default);
 * "x" is the reference median over the band median. max_dh: the largest
 * |band - reference| of a cell over the 100 frames (phase B of each
 * frame's snapshot both ways, 1 thread), in m and in spacings. Writes
 * <csv-dir>/extract.csv (gather: the instruction set; search: reference
 * or band).
 *
 *   bench_extract [--csv-dir DIR] [--quick] [--data DIR] [--scenes fig1,fig10] */
#include <pthread.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"
#include "volume/extract.h"
#include "volume/volume_internal.h"

/* s of CPU time of the calling thread: on a loaded machine the cost of a
 * 1-thread call, which wall-clock time is not */
static double thread_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The second thread of a 2-thread row: runs the pool's chunks until the
 * calling thread closes the pool to helpers. */
static void *lend(void *pool)
{
    ms_vpool_help(pool);
    return NULL;
}

static const char *const scenes[] = {"fig1", "fig1_x10", "fig10", "glass"};

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_extract [--csv-dir DIR] [--quick] [--data DIR] [--scenes a,b]\n"
                   "ms per height-field extraction (eqs. 16-18) of a scene's volume after 100\n"
                   "frames, 1 and 2 threads: median [p10, p90], the reference search and the\n"
                   "band search interleaved, and the band's max |dh| against the reference over\n"
                   "the 100 frames. Writes extract.csv.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const char *dir = bench_arg_value(argc, argv, "--data", "data/scenes");
    const char *only = bench_arg_value(argc, argv, "--scenes", NULL);
    char machine[300], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    FILE *csv = bench_csv_open(
        bench_csv_dir(argc, argv), "extract.csv",
        "scene,threads,particles,nx,ny,ms_median,ms_p10,ms_p90,cpu_ms_median,sim_extract_ms,"
        "machine,"
        "commit,gather,search,max_dh_m,max_dh_spacings");
    if (!csv)
        return 1;
    printf("extract: ms per ms_volume_extract_height after 100 frames, median [p10, p90]\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%-10s %3s %6s %9s %7s %9s %9s %9s %9s %9s %9s %6s %10s\n", "scene", "thr", "parts",
           "field", "gather", "search", "ms", "p10", "p90", "cpu_ms", "sim", "x", "max_dh");
    for (size_t s = 0; s < sizeof scenes / sizeof *scenes; ++s) {
        if (!bench_wanted(only, scenes[s]))
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
            const int frames = quick ? 10 : 100;
            ms_extract_snap es = {0};
            ms_extract_work ew = {0};
            float *ha = NULL, *hb = NULL;
            double max_dh = 0.0;
            for (int f = 0; f < frames; ++f) {
                if (ms_sim_step(sim, ms_scene_frame_dt(sc)) != MS_OK) {
                    fprintf(stderr, "bench_extract: %s: %s\n", scenes[s], ms_last_error());
                    return 1;
                }
                int fx, fy;
                ms_sim_volume_height(sim, &fx, &fy);
                if (!ha) {
                    ha = malloc((size_t)fx * fy * sizeof *ha);
                    hb = malloc((size_t)fx * fy * sizeof *hb);
                    if (!ha || !hb)
                        return 1;
                }
                if (ms_volume_extract_snap(ms_sim_volume(sim), &es) != MS_OK)
                    return 1;
                es.reference = 1;
                ms_status st = ms_extract_field(&es, &ew, NULL, fx, fy, ha);
                es.reference = 0;
                if (st != MS_OK || ms_extract_field(&es, &ew, NULL, fx, fy, hb) != MS_OK) {
                    fprintf(stderr, "bench_extract: %s: %s\n", scenes[s], ms_last_error());
                    return 1;
                }
                for (int c = 0; c < fx * fy; ++c) {
                    const double d = fabs((double)ha[c] - hb[c]);
                    max_dh = d > max_dh ? d : max_dh;
                }
            }
            const double spacing = es.spacing;
            free(ha);
            free(hb);
            ms_extract_snap_free(&es);
            ms_extract_work_free(&ew);
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
            float *h2 = malloc((size_t)nx * ny * sizeof *h2);
            if (!h || !h2)
                return 1;
            enum { REPEATS = 31 };
            /* the searches to compare: the reference and the band */
            double t[2][REPEATS], tc[2][REPEATS];
            ms_extract_snap snap = {0};
            ms_extract_work work = {0};
            if (ms_volume_extract_snap(v, &snap) != MS_OK)
                return 1;
                /* one call: phase A (marks and copy; the counts are valid
             * after the first) and phase B with the volume's pool */
#define EXTRACT_CALL(ref, out)                                                    \
    do {                                                                          \
        ms_volume_extract_snap(v, &snap);                                         \
        snap.reference = (ref);                                                   \
        ms_extract_field(&snap, &work, ms_volume_extract_pool(v), nx, ny, (out)); \
    } while (0)
            int calls = 1;
            for (;;) { /* calls per repeat: a repeat lasts about 20 ms (4 ms quick) */
                double t0 = bench_now();
                for (int c = 0; c < calls; ++c)
                    EXTRACT_CALL(1, h);
                if (bench_now() - t0 > (quick ? 0.004 : 0.02) || calls > 100000)
                    break;
                calls *= 2;
            }
            const int repeats = quick ? 5 : REPEATS;
            ms_vpool *pool = ms_volume_extract_pool(v);
            pthread_t helper;
            int lent = 0;
            if (threads == 2 && pool) {
                ms_vpool_help_open(pool);
                lent = pthread_create(&helper, NULL, lend, pool) == 0;
                if (!lent)
                    ms_vpool_help_close(pool);
            }
            for (int r = 0; r < repeats; ++r)
                for (int g = 0; g < 2; ++g) { /* interleaved: the same minute */
                    double t0 = bench_now(), c0 = thread_cpu_now();
                    for (int c = 0; c < calls; ++c)
                        EXTRACT_CALL(g == 0, h);
                    t[g][r] = (bench_now() - t0) * 1e3 / calls;
                    tc[g][r] = (thread_cpu_now() - c0) * 1e3 / calls;
                }
#undef EXTRACT_CALL
            if (lent) {
                ms_vpool_help_close(pool);
                pthread_join(helper, NULL);
            }
            if (threads == 2 && !lent) {
                fprintf(stderr, "bench_extract: %s: no second thread for the 2-thread row\n",
                        scenes[s]);
                return 1;
            }
            /* the library's own call is the band search */
            ms_volume_extract_height(v, nx, ny, h);
            ms_volume_extract_snap(v, &snap);
            ms_extract_field(&snap, &work, NULL, nx, ny, h2);
            if (memcmp(h, h2, (size_t)nx * ny * sizeof *h) != 0) {
                fprintf(stderr, "bench_extract: %s: ms_volume_extract_height is not the band's\n",
                        scenes[s]);
                return 1;
            }
            ms_extract_snap_free(&snap);
            ms_extract_work_free(&work);
            int n = 0;
            const float *pos[3];
            ms_sim_particles(sim, &n, pos, NULL);
            char field[32];
            snprintf(field, sizeof field, "%dx%d", nx, ny);
            double ref = 0.0;
            const char *isa = v->isa == MS_VOLUME_ISA_AVX512 ? "avx512" : "c";
            for (int g = 0; g < 2; ++g) {
                bench_stats st = bench_summarise(t[g], repeats);
                bench_stats sc_ = bench_summarise(tc[g], repeats);
                const char *search = g == 0 ? "reference" : "band";
                const double dh = g == 0 ? 0.0 : max_dh;
                if (g == 0)
                    ref = st.median;
                printf("%-10s %3d %6d %9s %7s %9s %9.3f %9.3f %9.3f %9.3f %9.3f %6.2f %10.3g\n",
                       scenes[s], threads, n, field, isa, search, st.median, st.p10, st.p90,
                       sc_.median, sim_ms, ref / st.median, dh);
                fprintf(csv, "%s,%d,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%s,%s,%s,%.3g,%.4f\n",
                        scenes[s], threads, n, nx, ny, st.median, st.p10, st.p90, sc_.median,
                        sim_ms, machine, commit, isa, search, dh, dh / spacing);
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
