/* Renderer benchmark: milliseconds per frame of ms_renderer_draw_field for
 * 256^2, 512^2 and 950^2 images (950 x 950 is the paper's Table 1) of a
 * 200^2 and a 400^2 field (the paper's wave grids), water shader with the
 * scenes' 512^2 caustics map, the full mesh (mesh_step 1), the automatic
 * one and a vertex every 2 cells. The field moves every frame (travelling waves), so every
 * frame uploads a new mesh and traces new caustics. Reports the median,
 * the 10th and 90th percentiles, and the stages' medians. llvmpipe renders
 * on the CPU with LP_NUM_THREADS threads (default: one per core); the
 * machine's load average is printed with each row, since other work on the
 * cores slows it. Writes render.csv. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_common.h"
#include "modesplit/modesplit.h"

static void waves(float *h, int n, double t)
{
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double x = (i + 0.5) / n, y = (j + 0.5) / n;
            double r = sqrt((x - 0.3) * (x - 0.3) + (y - 0.6) * (y - 0.6));
            h[(size_t)j * n + i] =
                (float)(0.25 + 0.004 * sin(40 * x + 3 * t) * cos(31 * y - 2 * t) +
                        0.003 * cos(90 * r - 8 * t) * exp(-5 * r));
        }
}

static double loadavg(void)
{
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1;
        fclose(f);
    }
    return l;
}

/* The paper's scenes as shipped (data/scenes/<name>.json, their render
 * sections at 950 x 950): per frame the simulation step (ms_sim_step), the
 * draw (ms_renderer_draw) and its stages, and the PNG encoding, medians
 * over the frames after a warm-up; the whole frame rate is 1000 / (sim +
 * draw): `modesplit run --png` and `render --png` encode in a writer
 * thread (tools/modesplit/png_queue.c) while the next frame is simulated
 * and drawn, so the PNG column is that thread's load, not the frame's. The
 * GL column is llvmpipe's vertex and fragment work; the mesh column the
 * CPU side of the screen-space-error LOD (mesh_nx^2 vertices). Each frame is
 * drawn a second time by a renderer with the full mesh (mesh_step 1),
 * interleaved, so the automatic mesh's gain is a ratio within one run
 * (the machine's load moves both alike). Writes render_scenes.csv. Returns 0, or 1 on an error. */
