/* A monotonic clock for the per-stage statistics. Results never depend on it. */
#include <time.h>

#include "core/core_internal.h"

double ms_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
