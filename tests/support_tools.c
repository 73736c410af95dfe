/* Helpers of the suites that check files with outside tools. */
#include "support.h"

#include <stdio.h>
#include <stdlib.h>

int ms_test_h5dump(const char *path)
{
    if (system("command -v h5dump > /dev/null 2>&1") != 0)
        return -1;
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "h5dump '%s' > /dev/null 2>&1", path);
    return system(cmd) == 0;
}
