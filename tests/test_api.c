/* The engine-facing promises of the API that are not one part's physics:
 * a step known to be impossible is refused before any work, a step in
 * progress can be canceled from another thread, and a sim caught being
 * stepped by two callers at once refuses the second. */
/* this suite calls the deprecated names on purpose, to keep them working */
#define MS_NO_DEPRECATION_WARNINGS 1
#include <check.h>
#include <hdf5.h>
#include <png.h>
#include <pthread.h>
#include <string.h>
#include <time.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "render/render_internal.h"
#include "support.h"

static ms_volume *dam(float courant, int max_substeps)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.courant = courant;
    d.max_substeps = max_substeps;
    ms_volume *v = NULL;
    ck_assert_int_eq(ms_volume_create(&d, &v), MS_OK);
    ck_assert_int_eq(ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.3f, 1, 0.5f}), MS_OK);
    return v;
}

START_TEST(a_step_known_to_need_too_many_substeps_is_refused_at_once)
{
    /* courant 1e-30 is in range, and needs ~1e30 sub-steps a frame: the
     * CFL bound at rest already says so, before any sub-step is taken */
    ms_volume *v = dam(1e-30f, 100000);
    MS_ASSERT_REFUSED(ms_volume_step(v, 1.0f / 60), MS_ERR_UNSTABLE, "at least");
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "max_substeps 100000"));
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert_int_eq(in.substeps, 0); /* refused before any work */
    ms_volume_destroy(v);
    /* an ordinary step is still taken in full */
    v = dam(0.4f, 100000);
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK);
    ms_volume_destroy(v);
}
END_TEST

typedef struct stepper {
    ms_volume *v;
    float dt;
    ms_status st;
} stepper;

static void *step_thread(void *arg)
{
    stepper *s = arg;
    s->st = ms_volume_step(s->v, s->dt);
    return NULL;
}

START_TEST(a_step_in_progress_can_be_canceled)
{
    /* a request made between steps stops the next one at once */
    ms_volume *v = dam(0.4f, 10000000);
    ms_volume_cancel(v);
    MS_ASSERT_REFUSED(ms_volume_step(v, 1.0f / 60), MS_ERR_CANCELED, "canceled after 0");
    ck_assert_int_eq(ms_volume_step(v, 1.0f / 60), MS_OK); /* the request is used up */
    /* from another thread, during a 10 s hitch (thousands of sub-steps) */
    stepper s = {.v = v, .dt = 10.0f, .st = MS_OK};
    pthread_t t;
    ck_assert_int_eq(pthread_create(&t, NULL, step_thread, &s), 0);
    struct timespec ts = {0, 50 * 1000 * 1000};
    nanosleep(&ts, NULL);
    ms_volume_cancel(v);
    pthread_join(t, NULL);
    ck_assert_int_eq(s.st, MS_ERR_CANCELED);
    ms_volume_info in = ms_volume_info_init();
    ms_volume_get_info(v, &in);
    ck_assert(in.time < 10.0); /* stopped part-way, at a valid state */
    ck_assert(ms_volume_kinetic_energy(v) == ms_volume_kinetic_energy(v)); /* finite */
    ms_volume_destroy(v);

    ms_surface_desc d = ms_surface_desc_default();
    ms_surface *w = NULL;
    ck_assert_int_eq(ms_surface_create(&d, &w), MS_OK);
    ms_surface_cancel(w);
    MS_ASSERT_REFUSED(ms_surface_step(w, 1.0f / 60), MS_ERR_CANCELED, "canceled");
    ck_assert_int_eq(ms_surface_step(w, 1.0f / 60), MS_OK);
    ms_surface_destroy(w);
}
END_TEST

/* An engine whose enqueue (wrongly) steps the same sim again. */
typedef struct reentry {
    ms_sim *sim;
    ms_status st;
    int calls;
} reentry;

static void *reenter(ms_task_fn *task, void *task_context, void *user)
{
    reentry *r = user;
    r->st = ms_sim_step(r->sim, 1.0f / 60);
    r->calls++;
    task(task_context); /* then run the task inline: NULL handle */
    return NULL;
}

static void finish_nothing(void *task, void *user)
{
    (void)task;
    (void)user;
}

