/* Determinism (as Box2D's test_determinism.c): the same scene gives the
 * same bytes every frame with 1 thread, with the sim's own second thread
 * and with an engine's task callbacks, with every effect on; and the same
 * bytes run after run. Runs under ThreadSanitizer (make check SAN=tsan). */
#include <check.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"

#define POOL_DOMAIN "\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.3]}"
#define POOL_VOLUME                                                                        \
    "\"volume\": {\"spacing\": 0.04, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.4, " \
    "0.12]}], \"field\": [16, 16]}"
#define POOL_SURFACE "\"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.3, \"damping\": 0.9}"

/* Every effect at once, for the determinism test: obstacles (one moving),
 * a container on a path, rain, a boat, drops, floaters, the pointer, both
 * couplings. */
#define EE_HEAD                                                         \
    "{\"seed\": 3, " POOL_DOMAIN ", " POOL_VOLUME ", " POOL_SURFACE "," \
    " \"coupling\": {\"surface_from_volume\": 0.1, \"volume_from_surface\": 0.3},"
#define EE_OBSTACLES                                                                               \
    " \"obstacles\": ["                                                                            \
    "   {\"shape\": \"sphere\", \"params\": {\"radius\": 0.04},"                                   \
    "    \"path\": {\"points\": [[0.1, 0.1, 0.1], [0.3, 0.3, 0.1]], \"speed\": 0.2, \"loop\": "    \
    "true}},"                                                                                      \
    "   {\"shape\": \"box\", \"params\": {\"size\": [0.05, 0.05, 0.3]}, \"position\": [0.3, 0.1, " \
    "0.15]}],"
#define EE_EFFECTS                                                                                \
    " \"effects\": {"                                                                             \
    "   \"rain\": {\"rate\": 60, \"radius\": 0.01, \"amplitude\": -0.002},"                       \
    "   \"boat\": {\"path\": {\"points\": [[0.1, 0.3], [0.3, 0.3]], \"speed\": 0.3, \"loop\": "   \
    "true},"                                                                                      \
    "              \"radius\": 0.02, \"depth\": 0.005},"                                          \
    "   \"drops\": [{\"at\": [0.2, 0.2], \"time\": 0.05}, {\"at\": [0.1, 0.25], \"time\": 0.5}]," \
    "   \"floaters\": {\"count\": 5},"                                                            \
    "   \"drag\": {\"path\": {\"points\": [[0.1, 0.2], [0.3, 0.2]], \"speed\": 0.3, \"loop\": "   \
    "true},"                                                                                      \
    "             \"radius\": 0.08, \"strength\": 5}"
#define EE_CONTAINER                                                                       \
    ",  \"container\": {\"shape\": \"box\", \"params\": {\"size\": [0.04, 0.04, 0.3]},"    \
    "                   \"path\": {\"points\": [[0.05, 0.35, 0.15], [0.35, 0.35, 0.15]], " \
    "\"speed\": 0.1}}"

static const char *const every_effect = EE_HEAD EE_OBSTACLES EE_EFFECTS EE_CONTAINER " }}";

static ms_scene *scene(const char *text)
{
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return sc;
}

static ms_sim *sim_of(const ms_scene *sc, int threads)
{
    ms_sim *sim = NULL;
    ms_status st = ms_sim_create_from_scene(sc, threads, &sim);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    return sim;
}

static void step(ms_sim *sim, float dt)
{
    ms_status st = ms_sim_step(sim, dt);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
}

