/* DFSPH against the weakly compressible laws, side by side in one run:
 * the same dam break (a column a x a x 2a released in a 4a x a x 2.2a
 * tank, h = 2 spacing, mu = 1 Pa s) with about 2k, 32k and 128k particles,
 * then the peer's scene (a 32^3 block of spacing 0.0303 m in a 4 x 3 x 1.5 m
 * box, 32768 particles, the first 0.3 s: SPlisHSPlasH's DamBreakModel, the
 * scene SPlisHSPlasH itself was timed on) (--quick: 2k and 32k, 3 frames), simulated for a
 * fixed time after a warm-up (the peer's scene: from its release), once per
 * law: ideal gas (k = 400 m^2/s^2, c = 20 m/s), Tait (c0 = 20 m/s) and
 * DFSPH (0.1 % average compression). For each: wall time per simulated
 * second (ms/s), sub-steps and solver iterations per simulated second,
 * average and maximum compression (max(rho/rho0 - 1, 0) at the positions
 * of every frame's end), and the ratio of each law's ms/s to DFSPH's.
 * The laws run interleaved frame by frame, so machine load falls on all
 * alike. Writes dfsph.csv. */
#include <math.h>
#include <string.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

enum { LAWS = 3 };
static const ms_pressure law_of[LAWS] = {MS_PRESSURE_IDEAL_GAS, MS_PRESSURE_TAIT,
                                         MS_PRESSURE_DFSPH};
static const char *const law_name[LAWS] = {"ideal_gas", "tait", "dfsph"};

/* target > 0: the dam break of about target particles; target 0: the
 * peer's scene (SPlisHSPlasH's DamBreakModel as the issue measured it: a
 * 32^3 block of spacing 0.0303 m in a corner of a 4 x 3 m box 1.5 m
 * high), whose figures compare with its 22-26 s per simulated second. */
static ms_volume *dam_break(int target, ms_pressure law)
{
    const float a = 0.5f;
    const float s = target > 0 ? a * cbrtf(2.0f / (float)target) : 0.0303f;
    const float lo[3] = {0, 0, 0};
    float box[3] = {4.0f * a, a, 2.2f * a}, block[3] = {a, a, 2.0f * a};
    if (target == 0)
        for (int k = 0; k < 3; ++k) {
            box[k] = k == 0 ? 4.0f : (k == 1 ? 3.0f : 1.5f);
            block[k] = 32.0f * s;
        }
    ms_volume_desc d = ms_volume_desc_default();
    for (int k = 0; k < 3; ++k)
        d.domain_max[k] = box[k];
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    d.max_particles = target > 0 ? 2 * target : 65536;
    d.pressure = law;
    ms_volume *v;
    if (ms_volume_create(&d, &v) != MS_OK || ms_volume_fill_box(v, lo, block) != MS_OK) {
        fprintf(stderr, "bench_dfsph: %s\n", ms_last_error());
        exit(1);
    }
    return v;
}

typedef struct run {
    ms_volume *v;
    double wall;     /* s */
    double sim;      /* s simulated after the warm-up */
    long sub0, it0;  /* sub-steps and iterations at the warm-up's end */
    double comp_sum; /* sum over frames of the average compression */
    float comp_max;
    int frames;
} run;

/* Average and maximum compression at the current positions: a particle's
 * density from its neighbours (r < h, the wall images by reflecting the
 * neighbours across the walls within h of it), max(rho/rho0 - 1, 0). The
 * volume's own info gives only the max of the last pass, before the drift,
 * so this reads the positions and recomputes, the same way for every law.
 * O(n * neighbours) with a cell grid. */