START_TEST(a_sim_stepped_from_two_callers_refuses_the_second)
{
    ms_volume_desc vd = ms_volume_desc_default();
    ms_surface_desc sd = ms_surface_desc_default();
    sd.nx = sd.ny = 64;
    sd.dx = 1.0f / 64;
    ms_sim_desc d = ms_sim_desc_default();
    d.volume = &vd;
    d.surface = &sd;
    d.threads = 2;
    reentry r = {NULL, MS_OK, 0};
    d.enqueue_task = reenter;
    d.finish_task = finish_nothing;
    d.user_task_context = &r;
    ck_assert_int_eq(ms_sim_create(&d, &r.sim), MS_OK);
    ck_assert_int_eq(ms_sim_step(r.sim, 1.0f / 60), MS_OK);
    ck_assert_int_ge(r.calls, 1);
    ck_assert_int_eq(r.st, MS_ERR_STATE);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "one thread at a time"));
    /* the first caller's step was not disturbed: the next one runs */
    ck_assert_int_eq(ms_sim_step(r.sim, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_sim_frame(r.sim), 2);
    ms_sim_destroy(r.sim);
}
END_TEST

START_TEST(a_canceled_sim_fails_and_keeps_its_views)
{
    ms_surface_desc sd = ms_surface_desc_default();
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &sd;
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ms_sim_cancel(sim);
    MS_ASSERT_REFUSED(ms_sim_step(sim, 1.0f / 60), MS_ERR_CANCELED, "canceled");
    MS_ASSERT_REFUSED(ms_sim_step(sim, 1.0f / 60), MS_ERR_STATE, "failed");
    int nx, ny;
    ck_assert_ptr_nonnull(ms_sim_height(sim, &nx, &ny));
    ck_assert_int_eq(nx, 256);
    ms_sim_destroy(sim);
}
END_TEST

/* The old names still do what they did, for one release. */
START_TEST(deprecated_names_still_work)
{
    ms_surface_desc sd = ms_surface_desc_default();
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &sd;
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ms_stats a = ms_stats_init(), b = ms_stats_init();
    ms_sim_stats(sim, &a);
    ms_sim_get_stats(sim, &b);
    ck_assert_int_eq(a.frames, 1);
    ck_assert_int_eq(a.surface_steps, b.surface_steps);
    ms_sim_destroy(sim);

    const char *text = "{\"surface\": {}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(text, strlen(text), &sc), MS_OK);
    ms_renderer *r = NULL;
    MS_ASSERT_REFUSED(ms_renderer_create(sc, &r), MS_ERR_INVALID_ARGUMENT, "no \"render\"");
    MS_ASSERT_REFUSED(ms_renderer_create_from_scene(sc, &r), MS_ERR_INVALID_ARGUMENT,
                      "no \"render\"");
    ms_scene_destroy(sc);
    ms_render_stats rs = ms_render_stats_init();
    rs.frames = 3;
    ms_renderer_stats(NULL, &rs);
    ck_assert_int_eq(rs.frames, 0);
}
END_TEST

/* A PNG of a signature, an IHDR declaring w x h RGBA8 and an IEND: a few
 * dozen bytes that ask a careless reader for w * h * 4 bytes. */
static uint32_t crc32_of(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k)
            c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void write_png_header(const char *path, uint32_t w, uint32_t h)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[4 + 4 + 13 + 4], iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D'};
    unsigned char idat[12] = {0, 0, 0, 0, 'I', 'D', 'A', 'T'}; /* empty: never decoded */
    put32(ihdr, 13);
    memcpy(ihdr + 4, "IHDR", 4);
    put32(ihdr + 8, w);
    put32(ihdr + 12, h);
    ihdr[16] = 8; /* bit depth */
    ihdr[17] = 6; /* RGBA */
    ihdr[18] = ihdr[19] = ihdr[20] = 0;
    put32(ihdr + 21, crc32_of(ihdr + 4, 17));
    put32(iend + 8, crc32_of(iend + 4, 4));
    put32(idat + 8, crc32_of(idat + 4, 4));
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    fwrite(sig, 1, sizeof sig, f);
    fwrite(ihdr, 1, sizeof ihdr, f);
    fwrite(idat, 1, sizeof idat, f);
    fwrite(iend, 1, sizeof iend, f);
    fclose(f);
}

START_TEST(a_cubemap_png_is_refused_by_its_header_before_decoding)
{
    char dir[] = "/tmp/ms_api_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char path[256];
    ms_cubemap cm;
    long before = ms_alloc_count();
    /* a face folder whose first face declares 24576 x 24576 (2.4 GB) */
    snprintf(path, sizeof path, "%s/px.png", dir);
    write_png_header(path, 24576, 24576);
    for (int f = 1; f < 6; ++f) {
        static const char *const names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
        char other[256];
        snprintf(other, sizeof other, "%s/%s.png", dir, names[f]);
        write_png_header(other, 16, 16);
    }
    MS_ASSERT_REFUSED(ms_cubemap_load(dir, &cm), MS_ERR_INVALID_ARGUMENT, "24576 x 24576");
    /* a strip 24576 wide: within six faces' height, but each face too big */
    char strip[256];
    snprintf(strip, sizeof strip, "%s/strip.png", dir);
    write_png_header(strip, 24576, 6 * 24576);
    MS_ASSERT_REFUSED(ms_cubemap_load(strip, &cm), MS_ERR_INVALID_ARGUMENT, "at most 4096");
    ck_assert_int_eq(ms_alloc_count(), before); /* nothing was decoded */
    const char *const names[7] = {"px", "nx", "py", "ny", "pz", "nz", "strip"};
    for (int f = 0; f < 7; ++f) {
        snprintf(path, sizeof path, "%s/%s.png", dir, names[f]);
        unlink(path);
    }
    rmdir(dir);
}
END_TEST