static int bench_scenes(int reps, const char *csv_dir, const char *commit, const char *machine,
                        const char *lp)
{
    static const char *const names[4] = {"fig1", "fig9a", "fig9b", "fig10"};
    FILE *csv = bench_csv_open(csv_dir, "render_scenes.csv",
                               "commit,machine,lp_num_threads,scene,width,height,frames,"
                               "sim_ms,draw_ms_median,draw_ms_p10,draw_ms_p90,mesh_ms,"
                               "caustics_ms,gl_ms,readback_ms,png_ms,frame_fps,loadavg,"
                               "mesh_nx,full_mesh_draw_ms,full_over_auto");
    if (!csv)
        return 1;
    printf("\nscenes at their render size (950^2): ms per frame (median; draw p10-p90;\n"
           "png: the writer thread's encoding, off the frame's path)\n");
    printf("(full: the same frame drawn with the full mesh, mesh_step 1, interleaved)\n");
    printf("%-6s %7s %8s %13s %7s %9s %7s %9s %7s %9s %9s %8s %6s\n", "scene", "sim", "draw",
           "(p10-p90)", "mesh", "caustics", "GL", "readback", "png", "sim+draw", "mesh", "full",
           "ratio");
    const int warm = 5;
    for (int k = 0; k < 4; ++k) {
        char path[64], png[96];
        snprintf(path, sizeof path, "data/scenes/%s.json", names[k]);
        snprintf(png, sizeof png, "/tmp/bench_render_%d.png", (int)getpid());
        ms_scene *sc = NULL;
        ms_sim *sim = NULL;
        ms_renderer *r = NULL, *full = NULL;
        ms_renderer_desc fd = ms_renderer_desc_default();
        if (ms_scene_load(path, &sc) != MS_OK || ms_sim_create_from_scene(sc, 0, &sim) != MS_OK ||
            ms_renderer_create_from_scene(sc, &r) != MS_OK ||
            ms_renderer_desc_from_scene(sc, &fd) != MS_OK ||
            ((fd.mesh_step = 1), ms_renderer_create_desc(&fd, &full)) != MS_OK) {
            fprintf(stderr, "bench_render: %s: %s (run from the source tree)\n", path,
                    ms_last_error());
            return 1;
        }
        const float dt = ms_scene_frame_dt(sc);
        double simv[64], drawv[64], mesh[64], caus[64], gl[64], rb[64], pngv[64], fullv[64];
        int mesh_nx = 0;
        ms_render_stats st = ms_render_stats_init();
        for (int f = 0; f < warm + reps; ++f) {
            double t0 = bench_now();
            if (ms_sim_step(sim, dt) != MS_OK) {
                fprintf(stderr, "bench_render: %s: %s\n", path, ms_last_error());
                return 1;
            }
            double t1 = bench_now();
            if (ms_renderer_draw(r, sim) != MS_OK) {
                fprintf(stderr, "bench_render: %s: %s\n", path, ms_last_error());
                return 1;
            }
            double t2 = bench_now();
            if (ms_renderer_write_png(r, png) != MS_OK) {
                fprintf(stderr, "bench_render: %s\n", ms_last_error());
                return 1;
            }
            double t3 = bench_now();
            ms_renderer_get_stats(r, &st);
            mesh_nx = st.mesh_nx;
            if (ms_renderer_draw(full, sim) != MS_OK) {
                fprintf(stderr, "bench_render: %s: %s\n", path, ms_last_error());
                return 1;
            }
            double t4 = bench_now();
            if (f >= warm) {
                int i = f - warm;
                simv[i] = 1e3 * (t1 - t0);
                drawv[i] = 1e3 * (t2 - t1);
                pngv[i] = 1e3 * (t3 - t2);
                mesh[i] = st.mesh_ms;
                caus[i] = st.caustics_ms;
                gl[i] = st.draw_ms;
                rb[i] = st.readback_ms;
                fullv[i] = 1e3 * (t4 - t3);
            }
        }
        remove(png);
        bench_stats d = bench_summarise(drawv, reps);
        double sm = bench_summarise(simv, reps).median, m = bench_summarise(mesh, reps).median;
        double c = bench_summarise(caus, reps).median, g = bench_summarise(gl, reps).median;
        double b = bench_summarise(rb, reps).median, pn = bench_summarise(pngv, reps).median;
        double fps = 1e3 / (sm + d.median), load = loadavg();
        double fm = bench_summarise(fullv, reps).median;
        printf("%-6s %7.1f %8.1f (%5.1f-%5.1f) %7.2f %9.2f %7.1f %9.2f %7.1f %5.1f fps %5d^2 %8.1f "
               "%6.2f\n",
               names[k], sm, d.median, d.p10, d.p90, m, c, g, b, pn, fps, mesh_nx, fm,
               fm / d.median);
        fprintf(csv,
                "%s,%s,%s,%s,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f,%.2f,%d,"
                "%.3f,%.3f\n",
                commit, machine, lp ? lp : "default", names[k], 950, 950, reps, sm, d.median, d.p10,
                d.p90, m, c, g, b, pn, fps, load, mesh_nx, fm, fm / d.median);
        fflush(stdout);
        ms_renderer_destroy(r);
        ms_renderer_destroy(full);
        ms_sim_destroy(sim);
        ms_scene_destroy(sc);
    }
    fclose(csv);
    return 0;
}

/* ---- LP_NUM_THREADS ----------------------------------------------------
 *
 * llvmpipe reads LP_NUM_THREADS once, when it makes its first context, so
 * each setting runs in a child process of its own (this program again,
 * --lp-child, through popen): fig1 at 950^2, the simulation stepped and
 * the frame drawn, each draw's ms (and the GL part) printed a line each.
 * The settings take turns, LP_ROUNDS rounds of LP_FRAMES frames each, so
 * the machine's load moves them alike; medians and 10th-90th percentiles
 * over all rounds go to render_lp_threads.csv. */
#define LP_ROUNDS 4
#define LP_FRAMES 12
#define LP_MAX (LP_ROUNDS * LP_FRAMES)

