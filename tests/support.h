/* Shared helpers of the Check suites (tests/support_*.c). */
#ifndef MS_TESTS_SUPPORT_H
#define MS_TESTS_SUPPORT_H

#include <check.h>
#include <string.h>
#include <sys/types.h>

/* Run a suite in fork mode (each case in its own process, so a crash is a
 * failure, not the end of the run); returns the exit status for main. */
int ms_test_run(Suite *s);

/* A case that cannot run here (a client not installed, not root, no GL)
 * calls MS_SKIP("why") and returns: the case is recorded as skipped, never
 * counted as passed. Check has no skip status, so the record goes to the
 * file named by MS_TEST_SKIP_FILE (one line "suite/case: why"), which
 * `make check` counts and prints; with MS_TEST_NO_SKIP=1 (.ci/run) a skip
 * fails the case instead, so CI fails when something it must run did not. */
void ms_test_skip(const char *file, int line, const char *why);
#define MS_SKIP(why)                             \
    do {                                         \
        ms_test_skip(__FILE__, __LINE__, (why)); \
        return;                                  \
    } while (0)

/* A path this machine does not have (an instruction set the CPU lacks):
 * MS_NOT_APPLICABLE("what") records it and the case goes on to check the
 * paths the machine has. Not a skip: nothing that could run here was left
 * out, so MS_TEST_NO_SKIP=1 accepts it. The record goes to the file named
 * by MS_TEST_NA_FILE (one line "file:line case: what"), which `make check`
 * prints apart from the skips. */
void ms_test_not_applicable(const char *file, int line, const char *what);
#define MS_NOT_APPLICABLE(what) ms_test_not_applicable(__FILE__, __LINE__, (what))

/* support_tools.c: a fresh directory $TMPDIR/<prefix>_XXXXXX (or /tmp)
 * into buf (0, or -1); remove a directory and everything below it; a
 * file's whole text (malloc'd, "" when it cannot be read; free() it). */
int ms_test_tmp_dir(char *buf, size_t size, const char *prefix);
void ms_test_remove_tree(const char *dir);
char *ms_test_slurp(const char *path);
/* The same, with its length in *size (binary files). */
char *ms_test_slurp_n(const char *path, size_t *size);
/* The text of the scene file at path with its first `from` replaced by
 * `to` (a variant of a shipped scene; from NULL: the text as it is);
 * malloc'd, NULL when `from` is not in it. */
char *ms_test_scene_variant(const char *path, const char *from, const char *to);
/* The `modesplit` tool of the build under test: $MS_TEST_BUILD/bin/modesplit
 * (`make check` sets it), else build/bin/modesplit. */
const char *ms_test_tool_path(void);
/* Start that tool with args (NULL-terminated, without the program; at most
 * 30): stdin from /dev/null, stdout into the file `out` and stderr into
 * `err` (created or truncated; NULL: /dev/null; the same path: one file
 * holding both), SIGINT and SIGTERM at their defaults. Returns its pid.
 * ms_test_run_tool also waits: the waitpid status. */
pid_t ms_test_spawn_tool(const char *const *args, const char *out, const char *err);
int ms_test_run_tool(const char *const *args, const char *out, const char *err);

/* h5dump (HDF5's own reader, independent of ours) reads the whole file:
 * 1 yes, 0 no, -1 when h5dump is not installed. MS_ASSERT_H5DUMP_READS
 * skips the case (MS_SKIP) rather than pass it when h5dump is absent. */
int ms_test_h5dump(const char *path);
/* Wait until no process holds `path` open (a killed run's writer helper
 * finishing the flush it was given, lib/io/h5_atomic.c), at most `seconds`:
 * 1 when none does, 0 on time out. */
int ms_test_wait_unused(const char *path, double seconds);
#define MS_ASSERT_H5DUMP_READS(path)                                         \
    do {                                                                     \
        const char *p_ = (path);                                             \
        int r_ = ms_test_h5dump(p_);                                         \
        if (r_ < 0)                                                          \
            MS_SKIP("h5dump is not installed (apt-get install hdf5-tools)"); \
        ck_assert_msg(r_ == 1, "h5dump fails on %s", p_);                    \
    } while (0)

/* Assert a call failed with `status` and that ms_last_error() contains
 * `word`: every refusal is tested like a feature. */
#define MS_ASSERT_REFUSED(call, status, word)                                                 \
    do {                                                                                      \
        ms_status st_ = (call);                                                               \
        ck_assert_msg(st_ == (status), "%s returned %s, expected %s (%s)", #call,             \
                      ms_status_name(st_), ms_status_name(status), ms_last_error());          \
        ck_assert_msg(strstr(ms_last_error(), (word)) != NULL, "message \"%s\" lacks \"%s\"", \
                      ms_last_error(), (word));                                               \
    } while (0)

#endif