static double max_wave(const ms_sim *sim)
{
    int nx, ny;
    const float *w = ms_sim_surface_height(sim, &nx, &ny);
    double m = 0;
    for (int i = 0; i < nx * ny; ++i)
        m = fmax(m, fabs(w[i]));
    return m;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t frame_hash(const ms_sim *sim)
{
    uint64_t h = 1469598103934665603ull;
    int nx, ny, n;
    const float *f = ms_sim_height(sim, &nx, &ny);
    h = fnv(h, f, sizeof *f * nx * ny);
    f = ms_sim_surface_height(sim, &nx, &ny);
    h = fnv(h, f, sizeof *f * nx * ny);
    f = ms_sim_volume_height(sim, &nx, &ny);
    h = fnv(h, f, sizeof *f * nx * ny);
    const float *pos[3], *vel[3];
    ms_sim_particles(sim, &n, pos, vel);
    for (int a = 0; a < 3; ++a) {
        h = fnv(h, pos[a], sizeof(float) * n);
        h = fnv(h, vel[a], sizeof(float) * n);
    }
    f = ms_sim_floaters(sim, &n);
    return fnv(h, f, sizeof *f * 3 * n);
}

/* An engine's task system: each task on a thread of its own. */
typedef struct {
    pthread_t t;
    ms_task_fn *fn;
    void *ctx;
} engine_task;
static int engine_calls;

static void *engine_thread(void *arg)
{
    engine_task *et = arg;
    et->fn(et->ctx);
    return NULL;
}

static void *engine_enqueue(ms_task_fn *fn, void *ctx, void *user)
{
    ck_assert_ptr_eq(user, &engine_calls);
    engine_task *et = malloc(sizeof *et);
    et->fn = fn;
    et->ctx = ctx;
    pthread_create(&et->t, NULL, engine_thread, et);
    ++engine_calls;
    return et;
}

static void engine_finish(void *task, void *user)
{
    (void)user;
    engine_task *et = task;
    pthread_join(et->t, NULL);
    free(et);
}

#define DET_FRAMES 200

/* Two cores or one, or the engine's threads: the same bytes, every frame,
 * with every effect on. */
START_TEST(one_and_two_threads_give_the_same_bytes)
{
    ms_scene *sc = scene(every_effect);
    ms_sim *one = sim_of(sc, 1), *two = sim_of(sc, 2);
    ms_sim *eng = sim_of(sc, 2);
    ck_assert_int_eq(ms_sim_set_tasks(eng, engine_enqueue, engine_finish, &engine_calls), MS_OK);
    for (int f = 0; f < DET_FRAMES; ++f) {
        /* a hitch now and then: frame_dt varies */
        float dt = f % 37 == 5 ? 0.05f : 1.0f / 60;
        step(one, dt);
        step(two, dt);
        step(eng, dt);
        uint64_t h1 = frame_hash(one), h2 = frame_hash(two), h3 = frame_hash(eng);
        ck_assert_msg(h1 == h2 && h1 == h3, "frame %d differs: %016llx %016llx %016llx", f,
                      (unsigned long long)h1, (unsigned long long)h2, (unsigned long long)h3);
    }
    ck_assert_int_eq(engine_calls, DET_FRAMES);
    /* and the run did something: particles moved, waves, floaters */
    ms_stats s = ms_stats_init();
    ms_sim_get_stats(two, &s);
    ck_assert_int_gt(s.volume_steps, DET_FRAMES);
    ck_assert_int_gt(s.drops, 2);
    ck_assert(max_wave(two) > 1e-4);
    ms_sim_destroy(one);
    ms_sim_destroy(two);
    ms_sim_destroy(eng);
    ms_scene_destroy(sc);
}
END_TEST

/* The same scene twice in one process: the same bytes (no hidden state,
 * the RNG is seeded from the scene). */
START_TEST(the_same_scene_runs_to_the_same_bytes)
{
    ms_scene *sc = scene(every_effect);
    ms_sim *a = sim_of(sc, 2);
    for (int f = 0; f < 40; ++f)
        step(a, 1.0f / 60);
    uint64_t ha = frame_hash(a);
    ms_sim_destroy(a);
    ms_sim *b = sim_of(sc, 2);
    for (int f = 0; f < 40; ++f)
        step(b, 1.0f / 60);
    ck_assert_uint_eq(frame_hash(b), ha);
    ms_sim_destroy(b);
    ms_scene_destroy(sc);
}
END_TEST

/* A volume-only scene on two threads gives the volume solver the second
 * core: still the same bytes as one. */
START_TEST(volume_only_on_two_threads_gives_the_same_bytes)
{
    ms_scene *sc =
        scene("{" POOL_DOMAIN ", " POOL_VOLUME ", \"effects\": {\"floaters\": {\"count\": 4}}}");
    ms_sim *one = sim_of(sc, 1), *two = sim_of(sc, 2);
    for (int f = 0; f < 60; ++f) {
        step(one, 1.0f / 60);
        step(two, 1.0f / 60);
        ck_assert_msg(frame_hash(one) == frame_hash(two), "frame %d differs", f);
    }
    ms_sim_destroy(one);
    ms_sim_destroy(two);
    ms_scene_destroy(sc);
}
END_TEST

/* DFSPH's solver passes on two threads (the suite runs under TSan in CI,
 * so a pass that writes what another thread's neighbours read is caught):
 * the same bytes as one thread, and the solve iterated. */
START_TEST(dfsph_on_two_threads_gives_the_same_bytes)
{
    ms_scene *sc = scene("{" POOL_DOMAIN ", \"volume\": {\"spacing\": 0.04, \"pressure\": "
                         "\"dfsph\", \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.2, 0.4, "
                         "0.3]}], \"field\": [16, 16]}}");
    ms_sim *one = sim_of(sc, 1), *two = sim_of(sc, 2);
    for (int f = 0; f < 30; ++f) {
        step(one, 1.0f / 60);
        step(two, 1.0f / 60);
        ck_assert_msg(frame_hash(one) == frame_hash(two), "frame %d differs", f);
    }
    ms_stats s = ms_stats_init();
    ms_sim_get_stats(two, &s);
    ck_assert_int_ge(s.volume_steps, 30);
    ms_sim_destroy(one);
    ms_sim_destroy(two);
    ms_scene_destroy(sc);
}
END_TEST

/* The volume's parallel loops on an engine's tasks (ms_volume_set_tasks,
 * handed on by the sim): its own worker threads are stopped, the chunks
 * run as the engine's tasks, and the bytes are those of one thread. */
START_TEST(volume_loops_on_engine_tasks_give_the_same_bytes)
{
    ms_scene *sc = scene("{" POOL_DOMAIN ", \"volume\": {\"spacing\": 0.04, \"threads\": 2, "
                         "\"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.12]}], "
                         "\"field\": [16, 16]}}");
    ms_sim *one = sim_of(sc, 1), *eng = sim_of(sc, 2);
    ck_assert_int_eq(ms_sim_set_tasks(eng, engine_enqueue, engine_finish, &engine_calls), MS_OK);
    engine_calls = 0;
    for (int f = 0; f < 40; ++f) {
        step(one, 1.0f / 60);
        step(eng, 1.0f / 60);
        ck_assert_msg(frame_hash(one) == frame_hash(eng), "frame %d differs", f);
    }
    /* every parallel loop of every sub-step went through the engine */
    ms_stats st = ms_stats_init();
    ms_sim_get_stats(eng, &st);
    ck_assert_int_gt(engine_calls, st.volume_steps);
    ms_sim_destroy(one);
    ms_sim_destroy(eng);
    ms_scene_destroy(sc);

    /* the same on a bare volume, and back to its own threads */
    ms_volume_desc d = ms_volume_desc_default();
    ms_volume *a = NULL, *b = NULL;
    ck_assert_int_eq(ms_volume_create(&d, &a), MS_OK);
    d.threads = 3;
    ck_assert_int_eq(ms_volume_create(&d, &b), MS_OK);
    const float lo[3] = {0, 0, 0}, hi[3] = {0.3f, 1, 0.5f};
    ck_assert_int_eq(ms_volume_fill_box(a, lo, hi), MS_OK);
    ck_assert_int_eq(ms_volume_fill_box(b, lo, hi), MS_OK);
    ck_assert_int_eq(ms_volume_set_tasks(b, engine_enqueue, engine_finish, &engine_calls), MS_OK);
    for (int f = 0; f < 10; ++f) {
        if (f == 5)
            ck_assert_int_eq(ms_volume_set_tasks(b, NULL, NULL, NULL), MS_OK);
        ck_assert_int_eq(ms_volume_step(a, 1.0f / 60), MS_OK);
        ck_assert_int_eq(ms_volume_step(b, 1.0f / 60), MS_OK);
    }
    int n = ms_volume_count(a);
    float *pa = malloc(sizeof(float) * 3 * n), *pb = malloc(sizeof(float) * 3 * n);
    ck_assert_int_eq(ms_volume_get_particles(a, pa, NULL), MS_OK);
    ck_assert_int_eq(ms_volume_get_particles(b, pb, NULL), MS_OK);
    ck_assert(memcmp(pa, pb, sizeof(float) * 3 * n) == 0);
    free(pa);
    free(pb);
    MS_ASSERT_REFUSED(ms_volume_set_tasks(b, engine_enqueue, NULL, NULL), MS_ERR_INVALID_ARGUMENT,
                      "both");
    ms_volume_destroy(a);
    ms_volume_destroy(b);
}
END_TEST

/* Determinism across commits (as Box2D pins a state hash): the hash of
 * every field, particle and floater of the every-effect scene after
 * GOLDEN_FRAMES frames is the one in GOLDEN_FILE. A change that changes
 * results fails here and shows as a diff of that file: if it is meant,
 * `make golden` writes the new hash (commit it with the change, saying why
 * the results moved). Builds with other floating-point code (NATIVE=1,
 * another compiler) may differ in the last bits. */
#define GOLDEN_FILE "tests/data/golden_hash.txt"
#define GOLDEN_FRAMES 60

START_TEST(results_match_the_golden_hash)
{
    ms_scene *sc = scene(every_effect);
    ms_sim *sim = sim_of(sc, 1);
    for (int f = 0; f < GOLDEN_FRAMES; ++f)
        step(sim, 1.0f / 60);
    unsigned long long h = (unsigned long long)frame_hash(sim);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    const char *write = getenv("MS_GOLDEN_WRITE");
    if (write && write[0] == '1') {
        FILE *f = fopen(GOLDEN_FILE, "w");
        ck_assert_msg(f != NULL, "cannot write %s (run from the source root)", GOLDEN_FILE);
        fprintf(f, "%016llx\n", h);
        fclose(f);
        fprintf(stderr, "golden: wrote %016llx to %s\n", h, GOLDEN_FILE);
        return;
    }
    FILE *f = fopen(GOLDEN_FILE, "r");
    ck_assert_msg(f != NULL, "%s is missing: run `make golden`", GOLDEN_FILE);
    unsigned long long want = 0;
    int got = fscanf(f, "%llx", &want);
    fclose(f);
    ck_assert_int_eq(got, 1);
    ck_assert_msg(h == want,
                  "the every-effect scene after %d frames hashes to %016llx, %s says %016llx: "
                  "the results changed; if that is meant, run `make golden` and commit it",
                  GOLDEN_FRAMES, h, GOLDEN_FILE, want);
}
END_TEST

static Suite *determinism_suite(void)
{
    Suite *s = suite_create("determinism");
    TCase *tc = tcase_create("determinism");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, one_and_two_threads_give_the_same_bytes);
    tcase_add_test(tc, the_same_scene_runs_to_the_same_bytes);
    tcase_add_test(tc, volume_only_on_two_threads_gives_the_same_bytes);
    tcase_add_test(tc, dfsph_on_two_threads_gives_the_same_bytes);
    tcase_add_test(tc, volume_loops_on_engine_tasks_give_the_same_bytes);
    suite_add_tcase(s, tc);
    TCase *golden = tcase_create("golden");
    tcase_set_timeout(golden, 600);
    tcase_add_test(golden, results_match_the_golden_hash);
    suite_add_tcase(s, golden);
    return s;
}

int main(void)
{
    return ms_test_run(determinism_suite());
}
