/* SPDX-License-Identifier: MIT */
/* A blocking call with a timeout: the call runs on a helper thread and the
 * caller waits at most timeout_ms for it. Used for FBIO_WAITFORVSYNC, which
 * some fbdev drivers never complete: the program loses one timeout, once,
 * instead of freezing. A call that never returns leaves its thread behind
 * (it owns no lock the program needs); the waiter frees itself if the call
 * ever comes back after fx_waiter_destroy. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <time.h>

#include "posix_int.h"
#include "fixel/error.h"

struct fx_waiter {
    pthread_t thread;
    pthread_mutex_t lock;
    pthread_cond_t cond;
    int (*fn)(void *arg);
    void *arg;
    int requested, running, done, result, orphaned, quit;
};

static void *waiter_main(void *p)
{
    fx_waiter *w = p;
    pthread_mutex_lock(&w->lock);
    for (;;) {
        while (!w->requested && !w->quit)
            pthread_cond_wait(&w->cond, &w->lock);
        if (w->quit)
            break;
        w->requested = 0;
        w->running = 1;
        pthread_mutex_unlock(&w->lock);
        int r = w->fn(w->arg);
        pthread_mutex_lock(&w->lock);
        w->running = 0;
        if (w->orphaned)
            break;
        w->result = r;
        w->done = 1;
        pthread_cond_broadcast(&w->cond);
    }
    int free_it = w->orphaned;
    pthread_mutex_unlock(&w->lock);
    if (free_it) {
        pthread_mutex_destroy(&w->lock);
        pthread_cond_destroy(&w->cond);
        free(w);
    }
    return NULL;
}

int fx_waiter_create(fx_waiter **out, int (*fn)(void *arg), void *arg)
{
    fx_waiter *w = calloc(1, sizeof *w);
    pthread_condattr_t ca;
    sigset_t all, old;
    *out = NULL;
    if (!w)
        return -FX_ENOMEM;
    w->fn = fn;
    w->arg = arg;
    pthread_mutex_init(&w->lock, NULL);
    pthread_condattr_init(&ca);
    pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
    pthread_cond_init(&w->cond, &ca);
    pthread_condattr_destroy(&ca);
    /* The helper must never take the program's signals: an event loop that
     * blocks SIGINT/SIGTERM for signalfd would otherwise see them delivered
     * here, with their default action. */
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    int r = pthread_create(&w->thread, NULL, waiter_main, w);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (r != 0) {
        pthread_mutex_destroy(&w->lock);
        pthread_cond_destroy(&w->cond);
        free(w);
        return -r;
    }
    *out = w;
    return 0;
}

int fx_waiter_run(fx_waiter *w, int timeout_ms, int *result)
{
    struct timespec end;
    int r = 0;
    clock_gettime(CLOCK_MONOTONIC, &end);
    end.tv_sec += timeout_ms / 1000;
    end.tv_nsec += (long)(timeout_ms % 1000) * 1000000L;
    if (end.tv_nsec >= 1000000000L) {
        end.tv_sec++;
        end.tv_nsec -= 1000000000L;
    }
    pthread_mutex_lock(&w->lock);
    /* A call that timed out earlier is not queued twice: this run waits for
     * it, or collects it when it has finished meanwhile. */
    if (!w->running && !w->requested && !w->done) {
        w->requested = 1;
        pthread_cond_broadcast(&w->cond);
    }
    while (!w->done && r != ETIMEDOUT)
        r = pthread_cond_timedwait(&w->cond, &w->lock, &end);
    int finished = w->done;
    if (finished && result)
        *result = w->result;
    w->done = 0;
    pthread_mutex_unlock(&w->lock);
    return finished ? 0 : 1;
}

void fx_waiter_destroy(fx_waiter *w)
{
    if (!w)
        return;
    pthread_mutex_lock(&w->lock);
    if (w->running) {
        w->orphaned = 1;
        pthread_mutex_unlock(&w->lock);
        pthread_detach(w->thread);
        return;
    }
    w->quit = 1;
    w->requested = 0;
    pthread_cond_broadcast(&w->cond);
    pthread_mutex_unlock(&w->lock);
    pthread_join(w->thread, NULL);
    pthread_mutex_destroy(&w->lock);
    pthread_cond_destroy(&w->cond);
    free(w);
}
