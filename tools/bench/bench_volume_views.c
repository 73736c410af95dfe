/* What ms_volume_particles costs (the Python package's zero-copy
 * volume.positions / volume.velocities): once a caller asked for the
 * views, every ms_volume_step ends with one copy of the particles into
 * them. Two identical dam breaks (bench_volume's, 1 thread), one with the
 * views on, are stepped in turn, one SPH sub-step per ms_volume_step (the
 * worst case: a frame usually takes several sub-steps per copy); the
 * median and 10th/90th percentiles of the per-pair ratio on/off are
 * printed, so a loaded machine shifts both sides alike. The copy alone is
 * timed too: ms_volume_step(v, 0) takes no sub-step but still refreshes
 * the views, so its time with the views on minus off is the copy's, and
 * copy / sub-step the overhead (less noisy than the ratio). Writes
 * volume_views.csv. */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

static ms_volume *dam_break(int target)
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
    ms_volume *v;
    if (ms_volume_create(&d, &v) != MS_OK ||
        ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){a, a, 2.0f * a}) != MS_OK) {
        fprintf(stderr, "bench_volume_views: %s\n", ms_last_error());
        exit(1);
    }
    return v;
}

/* One ms_volume_step of dt; its wall time in ms. */
static double timed_step(ms_volume *v, float dt)
{
    double t0 = bench_now();
    if (ms_volume_step(v, dt) != MS_OK) {
        fprintf(stderr, "bench_volume_views: %s\n", ms_last_error());
        exit(1);
    }
    return (bench_now() - t0) * 1e3;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_volume_views [--csv-dir DIR] [--quick]\n"
                   "ms per SPH sub-step with and without ms_volume_particles' views kept\n"
                   "(two dam breaks stepped in turn), and the ratio; writes\n"
                   "DIR/volume_views.csv (default DIR: bench).\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    printf("volume views: ms per SPH sub-step, views kept vs not, 1 thread\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%9s %7s %10s %10s %10s %10s %10s %10s %9s\n", "particles", "repeats", "ms on", "ms off",
           "ratio", "p10", "p90", "copy ms", "copy/step");
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "volume_views.csv",
                               "commit,machine,particles,repeats,ms_on_median,ms_off_median,"
                               "ratio_median,ratio_p10,ratio_p90,copy_ms_median,copy_per_step");
    if (!csv)
        return 1;
    const int sizes[3] = {8000, 32000, 128000};
    for (int k = 0; k < (quick ? 2 : 3); ++k) {
        ms_volume *on = dam_break(sizes[k]), *off = dam_break(sizes[k]);
        int n;
        const float *pos[3], *vel[3];
        if (ms_volume_particles(on, &n, pos, vel) != MS_OK) {
            fprintf(stderr, "bench_volume_views: %s\n", ms_last_error());
            return 1;
        }
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(off, &in);
        const float dt = 0.5f * in.max_dt; /* one sub-step each, the same for both */
        for (int w = 0; w < 10; ++w) {
            timed_step(on, dt);
            timed_step(off, dt);
        }
        const int reps = quick ? 5 : (sizes[k] >= 128000 ? 9 : 21);
        double a[32], b[32], r[32];
        for (int i = 0; i < reps; ++i) {
            /* alternate which goes first, so neither always runs warm */
            if (i % 2) {
                a[i] = timed_step(on, dt);
                b[i] = timed_step(off, dt);
            } else {
                b[i] = timed_step(off, dt);
                a[i] = timed_step(on, dt);
            }
            r[i] = a[i] / b[i];
        }
        bench_stats sa = bench_summarise(a, reps), sb = bench_summarise(b, reps),
                    sr = bench_summarise(r, reps);
        /* the copy alone: steps of 0 s, many, interleaved */
        double c_on[101], c_off[101];
        for (int i = 0; i < 101; ++i) {
            c_on[i] = timed_step(on, 0.0f);
            c_off[i] = timed_step(off, 0.0f);
        }
        double copy = bench_summarise(c_on, 101).median - bench_summarise(c_off, 101).median;
        printf("%9d %7d %10.3f %10.3f %10.4f %10.4f %10.4f %10.4f %8.2f%%\n", ms_volume_count(on),
               reps, sa.median, sb.median, sr.median, sr.p10, sr.p90, copy,
               100.0 * copy / sb.median);
        fprintf(csv, "%s,%s,%d,%d,%.4f,%.4f,%.5f,%.5f,%.5f,%.5f,%.5f\n", commit, machine,
                ms_volume_count(on), reps, sa.median, sb.median, sr.median, sr.p10, sr.p90, copy,
                copy / sb.median);
        ms_volume_destroy(on);
        ms_volume_destroy(off);
    }
    fclose(csv);
    printf("wrote %s/volume_views.csv\n", bench_csv_dir(argc, argv));
    return 0;
}
