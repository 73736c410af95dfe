/* Surface-solver benchmark: ns per cell-update of the leapfrog step
 * (speed and damping maps on) for grids 256^2 .. 2048^2 on one core, next
 * to the memory bandwidth measured in the same run and the bound it puts
 * on a step that streams its fields from memory. Writes surface.csv. */
#include <math.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

/* Bytes one cell-update moves when nothing stays in cache: reads h, v,
 * a, delta; writes v, h (4-byte floats). */
#define BYTES_PER_CELL 24.0

static ms_surface *make_pool(int n)
{
    ms_surface_desc d = ms_surface_desc_default();
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
    ms_surface_set_speed_map(s, c);
    ms_surface_set_damping_map(s, damp);
    for (int k = 0; k < 20; ++k)
        ms_surface_add_drop(s, 0.1f + 0.09f * k, 0.2f + 0.08f * k, 0.05f, 0.01f);
    free(depth);
    free(c);
    free(damp);
    return s;
}

int main(int argc, char **argv)
{
    if (bench_help(argc, argv,
                   "usage: bench_surface [--csv-dir DIR] [--quick]\n"
        "ns per cell-update of the wave equation with speed and damping maps on grids\n"
        "256^2 to 2048^2, one core (median, 10th-90th percentile), beside the memory\n"
        "bandwidth; writes DIR/surface.csv (default DIR: bench).\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
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
        printf("%5d^2 %10d %12.3f %12.3f %12.3f %12.3f %9.1f\n", n, sub, st.median, st.p10,
               st.p90, st.median * cells * 1e-6, BYTES_PER_CELL / st.median);
        fprintf(csv, "%s,%s,1,%d,%.0f,%d,%d,%.4f,%.4f,%.4f,%.4f,%.2f,%.4f\n", commit, machine, n,
                cells, sub, reps, st.median, st.p10, st.p90, st.median * cells * 1e-6, gbps,
                BYTES_PER_CELL / gbps);
        ms_surface_destroy(s);
    }
    fclose(csv);
    return 0;
}
