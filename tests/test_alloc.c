/* The engine's allocator (ms_set_allocator, core.h): every block of the
 * library comes from it and goes back to it; ms_surface_step (disturbers,
 * rain) allocates nothing after the first step, a running scene's frame
 * (1 and 2 threads) nothing once settled. */
#include <check.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "support.h"

static atomic_long allocs, frees, live;

static void *counting_alloc(size_t size, size_t alignment, void *user)
{
    ck_assert_ptr_eq(user, &allocs);
    ck_assert_uint_eq(alignment, 64);
    atomic_fetch_add(&allocs, 1);
    atomic_fetch_add(&live, 1);
    return aligned_alloc(alignment, size);
}

static void counting_free(void *p, void *user)
{
    ck_assert_ptr_eq(user, &allocs);
    atomic_fetch_add(&frees, 1);
    atomic_fetch_sub(&live, 1);
    free(p);
}

static void install(void)
{
    ck_assert_int_eq(ms_set_allocator(counting_alloc, counting_free, &allocs), MS_OK);
}

START_TEST(set_allocator_refuses_half_a_pair_and_a_change_while_memory_is_held)
{
    MS_ASSERT_REFUSED(ms_set_allocator(counting_alloc, NULL, NULL), MS_ERR_INVALID_ARGUMENT,
                      "both");
    install();
    ms_surface_desc d = ms_surface_desc_default();
    ms_surface *s = NULL;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ck_assert_int_gt(atomic_load(&live), 0);
    MS_ASSERT_REFUSED(ms_set_allocator(NULL, NULL, NULL), MS_ERR_STATE, "holds");
    ms_surface_destroy(s);
    ck_assert_int_eq(atomic_load(&live), 0);
    ck_assert_int_eq(ms_set_allocator(NULL, NULL, NULL), MS_OK); /* back to the default */
    long before = atomic_load(&allocs);
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ck_assert_int_eq(atomic_load(&allocs), before);
    ms_surface_destroy(s);
}
END_TEST

/* Everything a scene run touches (scene, plugins, shapes, sim, writer)
 * allocates through the hook and gives all of it back. */
START_TEST(every_block_comes_from_the_hook_and_goes_back)
{
    install();
    long lib0 = ms_alloc_count();
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load("data/scenes/fig10.json", &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &sim), MS_OK);
    for (int f = 0; f < 3; ++f)
        ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    ck_assert_int_eq(atomic_load(&allocs), ms_alloc_count() - lib0);
    ck_assert_int_gt(atomic_load(&allocs), 10);
    /* the plugin registry keeps its records for the process; the rest is back */
    ck_assert_int_eq(atomic_load(&live), ms_alloc_live());
}
END_TEST

START_TEST(surface_steps_allocate_nothing_after_the_first)
{
    install();
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = 64;
    ms_surface *s = NULL;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ms_disturber_desc b = ms_disturber_desc_default();
    b.x = b.y = 0.2f;
    b.vx = 0.1f;
    int id;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    b.x = 0.4f;
    ck_assert_int_eq(ms_surface_add_disturber(s, &b, &id), MS_OK);
    ms_rain rain = ms_rain_default();
    rain.rate = 50;
    ck_assert_int_eq(ms_surface_set_rain(s, &rain), MS_OK);
    ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    long after_first = atomic_load(&allocs);
    for (int k = 0; k < 60; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_int_eq(atomic_load(&allocs), after_first);
    ms_surface_destroy(s);
}
END_TEST

/* A running scene: the pipeline's first two frames (the first publishes
 * the start, the second is the first to step the waves on the SPH field)
 * make the buffers that are sized on first use; after them, blocks are
 * only made when a high-water mark rises (neighbour lists, the extraction's
 * scratch, grown geometrically): a few times while the liquid settles, and
 * never once it has (frames 60-179 here). */
static void frames_allocate_nothing(const char *path, int threads)
{
    install();
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load(path, &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, threads, &sim), MS_OK);
    const float dt = ms_scene_frame_dt(sc);
    for (int f = 0; f < 2; ++f)
        ck_assert_int_eq(ms_sim_step(sim, dt), MS_OK);
    long warm = atomic_load(&allocs);
    for (int f = 2; f < 60; ++f)
        ck_assert_int_eq(ms_sim_step(sim, dt), MS_OK);
    long grown = atomic_load(&allocs) - warm;
    /* measured at most 4 blocks (fig1: two lists at frames 15 and 68) */
    ck_assert_msg(grown <= 8, "%s, %d threads: %ld blocks in frames 2-59", path, threads, grown);
    long settled = atomic_load(&allocs);
    for (int f = 60; f < 180; ++f) {
        ck_assert_int_eq(ms_sim_step(sim, dt), MS_OK);
        ck_assert_msg(atomic_load(&allocs) == settled, "%s, %d threads: frame %d allocated %ld blocks",
                      path, threads, f, atomic_load(&allocs) - settled);
    }
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}

START_TEST(a_running_scene_allocates_nothing_once_settled)
{
    static const char *const scenes[] = {"data/scenes/fig10.json", "data/scenes/fig3.json",
                                         "data/scenes/stir.json", "data/scenes/glass.json"};
    frames_allocate_nothing(scenes[_i / 2], 1 + _i % 2);
}
END_TEST

static Suite *alloc_suite(void)
{
    Suite *s = suite_create("alloc");
    TCase *tc = tcase_create("alloc");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, set_allocator_refuses_half_a_pair_and_a_change_while_memory_is_held);
    tcase_add_test(tc, every_block_comes_from_the_hook_and_goes_back);
    tcase_add_test(tc, surface_steps_allocate_nothing_after_the_first);
    tcase_add_loop_test(tc, a_running_scene_allocates_nothing_once_settled, 0, 8);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(alloc_suite());
}
