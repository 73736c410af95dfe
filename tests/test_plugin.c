/* Plugins: the loader's refusals (each one closes the library and leaves
 * the registry usable), the search path, the registry and its listing. */
#define _DEFAULT_SOURCE /* mkdtemp, setenv */
#include <check.h>
#include <dlfcn.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "plugin/plugin_internal.h"
#include "support.h"

/* The test builds its broken plugins from tests/plugins/bad_plugin.c into
 * a temporary directory, once (the runs start in the source tree). */
static char tmp[256];

static const char *const variants[][2] = {
    {"no_entry", "-DNO_ENTRY"},
    {"abi_major", "-DABI_MAJOR"},
    {"abi_newer", "-DABI_NEWER"},
    {"size_zero", "-DSIZE_ZERO"},
    {"size_trunc", "-DSIZE_TRUNC"},
    {"null_info", "-DNULL_INFO"},
    {"bad_kind", "-DBAD_KIND"},
    {"bad_name", "-DBAD_NAME"},
    {"no_vtable", "-DNO_VTABLE"},
    {"vt_trunc", "-DVT_TRUNC"},
    {"no_distance", "-DNO_DISTANCE"},
    {"testball", ""},
    {"testball_again", ""},
    {"fake_sphere", "-DNAME=\\\"sphere\\\""},
    {"oldball", "-DABI_1_0 -DNAME=\\\"oldball\\\""},
};
#define N_VARIANTS (int)(sizeof variants / sizeof variants[0])
#define N_BAD 11 /* the first N_BAD variants are refused */

static void path_of(char *out, size_t n, const char *name, const char *ext)
{
    snprintf(out, n, "%s/%s%s", tmp, name, ext);
}

static void build_plugins(void)
{
    snprintf(tmp, sizeof tmp, "/tmp/ms_test_plugin_XXXXXX");
    if (!mkdtemp(tmp)) {
        tmp[0] = '\0';
        return;
    }
    const char *cc = getenv("CC") ? getenv("CC") : "cc";
    char cmd[8192];
    /* all variants in one shell, two at a time */
    size_t len = (size_t)snprintf(cmd, sizeof cmd, "set -e; ");
    for (int i = 0; i < N_VARIANTS; ++i)
        len += (size_t)snprintf(cmd + len, sizeof cmd - len,
                                "%s -std=c11 -shared -fPIC -fvisibility=hidden -Iinclude %s "
                                "tests/plugins/bad_plugin.c -o %s/%s.so -lm %s ",
                                cc, variants[i][1], tmp, variants[i][0], i % 2 ? "; wait;" : "&");
    len += (size_t)snprintf(cmd + len, sizeof cmd - len,
                            "wait; %s -std=c11 -c -fPIC -Iinclude tests/plugins/bad_plugin.c "
                            "-o %s/object.so; printf 'not a plugin\\n' > %s/notes.so",
                            cc, tmp, tmp);
    if (system(cmd) != 0)
        tmp[0] = '\0';
}

static void remove_plugins(void)
{
    if (!tmp[0])
        return;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmp);
}

/* The file was closed: a library still loaded would be found by NOLOAD. */
static int is_loaded(const char *path)
{
    void *h = dlopen(path, RTLD_NOW | RTLD_NOLOAD);
    if (h)
        dlclose(h);
    return h != NULL;
}

/* The library still works: the built-in sphere is there and usable. */
static void assert_usable(int count)
{
    ck_assert_int_eq(ms_plugin_count(), count);
    ms_shape *s;
    ck_assert_int_eq(ms_shape_create("sphere", "{\"radius\": 1}", &s), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){2, 0, 0}, NULL), 1.0f, 1e-6f);
    ms_shape_destroy(s);
}

static void assert_refused(const char *variant, ms_status status, const char *word)
{
    ck_assert_msg(tmp[0], "the test plugins could not be built");
    int n = ms_plugin_count();
    char path[512];
    path_of(path, sizeof path, variant, ".so");
    MS_ASSERT_REFUSED(ms_plugin_load(path), status, word);
    ck_assert_msg(strstr(ms_last_error(), path), "message \"%s\" lacks the file", ms_last_error());
    ck_assert_msg(!is_loaded(path), "%s is still loaded after the refusal", path);
    assert_usable(n);
}

