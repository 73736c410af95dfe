/* The worker threads of one volume: a parallel loop over particles split
 * into as many contiguous chunks as there are threads. Every chunk does the
 * same per-particle arithmetic as the sequential loop (gathers, no shared
 * sums), so the results are the same bytes for any thread count; only
 * order-free reductions (max) are combined across chunks.
 * A volume's own pool (ms_vpool_create, desc.threads) is a shared pool
 * (below) with threads - 1 helper threads of its own that never stop
 * helping once started. They start at the first step (ms_vpool_start),
 * not at create: an engine that hands over its task interface
 * (ms_volume_set_tasks) between create and the first step never sees a
 * thread of the library's own. With the engine's tasks the pool runs
 * chunks 1.. as the engine's tasks (enqueue, then finish each), chunk 0
 * on the calling thread, and stops its own threads if they ran: the same
 * split, the same bytes. A loop before the first step (the density at
 * create) runs every chunk on the calling thread, again the same bytes.
 * A shared pool (ms_vpool_create_shared, the sim's work sharing) has no
 * threads of its own: each loop's chunks are claimed one at a time by the
 * calling thread and by whoever else has a moment: a helper that another
 * part of the program lends while it has nothing to do (ms_vpool_help
 * between help_open and help_close: lib/sim's second thread once its
 * surface task is done), and, given the engine's task interface, one
 * engine task per loop that claims chunks like the helper (the volume's
 * parallel-for through the engine's enqueue/finish, no thread of the
 * library's own). Chunks are claimed as they come, so a helper that
 * arrives late still takes its share; who runs a chunk changes nothing in
 * it, so the bytes are the same.
 * Hand-over: a chunk is claimed with one atomic
 * compare-and-swap on a word holding the loop's generation and the chunks
 * taken from each end, not under a mutex. The caller claims from the
 * front (0, 1, ...), a helper from the back (parts - 1, parts - 2, ...):
 * each thread then keeps the same end of the particle arrays
 * from loop to loop, in its own core's cache, and they meet wherever the
 * work balances. With the chunks dealt alternately (one counter) the two
 * cores passed each loop's data back and forth: a per-thread CPU-time
 * trace of fig1_x10 at 2 threads counted 2.0-2.1x the chunk work of 1
 * thread (the cache misses of a range last written by the other core);
 * from both ends, 1.3-1.4x, and the volume thread's frame 25-35 % shorter.
 * A thread with nothing to claim spins (the CPU's pause
 * hint, yielding the core every 64 turns) for at most MS_VPOOL_SPIN_US
 * for the next loop or for the last chunk to finish, and then sleeps on
 * a condition variable, which the other side signals only when it sees
 * it asleep. A volume step's loops
 * follow each other within microseconds, so the helper stays awake
 * through a step and a loop costs no wake-up (fig1's loops of 2000
 * particles last tens of microseconds, as long as waking a sleeping
 * thread: 2 threads over 1 went from 1.50-1.57x to 1.72-1.78x on the
 * shared VM); a side that waits longer (the volume thread's serial parts,
 * the end of the frame) stops burning the core after 0.1 ms, so two sims
 * on two cores lose at most that per wait. */
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdint.h>

#include "volume/extract.h"
#include "volume/volume_internal.h"

typedef struct worker_arg {
    struct ms_vpool *pool;
    int part;
} worker_arg;

