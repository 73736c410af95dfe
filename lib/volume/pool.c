/* The worker threads of one volume: a parallel loop over particles split
 * into as many contiguous chunks as there are threads. Every chunk does the
 * same per-particle arithmetic as the sequential loop (gathers, no shared
 * sums), so the results are the same bytes for any thread count; only
 * order-free reductions (max) are combined across chunks.
 * When an engine gives its task interface (ms_volume_set_tasks), the pool
 * stops its own threads and runs chunks 1.. as the engine's tasks
 * (enqueue, then finish each), chunk 0 on the calling thread: the same
 * split, the same bytes.
 * A shared pool (ms_vpool_create_shared, issue 12's work sharing) has no
 * threads of its own: each loop's chunks are claimed one at a time by the
 * calling thread and by whoever else has a moment: a helper that another
 * part of the program lends while it has nothing to do (ms_vpool_help
 * between help_open and help_close: lib/sim's second thread once its
 * surface task is done), and, given the engine's task interface, one
 * engine task per loop that claims chunks like the helper (issue 15: the
 * volume's parallel-for through the engine's enqueue/finish, no thread of
 * the library's own). Chunks are claimed as they come, so a helper that
 * arrives late still takes its share; who runs a chunk changes nothing in
 * it, so the bytes are the same. */
#include <pthread.h>

#include "volume/extract.h"
#include "volume/volume_internal.h"

typedef struct worker_arg {
    struct ms_vpool *pool;
    int part;
    unsigned long start_gen; /* the loops before this worker started */
} worker_arg;

struct ms_vpool {
    int threads;  /* including the calling thread */
    int started;  /* workers running */
    pthread_t tid[MS_VOLUME_MAX_THREADS];
    worker_arg arg[MS_VOLUME_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t go, done;
    unsigned long generation; /* bumped for each loop */
    int pending;              /* workers still running the current loop */
    int quit;
    ms_vpool_fn *fn;
    void *ctx;
    int n;
    /* the engine's tasks, or NULL: the pool's own threads */
    ms_enqueue_task_fn *enqueue;
    ms_finish_task_fn *finish;
    void *user;
    void *handle[MS_VOLUME_MAX_THREADS];
    /* shared pool: chunks claimed by the caller and a helper */
    int shared;
    int next;     /* the next unclaimed chunk of the current loop */
    int help_open; /* a helper may claim chunks */
};

static void chunk(int n, int parts, int part, int *b, int *e)
{
    long nn = n;
    *b = (int)(nn * part / parts);
    *e = (int)(nn * (part + 1) / parts);
}

static void *worker(void *argp)
{
    worker_arg *a = argp;
    ms_vpool *p = a->pool;
    unsigned long seen = a->start_gen;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        while (p->generation == seen && !p->quit)
            pthread_cond_wait(&p->go, &p->lock);
        if (p->quit) {
            pthread_mutex_unlock(&p->lock);
            return NULL;
        }
        seen = p->generation;
        ms_vpool_fn *fn = p->fn;
        void *ctx = p->ctx;
        int n = p->n;
        pthread_mutex_unlock(&p->lock);
        int b, e;
        chunk(n, p->threads, a->part, &b, &e);
        if (e > b)
            fn(ctx, a->part, b, e);
        pthread_mutex_lock(&p->lock);
        if (--p->pending == 0)
            pthread_cond_signal(&p->done);
        pthread_mutex_unlock(&p->lock);
    }
}

static ms_status start_workers(ms_vpool *p)
{
    p->quit = 0;
    for (int t = 1; t < p->threads; ++t) {
        p->arg[t].pool = p;
        p->arg[t].part = t;
        p->arg[t].start_gen = p->generation;
        if (pthread_create(&p->tid[t], NULL, worker, &p->arg[t]) != 0)
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "volume: could not start worker thread %d of %d", t, p->threads);
        p->started = t;
    }
    return MS_OK;
}

static void stop_workers(ms_vpool *p)
{
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
    for (int t = 1; t <= p->started; ++t)
        pthread_join(p->tid[t], NULL);
    p->started = 0;
}

ms_status ms_vpool_create(int threads, ms_vpool **out)
{
    *out = NULL;
    if (threads <= 1)
        return MS_OK; /* a NULL pool runs loops inline */
    ms_vpool *p = ms_alloc(sizeof *p);
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the thread pool");
    p->threads = threads;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->go, NULL);
    pthread_cond_init(&p->done, NULL);
    ms_status st = start_workers(p);
    if (st != MS_OK) {
        ms_vpool_destroy(p);
        return st;
    }
    *out = p;
    return MS_OK;
}

