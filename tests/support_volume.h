/* Helpers of the volume suites (tests/test_volume.c, tests/test_colliders.c):
 * small descs, create/step asserting success, the sanity of a state. */
#ifndef MS_TESTS_SUPPORT_VOLUME_H
#define MS_TESTS_SUPPORT_VOLUME_H

#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "modesplit/modesplit.h"
#include "support.h"

/* Under ThreadSanitizer (MS_TEST_SAN=tsan, ~15x slower) the long
 * single-threaded physics runs are skipped, and counted as skipped
 * (MS_SKIP): they exercise no threads, and run in the plain and ASan
 * builds. The threaded ones still run. (make check SAN=tsan runs only the
 * threaded suites, TSAN_SUITES, so CI does not get here.) */
#define TSAN_WHY                                                                       \
    "single-threaded physics run, too slow under ThreadSanitizer; the plain and ASan " \
    "builds run it"
static inline int skip_under_tsan(void)
{
    const char *san = getenv("MS_TEST_SAN");
    return san && strcmp(san, "tsan") == 0;
}

static inline int long_tests(void)
{
    const char *e = getenv("MS_TEST_LONG");
    return e && *e && strcmp(e, "0") != 0;
}

/* A box domain of the given size (m) at the origin, spacing s, h = 2 s. */
static inline ms_volume_desc box_desc(float lx, float ly, float lz, float s)
{
    ms_volume_desc d = ms_volume_desc_default();
    d.domain_max[0] = lx;
    d.domain_max[1] = ly;
    d.domain_max[2] = lz;
    d.spacing = s;
    d.smoothing_length = 2.0f * s;
    return d;
}

static inline ms_volume *make(const ms_volume_desc *d)
{
    ms_volume *v = NULL;
    ms_status st = ms_volume_create(d, &v);
    ck_assert_msg(st == MS_OK, "create: %s", ms_last_error());
    return v;
}

static inline void step(ms_volume *v, float dt)
{
    ms_status st = ms_volume_step(v, dt);
    ck_assert_msg(st == MS_OK, "step: %s", ms_last_error());
}

/* Every particle finite and inside the domain. */
static inline void assert_sane(const ms_volume *v, const ms_volume_desc *d)
{
    int n = ms_volume_count(v);
    float *p = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    float *u = malloc(sizeof(float) * 3 * (size_t)(n + 1));
    ck_assert_int_eq(ms_volume_get_particles(v, p, u), MS_OK);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            ck_assert_msg(isfinite(p[3 * i + k]) && isfinite(u[3 * i + k]),
                          "particle %d not finite", i);
            ck_assert_msg(p[3 * i + k] >= d->domain_min[k] && p[3 * i + k] <= d->domain_max[k],
                          "particle %d at %g outside the domain on axis %d", i, p[3 * i + k], k);
        }
    free(p);
    free(u);
}

#endif