static void compression(const ms_volume *v, double *avg, float *mx)
{
    ms_volume_desc d = ms_volume_get_desc(v);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    int n = 0;
    const float *p[3], *u[3];
    ms_volume_particle_views(v, &n, p, u);
    const float h = d.smoothing_length, h2 = h * h;
    const double kc = 15.0 / (3.14159265358979323846 * pow(h, 6)); /* spiky, eq. 11 */
    int g[3];
    for (int k = 0; k < 3; ++k)
        g[k] = (int)ceil((d.domain_max[k] - d.domain_min[k]) / h) + 1;
    long cells = (long)g[0] * g[1] * g[2];
    int *start = calloc((size_t)cells + 1, sizeof(int)), *order = malloc(sizeof(int) * (size_t)n);
    int *cell = malloc(sizeof(int) * (size_t)n);
    for (int i = 0; i < n; ++i) {
        int c[3];
        for (int k = 0; k < 3; ++k) {
            c[k] = (int)((p[k][i] - d.domain_min[k]) / h);
            c[k] = c[k] < 0 ? 0 : (c[k] >= g[k] ? g[k] - 1 : c[k]);
        }
        cell[i] = (c[2] * g[1] + c[1]) * g[0] + c[0];
        start[cell[i] + 1]++;
    }
    for (long c = 0; c < cells; ++c)
        start[c + 1] += start[c];
    int *fill = malloc(sizeof(int) * (size_t)cells);
    memcpy(fill, start, sizeof(int) * (size_t)cells);
    for (int i = 0; i < n; ++i)
        order[fill[cell[i]]++] = i;
    double sum = 0.0;
    float m = 0.0f;
    for (int i = 0; i < n; ++i) {
        int ci[3] = {cell[i] % g[0], cell[i] / g[0] % g[1], cell[i] / (g[0] * g[1])};
        float q[3] = {p[0][i], p[1][i], p[2][i]};
        double rho = 0.0;
        for (unsigned f = 0; f < 8; ++f) { /* the particle's neighbours and their wall images */
            float w[3];
            int ok = 1;
            for (int k = 0; k < 3 && ok; ++k) {
                if (!(f & (1u << k)))
                    continue;
                float lo = d.domain_min[k], hi = d.domain_max[k];
                w[k] = q[k] - lo <= hi - q[k] ? lo : hi;
                ok = fabsf(q[k] - w[k]) < h;
            }
            if (!ok)
                continue;
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int c[3] = {ci[0] + dx, ci[1] + dy, ci[2] + dz};
                        if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[0] >= g[0] || c[1] >= g[1] ||
                            c[2] >= g[2])
                            continue;
                        long cc = ((long)c[2] * g[1] + c[1]) * g[0] + c[0];
                        for (int t = start[cc]; t < start[cc + 1]; ++t) {
                            int j = order[t];
                            float r2 = 0.0f;
                            for (int k = 0; k < 3; ++k) {
                                float x = p[k][j];
                                if (f & (1u << k))
                                    x = 2.0f * w[k] - x;
                                r2 += (q[k] - x) * (q[k] - x);
                            }
                            if (r2 < h2) {
                                double t3 = h - sqrt(r2);
                                rho += t3 * t3 * t3;
                            }
                        }
                    }
        }
        float e = (float)(rho * kc * in.particle_mass / d.rest_density - 1.0);
        e = e > 0.0f ? e : 0.0f;
        sum += e;
        m = e > m ? e : m;
    }
    free(start);
    free(order);
    free(cell);
    free(fill);
    *avg = n ? sum / n : 0.0;
    *mx = m;
}

/* --scene FILE [--frames N]: a shipped scene as it is (its pressure law)
 * and with volume.pressure "dfsph", one thread each, interleaved frame by
 * frame (a scene switches to DFSPH where it is faster at equal or better
 * accuracy). Per law: the volume's ms a frame (ms_stats.volume_ms: SPH and
 * interaction, no extraction), sub-steps a frame, DFSPH iterations a
 * sub-step (density + divergence), average and maximum compression as
 * above, and the ratio of the scene law's volume time to DFSPH's. Prints
 * only (no CSV): a diagnosis, not one of the committed figures. --set
 * KEY=VALUE (as `modesplit run --set`) applies to both, e.g. the ideal gas
 * at DFSPH's accuracy: --set volume.gas_constant=3600. */
