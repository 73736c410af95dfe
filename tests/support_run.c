/* The one main loop every suite shares, and the skip and not-applicable
 * records. */
#include "support.h"

#include <stdio.h>
#include <stdlib.h>

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