struct ms_vpool {
    int threads; /* including the calling thread */
    int started; /* workers running */
    pthread_t tid[MS_VOLUME_MAX_THREADS];
    worker_arg arg[MS_VOLUME_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t go, done_cv;
    ms_vpool_fn *fn;
    void *ctx;
    int n;
    /* the engine's tasks, or NULL: the pool's own threads */
    ms_enqueue_task_fn *enqueue;
    ms_finish_task_fn *finish;
    void *user;
    void *handle[MS_VOLUME_MAX_THREADS];
    /* shared pool: chunks claimed by the caller and a helper. fn, ctx and
     * n of a loop are written before its generation is published in
     * `claim` (seq_cst) and read only after a chunk of it was claimed; the
     * caller writes the next loop's only once `done` says every chunk of
     * this one ran. */
    int own;                /* threads - 1 helper threads of its own (ms_vpool_create) */
    _Atomic uint64_t claim; /* generation << 32 | back << 16 | front */
    _Atomic int done;       /* chunks of the current loop finished */
    _Atomic int help_open;  /* a helper may claim chunks */
    _Atomic int helper_sleeps, caller_sleeps; /* how many sleep on `go`, on `done` */
    uint64_t gen;                             /* the caller's: the current loop's generation */
};

/* Claim word: the generation of the current loop in the high 32 bits,
 * the chunks taken from the back in bits 16-31 and from the front in
 * bits 0-15; a claim never takes the two past each other (front + back
 * <= parts). A claim of an old generation fails its compare-and-swap. */
#define CLAIM_BITS 16
#define CLAIM_MASK ((UINT64_C(1) << CLAIM_BITS) - 1)
#define CLAIM_FRONT(w) ((int)((w)&CLAIM_MASK))
#define CLAIM_BACK(w) ((int)(((w) >> CLAIM_BITS) & CLAIM_MASK))
/* How long a thread with nothing to claim spins before it sleeps. */
#define MS_VPOOL_SPIN_US 100.0

/* One turn of a bounded spin: the CPU's pause hint, and every 64th turn
 * the core offered to any other runnable thread (on a machine with more
 * runnable threads than cores the thread we wait for may be the one
 * waiting for this core). Returns 0 once `until` (ms_now() s) has passed. */
static int spin_turn(int *turns, double until)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    __asm__ __volatile__("yield");
#endif
    if (++*turns & 63)
        return 1;
    sched_yield();
    return ms_now() < until;
}

static void chunk(int n, int parts, int part, int *b, int *e)
{
    long nn = n;
    *b = (int)(nn * part / parts);
    *e = (int)(nn * (part + 1) / parts);
}

ms_status ms_vpool_create_shared(int parts, ms_vpool **out)
{
    *out = NULL;
    ms_vpool *p = ms_alloc(sizeof *p);
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the thread pool");
    p->threads = parts;
    atomic_init(&p->claim, (uint64_t)parts); /* generation 0: all taken from the front */
    atomic_init(&p->done, parts);
    atomic_init(&p->help_open, 0);
    atomic_init(&p->helper_sleeps, 0);
    atomic_init(&p->caller_sleeps, 0);
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->go, NULL);
    pthread_cond_init(&p->done_cv, NULL);
    *out = p;
    return MS_OK;
}

/* Chunk k of the current loop, claimed by this thread; then counted done
 * (the caller, asleep on the last one, is woken). */
static void run_chunk(ms_vpool *p, int k)
{
    int b, e;
    chunk(p->n, p->threads, k, &b, &e);
    if (e > b)
        p->fn(p->ctx, k, b, e);
    if (atomic_fetch_add(&p->done, 1) + 1 == p->threads && atomic_load(&p->caller_sleeps)) {
        pthread_mutex_lock(&p->lock);
        pthread_cond_signal(&p->done_cv);
        pthread_mutex_unlock(&p->lock);
    }
}

/* A chunk of the current loop, from the back (a helper) or the front (the
 * caller), or -1 when none is left. */
static int claim_one(ms_vpool *p, int back)
{
    uint64_t w = atomic_load(&p->claim);
    for (;;) {
        const int f = CLAIM_FRONT(w), b = CLAIM_BACK(w);
        if (f + b >= p->threads)
            return -1;
        const uint64_t one = back ? UINT64_C(1) << CLAIM_BITS : UINT64_C(1);
        if (atomic_compare_exchange_weak(&p->claim, &w, w + one))
            return back ? p->threads - 1 - b : f;
    }
}

/* Claims and runs chunks from one end until none of the loop is left. */
static void claim_chunks(ms_vpool *p, int back)
{
    for (int k; (k = claim_one(p, back)) >= 0;)
        run_chunk(p, k);
}

static int open_chunks(ms_vpool *p)
{
    const uint64_t w = atomic_load(&p->claim);
    return CLAIM_FRONT(w) + CLAIM_BACK(w) < p->threads;
}

static void open_help(ms_vpool *p)
{
    atomic_store(&p->help_open, 1);
}

