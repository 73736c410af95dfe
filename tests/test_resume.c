/* modesplit run --resume: a run killed by SIGKILL at a random
 * frame, or stopped, continues from its file's last complete frame, and
 * the finished file holds the same bytes in every field, time and particle
 * array as a run never stopped, with 1 and 2 threads; a frame cut by the
 * kill is dropped and written again; another scene, another build's bytes,
 * another set of fields are refused with a sentence and leave the file as
 * it was. The tool is run as a user runs it (fork + exec, SIGKILL).
 */
#define _GNU_SOURCE
#include <dirent.h>
#include <math.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/blob.h"
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

/* Frames a running writer of `path` (run.h5) has committed, as its
 * sidecar run.xmf lists them (appended after each commit): read without
 * opening the HDF5 file mid-flush, where HDF5 1.10.8 leaks (io.h), which
 * LeakSanitizer reports. */
static long frames_listed(const char *path)
{
    char xmf[600];
    snprintf(xmf, sizeof xmf, "%.*s.xmf", (int)strlen(path) - 3, path);
    FILE *f = fopen(xmf, "rb");
    if (!f)
        return 0;
    static char text[1 << 20];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    long frames = 0;
    for (const char *p = strstr(text, "<Time Value="); p; p = strstr(p + 1, "<Time Value="))
        ++frames;
    return frames;
}

