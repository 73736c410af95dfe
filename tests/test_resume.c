/* modesplit run --resume (issue 17): a run killed by SIGKILL at a random
 * frame, or stopped, continues from its file's last complete frame, and
 * the finished file holds the same bytes in every field, time and particle
 * array as a run never stopped, with 1 and 2 threads; a frame cut by the
 * kill is dropped and written again; another scene, another build's bytes,
 * another set of fields are refused with a sentence and leave the file as
 * it was. The tool is run as a user runs it (fork + exec, SIGKILL).
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <hdf5.h>

#include "io/io_internal.h"
#include "modesplit/modesplit.h"
#include "support.h"

/* Frames of the runs compared: enough for the boat, the rain and the SPH
 * pool of fig10 to move, few enough for ASan. */
#define FRAMES 24

static char tmp_dir[256];

static void make_tmp_dir(void)
{
    ck_assert_int_eq(ms_test_tmp_dir(tmp_dir, sizeof tmp_dir, "ms_resume"), 0);
}

static const char *tmp_path(const char *name)
{
    static char p[4][512];
    static int k;
    k = (k + 1) % 4;
    snprintf(p[k], sizeof p[k], "%s/%s", tmp_dir, name);
    return p[k];
}

/* Start the tool with argv (NULL-terminated, without the program), its
 * output into tmp/log.txt; returns the pid. */
static pid_t start_tool(const char *const *args)
{
    char log[512];
    snprintf(log, sizeof log, "%s/log.txt", tmp_dir);
    return ms_test_spawn_tool(args, log, log);
}

static char log_text[8192];

