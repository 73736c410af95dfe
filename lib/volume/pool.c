/* The worker threads of one volume: a parallel loop over particles split
 * into as many contiguous chunks as there are threads. Every chunk does the
 * same per-particle arithmetic as the sequential loop (gathers, no shared
 * sums), so the results are the same bytes for any thread count; only
 * order-free reductions (max) are combined across chunks. */
#include <pthread.h>

#include "volume/volume_impl.h"

typedef struct worker_arg {
    struct ms_vpool *pool;
    int part;
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
    unsigned long seen = 0;
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
    for (int t = 1; t < threads; ++t) {
        p->arg[t].pool = p;
        p->arg[t].part = t;
        if (pthread_create(&p->tid[t], NULL, worker, &p->arg[t]) != 0) {
            ms_vpool_destroy(p);
            return ms_fail(MS_ERR_OUT_OF_MEMORY,
                           "volume: could not start worker thread %d of %d", t, threads);
        }
        p->started = t;
    }
    *out = p;
    return MS_OK;
}

void ms_vpool_destroy(ms_vpool *p)
{
    if (!p)
        return;
    pthread_mutex_lock(&p->lock);
    p->quit = 1;
    pthread_cond_broadcast(&p->go);
    pthread_mutex_unlock(&p->lock);
    for (int t = 1; t <= p->started; ++t)
        pthread_join(p->tid[t], NULL);
    pthread_cond_destroy(&p->go);
    pthread_cond_destroy(&p->done);
    pthread_mutex_destroy(&p->lock);
    ms_free(p);
}

int ms_vpool_threads(const ms_vpool *p)
{
    return p ? p->threads : 1;
}

void ms_vpool_run(ms_vpool *p, ms_vpool_fn *fn, void *ctx, int n)
{
    if (n <= 0)
        return;
    /* Small loops are not worth waking threads for; the chunks of the
     * calling thread then cover everything, with the same arithmetic. */
    if (!p || n < 256) {
        fn(ctx, 0, 0, n);
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
