/* The engine's allocator (ms_set_allocator, core.h): every block of the
 * library comes from it and goes back to it; ms_surface_step (disturbers,
 * rain) allocates nothing, a running scene's frame (1 and 2 threads)
 * nothing after the first. */
#include <check.h>
#include <stdatomic.h>
#include <stdio.h>
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
    /* add_disturber made the room the steps use: no step allocates, the
     * first included */
    const long before = atomic_load(&allocs);
    for (int k = 0; k < 60; ++k)
        ck_assert_int_eq(ms_surface_step(s, 1.0f / 60), MS_OK);
    ck_assert_int_eq(atomic_load(&allocs), before);
    ms_surface_destroy(s);
}
END_TEST

/* A running scene allocates nothing in any frame after the first, at 1
 * and 2 threads: the first frame makes every block the pipeline
 * uses at its largest (both snapshot slots, the extraction scratch, the
 * drag's one-cell extraction), create makes the boat's path, the drag
 * dent's room and the volume's wave record, and the first density pass
 * gives the neighbour lists their headroom (neighbours.c). The scenes
 * cover every effect: fig10 (SPH, boat, rain, floaters, both couplings),
 * fig3 (waves only: drops, rain, boat), fig1 (the pointer dragging the
 * volume), fig4c (SPH only), stir (moving shapes), glass (a container),
 * and fig10 with DFSPH pressure. 150 frames: 2.5 s, through the sloshing's
 * first swing (the lists' high-water marks came at frames 7-68 before). */
static void frames_allocate_nothing(const char *path, const char *from, const char *to, int threads)
{
    install();
    char *text = ms_test_scene_variant(path, from, to); /* from: one key changed */
    ck_assert_ptr_nonnull(text);
    ms_scene *sc = NULL;
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    free(text);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, threads, &sim), MS_OK);
    const float dt = ms_scene_frame_dt(sc);
    ck_assert_int_eq(ms_sim_step(sim, dt), MS_OK);
    const long first = atomic_load(&allocs);
    for (int f = 1; f < 150; ++f) {
        st = ms_sim_step(sim, dt);
        ck_assert_msg(st == MS_OK, "%s", ms_last_error());
        ck_assert_msg(atomic_load(&allocs) == first, "%s%s, %d threads: frame %d made %ld blocks",
                      path, from ? " (variant)" : "", threads, f, atomic_load(&allocs) - first);
    }
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
}

START_TEST(a_running_scene_allocates_nothing_after_the_first_frame)
{
    static const char *const scenes[] = {"data/scenes/fig10.json", "data/scenes/fig3.json",
                                         "data/scenes/fig1.json",  "data/scenes/fig4c.json",
                                         "data/scenes/stir.json",  "data/scenes/glass.json"};
    frames_allocate_nothing(scenes[_i / 2], NULL, NULL, 1 + _i % 2);
}
END_TEST

START_TEST(a_dfsph_scene_allocates_nothing_after_the_first_frame)
{
    frames_allocate_nothing("data/scenes/fig10.json", "\"spacing\": 0.05,",
                            "\"spacing\": 0.05, \"pressure\": \"dfsph\",", 1 + _i);
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
    tcase_add_loop_test(tc, a_running_scene_allocates_nothing_after_the_first_frame, 0, 12);
    tcase_add_loop_test(tc, a_dfsph_scene_allocates_nothing_after_the_first_frame, 0, 2);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(alloc_suite());
}