/* Run the tool to its end: its exit status (-1 if killed), log_text holds its output. */
static int run_tool(const char *const *args)
{
    pid_t pid = start_tool(args);
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    char log[512];
    snprintf(log, sizeof log, "%s/log.txt", tmp_dir);
    FILE *f = fopen(log, "r");
    size_t got = f ? fread(log_text, 1, sizeof log_text - 1, f) : 0;
    log_text[got] = '\0';
    if (f)
        fclose(f);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* Complete frames of a run file being written (0 while it cannot be opened). */
static long frames_now(const char *path)
{
    ms_reader *r;
    if (ms_reader_open(path, &r) != MS_OK)
        return 0;
    long n = ms_reader_frames(r);
    ms_reader_close(r);
    return n;
}

/* Start args, wait until `path` holds at least `at` frames, SIGKILL. */
static void kill_at(const char *const *args, const char *path, long at)
{
    pid_t pid = start_tool(args);
    int status;
    for (;;) {
        if (frames_now(path) >= at)
            break;
        pid_t w = waitpid(pid, &status, WNOHANG);
        ck_assert_msg(w == 0, "the run ended before frame %ld", at);
        usleep(1000);
    }
    kill(pid, SIGKILL);
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

/* A random frame in [lo, hi], printed so a failure can be rerun. */
static long random_frame(long lo, long hi)
{
    unsigned seed = (unsigned)time(NULL) ^ (unsigned)getpid() * 2654435761u;
    srand(seed);
    long k = lo + rand() % (hi - lo + 1);
    fprintf(stderr, "test_resume: seed %u, kill at frame %ld\n", seed, k);
    return k;
}

static void assert_same_bits(const void *a, const void *b, size_t n, const char *what, long k)
{
    ck_assert_msg(memcmp(a, b, n) == 0, "frame %ld: %s differs from the unbroken run", k, what);
}

/* Every frame of b equals a's, bit for bit: time, fields, particles, ids. */
static void assert_same_run(const char *path_a, const char *path_b, long frames)
{
    ms_reader *a, *b;
    ck_assert_msg(ms_reader_open(path_a, &a) == MS_OK, "%s", ms_last_error());
    ck_assert_msg(ms_reader_open(path_b, &b) == MS_OK, "%s", ms_last_error());
    ck_assert_int_eq(ms_reader_frames(a), frames);
    ck_assert_int_eq(ms_reader_frames(b), frames);
    ck_assert_uint_eq(ms_reader_fields(a), ms_reader_fields(b));
    unsigned fields = ms_reader_fields(a);
    static const unsigned bits[3] = {MS_FIELD_COMBINED, MS_FIELD_SURFACE, MS_FIELD_VOLUME};
    for (long k = 0; k < frames; ++k) {
        double ta, tb;
        ck_assert_int_eq(ms_reader_time(a, k, &ta), MS_OK);
        ck_assert_int_eq(ms_reader_time(b, k, &tb), MS_OK);
        assert_same_bits(&ta, &tb, sizeof ta, "time", k);
        for (int i = 0; i < 3; ++i) {
            if (!(fields & bits[i]))
                continue;
            ms_grid g;
            ck_assert_int_eq(ms_reader_field_grid(a, bits[i], &g), MS_OK);
            size_t n = (size_t)g.nx * (size_t)g.ny;
            float *fa = malloc(n * sizeof *fa), *fb = malloc(n * sizeof *fb);
            ck_assert_int_eq(ms_reader_read_field(a, bits[i], k, fa, n), MS_OK);
            ck_assert_int_eq(ms_reader_read_field(b, bits[i], k, fb, n), MS_OK);
            assert_same_bits(fa, fb, n * sizeof *fa, "a field", k);
            free(fa);
            free(fb);
        }
        if (!(fields & MS_FIELD_PARTICLES))
            continue;
        int na, nb;
        ck_assert_int_eq(ms_reader_particle_count(a, k, &na), MS_OK);
        ck_assert_int_eq(ms_reader_particle_count(b, k, &nb), MS_OK);
        ck_assert_int_eq(na, nb);
        ck_assert_int_gt(na, 0);
        float *pa = malloc((size_t)na * 6 * sizeof *pa), *pb = malloc((size_t)na * 6 * sizeof *pb);
        float *qa[3], *va[3], *qb[3], *vb[3];
        for (int c = 0; c < 3; ++c) {
            qa[c] = pa + (size_t)c * (size_t)na;
            va[c] = pa + (size_t)(3 + c) * (size_t)na;
            qb[c] = pb + (size_t)c * (size_t)na;
            vb[c] = pb + (size_t)(3 + c) * (size_t)na;
        }
        ck_assert_int_eq(ms_reader_read_particles(a, k, na, qa, va), MS_OK);
        ck_assert_int_eq(ms_reader_read_particles(b, k, na, qb, vb), MS_OK);
        assert_same_bits(pa, pb, (size_t)na * 6 * sizeof *pa, "the particles", k);
        free(pa);
        free(pb);
    }
    ms_reader_close(a);
    ms_reader_close(b);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    *len = fread(s, 1, (size_t)n, f);
    s[*len] = '\0';
    fclose(f);
    return s;
}

#define SCENE "data/scenes/fig10.json"
#define FRAMES_ARG "24"

/* The unbroken run, at `threads`. */
static void unbroken(const char *out, const char *threads)
{
    const char *args[] = {"run", SCENE, "--frames", FRAMES_ARG, "--threads", threads,
                          "--quiet", "--out", out, NULL};
    ck_assert_msg(run_tool(args) == 0, "%s", log_text);
}

/* Kill a run at a random frame with `threads`, resume it with `resume_threads`. */
static void kill_and_resume(const char *threads, const char *resume_threads)
{
    make_tmp_dir();
    unbroken(tmp_path("full.h5"), "1");
    const char *part = tmp_path("part.h5");
    const char *args[] = {"run", SCENE, "--frames", FRAMES_ARG, "--threads", threads,
                          "--quiet", "--out", part, NULL};
    kill_at(args, part, random_frame(1, FRAMES - 4));
    long kept = frames_now(part);
    ck_assert_int_lt(kept, FRAMES);
    const char *res[] = {"run", SCENE, "--frames", FRAMES_ARG, "--threads", resume_threads,
                         "--resume", part, NULL};
    ck_assert_msg(run_tool(res) == 0, "%s", log_text);
    ck_assert_msg(strstr(log_text, "resuming") != NULL, "%s", log_text);
    ck_assert_msg(strstr(log_text, "(24 frames") != NULL, "%s", log_text);
    assert_same_run(tmp_path("full.h5"), part, FRAMES);
    /* the sidecars list every frame once, as the unbroken run's */
    size_t n;
    char *x = slurp(tmp_path("part.xmf"), &n);
    int times = 0;
    for (const char *p = strstr(x, "<Time Value="); p; p = strstr(p + 1, "<Time Value="))
        ++times;
    ck_assert_int_eq(times, FRAMES);
    free(x);
    ms_test_remove_tree(tmp_dir);
}

START_TEST(sigkill_then_resume_is_the_unbroken_run_1_thread)
{
    kill_and_resume("1", "1");
}
END_TEST

START_TEST(sigkill_then_resume_is_the_unbroken_run_2_threads)
{
    /* killed and resumed with 2 threads, compared with a 1-thread run:
     * the thread count is no part of the result */
    kill_and_resume("2", "2");
}
END_TEST

START_TEST(resume_twice_with_output_every_3)
{
    make_tmp_dir();
    const char *full = tmp_path("full.h5");
    const char *a1[] = {"run", SCENE, "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--quiet", "--out", full, NULL};
    ck_assert_msg(run_tool(a1) == 0, "%s", log_text);
    const char *part = tmp_path("part.h5");
    const char *a2[] = {"run", SCENE, "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--threads", "2", "--quiet", "--out", part, NULL};
    kill_at(a2, part, 2);
    /* the first resume is stopped after 15 frames (5 written), the second
     * goes to the end */
    const char *r1[] = {"run", SCENE, "--frames", "15", "--set", "output.every=3", "--quiet",
                        "--resume", part, NULL};
    ck_assert_msg(run_tool(r1) == 0, "%s", log_text);
    ck_assert_int_eq(frames_now(part), 5);
    const char *r2[] = {"run", SCENE, "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--quiet", "--resume", part, NULL};
    ck_assert_msg(run_tool(r2) == 0, "%s", log_text);
    assert_same_run(full, part, 8); /* frames 0, 3, ..., 21 */
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* What a kill between a frame's data and its commit leaves: datasets one
 * frame longer than `frames`, with junk, and the step's links. */
static void cut_a_frame(const char *path, long frames)
{
    hid_t f = H5Fopen(path, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    static const char *const names[] = {"fields/combined", "fields/surface", "fields/volume"};
    for (int i = 0; i < 3; ++i) {
        hid_t d = H5Dopen2(f, names[i], H5P_DEFAULT);
        ck_assert_int_ge(d, 0);
        hid_t s = H5Dget_space(d);
        hsize_t dims[3];
        H5Sget_simple_extent_dims(s, dims, NULL);
        H5Sclose(s);
        ck_assert_int_eq((long)dims[0], frames);
        dims[0] = (hsize_t)frames + 1;
        ck_assert_int_ge(H5Dset_extent(d, dims), 0);
        size_t n = (size_t)dims[1] * dims[2];
        float *junk = malloc(n * sizeof *junk);
        for (size_t j = 0; j < n; ++j)
            junk[j] = 12345.0f;
        hsize_t start[3] = {(hsize_t)frames, 0, 0}, count[3] = {1, dims[1], dims[2]};
        s = H5Dget_space(d);
        hid_t m = H5Screate_simple(3, count, NULL);
        H5Sselect_hyperslab(s, H5S_SELECT_SET, start, NULL, count, NULL);
        ck_assert_int_ge(H5Dwrite(d, H5T_NATIVE_FLOAT, m, s, H5P_DEFAULT, junk), 0);
        H5Sclose(m);
        H5Sclose(s);
        H5Dclose(d);
        free(junk);
    }
    char step[64], xyz[64];
    snprintf(step, sizeof step, "Step#%ld", frames);
    snprintf(xyz, sizeof xyz, "particles/%ld", frames);
    hid_t g = H5Gcreate2(f, step, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(g, 0);
    H5Gclose(g);
    g = H5Gcreate2(f, xyz, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ck_assert_int_ge(g, 0);
    H5Gclose(g);
    H5Fclose(f);
}

START_TEST(resume_drops_a_frame_cut_by_the_kill)
{
    make_tmp_dir();
    unbroken(tmp_path("full.h5"), "2");
    const char *part = tmp_path("part.h5");
    const char *a[] = {"run", SCENE, "--frames", "9", "--quiet", "--out", part, NULL};
    ck_assert_msg(run_tool(a) == 0, "%s", log_text);
    cut_a_frame(part, 9);
    ck_assert_int_eq(frames_now(part), 9); /* the reader already ignores the cut frame */
    const char *r[] = {"run", SCENE, "--frames", FRAMES_ARG, "--quiet", "--resume", part, NULL};
    ck_assert_msg(run_tool(r) == 0, "%s", log_text);
    assert_same_run(tmp_path("full.h5"), part, FRAMES);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* A run killed before its first frame (or run with --frames 0) resumes
 * from the start. */
START_TEST(resume_a_run_of_no_frame)
{
    make_tmp_dir();
    const char *full = tmp_path("full.h5"), *part = tmp_path("part.h5");
    const char *a[] = {"run", SCENE, "--frames", "6", "--quiet", "--out", full, NULL};
    ck_assert_msg(run_tool(a) == 0, "%s", log_text);
    const char *b[] = {"run", SCENE, "--frames", "0", "--quiet", "--out", part, NULL};
    ck_assert_msg(run_tool(b) == 0, "%s", log_text);
    ck_assert_int_eq(frames_now(part), 0);
    const char *r[] = {"run", SCENE, "--frames", "6", "--quiet", "--resume", part, NULL};
    ck_assert_msg(run_tool(r) == 0, "%s", log_text);
    assert_same_run(full, part, 6);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

START_TEST(resume_refuses_another_scene_and_leaves_the_file)
{
    make_tmp_dir();
    const char *part = tmp_path("part.h5");
    const char *a[] = {"run", SCENE, "--frames", "3", "--quiet", "--out", part, NULL};
    ck_assert_msg(run_tool(a) == 0, "%s", log_text);
    size_t n0, n1;
    char *before = slurp(part, &n0);

    const char *other[] = {"run", SCENE, "--frames", "6", "--quiet", "--set",
                           "surface.damping=0.5", "--resume", part, NULL};
    ck_assert_int_eq(run_tool(other), 2);
    ck_assert_msg(strstr(log_text, "another scene") && strstr(log_text, "damping"), "%s",
                  log_text);
    const char *scene3[] = {"run", "data/scenes/fig3.json", "--frames", "6", "--quiet",
                            "--resume", part, NULL};
    ck_assert_int_eq(run_tool(scene3), 2);
    ck_assert_msg(strstr(log_text, "another scene") != NULL, "%s", log_text);
    const char *fewer[] = {"run", SCENE, "--frames", "1", "--quiet", "--resume", part, NULL};
    ck_assert_int_eq(run_tool(fewer), 2);
    ck_assert_msg(strstr(log_text, "more than a run of 1 frames") != NULL, "%s", log_text);
    const char *both[] = {"run", SCENE, "--resume", part, "--out", part, NULL};
    ck_assert_int_eq(run_tool(both), 2);
    ck_assert_msg(strstr(log_text, "--resume") != NULL, "%s", log_text);
    const char *none[] = {"run", SCENE, "--resume", tmp_path("none.h5"), NULL};
    ck_assert_int_eq(run_tool(none), 1);
    ck_assert_msg(strstr(log_text, "none.h5") != NULL, "%s", log_text);

    char *after = slurp(part, &n1);
    ck_assert_msg(n0 == n1 && memcmp(before, after, n0) == 0,
                  "a refused resume changed the file");
    free(before);
    free(after);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* A file whose last frame is not what this build computes (another build
 * or platform wrote it): the replay's check refuses it before appending. */
START_TEST(resume_refuses_a_file_this_build_does_not_reproduce)
{
    make_tmp_dir();
    const char *part = tmp_path("part.h5");
    const char *a[] = {"run", SCENE, "--frames", "4", "--quiet", "--out", part, NULL};
    ck_assert_msg(run_tool(a) == 0, "%s", log_text);
    hid_t f = H5Fopen(part, H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "fields/volume", H5P_DEFAULT);
    hid_t s = H5Dget_space(d);
    hsize_t start[3] = {3, 2, 5}, count[3] = {1, 1, 1};
    H5Sselect_hyperslab(s, H5S_SELECT_SET, start, NULL, count, NULL);
    hid_t m = H5Screate_simple(3, count, NULL);
    float v = 0.123f;
    ck_assert_int_ge(H5Dwrite(d, H5T_NATIVE_FLOAT, m, s, H5P_DEFAULT, &v), 0);
    H5Sclose(m);
    H5Sclose(s);
    H5Dclose(d);
    H5Fclose(f);
    const char *r[] = {"run", SCENE, "--frames", "8", "--quiet", "--resume", part, NULL};
    ck_assert_int_eq(run_tool(r), 1);
    ck_assert_msg(strstr(log_text, "frame 3's volume field differs") != NULL, "%s", log_text);
    ck_assert_int_eq(frames_now(part), 4);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

static Suite *resume_suite(void)
{
    Suite *s = suite_create("resume");
    TCase *tc = tcase_create("resume");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, sigkill_then_resume_is_the_unbroken_run_1_thread);
    tcase_add_test(tc, sigkill_then_resume_is_the_unbroken_run_2_threads);
    tcase_add_test(tc, resume_twice_with_output_every_3);
    tcase_add_test(tc, resume_drops_a_frame_cut_by_the_kill);
    tcase_add_test(tc, resume_a_run_of_no_frame);
    tcase_add_test(tc, resume_refuses_another_scene_and_leaves_the_file);
    tcase_add_test(tc, resume_refuses_a_file_this_build_does_not_reproduce);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(resume_suite());
}
