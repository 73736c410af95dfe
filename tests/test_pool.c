/* The volume's shared pool (lib/volume/pool.c, the sim's work sharing):
 * the calling thread and a lent helper claim the chunks of each loop; the
 * helper really runs chunks, every chunk runs once, and a loop gives the
 * same values as a loop on one thread. Given an engine's task interface,
 * each loop runs through it: a test task system counts the
 * tasks it ran, and the sim's volume loops go through it with the bytes
 * of one thread. */
#include <check.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "modesplit/modesplit.h"
#include "support.h"
#include "volume/extract.h"
#include "volume/volume_internal.h"

enum { N = 4096 };

typedef struct loop_ctx {
    float out[N];
    atomic_int runs[2];     /* chunks run, per part */
    atomic_int part1_done;  /* part 1 has finished */
    pthread_t part1_thread; /* who ran part 1 */
    int wait_for_part1;     /* part 0 holds until part 1 is done */
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

/* A volume of desc.threads 2 in a sim of 2 threads: the sim offers its
 * second thread (open, help, close) to a pool with a helper thread of its
 * own. That is a no-op: the offered thread returns at once (it would
 * otherwise claim chunks until a close), and after the close the pool's
 * own helper still takes chunk 1 while the caller holds chunk 0 (a close
 * must not send the pool's own helpers away). */
START_TEST(a_pool_with_threads_of_its_own_ignores_a_lent_helper)
{
    caller = pthread_self();
    static loop_ctx one, own;
    body(&one, 0, 0, N);
    ms_vpool *p = NULL;
    ck_assert_int_eq(ms_vpool_create(2, &p), MS_OK);
    ck_assert_int_eq(ms_vpool_threads(p), 2);
    ck_assert_int_eq(ms_vpool_start(p), MS_OK); /* as a volume's first step does */
    ms_vpool_help_open(p);
    pthread_t t;
    ck_assert_int_eq(pthread_create(&t, NULL, helper, p), 0);
    ck_assert_int_eq(pthread_join(t, NULL), 0); /* returned at once */
    ms_vpool_help_close(p);
    own.wait_for_part1 = 1;
    for (int k = 0; k < 3; ++k) {
        ms_vpool_run(p, body, &own, N);
        ck_assert(!pthread_equal(own.part1_thread, caller));
        atomic_store(&own.part1_done, 0);
    }
    ck_assert_int_eq(atomic_load(&own.runs[0]), 3);
    ck_assert_int_eq(atomic_load(&own.runs[1]), 3);
    ck_assert_mem_eq(own.out, one.out, sizeof one.out);
    ms_vpool_destroy(p);
}
END_TEST

/* Chunks are claimed atomically, a helper spins a
 * little between loops and then sleeps. Many loops of odd sizes with a
 * lent helper: every chunk of every loop runs exactly once, on its own
 * range, and the loop's values are one thread's. */
typedef struct tally_ctx {
    int n;
    atomic_int chunks[MS_VPOOL_SHARED_PARTS];
    atomic_long items; /* items touched, all chunks */
    atomic_int bad;    /* chunks called with other bounds than their own */
    float out[N];
} tally_ctx;

static void tally_body(void *ctxp, int part, int b, int e)
{
    tally_ctx *c = ctxp;
    const long n = c->n;
    /* the bounds of chunk `part`: contiguous, in order, covering [0, n)
     * (counted, not asserted: this may be the helper's thread) */
    if (b != (int)(n * part / MS_VPOOL_SHARED_PARTS) ||
        e != (int)(n * (part + 1) / MS_VPOOL_SHARED_PARTS))
        atomic_fetch_add(&c->bad, 1);
    for (int i = b; i < e; ++i)
        c->out[i] = (float)i * 0.25f + (float)c->n;
    atomic_fetch_add(&c->chunks[part], 1);
    atomic_fetch_add(&c->items, e - b);
}

/* A shared pool of MS_VPOOL_SHARED_PARTS chunks with a helper thread lent
 * to it; return_helper closes, joins and destroys. */
static ms_vpool *lend_helper(pthread_t *t)
{
    ms_vpool *p = NULL;
    ck_assert_int_eq(ms_vpool_create_shared(MS_VPOOL_SHARED_PARTS, &p), MS_OK);
    ms_vpool_help_open(p);
    ck_assert_int_eq(pthread_create(t, NULL, helper, p), 0);
    return p;
}

static void return_helper(ms_vpool *p, pthread_t t)
{
    ms_vpool_help_close(p);
    ck_assert_int_eq(pthread_join(t, NULL), 0);
    ms_vpool_destroy(p);
}

START_TEST(every_chunk_of_every_loop_runs_once_with_a_lent_helper)
{
    pthread_t t;
    ms_vpool *p = lend_helper(&t);
    enum { LOOPS = 3000 };
    static tally_ctx c;
    long expect = 0;
    for (int k = 0; k < LOOPS; ++k) {
        const int n = MS_VPOOL_SHARED_MIN + (k * 37) % (N - MS_VPOOL_SHARED_MIN + 1);
        c.n = n;
        ms_vpool_run(p, tally_body, &c, n);
        expect += n;
        ck_assert_int_eq(atomic_load(&c.items), expect); /* the loop is over when run returns */
        for (int i = 0; i < n; i += 97)
            ck_assert_float_eq(c.out[i], (float)i * 0.25f + (float)n);
    }
    return_helper(p, t);
    for (int q = 0; q < MS_VPOOL_SHARED_PARTS; ++q)
        ck_assert_int_eq(atomic_load(&c.chunks[q]), LOOPS);
    ck_assert_int_eq(atomic_load(&c.bad), 0);
}
END_TEST

/* The caller claims chunks from the front, a lent helper from
 * the back, so that each keeps its end of the arrays (and its core's cache)
 * from loop to loop. In every loop the caller's chunks are 0 .. k-1 and the
 * helper's k .. parts-1: with the chunks dealt alternately (one counter)
 * the helper's would be interleaved with the caller's and this
 * fails. Chunk 0 (always the caller's) holds until the helper has run the
 * last chunk (bounded: 20 s); the helper's chunks take 1 ms, so the caller
 * takes some of the rest from the front. */
typedef struct ends_ctx {
    pthread_t caller;
    atomic_int ran_by_caller[MS_VPOOL_SHARED_PARTS]; /* 1 caller, 2 helper */
    atomic_int last_done;
} ends_ctx;

static void ends_body(void *ctxp, int part, int b, int e)
{
    ends_ctx *c = ctxp;
    (void)b;
    (void)e;
    const int mine = pthread_equal(pthread_self(), c->caller);
    atomic_store(&c->ran_by_caller[part], mine ? 1 : 2);
    if (part == 0) {
        for (int k = 0; k < 20000 && !atomic_load(&c->last_done); ++k)
            nanosleep(&(struct timespec){0, 1000000}, NULL);
    } else if (!mine) {
        nanosleep(&(struct timespec){0, 1000000}, NULL);
    }
    if (part == MS_VPOOL_SHARED_PARTS - 1)
        atomic_store(&c->last_done, 1);
}

START_TEST(the_caller_claims_from_the_front_and_a_helper_from_the_back)
{
    pthread_t t;
    ms_vpool *p = lend_helper(&t);
    static ends_ctx c;
    c.caller = pthread_self();
    int caller_more = 0; /* loops where the caller took more than chunk 0 */
    for (int loop = 0; loop < 50; ++loop) {
        for (int q = 0; q < MS_VPOOL_SHARED_PARTS; ++q)
            atomic_store(&c.ran_by_caller[q], 0);
        atomic_store(&c.last_done, 0);
        ms_vpool_run(p, ends_body, &c, N);
        int k = 0; /* the caller's chunks: 0 .. k-1 */
        while (k < MS_VPOOL_SHARED_PARTS && atomic_load(&c.ran_by_caller[k]) == 1)
            ++k;
        ck_assert_int_ge(k, 1);
        for (int q = k; q < MS_VPOOL_SHARED_PARTS; ++q)
            ck_assert_msg(atomic_load(&c.ran_by_caller[q]) == 2,
                          "loop %d: chunk %d ran on %s after the caller's 0..%d", loop, q,
                          atomic_load(&c.ran_by_caller[q]) == 1 ? "the caller" : "nobody", k - 1);
        caller_more += k > 1;
    }
    return_helper(p, t);
    /* the helper's chunks are slow: the caller went on from the front too */
    ck_assert_int_gt(caller_more, 0);
}
END_TEST

/* No busy-wait: a helper lent while no loop comes spins at most ~0.1 ms,
 * then sleeps; over half a second of nothing (and again after a burst of
 * loops) it uses a small fraction of a core. */
static double thread_cpu_s(pthread_t t)
{
    clockid_t id;
    struct timespec ts;
    ck_assert_int_eq(pthread_getcpuclockid(t, &id), 0);
    ck_assert_int_eq(clock_gettime(id, &ts), 0);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

START_TEST(an_idle_lent_helper_sleeps_instead_of_spinning)
{
    pthread_t t;
    ms_vpool *p = lend_helper(&t);
    static tally_ctx c;
    for (int round = 0; round < 2; ++round) {
        if (round == 1) /* a burst of loops, then nothing again */
            for (int k = 0; k < 200; ++k) {
                c.n = N;
                ms_vpool_run(p, tally_body, &c, N);
            }
        nanosleep(&(struct timespec){0, 50000000}, NULL); /* let it settle: 50 ms */
        const double c0 = thread_cpu_s(t);
        nanosleep(&(struct timespec){0, 500000000}, NULL); /* 0.5 s of no loops */
        const double used = thread_cpu_s(t) - c0;
        /* asleep: next to nothing; spinning would be ~0.5 s */
        ck_assert_msg(used < 0.05, "round %d: the idle helper used %.3f s of CPU in 0.5 s", round,
                      used);
    }
    return_helper(p, t);
}
END_TEST

/* ---- the engine's task interface ---------------------------------------- */

/* A test task system: each enqueued task on a thread of its own (or, with
 * `inline_run`, run at once and NULL returned, as core.h allows); it
 * counts the tasks it started and the ones finish_task waited for. */
typedef struct engine {
    atomic_int enqueued, finished, ran;
    int inline_run;
} engine;

typedef struct engine_task {
    pthread_t t;
    ms_task_fn *fn;
    void *ctx;
    engine *e;
} engine_task;

static void *engine_thread(void *arg)
{
    engine_task *et = arg;
    et->fn(et->ctx);
    atomic_fetch_add(&et->e->ran, 1);
    return NULL;
}

static void *engine_enqueue(ms_task_fn *fn, void *ctx, void *user)
{
    engine *e = user;
    atomic_fetch_add(&e->enqueued, 1);
    if (e->inline_run) {
        fn(ctx);
        atomic_fetch_add(&e->ran, 1);
        return NULL;
    }
    engine_task *et = malloc(sizeof *et);
    ck_assert_ptr_nonnull(et);
    et->fn = fn;
    et->ctx = ctx;
    et->e = e;
    ck_assert_int_eq(pthread_create(&et->t, NULL, engine_thread, et), 0);
    return et;
}

static void engine_finish(void *task, void *user)
{
    engine *e = user;
    engine_task *et = task;
    ck_assert_int_eq(pthread_join(et->t, NULL), 0);
    free(et);
    atomic_fetch_add(&e->finished, 1);
}

typedef struct count_ctx {
    float out[N];
    atomic_int chunks[MS_VPOOL_SHARED_PARTS];
    atomic_int by_engine; /* chunks run off the calling thread */
} count_ctx;

static void count_body(void *ctxp, int part, int b, int e)
{
    count_ctx *c = ctxp;
    for (int i = b; i < e; ++i)
        c->out[i] = sqrtf((float)i) * 0.5f;
    atomic_fetch_add(&c->chunks[part], 1);
    if (!pthread_equal(pthread_self(), caller))
        atomic_fetch_add(&c->by_engine, 1);
}

/* A shared pool given the engine's tasks runs each loop through one
 * engine task (enqueue, then finish): every chunk once, the values of one
 * thread; an engine that runs the task inline runs every chunk. */
START_TEST(a_shared_pool_runs_its_loops_through_the_engines_tasks)
{
    caller = pthread_self();
    static loop_ctx one;
    body(&one, 0, 0, N);
    ms_vpool *p = NULL;
    ck_assert_int_eq(ms_vpool_create_shared(MS_VPOOL_SHARED_PARTS, &p), MS_OK);
    ck_assert_int_eq(ms_vpool_parts(p), MS_VPOOL_SHARED_PARTS);
    ck_assert_int_eq(ms_vpool_threads(p), 2);
    static engine e;
    ck_assert_int_eq(ms_vpool_set_tasks(p, engine_enqueue, engine_finish, &e), MS_OK);
    enum { LOOPS = 50 };
    static count_ctx c;
    for (int k = 0; k < LOOPS; ++k)
        ms_vpool_run(p, count_body, &c, N);
    ck_assert_int_eq(atomic_load(&e.enqueued), LOOPS);
    ck_assert_int_eq(atomic_load(&e.ran), LOOPS);
    ck_assert_int_eq(atomic_load(&e.finished), LOOPS); /* each one finished */
    for (int q = 0; q < MS_VPOOL_SHARED_PARTS; ++q)
        ck_assert_int_eq(atomic_load(&c.chunks[q]), LOOPS);
    ck_assert_mem_eq(c.out, one.out, sizeof one.out);
    /* too small to split: no task */
    ms_vpool_run(p, count_body, &c, 100);
    ck_assert_int_eq(atomic_load(&e.enqueued), LOOPS);

    /* an engine that runs the task at once: its task claims every chunk */
    static engine in;
    in.inline_run = 1;
    static count_ctx ci;
    ck_assert_int_eq(ms_vpool_set_tasks(p, engine_enqueue, engine_finish, &in), MS_OK);
    ms_vpool_run(p, count_body, &ci, N);
    ck_assert_int_eq(atomic_load(&in.enqueued), 1);
    ck_assert_int_eq(atomic_load(&in.finished), 0); /* NULL handle: nothing to finish */
    for (int q = 0; q < MS_VPOOL_SHARED_PARTS; ++q)
        ck_assert_int_eq(atomic_load(&ci.chunks[q]), 1);
    ck_assert_mem_eq(ci.out, one.out, sizeof one.out);

    /* back to no engine: the caller runs every chunk, no task */
    ck_assert_int_eq(ms_vpool_set_tasks(p, NULL, NULL, NULL), MS_OK);
    static count_ctx cn;
    ms_vpool_run(p, count_body, &cn, N);
    ck_assert_int_eq(atomic_load(&cn.by_engine), 0);
    ck_assert_int_eq(atomic_load(&in.enqueued), 1);
    ck_assert_mem_eq(cn.out, one.out, sizeof one.out);
    ms_vpool_destroy(p);
}
END_TEST

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t sim_hash(const ms_sim *sim)
{
    uint64_t h = 1469598103934665603ull;
    int nx, ny, n;
    const float *f = ms_sim_height(sim, &nx, &ny);
    h = fnv(h, f, sizeof *f * (size_t)nx * ny);
    const float *pos[3], *vel[3];
    ck_assert_int_eq(ms_sim_particles(sim, &n, pos, vel), MS_OK);
    for (int a = 0; a < 3; ++a) {
        h = fnv(h, pos[a], sizeof(float) * (size_t)n);
        h = fnv(h, vel[a], sizeof(float) * (size_t)n);
    }
    return h;
}

/* A two-thread sim with the engine's tasks and a volume of one thread (the
 * default): the surface task and the volume's parallel loops all run
 * through the engine (far more tasks than frames), no thread of the
 * library's own, and the bytes are those of one thread; the same for a
 * volume-only sim, and for a sim given the engine after creation. */
START_TEST(a_sims_volume_loops_run_through_the_engines_tasks)
{
    static const char *const texts[] = {
        "{\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.3]}, \"volume\": "
        "{\"spacing\": 0.02, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.08]}], "
        "\"field\": [16, 16]}, \"surface\": {\"cells\": [64, 64], \"wave_speed\": 0.3}}",
        "{\"domain\": {\"min\": [0, 0, 0], \"max\": [0.4, 0.4, 0.3]}, \"volume\": "
        "{\"spacing\": 0.02, \"fill\": [{\"min\": [0, 0, 0], \"max\": [0.2, 0.4, 0.12]}], "
        "\"field\": [16, 16]}}",
    };
    enum { FRAMES = 8 };
    for (int t = 0; t < 2; ++t) {
        ms_scene *sc = NULL;
        ck_assert_int_eq(ms_scene_parse(texts[t], strlen(texts[t]), &sc), MS_OK);
        ms_sim *one = NULL, *eng = NULL, *late = NULL, *two = NULL;
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 1, &one), MS_OK);
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &two), MS_OK);
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &late), MS_OK);
        static engine e, el;
        memset(&e, 0, sizeof e);
        memset(&el, 0, sizeof el);
        ck_assert_int_eq(ms_sim_create_from_scene(sc, 2, &eng), MS_OK);
        ck_assert_int_eq(ms_sim_set_tasks(eng, engine_enqueue, engine_finish, &e), MS_OK);
        ms_volume_info vi = ms_volume_info_init();
        ms_volume_get_info(ms_sim_volume(eng), &vi);
        ck_assert_int_eq(vi.threads, 2); /* the calling thread and the engine's */
        for (int f = 0; f < FRAMES; ++f) {
            if (f == FRAMES / 2) /* handed to the engine mid-run */
                ck_assert_int_eq(ms_sim_set_tasks(late, engine_enqueue, engine_finish, &el), MS_OK);
            ck_assert_int_eq(ms_sim_step(one, 1.0f / 60), MS_OK);
            ck_assert_int_eq(ms_sim_step(two, 1.0f / 60), MS_OK);
            ck_assert_int_eq(ms_sim_step(eng, 1.0f / 60), MS_OK);
            ck_assert_int_eq(ms_sim_step(late, 1.0f / 60), MS_OK);
            const uint64_t h = sim_hash(one);
            ck_assert_msg(sim_hash(two) == h, "scene %d frame %d: 2 threads differ", t, f);
            ck_assert_msg(sim_hash(eng) == h, "scene %d frame %d: the engine's differ", t, f);
            ck_assert_msg(sim_hash(late) == h, "scene %d frame %d: late engine differs", t, f);
        }
        ms_stats st = ms_stats_init();
        ms_sim_get_stats(eng, &st);
        /* a task per frame for the second side, and per parallel loop of
         * each sub-step (a dozen loops: bounds, density, forces, kick,
         * drift, ...) one for the volume */
        ck_assert_int_ge(st.volume_steps, FRAMES);
        ck_assert_int_gt(atomic_load(&e.enqueued), FRAMES + 5 * st.volume_steps);
        ck_assert_int_eq(atomic_load(&e.finished), atomic_load(&e.enqueued));
        ck_assert_int_eq(atomic_load(&e.ran), atomic_load(&e.enqueued));
        ck_assert_int_gt(atomic_load(&el.enqueued), FRAMES / 2);
        ms_sim_destroy(one);
        ms_sim_destroy(two);
        ms_sim_destroy(eng);
        ms_sim_destroy(late);
        ms_scene_destroy(sc);
    }
}
END_TEST

