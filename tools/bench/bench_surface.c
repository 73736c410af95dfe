/* Surface-solver benchmark: ns per cell-update of the leapfrog step
 * (speed and damping maps on) for grids 256^2 .. 2048^2 on one core, next
 * to the memory bandwidth measured in the same run and the bound it puts
 * on a step that streams its fields from memory. Writes surface.csv.
 *
 * Then the surface side of a sim's frame on fig1 and fig1_x10: the
 * coupling's impulse, N_time wave steps ("waves") and eq. 20 with the
 * average the volume reads ("combine"), ms a frame, the separate-call
 * sequence (path "round8" in the CSV: up-sample into a scratch field +
 * ms_surface_excite, N_time ms_surface_step calls, the view copy,
 * up-sample + sum, the per-run average) against today's (one pass each,
 * fused sweeps), on the same sim, interleaved repeat by repeat, 1 thread
 * (both with today's wave kernel: the uniform rows speed either).
 * Writes surface_frame.csv.
 *
 * Then each surface model (desc.model) on the same pools: ns of CPU time
 * per cell per sub-step, and the sub-steps a simulated second takes (the
 * dispersive model's bound is omega dt <= 2, eq. 2's the Courant number),
 * at fig10's 200^2 grid and at 512^2, with one depth (one band) and with
 * the sloping beach (several bands), the models interleaved repeat by
 * repeat. Writes surface_models.csv. */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"
#include "sim/sim_internal.h"
#include "surface/surface_internal.h"

/* Bytes one cell-update moves when nothing stays in cache: reads h, v,
 * a, delta; writes v, h (4-byte floats). */
#define BYTES_PER_CELL 24.0

static ms_surface *make_pool_model(int n, ms_surface_model model, int beach)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.model = model;
    d.nx = d.ny = n;
    d.dx = 2.0f / n; /* a 2 m pool */
    d.wave_speed = 0.7f;
    d.damping = 0.95f;
    ms_surface *s;
    if (ms_surface_create(&d, &s) != MS_OK) {
        fprintf(stderr, "bench_surface: %s\n", ms_last_error());
        exit(1);
    }
    float *depth = malloc((size_t)n * n * sizeof *depth), *c = malloc((size_t)n * n * sizeof *c);
    float *damp = malloc((size_t)n * n * sizeof *damp);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            /* a sloping beach and reeds along one side */
            depth[(size_t)y * n + x] = 0.01f + 0.05f * (float)x / n;
            damp[(size_t)y * n + x] = y < n / 8 ? 0.5f : 1.0f;
        }
    ms_surface_speed_from_depth(depth, (size_t)n * n, 9.81f, c);
    if (beach)
        ms_surface_set_speed_map(s, c);
    ms_surface_set_damping_map(s, damp);
    for (int k = 0; k < 20; ++k)
        ms_surface_add_drop(s, 0.1f + 0.09f * k, 0.2f + 0.08f * k, 0.05f, 0.01f);
    free(depth);
    free(c);
    free(damp);
    return s;
}