/* Start args, wait until `path` holds at least `at` frames, SIGKILL. */
static void kill_at(const char *const *args, const char *path, long at)
{
    pid_t pid = start_tool(args);
    int status;
    for (;;) {
        if (frames_listed(path) >= at)
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

/* b holds `frames` frames, each equal to a's, bit for bit: time, fields,
 * particles, ids (a may hold more). */
static void assert_same_run(const char *path_a, const char *path_b, long frames)
{
    ms_reader *a, *b;
    ck_assert_msg(ms_reader_open(path_a, &a) == MS_OK, "%s", ms_last_error());
    ck_assert_msg(ms_reader_open(path_b, &b) == MS_OK, "%s", ms_last_error());
    ck_assert_int_ge(ms_reader_frames(a), frames);
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
    const char *args[] = {"run",   SCENE,     "--frames", FRAMES_ARG, "--threads",
                          threads, "--quiet", "--out",    out,        NULL};
    ck_assert_msg(run_tool(args) == 0, "%s", log_text);
}

/* Kill a run at a random frame with `threads`, resume it with `resume_threads`. */
static void kill_and_resume(const char *threads, const char *resume_threads)
{
    make_tmp_dir();
    unbroken(tmp_path("full.h5"), "1");
    const char *part = tmp_path("part.h5");
    const char *args[] = {"run",   SCENE,     "--frames", FRAMES_ARG, "--threads",
                          threads, "--quiet", "--out",    part,       NULL};
    kill_at(args, part, random_frame(1, FRAMES - 4));
    long kept = frames_now(part);
    ck_assert_int_lt(kept, FRAMES);
    const char *res[] = {"run",          SCENE,      "--frames", FRAMES_ARG, "--threads",
                         resume_threads, "--resume", part,       NULL};
    ck_assert_msg(run_tool(res) == 0, "%s", log_text);
    ck_assert_msg(strstr(log_text, "resuming") != NULL, "%s", log_text);
    /* from the checkpoint of the last complete frame: nothing is stepped twice */
    char want[64];
    snprintf(want, sizeof want, "restored the checkpoint of frame %ld", kept - 1);
    ck_assert_msg(strstr(log_text, want) != NULL, "%s", log_text);
    ck_assert_msg(strstr(log_text, "replaying 0 steps") != NULL, "%s", log_text);
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
    const char *a1[] = {"run",     SCENE,   "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--quiet", "--out", full,       NULL};
    ck_assert_msg(run_tool(a1) == 0, "%s", log_text);
    const char *part = tmp_path("part.h5");
    const char *a2[] = {"run",       SCENE, "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--threads", "2",   "--quiet",  "--out",    part,    NULL};
    kill_at(a2, part, 2);
    /* the first resume is stopped after 15 frames (5 written), the second
     * goes to the end */
    const char *r1[] = {"run",     SCENE,      "--frames", "15", "--set", "output.every=3",
                        "--quiet", "--resume", part,       NULL};
    ck_assert_msg(run_tool(r1) == 0, "%s", log_text);
    ck_assert_int_eq(frames_now(part), 5);
    assert_same_run(full, part, 5);
    const char *r2[] = {"run",     SCENE,      "--frames", FRAMES_ARG, "--set", "output.every=3",
                        "--quiet", "--resume", part,       NULL};
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

    const char *other[] = {
        "run",      SCENE, "--frames", "6", "--quiet", "--set", "surface.damping=0.5",
        "--resume", part,  NULL};
    ck_assert_int_eq(run_tool(other), 2);
    ck_assert_msg(strstr(log_text, "another scene") && strstr(log_text, "damping"), "%s", log_text);
    const char *scene3[] = {
        "run", "data/scenes/fig3.json", "--frames", "6", "--quiet", "--resume", part, NULL};
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
    ck_assert_msg(n0 == n1 && memcmp(before, after, n0) == 0, "a refused resume changed the file");
    free(before);
    free(after);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* FNV-1a 64 of a whole file: the checksum compared around each refusal. */
static uint64_t file_checksum(const char *path, size_t *len)
{
    char *b = slurp(path, len);
    uint64_t h = 1469598103934665603u;
    for (size_t i = 0; i < *len; ++i)
        h = (h ^ (unsigned char)b[i]) * 1099511628211u;
    free(b);
    return h;
}

/* A killed file has an unreferenced tail past its end of allocation (the
 * frame the kill cut). A writable HDF5 open and close rewrites the
 * superblock and drops that tail; a refusal must not get that far: every
 * refusal below leaves the file's bytes and length as they were. */
START_TEST(resume_refusals_leave_a_killed_file_byte_for_byte)
{
    make_tmp_dir();
    const char *part = tmp_path("killed.h5");
    const char *a[] = {"run", SCENE, "--frames", "100000", "--quiet", "--out", part, NULL};
    kill_at(a, part, 3);
    ck_assert(ms_test_wait_unused(part, 30.0));
    size_t n0, n1;
    uint64_t h0 = file_checksum(part, &n0);
    struct {
        const char *const args[12];
        int status;
        const char *word;
    } refusals[] = {
        {{"run", "data/scenes/fig1.json", "--frames", "100000", "--quiet", "--resume", part, NULL},
         2,
         "another scene"},
        {{"run", SCENE, "--frames", "100000", "--quiet", "--set", "surface.damping=0.5", "--resume",
          part, NULL},
         2,
         "damping"},
        {{"run", SCENE, "--frames", "1", "--quiet", "--resume", part, NULL}, 2, "more than"},
        {{"run", SCENE, "--quiet", "--resume", part, "--no-out", NULL}, 2, "--resume"},
    };
    for (size_t i = 0; i < sizeof refusals / sizeof refusals[0]; ++i) {
        ck_assert_int_eq(run_tool(refusals[i].args), refusals[i].status);
        ck_assert_msg(strstr(log_text, refusals[i].word) != NULL, "refusal %zu: %s", i, log_text);
        uint64_t h1 = file_checksum(part, &n1);
        ck_assert_msg(n1 == n0 && h1 == h0,
                      "refusal %zu (%s) changed the file: %zu bytes, checksum %016llx; "
                      "before %zu bytes, %016llx",
                      i, refusals[i].word, n1, (unsigned long long)h1, n0, (unsigned long long)h0);
    }
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

static void assert_same_sims(const ms_sim *a, const ms_sim *b);

/* output.checkpoint_every = 3: the newest checkpoint is of frame 6 of a
 * run of 8 frames, so a resume steps only to frame 7 again; with a torn
 * newest checkpoint it takes the older one (frame 3); with 0 it steps the
 * whole run again (the replay). Every way gives the unbroken run's bytes. */
START_TEST(resume_from_an_older_checkpoint_or_none)
{
    make_tmp_dir();
    const char *full = tmp_path("full.h5");
    const char *a1[] = {"run",     SCENE,   "--frames", "14", "--set", "output.checkpoint_every=3",
                        "--quiet", "--out", full,       NULL};
    ck_assert_msg(run_tool(a1) == 0, "%s", log_text);
    const char *part = tmp_path("part.h5");
    const char *a2[] = {"run",     SCENE,   "--frames", "8", "--set", "output.checkpoint_every=3",
                        "--quiet", "--out", part,       NULL};
    ck_assert_msg(run_tool(a2) == 0, "%s", log_text);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(part, &r), MS_OK);
    long at[2] = {-1, -1};
    ck_assert_int_eq(ms_reader_checkpoints(r, at), 2);
    ck_assert_int_eq(at[0], 6);
    ck_assert_int_eq(at[1], 3);
    ms_reader_close(r);
    const char *r1[] = {"run",      SCENE, "--frames", "10", "--set", "output.checkpoint_every=3",
                        "--resume", part,  NULL};
    ck_assert_msg(run_tool(r1) == 0, "%s", log_text);
    ck_assert_msg(strstr(log_text, "checkpoint of frame 6") &&
                      strstr(log_text, "replaying 1 steps"),
                  "%s", log_text);
    assert_same_run(full, part, 10);

    /* tear the newest checkpoint (frame 9, written by the resume); the
     * other holds frame 6, so the next resume steps 7..9 again */
    hid_t f = H5Fopen(part, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    int torn = 0;
    for (int s = 0; s < 2; ++s) {
        char name[32];
        snprintf(name, sizeof name, "checkpoint/%d", s);
        hid_t d = H5Dopen2(f, name, H5P_DEFAULT), a = H5Aopen(d, "frame", H5P_DEFAULT);
        int64_t frame = -1;
        ck_assert_int_ge(H5Aread(a, H5T_NATIVE_INT64, &frame), 0);
        H5Aclose(a);
        if (frame == 9) {
            hid_t sp = H5Dget_space(d);
            hsize_t start[1] = {1000}, count[1] = {64};
            H5Sselect_hyperslab(sp, H5S_SELECT_SET, start, NULL, count, NULL);
            hid_t m = H5Screate_simple(1, count, NULL);
            unsigned char junk[64];
            memset(junk, 0xA5, sizeof junk);
            ck_assert_int_ge(H5Dwrite(d, H5T_NATIVE_UCHAR, m, sp, H5P_DEFAULT, junk), 0);
            H5Sclose(m);
            H5Sclose(sp);
            torn = 1;
        }
        H5Dclose(d);
    }
    H5Fclose(f);
    ck_assert(torn);
    const char *r2[] = {"run",      SCENE, "--frames", "14", "--set", "output.checkpoint_every=3",
                        "--resume", part,  NULL};
    ck_assert_msg(run_tool(r2) == 0, "%s", log_text);
    ck_assert_msg(strstr(log_text, "cannot use the checkpoint of frame 9") &&
                      strstr(log_text, "checksum") &&
                      strstr(log_text, "restored the checkpoint of frame 6") &&
                      strstr(log_text, "replaying 3 steps"),
                  "%s", log_text);
    assert_same_run(full, part, 14);

    /* no checkpoints: the replay */
    const char *none = tmp_path("none.h5");
    const char *a3[] = {"run",     SCENE,   "--frames", "5", "--set", "output.checkpoint_every=0",
                        "--quiet", "--out", none,       NULL};
    ck_assert_msg(run_tool(a3) == 0, "%s", log_text);
    ck_assert_int_eq(ms_reader_open(none, &r), MS_OK);
    ck_assert_int_eq(ms_reader_checkpoints(r, at), 0);
    MS_ASSERT_REFUSED(ms_reader_checkpoint_size(r, 0, &(size_t){0}), MS_ERR_INVALID_ARGUMENT,
                      "does not exist");
    ms_reader_close(r);
    const char *r3[] = {"run",      SCENE, "--frames", "14", "--set", "output.checkpoint_every=0",
                        "--resume", none,  NULL};
    ck_assert_msg(run_tool(r3) == 0, "%s", log_text);
    ck_assert_msg(strstr(log_text, "replaying 5 steps") != NULL, "%s", log_text);
    assert_same_run(full, none, 14);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* The scene key is checked like every other; the writer's setter too. */
START_TEST(checkpoint_every_out_of_range_is_refused)
{
    make_tmp_dir();
    const char *neg[] = {
        "run",     SCENE,   "--frames",       "2", "--set", "output.checkpoint_every=-1",
        "--quiet", "--out", tmp_path("x.h5"), NULL};
    ck_assert_int_eq(run_tool(neg), 2);
    ck_assert_msg(strstr(log_text, "checkpoint_every") != NULL, "%s", log_text);
    const char *frac[] = {
        "run",     SCENE,   "--frames",       "2", "--set", "output.checkpoint_every=1.5",
        "--quiet", "--out", tmp_path("x.h5"), NULL};
    ck_assert_int_eq(run_tool(frac), 2);
    ck_assert_msg(strstr(log_text, "checkpoint_every") != NULL, "%s", log_text);
    ms_scene *sc;
    ck_assert_int_eq(ms_scene_load(SCENE, &sc), MS_OK);
    ck_assert_int_eq(ms_scene_output_checkpoint_every(sc), 1); /* the default */
    ms_sim *sim;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    ms_writer *w;
    ck_assert_int_eq(ms_writer_open(tmp_path("w.h5"), sim, 0, &w), MS_OK);
    MS_ASSERT_REFUSED(ms_writer_set_checkpoint_every(w, -2), MS_ERR_INVALID_ARGUMENT,
                      "checkpoint_every");
    MS_ASSERT_REFUSED(ms_writer_set_checkpoint_every(NULL, 1), MS_ERR_INVALID_ARGUMENT, "writer");
    ck_assert_int_eq(ms_writer_set_checkpoint_every(w, 2), MS_OK);
    float leaves[5][64 * 3];
    int nleaves = 0;
    for (int i = 0; i < 5; ++i) {
        ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
        ck_assert_int_eq(ms_writer_frame(w, sim), MS_OK);
        const float *xyz = ms_sim_floaters(sim, &nleaves);
        ck_assert(nleaves > 0 && nleaves <= 64);
        memcpy(leaves[i], xyz, (size_t)nleaves * 3 * sizeof(float));
    }
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("w.h5"), &r), MS_OK);
    long at[2];
    ck_assert_int_eq(ms_reader_checkpoints(r, at), 2);
    ck_assert_int_eq(at[0], 4);
    ck_assert_int_eq(at[1], 2);
    /* fig10's leaves, each frame as the sim showed them */
    ck_assert_int_eq(ms_reader_floater_count(r), nleaves);
    for (int i = 0; i < 5; ++i) {
        float got[64 * 3];
        ck_assert_int_eq(ms_reader_read_floaters(r, i, got, 64), MS_OK);
        ck_assert(memcmp(got, leaves[i], (size_t)nleaves * 3 * sizeof(float)) == 0);
    }
    float few[3];
    MS_ASSERT_REFUSED(ms_reader_read_floaters(r, 0, few, 1), MS_ERR_INVALID_ARGUMENT, "capacity");
    MS_ASSERT_REFUSED(ms_reader_read_floaters(r, 5, few, 64), MS_ERR_INVALID_ARGUMENT, "outside");
    size_t bytes = 0;
    ck_assert_int_eq(ms_reader_checkpoint_size(r, 0, &bytes), MS_OK);
    void *blob = malloc(bytes);
    MS_ASSERT_REFUSED(ms_reader_read_checkpoint(r, 0, blob, bytes - 1), MS_ERR_INVALID_ARGUMENT,
                      "more than the buffer");
    MS_ASSERT_REFUSED(ms_reader_read_checkpoint(r, 2, blob, bytes), MS_ERR_INVALID_ARGUMENT,
                      "does not exist");
    ck_assert_int_eq(ms_reader_read_checkpoint(r, 0, blob, bytes), MS_OK);
    /* the checkpoint of frame 4 is the sim after the step that published it */
    ms_sim *b;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &b), MS_OK);
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    assert_same_sims(sim, b);
    free(blob);
    ms_reader_close(r);
    /* a scene without floaters writes none */
    const char *waves[] = {"run",   "data/scenes/fig3.json", "--frames", "2", "--quiet",
                           "--out", tmp_path("waves.h5"),    NULL};
    ck_assert_msg(run_tool(waves) == 0, "%s", log_text);
    ck_assert_int_eq(ms_reader_open(tmp_path("waves.h5"), &r), MS_OK);
    ck_assert_int_eq(ms_reader_floater_count(r), 0);
    MS_ASSERT_REFUSED(ms_reader_read_floaters(r, 0, few, 1), MS_ERR_INVALID_ARGUMENT,
                      "no floaters");
    ms_reader_close(r);
    ms_sim_destroy(b);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* ---- the API: ms_sim_snapshot / ms_sim_restore ---- */

static ms_sim *scene_sim(const char *path, int threads, ms_scene **sc)
{
    ck_assert_msg(ms_scene_load(path, sc) == MS_OK, "%s", ms_last_error());
    ms_sim *sim = NULL;
    ck_assert_msg(ms_sim_create_from_scene(*sc, threads, &sim) == MS_OK, "%s", ms_last_error());
    return sim;
}

static void *take_snapshot(const ms_sim *sim, size_t *bytes)
{
    ck_assert_int_eq(ms_sim_snapshot_size(sim, bytes), MS_OK);
    void *blob = malloc(*bytes);
    size_t written = 0;
    ck_assert_msg(ms_sim_snapshot(sim, blob, *bytes, &written) == MS_OK, "%s", ms_last_error());
    ck_assert_uint_eq(written, *bytes);
    return blob;
}

static void assert_same_field(const float *a, int anx, int any, const float *b, int bnx, int bny,
                              const char *what)
{
    ck_assert_int_eq(anx, bnx);
    ck_assert_int_eq(any, bny);
    ck_assert_msg((a == NULL) == (b == NULL), "%s: one sim lacks it", what);
    if (a)
        ck_assert_msg(memcmp(a, b, (size_t)anx * any * sizeof *a) == 0,
                      "%s differs from the unbroken sim", what);
}

/* Everything a user sees of the two sims is the same, bit for bit. */
static void assert_same_sims(const ms_sim *a, const ms_sim *b)
{
    int nx, ny, mx, my;
    const float *fa = ms_sim_height(a, &nx, &ny), *fb = ms_sim_height(b, &mx, &my);
    assert_same_field(fa, nx, ny, fb, mx, my, "the combined field");
    fa = ms_sim_surface_height(a, &nx, &ny);
    fb = ms_sim_surface_height(b, &mx, &my);
    assert_same_field(fa, nx, ny, fb, mx, my, "the surface field");
    fa = ms_sim_volume_height(a, &nx, &ny);
    fb = ms_sim_volume_height(b, &mx, &my);
    assert_same_field(fa, nx, ny, fb, mx, my, "the volume field");
    int na, nb;
    const float *pa[3], *va[3], *pb[3], *vb[3];
    ck_assert_int_eq(ms_sim_particles(a, &na, pa, va), MS_OK);
    ck_assert_int_eq(ms_sim_particles(b, &nb, pb, vb), MS_OK);
    ck_assert_int_eq(na, nb);
    for (int k = 0; k < 3 && na > 0; ++k) {
        ck_assert(memcmp(pa[k], pb[k], (size_t)na * sizeof(float)) == 0);
        ck_assert(memcmp(va[k], vb[k], (size_t)na * sizeof(float)) == 0);
    }
    fa = ms_sim_floaters(a, &na);
    fb = ms_sim_floaters(b, &nb);
    ck_assert_int_eq(na, nb);
    if (na > 0)
        ck_assert(memcmp(fa, fb, (size_t)na * 3 * sizeof *fa) == 0);
    double ta = ms_sim_time(a), tb = ms_sim_time(b);
    ck_assert(memcmp(&ta, &tb, sizeof ta) == 0);
    ck_assert_int_eq(ms_sim_frame(a), ms_sim_frame(b));
}

/* Step sim a (1 thread) `frames` frames, taking a snapshot after `at`;
 * restore it into a fresh sim of `threads` threads, step that to the end:
 * the same fields, particles, floaters and time, and the same snapshot. */
/* The scene at path with the text `from` replaced by `to` (a variant). */
static ms_sim *variant_sim(const char *path, const char *from, const char *to, ms_scene **sc)
{
    char *v = ms_test_scene_variant(path, from, to);
    ck_assert_ptr_nonnull(v);
    ck_assert_msg(ms_scene_parse(v, strlen(v), sc) == MS_OK, "%s", ms_last_error());
    free(v);
    ms_sim *sim = NULL;
    ck_assert_msg(ms_sim_create_from_scene(*sc, 1, &sim) == MS_OK, "%s", ms_last_error());
    return sim;
}

static void snapshot_continues_sim(ms_sim *a, ms_scene *sc, int at, int frames, int threads);

static void snapshot_continues(const char *scene, int at, int frames, int threads)
{
    ms_scene *sc;
    ms_sim *a = scene_sim(scene, 1, &sc);
    snapshot_continues_sim(a, sc, at, frames, threads);
}

/* As snapshot_continues, from sim a (1 thread) of scene sc (both freed). */
static void snapshot_continues_sim(ms_sim *a, ms_scene *sc, int at, int frames, int threads)
{
    ms_sim *b = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, threads, &b), MS_OK);
    float dt = ms_scene_frame_dt(sc);
    void *blob = NULL;
    size_t bytes = 0;
    for (int i = 0; i < frames; ++i) {
        if (i == at) {
            blob = take_snapshot(a, &bytes);
            ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
            /* the restored sim shows the snapshot's frame before any step */
            assert_same_sims(a, b);
        }
        ck_assert_msg(ms_sim_step(a, dt) == MS_OK, "%s", ms_last_error());
        if (i >= at)
            ck_assert_msg(ms_sim_step(b, dt) == MS_OK, "%s", ms_last_error());
    }
    assert_same_sims(a, b);
    size_t na, nb;
    void *sa = take_snapshot(a, &na), *sb = take_snapshot(b, &nb);
    ck_assert_uint_eq(na, nb);
    ck_assert_msg(memcmp(sa, sb, na) == 0, "the two sims' snapshots differ");
    free(sa);
    free(sb);
    free(blob);
    ms_sim_destroy(a);
    ms_sim_destroy(b);
    ms_scene_destroy(sc);
}