ms_status ms_vpool_create_shared(int parts, ms_vpool **out)
{
    *out = NULL;
    ms_vpool *p = ms_alloc(sizeof *p);
    if (!p)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "volume: out of memory for the thread pool");
    p->threads = parts;
    p->shared = 1;
    p->next = parts; /* no loop yet */
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->go, NULL);
    pthread_cond_init(&p->done, NULL);
    *out = p;
    return MS_OK;
}

/* Runs claimed chunks of the current loop; the lock is held on entry and
 * on return. */
static void claim_chunks(ms_vpool *p)
{
    while (p->next < p->threads) {
        const int part = p->next++;
        ms_vpool_fn *fn = p->fn;
        void *ctx = p->ctx;
        const int n = p->n, parts = p->threads;
        pthread_mutex_unlock(&p->lock);
        int b, e;
        chunk(n, parts, part, &b, &e);
        if (e > b)
            fn(ctx, part, b, e);
        pthread_mutex_lock(&p->lock);
        if (--p->pending == 0)
            pthread_cond_broadcast(&p->done);
    }
}

void ms_vpool_help_open(ms_vpool *p)
{
    if (!p || !p->shared)
        return;
    pthread_mutex_lock(&p->lock);
    p->help_open = 1;
    pthread_mutex_unlock(&p->lock);
}

void ms_vpool_help_close(ms_vpool *p)
{
    if (!p || !p->shared)
        return;
    pthread_mutex_lock(&p->lock);
    p->help_open = 0;
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
}

void ms_vpool_help(ms_vpool *p)
{
    if (!p || !p->shared)
        return;
    pthread_mutex_lock(&p->lock);
    while (p->help_open) {
        claim_chunks(p);
        if (p->help_open)
            pthread_cond_wait(&p->go, &p->lock);
    }
    pthread_mutex_unlock(&p->lock);
}

/* A shared pool's engine task: the chunks of the current loop still open
 * (none if the loop was done before the engine ran it). */
static void help_task(void *argp)
{
    ms_vpool *p = argp;
    pthread_mutex_lock(&p->lock);
    claim_chunks(p);
    pthread_mutex_unlock(&p->lock);
}

ms_status ms_vpool_set_tasks(ms_vpool *p, ms_enqueue_task_fn *enqueue, ms_finish_task_fn *finish,
                             void *user)
{
    if (!p)
        return MS_OK; /* one thread: nothing to hand over */
    if (p->shared) { /* no threads of its own: the engine's task helps */
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
    if (!enqueue && !p->started && !p->shared)
        return start_workers(p);
    return MS_OK;
}

void ms_vpool_destroy(ms_vpool *p)
{
    if (!p)
        return;
    stop_workers(p);
    pthread_cond_destroy(&p->go);
    pthread_cond_destroy(&p->done);
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
    return p ? (p->shared ? 2 : p->threads) : 1;
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
    if (!p || n < 256 || (p->shared && n < MS_VPOOL_SHARED_MIN)) {
        fn(ctx, 0, 0, n);
        return;
    }
    if (p->shared) {
        pthread_mutex_lock(&p->lock);
        p->fn = fn;
        p->ctx = ctx;
        p->n = n;
        p->next = 0;
        p->pending = p->threads;
        if (p->help_open)
            pthread_cond_broadcast(&p->go);
        void *task = NULL;
        if (p->enqueue) {
            /* the engine's helper, outside the lock (it may run at once,
             * inline: then it takes every chunk, and this thread none) */
            pthread_mutex_unlock(&p->lock);
            task = p->enqueue(help_task, p, p->user);
            pthread_mutex_lock(&p->lock);
        }
        claim_chunks(p);
        while (p->pending > 0) /* chunks a helper is still running */
            pthread_cond_wait(&p->done, &p->lock);
        pthread_mutex_unlock(&p->lock);
        if (task)
            p->finish(task, p->user);
        return;
    }
    if (p->enqueue) {
        run_on_tasks(p, fn, ctx, n);
        return;
    }
    pthread_mutex_lock(&p->lock);
    p->fn = fn;
    p->ctx = ctx;
    p->n = n;
    p->pending = p->threads - 1;
    p->generation++;
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
    int b, e;
    chunk(n, p->threads, 0, &b, &e);
    if (e > b)
        fn(ctx, 0, b, e);
    pthread_mutex_lock(&p->lock);
    while (p->pending > 0)
        pthread_cond_wait(&p->done, &p->lock);
    pthread_mutex_unlock(&p->lock);
}