/* A FIFO named *.so in a plugin folder: neither ms_plugin_load nor the
 * folder scan opens it for reading (which would block until a writer
 * came); it is refused as not a regular file. */
START_TEST(a_fifo_in_a_plugin_folder_does_not_block_the_scan)
{
    char dir[] = "/tmp/ms_api_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char fifo[256];
    snprintf(fifo, sizeof fifo, "%s/shape_fifo.so", dir);
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    setenv("MODESPLIT_PLUGIN_PATH", dir, 1);
    ck_assert_int_gt(ms_plugin_count(), 0); /* the build's plugins, after ours */
    int found = 0;
    for (int i = 0; i < ms_plugin_problem_count(); ++i)
        found |= strstr(ms_plugin_problem(i), "shape_fifo.so is not a regular file") != NULL;
    ck_assert_msg(found, "the scan did not report the FIFO");
    MS_ASSERT_REFUSED(ms_plugin_load(fifo), MS_ERR_PLUGIN, "not a regular file");
    unlink(fifo);
    rmdir(dir);
}
END_TEST

/* Rain's work per frame is bounded: a top rate over a large grid is
 * refused with the bound, not drawn as ~1e12 drops a frame. */
START_TEST(rain_over_a_large_grid_is_bounded)
{
    ms_surface_desc d = ms_surface_desc_default();
    d.nx = d.ny = 4096;
    d.dx = 1.0f; /* 4 km x 4 km */
    ms_surface *s = NULL;
    ck_assert_int_eq(ms_surface_create(&d, &s), MS_OK);
    ms_rain r = ms_rain_default();
    r.rate = 1e6f;
    MS_ASSERT_REFUSED(ms_surface_set_rain(s, &r), MS_ERR_INVALID_ARGUMENT, "at most 100000");
    r.rate = 1e-3f; /* 1.7e4 drops a second: allowed */
    ck_assert_int_eq(ms_surface_set_rain(s, &r), MS_OK);
    ms_surface_destroy(s);
}
END_TEST

/* A run file whose scene name carries terminal escapes and whose dx is a
 * denormal: `modesplit info` prints the escapes as text, and the reader
 * refuses the denormal grid (it would be a 0 mm grid as a float). */
START_TEST(a_hostile_run_file_is_printed_as_text_and_its_denormal_dx_refused)
{
    char dir[] = "/tmp/ms_api_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char path[256];
    snprintf(path, sizeof path, "%s/run.h5", dir);
    ms_surface_desc sd = ms_surface_desc_default();
    sd.nx = sd.ny = 16;
    ms_sim_desc d = ms_sim_desc_default();
    d.surface = &sd;
    ms_sim *sim = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &sim), MS_OK);
    ms_writer *w = NULL;
    ck_assert_int_eq(ms_writer_open(path, sim, MS_FIELD_COMBINED, &w), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_writer_frame(w, sim), MS_OK);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_sim_destroy(sim);

    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    const char *evil = "pool\x1b]0;owned\x07\x1b[2J";
    hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, H5T_VARIABLE);
    if (H5Aexists(f, "scene_name") > 0)
        H5Adelete(f, "scene_name");
    hid_t sp = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(f, "scene_name", t, sp, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(H5Awrite(a, t, &evil), 0);
    H5Aclose(a);
    H5Sclose(sp);
    H5Tclose(t);
    H5Fclose(f);

    char cmd[1024], out[256];
    snprintf(out, sizeof out, "%s/info.txt", dir);
    snprintf(cmd, sizeof cmd, "%s/bin/modesplit info %s > %s 2>&1",
             getenv("MS_TEST_BUILD") ? getenv("MS_TEST_BUILD") : "build", path, out);
    int rc = system(cmd);
    (void)rc;
    FILE *in = fopen(out, "rb");
    ck_assert_ptr_nonnull(in);
    char text[4096];
    size_t n = fread(text, 1, sizeof text - 1, in);
    fclose(in);
    text[n] = '\0';
    ck_assert_msg(strchr(text, 0x1b) == NULL && strchr(text, 0x07) == NULL,
                  "info printed raw control characters: %s", text);
    ck_assert_msg(strstr(text, "pool\\x1b]0;owned\\x07") != NULL, "%s", text);

    f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    hid_t ds = H5Dopen2(f, "/fields/combined", H5P_DEFAULT);
    a = H5Aopen(ds, "dx", H5P_DEFAULT);
    const double tiny[2] = {1e-40, 1e-40};
    ck_assert_int_ge(H5Awrite(a, H5T_NATIVE_DOUBLE, tiny), 0);
    H5Aclose(a);
    H5Dclose(ds);
    H5Fclose(f);

    ms_reader *r = NULL;
    ms_grid g;
    ms_status st = ms_reader_open(path, &r);
    if (st == MS_OK) {
        MS_ASSERT_REFUSED(ms_reader_field_grid(r, MS_FIELD_COMBINED, &g), MS_ERR_PARSE, "dx");
        ms_reader_close(r);
    } else {
        ck_assert_int_eq(st, MS_ERR_PARSE);
        ck_assert_ptr_nonnull(strstr(ms_last_error(), "dx"));
    }
    ms_test_remove_tree(dir); /* run.h5, both sidecars, info.txt */
}
END_TEST

