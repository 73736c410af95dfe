/* Volume-solver benchmark: ms per SPH sub-step of a dam break (a column
 * a x a x 2a released in a 4a x a x 2.2a tank, h = 2 spacing) with about
 * 2k, 8k, 32k and 128k particles, on one and two threads, and the neighbour
 * pairs (r < h, wall images included) handled per second. Each measured
 * step is one sub-step at half the largest stable dt, after a warm-up of
 * 20 sub-steps that lets the column start to fall; the median and the
 * 10th/90th percentiles of the repeats are printed. Writes volume.csv.
 * --sizes N,N and --threads T run only those (an A/B of two builds runs
 * them alternately). */
#include <math.h>
#include <string.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

#if defined(__AVX512F__)
#define BUILD_FLAVOUR "avx512"
#elif defined(__AVX2__)
#define BUILD_FLAVOUR "avx2"
#else
#define BUILD_FLAVOUR "portable"
#endif

static ms_volume *dam_break(int target, int threads)
{
    const float a = 0.5f;
    const float s = a * cbrtf(2.0f / (float)target);
    ms_volume_desc d = ms_volume_desc_default();
    d.domain_max[0] = 4.0f * a;
    d.domain_max[1] = a;
    d.domain_max[2] = 2.2f * a;
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    d.threads = threads;
    d.max_particles = 2 * target;
    ms_volume *v;
    if (ms_volume_create(&d, &v) != MS_OK ||
        ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){a, a, 2.0f * a}) != MS_OK) {
        fprintf(stderr, "bench_volume: %s\n", ms_last_error());
        exit(1);
    }
    return v;
}

/* One sub-step; returns its wall time in s (0 if it took more than one). */
static double one_substep(ms_volume *v)
{
    ms_volume_info a = ms_volume_info_init(), b = ms_volume_info_init();
    ms_volume_get_info(v, &a);
    double t0 = bench_now();
    if (ms_volume_step(v, 0.5f * a.max_dt) != MS_OK) {
        fprintf(stderr, "bench_volume: %s\n", ms_last_error());
        exit(1);
    }
    double t = bench_now() - t0;
    ms_volume_get_info(v, &b);
    return b.substeps == a.substeps + 1 ? t : 0.0;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_volume [--csv-dir DIR] [--quick] [--sizes N,N] [--threads T]\n"
                   "ms per SPH sub-step of a dam break with ~2k, 8k, 32k and 128k particles on 1\n"
                   "and 2 threads (median, 10th-90th percentile) and neighbour pairs per second;\n"
                   "writes DIR/volume.csv (default DIR: bench).\n"
                   "  --sizes N,N    only these particle counts (default 2000,8000,32000,128000)\n"
                   "  --threads T    only T threads (default 1 and 2)\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    int sizes[8] = {2000, 8000, 32000, 128000}, nsizes = 4, tlo = 1, thi = 2;
    for (int a = 1; a + 1 < argc; ++a) {
        if (strcmp(argv[a], "--sizes") == 0) {
            nsizes = 0;
            for (char *p = argv[a + 1]; *p && nsizes < 8;) {
                char *end;
                long n = strtol(p, &end, 10);
                if (end == p || n < 100 || n > 4000000) {
                    fprintf(stderr, "bench_volume: --sizes %s: want counts in [100, 4e6]\n",
                            argv[a + 1]);
                    return 1;
                }
                sizes[nsizes++] = (int)n;
                p = *end == ',' ? end + 1 : end;
            }
        } else if (strcmp(argv[a], "--threads") == 0) {
            tlo = thi = atoi(argv[a + 1]);
            if (tlo < 1 || tlo > 64) {
                fprintf(stderr, "bench_volume: --threads %s: want 1..64\n", argv[a + 1]);
                return 1;
            }
        }
    }
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    printf("volume: SPH dam break, ms per sub-step (median, p10 .. p90), build %s\n",
           BUILD_FLAVOUR);
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%9s %7s %7s %10s %10s %10s %12s %11s\n", "particles", "threads", "repeats", "ms/step",
           "p10", "p90", "pairs/step", "Mpairs/s");
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "volume.csv",
                               "commit,machine,build,threads,particles,repeats,"
                               "ms_per_step_median,ms_per_step_p10,ms_per_step_p90,"
                               "pairs_per_step,Mpairs_per_s");
    if (!csv)
        return 1;
    for (int k = 0; k < nsizes; ++k) {
        for (int threads = tlo; threads <= thi; ++threads) {
            ms_volume *v = dam_break(sizes[k], threads);
            for (int w = 0; w < 20; ++w) /* warm-up: lists grown, column moving */
                one_substep(v);
            const int reps = quick ? 3 : (sizes[k] >= 128000 ? 9 : 21);
            double t[32];
            int got = 0;
            for (int r = 0; r < reps; ++r) {
                double dt = one_substep(v);
                if (dt > 0.0)
                    t[got++] = dt * 1e3;
            }
            ms_volume_info in = ms_volume_info_init();
            ms_volume_get_info(v, &in);
            bench_stats st = bench_summarise(t, got);
            double mpairs = in.pairs / (st.median * 1e-3) * 1e-6;
            printf("%9d %7d %7d %10.3f %10.3f %10.3f %12.0f %11.1f\n", in.count, threads, got,
                   st.median, st.p10, st.p90, in.pairs, mpairs);
            fprintf(csv, "%s,%s,%s,%d,%d,%d,%.4f,%.4f,%.4f,%.0f,%.2f\n", commit, machine,
                    BUILD_FLAVOUR, threads, in.count, got, st.median, st.p10, st.p90, in.pairs,
                    mpairs);
            ms_volume_destroy(v);
        }
    }
    fclose(csv);
    printf("wrote %s/volume.csv\n", bench_csv_dir(argc, argv));
    return 0;
}
