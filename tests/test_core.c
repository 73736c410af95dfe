/* Core: version, status names, the thread-local error sentence, checks,
 * aligned allocation and the seeded RNG. */
#include <check.h>
#include <pthread.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>

#include "core/core_internal.h"
#include "modesplit/modesplit.h"
#include "support.h"

/* The string the library reports is the one its numbers spell (core.h
 * holds both; the Makefile reads its VERSION from core.h). */
START_TEST(version_matches_header)
{
    char spelled[32];
    snprintf(spelled, sizeof spelled, "%d.%d.%d", MS_VERSION_MAJOR, MS_VERSION_MINOR,
             MS_VERSION_PATCH);
    ck_assert_str_eq(ms_version(), spelled);
    ck_assert_str_eq(MS_VERSION_STRING, spelled);
}
END_TEST

START_TEST(status_names_cover_every_code)
{
    ck_assert_str_eq(ms_status_name(MS_OK), "MS_OK");
    ck_assert_str_eq(ms_status_name(MS_ERR_INVALID_ARGUMENT), "MS_ERR_INVALID_ARGUMENT");
    ck_assert_str_eq(ms_status_name(MS_ERR_OUT_OF_MEMORY), "MS_ERR_OUT_OF_MEMORY");
    ck_assert_str_eq(ms_status_name(MS_ERR_UNSTABLE), "MS_ERR_UNSTABLE");
    ck_assert_str_eq(ms_status_name(MS_ERR_IO), "MS_ERR_IO");
    ck_assert_str_eq(ms_status_name(MS_ERR_PARSE), "MS_ERR_PARSE");
    ck_assert_str_eq(ms_status_name(MS_ERR_PLUGIN), "MS_ERR_PLUGIN");
    ck_assert_str_eq(ms_status_name(MS_ERR_UNSUPPORTED), "MS_ERR_UNSUPPORTED");
    ck_assert_str_eq(ms_status_name(MS_ERR_STATE), "MS_ERR_STATE");
    ck_assert_str_eq(ms_status_name(MS_ERR_CANCELED), "MS_ERR_CANCELED");
    ck_assert_str_eq(ms_status_name((ms_status)-99), "MS_UNKNOWN_STATUS");
    ck_assert_str_eq(ms_status_text(MS_ERR_OUT_OF_MEMORY), "out of memory");
    ck_assert_int_eq(sizeof(ms_status), 4);
}
END_TEST

static void *fail_in_thread(void *arg)
{
    (void)arg;
    ms_fail(MS_ERR_IO, "thread: other sentence");
    return NULL;
}

START_TEST(last_error_is_thread_local)
{
    ck_assert_int_eq(ms_fail(MS_ERR_PARSE, "main: value %d", 7), MS_ERR_PARSE);
    pthread_t t;
    pthread_create(&t, NULL, fail_in_thread, NULL);
    pthread_join(t, NULL);
    ck_assert_str_eq(ms_last_error(), "main: value 7");
}
END_TEST

START_TEST(checks_name_value_and_bound)
{
    ck_assert_int_eq(ms_check_positive("surface", "dx", 0.0, "m"), MS_ERR_INVALID_ARGUMENT);
    ck_assert_str_eq(ms_last_error(), "surface: dx 0 m must be finite and > 0");
    ck_assert_int_eq(ms_check_range("surface", "damping", 1.5, 0, 1, ""), MS_ERR_INVALID_ARGUMENT);
    ck_assert_str_eq(ms_last_error(), "surface: damping 1.5 is outside [0, 1]");
    ck_assert_int_eq(ms_check_int_range("surface", "nx", 1, 2, 16384), MS_ERR_INVALID_ARGUMENT);
    ck_assert_str_eq(ms_last_error(), "surface: nx 1 is outside [2, 16384]");
    ck_assert_int_eq(ms_check_finite("volume", "viscosity", NAN), MS_ERR_INVALID_ARGUMENT);
    ck_assert_ptr_nonnull(strstr(ms_last_error(), "finite"));
    ck_assert_int_eq(ms_check_range("x", "y", 0.5, 0, 1, "m"), MS_OK);
}
END_TEST