START_TEST(refuses_a_file_that_is_not_elf)
{
    assert_refused("notes", MS_ERR_PLUGIN, "not a shared object");
}
END_TEST

START_TEST(refuses_an_elf_file_that_is_not_shared)
{
    assert_refused("object", MS_ERR_PLUGIN, "ELF type 1");
}
END_TEST

START_TEST(refuses_a_missing_file)
{
    assert_refused("does_not_exist", MS_ERR_IO, "cannot open");
}
END_TEST

START_TEST(refuses_a_library_without_the_entry_symbol)
{
    assert_refused("no_entry", MS_ERR_PLUGIN, "no symbol ms_plugin_entry");
}
END_TEST

START_TEST(refuses_another_abi_major)
{
    assert_refused("abi_major", MS_ERR_PLUGIN, "ABI 2.0");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "ms_plugin_entry"));
}
END_TEST

START_TEST(refuses_a_newer_abi_minor)
{
    assert_refused("abi_newer", MS_ERR_PLUGIN, "newer");
}
END_TEST

START_TEST(refuses_a_zero_size_info)
{
    assert_refused("size_zero", MS_ERR_PLUGIN, "size 0 bytes");
}
END_TEST

START_TEST(refuses_a_truncated_info)
{
    assert_refused("size_trunc", MS_ERR_PLUGIN, "truncated");
}
END_TEST

START_TEST(refuses_a_null_info)
{
    assert_refused("null_info", MS_ERR_PLUGIN, "returned NULL");
}
END_TEST

START_TEST(refuses_an_unknown_plugin_kind)
{
    assert_refused("bad_kind", MS_ERR_PLUGIN, "kind 7");
}
END_TEST

START_TEST(refuses_an_invalid_name)
{
    assert_refused("bad_name", MS_ERR_PLUGIN, "invalid name");
}
END_TEST

START_TEST(refuses_a_missing_vtable)
{
    assert_refused("no_vtable", MS_ERR_PLUGIN, "no vtable");
}
END_TEST

START_TEST(refuses_a_truncated_vtable)
{
    assert_refused("vt_trunc", MS_ERR_PLUGIN, "truncated");
}
END_TEST

START_TEST(refuses_a_vtable_without_distance)
{
    assert_refused("no_distance", MS_ERR_PLUGIN, "no distance");
}
END_TEST

START_TEST(refuses_a_duplicate_name)
{
    ck_assert_msg(tmp[0], "the test plugins could not be built");
    char path[512];
    path_of(path, sizeof path, "testball", ".so");
    int n = ms_plugin_count();
    ck_assert_int_eq(ms_plugin_load(path), MS_OK);
    ck_assert_int_eq(ms_plugin_count(), n + 1);
    /* the same name from another file; the first stays registered */
    assert_refused("testball_again", MS_ERR_PLUGIN, "already registered");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), path));
    /* the same file twice */
    MS_ASSERT_REFUSED(ms_plugin_load(path), MS_ERR_PLUGIN, "already registered");
    ck_assert(is_loaded(path));
    /* a name the build tree already has */
    assert_refused("fake_sphere", MS_ERR_PLUGIN, "\"sphere\"");
    /* the loaded test plugin works */
    ms_shape *s;
    ck_assert_int_eq(ms_shape_create("testball", NULL, &s), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0, 0, 3}, NULL), 2.0f, 1e-6f);
    ck_assert_str_eq(ms_shape_kind(s), "testball");
    ms_shape_destroy(s);
}
END_TEST

/* The engine's allocator, counting its blocks. */
static atomic_long hook_allocs, hook_frees;

static void *count_alloc(size_t size, size_t alignment, void *user)
{
    (void)user;
    atomic_fetch_add(&hook_allocs, 1);
    return aligned_alloc(alignment, size);
}

static void count_free(void *p, void *user)
{
    (void)user;
    atomic_fetch_add(&hook_frees, 1);
    free(p);
}

/* Blocks of the engine's allocator that one instance of a plugin shape
 * holds: created and destroyed through the plugin's own vtable (the
 * ms_shape handle around it is the library's). */