static void close_help(ms_vpool *p)
{
    atomic_store(&p->help_open, 0);
    pthread_mutex_lock(&p->lock);
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
}

/* Claims chunks from the back until the help is closed: a lent helper,
 * or a pool's own helper thread (worker). */
static void help_loop(ms_vpool *p)
{
    while (atomic_load(&p->help_open)) {
        claim_chunks(p, 1);
        /* nothing open: spin a while for the next loop, then sleep */
        const double until = ms_now() + MS_VPOOL_SPIN_US * 1e-6;
        int turns = 0;
        while (atomic_load(&p->help_open) && !open_chunks(p) && spin_turn(&turns, until))
            ;
        if (!atomic_load(&p->help_open) || open_chunks(p))
            continue;
        pthread_mutex_lock(&p->lock);
        atomic_fetch_add(&p->helper_sleeps, 1);
        while (atomic_load(&p->help_open) && !open_chunks(p))
            pthread_cond_wait(&p->go, &p->lock);
        atomic_fetch_sub(&p->helper_sleeps, 1);
        pthread_mutex_unlock(&p->lock);
    }
}

/* The lent helper's calls (lib/sim): no-ops on a pool with threads of its
 * own (a volume of desc.threads > 1), whose help stays open while its
 * threads run, as on a NULL pool. */
void ms_vpool_help_open(ms_vpool *p)
{
    if (p && !p->own)
        open_help(p);
}

void ms_vpool_help(ms_vpool *p)
{
    if (p && !p->own)
        help_loop(p);
}

void ms_vpool_help_close(ms_vpool *p)
{
    if (p && !p->own)
        close_help(p);
}

/* A helper thread of a pool's own: claims chunks from the back of each
 * loop (help_loop) until the pool is stopped. */
static void *worker(void *argp)
{
    help_loop(argp);
    return NULL;
}

static void stop_workers(ms_vpool *p)
{
    close_help(p);
    for (int t = 1; t <= p->started; ++t)
        pthread_join(p->tid[t], NULL);
    p->started = 0;
}

static ms_status start_workers(ms_vpool *p)
{
    open_help(p);
    for (int t = 1; t < p->threads; ++t) {
        if (pthread_create(&p->tid[t], NULL, worker, p) != 0) {
            stop_workers(p);
            return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: could not start worker thread %d of %d",
                           t, p->threads);
        }
        p->started = t;
    }
    return MS_OK;
}

/* A pool with threads - 1 helper threads of its own (a volume's
 * desc.threads), started by ms_vpool_start. Its loops are shared loops (run_shared) whose helpers
 * never leave: each spins MS_VPOOL_SPIN_US for the next loop before it
 * sleeps, so a step's loops, microseconds apart, cost no wake-up (a
 * worker woken from a condition variable for every loop made
 * bench_volume's 2000-particle sub-step 0.78 ms on 2 threads against 1
 * thread's 0.33). The
 * split is the same chunks, so the same bytes. */
ms_status ms_vpool_create(int threads, ms_vpool **out)
{
    *out = NULL;
    if (threads <= 1)
        return MS_OK; /* a NULL pool runs loops inline */
    ms_status st = ms_vpool_create_shared(threads, out);
    if (st != MS_OK)
        return st;
    (*out)->own = 1;
    return MS_OK;
}

ms_status ms_vpool_start(ms_vpool *p)
{
    if (!p || !p->own || p->enqueue || p->started)
        return MS_OK; /* inline, the engine's tasks, or running */
    return start_workers(p);
}

/* A shared pool's engine task: the chunks of the current loop still open
 * (none if the loop was done before the engine ran it). */
static void help_task(void *argp)
{
    claim_chunks(argp, 1);
}

/* The caller of a shared loop, its chunks done: waits for the others'. */
static void wait_done(ms_vpool *p)
{
    const double until = ms_now() + MS_VPOOL_SPIN_US * 1e-6;
    int turns = 0;
    while (atomic_load(&p->done) != p->threads && spin_turn(&turns, until))
        ;
    if (atomic_load(&p->done) == p->threads)
        return;
    pthread_mutex_lock(&p->lock);
    atomic_store(&p->caller_sleeps, 1);
    while (atomic_load(&p->done) != p->threads)
        pthread_cond_wait(&p->done_cv, &p->lock);
    atomic_store(&p->caller_sleeps, 0);
    pthread_mutex_unlock(&p->lock);
}

