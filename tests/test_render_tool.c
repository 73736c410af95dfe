/* The renderer's commands of the `modesplit` tool: `render RUN.h5`
 * re-renders a finished run's frames with another shader, size or camera
 * without simulating again (PNG frames, or a video through ffmpeg when it
 * is installed), and `cubemap --out DIR` writes the builtin sky as six
 * faces a renderer loads. Every bad argument is refused with exit status 2
 * and a sentence naming it. */
#include <check.h>
#include <fcntl.h>
#include <png.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "modesplit/modesplit.h"
#include "support.h"

#define SMALL_SCENE "tests/data/small_run.json" /* fast: 64x48 waves, no render section */

static char tmp_dir[256];

static void make_tmp_dir(void)
{
    ck_assert_int_eq(ms_test_tmp_dir(tmp_dir, sizeof tmp_dir, "ms_rtool"), 0);
}

static void remove_tmp_dir(void)
{
    ms_test_remove_tree(tmp_dir);
}

typedef struct result {
    int status; /* exit status, -1 if it did not exit */
    char *err;
} result;

/* Runs the tool with args (NULL-terminated), stderr kept. */
static result run_tool(const char *const *args)
{
    char err[512];
    snprintf(err, sizeof err, "%s/stderr.txt", tmp_dir);
    int status = ms_test_run_tool(args, NULL, err);
    result r = {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ms_test_slurp(err)};
    return r;
}

#define ASSERT_TOOL(args, code, word)                                                          \
    do {                                                                                       \
        result r_ = run_tool(args);                                                            \
        ck_assert_msg(r_.status == (code), "exit %d, expected %d; stderr: %s", r_.status,       \
                      (code), r_.err);                                                         \
        ck_assert_msg(strstr(r_.err, (word)) != NULL, "stderr \"%s\" lacks \"%s\"", r_.err,    \
                      (word));                                                                 \
        free(r_.err);                                                                          \
    } while (0)

static void png_size(const char *path, int *w, int *h)
{
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    ck_assert_msg(png_image_begin_read_from_file(&img, path), "%s: %s", path, img.message);
    *w = (int)img.width, *h = (int)img.height;
    png_image_free(&img);
}

/* A run of SMALL_SCENE (no render section) of 3 frames. */
static void make_run(const char *run)
{
    const char *args[] = {"run", SMALL_SCENE, "--frames", "3", "--out", run, "--quiet", NULL};
    result r = run_tool(args);
    ck_assert_msg(r.status == 0, "run failed: %s", r.err);
    free(r.err);
}

START_TEST(render_draws_a_finished_run_again)
{
    if (!MS_HAVE_GL)
        MS_SKIP("built without OSMesa and EGL: nothing can draw");
    make_tmp_dir();
    char run[300], dir[300], png[320];
    snprintf(run, sizeof run, "%s/run.h5", tmp_dir);
    snprintf(dir, sizeof dir, "%s/frames", tmp_dir);
    make_run(run);
    const char *args[] = {"render", run,        "--shader", "milk",  "--size", "64x48",
                          "--frames", "1:2",    "--camera", "0.6,-0.8,1.2,0.6,0.45,0.1,40",
                          "--png",  dir,        NULL};
    result r = run_tool(args);
    ck_assert_msg(r.status == 0, "render failed: %s", r.err);
    free(r.err);
    int w = 0, h = 0;
    snprintf(png, sizeof png, "%s/frame_00001.png", dir);
    png_size(png, &w, &h);
    ck_assert_int_eq(w, 64);
    ck_assert_int_eq(h, 48);
    snprintf(png, sizeof png, "%s/frame_00002.png", dir);
    png_size(png, &w, &h);
    snprintf(png, sizeof png, "%s/frame_00000.png", dir);
    ck_assert_int_ne(access(png, F_OK), 0); /* only the frames asked for */
    remove_tmp_dir();
}
END_TEST

START_TEST(render_pipes_a_video_to_ffmpeg_or_says_it_is_missing)
{
    if (!MS_HAVE_GL)
        MS_SKIP("built without OSMesa and EGL: nothing can draw");
    make_tmp_dir();
    char run[300], mp4[300];
    snprintf(run, sizeof run, "%s/run.h5", tmp_dir);
    snprintf(mp4, sizeof mp4, "%s/run.mp4", tmp_dir);
    make_run(run);
    const char *args[] = {"render", run, "--size", "64x64", "--video", mp4, NULL};
    if (system("command -v ffmpeg >/dev/null 2>&1") != 0) {
        ASSERT_TOOL(args, 2, "ffmpeg, which is not installed");
        remove_tmp_dir();
        MS_SKIP("ffmpeg is not installed: the video itself is not made here");
    }
    result r = run_tool(args);
    ck_assert_msg(r.status == 0, "render --video failed: %s", r.err);
    free(r.err);
    struct stat sb;
    ck_assert_int_eq(stat(mp4, &sb), 0);
    ck_assert_int_gt(sb.st_size, 100);
    remove_tmp_dir();
}
END_TEST