START_TEST(snapshot_restore_continues_bit_for_bit)
{
    /* fig10: SPH pool, boat on a path, rain (RNG), the pipeline's lag;
     * stir: a turning paddle and waves pushing the volume (3.5), whose
     * surface particles come from the snapshot's neighbour counts;
     * glass: a tilted container; fig3: waves only, drops and a swimmer */
    static const char *const scenes[] = {"data/scenes/fig10.json", "data/scenes/stir.json",
                                         "data/scenes/glass.json", "data/scenes/fig3.json"};
    for (int i = 0; i < 4; ++i) {
        snapshot_continues(scenes[i], 7, 14, 1);
        snapshot_continues(scenes[i], 6, 12, 2);
    }
    /* before the first step (not primed) and after it */
    snapshot_continues("data/scenes/fig10.json", 0, 4, 2);
    snapshot_continues("data/scenes/fig10.json", 1, 4, 1);
    /* DFSPH: its warm start (the last density solve's pressure) is state */
    ms_scene *sc;
    ms_sim *a = variant_sim("data/scenes/fig10.json", "\"spacing\": 0.05,",
                            "\"spacing\": 0.05, \"pressure\": \"dfsph\",", &sc);
    snapshot_continues_sim(a, sc, 5, 10, 2);
}
END_TEST