static long instance_blocks(const char *name)
{
    const ms_plugin_rec *rec;
    ck_assert_int_eq(ms_plugin_find("test", name, MS_PLUGIN_SHAPE, &rec), MS_OK);
    const long a0 = atomic_load(&hook_allocs), f0 = atomic_load(&hook_frees);
    void *self = NULL;
    char err[256];
    ck_assert_int_eq(rec->vt.shape.create(NULL, &self, err, sizeof err), MS_PLUGIN_OK);
    const long held = atomic_load(&hook_allocs) - a0;
    ck_assert_float_eq_tol(rec->vt.shape.distance(self, (float[3]){0, 0, 3}, NULL), 2.0f, 1e-6f);
    rec->vt.shape.destroy(self);
    ck_assert_int_eq(atomic_load(&hook_frees) - f0, held); /* all given back */
    return held;
}

/* ABI 1.1 added the host's allocator (ms_plugin_info.set_host): a plugin
 * built against 1.0 (its info ends at vtable, its instances from malloc)
 * still loads and works; one of 1.1 gets the host's allocator, which is
 * the engine's. */
START_TEST(a_plugin_of_abi_1_0_still_loads_and_one_of_1_1_allocates_through_the_host)
{
    ck_assert_msg(tmp[0], "the test plugins could not be built");
    ck_assert_int_eq(ms_set_allocator(count_alloc, count_free, NULL), MS_OK);
    char old[512], cur[512];
    path_of(old, sizeof old, "oldball", ".so");
    path_of(cur, sizeof cur, "testball", ".so");
    ck_assert_msg(ms_plugin_load(old) == MS_OK, "%s", ms_last_error());
    ck_assert_int_eq(ms_plugin_load(cur), MS_OK);
    int seen = 0;
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ck_assert_int_eq(ms_plugin_describe(i, &d), MS_OK);
        if (!strcmp(d.name, "oldball")) {
            ck_assert_uint_eq(d.abi, 1u << 16); /* 1.0 */
            ++seen;
        }
        if (!strcmp(d.name, "testball")) {
            ck_assert_uint_eq(d.abi, MS_PLUGIN_ABI);
            ++seen;
        }
    }
    ck_assert_int_eq(seen, 2);
    ck_assert_uint_eq(MS_PLUGIN_ABI, (1u << 16) | 1u);
    ms_shape *s;
    ck_assert_int_eq(ms_shape_create("oldball", NULL, &s), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0, 0, 3}, NULL), 2.0f, 1e-6f);
    ms_shape_destroy(s);
    ck_assert_int_eq(instance_blocks("oldball"), 0); /* malloc's, as 1.0 had it */
    ck_assert_int_eq(instance_blocks("testball"), 1);
}
END_TEST

START_TEST(unknown_kind_lists_the_kinds_available)
{
    ms_shape *s = (ms_shape *)&s;
    MS_ASSERT_REFUSED(ms_shape_create("teapot", NULL, &s), MS_ERR_PLUGIN, "\"teapot\"");
    ck_assert_ptr_null(s);
    const char *e = ms_last_error();
    ck_assert_msg(strstr(e, "available shapes: ") && strstr(e, "box") && strstr(e, "plane") &&
                      strstr(e, "sphere"),
                  "message \"%s\" does not list the shapes", e);
    MS_ASSERT_REFUSED(ms_shape_create(NULL, NULL, &s), MS_ERR_INVALID_ARGUMENT, "kind");
    MS_ASSERT_REFUSED(ms_shape_create("", NULL, &s), MS_ERR_INVALID_ARGUMENT, "empty");
    assert_usable(ms_plugin_count());
}
END_TEST