static int scene_mode(const char *path, int frames, int nset, const char **set)
{
    /* set[0 .. nset) from --set, then room for the DFSPH key */
    set[nset] = "volume.pressure=\"dfsph\"";
    ms_scene *sc[2];
    ms_sim *sim[2];
    for (int l = 0; l < 2; ++l)
        if (ms_scene_load_with_overrides(path, nset + l, set, &sc[l]) != MS_OK ||
            ms_sim_create_from_scene(sc[l], 1, &sim[l]) != MS_OK) {
            fprintf(stderr, "bench_dfsph: %s: %s\n", path, ms_last_error());
            return 1;
        }
    if (!ms_sim_volume(sim[0])) {
        fprintf(stderr, "bench_dfsph: %s has no volume\n", path);
        return 1;
    }
    const float fdt = ms_scene_frame_dt(sc[0]);
    double comp_sum[2] = {0, 0};
    float comp_max[2] = {0, 0};
    for (int f = 0; f < frames; ++f)
        for (int l = 0; l < 2; ++l) {
            if (ms_sim_step(sim[l], fdt) != MS_OK) {
                fprintf(stderr, "bench_dfsph: %s: %s\n", path, ms_last_error());
                return 1;
            }
            double avg;
            float mx;
            compression(ms_sim_volume(sim[l]), &avg, &mx);
            comp_sum[l] += avg;
            comp_max[l] = mx > comp_max[l] ? mx : comp_max[l];
        }
    ms_volume_desc d0 = ms_volume_get_desc(ms_sim_volume(sim[0]));
    printf("scene %s, %d frames of %g s, one thread, interleaved frame by frame\n", path, frames,
           (double)fdt);
    printf("%10s %12s %12s %12s %10s %10s %9s\n", "law", "volume_ms/f", "substeps/f", "iters/sub",
           "avg_comp%", "max_comp%", "x_dfsph");
    double ms[2];
    for (int l = 0; l < 2; ++l) {
        ms_stats st = ms_stats_init();
        ms_sim_get_stats(sim[l], &st);
        ms[l] = st.volume_ms / frames;
    }
    for (int l = 0; l < 2; ++l) {
        ms_volume_info in = ms_volume_info_init();
        ms_volume_get_info(ms_sim_volume(sim[l]), &in);
        const char *name = l == 1 ? "dfsph" : law_name[d0.pressure == MS_PRESSURE_TAIT ? 1 : 0];
        printf("%10s %12.1f %12.2f %12.2f %10.3f %10.3f %9.2f\n", name, ms[l],
               (double)in.substeps / frames,
               in.substeps
                   ? (double)(in.density_iterations_total + in.divergence_iterations_total) /
                         in.substeps
                   : 0.0,
               100.0 * comp_sum[l] / frames, 100.0 * comp_max[l], ms[l] / ms[1]);
    }
    for (int l = 0; l < 2; ++l) {
        ms_sim_destroy(sim[l]);
        ms_scene_destroy(sc[l]);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_dfsph [--csv-dir DIR] [--quick | --peer]\n"
                   "       bench_dfsph --scene FILE [--frames N] [--set KEY=VALUE ...]\n"
                   "the same dam break with the ideal gas, Tait and DFSPH laws, interleaved, at\n"
                   "~2k, 32k and 128k particles, and the peer's scene (SPlisHSPlasH's\n"
                   "DamBreakModel: 32768 particles, its first 0.3 s); --quick: 2k and 32k, 3\n"
                   "frames; --peer: the peer's scene alone. Prints ms per simulated second,\n"
                   "sub-steps and iterations per simulated second, average and max compression,\n"
                   "ratios; writes DIR/dfsph.csv (default DIR: bench). --scene: a scene's\n"
                   "own law against DFSPH, interleaved, N frames (default 60), one thread:\n"
                   "volume ms, sub-steps a frame, iterations a sub-step, compression\n"
                   "(printed only); --set KEY=VALUE overrides a scene key for both.\n"))
        return 0;
    for (int i = 1; i + 1 < argc; ++i)
        if (strcmp(argv[i], "--scene") == 0) {
            int frames = 60;
            for (int k = 1; k + 1 < argc; ++k)
                if (strcmp(argv[k], "--frames") == 0)
                    frames = atoi(argv[k + 1]);
            if (frames < 1) {
                fprintf(stderr, "bench_dfsph: --frames must be at least 1\n");
                return 1;
            }
            enum { MAXSET = 16 };
            const char *set[MAXSET + 1];
            int nset = 0;
            for (int k = 1; k + 1 < argc; ++k)
                if (strcmp(argv[k], "--set") == 0) {
                    if (nset == MAXSET) {
                        fprintf(stderr, "bench_dfsph: at most %d --set options\n", MAXSET);
                        return 1;
                    }
                    set[nset++] = argv[++k];
                }
            return scene_mode(argv[i + 1], frames, nset, set);
        }
    const int quick = bench_quick(argc, argv);
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    printf("dfsph: dam break, one thread, the three laws interleaved frame by frame\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("%9s %10s %10s %10s %11s %10s %10s %9s\n", "particles", "law", "ms/sim_s", "steps/s",
           "iters/s", "avg_comp%", "max_comp%", "x_dfsph");
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "dfsph.csv",
                               "commit,machine,threads,particles,law,simulated_s,"
                               "ms_per_simulated_s,substeps_per_simulated_s,"
                               "iterations_per_simulated_s,avg_compression,max_compression,"
                               "ms_ratio_to_dfsph");
    if (!csv)
        return 1;
    /* 0: the peer's scene, 0.3 s from its release (as the peer was
     * timed), no warm-up */
    const int sizes[4] = {2000, 32000, 128000, 0};
    int peer_only = 0;
    for (int i = 1; i < argc; ++i)
        peer_only |= strcmp(argv[i], "--peer") == 0;
    const int nsizes = quick ? 2 : 4;
    const float frame = 1.0f / 60;
    for (int k = peer_only ? 3 : 0; k < nsizes; ++k) {
        run r[LAWS];
        memset(r, 0, sizeof r);
        const int warm = sizes[k] == 0 ? 0 : 6;
        const int frames = quick ? 3 : (sizes[k] >= 128000 ? 6 : 18);
        for (int l = 0; l < LAWS; ++l)
            r[l].v = dam_break(sizes[k], law_of[l]);
        for (int f = 0; f < warm + frames; ++f)
            for (int l = 0; l < LAWS; ++l) {
                if (f == warm) {
                    ms_volume_info in = ms_volume_info_init();
                    ms_volume_get_info(r[l].v, &in);
                    r[l].sub0 = in.substeps;
                    r[l].it0 = in.density_iterations_total + in.divergence_iterations_total;
                }
                double t0 = bench_now();
                if (ms_volume_step(r[l].v, frame) != MS_OK) {
                    fprintf(stderr, "bench_dfsph: %s: %s\n", law_name[l], ms_last_error());
                    return 1;
                }
                double t = bench_now() - t0;
                if (f < warm)
                    continue;
                r[l].wall += t;
                r[l].sim += frame;
                double avg;
                float mx;
                compression(r[l].v, &avg, &mx);
                r[l].comp_sum += avg;
                r[l].comp_max = mx > r[l].comp_max ? mx : r[l].comp_max;
                r[l].frames++;
            }
        const double ref = r[LAWS - 1].wall / r[LAWS - 1].sim;
        for (int l = 0; l < LAWS; ++l) {
            ms_volume_info in = ms_volume_info_init();
            ms_volume_get_info(r[l].v, &in);
            double ms = r[l].wall / r[l].sim * 1e3;
            double steps = (in.substeps - r[l].sub0) / r[l].sim;
            double its = (in.density_iterations_total + in.divergence_iterations_total - r[l].it0) /
                         r[l].sim;
            double avg = r[l].comp_sum / r[l].frames;
            printf("%9d %10s %10.0f %10.0f %11.0f %10.3f %10.3f %9.2f\n", in.count, law_name[l], ms,
                   steps, its, 100.0 * avg, 100.0 * r[l].comp_max, ms / (ref * 1e3));
            fprintf(csv, "%s,%s,1,%d,%s,%.4f,%.1f,%.1f,%.1f,%.6f,%.6f,%.3f\n", commit, machine,
                    in.count, law_name[l], r[l].sim, ms, steps, its, avg, r[l].comp_max,
                    ms / (ref * 1e3));
            ms_volume_destroy(r[l].v);
        }
    }
    fclose(csv);
    printf("wrote %s/dfsph.csv\n", bench_csv_dir(argc, argv));
    return 0;
}