/* An engine's own changes between steps are state too: drags, a moved and
 * turned obstacle, rain turned on, a steered boat, particles added. */
START_TEST(snapshot_keeps_what_an_engine_changed)
{
    ms_scene *sc;
    ms_sim *a = scene_sim("data/scenes/fig10.json", 2, &sc), *b = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &b), MS_OK);
    float dt = ms_scene_frame_dt(sc);
    for (int i = 0; i < 4; ++i)
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
    const float vel[2] = {-0.3f, 0.2f}, pos[2] = {0.4f, 0.5f}, dv[2] = {0.5f, 0.0f};
    ck_assert_int_eq(ms_sim_steer_boat(a, vel), MS_OK);
    ck_assert_int_eq(ms_sim_drag(a, pos, dv, 0.1f, 0.05f, 5.0f), MS_OK);
    ck_assert_int_eq(ms_sim_set_rain(a, 0), MS_OK);
    const float p[3] = {0.5f, 0.5f, 0.3f}, v[3] = {0.1f, 0.0f, 0.0f};
    ck_assert_int_eq(ms_volume_add_particles(ms_sim_volume(a), 1, p, v), MS_OK);
    size_t bytes;
    void *blob = take_snapshot(a, &bytes);
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    for (int i = 0; i < 5; ++i) {
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
        ck_assert_int_eq(ms_sim_step(b, dt), MS_OK);
    }
    assert_same_sims(a, b);
    float ba[2], bb[2];
    ck_assert_int_eq(ms_sim_boat(a, ba), MS_OK);
    ck_assert_int_eq(ms_sim_boat(b, bb), MS_OK);
    ck_assert(memcmp(ba, bb, sizeof ba) == 0);
    free(blob);
    ms_sim_destroy(a);
    ms_sim_destroy(b);
    ms_scene_destroy(sc);
}
END_TEST

START_TEST(restore_refuses_another_version_scene_size_or_blob)
{
    ms_scene *sc, *sc3, *damp;
    ms_sim *a = scene_sim("data/scenes/fig10.json", 1, &sc);
    ms_sim *other = scene_sim("data/scenes/fig3.json", 1, &sc3);
    const char *set[] = {"surface.damping=0.5"};
    ck_assert_int_eq(ms_scene_load_with_overrides("data/scenes/fig10.json", 1, set, &damp), MS_OK);
    ms_sim *damped = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(damp, 1, &damped), MS_OK);
    float dt = ms_scene_frame_dt(sc);
    for (int i = 0; i < 3; ++i)
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
    size_t bytes;
    unsigned char *blob = take_snapshot(a, &bytes);
    unsigned char *bad = malloc(bytes);
    size_t before_n;
    void *before = take_snapshot(other, &before_n);

    MS_ASSERT_REFUSED(ms_sim_restore(NULL, blob, bytes), MS_ERR_INVALID_ARGUMENT, "sim");
    MS_ASSERT_REFUSED(ms_sim_restore(a, NULL, bytes), MS_ERR_INVALID_ARGUMENT, "buf");
    MS_ASSERT_REFUSED(ms_sim_snapshot(a, blob, bytes - 1, NULL), MS_ERR_INVALID_ARGUMENT, "needs");
    MS_ASSERT_REFUSED(ms_sim_snapshot_size(a, NULL), MS_ERR_INVALID_ARGUMENT, "bytes");
    /* another scene, and the same scene with one key changed */
    MS_ASSERT_REFUSED(ms_sim_restore(other, blob, bytes), MS_ERR_INVALID_ARGUMENT, "another scene");
    MS_ASSERT_REFUSED(ms_sim_restore(damped, blob, bytes), MS_ERR_INVALID_ARGUMENT,
                      "another scene");
    /* cut, padded, not a snapshot, corrupt */
    MS_ASSERT_REFUSED(ms_sim_restore(other, blob, bytes - 8), MS_ERR_INVALID_ARGUMENT, "cut");
    MS_ASSERT_REFUSED(ms_sim_restore(other, blob, 10), MS_ERR_INVALID_ARGUMENT, "not a snapshot");
    memset(bad, 'x', bytes);
    MS_ASSERT_REFUSED(ms_sim_restore(other, bad, bytes), MS_ERR_INVALID_ARGUMENT, "not a snapshot");
    memcpy(bad, blob, bytes);
    bad[bytes / 2] ^= 1;
    MS_ASSERT_REFUSED(ms_sim_restore(a, bad, bytes), MS_ERR_INVALID_ARGUMENT, "checksum");
    /* another format version (bytes 12..15) and library version (40..71) */
    memcpy(bad, blob, bytes);
    bad[12] ^= 0x40;
    MS_ASSERT_REFUSED(ms_sim_restore(a, bad, bytes), MS_ERR_UNSUPPORTED, "format version");
    memcpy(bad, blob, bytes);
    memcpy(bad + 40, "0.0.0-elsewhere", 16);
    MS_ASSERT_REFUSED(ms_sim_restore(a, bad, bytes), MS_ERR_UNSUPPORTED, "library version");
    /* nothing refused changed the sim it was given */
    size_t after_n;
    void *after = take_snapshot(other, &after_n);
    ck_assert_uint_eq(before_n, after_n);
    ck_assert(memcmp(before, after, before_n) == 0);
    free(before);
    free(after);
    free(bad);
    free(blob);
    ms_sim_destroy(a);
    ms_sim_destroy(other);
    ms_sim_destroy(damped);
    ms_scene_destroy(sc);
    ms_scene_destroy(sc3);
    ms_scene_destroy(damp);
}
END_TEST

