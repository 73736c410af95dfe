/* The volume's shared pool (lib/volume/pool.c, issue 12's work sharing):
 * the calling thread and a lent helper claim the chunks of each loop; the
 * helper really runs chunks, every chunk runs once, and a loop gives the
 * same values as a loop on one thread. */
#include <check.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <time.h>

#include "support.h"
#include "volume/extract.h"
#include "volume/volume_internal.h"

enum { N = 4096 };

typedef struct loop_ctx {
    float out[N];
    atomic_int runs[2];       /* chunks run, per part */
    atomic_int part1_done;    /* part 1 has finished */
    pthread_t part1_thread;   /* who ran part 1 */
    int wait_for_part1;       /* part 0 holds until part 1 is done */
} loop_ctx;

static pthread_t caller;

static void body(void *ctxp, int part, int b, int e)
{
    loop_ctx *c = ctxp;
    for (int i = b; i < e; ++i)
        c->out[i] = sqrtf((float)i) * 0.5f;
    atomic_fetch_add(&c->runs[part], 1);
    if (part == 1) {
        c->part1_thread = pthread_self();
        atomic_store(&c->part1_done, 1);
    } else if (c->wait_for_part1) {
        /* the caller always claims chunk 0 first; it can only go on once
         * the helper has run chunk 1 (bounded: 20 s, then the test fails) */
        for (int k = 0; k < 20000 && !atomic_load(&c->part1_done); ++k)
            nanosleep(&(struct timespec){0, 1000000}, NULL);
    }
}

static void *helper(void *p)
{
    ms_vpool_help(p);
    return NULL;
}

START_TEST(a_lent_helper_runs_chunks_and_the_values_are_one_threads)
{
    caller = pthread_self();
    static loop_ctx one, shared;
    body(&one, 0, 0, N); /* one thread, one chunk */
    ms_vpool *p = NULL;
    ck_assert_int_eq(ms_vpool_create_shared(2, &p), MS_OK);
    ck_assert_int_eq(ms_vpool_threads(p), 2);
    /* no helper: the caller claims both chunks */
    ms_vpool_run(p, body, &shared, N);
    ck_assert_int_eq(atomic_load(&shared.runs[0]), 1);
    ck_assert_int_eq(atomic_load(&shared.runs[1]), 1);
    ck_assert(pthread_equal(shared.part1_thread, caller));
    ck_assert_mem_eq(shared.out, one.out, sizeof one.out);

    /* a helper lent between open and close takes chunk 1 */
    static loop_ctx lent;
    lent.wait_for_part1 = 1;
    ms_vpool_help_open(p);
    pthread_t t;
    ck_assert_int_eq(pthread_create(&t, NULL, helper, p), 0);
    ms_vpool_run(p, body, &lent, N);
    ck_assert_int_eq(atomic_load(&lent.part1_done), 1);
    ck_assert(!pthread_equal(lent.part1_thread, caller));
    for (int k = 0; k < 3; ++k) /* more loops while it is lent */
        ms_vpool_run(p, body, &lent, N);
    ms_vpool_help_close(p);
    ck_assert_int_eq(pthread_join(t, NULL), 0);
    ck_assert_int_eq(atomic_load(&lent.runs[0]), 4);
    ck_assert_int_eq(atomic_load(&lent.runs[1]), 4);
    ck_assert_mem_eq(lent.out, one.out, sizeof one.out);

    /* closed: a helper returns at once, the caller runs everything */
    ck_assert_int_eq(pthread_create(&t, NULL, helper, p), 0);
    ck_assert_int_eq(pthread_join(t, NULL), 0);
    ms_vpool_destroy(p);
}
END_TEST

static Suite *pool_suite(void)
{
    Suite *s = suite_create("pool");
    TCase *tc = tcase_create("pool");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, a_lent_helper_runs_chunks_and_the_values_are_one_threads);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(pool_suite());
}