static void run_shared(ms_vpool *p, ms_vpool_fn *fn, void *ctx, int n)
{
    p->fn = fn;
    p->ctx = ctx;
    p->n = n;
    atomic_store(&p->done, 0);
    /* publish: chunk 0 is the caller's, 1.. are open */
    atomic_store(&p->claim, (++p->gen << 32) | 1);
    if (atomic_load(&p->helper_sleeps)) {
        pthread_mutex_lock(&p->lock);
        pthread_cond_broadcast(&p->go);
        pthread_mutex_unlock(&p->lock);
    }
    /* the engine's helper (it may run at once, inline: it then takes
     * every open chunk) */
    void *task = p->enqueue ? p->enqueue(help_task, p, p->user) : NULL;
    run_chunk(p, 0);
    claim_chunks(p, 0);
    wait_done(p);
    if (task)
        p->finish(task, p->user);
}

ms_status ms_vpool_set_tasks(ms_vpool *p, ms_enqueue_task_fn *enqueue, ms_finish_task_fn *finish,
                             void *user)
{
    if (!p)
        return MS_OK; /* one thread: nothing to hand over */
    if (!p->own) {    /* no threads of its own: the engine's task helps */
        p->enqueue = enqueue;
        p->finish = finish;
        p->user = user;
        return MS_OK;
    }
    if (enqueue && !p->enqueue)
        stop_workers(p);
    p->enqueue = enqueue;
    p->finish = finish;
    p->user = user;
    return MS_OK; /* without tasks, the next step starts the threads */
}

void ms_vpool_destroy(ms_vpool *p)
{
    if (!p)
        return;
    if (p->own)
        stop_workers(p);
    pthread_cond_destroy(&p->go);
    pthread_cond_destroy(&p->done_cv);
    pthread_mutex_destroy(&p->lock);
    ms_free(p);
}

/* One chunk as an engine task. */
static void task_part(void *argp)
{
    worker_arg *a = argp;
    ms_vpool *p = a->pool;
    int b, e;
    chunk(p->n, p->threads, a->part, &b, &e);
    if (e > b)
        p->fn(p->ctx, a->part, b, e);
}

static void run_on_tasks(ms_vpool *p, ms_vpool_fn *fn, void *ctx, int n)
{
    p->fn = fn;
    p->ctx = ctx;
    p->n = n;
    for (int t = 1; t < p->threads; ++t) {
        p->arg[t].pool = p;
        p->arg[t].part = t;
        p->handle[t] = p->enqueue(task_part, &p->arg[t], p->user); /* NULL: ran inline */
    }
    int b, e;
    chunk(n, p->threads, 0, &b, &e);
    if (e > b)
        fn(ctx, 0, b, e);
    for (int t = 1; t < p->threads; ++t)
        if (p->handle[t])
            p->finish(p->handle[t], p->user);
}

int ms_vpool_threads(const ms_vpool *p)
{
    /* a shared pool: the calling thread and one lent helper (or the
     * engine's task) */
    return p ? (p->own ? p->threads : 2) : 1;
}

int ms_vpool_parts(const ms_vpool *p)
{
    return p ? p->threads : 1;
}

void ms_vpool_run(ms_vpool *p, ms_vpool_fn *fn, void *ctx, int n)
{
    if (n <= 0)
        return;
    /* Small loops are not worth waking threads for; the chunks of the
     * calling thread then cover everything, with the same arithmetic. A
     * shared pool's hand-over (a helper's wake-up, an engine task) costs
     * more than a worker's: only from MS_VPOOL_SHARED_MIN on. */
    if (!p || n < 256 || (!p->own && n < MS_VPOOL_SHARED_MIN)) {
        fn(ctx, 0, 0, n);
        return;
    }
    if (p->own && p->enqueue)
        run_on_tasks(p, fn, ctx, n);
    else
        run_shared(p, fn, ctx, n);
}
