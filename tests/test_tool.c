/* tool: the `modesplit` command line, driven as a user would (fork + exec
 * of build/bin/modesplit): usage and exit codes, every malformed scene of
 * tests/data/bad_scenes refused with status 2 and a sentence that names
 * it, `info` and `plugins`. (`run` and its tests arrive with lib/sim.) */
#define _POSIX_C_SOURCE 200809L
#include <check.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "modesplit/modesplit.h"
#include "modesplit/plugin.h"
#include "support.h"

#define DEFAULT_SCENE "data/scenes/default.json"
#define BAD_DIR "tests/data/bad_scenes"

/* ---- helpers ---------------------------------------------------------- */

static char tmp_dir[256];

static void make_tmp_dir(void)
{
    const char *base = getenv("TMPDIR");
    snprintf(tmp_dir, sizeof tmp_dir, "%s/ms_tool_XXXXXX", base && base[0] ? base : "/tmp");
    ck_assert_ptr_nonnull(mkdtemp(tmp_dir));
}

static void remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        char p[1024];
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        struct stat sb;
        if (lstat(p, &sb) == 0 && S_ISDIR(sb.st_mode))
            remove_tree(p);
        else
            remove(p);
    }
    closedir(d);
    rmdir(dir);
}

static void remove_tmp_dir(void)
{
    remove_tree(tmp_dir);
}

static const char *tool_path(void)
{
    static char p[512];
    const char *b = getenv("MS_TEST_BUILD");
    snprintf(p, sizeof p, "%s/bin/modesplit", b && b[0] ? b : "build");
    return p;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return strdup("");
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)n + 1);
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
    fclose(f);
    return s;
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

/* Start the tool with args (NULL-terminated), stdout/stderr to files. */
static pid_t spawn_tool(const char *const *args, const char *out, const char *err)
{
    const char *argv[32];
    int n = 0;
    argv[n++] = tool_path();
    for (int i = 0; args[i] && n < 31; ++i)
        argv[n++] = args[i];
    argv[n] = NULL;
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        int o = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int in = open("/dev/null", O_RDONLY);
        dup2(o, 1);
        dup2(e, 2);
        dup2(in, 0);
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        execv(argv[0], (char *const *)argv);
        _exit(127);
    }
    return pid;
}

static result run_tool(const char *const *args)
{
    result r;
    char out[512], err[512];
    snprintf(out, sizeof out, "%s/stdout.txt", tmp_dir);
    snprintf(err, sizeof err, "%s/stderr.txt", tmp_dir);
    pid_t pid = spawn_tool(args, out, err);
    waitpid(pid, &r.status, 0);
    r.out = slurp(out);
    r.err = slurp(err);
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

#define ASSERT_EXIT(r, code)                                                                 \
    ck_assert_msg(exited(&(r), code), "exit %d (signal %d), expected %d; stderr: %s",       \
                  WIFEXITED((r).status) ? WEXITSTATUS((r).status) : -1,                      \
                  WIFSIGNALED((r).status) ? WTERMSIG((r).status) : 0, code, (r).err)





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
    r = run_tool((const char *[]){"check", "--help", NULL});
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
        {"info", NULL},
        {"info", "a.h5", "b.h5", NULL},
        {"check", NULL},
        {"check", "--deep", NULL},
        {"plugins", "extra", NULL},
    };
    static const char *const word[] = {"which run file", "one run file", "which scenes",
                                       "--deep", "no arguments"};
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
        ms_plugin_description d;
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
        const char *const *modes[1] = {(const char *[]){"check", path, NULL}};
        for (int m = 0; m < 1; ++m) {
            result r = run_tool(modes[m]);
            ck_assert_msg(WIFEXITED(r.status), "%s crashed (signal %d)", name,
                          WTERMSIG(r.status));
            ck_assert_msg(exited(&r, 2), "%s: exit %d, stderr: %s", name, WEXITSTATUS(r.status),
                          r.err);
            ck_assert_msg(count_lines(r.err) == 1, "%s: not one line: %s", name, r.err);
            ck_assert_msg(strstr(r.err, name) != NULL, "%s: message does not name the file: %s",
                          name, r.err);
            ck_assert_msg(strstr(r.err, phrase) != NULL, "%s: message lacks \"%s\": %s", name,
                          phrase, r.err);
            ck_assert_msg(strncmp(r.err, "modesplit: ", 11) == 0, "%s: %s", name, r.err);
            result_free(&r);
        }
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


/* The writer on the real sim: what is read back is what the sim held. */


/* ---- interruptions ---------------------------------------------------------- */




/* A full disk: a 4 MiB tmpfs in a private mount namespace (root only; it
 * vanishes with the process). The run stops with status 1 and a sentence,
 * and the file keeps the frames written before. */

/* ---- progress display ------------------------------------------------------ */


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
    return s;
}

int main(void)
{
    return ms_test_run(tool_suite());
}