static ms_surface *make_pool(int n)
{
    return make_pool_model(n, MS_SURFACE_MODEL_WAVE, 1);
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ns of CPU time per cell per sub-step of each model, interleaved */
static int models_bench(int argc, char **argv, const char *machine, const char *commit, int quick)
{
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "surface_models.csv",
                               "commit,machine,threads,grid,depth,model,bands,substeps_per_s,"
                               "ns_per_cell_median,ns_per_cell_p10,ns_per_cell_p90,repeats");
    if (!csv)
        return 1;
    static const char *const names[2] = {"wave", "dispersive"};
    printf("\nsurface models: CPU ns per cell per sub-step, median [p10, p90], 1 thread\n");
    printf("%8s %6s %11s %6s %12s %12s %12s %12s\n", "grid", "depth", "model", "bands",
           "substeps/s", "ns/cell", "p10", "p90");
    const int sizes[2] = {200, 512};
    for (int k = 0; k < 2; ++k)
        for (int beach = 0; beach < 2; ++beach) {
            const int n = sizes[k];
            const double cells = (double)n * n;
            ms_surface *s[2];
            float sub[2];
            const int reps = quick ? 3 : 9;
            double t[2][32];
            for (int m = 0; m < 2; ++m) {
                s[m] = make_pool_model(n, (ms_surface_model)m, beach);
                ms_surface_info info = ms_surface_info_init();
                ms_surface_get_info(s[m], &info);
                sub[m] = info.max_dt * 0.999f;
                ms_surface_step(s[m], sub[m]); /* warm-up: caches, coefficients */
            }
            const int steps = (int)fmax(1.0, round(4e6 / cells));
            for (int r = 0; r < reps; ++r)
                for (int m = 0; m < 2; ++m) {
                    double t0 = cpu_now();
                    for (int i = 0; i < steps; ++i)
                        if (ms_surface_step(s[m], sub[m]) != MS_OK) {
                            fprintf(stderr, "bench_surface: %s\n", ms_last_error());
                            return 1;
                        }
                    t[m][r] = (cpu_now() - t0) * 1e9 / (steps * cells);
                }
            for (int m = 0; m < 2; ++m) {
                bench_stats st = bench_summarise(t[m], reps);
                const int bands = m ? ms_surface_dispersive_band_count(s[m]) : 0;
                const char *depth = beach ? "beach" : "0.05m"; /* 0.7 m/s */
                printf("%5d^2 %6s %11s %6d %12.0f %12.2f %12.2f %12.2f\n", n, depth, names[m],
                       bands, 1.0 / sub[m], st.median, st.p10, st.p90);
                fprintf(csv, "%s,%s,1,%d,%s,%s,%d,%.1f,%.3f,%.3f,%.3f,%d\n", commit, machine, n,
                        depth, names[m], bands, 1.0 / sub[m], st.median, st.p10, st.p90, reps);
                ms_surface_destroy(s[m]);
            }
        }
    fclose(csv);
    return 0;
}

/* The separate-call sequence's average: a run of wave columns summed in a
 * register, one run after the other. */
static void average_round8(ms_sim *sim, const float *w, float *out)
{
    const int snx = sim->snx, fnx = sim->fnx;
    size_t nf = (size_t)fnx * sim->fny;
    float *restrict acc = sim->wave_rowsum;
    memset(acc, 0, nf * sizeof *acc);
    memset(out, 0, nf * sizeof *out);
    int count_x[4096] = {0}, count_y = 0, row = 0;
    for (int i = 0; i < snx; ++i)
        ++count_x[sim->wave_colmap[i]];
    for (int j = 0; j < sim->sny; ++j) {
        int r = (int)(((2L * j + 1) * sim->fny) / (2L * sim->sny));
        if (r != row) {
            for (int c = 0; c < fnx; ++c)
                out[(size_t)row * fnx + c] =
                    count_y ? acc[(size_t)row * fnx + c] / (float)(count_y * count_x[c]) : 0.0f;
            row = r;
            count_y = 0;
        }
        ++count_y;
        const float *restrict src = w + (size_t)j * snx;
        float *restrict dst = acc + (size_t)r * fnx;
        const int *restrict map = sim->wave_colmap;
        for (int i = 0; i < snx;) {
            const int c = map[i];
            float t = dst[c];
            for (; i < snx && map[i] == c; ++i)
                t += src[i];
            dst[c] = t;
        }
    }
    for (int c = 0; c < fnx; ++c)
        out[(size_t)row * fnx + c] =
            count_y ? acc[(size_t)row * fnx + c] / (float)(count_y * count_x[c]) : 0.0f;
}

