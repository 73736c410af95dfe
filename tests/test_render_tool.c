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
#include <time.h>
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

#define ASSERT_TOOL(args, code, word)                                                             \
    do {                                                                                          \
        result r_ = run_tool(args);                                                               \
        ck_assert_msg(r_.status == (code), "exit %d, expected %d; stderr: %s", r_.status, (code), \
                      r_.err);                                                                    \
        ck_assert_msg(strstr(r_.err, (word)) != NULL, "stderr \"%s\" lacks \"%s\"", r_.err,       \
                      (word));                                                                    \
        free(r_.err);                                                                             \
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
    const char *args[] = {
        "render", run,        "--shader", "milk",     "--size",
        "64x48",  "--frames", "1:2",      "--camera", "0.6,-0.8,1.2,0.6,0.45,0.1,40",
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
    /* a name with quotes and a command in it is a name: ffmpeg is started
     * without a shell, so the video lands there and nothing runs */
    /* (a shell would run touch in the tool's directory, this one) */
    char odd[600];
    const char *pwned = "PWNED_by_render_video";
    snprintf(odd, sizeof odd, "%s/a'; touch %s; echo '$(touch %s).mp4", tmp_dir, pwned, pwned);
    const char *hostile[] = {"render", run, "--size", "64x64", "--video", odd, NULL};
    r = run_tool(hostile);
    ck_assert_msg(r.status == 0, "render --video failed: %s", r.err);
    free(r.err);
    ck_assert_int_eq(stat(odd, &sb), 0);
    ck_assert_int_gt(sb.st_size, 100);
    ck_assert_int_ne(stat(pwned, &sb), 0);
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
    const char *args[] = {"cubemap", "--out", dir, "--size", "32", "--sun", "0.2,0.9,-0.4", NULL};
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

/* The bytes of a file (*n of them); NULL if it cannot be read. */
static unsigned char *file_bytes(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)*n + 1);
    if (b && fread(b, 1, (size_t)*n, f) != (size_t)*n) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

static int same_file(const char *a, const char *b)
{
    long na = -1, nb = -2;
    unsigned char *x = file_bytes(a, &na), *y = file_bytes(b, &nb);
    int same = x && y && na == nb && memcmp(x, y, (size_t)na) == 0;
    free(x);
    free(y);
    return same;
}

/* `render --png` encodes in a writer thread while it draws the next frame:
 * the frames of one call are, byte for byte and in order, the
 * frames each drawn alone, and they are what ms_image_write_png (the
 * encoder of ms_renderer_write_png) makes of their pixels. */
START_TEST(png_frames_encoded_off_the_render_thread_keep_their_bytes_and_order)
{
    if (!MS_HAVE_GL)
        MS_SKIP("built without OSMesa and EGL: nothing can draw");
    make_tmp_dir();
    char run[300], all[300], one[300], a[340], b[340];
    snprintf(run, sizeof run, "%s/run.h5", tmp_dir);
    snprintf(all, sizeof all, "%s/all", tmp_dir);
    make_run(run);
    const char *args[] = {"render", run,     "--shader", "water", "--size",
                          "80x60",  "--png", all,        NULL};
    result r = run_tool(args);
    ck_assert_msg(r.status == 0, "render failed: %s", r.err);
    free(r.err);
    for (int f = 0; f < 3; ++f) {
        char frames[16];
        snprintf(frames, sizeof frames, "%d:%d", f, f);
        snprintf(one, sizeof one, "%s/one%d", tmp_dir, f);
        const char *alone[] = {"render",   run,    "--shader", "water", "--size", "80x60",
                               "--frames", frames, "--png",    one,     NULL};
        r = run_tool(alone);
        ck_assert_msg(r.status == 0, "render of frame %d failed: %s", f, r.err);
        free(r.err);
        snprintf(a, sizeof a, "%s/frame_%05d.png", all, f);
        snprintf(b, sizeof b, "%s/frame_%05d.png", one, f);
        ck_assert_msg(same_file(a, b), "%s and %s differ", a, b);
    }
    /* the frames differ, so a swap would show */
    snprintf(a, sizeof a, "%s/frame_%05d.png", all, 0);
    snprintf(b, sizeof b, "%s/frame_%05d.png", all, 2);
    ck_assert_msg(!same_file(a, b), "frames 0 and 2 are the same picture");
    /* decoded and encoded again by the library: the same file */
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    ck_assert(png_image_begin_read_from_file(&img, a));
    img.format = PNG_FORMAT_RGBA;
    unsigned char *px = malloc(PNG_IMAGE_SIZE(img));
    ck_assert(png_image_finish_read(&img, NULL, px, 0, NULL));
    snprintf(b, sizeof b, "%s/again.png", tmp_dir);
    ck_assert_int_eq(ms_image_write_png(b, px, (int)img.width, (int)img.height), MS_OK);
    ck_assert_msg(same_file(a, b), "ms_image_write_png made other bytes than %s", a);
    free(px);
    remove_tmp_dir();
}
END_TEST

START_TEST(image_write_png_refuses_bad_arguments_naming_them)
{
    make_tmp_dir();
    unsigned char px[16] = {0};
    char path[300];
    snprintf(path, sizeof path, "%s/x.png", tmp_dir);
    MS_ASSERT_REFUSED(ms_image_write_png(NULL, px, 2, 2), MS_ERR_INVALID_ARGUMENT, "path");
    MS_ASSERT_REFUSED(ms_image_write_png(path, NULL, 2, 2), MS_ERR_INVALID_ARGUMENT, "NULL");
    MS_ASSERT_REFUSED(ms_image_write_png(path, px, 0, 2), MS_ERR_INVALID_ARGUMENT, "0 x 2");
    MS_ASSERT_REFUSED(ms_image_write_png(path, px, 2, 20000), MS_ERR_INVALID_ARGUMENT,
                      "[1, 16384]");
    snprintf(path, sizeof path, "%s/no/such/dir/x.png", tmp_dir);
    MS_ASSERT_REFUSED(ms_image_write_png(path, px, 2, 2), MS_ERR_IO, "cannot write");
    ck_assert_int_ne(access(path, F_OK), 0);
    remove_tmp_dir();
}
END_TEST

/* SIGINT during `run --png` of a scene with a render section: the run
 * finishes the frame in hand and every frame in the run file has its PNG
 * on disk (the writer thread's queue is written out before the exit). */
START_TEST(sigint_during_run_png_loses_no_queued_frame)
{
    if (!MS_HAVE_GL)
        MS_SKIP("built without OSMesa and EGL: nothing can draw");
    make_tmp_dir();
    char scene[300], out[300], dir[300], p[340];
    snprintf(scene, sizeof scene, "%s/drawn.json", tmp_dir);
    snprintf(out, sizeof out, "%s/drawn.h5", tmp_dir);
    snprintf(dir, sizeof dir, "%s/png", tmp_dir);
    char *text = ms_test_slurp(SMALL_SCENE);
    ck_assert_ptr_nonnull(text);
    char *brace = strrchr(text, '}');
    ck_assert_ptr_nonnull(brace);
    *brace = '\0';
    FILE *f = fopen(scene, "w");
    ck_assert_ptr_nonnull(f);
    fprintf(f, "%s, \"render\": {\"width\": 160, \"height\": 120, \"shader\": \"water\"}}\n", text);
    fclose(f);
    free(text);
    const char *argv[] = {
        ms_test_tool_path(), "run", scene, "--frames", "100000", "--out", out, "--png", dir,
        "--quiet",           NULL};
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int o = open("/dev/null", O_WRONLY);
        dup2(o, 1);
        dup2(o, 2);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    snprintf(p, sizeof p, "%s/frame_00003.png", dir);
    for (int i = 0; i < 1200 && access(p, F_OK) != 0; ++i)
        nanosleep(&(struct timespec){0, 50000000}, NULL);
    ck_assert_msg(access(p, F_OK) == 0, "no 4th frame within 60 s");
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT, "status %d", status);
    ms_reader *rd;
    ck_assert_msg(ms_reader_open(out, &rd) == MS_OK, "%s", ms_last_error());
    const long frames = ms_reader_frames(rd);
    ms_reader_close(rd);
    ck_assert_int_ge(frames, 4);
    for (long k = 0; k < frames; ++k) {
        int w = 0, h = 0;
        snprintf(p, sizeof p, "%s/frame_%05ld.png", dir, k);
        png_size(p, &w, &h); /* there, and a whole picture */
        ck_assert_int_eq(w, 160);
    }
    snprintf(p, sizeof p, "%s/frame_%05ld.png", dir, frames);
    ck_assert_msg(access(p, F_OK) != 0, "a PNG for frame %ld, which the file lacks", frames);
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
    tcase_add_test(tc, png_frames_encoded_off_the_render_thread_keep_their_bytes_and_order);
    tcase_add_test(tc, image_write_png_refuses_bad_arguments_naming_them);
    tcase_add_test(tc, sigint_during_run_png_loses_no_queued_frame);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(render_tool_suite());
}