/* A failed sim gives no snapshot; a restore brings it back to life. */
START_TEST(restore_revives_a_failed_sim)
{
    ms_scene *sc;
    ms_sim *a = scene_sim("data/scenes/fig10.json", 1, &sc), *b = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &b), MS_OK);
    float dt = ms_scene_frame_dt(sc);
    for (int i = 0; i < 3; ++i)
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
    size_t bytes;
    void *blob = take_snapshot(a, &bytes);
    ms_sim_cancel(b);
    ck_assert_int_eq(ms_sim_step(b, dt), MS_ERR_CANCELED);
    MS_ASSERT_REFUSED(ms_sim_step(b, dt), MS_ERR_STATE, "failed");
    MS_ASSERT_REFUSED(ms_sim_snapshot(b, blob, bytes, NULL), MS_ERR_STATE, "failed");
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    for (int i = 0; i < 3; ++i) {
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
        ck_assert_msg(ms_sim_step(b, dt) == MS_OK, "%s", ms_last_error());
    }
    assert_same_sims(a, b);
    free(blob);
    ms_sim_destroy(a);
    ms_sim_destroy(b);
    ms_scene_destroy(sc);
}
END_TEST

/* A sim made from descs (an engine's, no scene): the same round trip. */
START_TEST(snapshot_of_a_desc_sim)
{
    ms_volume_desc vd = ms_volume_desc_default();
    ms_surface_desc sd = ms_surface_desc_default();
    sd.nx = sd.ny = 100;
    ms_sim_desc d = ms_sim_desc_default();
    d.volume = &vd;
    d.surface = &sd;
    d.field_nx = d.field_ny = 25;
    ms_sim *a = NULL, *b = NULL, *c = NULL;
    ck_assert_int_eq(ms_sim_create(&d, &a), MS_OK);
    ck_assert_int_eq(ms_sim_create(&d, &b), MS_OK);
    const float lo[3] = {0.0f, 0.0f, 0.0f}, hi[3] = {0.5f, 1.0f, 0.2f};
    ck_assert_int_eq(ms_volume_fill_box(ms_sim_volume(a), lo, hi), MS_OK);
    ck_assert_int_eq(ms_surface_add_drop(ms_sim_surface(a), 0.3f, 0.6f, 0.05f, 0.01f), MS_OK);
    for (int i = 0; i < 4; ++i)
        ck_assert_int_eq(ms_sim_step(a, 1.0f / 60), MS_OK);
    size_t bytes;
    void *blob = take_snapshot(a, &bytes);
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    for (int i = 0; i < 4; ++i) {
        ck_assert_int_eq(ms_sim_step(a, 1.0f / 60), MS_OK);
        ck_assert_int_eq(ms_sim_step(b, 1.0f / 60), MS_OK);
    }
    assert_same_sims(a, b);
    /* another desc: refused */
    sd.wave_speed = 0.4f;
    ck_assert_int_eq(ms_sim_create(&d, &c), MS_OK);
    MS_ASSERT_REFUSED(ms_sim_restore(c, blob, bytes), MS_ERR_INVALID_ARGUMENT, "another scene");
    free(blob);
    ms_sim_destroy(a);
    ms_sim_destroy(b);
    ms_sim_destroy(c);
}
END_TEST

/* ---- forged checkpoints: every value read is checked before use ---- */

/* The payload of the nth record `name` of a snapshot blob (the layout of
 * core/blob.h after the 72-byte header), its byte count in *len. */
static unsigned char *blob_record(unsigned char *blob, size_t bytes, const char *name, int nth,
                                  size_t *len)
{
    size_t pos = 72;
    while (pos + 24 <= bytes) {
        uint64_t n;
        memcpy(&n, blob + pos + 16, sizeof n);
        if (strncmp((const char *)blob + pos, name, 16) == 0 && nth-- == 0) {
            *len = (size_t)n;
            return blob + pos + 24;
        }
        pos += 24 + (((size_t)n + 7u) & ~(size_t)7u);
    }
    ck_abort_msg("no record '%s' in the snapshot", name);
    return NULL;
}

/* What a forger does after an edit: the checksum the writer computes. */
static void reseal(unsigned char *blob, size_t bytes)
{
    uint64_t sum = ms_blob_hash(MS_BLOB_HASH0, blob + 72, bytes - 72);
    memcpy(blob + 32, &sum, sizeof sum);
}

/* A fresh sim of sc refuses the blob with `status` and a message holding
 * both words; it is then failed, and refuses to step. */
static void assert_forgery_refused(ms_scene *sc, const unsigned char *blob, size_t bytes,
                                   ms_status status, const char *word, const char *bound)
{
    ms_sim *b = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &b), MS_OK);
    MS_ASSERT_REFUSED(ms_sim_restore(b, blob, bytes), status, word);
    ck_assert_msg(strstr(ms_last_error(), bound) != NULL, "message \"%s\" lacks \"%s\"",
                  ms_last_error(), bound);
    MS_ASSERT_REFUSED(ms_sim_step(b, ms_scene_frame_dt(sc)), MS_ERR_STATE, "restore failed");
    /* what the engine can still read of it stays in bounds */
    int n = 0;
    const float *pos[3], *vel[3];
    (void)ms_sim_particles(b, &n, pos, vel);
    ms_sim_destroy(b);
}

typedef struct forgery {
    const char *record;
    int nth;
    size_t offset; /* bytes into the payload */
    int is_float;  /* 1: a float, 0: an int32 */
    double value;
    ms_status status;
    const char *word, *bound; /* in the sentence: the value and its bound */
} forgery;