START_TEST(render_refuses_bad_arguments_naming_them)
{
    make_tmp_dir();
    char run[300], dir[300];
    snprintf(run, sizeof run, "%s/run.h5", tmp_dir);
    snprintf(dir, sizeof dir, "%s/frames", tmp_dir);
    const char *none[] = {"render", NULL};
    ASSERT_TOOL(none, 2, "which run file");
    const char *nowhere[] = {"render", "x.h5", NULL};
    ASSERT_TOOL(nowhere, 2, "--png DIR");
    const char *missing[] = {"render", "/nonexistent/x.h5", "--png", dir, NULL};
    ASSERT_TOOL(missing, 2, "/nonexistent/x.h5");
    const char *size[] = {"render", "x.h5", "--size", "8x8", "--png", dir, NULL};
    ASSERT_TOOL(size, 2, "--size 8x8");
    const char *frames[] = {"render", "x.h5", "--frames", "5:1", "--png", dir, NULL};
    ASSERT_TOOL(frames, 2, "--frames 5:1");
    const char *camera[] = {"render", "x.h5", "--camera", "1,2,3", "--png", dir, NULL};
    ASSERT_TOOL(camera, 2, "--camera 1,2,3");
    const char *opt[] = {"render", "x.h5", "--shiny", NULL};
    ASSERT_TOOL(opt, 2, "--shiny");
    make_run(run);
    const char *beyond[] = {"render", run, "--frames", "7:9", "--png", dir, NULL};
    ASSERT_TOOL(beyond, 2, "holds 3 frames");
    const char *shader[] = {"render", run, "--shader", "lava", "--png", dir, NULL};
    if (MS_HAVE_GL)
        ASSERT_TOOL(shader, 2, "lava");
    else /* nothing can draw: said before the shader is looked at */
        ASSERT_TOOL(shader, 1, "no OpenGL");
    remove_tmp_dir();
}
END_TEST

START_TEST(cubemap_writes_six_faces_a_renderer_loads)
{
    make_tmp_dir();
    char dir[300], face[320];
    snprintf(dir, sizeof dir, "%s/sky/evening", tmp_dir); /* parents made too */
    const char *args[] = {"cubemap", "--out", dir, "--size", "32", "--sun", "0.2,0.9,-0.4",
                          NULL};
    result r = run_tool(args);
    ck_assert_msg(r.status == 0, "cubemap failed: %s", r.err);
    free(r.err);
    static const char *const names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (int f = 0; f < 6; ++f) {
        int w = 0, h = 0;
        snprintf(face, sizeof face, "%s/%s.png", dir, names[f]);
        png_size(face, &w, &h);
        ck_assert_int_eq(w, 32);
        ck_assert_int_eq(h, 32);
    }
    if (MS_HAVE_GL) {
        ms_renderer_desc d = ms_renderer_desc_default();
        d.width = d.height = 32;
        d.cubemap = dir;
        ms_renderer *rd = NULL;
        ck_assert_msg(ms_renderer_create_desc(&d, &rd) == MS_OK, "%s", ms_last_error());
        ms_renderer_destroy(rd);
    }
    const char *small[] = {"cubemap", "--out", dir, "--size", "8", NULL};
    ASSERT_TOOL(small, 2, "--size 8");
    const char *zero[] = {"cubemap", "--out", dir, "--sun", "0,0,0", NULL};
    ASSERT_TOOL(zero, 2, "--sun 0,0,0");
    const char *noout[] = {"cubemap", NULL};
    ASSERT_TOOL(noout, 2, "--out DIR");
    snprintf(face, sizeof face, "%s/px.png/inside", dir); /* under a file */
    const char *blocked[] = {"cubemap", "--out", face, NULL};
    ASSERT_TOOL(blocked, 1, "cannot create");
    MS_ASSERT_REFUSED(ms_sky_write_cubemap(dir, 8, (const float[3]){0, 0, -1}),
                      MS_ERR_INVALID_ARGUMENT, "size");
    MS_ASSERT_REFUSED(ms_sky_write_cubemap(NULL, 32, (const float[3]){0, 0, -1}),
                      MS_ERR_INVALID_ARGUMENT, "dir");
    remove_tmp_dir();
}
END_TEST

static Suite *render_tool_suite(void)
{
    Suite *s = suite_create("render_tool");
    TCase *tc = tcase_create("render_tool");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, render_draws_a_finished_run_again);
    tcase_add_test(tc, render_pipes_a_video_to_ffmpeg_or_says_it_is_missing);
    tcase_add_test(tc, render_refuses_bad_arguments_naming_them);
    tcase_add_test(tc, cubemap_writes_six_faces_a_renderer_loads);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(render_tool_suite());
}
