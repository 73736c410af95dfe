/* The engine's allocator (ms_set_allocator, core.h): every block of the
 * library and of the shipped plugins comes from it and goes back to it;
 * neither calls the C allocator itself; ms_surface_step (disturbers,
 * rain) allocates nothing, a running scene's frame (1 and 2 threads)
 * nothing after the first.
 * The library's direct calls are counted: this suite is linked with
 * -Wl,--wrap=malloc and its siblings (Makefile), so every call the static
 * library makes to them comes to __wrap_malloc & co. below first (the
 * dependencies, shared objects such as jansson and HDF5, keep their own
 * allocators, and are not counted). A plugin is a shared object, so its
 * direct calls are read from its imports (nm -D). */
#include <check.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "plugin/plugin_internal.h"
#include "support.h"

static atomic_long allocs, frees, live;

/* ---- the C allocator's entries, counted while `watching` ---- */
static atomic_int watching;
static atomic_long direct; /* calls while watching */

#define WRAPPED(ret, name, params, args)  \
    ret __real_##name params;             \
    ret __wrap_##name params;             \
    ret __wrap_##name params              \
    {                                     \
        if (atomic_load(&watching))       \
            atomic_fetch_add(&direct, 1); \
        return __real_##name args;        \
    }
WRAPPED(void *, malloc, (size_t n), (n))
WRAPPED(void *, calloc, (size_t n, size_t size), (n, size))
WRAPPED(void *, realloc, (void *p, size_t n), (p, n))
WRAPPED(void *, aligned_alloc, (size_t alignment, size_t n), (alignment, n))
WRAPPED(int, posix_memalign, (void **p, size_t alignment, size_t n), (p, alignment, n))
WRAPPED(char *, strdup, (const char *str), (str))
WRAPPED(char *, strndup, (const char *str, size_t n), (str, n))
void __real_free(void *p);
void __wrap_free(void *p);
void __wrap_free(void *p)
{
    if (atomic_load(&watching))
        atomic_fetch_add(&direct, 1);
    __real_free(p);
}

static void watch(void)
{
    atomic_store(&direct, 0);
    atomic_store(&watching, 1);
}

/* the direct calls since watch() */
static long unwatch(void)
{
    atomic_store(&watching, 0);
    return atomic_load(&direct);
}

/* Check's assertions allocate (its static library is wrapped too), so
 * none runs while watching: REQUIRE notes the first condition that failed
 * and ASSERT_REQUIRED reports it once the watch is over. */
static const char *required_failed;
static int required_line;
static char required_why[512];
#define REQUIRE(cond)                                                           \
    do {                                                                        \
        if (!(cond) && !required_failed) {                                      \
            required_failed = #cond;                                            \
            required_line = __LINE__;                                           \
            snprintf(required_why, sizeof required_why, "%s", ms_last_error()); \
        }                                                                       \
    } while (0)
#define ASSERT_REQUIRED()                                                                          \
    do {                                                                                           \
        ck_assert_msg(!required_failed, "line %d: %s failed (%s)", required_line, required_failed, \
                      required_why);                                                               \
        ck_assert_int_eq(atomic_load(&hook_misused), 0);                                           \
    } while (0)

/* A call of the hooks with another user pointer or alignment; noted, not
 * asserted there (an assertion allocates: REQUIRE's comment). */
static atomic_int hook_misused;

static void *counting_alloc(size_t size, size_t alignment, void *user)
{
    if (user != &allocs || alignment != 64)
        atomic_store(&hook_misused, 1);
    atomic_fetch_add(&allocs, 1);
    atomic_fetch_add(&live, 1);
    return __real_aligned_alloc(alignment, size);
}