START_TEST(alloc_is_aligned_zeroed_and_overflow_safe)
{
    float *p = ms_alloc_array(1000, sizeof *p);
    ck_assert_ptr_nonnull(p);
    ck_assert_uint_eq((uintptr_t)p % 64, 0);
    for (int i = 0; i < 1000; ++i)
        ck_assert_float_eq(p[i], 0.0f);
    ms_free(p);
    ck_assert_ptr_null(ms_alloc_array(SIZE_MAX / 2, 4));
}
END_TEST

START_TEST(rng_is_reproducible_and_uniform)
{
    ms_rng a, b, c;
    ms_rng_seed(&a, 42);
    ms_rng_seed(&b, 42);
    ms_rng_seed(&c, 43);
    int differ = 0;
    double sum = 0, sum2 = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        uint32_t x = ms_rng_u32(&a);
        ck_assert_uint_eq(x, ms_rng_u32(&b));
        differ += x != ms_rng_u32(&c);
        float u = ms_rng_uniform(&a);
        ck_assert(u >= 0.0f && u < 1.0f);
        sum += u;
        sum2 += (double)u * u;
        (void)ms_rng_u32(&b);
    }
    ck_assert_int_gt(differ, n - 10);
    /* mean 1/2 and variance 1/12, to 5 standard errors */
    double mean = sum / n, var = sum2 / n - mean * mean;
    ck_assert_double_lt(fabs(mean - 0.5), 5 * sqrt(1.0 / 12 / n));
    ck_assert_double_lt(fabs(var - 1.0 / 12), 0.002);
}
END_TEST

START_TEST(poisson_has_the_requested_mean)
{
    const double means[] = {0.3, 4.0, 200.0};
    for (int k = 0; k < 3; ++k) {
        ms_rng r;
        ms_rng_seed(&r, 7);
        double sum = 0;
        const int n = 20000;
        for (int i = 0; i < n; ++i)
            sum += (double)ms_rng_poisson(&r, means[k]);
        /* standard error of the mean is sqrt(mean/n) */
        ck_assert_double_lt(fabs(sum / n - means[k]), 5 * sqrt(means[k] / n));
    }
    ms_rng r;
    ms_rng_seed(&r, 1);
    ck_assert_int_eq(ms_rng_poisson(&r, 0.0), 0);
    ck_assert_int_eq(ms_rng_poisson(&r, -1.0), 0);
}
END_TEST

/* The "did you mean" of unknown keys: the closest name within 1 edit for
 * short names, 2 for longer ones; swapped letters count as one edit. */
START_TEST(closest_name_is_within_the_edit_bound)
{
    static const char *const names[] = {"rain", "boat", "floaters", "wave_speed", "nx", NULL};
    ck_assert_str_eq(ms_closest_name("rian", names), "rain");        /* transposition: 1 */
    ck_assert_str_eq(ms_closest_name("bot", names), "boat");         /* deletion: 1 */
    ck_assert_str_eq(ms_closest_name("flaoter", names), "floaters"); /* 2 */
    ck_assert_str_eq(ms_closest_name("wavespeed", names), "wave_speed");
    ck_assert_str_eq(ms_closest_name("ny", names), "nx");
    ck_assert_ptr_null(ms_closest_name("ab", names));      /* 2 edits from "nx": too far for 2 */
    ck_assert_ptr_null(ms_closest_name("flotsam", names)); /* 4 edits from "floaters" */
    ck_assert_ptr_null(ms_closest_name("rain", names));    /* a known name needs no guess */
    ck_assert_ptr_null(ms_closest_name("", names));
    ck_assert_ptr_null(ms_closest_name(NULL, names));
    char longname[200];
    memset(longname, 'a', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    ck_assert_ptr_null(ms_closest_name(longname, names)); /* past the 64-char rows */
}
END_TEST

static Suite *core_suite(void)
{
    Suite *s = suite_create("core");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, version_matches_header);
    tcase_add_test(tc, status_names_cover_every_code);
    tcase_add_test(tc, last_error_is_thread_local);
    tcase_add_test(tc, checks_name_value_and_bound);
    tcase_add_test(tc, alloc_is_aligned_zeroed_and_overflow_safe);
    tcase_add_test(tc, rng_is_reproducible_and_uniform);
    tcase_add_test(tc, poisson_has_the_requested_mean);
    tcase_add_test(tc, closest_name_is_within_the_edit_bound);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(core_suite());
}
