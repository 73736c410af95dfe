/* The engine owns the threads (core.h's task interface): when it gives its
 * enqueue/finish callbacks, the library starts no pthread of its own,
 * whatever the thread counts of the sim and volume descs; without them it
 * does (so a count of 0 means something). The library's pthread_create
 * calls are counted by linking this suite with
 * -Wl,--wrap=pthread_create (Makefile): every call the static library
 * makes goes to __wrap_pthread_create below, which counts and starts the
 * thread as asked (through __real_pthread_create, so a sanitizer's
 * interceptor still sees it). */
#include <check.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"

int __real_pthread_create(pthread_t *t, const pthread_attr_t *a, void *(*fn)(void *), void *arg);
int __wrap_pthread_create(pthread_t *t, const pthread_attr_t *a, void *(*fn)(void *), void *arg);

static atomic_int created; /* pthread_create calls of the library */

int __wrap_pthread_create(pthread_t *t, const pthread_attr_t *a, void *(*fn)(void *), void *arg)
{
    atomic_fetch_add(&created, 1);
    return __real_pthread_create(t, a, fn, arg);
}

static int made(void)
{
    return atomic_load(&created);
}

/* A stand-in for an engine's task system that runs each task when the
 * library waits for it (finish), on the calling thread: a serial engine,
 * which the library must accept as it accepts a parallel one. */
typedef struct task {
    ms_task_fn *fn;
    void *ctx;
} task;

typedef struct engine {
    int enqueued, finished;
} engine;

static void *engine_enqueue(ms_task_fn *fn, void *ctx, void *user)
{
    engine *e = user;
    task *t = malloc(sizeof *t);
    ck_assert_ptr_nonnull(t);
    t->fn = fn;
    t->ctx = ctx;
    ++e->enqueued;
    return t;
}

static void engine_finish(void *handle, void *user)
{
    engine *e = user;
    task *t = handle;
    ++e->finished;
    t->fn(t->ctx);
    free(t);
}

/* A volume of 4 threads with ~4000 particles (loops of fewer than 256 run
 * on the calling thread), a dam of 1 m x 1 m x 0.24 m at 0.04 m. */
static ms_volume *volume_of_4_threads(void)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.threads = 4;
    ms_volume *v = NULL;
    ck_assert_int_eq(ms_volume_create(&d, &v), MS_OK);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){1, 1, 0.24f}), MS_OK);
    ck_assert_int_gt(ms_volume_count(v), 3000);
    return v;
}

START_TEST(a_volume_of_4_threads_given_tasks_creates_no_pthread)
{
    engine e = {0};
    atomic_store(&created, 0);
    ms_volume *v = volume_of_4_threads();
    ck_assert_int_eq(made(), 0); /* none before the engine could hand over */
    ck_assert_int_eq(ms_volume_settle(v, 0.05f), MS_OK); /* nor to settle the fill */
    ck_assert_int_eq(made(), 0);
    ck_assert_int_eq(ms_volume_set_tasks(v, engine_enqueue, engine_finish, &e), MS_OK);
    for (int k = 0; k < 3; ++k)
        ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(made(), 0);
    ck_assert_int_gt(e.enqueued, 0); /* the loops ran as the engine's tasks */
    ck_assert_int_eq(e.finished, e.enqueued);
    ms_volume_info info = ms_volume_info_init();
    ms_volume_get_info(v, &info);
    ck_assert_int_eq(info.threads, 4);
    ms_volume_destroy(v);
    ck_assert_int_eq(made(), 0);
}
END_TEST

/* The control: the count sees the library's own threads. */
START_TEST(a_volume_of_4_threads_without_tasks_starts_3_at_its_first_step)
{
    atomic_store(&created, 0);
    ms_volume *v = volume_of_4_threads();
    ck_assert_int_eq(made(), 0);
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(made(), 3);
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(made(), 3); /* started once */
    /* handed over, then given back: the next step starts them again */
    engine e = {0};
    ck_assert_int_eq(ms_volume_set_tasks(v, engine_enqueue, engine_finish, &e), MS_OK);
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(made(), 3);
    ck_assert_int_gt(e.enqueued, 0);
    ck_assert_int_eq(ms_volume_set_tasks(v, NULL, NULL, NULL), MS_OK);
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ck_assert_int_eq(made(), 6);
    ms_volume_destroy(v);
}
END_TEST

/* A sim of threads 2 whose volume desc asks for 2 threads, over a 1 m
 * pool with waves: the desc's tasks (_i = 1) or none (_i = 0). */
START_TEST(a_sim_given_tasks_in_its_desc_creates_no_pthread)
{
    const int tasks = _i;
    engine e = {0};
    ms_volume_desc v = ms_volume_desc_default();
    v.threads = 2;
    ms_surface_desc s = ms_surface_desc_default();
    s.nx = s.ny = 100; /* 1 m, as the default volume */
    ms_sim_desc d = ms_sim_desc_default();
    d.volume = &v;
    d.surface = &s;
    d.threads = 2;
    if (tasks) {
        d.enqueue_task = engine_enqueue;
        d.finish_task = engine_finish;
        d.user_task_context = &e;
    }
    atomic_store(&created, 0);
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ck_assert_int_eq(
        ms_volume_fill_box(ms_sim_volume(sim), (float[3]){0, 0, 0}, (float[3]){0.5f, 1, 0.3f}),
        MS_OK);
    ck_assert_int_eq(made(), 0);
    for (int k = 0; k < 3; ++k)
        ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    if (tasks) {
        ck_assert_int_eq(made(), 0);
        ck_assert_int_gt(e.enqueued, 3); /* the split and the volume's loops */
    } else {
        /* the sim's second thread and the volume's own one */
        ck_assert_int_eq(made(), 2);
    }
    ms_sim_destroy(sim);
}
END_TEST

/* A scene's sim handed to the engine after create, before its first
 * frame: no thread either (the sim's second thread starts with the first
 * frame that needs it). */
START_TEST(a_scene_sim_given_tasks_before_its_first_frame_creates_no_pthread)
{
    char *text = ms_test_scene_variant("tests/data/small_run.json", "\"spacing\": 0.06,",
                                       "\"spacing\": 0.04, \"threads\": 2,");
    ck_assert_ptr_nonnull(text);
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    free(text);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    engine e = {0};
    atomic_store(&created, 0);
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &sim), MS_OK);
    ck_assert_int_eq(ms_sim_set_tasks(sim, engine_enqueue, engine_finish, &e), MS_OK);
    for (int k = 0; k < 3; ++k)
        ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
    ck_assert_int_eq(made(), 0);
    ck_assert_int_gt(e.enqueued, 3);
    /* given back: the next frame starts the library's own */
    ck_assert_int_eq(ms_sim_set_tasks(sim, NULL, NULL, NULL), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
    ck_assert_int_gt(made(), 0);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *threads_suite(void)
{
    Suite *s = suite_create("threads");
    TCase *tc = tcase_create("threads");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, a_volume_of_4_threads_given_tasks_creates_no_pthread);
    tcase_add_test(tc, a_volume_of_4_threads_without_tasks_starts_3_at_its_first_step);
    tcase_add_loop_test(tc, a_sim_given_tasks_in_its_desc_creates_no_pthread, 0, 2);
    tcase_add_test(tc, a_scene_sim_given_tasks_before_its_first_frame_creates_no_pthread);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(threads_suite());
}