START_TEST(restore_refuses_a_forged_checkpoint)
{
    ms_scene *sc;
    ms_sim *a = scene_sim(SCENE, 1, &sc);
    float dt = ms_scene_frame_dt(sc);
    for (int i = 0; i < 4; ++i)
        ck_assert_int_eq(ms_sim_step(a, dt), MS_OK);
    /* a drag queued for the next frame is state too */
    const float dpos[2] = {0.4f, 0.5f}, dvel[2] = {0.5f, 0.0f};
    ck_assert_int_eq(ms_sim_drag(a, dpos, dvel, 0.1f, 0.05f, 5.0f), MS_OK);
    size_t bytes;
    unsigned char *blob = take_snapshot(a, &bytes), *bad = malloc(bytes);
    int n = 0;
    const float *pos[3], *vel[3];
    ck_assert_int_eq(ms_sim_particles(a, &n, pos, vel), MS_OK);
    ck_assert_int_gt(n, 100);
    const double nan = NAN;
    const forgery cases[] = {
        /* an id past the particles: the out-of-bounds write of the copy */
        {"vol.id", 0, 5 * 4, 0, n + 1000.0, MS_ERR_INVALID_ARGUMENT, "id", "outside [0, "},
        {"vol.id", 0, 7 * 4, 0, -3, MS_ERR_INVALID_ARGUMENT, "id -3", "outside [0, "},
        {"vol.id", 0, 9 * 4, 0, 0, MS_ERR_INVALID_ARGUMENT, "id 0", "once each"},
        /* counts no record backs, counts past the desc's bound */
        {"vol.n", 0, 0, 0, 2e9, MS_ERR_INVALID_ARGUMENT, "2000000000", "outside [0, "},
        {"vol.n", 0, 0, 0, n + 1, MS_ERR_INVALID_ARGUMENT, "vol.x", "count says"},
        {"sim.x.n", 1, 0, 0, n + 1, MS_ERR_INVALID_ARGUMENT, "sim.x.x", "count says"},
        {"sim.x.m", 1, 0, 0, n + 1, MS_ERR_INVALID_ARGUMENT, "marked", "at most all"},
        {"sim.p.n", 0, 0, 0, 1 << 30, MS_ERR_INVALID_ARGUMENT, "sim.p.n", "outside [0, "},
        {"sf.ndist", 0, 0, 0, 1 << 20, MS_ERR_INVALID_ARGUMENT, "1048576 disturbers", "bytes left"},
        /* floats: NaN, infinite, far outside the domain */
        {"vol.vx", 0, 3 * 4, 1, nan, MS_ERR_INVALID_ARGUMENT, "nan", "must be finite"},
        {"vol.x", 0, 0, 1, 1e30, MS_ERR_INVALID_ARGUMENT, "1e+30 m", "outside ["},
        {"sim.p.z", 1, 4, 1, -INFINITY, MS_ERR_INVALID_ARGUMENT, "-inf", "must be finite"},
        {"sim.x.y", 1, 0, 1, nan, MS_ERR_INVALID_ARGUMENT, "nan", "must be finite"},
        {"sf.h", 0, 400, 1, nan, MS_ERR_INVALID_ARGUMENT, "sf.h", "must be finite"},
        {"sim.hfield", 0, 40, 1, INFINITY, MS_ERR_INVALID_ARGUMENT, "inf", "must be finite"},
        {"vol.viscosity", 0, 0, 1, 1e9, MS_ERR_INVALID_ARGUMENT, "1e+09 Pa s",
         "outside [0, 1e+06]"},
        {"sim.dt_prev", 0, 0, 1, 1e9, MS_ERR_INVALID_ARGUMENT, "1e+09 s", "outside [0, 10]"},
        {"sim.n_time_last", 0, 0, 0, 2e9, MS_ERR_INVALID_ARGUMENT, "2000000000", "[0, 10000000]"},
        /* the settings that bound the extraction's work: this volume's own */
        {"sim.x.R", 1, 0, 1, 1e-30, MS_ERR_INVALID_ARGUMENT, "extraction radius R 1e-30 m",
         "this sim's volume has"},
        {"sim.x.R", 0, 0, 1, 1e30, MS_ERR_INVALID_ARGUMENT, "extraction radius R 1e+30 m",
         "this sim's volume has"},
        {"sim.x.spacing", 1, 0, 1, 1e-30, MS_ERR_INVALID_ARGUMENT, "extraction spacing 1e-30",
         "this sim's volume has 0.05 m"},
        {"sim.x.smooth", 1, 0, 0, 2e9, MS_ERR_INVALID_ARGUMENT,
         "extraction smoothing passes 2000000000", "this sim's volume has"},
        {"sim.x.lo", 0, 4, 1, -1e30, MS_ERR_INVALID_ARGUMENT, "extraction domain min y",
         "this sim's volume has"},
        /* a drag's radius bounds the particles it visits: ms_sim_drag's range */
        {"sim.drags", 0, 16, 1, 1e9, MS_ERR_INVALID_ARGUMENT, "sim.drags radius",
         "outside [1e-06, 100] m"},
        /* rain: the range and the drops-a-second cap of ms_surface_set_rain */
        {"sf.rain", 0, 4, 1, 1e9, MS_ERR_INVALID_ARGUMENT, "rain rate 1e+09", "outside [0, 1e+06]"},
        {"sf.rain", 0, 4, 1, 9e5, MS_ERR_INVALID_ARGUMENT, "rain rate 900000", "at most"},
        {"sf.rain", 0, 4, 1, nan, MS_ERR_INVALID_ARGUMENT, "rain rate nan", "outside"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        const forgery *f = &cases[c];
        memcpy(bad, blob, bytes);
        size_t len = 0;
        unsigned char *p = blob_record(bad, bytes, f->record, f->nth, &len);
        ck_assert_msg(f->offset + 4 <= len, "%s holds %zu bytes", f->record, len);
        if (f->is_float) {
            float v = (float)f->value;
            memcpy(p + f->offset, &v, sizeof v);
        } else {
            int32_t v = (int32_t)f->value;
            memcpy(p + f->offset, &v, sizeof v);
        }
        reseal(bad, bytes);
        assert_forgery_refused(sc, bad, bytes, f->status, f->word, f->bound);
    }
    /* a fresh sim's snapshot (both extraction slots zeros, never filled)
     * that claims frames were done: its zero radius and domain would reach
     * the extraction, so the zeros are refused */
    ms_sim *fresh = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &fresh), MS_OK);
    size_t fbytes;
    unsigned char *fblob = take_snapshot(fresh, &fbytes);
    ms_sim_destroy(fresh);
    size_t len = 0;
    int64_t calls = 5;
    memcpy(blob_record(fblob, fbytes, "sim.calls", 0, &len), &calls, sizeof calls);
    reseal(fblob, fbytes);
    assert_forgery_refused(sc, fblob, fbytes, MS_ERR_INVALID_ARGUMENT, "extraction radius R 0 m",
                           "this sim's volume has");
    free(fblob);
    /* the untouched blob still restores */
    ms_sim *b = NULL;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &b), MS_OK);
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    assert_same_sims(a, b);
    ms_sim_destroy(b);
    free(bad);
    free(blob);
    ms_sim_destroy(a);
    ms_scene_destroy(sc);
}
END_TEST

/* Read checkpoint slot `slot` of a run file: its blob (malloc'd), bytes
 * and frame. */
static unsigned char *read_slot(hid_t f, int slot, size_t *bytes, int64_t *frame)
{
    char name[32];
    snprintf(name, sizeof name, "checkpoint/%d", slot);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    ck_assert_int_ge(d, 0);
    int64_t n = 0;
    hid_t a = H5Aopen(d, "bytes", H5P_DEFAULT);
    ck_assert_int_ge(H5Aread(a, H5T_NATIVE_INT64, &n), 0);
    H5Aclose(a);
    a = H5Aopen(d, "frame", H5P_DEFAULT);
    ck_assert_int_ge(H5Aread(a, H5T_NATIVE_INT64, frame), 0);
    H5Aclose(a);
    hsize_t dims[1];
    hid_t sp = H5Dget_space(d);
    H5Sget_simple_extent_dims(sp, dims, NULL);
    unsigned char *buf = malloc(dims[0]);
    ck_assert_int_ge(H5Dread(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf), 0);
    H5Sclose(sp);
    H5Dclose(d);
    *bytes = (size_t)n;
    return buf;
}

static void write_slot(hid_t f, int slot, const unsigned char *buf)
{
    char name[32];
    snprintf(name, sizeof name, "checkpoint/%d", slot);
    hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    ck_assert_int_ge(H5Dwrite(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf), 0);
    H5Dclose(d);
}

/* A run file whose checkpoints were forged with care (a particle id past
 * the particles, the checksum recomputed): --resume refuses it in a
 * sentence with a non-zero exit and leaves the file's frames as they were.
 * A checkpoint claiming 3 GiB that the file does not store is not offered
 * (nothing is allocated for it): the resume replays instead. */