/* The neighbour grid's sort runs in the pool's chunks from 4096 particles
 * on (grid.c): each chunk counts, then places its particles after the
 * chunks before it: the permutation of the sequential stable sort. Own
 * threads, a shared pool with the engine's tasks, and a shared pool alone
 * give the bytes of one thread, and the engine ran the sort's loops. */
START_TEST(the_pooled_grid_sort_gives_the_bytes_of_one_thread)
{
    enum { VOLS = 4, FRAMES = 3, NX = 16 };
    ms_volume *v[VOLS];
    static engine e;
    for (int k = 0; k < VOLS; ++k) {
        ms_volume_desc d = ms_volume_desc_default();
        d.threads = k == 1 ? 3 : 1;
        ck_assert_int_eq(ms_volume_create(&d, &v[k]), MS_OK);
        /* a tilted block: it flows */
        ck_assert_int_eq(ms_volume_fill_box(v[k], (float[3]){0, 0, 0}, (float[3]){0.6f, 1, 0.48f}),
                         MS_OK);
        if (k >= 2)
            ck_assert_int_eq(ms_volume_share_loops(v[k]), MS_OK);
    }
    ck_assert_int_eq(ms_vpool_parts(ms_volume_extract_pool(v[2])), MS_VPOOL_SHARED_PARTS);
    ck_assert_int_eq(ms_volume_set_tasks(v[2], engine_enqueue, engine_finish, &e), MS_OK);
    const int n = ms_volume_count(v[0]);
    ck_assert_int_ge(n, 4096); /* the pooled sort's threshold */
    float *p0 = malloc(sizeof(float) * 6 * (size_t)n), *pk = malloc(sizeof(float) * 6 * (size_t)n);
    ck_assert_ptr_nonnull(p0);
    ck_assert_ptr_nonnull(pk);
    float h0[NX * NX], hk[NX * NX];
    for (int f = 0; f < FRAMES; ++f) {
        for (int k = 0; k < VOLS; ++k)
            ck_assert_int_eq(ms_volume_step(v[k], 1.0f / 60), MS_OK);
        ck_assert_int_eq(ms_volume_get_particles(v[0], p0, p0 + 3 * (size_t)n), MS_OK);
        ck_assert_int_eq(ms_volume_extract_height(v[0], NX, NX, h0), MS_OK);
        for (int k = 1; k < VOLS; ++k) {
            ck_assert_int_eq(ms_volume_count(v[k]), n);
            ck_assert_int_eq(ms_volume_get_particles(v[k], pk, pk + 3 * (size_t)n), MS_OK);
            ck_assert_msg(memcmp(p0, pk, sizeof(float) * 6 * (size_t)n) == 0,
                          "volume %d frame %d: particles differ", k, f);
            ck_assert_int_eq(ms_volume_extract_height(v[k], NX, NX, hk), MS_OK);
            ck_assert_msg(memcmp(h0, hk, sizeof h0) == 0, "volume %d frame %d: heights differ", k,
                          f);
        }
    }
    /* it moved, and the engine ran loops: the sort's two and the rest */
    double ke = ms_volume_kinetic_energy(v[0]);
    ck_assert(ke > 0.0);
    /* each sub-step: the sort's two loops, boundary, pack, density,
     * forces, bounds, kick, drift, ... */
    ck_assert_int_gt(atomic_load(&e.enqueued), 8 * FRAMES);
    ck_assert_int_eq(atomic_load(&e.finished), atomic_load(&e.enqueued));
    free(p0);
    free(pk);
    for (int k = 0; k < VOLS; ++k)
        ms_volume_destroy(v[k]);
}
END_TEST

static Suite *pool_suite(void)
{
    Suite *s = suite_create("pool");
    TCase *tc = tcase_create("pool");
    tcase_set_timeout(tc, 180); /* TSan: the sim and grid cases run ~20 s each */
    tcase_add_test(tc, a_lent_helper_runs_chunks_and_the_values_are_one_threads);
    tcase_add_test(tc, a_pool_with_threads_of_its_own_ignores_a_lent_helper);
    tcase_add_test(tc, every_chunk_of_every_loop_runs_once_with_a_lent_helper);
    tcase_add_test(tc, the_caller_claims_from_the_front_and_a_helper_from_the_back);
    tcase_add_test(tc, an_idle_lent_helper_sleeps_instead_of_spinning);
    tcase_add_test(tc, a_shared_pool_runs_its_loops_through_the_engines_tasks);
    tcase_add_test(tc, a_sims_volume_loops_run_through_the_engines_tasks);
    tcase_add_test(tc, the_pooled_grid_sort_gives_the_bytes_of_one_thread);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    return ms_test_run(pool_suite());
}