START_TEST(lists_the_shipped_plugins)
{
    int n = ms_plugin_count();
    ck_assert_int_ge(n, 3);
    const char *want[] = {"box", "plane", "sphere"};
    int found = 0;
    const char *prev_name = "";
    int prev_rank = 0;
    for (int i = 0; i < n; ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ck_assert_int_eq(ms_plugin_describe(i, &d), MS_OK);
        ck_assert(strcmp(d.kind, "shape") == 0 || strcmp(d.kind, "shader") == 0);
        ck_assert_int_gt(strlen(d.description), 5);
        ck_assert_int_gt(strlen(d.version), 0);
        ck_assert_uint_eq(d.abi >> 16, MS_PLUGIN_ABI_MAJOR);
        ck_assert_int_eq(access(d.path, R_OK), 0);
        /* sorted by kind (shapes, then shaders), then name */
        int rank = strcmp(d.kind, "shape") == 0 ? 0 : 1;
        ck_assert(rank > prev_rank || (rank == prev_rank && strcmp(prev_name, d.name) < 0));
        prev_rank = rank;
        prev_name = d.name;
        for (int k = 0; k < 3; ++k)
            found += strcmp(d.name, want[k]) == 0;
    }
    ck_assert_int_eq(found, 3);
    ms_plugin_description d = ms_plugin_description_init();
    MS_ASSERT_REFUSED(ms_plugin_describe(n, &d), MS_ERR_INVALID_ARGUMENT, "index");
    MS_ASSERT_REFUSED(ms_plugin_describe(-1, &d), MS_ERR_INVALID_ARGUMENT, "index");
    ck_assert_int_eq(ms_plugin_problem_count(), 0);
    ck_assert_ptr_null(ms_plugin_problem(0));
    ck_assert_ptr_nonnull(strstr(ms_plugin_search_path(), MS_BUILD_PLUGIN_DIR));
}
END_TEST

START_TEST(search_path_scan_skips_bad_files_and_earlier_names_win)
{
    ck_assert_msg(tmp[0], "the test plugins could not be built");
    char env[600];
    snprintf(env, sizeof env, "/nonexistent/dir::%s", tmp);
    setenv("MODESPLIT_PLUGIN_PATH", env, 1);
    ck_assert_ptr_nonnull(strstr(ms_plugin_search_path(), tmp));
    /* the missing directory, every bad file, the object file, the text
     * file, the second testball and the build tree's sphere (shadowed) are
     * problems; the first testball and the fake sphere load */
    ck_assert_int_eq(ms_plugin_problem_count(), 1 + N_BAD + 4);
    ck_assert_str_eq(ms_plugin_problem(0),
                     "plugin: directory /nonexistent/dir of MODESPLIT_PLUGIN_PATH does not exist");
    for (int i = 1; i < ms_plugin_problem_count(); ++i)
        ck_assert_ptr_nonnull(strstr(ms_plugin_problem(i), tmp));
    int testball = 0, sphere_from_tmp = 0, sphere_from_build = 0;
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ck_assert_int_eq(ms_plugin_describe(i, &d), MS_OK);
        testball += strcmp(d.name, "testball") == 0;
        if (strcmp(d.name, "sphere") == 0) {
            sphere_from_tmp += strstr(d.path, tmp) != NULL;
            sphere_from_build += strstr(d.path, MS_BUILD_PLUGIN_DIR) != NULL;
        }
    }
    ck_assert_int_eq(testball, 1);
    ck_assert_int_eq(sphere_from_tmp, 1); /* MODESPLIT_PLUGIN_PATH wins */
    ck_assert_int_eq(sphere_from_build, 0);
    int shadowed = 0;
    for (int i = 0; i < ms_plugin_problem_count(); ++i)
        shadowed += strstr(ms_plugin_problem(i), "shape_sphere.so") != NULL;
    ck_assert_int_eq(shadowed, 1);
    for (int i = 0; i < N_BAD; ++i) {
        char path[512];
        path_of(path, sizeof path, variants[i][0], ".so");
        ck_assert_msg(!is_loaded(path), "%s is still loaded", path);
    }
    /* the fake sphere (unit ball, ignores parameters) is what users get */
    ms_shape *s;
    ck_assert_int_eq(ms_shape_create("sphere", "{\"radius\": 5}", &s), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){3, 0, 0}, NULL), 2.0f, 1e-6f);
    ms_shape_destroy(s);
}
END_TEST

START_TEST(search_path_order)
{
    char *p = ms_plugin_compose_search_path("/a:/b::/c", "/usr/lib/libmodesplit.so.0",
                                            "/src/build/plugins");
    ck_assert_str_eq(p, "/a:/b:/c:/usr/lib/modesplit/plugins:/src/build/plugins");
    ms_free(p);
    p = ms_plugin_compose_search_path(NULL, "/opt/ms/bin/modesplit", NULL);
    ck_assert_str_eq(p, "/opt/ms/bin/../lib/modesplit/plugins");
    ms_free(p);
    p = ms_plugin_compose_search_path("", "/libmodesplit.so", "/b");
    ck_assert_str_eq(p, "/modesplit/plugins:/b");
    ms_free(p);
    p = ms_plugin_compose_search_path(NULL, NULL, NULL);
    ck_assert_str_eq(p, "");
    ms_free(p);
    /* this test is linked statically: the executable's ../lib */
    char *d = ms_plugin_default_search_path();
    ck_assert_ptr_nonnull(strstr(d, "/../lib/modesplit/plugins"));
    ck_assert_ptr_nonnull(strstr(d, MS_BUILD_PLUGIN_DIR));
    ms_free(d);
}
END_TEST

