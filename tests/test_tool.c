/* tool: the `modesplit` command line, driven as a user would (fork + exec
 * of build/bin/modesplit): usage and exit codes, every malformed scene of
 * tests/data/bad_scenes refused with status 2 and a sentence that names
 * it (the same sentence from check and from run), a run's HDF5 + XDMF + PNG output, SIGKILL / SIGINT / SIGTERM in the
 * middle of a run, unwritable paths, the progress display on a terminal
 * and off it; and the writer on a real sim, read back bit for bit. */
#define _GNU_SOURCE /* posix_openpt, grantpt, unlockpt, ptsname; unshare */
#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "support.h"

#define DEFAULT_SCENE "data/scenes/default.json"
#define SMALL_SCENE "tests/data/small_run.json" /* fast: 64x48 waves, 450 particles */
#define BAD_DIR "tests/data/bad_scenes"

/* ---- helpers ---------------------------------------------------------- */

static char tmp_dir[256];

static void make_tmp_dir(void)
{
    ck_assert_int_eq(ms_test_tmp_dir(tmp_dir, sizeof tmp_dir, "ms_tool"), 0);
}

/* A path in the test's directory; each call returns a fresh string, all
 * freed by remove_tmp_dir. */
static char *paths[1024];
static int npaths;

static char *tmp_path(const char *name)
{
    size_t n = strlen(tmp_dir) + strlen(name) + 2;
    char *p = malloc(n);
    snprintf(p, n, "%s/%s", tmp_dir, name);
    ck_assert_int_lt(npaths, 1024);
    paths[npaths++] = p;
    return p;
}

static void remove_tmp_dir(void)
{
    ms_test_remove_tree(tmp_dir);
    for (int i = 0; i < npaths; ++i)
        free(paths[i]);
    npaths = 0;
}

/* The directory of the tool (BUILD/bin). */
static const char *tool_dir(void)
{
    static char d[512];
    snprintf(d, sizeof d, "%s", ms_test_tool_path());
    char *slash = strrchr(d, '/');
    if (slash)
        *slash = '\0';
    return d;
}

static int count_lines(const char *s)
{
    int n = 0;
    for (; *s; ++s)
        n += *s == '\n';
    return n;
}

typedef struct result {
    int status; /* waitpid status */
    char *out, *err;
} result;

static result run_tool(const char *const *args)
{
    result r;
    char out[512], err[512];
    snprintf(out, sizeof out, "%s/stdout.txt", tmp_dir);
    snprintf(err, sizeof err, "%s/stderr.txt", tmp_dir);
    r.status = ms_test_run_tool(args, out, err);
    r.out = ms_test_slurp(out);
    r.err = ms_test_slurp(err);
    return r;
}

static void result_free(result *r)
{
    free(r->out);
    free(r->err);
}

static int exited(const result *r, int code)
{
    return WIFEXITED(r->status) && WEXITSTATUS(r->status) == code;
}

#define ASSERT_EXIT(r, code)                                                          \
    ck_assert_msg(exited(&(r), code), "exit %d (signal %d), expected %d; stderr: %s", \
                  WIFEXITED((r).status) ? WEXITSTATUS((r).status) : -1,               \
                  WIFSIGNALED((r).status) ? WTERMSIG((r).status) : 0, code, (r).err)

/* Frames a run file holds right now (-1 if it does not open). */
static long frames_in(const char *path)
{
    ms_reader *r;
    if (ms_reader_open(path, &r) != MS_OK)
        return -1;
    long n = ms_reader_frames(r);
    ms_reader_close(r);
    return n;
}

/* Frames `modesplit info` sees in a file (-1 if it cannot read it now).
 * A file being written is read through the tool, as a user would: HDF5
 * 1.10.8 can leak (and complain at exit) after opening a file caught in
 * the middle of a flush, which must not count against this process. */
static long frames_via_info(const char *path)
{
    result r = run_tool((const char *[]){"info", path, NULL});
    long n = -1;
    const char *p = strstr(r.out, "\n  frames    ");
    if (exited(&r, 0) && p)
        n = strtol(p + 14, NULL, 10);
    result_free(&r);
    return n;
}

/* Wait until the file holds at least n frames (reading it while the run
 * goes on); 0 on time-out. */
static int wait_for_frames(const char *path, long n, double timeout_s)
{
    double start = 0;
    for (int i = 0; start < timeout_s; ++i, start += 0.05) {
        if (frames_via_info(path) >= n)
            return 1;
        struct timespec ts = {0, 50000000};
        nanosleep(&ts, NULL);
    }
    return 0;
}

/* ---- usage ---------------------------------------------------------------- */

