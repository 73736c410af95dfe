/* PNG encoding off the render thread: `modesplit run --png` and
 * `modesplit render --png` hand each drawn frame's pixels (a copy) to one
 * writer thread, which encodes them with ms_image_write_png in the order
 * they came, while the caller draws the next frame. At most PNG_QUEUE_DEPTH
 * frames wait; the caller blocks when they do, so memory stays bounded and
 * the files are those a synchronous writer makes, byte for byte. Finishing
 * (also after SIGINT) writes every frame queued before it returns. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tool.h"

#define PNG_QUEUE_DEPTH 2 /* frames waiting besides the one being encoded */

typedef struct png_job {
    char *path;
    unsigned char *rgba;
    size_t cap; /* bytes of rgba */
    int w, h;
} png_job;

struct png_queue {
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t changed;
    png_job jobs[PNG_QUEUE_DEPTH + 1]; /* a ring */
    int head, count;                   /* the oldest waiting job, jobs waiting */
    int stop;
    int failed;   /* a frame could not be written: the first one's sentence */
    int reported; /* ... already printed */
    char error[512];
};

static void *writer(void *arg)
{
    png_queue *q = arg;
    pthread_mutex_lock(&q->lock);
    for (;;) {
        while (!q->count && !q->stop)
            pthread_cond_wait(&q->changed, &q->lock);
        if (!q->count)
            break; /* stopped, nothing left */
        /* jobs[head] stays counted until it is written: the caller fills
         * only the free slots of the ring */
        png_job *j = &q->jobs[q->head];
        pthread_mutex_unlock(&q->lock);
        ms_status st = q->failed ? MS_OK : ms_image_write_png(j->path, j->rgba, j->w, j->h);
        pthread_mutex_lock(&q->lock);
        if (st != MS_OK && !q->failed) {
            q->failed = 1;
            snprintf(q->error, sizeof q->error, "%s", ms_last_error());
        }
        q->head = (q->head + 1) % (PNG_QUEUE_DEPTH + 1);
        --q->count;
        pthread_cond_broadcast(&q->changed);
    }
    pthread_mutex_unlock(&q->lock);
    return NULL;
}

int png_queue_start(png_queue **out)
{
    *out = NULL;
    png_queue *q = calloc(1, sizeof *q);
    if (!q) {
        tool_error("out of memory for the PNG writer");
        return -1;
    }
    pthread_mutex_init(&q->lock, NULL);
    pthread_cond_init(&q->changed, NULL);
    int err = pthread_create(&q->thread, NULL, writer, q);
    if (err) {
        tool_error("cannot start the PNG writer thread: %s", strerror(err));
        pthread_cond_destroy(&q->changed);
        pthread_mutex_destroy(&q->lock);
        free(q);
        return -1;
    }
    *out = q;
    return 0;
}

int png_queue_push(png_queue *q, const char *path, const unsigned char *rgba, int w, int h)
{
    const size_t bytes = (size_t)w * (size_t)h * 4;
    pthread_mutex_lock(&q->lock);
    while (q->count == PNG_QUEUE_DEPTH + 1 && !q->failed)
        pthread_cond_wait(&q->changed, &q->lock);
    if (q->failed) {
        tool_error("%s", q->error);
        q->reported = 1;
        pthread_mutex_unlock(&q->lock);
        return -1;
    }
    /* the free slot after the waiting ones: the writer never touches it */
    png_job *j = &q->jobs[(q->head + q->count) % (PNG_QUEUE_DEPTH + 1)];
    pthread_mutex_unlock(&q->lock);
    if (j->cap < bytes) {
        free(j->rgba);
        j->rgba = malloc(bytes);
        j->cap = j->rgba ? bytes : 0;
    }
    free(j->path);
    j->path = strdup(path);
    if (!j->rgba || !j->path) {
        tool_error("out of memory for a PNG frame (%d x %d)", w, h);
        return -1;
    }
    memcpy(j->rgba, rgba, bytes);
    j->w = w;
    j->h = h;
    pthread_mutex_lock(&q->lock);
    ++q->count;
    pthread_cond_broadcast(&q->changed);
    pthread_mutex_unlock(&q->lock);
    return 0;
}

int png_queue_finish(png_queue *q)
{
    if (!q)
        return 0;
    pthread_mutex_lock(&q->lock);
    q->stop = 1;
    pthread_cond_broadcast(&q->changed);
    pthread_mutex_unlock(&q->lock);
    pthread_join(q->thread, NULL);
    int failed = q->failed;
    if (failed && !q->reported)
        tool_error("%s", q->error);
    for (int k = 0; k <= PNG_QUEUE_DEPTH; ++k) {
        free(q->jobs[k].path);
        free(q->jobs[k].rgba);
    }
    pthread_cond_destroy(&q->changed);
    pthread_mutex_destroy(&q->lock);
    free(q);
    return failed ? -1 : 0;
}
