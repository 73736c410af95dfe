/* The one main loop every suite shares, and the skip and not-applicable
 * records. */
#include "support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "modesplit/modesplit.h"

/* CPU seconds of this process */
static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* CPU seconds of a small dam break (3 000 particles, one thread, 3
 * frames) on the path a new volume takes; -1 when it cannot run. */
static double dam_seconds(void)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.threads = 1;
    d.domain_max[0] = 0.5f;
    d.domain_max[1] = 0.1f;
    d.domain_max[2] = 0.25f;
    d.spacing = 0.01f;
    d.smoothing_length = 0.02f;
    ms_volume *v = NULL;
    if (ms_volume_create(&d, &v) != MS_OK)
        return -1;
    double t0 = cpu_seconds();
    ms_status st = ms_volume_fill_box(v, (float[3]){0, 0, 0}, (float[3]){0.15f, 0.1f, 0.2f});
    for (int f = 0; f < 3 && st == MS_OK; ++f)
        st = ms_volume_step(v, 1.0f / 60);
    double t = cpu_seconds() - t0;
    ms_volume_destroy(v);
    return st == MS_OK ? t : -1;
}

/* MODESPLIT_ISA=c (or another path narrower than the one this machine
 * picks) runs every suite's work on a slower path. A case's time limit
 * (tcase_set_timeout) guards against a hang; it is set for the picked
 * path, so here it is scaled by how much slower the forced path is: the
 * CPU time of the same small dam break on the forced path over that on
 * the picked one, measured in each suite process. It runs before main,
 * as Check reads CK_TIMEOUT_MULTIPLIER when a suite's cases are made. A
 * multiplier already set (by hand, make check-aarch64) is kept. */
__attribute__((constructor)) static void scale_timeouts_to_the_path(void)
{
    const char *want = getenv("MODESPLIT_ISA");
    if (!want || !want[0] || getenv("CK_TIMEOUT_MULTIPLIER"))
        return;
    char forced[16];
    snprintf(forced, sizeof forced, "%s", want);
    /* the faster of two runs each, alternated: another process on the
     * core slows either, never speeds it up */
    double picked = 1e30, slow = 1e30;
    for (int k = 0; k < 2; ++k) {
        unsetenv("MODESPLIT_ISA");
        double a = dam_seconds();
        setenv("MODESPLIT_ISA", forced, 1);
        double b = dam_seconds();
        if (a <= 0 || b <= 0)
            return; /* a path refused: the suites say so */
        picked = fmin(picked, a);
        slow = fmin(slow, b);
    }
    double k = ceil(10.0 * slow / picked) / 10.0;
    if (k <= 1.0)
        return;
    char text[32];
    snprintf(text, sizeof text, "%.1f", k);
    setenv("CK_TIMEOUT_MULTIPLIER", text, 1);
    fprintf(stderr,
            "MODESPLIT_ISA=%s: %.1fx the CPU time of the picked path here; the cases' "
            "time limits are scaled by that (CK_TIMEOUT_MULTIPLIER=%s)\n",
            forced, k, text);
}

int ms_test_run(Suite *s)
{
    SRunner *sr = srunner_create(s);
    srunner_set_fork_status(sr, CK_FORK);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed ? 1 : 0;
}

void ms_test_skip(const char *file, int line, const char *why)
{
    const char *no_skip = getenv("MS_TEST_NO_SKIP");
    if (no_skip && no_skip[0] == '1')
        ck_abort_msg("%s:%d: %s: cannot run here (%s), and MS_TEST_NO_SKIP=1 forbids a skip", file,
                     line, tcase_name(), why);
    fprintf(stderr, "SKIP %s: %s\n", tcase_name(), why);
    const char *path = getenv("MS_TEST_SKIP_FILE");
    if (!path || !path[0])
        return;
    /* Each case runs in its own forked process: append, one line a write. */
    FILE *f = fopen(path, "a");
    if (!f)
        return;
    fprintf(f, "%s:%d %s: %s\n", file, line, tcase_name(), why);
    fclose(f);
}

void ms_test_not_applicable(const char *file, int line, const char *what)
{
    fprintf(stderr, "N/A %s: %s\n", tcase_name(), what);
    const char *path = getenv("MS_TEST_NA_FILE");
    if (!path || !path[0])
        return;
    FILE *f = fopen(path, "a");
    if (!f)
        return;
    fprintf(f, "%s:%d %s: %s\n", file, line, tcase_name(), what);
    fclose(f);
}