/* One frame's surface side by either sequence: ms of waves and combine. */
static int frame_side(ms_sim *sim, int now, float dt_step, int n_time, const float *e,
                      double *waves_ms, double *combine_ms)
{
    ms_surface *sf = sim->surface;
    const float *h = sim->hfield[0];
    float *avg = sim->wave_snap[0];
    ms_status st = MS_OK;
    double t0 = bench_now();
    if (now) {
        st = ms_sim_upsample_excite(sim, e, sf);
        if (st == MS_OK)
            st = ms_surface_step_calls(sf, dt_step, n_time);
    } else {
        ms_sim_upsample(sim, e, sim->rowtmp, sim->excite);
        st = ms_surface_excite(sf, sim->excite, 1.0f);
        for (int k = 0; st == MS_OK && k < n_time; ++k)
            st = ms_surface_step(sf, dt_step);
    }
    double t1 = bench_now();
    if (st != MS_OK)
        return 0;
    if (now)
        ms_sim_combine(sim, h, sf->h + ms_surface_at(sf, 0, 0), (size_t)sf->stride, sim->combined,
                       avg);
    else {
        const float *w = ms_surface_height(sf, NULL, NULL);
        ms_sim_upsample_add(sim, h, w, 0.0f, sim->rowtmp, sim->combined);
        if (avg)
            average_round8(sim, w, avg);
    }
    double t2 = bench_now();
    *waves_ms = (t1 - t0) * 1e3;
    *combine_ms = (t2 - t1) * 1e3;
    return 1;
}

static int frame_bench(int argc, char **argv, const char *machine, const char *commit, int quick)
{
    const char *dir = bench_arg_value(argc, argv, "--data", "data/scenes");
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "surface_frame.csv",
                               "commit,machine,threads,scene,wave_grid,field,n_time,path,"
                               "waves_ms_median,waves_ms_p10,waves_ms_p90,combine_ms_median,"
                               "combine_ms_p10,combine_ms_p90,repeats");
    if (!csv)
        return 1;
    printf("\nsurface side of a sim frame: ms a frame, median [p10, p90], the separate-call\n"
           "sequence and today's interleaved on the same sim, 1 thread\n");
    printf("%-9s %9s %6s %6s %7s %20s %20s\n", "scene", "grid", "field", "n_time", "path",
           "waves ms", "combine ms");
    static const char *const scenes[] = {"fig1", "fig1_x10"};
    for (int q = 0; q < 2; ++q) {
        char path[512];
        snprintf(path, sizeof path, "%s/%s.json", dir, scenes[q]);
        ms_scene *sc = NULL;
        ms_sim *sim = NULL;
        if (ms_scene_load(path, &sc) != MS_OK || ms_sim_create_from_scene(sc, 1, &sim) != MS_OK) {
            fprintf(stderr, "bench_surface: %s\n", ms_last_error());
            return 1;
        }
        const float frame_dt = ms_scene_frame_dt(sc);
        for (int f = 0; f < 3; ++f) /* the pipeline primed, N_time known */
            if (ms_sim_step(sim, frame_dt) != MS_OK) {
                fprintf(stderr, "bench_surface: %s\n", ms_last_error());
                return 1;
            }
        const int n_time = ms_sim_wave_plan(sim)->n_time;
        const float dt_step = frame_dt / (float)n_time;
        const size_t nf = (size_t)sim->fnx * sim->fny;
        float *e = malloc(nf * sizeof *e);
        if (!e || !sim->excite)
            return 1;
        for (size_t c = 0; c < nf; ++c) /* an impulse of a few micrometres */
            e[c] = 2e-6f * sinf(0.37f * (float)c);
        const int reps = quick ? 5 : 21, frames = quick ? 5 : 20;
        double tw[2][64], tc[2][64];
        double wm, cm;
        for (int r = -1; r < reps; ++r) /* r = -1: warm-up */
            for (int k = 0; k < 2; ++k) {
                const int now = (r + k) % 2 != 0; /* the order alternates */
                double sw = 0, sc2 = 0;
                for (int f = 0; f < frames; ++f) {
                    if (!frame_side(sim, now, dt_step, n_time, e, &wm, &cm)) {
                        fprintf(stderr, "bench_surface: %s\n", ms_last_error());
                        return 1;
                    }
                    sw += wm;
                    sc2 += cm;
                }
                if (r >= 0) {
                    tw[now][r] = sw / frames;
                    tc[now][r] = sc2 / frames;
                }
            }
        for (int now = 0; now < 2; ++now) {
            bench_stats w = bench_summarise(tw[now], reps), c = bench_summarise(tc[now], reps);
            const char *name = now ? "now" : "round8";
            printf("%-9s %4dx%-4d %3dx%-3d %6d %7s %7.3f [%5.3f, %5.3f] %7.3f [%5.3f, %5.3f]\n",
                   scenes[q], sim->snx, sim->sny, sim->fnx, sim->fny, n_time, name, w.median, w.p10,
                   w.p90, c.median, c.p10, c.p90);
            fprintf(csv, "%s,%s,1,%s,%dx%d,%dx%d,%d,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n", commit,
                    machine, scenes[q], sim->snx, sim->sny, sim->fnx, sim->fny, n_time, name,
                    w.median, w.p10, w.p90, c.median, c.p10, c.p90, reps);
        }
        free(e);
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
    fclose(csv);
    return 0;
}