static int lp_child(int frames)
{
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    ms_renderer *r = NULL;
    if (ms_scene_load("data/scenes/fig1.json", &sc) != MS_OK ||
        ms_sim_create_from_scene(sc, 0, &sim) != MS_OK ||
        ms_renderer_create_from_scene(sc, &r) != MS_OK) {
        fprintf(stderr, "bench_render: fig1: %s (run from the source tree)\n", ms_last_error());
        return 1;
    }
    const float dt = ms_scene_frame_dt(sc);
    ms_render_stats st = ms_render_stats_init();
    for (int f = 0; f < 3 + frames; ++f) { /* 3 warm-up frames */
        if (ms_sim_step(sim, dt) != MS_OK)
            return 1;
        double t0 = bench_now();
        if (ms_renderer_draw(r, sim) != MS_OK) {
            fprintf(stderr, "bench_render: fig1: %s\n", ms_last_error());
            return 1;
        }
        double t1 = bench_now();
        ms_renderer_get_stats(r, &st);
        if (f >= 3)
            printf("%.3f %.3f\n", 1e3 * (t1 - t0), st.draw_ms);
    }
    ms_renderer_destroy(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    return 0;
}

static int bench_lp_threads(const char *csv_dir, const char *commit, const char *machine)
{
    static const int threads[3] = {1, 2, 4};
    double draw[3][LP_MAX], gl[3][LP_MAX];
    int got[3] = {0, 0, 0};
    char exe[4096];
    const ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (len <= 0)
        return 1;
    exe[len] = 0;
    printf("\nLP_NUM_THREADS: fig1 at 950^2, ms per draw (median; p10-p90), a process per "
           "setting, %d rounds of %d frames taking turns\n",
           LP_ROUNDS, LP_FRAMES);
    for (int round = 0; round < LP_ROUNDS; ++round)
        for (int k = 0; k < 3; ++k) {
            char cmd[4200];
            snprintf(cmd, sizeof cmd, "LP_NUM_THREADS=%d '%s' --lp-child %d", threads[k], exe,
                     LP_FRAMES);
            FILE *p = popen(cmd, "r");
            if (!p)
                return 1;
            double a, b;
            while (got[k] < LP_MAX && fscanf(p, "%lf %lf", &a, &b) == 2)
                draw[k][got[k]] = a, gl[k][got[k]++] = b;
            if (pclose(p) != 0) {
                fprintf(stderr, "bench_render: LP_NUM_THREADS=%d: the child failed\n", threads[k]);
                return 1;
            }
        }
    FILE *csv = bench_csv_open(csv_dir, "render_lp_threads.csv",
                               "commit,machine,lp_num_threads,scene,width,height,frames,"
                               "draw_ms_median,draw_ms_p10,draw_ms_p90,gl_ms_median,"
                               "over_default,loadavg");
    if (!csv)
        return 1;
    const long cores = sysconf(_SC_NPROCESSORS_ONLN);
    bench_stats s[3];
    double g[3];
    int def = 1; /* llvmpipe's default: one thread per core */
    for (int k = 0; k < 3; ++k) {
        s[k] = bench_summarise(draw[k], got[k]);
        g[k] = bench_summarise(gl[k], got[k]).median;
        if (threads[k] == cores)
            def = k;
    }
    for (int k = 0; k < 3; ++k) {
        printf("LP_NUM_THREADS=%d%s: %8.1f (%5.1f-%5.1f) ms, GL %8.1f ms, %.2f x the default\n",
               threads[k], k == def ? " (default here)" : "", s[k].median, s[k].p10, s[k].p90, g[k],
               s[k].median / s[def].median);
        fprintf(csv, "%s,%s,%d,fig1,950,950,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f\n", commit, machine,
                threads[k], got[k], s[k].median, s[k].p10, s[k].p90, g[k],
                s[k].median / s[def].median, loadavg());
    }
    fclose(csv);
    return 0;
}

int main(int argc, char **argv)
{
    for (int i = 1; i + 1 < argc; ++i)
        if (!strcmp(argv[i], "--lp-child"))
            return lp_child(atoi(argv[i + 1]) < 1 ? 1 : atoi(argv[i + 1]));
    if (bench_help(
            argc, argv,
            "usage: bench_render [--csv-dir DIR] [--quick]\n"
            "ms per frame of ms_renderer_draw_field (OSMesa) for 256^2, 512^2 and 950^2\n"
            "images of 200^2 and 400^2 fields, water shader with caustics (median,\n"
            "10th-90th percentile, stages); writes DIR/render.csv (default DIR: bench).\n"
            "Then the shipped scenes fig1, fig9a, fig9b, fig10 at 950^2 (sim step, draw and its\n"
            "split, PNG encoding): DIR/render_scenes.csv. --scenes: only those.\n"
            "Then fig1 at 950^2 with LP_NUM_THREADS 1, 2 and 4 (a process each, taking turns):\n"
            "DIR/render_lp_threads.csv. --lp-threads: only that.\n"))
        return 0;
    const int quick = bench_quick(argc, argv);
    const int reps = quick ? 3 : 8, warm = 2;
    char machine[320], commit[64];
    bench_machine(machine, sizeof machine);
    bench_commit(commit, sizeof commit);
    const char *lp = getenv("LP_NUM_THREADS");
    printf("render: water shader, caustics 512^2, ms per frame of ms_renderer_draw_field\n");
    printf("machine: %s; commit %s; LP_NUM_THREADS %s; load average %.2f\n", machine, commit,
           lp ? lp : "default (one per core)", loadavg());
    {
        ms_renderer_desc d = ms_renderer_desc_default();
        d.width = d.height = 16;
        ms_renderer *r;
        if (ms_renderer_create_desc(&d, &r) != MS_OK) {
            printf("render: skipped: %s\n", ms_last_error());
            return 0;
        }
        ms_renderer_destroy(r);
    }
    int scenes_only = 0;
    for (int i = 1; i < argc; ++i)
        scenes_only |= !strcmp(argv[i], "--scenes");
    int lp_only = 0;
    for (int i = 1; i < argc; ++i)
        lp_only |= !strcmp(argv[i], "--lp-threads");
    if (lp_only)
        return bench_lp_threads(bench_csv_dir(argc, argv), commit, machine);
    if (scenes_only)
        return bench_scenes(quick ? 8 : 30, bench_csv_dir(argc, argv), commit, machine, lp);
    FILE *csv = bench_csv_open(bench_csv_dir(argc, argv), "render.csv",
                               "commit,machine,lp_num_threads,width,height,field,mesh_step,"
                               "mesh_vertices,frames,ms_median,ms_p10,ms_p90,mesh_ms,"
                               "caustics_ms,draw_ms,readback_ms,loadavg");
    if (!csv)
        return 1;
    printf("%6s %6s %5s %9s %9s %9s %9s %8s %9s %8s %9s %5s\n", "image", "field", "step",
           "vertices", "ms/frame", "p10", "p90", "mesh", "caustics", "draw", "readback", "load");
    static const int sizes[3] = {256, 512, 950}, fields[2] = {200, 400}, steps[3] = {1, 0, 2};
    for (int fi = 0; fi < 2; ++fi) {
        const int n = fields[fi];
        float *h = malloc(sizeof *h * (size_t)n * n);
        if (!h)
            return 1;
        ms_grid g = {n, n, 1.0f / n, 1.0f / n, {0, 0}};
        for (int si = 0; si < 3; ++si)
            for (int k = 0; k < 3; ++k) {
                ms_renderer_desc d = ms_renderer_desc_default();
                d.width = d.height = sizes[si];
                d.mesh_step = steps[k];
                ms_renderer *r;
                if (ms_renderer_create_desc(&d, &r) != MS_OK) {
                    fprintf(stderr, "bench_render: %s\n", ms_last_error());
                    return 1;
                }
                double t[64], mesh[64], caus[64], draw[64], rb[64];
                ms_render_stats st = ms_render_stats_init();
                for (int f = 0; f < warm + reps; ++f) {
                    waves(h, n, f / 30.0);
                    double t0 = bench_now();
                    if (ms_renderer_draw_field(r, h, &g, f / 30.0) != MS_OK) {
                        fprintf(stderr, "bench_render: %s\n", ms_last_error());
                        return 1;
                    }
                    double dt = bench_now() - t0;
                    ms_renderer_get_stats(r, &st);
                    if (f >= warm) {
                        int i = f - warm;
                        t[i] = 1e3 * dt;
                        mesh[i] = st.mesh_ms;
                        caus[i] = st.caustics_ms;
                        draw[i] = st.draw_ms;
                        rb[i] = st.readback_ms;
                    }
                }
                bench_stats s = bench_summarise(t, reps);
                double m = bench_summarise(mesh, reps).median;
                double c = bench_summarise(caus, reps).median;
                double dr = bench_summarise(draw, reps).median;
                double b = bench_summarise(rb, reps).median;
                double load = loadavg();
                int step = st.mesh_nx > 0 ? n / st.mesh_nx : 0;
                char stepname[16];
                snprintf(stepname, sizeof stepname, steps[k] ? "%d" : "auto", steps[k]);
                printf("%4d^2 %4d^2 %5s %9d %9.1f %9.1f %9.1f %8.2f %9.2f %8.1f %9.2f %5.2f\n",
                       sizes[si], n, stepname, st.mesh_nx * st.mesh_ny, s.median, s.p10, s.p90, m,
                       c, dr, b, load);
                fprintf(csv, "%s,%s,%s,%d,%d,%d,%d,%d,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.2f\n",
                        commit, machine, lp ? lp : "default", sizes[si], sizes[si], n, step,
                        st.mesh_nx * st.mesh_ny, reps, s.median, s.p10, s.p90, m, c, dr, b, load);
                fflush(stdout);
                ms_renderer_destroy(r);
            }
        free(h);
    }
    fclose(csv);
    if (bench_scenes(quick ? 8 : 30, bench_csv_dir(argc, argv), commit, machine, lp))
        return 1;
    return lp ? 0 : bench_lp_threads(bench_csv_dir(argc, argv), commit, machine);
}