START_TEST(resume_refuses_a_forged_checkpoint_and_keeps_the_file)
{
    make_tmp_dir();
    const char *part = tmp_path("part.h5");
    const char *a[] = {"run", SCENE, "--frames", "4", "--quiet", "--out", part, NULL};
    ck_assert_msg(run_tool(a) == 0, "%s", log_text);
    hid_t f = H5Fopen(part, H5F_ACC_RDWR, H5P_DEFAULT);
    ck_assert_int_ge(f, 0);
    for (int slot = 0; slot < 2; ++slot) {
        size_t bytes;
        int64_t frame;
        unsigned char *blob = read_slot(f, slot, &bytes, &frame);
        size_t len;
        unsigned char *ids = blob_record(blob, bytes, "vol.id", 0, &len);
        int32_t id = 1 << 28;
        memcpy(ids + 4 * 10, &id, sizeof id);
        reseal(blob, bytes);
        write_slot(f, slot, blob);
        free(blob);
    }
    H5Fclose(f);
    const char *r[] = {"run", SCENE, "--frames", "8", "--resume", part, NULL};
    ck_assert_int_ne(run_tool(r), 0);
    ck_assert_msg(strstr(log_text, "id 268435456") && strstr(log_text, "outside [0, "), "%s",
                  log_text);
    ck_assert_int_eq(frames_now(part), 4);

    /* a slot that claims 3 GiB the file does not hold */
    const char *sparse = tmp_path("sparse.h5");
    const char *b[] = {"run", SCENE, "--frames", "4", "--quiet", "--out", sparse, NULL};
    ck_assert_msg(run_tool(b) == 0, "%s", log_text);
    f = H5Fopen(sparse, H5F_ACC_RDWR, H5P_DEFAULT);
    hid_t d = H5Dopen2(f, "checkpoint/0", H5P_DEFAULT);
    hsize_t big[1] = {(hsize_t)3 << 30};
    ck_assert_int_ge(H5Dset_extent(d, big), 0);
    hid_t at = H5Aopen(d, "bytes", H5P_DEFAULT);
    int64_t claim = (int64_t)big[0];
    ck_assert_int_ge(H5Awrite(at, H5T_NATIVE_INT64, &claim), 0);
    H5Aclose(at);
    H5Dclose(d);
    H5Fclose(f);
    ms_reader *rd;
    ck_assert_int_eq(ms_reader_open(sparse, &rd), MS_OK);
    long frames[2];
    ck_assert_int_eq(ms_reader_checkpoints(rd, frames), 1);
    size_t bytes = 0;
    ck_assert_int_eq(ms_reader_checkpoint_size(rd, 0, &bytes), MS_OK);
    ck_assert_uint_lt(bytes, (size_t)1 << 30);
    ms_reader_close(rd);
    const char *rs[] = {"run", SCENE, "--frames", "6", "--resume", sparse, NULL};
    ck_assert_msg(run_tool(rs) == 0, "%s", log_text);
    ck_assert_int_eq(frames_now(sparse), 6);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* Start args and wait until `path` lists at least `at` frames; the pid. */
static pid_t start_and_wait(const char *const *args, const char *path, long at)
{
    pid_t pid = start_tool(args);
    int status;
    while (frames_listed(path) < at) {
        ck_assert_msg(waitpid(pid, &status, WNOHANG) == 0, "the run ended before frame %ld", at);
        usleep(2000);
    }
    return pid;
}

/* SIGTERM: the tool finishes its frame and closes the file (exit 0 or
 * the signal's). */
static void stop(pid_t pid)
{
    int status;
    kill(pid, SIGTERM);
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
}

/* One writer per run file: while a run (or a resume) writes f.h5, a
 * --resume of it and another run with --out f.h5 --force are refused in one
 * sentence with exit 1, and the writer goes on: its file stays readable,
 * its sidecar lists what the file holds, and it resumes afterwards. */
START_TEST(a_second_writer_of_a_run_file_is_refused)
{
    make_tmp_dir();
    const char *f = tmp_path("f.h5");
    char xmf[600];
    snprintf(xmf, sizeof xmf, "%s/f.xmf", tmp_dir);
    const char *run[] = {"run", SCENE, "--frames", "100000", "--quiet", "--out", f, NULL};
    const char *resume[] = {"run", SCENE, "--frames", "100000", "--quiet", "--resume", f, NULL};
    /* --force: past the refusal of an existing run, to the writer's lock */
    const char *again[] = {"run", SCENE, "--frames", "3", "--quiet", "--out", f, "--force", NULL};
    for (int round = 0; round < 2; ++round) {
        /* pass 0: a run is writing; pass 1: a resume is */
        pid_t first = start_and_wait(round == 0 ? run : resume, f, frames_listed(f) + 2);
        ck_assert_int_eq(run_tool(resume), 1);
        ck_assert_msg(strstr(log_text, "is being written by another process") &&
                          strstr(log_text, "one writer per run file"),
                      "%s", log_text);
        ck_assert_int_eq(run_tool(again), 1);
        ck_assert_msg(strstr(log_text, "is being written by another process"), "%s", log_text);
        long before = frames_listed(f);
        stop(first);
        ck_assert(ms_test_wait_unused(f, 30.0));
        long n = frames_now(f);
        ck_assert_int_ge(n, before);
        ck_assert_int_eq(frames_listed(f), n); /* the sidecar agrees with the file */
    }
    /* no writer left: a resume goes on */
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(f, &r), MS_OK);
    long n = ms_reader_frames(r);
    ms_reader_close(r);
    char frames[32];
    snprintf(frames, sizeof frames, "%ld", n + 2);
    const char *more[] = {"run", SCENE, "--frames", frames, "--quiet", "--resume", f, NULL};
    ck_assert_msg(run_tool(more) == 0, "%s", log_text);
    ck_assert_int_eq(frames_now(f), n + 2);
    ms_test_remove_tree(tmp_dir);
}
END_TEST

/* How often needle occurs in hay. */
static int count_of(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle))
        ++n;
    return n;
}

/* Spray and foam in the run file: each frame's droplets and cover as the
 * sim showed them, listed in run.xmf and the legacy run.xdmf2; the checkpoint holds them, so a sim
 * restored from it throws the same spray as the one never stopped. */
