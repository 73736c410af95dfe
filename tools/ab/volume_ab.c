/* volume_ab: a one-process A/B of two builds of the library. Both shared libraries are loaded with dlmopen (each its own
 * namespace, so the same symbols do not clash) and stepped in turn: a
 * sub-step of each build's dam break (bench_volume's scene), or a frame of
 * each build's sim of a scene file, alternating which goes first; thread
 * CPU time, 1 thread. On a machine shared with other work, two separate
 * runs differ by more than the changes measured here; taken in turn in one
 * process they see the same load. Prints the medians and B/A.
 *
 *   build/bin/volume_ab A.so B.so dam N REPS      (N particles, REPS sub-steps)
 *   build/bin/volume_ab A.so B.so scene FILE REPS (REPS frames after 10)
 *   build/bin/volume_ab A.so B.so peer FRAMES REPS (bench_dfsph --peer's
 *       scene under DFSPH: FRAMES frames of 1/60 s from the release, taken
 *       REPS times; prints the medians of the runs' totals)
 *
 * A speed tool, not a benchmark of record (make bench): no CSV. */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "modesplit/modesplit.h"

typedef struct build {
    ms_volume_desc (*desc_default)(void);
    ms_status (*create)(const ms_volume_desc *, ms_volume **);
    ms_status (*fill)(ms_volume *, const float[3], const float[3]);
    ms_status (*step)(ms_volume *, float);
    void (*destroy)(ms_volume *);
    void (*info)(const ms_volume *, ms_volume_info *);
    const char *(*last_error)(void);
    ms_status (*scene_load)(const char *, ms_scene **);
    ms_status (*sim_create)(const ms_scene *, int, ms_sim **);
    ms_status (*sim_step)(ms_sim *, float);
    float (*frame_dt)(const ms_scene *);
} build;

static void bind(void *h, const char *name, void *fn, size_t size)
{
    void *p = dlsym(h, name);
    if (!p) {
        fprintf(stderr, "volume_ab: %s\n", dlerror());
        exit(2);
    }
    memcpy(fn, &p, size); /* POSIX: a function pointer is as wide as void * */
}

#define BIND(h, b, f, name) bind(h, name, &(b).f, sizeof((b).f))

static build load(const char *path)
{
    void *h = dlmopen(LM_ID_NEWLM, path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        fprintf(stderr, "volume_ab: %s\n", dlerror());
        exit(2);
    }
    build b;
    BIND(h, b, desc_default, "ms_volume_desc_default");
    BIND(h, b, create, "ms_volume_create");
    BIND(h, b, fill, "ms_volume_fill_box");
    BIND(h, b, step, "ms_volume_step");
    BIND(h, b, destroy, "ms_volume_destroy");
    BIND(h, b, info, "ms_volume_get_info");
    BIND(h, b, last_error, "ms_last_error");
    BIND(h, b, scene_load, "ms_scene_load");
    BIND(h, b, sim_create, "ms_sim_create_from_scene");
    BIND(h, b, sim_step, "ms_sim_step");
    BIND(h, b, frame_dt, "ms_scene_frame_dt");
    return b;
}

static void check(const build *b, ms_status st)
{
    if (st != MS_OK) {
        fprintf(stderr, "volume_ab: %s\n", b->last_error());
        exit(1);
    }
}

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* bench_volume's dam break: a column a x a x 2a in a 4a x a x 2.2a tank. */
static ms_volume *dam_break(const build *b, int target)
{
    const float a = 0.5f, s = a * cbrtf(2.0f / (float)target);
    ms_volume_desc d = b->desc_default();
    d.domain_max[0] = 4.0f * a;
    d.domain_max[1] = a;
    d.domain_max[2] = 2.2f * a;
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    d.threads = 1;
    d.max_particles = 2 * target;
    ms_volume *v = NULL;
    check(b, b->create(&d, &v));
    check(b, b->fill(v, (float[3]){0, 0, 0}, (float[3]){a, a, 2.0f * a}));
    return v;
}

/* bench_dfsph --peer's scene (SPlisHSPlasH's DamBreakModel, the scene
 * SPlisHSPlasH itself was timed on): a 32^3 block of spacing 0.0303 m in a 4 x 3 x 1.5 m box,
 * DFSPH. */
static ms_volume *peer_scene(const build *b)
{
    const float s = 0.0303f;
    ms_volume_desc d = b->desc_default();
    d.domain_max[0] = 4.0f;
    d.domain_max[1] = 3.0f;
    d.domain_max[2] = 1.5f;
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    d.threads = 1;
    d.max_particles = 65536;
    d.pressure = MS_PRESSURE_DFSPH;
    ms_volume *v = NULL;
    check(b, b->create(&d, &v));
    check(b, b->fill(v, (float[3]){0, 0, 0}, (float[3]){32 * s, 32 * s, 32 * s}));
    return v;
}