static void *create_in_thread(void *arg)
{
    ms_shape *s = NULL;
    *(ms_status *)arg = ms_shape_create(ms_plugin_count() > 0 ? "box" : "none", NULL, &s);
    ms_shape_destroy(s);
    return NULL;
}

START_TEST(first_use_from_many_threads_scans_once)
{
    pthread_t t[8];
    ms_status st[8];
    for (int i = 0; i < 8; ++i)
        pthread_create(&t[i], NULL, create_in_thread, &st[i]);
    for (int i = 0; i < 8; ++i) {
        pthread_join(t[i], NULL);
        ck_assert_int_eq(st[i], MS_OK);
    }
    int boxes = 0;
    for (int i = 0; i < ms_plugin_count(); ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        ms_plugin_describe(i, &d);
        boxes += strcmp(d.name, "box") == 0;
    }
    ck_assert_int_eq(boxes, 1);
}
END_TEST

/* Reads a whole small file into buf. */
static void slurp(const char *path, char *buf, size_t n)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    size_t got = fread(buf, 1, n - 1, f);
    buf[got] = '\0';
    fclose(f);
}

/* make install into a temporary prefix; a plugin written outside the tree
 * is built against the installed headers found by pkg-config, and a program
 * linked against the installed shared library finds the installed plugins
 * (dladdr) and, through MODESPLIT_PLUGIN_PATH, the new one. */
START_TEST(out_of_tree_plugin_builds_against_installed_headers)
{
    char dir[] = "/tmp/ms_test_install_XXXXXX", cwd[1024], cmd[4096];
    ck_assert_ptr_nonnull(mkdtemp(dir));
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    const char *build = getenv("MS_TEST_BUILD") ? getenv("MS_TEST_BUILD") : "build";
    const char *san = getenv("MS_TEST_SAN") ? getenv("MS_TEST_SAN") : "";
    const char *sanflags = strcmp(san, "asan") == 0   ? "-fsanitize=address,undefined"
                           : strcmp(san, "tsan") == 0 ? "-fsanitize=thread"
                                                      : "";
    const char *cc = getenv("CC") ? getenv("CC") : "cc";
    snprintf(cmd, sizeof cmd,
             "set -e; cd '%s'; env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make -s install "
             "PREFIX='%s/prefix' BUILD='%s' SAN='%s' > '%s/install.log' 2>&1; "
             "mkdir '%s/plugins'; cp tests/plugins/torus.c tests/plugins/host.c '%s/'; "
             "cd '%s'; export PKG_CONFIG_PATH='%s/prefix/lib/pkgconfig'; "
             "%s -std=c11 -Wall -Wextra -Werror -shared -fPIC $(pkg-config --cflags modesplit) "
             "torus.c -o plugins/torus.so -lm; "
             "%s -std=c11 -Wall -Werror %s $(pkg-config --cflags modesplit) host.c -o host "
             "$(pkg-config --libs modesplit) -Wl,-rpath,'%s/prefix/lib'; "
             "env -u MODESPLIT_PLUGIN_PATH ./host > installed.txt; "
             "MODESPLIT_PLUGIN_PATH='%s/plugins' ./host > env.txt",
             cwd, dir, build, san, dir, dir, dir, dir, dir, cc, cc, sanflags, dir, dir);
    int rc = system(cmd);
    char out[8192], path[600], want[700];
    if (rc != 0) {
        snprintf(path, sizeof path, "%s/install.log", dir);
        slurp(path, out, sizeof out);
    }
    ck_assert_msg(rc == 0, "install/build failed (%d): %s", rc, rc ? out : "");
    /* installed program, no MODESPLIT_PLUGIN_PATH: the install's plugins,
     * and not the build tree's (it is not the installed code's) */
    snprintf(path, sizeof path, "%s/installed.txt", dir);
    slurp(path, out, sizeof out);
    snprintf(want, sizeof want, "path %s/prefix/lib/modesplit/plugins\n", dir);
    ck_assert_msg(strstr(out, want), "%s lacks \"%s\"", out, want);
    ck_assert_msg(!strstr(out, MS_BUILD_PLUGIN_DIR), "%s searches the build tree", out);
    snprintf(want, sizeof want, "plugin sphere %s/prefix/lib/modesplit/plugins/shape_sphere.so",
             dir);
    ck_assert_msg(strstr(out, want), "%s lacks \"%s\"", out, want);
    ck_assert_ptr_nonnull(strstr(out, "error shape: no shape plugin named \"torus\""));
    /* with the plugin's directory on MODESPLIT_PLUGIN_PATH */
    snprintf(path, sizeof path, "%s/env.txt", dir);
    slurp(path, out, sizeof out);
    ck_assert_msg(strstr(out, "torus 0.400000"), "%s", out);
    /* and loaded explicitly into this (static) program */
    snprintf(path, sizeof path, "%s/plugins/torus.so", dir);
    ck_assert_int_eq(ms_plugin_load(path), MS_OK);
    ms_shape *s;
    ck_assert_int_eq(ms_shape_create("torus", "{\"major\": 0.5, \"minor\": 0.2}", &s), MS_OK);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0, 0.5f, 0.3f}, NULL), 0.1f, 1e-6f);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0.9f, 0, 0}, NULL), 0.2f, 1e-6f);
    ck_assert_float_eq_tol(ms_shape_distance(s, (float[3]){0.5f, 0, 0}, NULL), -0.2f, 1e-6f);
    ms_shape_destroy(s);
    MS_ASSERT_REFUSED(ms_shape_create("torus", "{\"major\": 0.1, \"minor\": 0.2}", &s),
                      MS_ERR_INVALID_ARGUMENT, "minor 0.2 m");
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    ck_assert_int_eq(system(cmd), 0);
}
END_TEST