START_TEST(help_version_and_usage_errors)
{
    make_tmp_dir();
    result r = run_tool((const char *[]){"--help", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_ptr_nonnull(strstr(r.out, "usage: modesplit <command>"));
    ck_assert_ptr_nonnull(strstr(r.out, "--frames N"));
    ck_assert_str_eq(r.err, "");
    result_free(&r);
    r = run_tool((const char *[]){"run", "--help", NULL});
    ASSERT_EXIT(r, 0);
    result_free(&r);
    r = run_tool((const char *[]){"--version", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_ptr_nonnull(strstr(r.out, ms_version()));
    result_free(&r);
    r = run_tool((const char *[]){NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "usage:"));
    result_free(&r);
    r = run_tool((const char *[]){"explode", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "unknown command \"explode\""));
    ck_assert_int_eq(count_lines(r.err), 1);
    result_free(&r);

    /* each bad option: status 2, one sentence naming it */
    static const char *const bad[][6] = {
        {"run", NULL},
        {"run", DEFAULT_SCENE, "--frames", "many", NULL},
        {"run", DEFAULT_SCENE, "--frames", NULL},
        {"run", DEFAULT_SCENE, "--duration", "-1", NULL},
        {"run", DEFAULT_SCENE, "--frames", "3", "--duration", "1"},
        {"run", DEFAULT_SCENE, "--threads", "3", NULL},
        {"run", DEFAULT_SCENE, "--out", "x.h5", "--no-out", NULL},
        {"run", DEFAULT_SCENE, "--fast", NULL},
        {"run", DEFAULT_SCENE, DEFAULT_SCENE, NULL},
        {"info", NULL},
        {"info", "a.h5", "b.h5", NULL},
        {"check", NULL},
        {"check", "--deep", NULL},
        {"plugins", "extra", NULL},
    };
    static const char *const word[] = {
        "which scene",  "--frames many", "needs a value", "--duration -1", "not both",
        "--threads 3",  "not both",      "--fast",        "one scene",     "which run file",
        "one run file", "which scenes",  "--deep",        "no arguments"};
    for (size_t i = 0; i < sizeof word / sizeof *word; ++i) {
        const char *args[8] = {0};
        for (int k = 0; k < 6 && bad[i][k]; ++k)
            args[k] = bad[i][k];
        r = run_tool(args);
        ASSERT_EXIT(r, 2);
        ck_assert_msg(strstr(r.err, word[i]) && count_lines(r.err) == 1,
                      "case %zu: stderr \"%s\" lacks \"%s\"", i, r.err, word[i]);
        result_free(&r);
    }
    remove_tmp_dir();
}
END_TEST

/* ---- malformed scenes ------------------------------------------------------ */

static int have_shader_plugins(void)
{
    int n = ms_plugin_count();
    for (int i = 0; i < n; ++i) {
        ms_plugin_description d = ms_plugin_description_init();
        if (ms_plugin_describe(i, &d) == MS_OK && !strcmp(d.kind, "shader"))
            return 1;
    }
    return 0;
}

START_TEST(every_malformed_scene_exits_2_naming_the_problem)
{
    make_tmp_dir();
    FILE *f = fopen(BAD_DIR "/expect.txt", "r");
    ck_assert_ptr_nonnull(f);
    char line[512];
    int cases = 0, skipped = 0;
    int shaders = have_shader_plugins();
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == '\n')
            continue;
        line[strcspn(line, "\n")] = '\0';
        char *name = strtok(line, "\t"), *phrase = strtok(NULL, "\t"), *needs = strtok(NULL, "\t");
        ck_assert_ptr_nonnull(phrase);
        char path[600];
        snprintf(path, sizeof path, BAD_DIR "/%s", name);
        ck_assert_msg(access(path, R_OK) == 0, "%s is listed but missing", path);
        if (needs && !strcmp(needs, "shader") && !shaders) {
            /* refused only once shader plugins exist: accepted today */
            result r = run_tool((const char *[]){"check", path, NULL});
            ASSERT_EXIT(r, 0);
            result_free(&r);
            ++skipped;
            continue;
        }
        const char *const *modes[2] = {(const char *[]){"check", path, NULL},
                                       (const char *[]){"run", path, "--no-out", NULL}};
        char *verdict = NULL; /* check's sentence, which run must say word for word */
        for (int m = 0; m < 2; ++m) {
            result r = run_tool(modes[m]);
            ck_assert_msg(WIFEXITED(r.status), "%s crashed (signal %d)", name, WTERMSIG(r.status));
            ck_assert_msg(exited(&r, 2), "%s: exit %d, stderr: %s", name, WEXITSTATUS(r.status),
                          r.err);
            ck_assert_msg(count_lines(r.err) == 1, "%s: not one line: %s", name, r.err);
            ck_assert_msg(strstr(r.err, name) != NULL, "%s: message does not name the file: %s",
                          name, r.err);
            ck_assert_msg(strstr(r.err, phrase) != NULL, "%s: message lacks \"%s\": %s", name,
                          phrase, r.err);
            ck_assert_msg(strncmp(r.err, "modesplit: ", 11) == 0, "%s: %s", name, r.err);
            if (m == 0)
                verdict = strdup(r.err);
            else
                ck_assert_msg(!strcmp(verdict, r.err), "%s: check said %s, run said %s", name,
                              verdict, r.err);
            result_free(&r);
        }
        free(verdict);
        ++cases;
    }
    fclose(f);
    ck_assert_int_ge(cases + skipped, 30);
    ck_assert_int_ge(cases, 30);
    /* no directory entry is left out of the list */
    DIR *d = opendir(BAD_DIR);
    int files = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        files += strstr(e->d_name, ".json") != NULL;
    closedir(d);
    ck_assert_int_eq(files, cases + skipped);
    /* a scene file that does not exist is bad input too */
    result r = run_tool((const char *[]){"check", "no/such/scene.json", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "no/such/scene.json"));
    result_free(&r);
    remove_tmp_dir();
}
END_TEST

/* ---- runs ------------------------------------------------------------------ */

/* A --png that is a file is refused before the run file is created:
 * nothing empty is left behind. */
START_TEST(png_pointing_at_a_file_leaves_no_empty_run_file)
{
    make_tmp_dir();
    const char *file = tmp_path("not_a_dir");
    FILE *f = fopen(file, "w");
    ck_assert_ptr_nonnull(f);
    fputs("x", f);
    fclose(f);
    result r = run_tool((const char *[]){"run", DEFAULT_SCENE, "--frames", "2", "--out",
                                         tmp_path("left.h5"), "--png", file, NULL});
    ck_assert_msg(WIFEXITED(r.status) && WEXITSTATUS(r.status) == 1, "%s", r.err);
    ck_assert_msg(strstr(r.err, "not_a_dir"), "%s", r.err);
    result_free(&r);
    ck_assert_int_ne(access(tmp_path("left.h5"), F_OK), 0);
    ck_assert_int_ne(access(tmp_path("left.xmf"), F_OK), 0);
    ck_assert_int_ne(access(tmp_path("left.xdmf2"), F_OK), 0);
    remove_tmp_dir();
}
END_TEST

START_TEST(run_writes_hdf5_xdmf_png_and_a_summary)
{
    make_tmp_dir();
    const char *out = tmp_path("demo.h5");
    const char *png = tmp_path("png/frames");
    result r = run_tool(
        (const char *[]){"run", DEFAULT_SCENE, "--frames", "6", "--out", out, "--png", png, NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_msg(strstr(r.out, "6 of 6 frames"), "%s", r.out);
    ck_assert_ptr_nonnull(strstr(r.out, "per frame: volume"));
    ck_assert_ptr_nonnull(strstr(r.out, "demo.xmf"));
    ck_assert_ptr_nonnull(strstr(r.out, "3 PNG frames"));
    /* not a terminal: plain progress lines, ending at 100 % */
    ck_assert_ptr_nonnull(strstr(r.err, "frame 6/6 (100%)"));
    ck_assert_ptr_null(strstr(r.err, "\r"));
    result_free(&r);

    ms_scene *sc;
    ck_assert_int_eq(ms_scene_load(DEFAULT_SCENE, &sc), MS_OK);
    ms_reader *rd;
    ck_assert_msg(ms_reader_open(out, &rd) == MS_OK, "%s", ms_last_error());
    /* every 2nd frame of 6, the fields the scene asks for, its text */
    ck_assert_int_eq(ms_reader_frames(rd), 6 / ms_scene_output_every(sc));
    ck_assert_uint_eq(ms_reader_fields(rd), ms_scene_output_fields(sc));
    ck_assert_str_eq(ms_reader_scene(rd), ms_scene_text(sc));
    ck_assert_str_eq(ms_reader_scene_name(rd), "default");
    ms_reader_close(rd);
    ms_scene_destroy(sc);
    MS_ASSERT_H5DUMP_READS(out);
    for (int i = 0; i < 3; ++i) {
        char p[600];
        snprintf(p, sizeof p, "%s/frame_%05d.png", png, i);
        ck_assert_msg(access(p, R_OK) == 0, "%s missing", p);
    }
    char *x = ms_test_slurp(tmp_path("demo.xmf"));
    ck_assert_ptr_nonnull(strstr(x, "demo.h5:/fields/combined"));
    free(x);

    r = run_tool((const char *[]){"info", out, NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_ptr_nonnull(strstr(r.out, "frames    3"));
    ck_assert_ptr_nonnull(strstr(r.out, "combined"));
    ck_assert_ptr_nonnull(strstr(r.out, "H5Part"));
    result_free(&r);
    r = run_tool((const char *[]){"info", "--scene", out, NULL});
    ASSERT_EXIT(r, 0);
    char *scene = ms_test_slurp(DEFAULT_SCENE);
    ck_assert_str_eq(r.out, scene);
    free(scene);
    result_free(&r);

    /* --quiet: nothing on either stream; --no-out: no file; --preview */
    const char *pv = tmp_path("preview");
    r = run_tool((const char *[]){"run", DEFAULT_SCENE, "--frames", "2", "--no-out", "--quiet",
                                  "--png", pv, "--preview", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_str_eq(r.out, "");
    ck_assert_str_eq(r.err, "");
    result_free(&r);
    char pf[600];
    snprintf(pf, sizeof pf, "%s/frame_00000.png", pv);
    ck_assert_int_eq(access(pf, R_OK), 0);
    remove_tmp_dir();
}
END_TEST

/* The writer on the real sim: what is read back is what the sim held. */
START_TEST(run_file_holds_what_the_sim_held_bit_for_bit)
{
    make_tmp_dir();
    ms_scene *sc;
    ck_assert_int_eq(ms_scene_load(DEFAULT_SCENE, &sc), MS_OK);
    ms_sim *sim;
    ck_assert_msg(ms_sim_create_from_scene(sc, 1, &sim) == MS_OK, "%s", ms_last_error());
    ms_writer *w;
    const unsigned all =
        MS_FIELD_COMBINED | MS_FIELD_SURFACE | MS_FIELD_VOLUME | MS_FIELD_PARTICLES;
    ck_assert_msg(ms_writer_open(tmp_path("rt.h5"), sim, all, &w) == MS_OK, "%s", ms_last_error());
    enum { FRAMES = 4 };
    float *copy[FRAMES][3];
    float *pcopy[FRAMES][6];
    int np[FRAMES];
    double t[FRAMES];
    for (int k = 0; k < FRAMES; ++k) {
        ck_assert_int_eq(ms_sim_step(sim, ms_scene_frame_dt(sc)), MS_OK);
        ck_assert_msg(ms_writer_frame(w, sim) == MS_OK, "%s", ms_last_error());
        int nx, ny;
        const float *v[3] = {ms_sim_height(sim, &nx, &ny), NULL, NULL};
        for (int s = 0; s < 3; ++s) {
            v[s] = s == 0   ? ms_sim_height(sim, &nx, &ny)
                   : s == 1 ? ms_sim_surface_height(sim, &nx, &ny)
                            : ms_sim_volume_height(sim, &nx, &ny);
            copy[k][s] = malloc(sizeof(float) * (size_t)nx * ny);
            memcpy(copy[k][s], v[s], sizeof(float) * (size_t)nx * ny);
        }
        const float *pos[3], *vel[3];
        ck_assert_int_eq(ms_sim_particles(sim, &np[k], pos, vel), MS_OK);
        ck_assert_int_gt(np[k], 0);
        for (int c = 0; c < 6; ++c) {
            pcopy[k][c] = malloc(sizeof(float) * (size_t)np[k]);
            memcpy(pcopy[k][c], c < 3 ? pos[c] : vel[c - 3], sizeof(float) * (size_t)np[k]);
        }
        t[k] = ms_sim_time(sim);
    }
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    /* a field the sim lacks is refused */
    ms_sim_destroy(sim);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("rt.h5"), &r), MS_OK);
    ck_assert_int_eq(ms_reader_frames(r), FRAMES);
    for (int k = 0; k < FRAMES; ++k) {
        double tk;
        ck_assert_int_eq(ms_reader_time(r, k, &tk), MS_OK);
        ck_assert_mem_eq(&tk, &t[k], sizeof tk);
        for (int s = 0; s < 3; ++s) {
            ms_grid g;
            ck_assert_int_eq(ms_reader_field_grid(r, 1u << s, &g), MS_OK);
            size_t n = (size_t)g.nx * g.ny;
            float *got = malloc(n * sizeof *got);
            ck_assert_int_eq(ms_reader_read_field(r, 1u << s, k, got, n), MS_OK);
            ck_assert_msg(memcmp(got, copy[k][s], n * sizeof *got) == 0, "field %d frame %d", s, k);
            free(got);
            free(copy[k][s]);
        }
        int n;
        ck_assert_int_eq(ms_reader_particle_count(r, k, &n), MS_OK);
        ck_assert_int_eq(n, np[k]);
        float *p[6];
        for (int c = 0; c < 6; ++c)
            p[c] = malloc(sizeof(float) * (size_t)n);
        ck_assert_int_eq(ms_reader_read_particles(r, k, n, p, p + 3), MS_OK);
        for (int c = 0; c < 6; ++c) {
            ck_assert_mem_eq(p[c], pcopy[k][c], sizeof(float) * (size_t)n);
            free(p[c]);
            free(pcopy[k][c]);
        }
    }
    ms_reader_close(r);
    ms_scene_destroy(sc);
    remove_tmp_dir();
}
END_TEST

START_TEST(writer_refuses_fields_the_sim_lacks)
{
    make_tmp_dir();
    ms_scene *sc;
    /* waves only (Fig. 3): no volume, so no volume field and no particles */
    ck_assert_int_eq(ms_scene_load("data/scenes/fig3.json", &sc), MS_OK);
    ms_sim *sim;
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    ms_writer *w;
    MS_ASSERT_REFUSED(ms_writer_open(tmp_path("x.h5"), sim, MS_FIELD_VOLUME, &w),
                      MS_ERR_INVALID_ARGUMENT, "no volume");
    MS_ASSERT_REFUSED(ms_writer_open(tmp_path("x.h5"), sim, MS_FIELD_PARTICLES, &w),
                      MS_ERR_INVALID_ARGUMENT, "particles");
    MS_ASSERT_REFUSED(ms_writer_open(tmp_path("x.h5"), NULL, 0, &w), MS_ERR_INVALID_ARGUMENT,
                      "sim");
    /* 0: what the scene asks for */
    ck_assert_int_eq(ms_writer_open(tmp_path("x.h5"), sim, 0, &w), MS_OK);
    ck_assert_int_eq(ms_writer_close(w), MS_OK);
    ms_reader *r;
    ck_assert_int_eq(ms_reader_open(tmp_path("x.h5"), &r), MS_OK);
    ck_assert_uint_eq(ms_reader_fields(r),
                      ms_scene_output_fields(sc) & ~(unsigned)MS_FIELD_PARTICLES);
    ms_reader_close(r);
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    remove_tmp_dir();
}
END_TEST

/* ---- interruptions ---------------------------------------------------------- */

START_TEST(sigkill_mid_run_leaves_a_file_h5dump_and_info_read)
{
    make_tmp_dir();
    const char *out = tmp_path("killed.h5");
    for (int round = 0; round < 3; ++round) {
        remove(out);
        /* each round replaces the last one's run (its sidecars are left) */
        pid_t pid = ms_test_spawn_tool((const char *[]){"run", SMALL_SCENE, "--frames", "100000",
                                                        "--out", out, "--force", "--quiet", NULL},
                                       tmp_path("o.txt"), tmp_path("e.txt"));
        /* readable while the run goes on */
        int ok = wait_for_frames(out, 2 + round, 60);
        long seen = frames_via_info(out);
        struct timespec ts = {0, 1000000L * (7 * round)};
        nanosleep(&ts, NULL);
        kill(pid, SIGKILL);
        int status;
        waitpid(pid, &status, 0);
        ck_assert_msg(ok, "no frames appeared");
        ck_assert(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
        /* the writer's helper finishes the flush it was handed (h5_atomic.c) */
        ck_assert(ms_test_wait_unused(out, 10));
        MS_ASSERT_H5DUMP_READS(out);
        ck_assert_int_ge(frames_in(out), seen);
        result r = run_tool((const char *[]){"info", out, NULL});
        ASSERT_EXIT(r, 0);
        ck_assert_ptr_nonnull(strstr(r.out, "frames"));
        result_free(&r);
        char *x = ms_test_slurp(tmp_path("killed.xmf"));
        ck_assert_ptr_nonnull(strstr(x, "</Xdmf>"));
        free(x);
    }
    remove_tmp_dir();
}
END_TEST

START_TEST(sigint_and_sigterm_finish_the_frame_and_close_the_file)
{
    make_tmp_dir();
    const int sigs[2] = {SIGINT, SIGTERM};
    for (int i = 0; i < 2; ++i) {
        const char *out = tmp_path("stopped.h5");
        remove(out);
        pid_t pid = ms_test_spawn_tool((const char *[]){"run", SMALL_SCENE, "--frames", "100000",
                                                        "--out", out, "--force", NULL},
                                       tmp_path("o.txt"), tmp_path("e.txt"));
        ck_assert(wait_for_frames(out, 2, 60));
        kill(pid, sigs[i]);
        int status;
        waitpid(pid, &status, 0);
        /* ends by the signal, as shells expect, after closing the file */
        ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == sigs[i], "status %d", status);
        char *o = ms_test_slurp(tmp_path("o.txt"));
        ck_assert_msg(strstr(o, i == 0 ? "stopped by SIGINT" : "stopped by SIGTERM"), "%s", o);
        long in_file = frames_in(out);
        char want[64];
        snprintf(want, sizeof want, "(%ld frames,", in_file);
        ck_assert_msg(strstr(o, want), "summary \"%s\" disagrees with the file's %ld frames", o,
                      in_file);
        free(o);
        MS_ASSERT_H5DUMP_READS(out);
    }
    remove_tmp_dir();
}
END_TEST

static double tool_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* A frame that takes minutes (courant 1e-5: ~4e5 SPH sub-steps a frame):
 * the first SIGTERM asks for the frame in hand to finish, the second
 * cancels it (ms_sim_cancel), and the run still closes its file, says so
 * and ends by the signal, in well under the frame's time. */
START_TEST(a_second_sigterm_cancels_a_long_frame_and_closes_the_file)
{
    make_tmp_dir();
    const char *scene = tmp_path("slow.json");
    FILE *f = fopen(scene, "w");
    ck_assert_ptr_nonnull(f);
    fputs("{\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.3]},"
          " \"volume\": {\"spacing\": 0.04, \"courant\": 1e-5, \"max_substeps\": 10000000,"
          " \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.12]}], \"field\": [16, 16]}}",
          f);
    fclose(f);
    char out[600];
    snprintf(out, sizeof out, "%s", tmp_path("slow.h5"));
    pid_t pid =
        ms_test_spawn_tool((const char *[]){"run", scene, "--frames", "10", "--out", out, NULL},
                           tmp_path("o.txt"), tmp_path("e.txt"));
    struct timespec ts = {1, 0};
    nanosleep(&ts, NULL);
    kill(pid, SIGTERM);
    nanosleep(&ts, NULL);
    kill(pid, SIGTERM);
    double t0 = tool_clock();
    int status = 0;
    while (waitpid(pid, &status, WNOHANG) == 0 && tool_clock() - t0 < 30) {
        struct timespec poll = {0, 20000000};
        nanosleep(&poll, NULL);
    }
    double waited = tool_clock() - t0;
    if (waited >= 30)
        kill(pid, SIGKILL), waitpid(pid, &status, 0);
    ck_assert_msg(waited < 30, "the run did not stop after the second SIGTERM");
    ck_assert_msg(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM, "status %d", status);
    char *o = ms_test_slurp(tmp_path("o.txt"));
    ck_assert_msg(strstr(o, "stopped by SIGTERM"), "the run did not close its file: %s", o);
    free(o);
    MS_ASSERT_H5DUMP_READS(out);
    remove_tmp_dir();
}
END_TEST

START_TEST(unwritable_outputs_exit_1_with_a_sentence)
{
    make_tmp_dir();
    result r = run_tool((const char *[]){"run", DEFAULT_SCENE, "--frames", "2", "--out",
                                         "/no/such/dir/run.h5", NULL});
    ASSERT_EXIT(r, 1);
    ck_assert_ptr_nonnull(strstr(r.err, "No such file or directory"));
    ck_assert_ptr_nonnull(strstr(r.err, "/no/such/dir/run.h5"));
    ck_assert_int_eq(count_lines(r.err), 1);
    result_free(&r);
    r = run_tool(
        (const char *[]){"run", DEFAULT_SCENE, "--frames", "2", "--out", "/dev/full", NULL});
    ASSERT_EXIT(r, 1);
    ck_assert_ptr_nonnull(strstr(r.err, "it is a character device, not a regular file"));
    ck_assert_int_eq(count_lines(r.err), 1);
    result_free(&r);
    FILE *f = fopen(tmp_path("file"), "w");
    fclose(f);
    char png[600];
    snprintf(png, sizeof png, "%s/file/frames", tmp_dir);
    r = run_tool(
        (const char *[]){"run", DEFAULT_SCENE, "--frames", "2", "--no-out", "--png", png, NULL});
    ASSERT_EXIT(r, 1);
    ck_assert_ptr_nonnull(strstr(r.err, "Not a directory"));
    result_free(&r);
    remove_tmp_dir();
}
END_TEST

/* A copy of file `from` at tmp `to`; its bytes returned (malloc'd) in *text. */
static void copy_file(const char *from, const char *to, char **text, size_t *len)
{
    FILE *f = fopen(from, "rb");
    ck_assert_ptr_nonnull(f);
    static char buf[1 << 16];
    *len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    char *p = tmp_path(to);
    f = fopen(p, "wb");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(buf, 1, *len, f), *len);
    fclose(f);
    *text = malloc(*len);
    memcpy(*text, buf, *len);
}

static int same_bytes(const char *name, const char *text, size_t len)
{
    char *p = tmp_path(name);
    FILE *f = fopen(p, "rb");
    if (!f)
        return 0;
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    return n == len && memcmp(buf, text, len) == 0;
}

static int tmp_exists(const char *name)
{
    struct stat sb;
    return stat(tmp_path(name), &sb) == 0;
}

/* An output never overwrites an input: a run whose --out, or a sidecar of
 * it, is the scene file (under any spelling, or a hard link) is refused
 * with a sentence naming both and exit 1 before anything is written; the
 * scene keeps its bytes. */
START_TEST(run_refuses_an_output_that_is_its_scene)
{
    make_tmp_dir();
    char *text;
    size_t len;
    static const struct {
        const char *scene, *out, *word, *never; /* never: a file that must not appear */
    } cases[] = {
        {"s.json", "s.json", "s.json, the run file, is the scene file", "s.xmf"},
        {"s.json", "./sub/../s.json", "the run file, is the scene file", "s.xmf"},
        {"run.xmf", "run.h5", "run.xmf, the XDMF sidecar of", "run.h5"},
        {"run.xdmf2", "run.h5", "the legacy XDMF sidecar of", "run.h5"},
        {"a.json.part", "a.json", "(a temporary name of it), is the scene file", "a.json"},
        {"linked.json", "other.h5", "other.h5, the run file, is the scene file", "other.xmf"},
    };
    char *sub = tmp_path("sub");
    ck_assert_int_eq(mkdir(sub, 0777), 0);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        copy_file(SMALL_SCENE, cases[i].scene, &text, &len);
        if (!strcmp(cases[i].out, "other.h5")) {
            char *a = tmp_path(cases[i].scene), *b = tmp_path("other.h5");
            ck_assert_int_eq(link(a, b), 0); /* another name of the same file */
        }
        char *scene = tmp_path(cases[i].scene), *out = tmp_path(cases[i].out);
        result r = run_tool(
            (const char *[]){"run", scene, "--frames", "2", "--quiet", "--out", out, NULL});
        ASSERT_EXIT(r, 1);
        ck_assert_msg(strstr(r.err, cases[i].word) && strstr(r.err, "never overwrites an input"),
                      "%s", r.err);
        ck_assert_int_eq(count_lines(r.err), 1);
        ck_assert_msg(same_bytes(cases[i].scene, text, len), "%s changed", cases[i].scene);
        ck_assert_msg(!tmp_exists(cases[i].never), "%s was written", cases[i].never);
        result_free(&r);
        free(text);
    }
    remove_tmp_dir();
}
END_TEST

/* Does tmp file `name` hold these bytes (NULL: is it absent)? */
static int holds(const char *name, const char *bytes, size_t len)
{
    if (!bytes)
        return !tmp_exists(name);
    size_t n = 0;
    char *now = ms_test_slurp_n(tmp_path(name), &n);
    int same = n == len && memcmp(now, bytes, len) == 0;
    free(now);
    return same;
}

/* A run is replaced only on purpose: run --out over an existing run file,
 * or over a sidecar of it alone (the run file deleted, its .xmf or .xdmf2
 * left), or a dangling symbolic link, is refused in one sentence naming the
 * file and --force, exit 2, before the PNG folder is made; every file
 * keeps its bytes. --force replaces the run; --force with --resume is a
 * usage error; the library's check names the same files. */
START_TEST(run_replaces_an_existing_run_only_with_force)
{
    make_tmp_dir();
    char *out = tmp_path("r.h5"), *png = tmp_path("png");
    result r = run_tool(
        (const char *[]){"run", SMALL_SCENE, "--frames", "2", "--quiet", "--out", out, NULL});
    ASSERT_EXIT(r, 0);
    result_free(&r);
    const char *names[3] = {"r.h5", "r.xmf", "r.xdmf2"};
    char *bytes[3];
    size_t len[3];
    for (int i = 0; i < 3; ++i)
        ck_assert_ptr_nonnull(bytes[i] = ms_test_slurp_n(tmp_path(names[i]), &len[i]));
    /* the whole run there, then each sidecar alone */
    for (int k = -1; k < 3; ++k) {
        if (k >= 0) {
            for (int i = 0; i < 3; ++i)
                unlink(tmp_path(names[i]));
            FILE *f = fopen(tmp_path(names[k]), "wb");
            ck_assert_uint_eq(fwrite(bytes[k], 1, len[k], f), len[k]);
            fclose(f);
        }
        r = run_tool((const char *[]){"run", SMALL_SCENE, "--frames", "3", "--quiet", "--out", out,
                                      "--png", png, NULL});
        ASSERT_EXIT(r, 2);
        ck_assert_int_eq(count_lines(r.err), 1);
        ck_assert_msg(strstr(r.err, k <= 0 ? "r.h5 exists" : names[k]) &&
                          strstr(r.err, "pass --force") && strstr(r.err, "another --out"),
                      "%s", r.err);
        if (k > 0)
            ck_assert_msg(strstr(r.err, "XDMF sidecar of"), "%s", r.err);
        for (int i = 0; i < 3; ++i)
            ck_assert_msg(holds(names[i], k < 0 || i == k ? bytes[i] : NULL, len[i]),
                          "%s changed (case %d)", names[i], k);
        ck_assert_msg(!tmp_exists("png"), "the PNG folder was made for a refused run");
        result_free(&r);
    }
    /* a dangling symbolic link is a name the run would replace */
    unlink(tmp_path("r.xdmf2"));
    ck_assert_int_eq(symlink(tmp_path("nowhere.h5"), out), 0);
    r = run_tool(
        (const char *[]){"run", SMALL_SCENE, "--frames", "3", "--quiet", "--out", out, NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "r.h5 exists"), "%s", r.err);
    ck_assert(!tmp_exists("nowhere.h5"));
    result_free(&r);
    unlink(out);
    /* the library's check, on the run's sim */
    ms_scene *sc;
    ms_sim *sim;
    ck_assert_int_eq(ms_scene_load(SMALL_SCENE, &sc), MS_OK);
    ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &sim), MS_OK);
    char name[600];
    int exists = -1;
    ck_assert_int_eq(ms_writer_existing(out, sim, name, sizeof name, &exists), MS_OK);
    ck_assert_int_eq(exists, 0);
    ck_assert_str_eq(name, "");
    FILE *f = fopen(tmp_path("r.xdmf2"), "wb");
    fclose(f);
    ck_assert_int_eq(ms_writer_existing(out, sim, name, sizeof name, &exists), MS_OK);
    ck_assert_int_eq(exists, 1);
    ck_assert_str_eq(name, tmp_path("r.xdmf2"));
    MS_ASSERT_REFUSED(ms_writer_existing(out, sim, name, 0, &exists), MS_ERR_INVALID_ARGUMENT,
                      "no room");
    MS_ASSERT_REFUSED(ms_writer_existing(NULL, sim, name, sizeof name, &exists),
                      MS_ERR_INVALID_ARGUMENT, "path");
    MS_ASSERT_REFUSED(ms_writer_existing(SMALL_SCENE, sim, name, sizeof name, &exists),
                      MS_ERR_INVALID_ARGUMENT, "is the scene file");
    MS_ASSERT_REFUSED(ms_writer_existing("/dev/null", sim, name, sizeof name, &exists), MS_ERR_IO,
                      "not a regular file");
    ms_sim_destroy(sim);
    ms_scene_destroy(sc);
    /* --force replaces the run (the .xdmf2 left alone above goes too) */
    r = run_tool((const char *[]){"run", SMALL_SCENE, "--frames", "3", "--quiet", "--out", out,
                                  "--force", NULL});
    ASSERT_EXIT(r, 0);
    result_free(&r);
    ms_reader *rd;
    ck_assert_int_eq(ms_reader_open(out, &rd), MS_OK);
    ck_assert_int_eq(ms_reader_frames(rd), 3); /* output.every 1 */
    ms_reader_close(rd);
    ck_assert(!holds("r.xdmf2", "", 0));
    /* --resume continues a file without --force, and takes none */
    r = run_tool((const char *[]){"run", SMALL_SCENE, "--resume", out, "--force", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "--force replaces a run file, --resume appends"), "%s", r.err);
    result_free(&r);
    for (int i = 0; i < 3; ++i)
        free(bytes[i]);
    remove_tmp_dir();
}
END_TEST

/* A full disk: a 1 MiB tmpfs in a private mount namespace (root only; it
 * vanishes with the process). The run stops with status 1 and a sentence,
 * and the file keeps the frames written before. */
START_TEST(full_disk_exits_1_and_keeps_the_frames)
{
    if (unshare(CLONE_NEWNS) != 0 || mount(NULL, "/", NULL, MS_REC | MS_PRIVATE, NULL) != 0) {
        char why_[160];
        snprintf(why_, sizeof why_, "needs CAP_SYS_ADMIN: %s", strerror(errno));
        MS_SKIP(why_);
    }
    make_tmp_dir();
    char disk[600];
    snprintf(disk, sizeof disk, "%s/disk", tmp_dir);
    ck_assert_int_eq(mkdir(disk, 0700), 0);
    if (mount("tmpfs", disk, "tmpfs", 0, "size=1m") != 0) {
        char why_[160];
        snprintf(why_, sizeof why_, "cannot mount a tmpfs: %s", strerror(errno));
        remove_tmp_dir();
        MS_SKIP(why_);
    }
    char out[700];
    snprintf(out, sizeof out, "%s/run.h5", disk);
    result r = run_tool(
        (const char *[]){"run", SMALL_SCENE, "--frames", "100000", "--out", out, "--quiet", NULL});
    ASSERT_EXIT(r, 1);
    ck_assert_msg(strstr(r.err, "are free on the file system") || strstr(r.err, "No space left"),
                  "%s", r.err);
    ck_assert_int_eq(count_lines(r.err), 1);
    result_free(&r);
    long frames = frames_in(out);
    ck_assert_int_gt(frames, 0);
    MS_ASSERT_H5DUMP_READS(out);
    r = run_tool((const char *[]){"info", out, NULL});
    ASSERT_EXIT(r, 0);
    result_free(&r);
    umount(disk);
    remove_tmp_dir();
}
END_TEST

/* ---- progress display ------------------------------------------------------ */

/* Run the small scene with stderr on a terminal of `cols` columns (0: the
 * pty's default, no size); the bytes written to it, malloc'ed. */
static char *run_on_terminal(int cols)
{
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    ck_assert_int_ge(master, 0);
    ck_assert_int_eq(grantpt(master), 0);
    ck_assert_int_eq(unlockpt(master), 0);
    char *slave_name = ptsname(master);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int s = open(slave_name, O_RDWR);
        if (cols > 0) {
            struct winsize ws = {.ws_row = 24, .ws_col = (unsigned short)cols};
            ioctl(s, TIOCSWINSZ, &ws);
        }
        int o = open("/dev/null", O_WRONLY);
        dup2(s, 2);
        dup2(o, 1);
        unsetenv("COLUMNS");
        execl(ms_test_tool_path(), ms_test_tool_path(), "run", SMALL_SCENE, "--frames", "8",
              "--no-out", (char *)NULL);
        _exit(127);
    }
    char *buf = malloc(65536);
    size_t got = 0;
    for (;;) {
        ssize_t n = read(master, buf + got, 65535 - got);
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    buf[got] = '\0';
    int status;
    waitpid(pid, &status, 0);
    close(master);
    ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    return buf;
}

START_TEST(progress_is_a_bar_on_a_terminal)
{
    make_tmp_dir();
    char *buf = run_on_terminal(200);
    ck_assert_msg(strstr(buf, "\r[") && strstr(buf, "frames/s") && strstr(buf, "ETA"), "%s", buf);
    ck_assert_ptr_nonnull(strstr(buf, "8/8"));
    ck_assert_ptr_nonnull(strstr(buf, "vol "));
    free(buf);
    remove_tmp_dir();
}
END_TEST

/* Each redraw of the line fits the terminal (at most width - 1 columns),
 * so it never wraps: at 80 columns the stage split goes, at 40 the bar. */
START_TEST(progress_line_fits_the_terminal_width)
{
    make_tmp_dir();
    const int widths[] = {0, 80, 40, 20};
    for (int w = 0; w < 4; ++w) {
        int cols = widths[w] ? widths[w] : 80; /* no size: 80 */
        char *buf = run_on_terminal(widths[w]);
        int lines = 0;
        for (char *p = strchr(buf, '\r'); p; p = strchr(p + 1, '\r')) {
            char *end = strstr(p, "\033[K");
            if (!end)
                continue;
            ck_assert_msg(end - p - 1 <= cols - 1, "%d columns: a line of %d: %.*s", cols,
                          (int)(end - p - 1), (int)(end - p), p);
            ++lines;
        }
        ck_assert_int_gt(lines, 0);
        if (cols == 40)
            ck_assert_msg(strstr(buf, "8/8") && !strstr(buf, "vol "), "%s", buf);
        free(buf);
    }
    remove_tmp_dir();
}
END_TEST

/* An installed tool (a copy outside the build tree) searches its own
 * lib/modesplit/plugins, never the build tree's plugins. */
START_TEST(installed_tool_does_not_search_the_build_tree)
{
    make_tmp_dir();
    char bin[600], exe[700], cmd[4096];
    snprintf(bin, sizeof bin, "%s/prefix/bin", tmp_dir);
    snprintf(exe, sizeof exe, "%s/modesplit", bin);
    /* the tool and the shared library it loads ($ORIGIN/../lib) */
    snprintf(cmd, sizeof cmd,
             "mkdir -p '%s' '%s/../lib' && cp '%s' '%s' && cp -L '%s/../lib/libmodesplit.so.0' "
             "'%s/../lib/'",
             bin, bin, ms_test_tool_path(), exe, tool_dir(), bin);
    ck_assert_int_eq(system(cmd), 0);
    char out[700], err[700];
    snprintf(out, sizeof out, "%s/out.txt", tmp_dir);
    snprintf(err, sizeof err, "%s/err.txt", tmp_dir);
    snprintf(cmd, sizeof cmd, "env -u MODESPLIT_PLUGIN_PATH '%s' plugins > '%s' 2> '%s'", exe, out,
             err);
    ck_assert_int_eq(system(cmd), 0);
    char *o = ms_test_slurp(out);
    ck_assert_ptr_nonnull(strstr(o, "search path: "));
    /* <prefix>/lib/modesplit/plugins, spelled from the library or the tool */
    ck_assert_msg(strstr(o, "/prefix/") && strstr(o, "lib/modesplit/plugins"), "%s", o);
    ck_assert_msg(!strstr(o, MS_BUILD_PLUGIN_DIR), "the installed tool searches %s:\n%s",
                  MS_BUILD_PLUGIN_DIR, o);
    free(o);
    /* the tool in the build tree still finds the build's plugins */
    result r = run_tool((const char *[]){"plugins", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_ptr_nonnull(strstr(r.out, MS_BUILD_PLUGIN_DIR));
    result_free(&r);
    remove_tmp_dir();
}
END_TEST

/* ---- per-command help and "did you mean" ----------------------------------- */

START_TEST(each_command_has_its_help_and_typos_get_a_suggestion)
{
    make_tmp_dir();
    result r = run_tool((const char *[]){"run", "--help", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_msg(!strncmp(r.out, "usage: modesplit run SCENE.json", 31), "%s", r.out);
    ck_assert_ptr_nonnull(strstr(r.out, "--frames N"));
    ck_assert_ptr_null(strstr(r.out, "info [--scene]")); /* only run's part */
    result_free(&r);
    /* each command's own block: its options, no other command's line */
    static const struct {
        const char *cmd, *option;
    } cmds[] = {{"info", "--scene"},     {"check", "--set"},         {"plugins", "plugins"},
                {"export", "--usd"},     {"view", "--record-input"}, {"render", "--frames A:B"},
                {"accuracy", "--quick"}, {"cubemap", "--sun"}};
    for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; ++i) {
        r = run_tool((const char *[]){cmds[i].cmd, "--help", NULL});
        ASSERT_EXIT(r, 0);
        char want[64];
        snprintf(want, sizeof want, "usage: modesplit %s", cmds[i].cmd);
        ck_assert_msg(!strncmp(r.out, want, strlen(want)), "%s", r.out);
        ck_assert_msg(strstr(r.out, cmds[i].option) != NULL, "%s --help: %s", cmds[i].cmd, r.out);
        ck_assert_msg(!strstr(r.out, "<command>") &&
                          (!strcmp(cmds[i].cmd, "run") || !strstr(r.out, "  run SCENE.json")),
                      "%s --help prints more than its own usage: %s", cmds[i].cmd, r.out);
        result_free(&r);
        r = run_tool((const char *[]){"help", cmds[i].cmd, NULL});
        ASSERT_EXIT(r, 0);
        ck_assert_msg(!strncmp(r.out, want, strlen(want)), "%s", r.out);
        result_free(&r);
    }
    r = run_tool((const char *[]){"run", SMALL_SCENE, "--frame", "3", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "unknown option --frame; did you mean --frames?"), "%s", r.err);
    result_free(&r);
    r = run_tool((const char *[]){"run", SMALL_SCENE, "--thread=2", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "did you mean --threads?"), "%s", r.err);
    result_free(&r);
    r = run_tool((const char *[]){"info", "--scen", "x.h5", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "did you mean --scene?"), "%s", r.err);
    result_free(&r);
    /* nothing close: no guess */
    r = run_tool((const char *[]){"run", SMALL_SCENE, "--xyzzy", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "unknown option --xyzzy") && !strstr(r.err, "did you mean"), "%s",
                  r.err);
    result_free(&r);
    r = run_tool((const char *[]){"rnu", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_msg(strstr(r.err, "did you mean run?"), "%s", r.err);
    result_free(&r);
    r = run_tool((const char *[]){"help", "nope", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "no command \"nope\""));
    result_free(&r);
    remove_tmp_dir();
}
END_TEST

/* ---- info and plugins ------------------------------------------------------- */

START_TEST(info_refuses_what_is_not_a_run)
{
    make_tmp_dir();
    result r = run_tool((const char *[]){"info", "no/such/run.h5", NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "No such file"));
    result_free(&r);
    r = run_tool((const char *[]){"info", DEFAULT_SCENE, NULL});
    ASSERT_EXIT(r, 2);
    ck_assert_ptr_nonnull(strstr(r.err, "not an HDF5 file"));
    ck_assert_int_eq(count_lines(r.err), 1);
    result_free(&r);
    r = run_tool((const char *[]){"plugins", NULL});
    ASSERT_EXIT(r, 0);
    ck_assert_ptr_nonnull(strstr(r.out, "sphere"));
    ck_assert_ptr_nonnull(strstr(r.out, "search path"));
    result_free(&r);
    remove_tmp_dir();
}
END_TEST

static Suite *tool_suite(void)
{
    Suite *s = suite_create("tool");
    TCase *tc = tcase_create("cli");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, help_version_and_usage_errors);
    tcase_add_test(tc, every_malformed_scene_exits_2_naming_the_problem);
    tcase_add_test(tc, info_refuses_what_is_not_a_run);
    suite_add_tcase(s, tc);
    tc = tcase_create("run");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, run_writes_hdf5_xdmf_png_and_a_summary);
    tcase_add_test(tc, png_pointing_at_a_file_leaves_no_empty_run_file);
    tcase_add_test(tc, run_file_holds_what_the_sim_held_bit_for_bit);
    tcase_add_test(tc, writer_refuses_fields_the_sim_lacks);
    tcase_add_test(tc, unwritable_outputs_exit_1_with_a_sentence);
    tcase_add_test(tc, run_refuses_an_output_that_is_its_scene);
    tcase_add_test(tc, run_replaces_an_existing_run_only_with_force);
    tcase_add_test(tc, full_disk_exits_1_and_keeps_the_frames);
    tcase_add_test(tc, progress_is_a_bar_on_a_terminal);
    tcase_add_test(tc, progress_line_fits_the_terminal_width);
    tcase_add_test(tc, each_command_has_its_help_and_typos_get_a_suggestion);
    tcase_add_test(tc, installed_tool_does_not_search_the_build_tree);
    suite_add_tcase(s, tc);
    tc = tcase_create("signals");
    tcase_set_timeout(tc, 180);
    tcase_add_test(tc, sigkill_mid_run_leaves_a_file_h5dump_and_info_read);
    tcase_add_test(tc, sigint_and_sigterm_finish_the_frame_and_close_the_file);
    tcase_add_test(tc, a_second_sigterm_cancels_a_long_frame_and_closes_the_file);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(tool_suite());
}