START_TEST(spray_is_written_read_back_and_restored)
{
    make_tmp_dir();
    static const char text[] =
        "{\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.5]}, \"frame_dt\": 0.016667,"
        " \"volume\": {\"spacing\": 0.04, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.4, "
        "0.12]}, {\"min\": [0.12, 0.12, 0.3], \"max\": [0.28, 0.28, 0.45]}], \"field\": [16, 16]},"
        " \"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.3, \"damping\": 0.9},"
        " \"effects\": {\"spray\": {\"budget\": 300}}}";
    ms_scene *sc;
    ck_assert_msg(ms_scene_parse(text, strlen(text), &sc) == MS_OK, "%s", ms_last_error());
    ms_sim *sim;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    ms_writer *w;
    ck_assert_msg(ms_writer_open(tmp_path("s.h5"), sim, MS_FIELD_COMBINED, &w) == MS_OK, "%s",
                  ms_last_error());
    enum { F = 30 };
    static float drops[F][300 * 3], foam[F][64 * 64];
    int count[F], most = 0;
    for (int i = 0; i < F; ++i) {
        ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
        ck_assert_int_eq(ms_writer_frame(w, sim), MS_OK);
        const float *xyz = ms_sim_spray(sim, &count[i]);
        memcpy(drops[i], xyz, (size_t)count[i] * 3 * sizeof(float));
        memcpy(foam[i], ms_sim_foam(sim, NULL, NULL), sizeof foam[i]);
        most = count[i] > most ? count[i] : most;
    }
    ck_assert_int_gt(most, 10);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("s.h5"), &r), MS_OK);
    ck_assert_int_eq(ms_reader_spray_budget(r), 300);
    ms_grid g;
    ck_assert_int_eq(ms_reader_foam_grid(r, &g), MS_OK);
    ck_assert_int_eq(g.nx, 64);
    ck_assert_float_eq(g.dx, 0.4f / 64);
    static float got[300 * 3], cover[64 * 64];
    for (int i = 0; i < F; ++i) {
        int n = -1;
        ck_assert_int_eq(ms_reader_read_spray(r, i, got, 300, &n), MS_OK);
        ck_assert_int_eq(n, count[i]);
        ck_assert(memcmp(got, drops[i], (size_t)n * 3 * sizeof(float)) == 0);
        ck_assert_int_eq(ms_reader_read_foam(r, i, cover, 64 * 64), MS_OK);
        ck_assert(memcmp(cover, foam[i], sizeof cover) == 0);
    }
    int n;
    MS_ASSERT_REFUSED(ms_reader_read_spray(r, F, got, 300, &n), MS_ERR_INVALID_ARGUMENT, "outside");
    MS_ASSERT_REFUSED(ms_reader_read_foam(r, 0, cover, 10), MS_ERR_INVALID_ARGUMENT, "4096");
    /* the checkpoint of the last frame continues the spray bit for bit */
    size_t bytes = 0;
    ck_assert_int_eq(ms_reader_checkpoint_size(r, 0, &bytes), MS_OK);
    void *blob = malloc(bytes);
    ck_assert_int_eq(ms_reader_read_checkpoint(r, 0, blob, bytes), MS_OK);
    ms_sim *b;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &b), MS_OK);
    ck_assert_msg(ms_sim_restore(b, blob, bytes) == MS_OK, "%s", ms_last_error());
    for (int i = 0; i < 20; ++i) {
        ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
        ck_assert_int_eq(ms_sim_step(b, 1.0f / 60), MS_OK);
        int na, nb;
        const float *pa = ms_sim_spray(sim, &na), *pb = ms_sim_spray(b, &nb);
        ck_assert_int_eq(na, nb);
        ck_assert(memcmp(pa, pb, (size_t)na * 3 * sizeof(float)) == 0);
        ck_assert(memcmp(ms_sim_foam(sim, NULL, NULL), ms_sim_foam(b, NULL, NULL),
                         64 * 64 * sizeof(float)) == 0);
    }
    free(blob);
    ms_reader_close(r);
    /* ParaView's sidecar lists the droplets and the foam */
    size_t len = 0;
    char *xmf = slurp(tmp_path("s.xmf"), &len);
    ck_assert_ptr_nonnull(xmf);
    ck_assert_ptr_nonnull(strstr(xmf, "<Grid Name=\"spray\""));
    ck_assert_ptr_nonnull(strstr(xmf, ":/foam|29 0 0:1 1 1:1 64 64:30 64 64"));
    free(xmf);
    /* and so does the legacy one: its grid files foam.xml (every frame) and
     * spray.xml (the frames in which droplets fly), HyperSlabs of the same
     * datasets */
    int flying = 0, last = -1;
    for (int i = 0; i < F; ++i)
        if (count[i] > 0) {
            flying++;
            last = i;
        }
    ck_assert_int_gt(flying, 0);
    xmf = slurp(tmp_path("s.xdmf2"), &len);
    ck_assert_ptr_nonnull(xmf);
    ck_assert_ptr_nonnull(strstr(xmf, "s.xdmf2.d/foam.xml"));
    ck_assert_ptr_nonnull(strstr(xmf, "s.xdmf2.d/spray.xml"));
    free(xmf);
    xmf = slurp(tmp_path("s.xdmf2.d/foam.xml"), &len);
    ck_assert_ptr_nonnull(xmf);
    ck_assert_int_eq(count_of(xmf, "<Grid Name=\"foam\" GridType=\"Uniform\">"), F);
    ck_assert_ptr_nonnull(strstr(xmf, ">29 0 0 1 1 1 1 64 64</DataItem>"));
    ck_assert_ptr_nonnull(strstr(xmf, "Dimensions=\"30 64 64\" NumberType=\"Float\" "
                                      "Precision=\"4\" Format=\"HDF\">s.h5:/foam<"));
    free(xmf);
    xmf = slurp(tmp_path("s.xdmf2.d/spray.xml"), &len);
    ck_assert_ptr_nonnull(xmf);
    ck_assert_int_eq(count_of(xmf, "<Grid Name=\"spray\" GridType=\"Uniform\">"), flying);
    char want[160];
    snprintf(want, sizeof want, ">%d 0 0 1 1 1 1 %d 3</DataItem>", last, count[last]);
    ck_assert_msg(strstr(xmf, want), "no %s", want);
    snprintf(want, sizeof want, "Dimensions=\"%d 300 3\" NumberType=\"Float\"", last + 1);
    ck_assert_msg(strstr(xmf, want), "no %s", want);
    free(xmf);
    /* a file without spray has none */
    ms_sim_destroy(b);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    ck_assert_int_eq(ms_scene_load("data/scenes/fig3.json", &sc), MS_OK);
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    ck_assert_int_eq(ms_writer_open(tmp_path("n.h5"), sim, 0, &w), MS_OK);
    ck_assert_int_eq(ms_sim_step(sim, 1.0f / 60), MS_OK);
    ck_assert_int_eq(ms_writer_frame(w, sim), MS_OK);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ck_assert_int_eq(ms_reader_open(tmp_path("n.h5"), &r), MS_OK);
    ck_assert_int_eq(ms_reader_spray_budget(r), 0);
    MS_ASSERT_REFUSED(ms_reader_read_spray(r, 0, got, 300, &n), MS_ERR_INVALID_ARGUMENT,
                      "no spray");
    MS_ASSERT_REFUSED(ms_reader_foam_grid(r, &g), MS_ERR_INVALID_ARGUMENT, "no foam");
    ms_reader_close(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
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
    tcase_add_test(tc, resume_refusals_leave_a_killed_file_byte_for_byte);
    tcase_add_test(tc, resume_refuses_a_file_this_build_does_not_reproduce);
    tcase_add_test(tc, resume_from_an_older_checkpoint_or_none);
    tcase_add_test(tc, checkpoint_every_out_of_range_is_refused);
    tcase_add_test(tc, resume_refuses_a_forged_checkpoint_and_keeps_the_file);
    tcase_add_test(tc, a_second_writer_of_a_run_file_is_refused);
    tcase_add_test(tc, spray_is_written_read_back_and_restored);
    suite_add_tcase(s, tc);
    TCase *api = tcase_create("snapshot");
    tcase_set_timeout(api, 120);
    tcase_add_test(api, snapshot_restore_continues_bit_for_bit);
    tcase_add_test(api, snapshot_keeps_what_an_engine_changed);
    tcase_add_test(api, restore_refuses_another_version_scene_size_or_blob);
    tcase_add_test(api, restore_revives_a_failed_sim);
    tcase_add_test(api, snapshot_of_a_desc_sim);
    tcase_add_test(api, restore_refuses_a_forged_checkpoint);
    suite_add_tcase(s, api);
    return s;
}

int main(void)
{
    return ms_test_run(resume_suite());
}
