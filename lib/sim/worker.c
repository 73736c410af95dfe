/* The sim's own second thread for the two-core split (threads = 2 without
 * engine task callbacks): one persistent pthread that runs one task per
 * frame, handed over under a mutex (go/done generation counters), so a
 * frame costs two condition-variable signals, not a thread start. It
 * starts at the first frame that needs it (ms_sim_worker_ensure), not at
 * create: an engine that hands over its tasks after create
 * (ms_sim_set_tasks) gets no thread of the library's own, started and
 * stopped for nothing. */
#include <string.h>

#include "sim/sim_internal.h"

static void *worker_main(void *arg)
{
    ms_sim *sim = arg;
    long seen = 0;
    pthread_mutex_lock(&sim->mu);
    for (;;) {
        while (!sim->quit && sim->go_gen == seen)
            pthread_cond_wait(&sim->cv_go, &sim->mu);
        if (sim->quit)
            break;
        seen = sim->go_gen;
        ms_task_fn *fn = sim->worker_fn;
        void *fa = sim->worker_arg;
        pthread_mutex_unlock(&sim->mu);
        fn(fa);
        pthread_mutex_lock(&sim->mu);
        sim->done_gen = seen;
        pthread_cond_signal(&sim->cv_done);
    }
    pthread_mutex_unlock(&sim->mu);
    return NULL;
}

ms_status ms_sim_worker_start(ms_sim *sim)
{
    if (pthread_mutex_init(&sim->mu, NULL) != 0)
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: cannot create a mutex for the second thread");
    if (pthread_cond_init(&sim->cv_go, NULL) != 0) {
        pthread_mutex_destroy(&sim->mu);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: cannot create a condition variable");
    }
    if (pthread_cond_init(&sim->cv_done, NULL) != 0) {
        pthread_cond_destroy(&sim->cv_go);
        pthread_mutex_destroy(&sim->mu);
        return ms_fail(MS_ERR_OUT_OF_MEMORY, "sim: cannot create a condition variable");
    }
    sim->go_gen = sim->done_gen = 0;
    sim->quit = 0;
    if (pthread_create(&sim->worker, NULL, worker_main, sim) != 0) {
        pthread_cond_destroy(&sim->cv_done);
        pthread_cond_destroy(&sim->cv_go);
        pthread_mutex_destroy(&sim->mu);
        return ms_fail(MS_ERR_OUT_OF_MEMORY,
                       "sim: cannot start the second thread (threads 2); use threads 1");
    }
    sim->have_worker = 1;
    return MS_OK;
}

ms_status ms_sim_setup_threads(ms_sim *sim)
{
    if (sim->enqueue)
        ms_sim_worker_stop(sim);
    if (sim->threads != 2 || !sim->volume)
        return MS_OK; /* nothing runs beside the volume */
    /* work sharing: a volume of one thread splits its loops in
     * chunks that the other side claims while it has nothing to do: this
     * sim's second thread once its surface task is done (step.c), or one
     * engine task per loop (no thread of the library's own when
     * the engine gives its tasks). A volume-only sim too: its second side
     * is the height field's column search, which leaves most of the frame
     * free. The same bytes either way. */
    MS_TRY(ms_volume_share_loops(sim->volume));
    return ms_volume_set_tasks(sim->volume, sim->enqueue, sim->finish, sim->user_ctx);
}

ms_status ms_sim_worker_ensure(ms_sim *sim)
{
    if (sim->threads != 2 || !sim->volume || sim->enqueue || sim->have_worker)
        return MS_OK;
    return ms_sim_worker_start(sim);
}

void ms_sim_worker_stop(ms_sim *sim)
{
    if (!sim->have_worker)
        return;
    pthread_mutex_lock(&sim->mu);
    sim->quit = 1;
    pthread_cond_signal(&sim->cv_go);
    pthread_mutex_unlock(&sim->mu);
    pthread_join(sim->worker, NULL);
    pthread_cond_destroy(&sim->cv_done);
    pthread_cond_destroy(&sim->cv_go);
    pthread_mutex_destroy(&sim->mu);
    sim->have_worker = 0;
}

void ms_sim_worker_run(ms_sim *sim, ms_task_fn *fn, void *arg)
{
    pthread_mutex_lock(&sim->mu);
    sim->worker_fn = fn;
    sim->worker_arg = arg;
    ++sim->go_gen;
    pthread_cond_signal(&sim->cv_go);
    pthread_mutex_unlock(&sim->mu);
}

void ms_sim_worker_wait(ms_sim *sim)
{
    pthread_mutex_lock(&sim->mu);
    while (sim->done_gen != sim->go_gen)
        pthread_cond_wait(&sim->cv_done, &sim->mu);
    pthread_mutex_unlock(&sim->mu);
}