static void counting_free(void *p, void *user)
{
    if (user != &allocs)
        atomic_store(&hook_misused, 1);
    atomic_fetch_add(&frees, 1);
    atomic_fetch_sub(&live, 1);
    __real_free(p);
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
    watch();
    ms_scene *sc = NULL;
    ms_sim *sim = NULL;
    REQUIRE(ms_scene_load("data/scenes/fig10.json", &sc) == MS_OK);
    REQUIRE(!sc || ms_sim_create_from_scene(sc, 2, &sim) == MS_OK);
    for (int f = 0; sim && f < 3; ++f)
        REQUIRE(ms_sim_step(sim, 1.0f / 60) == MS_OK);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    ck_assert_int_eq(unwatch(), 0); /* no direct call of the library's */
    ASSERT_REQUIRED();
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
    long lib_direct = 0; /* the library's direct calls, each call watched */
    watch();
    ms_status st = ms_scene_parse(text, strlen(text), &sc);
    lib_direct += unwatch();
    free(text);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    watch();
    st = ms_sim_create_from_scene(sc, threads, &sim);
    lib_direct += unwatch();
    ck_assert_int_eq(st, MS_OK);
    const float dt = ms_scene_frame_dt(sc);
    watch();
    st = ms_sim_step(sim, dt);
    lib_direct += unwatch();
    ck_assert_int_eq(st, MS_OK);
    const long first = atomic_load(&allocs);
    for (int f = 1; f < 150; ++f) {
        watch();
        st = ms_sim_step(sim, dt);
        lib_direct += unwatch();
        ck_assert_msg(st == MS_OK, "%s", ms_last_error());
        ck_assert_msg(atomic_load(&allocs) == first, "%s%s, %d threads: frame %d made %ld blocks",
                      path, from ? " (variant)" : "", threads, f, atomic_load(&allocs) - first);
    }
    watch();
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    lib_direct += unwatch();
    ck_assert_int_eq(lib_direct, 0); /* no direct call of the library's */
    ASSERT_REQUIRED();
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

/* The libc allocator functions a plugin file imports ("" when none), read
 * with nm (binutils, which builds the library). */
static void allocator_imports(const char *path, char *out, size_t n)
{
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "nm -D --undefined-only '%s'", path);
    FILE *p = popen(cmd, "r");
    ck_assert_ptr_nonnull(p);
    static const char *const names[] = {
        "malloc",  "calloc",        "realloc",        "free",         "strdup",
        "strndup", "aligned_alloc", "posix_memalign", "reallocarray", NULL};
    char line[512];
    int lines = 0;
    out[0] = '\0';
    while (fgets(line, sizeof line, p)) {
        ++lines;
        char sym[256] = "";
        if (sscanf(line, " %*s %255[^@ \n]", sym) != 1)
            continue;
        for (int k = 0; names[k]; ++k)
            if (!strcmp(sym, names[k]) && strlen(out) + strlen(sym) + 2 < n) {
                strcat(out, sym);
                strcat(out, " ");
            }
    }
    ck_assert_int_eq(pclose(p), 0);
    ck_assert_int_gt(lines, 0); /* every plugin imports something (libm, jansson) */
}

/* Every shipped plugin's instances come from the engine's allocator
 * (through the host's, ABI 1.1), created and destroyed through the
 * plugin's own vtable, and no plugin imports the C allocator. */
START_TEST(shipped_plugins_allocate_through_the_host)
{
    install();
    int shapes = 0, shaders = 0;
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ck_assert_int_eq(ms_plugin_describe(i, &d), MS_OK);
        char imports[256];
        allocator_imports(d.path, imports, sizeof imports);
        ck_assert_msg(!imports[0], "%s imports %s", d.path, imports);
        const int shape = !strcmp(d.kind, "shape");
        const ms_plugin_rec *rec;
        ck_assert_int_eq(
            ms_plugin_find("test", d.name, shape ? MS_PLUGIN_SHAPE : MS_PLUGIN_SHADER, &rec),
            MS_OK);
        int (*create)(const char *, void **, char *, size_t) =
            shape ? rec->vt.shape.create : rec->vt.shader.create;
        void (*destroy)(void *) = shape ? rec->vt.shape.destroy : rec->vt.shader.destroy;
        if (!create)
            continue; /* a shader without parameters keeps nothing */
        const long a0 = atomic_load(&allocs), f0 = atomic_load(&frees);
        void *self = NULL;
        char err[256];
        watch();
        const int rc = create(NULL, &self, err, sizeof err);
        const long held = atomic_load(&allocs) - a0;
        if (rc == MS_PLUGIN_OK)
            destroy(self);
        ck_assert_int_eq(unwatch(), 0);
        ck_assert_msg(rc == MS_PLUGIN_OK, "%s: %s", d.name, err);
        ck_assert_msg(held > 0, "%s kept no block of the host's", d.name);
        ck_assert_int_eq(atomic_load(&frees) - f0, atomic_load(&allocs) - a0);
        shapes += shape;
        shaders += !shape;
    }
    ASSERT_REQUIRED();
    ck_assert_int_ge(shapes, 6);  /* box, capsule, glass, plane, sphere, terrain */
    ck_assert_int_ge(shaders, 4); /* honey, milk, oil, water */
}
END_TEST

static Suite *alloc_suite(void)
{
    Suite *s = suite_create("alloc");
    TCase *tc = tcase_create("alloc");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, set_allocator_refuses_half_a_pair_and_a_change_while_memory_is_held);
    tcase_add_test(tc, every_block_comes_from_the_hook_and_goes_back);
    tcase_add_test(tc, shipped_plugins_allocate_through_the_host);
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