int main(int argc, char **argv)
{
    if (bench_help(
            argc, argv,
            "usage: bench_surface [--csv-dir DIR] [--quick] [--data DIR] [--models]\n"
            "ns per cell-update of the wave equation with speed and damping maps on grids\n"
            "256^2 to 2048^2, one core (median, 10th-90th percentile), beside the memory\n"
            "bandwidth; writes DIR/surface.csv (default DIR: bench). Then the surface side\n"
            "of a sim frame on fig1 and fig1_x10 (--data DIR: the scenes), separate\n"
            "calls against today's sequence, interleaved; writes DIR/surface_frame.csv.\n"
            "Then CPU ns per cell per sub-step of each surface model (wave, dispersive)\n"
            "at 200^2 and 512^2; writes DIR/surface_models.csv (--models: that part alone).\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--models") == 0) /* the models' part alone */
            return models_bench(argc, argv, machine, commit, quick);
    const double gbps = bench_memcpy_gbps((size_t)256 << 20, quick ? 3 : 9);
    printf("surface: leapfrog step with speed + damping maps, 1 thread\n");
    printf("machine: %s; commit %s\n", machine, commit);
    printf("memory: memcpy %.1f GB/s (read + write) -> a step streaming %.0f B/cell from "
           "memory costs >= %.3f ns/cell\n",
           gbps, BYTES_PER_CELL, BYTES_PER_CELL / gbps);
    printf("%8s %10s %12s %12s %12s %12s %9s\n", "grid", "substeps", "ns/cell", "p10", "p90",
           "ms/substep", "GB/s eff");

    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "surface.csv",
                               "commit,machine,threads,grid,cells,substeps_per_rep,repeats,"
                               "ns_per_cell_median,ns_per_cell_p10,ns_per_cell_p90,"
                               "ms_per_substep_median,memcpy_GBps,bound_ns_per_cell");
    if (!csv)
        return 1;
    const int sizes[4] = {256, 512, 1024, 2048};
    for (int k = 0; k < 4; ++k) {
        const int n = sizes[k];
        const double cells = (double)n * n;
        ms_surface *s = make_pool(n);
        ms_surface_info info = ms_surface_info_init();
        ms_surface_get_info(s, &info);
        /* about 2e7 cell-updates a repeat: long enough to time well */
        const int sub = (int)fmax(1.0, round(2e7 / cells));
        const float dt = (float)sub * info.max_dt * 0.999f;
        const int reps = quick ? 3 : 11;
        double t[32];
        ms_surface_step(s, dt); /* warm-up: caches, coefficients */
        for (int r = 0; r < reps; ++r) {
            double t0 = bench_now();
            if (ms_surface_step(s, dt) != MS_OK) {
                fprintf(stderr, "bench_surface: %s\n", ms_last_error());
                return 1;
            }
            t[r] = (bench_now() - t0) * 1e9 / (sub * cells);
        }
        bench_stats st = bench_summarise(t, reps);
        printf("%5d^2 %10d %12.3f %12.3f %12.3f %12.3f %9.1f\n", n, sub, st.median, st.p10, st.p90,
               st.median * cells * 1e-6, BYTES_PER_CELL / st.median);
        fprintf(csv, "%s,%s,1,%d,%.0f,%d,%d,%.4f,%.4f,%.4f,%.4f,%.2f,%.4f\n", commit, machine, n,
                cells, sub, reps, st.median, st.p10, st.p90, st.median * cells * 1e-6, gbps,
                BYTES_PER_CELL / gbps);
        ms_surface_destroy(s);
    }
    fclose(csv);
    if (frame_bench(argc, argv, machine, commit, quick))
        return 1;
    return models_bench(argc, argv, machine, commit, quick);
}