/* One sub-step at half the largest stable dt (bench_volume's); CPU s. */
static double one_substep(const build *b, ms_volume *v)
{
    ms_volume_info in = ms_volume_info_init();
    b->info(v, &in);
    const double t0 = cpu_now();
    check(b, b->step(v, 0.5f * in.max_dt));
    return cpu_now() - t0;
}

int main(int argc, char **argv)
{
    if (argc != 6 ||
        (strcmp(argv[3], "dam") && strcmp(argv[3], "scene") && strcmp(argv[3], "peer"))) {
        fprintf(stderr, "usage: volume_ab A.so B.so dam N REPS | volume_ab A.so B.so scene FILE "
                        "REPS | volume_ab A.so B.so peer FRAMES REPS\n");
        return 2;
    }
    const int reps = atoi(argv[5]);
    if (reps < 1 || reps > 100000) {
        fprintf(stderr, "volume_ab: REPS %s is outside [1, 100000]\n", argv[5]);
        return 2;
    }
    build b[2] = {load(argv[1]), load(argv[2])};
    double *t[2] = {malloc(sizeof(double) * (size_t)reps), malloc(sizeof(double) * (size_t)reps)};
    if (!t[0] || !t[1])
        return 1;
    if (!strcmp(argv[3], "peer")) {
        /* whole runs in turn (a frame's cost changes along the run), each
         * from a fresh volume; the sums of the frames' thread CPU */
        const int frames = atoi(argv[4]);
        if (frames < 1 || frames > 6000) {
            fprintf(stderr, "volume_ab: FRAMES %s is outside [1, 6000]\n", argv[4]);
            return 2;
        }
        for (int r = 0; r < reps; ++r)
            for (int o = 0; o < 2; ++o) {
                const int k = (o + r) % 2;
                ms_volume *v = peer_scene(&b[k]);
                double sum = 0.0;
                for (int f = 0; f < frames; ++f) {
                    const double t0 = cpu_now();
                    check(&b[k], b[k].step(v, 1.0f / 60));
                    sum += cpu_now() - t0;
                }
                ms_volume_info in = ms_volume_info_init();
                b[k].info(v, &in);
                printf("run %d %c: %.1f ms, %ld sub-steps, %ld + %ld iterations\n", r, "AB"[k],
                       1e3 * sum, (long)in.substeps, (long)in.density_iterations_total,
                       (long)in.divergence_iterations_total);
                t[k][r] = sum;
                b[k].destroy(v);
            }
    } else if (!strcmp(argv[3], "dam")) {
        const int n = atoi(argv[4]);
        if (n < 100 || n > 4000000) {
            fprintf(stderr, "volume_ab: N %s is outside [100, 4e6]\n", argv[4]);
            return 2;
        }
        ms_volume *v[2] = {dam_break(&b[0], n), dam_break(&b[1], n)};
        for (int k = 0; k < 2; ++k)
            for (int w = 0; w < 20; ++w) /* the column starts to fall */
                one_substep(&b[k], v[k]);
        for (int r = 0; r < reps; ++r)
            for (int o = 0; o < 2; ++o) {
                const int k = (o + r) % 2;
                t[k][r] = one_substep(&b[k], v[k]);
            }
    } else {
        ms_scene *sc[2];
        ms_sim *sim[2];
        for (int k = 0; k < 2; ++k) {
            check(&b[k], b[k].scene_load(argv[4], &sc[k]));
            check(&b[k], b[k].sim_create(sc[k], 1, &sim[k]));
        }
        const float dt = b[0].frame_dt(sc[0]);
        for (int k = 0; k < 2; ++k)
            for (int w = 0; w < 10; ++w)
                check(&b[k], b[k].sim_step(sim[k], dt));
        for (int r = 0; r < reps; ++r)
            for (int o = 0; o < 2; ++o) {
                const int k = (o + r) % 2;
                const double t0 = cpu_now();
                check(&b[k], b[k].sim_step(sim[k], dt));
                t[k][r] = cpu_now() - t0;
            }
    }
    double med[2];
    for (int k = 0; k < 2; ++k) {
        qsort(t[k], (size_t)reps, sizeof(double), by_value);
        med[k] = t[k][reps / 2];
    }
    printf("%s %s: A %.4f ms, B %.4f ms (medians of %d, thread CPU), B/A %.3f\n", argv[3], argv[4],
           1e3 * med[0], 1e3 * med[1], reps, med[1] / med[0]);
    free(t[0]);
    free(t[1]);
    return 0; /* the sims and volumes end with the process */
}