static Suite *plugin_suite(void)
{
    Suite *s = suite_create("plugin");
    TCase *tc = tcase_create("loader");
    tcase_set_timeout(tc, 60);
    tcase_add_unchecked_fixture(tc, build_plugins, remove_plugins);
    tcase_add_test(tc, refuses_a_file_that_is_not_elf);
    tcase_add_test(tc, refuses_an_elf_file_that_is_not_shared);
    tcase_add_test(tc, refuses_a_missing_file);
    tcase_add_test(tc, refuses_a_library_without_the_entry_symbol);
    tcase_add_test(tc, refuses_another_abi_major);
    tcase_add_test(tc, refuses_a_newer_abi_minor);
    tcase_add_test(tc, refuses_a_zero_size_info);
    tcase_add_test(tc, refuses_a_truncated_info);
    tcase_add_test(tc, refuses_a_null_info);
    tcase_add_test(tc, refuses_an_unknown_plugin_kind);
    tcase_add_test(tc, refuses_an_invalid_name);
    tcase_add_test(tc, refuses_a_missing_vtable);
    tcase_add_test(tc, refuses_a_truncated_vtable);
    tcase_add_test(tc, refuses_a_vtable_without_distance);
    tcase_add_test(tc, refuses_a_duplicate_name);
    tcase_add_test(tc, search_path_scan_skips_bad_files_and_earlier_names_win);
    tcase_add_test(tc, a_plugin_of_abi_1_0_still_loads_and_one_of_1_1_allocates_through_the_host);
    suite_add_tcase(s, tc);
    TCase *reg = tcase_create("registry");
    tcase_set_timeout(reg, 30);
    tcase_add_test(reg, unknown_kind_lists_the_kinds_available);
    tcase_add_test(reg, lists_the_shipped_plugins);
    tcase_add_test(reg, search_path_order);
    tcase_add_test(reg, first_use_from_many_threads_scans_once);
    suite_add_tcase(s, reg);
    TCase *inst = tcase_create("install");
    tcase_set_timeout(inst, 120);
    tcase_add_test(inst, out_of_tree_plugin_builds_against_installed_headers);
    suite_add_tcase(s, inst);
    return s;
}

int main(void)
{
    /* the scan must see only the build tree unless a test says otherwise */
    unsetenv("MODESPLIT_PLUGIN_PATH");
    return ms_test_run(plugin_suite());
}