/* A terrain's "png" in a scene file is found beside the scene file, from
 * any working directory (as the scenes README says, and as cubemaps are). */
START_TEST(a_terrain_png_is_relative_to_the_scene_file)
{
    char dir[] = "/tmp/ms_api_XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char png[256], json[256];
    snprintf(png, sizeof png, "%s/ground.png", dir);
    unsigned char grey[16] = {0,  40,  80,  120, 40,  80,  120, 160,
                              80, 120, 160, 200, 120, 160, 200, 255};
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = img.height = 4;
    img.format = PNG_FORMAT_GRAY;
    ck_assert(png_image_write_to_file(&img, png, 0, grey, 0, NULL));
    snprintf(json, sizeof json, "%s/pond.json", dir);
    FILE *f = fopen(json, "w");
    ck_assert_ptr_nonnull(f);
    fputs("{\"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
          " \"surface\": {\"cells\": [32, 32]},"
          " \"obstacles\": [{\"shape\": \"terrain\", \"params\": {\"png\": \"ground.png\","
          " \"size\": [1, 1], \"height_range\": [0, 0.05]}}]}",
          f);
    fclose(f);
    ck_assert_int_eq(chdir("/"), 0); /* anywhere but the scene's folder */
    ms_scene *sc = NULL;
    ms_status st = ms_scene_load(json, &sc);
    ck_assert_msg(st == MS_OK, "%s", ms_last_error());
    ms_scene_destroy(sc);
    unlink(png);
    unlink(json);
    rmdir(dir);
}
END_TEST

/* A scripted drop that would be refused when it falls (at t = 100 s) is
 * refused when the sim is made, so `modesplit check` sees it. */
START_TEST(a_late_drop_too_large_is_refused_at_load)
{
    const char *text = "{\"domain\": {\"min\": [0, 0, 0], \"max\": [1, 1, 0.5]},"
                       " \"surface\": {\"cells\": [32, 32]},"
                       " \"effects\": {\"drops\": [{\"at\": [0.5, 0.5], \"time\": 100,"
                       " \"radius\": 5}]}}";
    ms_scene *sc = NULL;
    ck_assert_int_eq(ms_scene_parse(text, strlen(text), &sc), MS_OK);
    ms_sim *sim = NULL;
    MS_ASSERT_REFUSED(ms_sim_create_from_scene(sc, 1, &sim), MS_ERR_INVALID_ARGUMENT, "radius 5 m");
    ck_assert_ptr_null(sim);
    ms_scene_destroy(sc);
}
END_TEST

static Suite *api_suite(void)
{
    Suite *s = suite_create("api");
    TCase *tc = tcase_create("api");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, a_step_known_to_need_too_many_substeps_is_refused_at_once);
    tcase_add_test(tc, a_step_in_progress_can_be_canceled);
    tcase_add_test(tc, a_sim_stepped_from_two_callers_refuses_the_second);
    tcase_add_test(tc, a_canceled_sim_fails_and_keeps_its_views);
    tcase_add_test(tc, deprecated_names_still_work);
    tcase_add_test(tc, a_cubemap_png_is_refused_by_its_header_before_decoding);
    tcase_add_test(tc, a_fifo_in_a_plugin_folder_does_not_block_the_scan);
    tcase_add_test(tc, rain_over_a_large_grid_is_bounded);
    tcase_add_test(tc, a_hostile_run_file_is_printed_as_text_and_its_denormal_dx_refused);
    tcase_add_test(tc, a_terrain_png_is_relative_to_the_scene_file);
    tcase_add_test(tc, a_late_drop_too_large_is_refused_at_load);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(api_suite());
}
