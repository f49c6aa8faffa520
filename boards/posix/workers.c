/* SPDX-License-Identifier: MIT */
/* fixel — the worker threads the tiled renderers share (posix_int.h).
 *
 * The threads are kept between calls: a frame of a few milliseconds drawn
 * on two threads lost most of its gain to starting the second one each
 * time (the kiosk, whose workers were kept, went from 1.07x to 1.81x on a
 * busy 2-core machine). A call claims idle pool threads, or starts new ones
 * up to 63; a thread is never shared by two calls at once, so nested and
 * concurrent calls cannot wait on each other: a call that finds no thread
 * free simply runs on fewer (every fn here takes its work from a shared
 * counter). The threads block the asynchronous signals (a program's
 * signalfd or handler stays on its own threads) but not the ones a fault
 * raises (SIGSEGV, SIGBUS, ...: blocked, the kernel would kill the process
 * without running the console-restoring handler), and are stopped at exit.
 * A child forked during a call has none of the pool's threads: its copy of
 * the call returns without their part of the work. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include "posix_int.h"

enum { SLOT_IDLE, SLOT_RUN, SLOT_DONE, SLOT_QUIT };

typedef struct slot {
    pthread_t t;
    pthread_mutex_t m;
    pthread_cond_t cv;
    void *(*fn)(void *);
    void *arg;
    int state; /* SLOT_*, under m */
    int busy;  /* claimed by a call (or by pool_stop), under pool_lock */
} slot;

#define POOL_MAX 63
static slot pool[POOL_MAX];
static int pool_n;
static pthread_mutex_t pool_lock = PTHREAD_MUTEX_INITIALIZER;
static int pool_hooks;
static int pool_closed;     /* after exit began: nothing is claimed */
static unsigned pool_gen;   /* a fork's child starts a new generation */

static void *pool_thread(void *p)
{
    slot *s = p;
    pthread_mutex_lock(&s->m);
    for (;;) {
        while (s->state != SLOT_RUN && s->state != SLOT_QUIT)
            pthread_cond_wait(&s->cv, &s->m);
        if (s->state == SLOT_QUIT)
            break;
        pthread_mutex_unlock(&s->m);
        s->fn(s->arg);
        pthread_mutex_lock(&s->m);
        s->state = SLOT_DONE;
        pthread_cond_broadcast(&s->cv);
    }
    pthread_mutex_unlock(&s->m);
    return 0;
}

/* At exit, stop the idle threads (a leak checker then sees no live thread);
 * one still claimed by a call on another thread is left running. Which ones
 * are decided under the lock, and none is claimed after. */
static void pool_stop(void)
{
    int stop[POOL_MAX], n = 0;
    pthread_mutex_lock(&pool_lock);
    pool_closed = 1;
    for (int i = 0; i < pool_n; i++)
        if (!pool[i].busy) {
            pool[i].busy = 1;
            stop[n++] = i;
        }
    pthread_mutex_unlock(&pool_lock);
    for (int k = 0; k < n; k++) {
        int i = stop[k];
        pthread_mutex_lock(&pool[i].m);
        pool[i].state = SLOT_QUIT;
        pthread_cond_broadcast(&pool[i].cv);
        pthread_mutex_unlock(&pool[i].m);
        pthread_join(pool[i].t, 0);
    }
}

/* A child of fork has none of the threads: it starts with an empty pool. */
static void pool_forget(void)
{
    memset(pool, 0, sizeof pool);
    pool_n = 0;
    pool_gen++; /* a call the fork interrupted waits for none of them */
    pthread_mutex_t fresh = PTHREAD_MUTEX_INITIALIZER;
    pool_lock = fresh;
}

static void pool_lock_fork(void) { pthread_mutex_lock(&pool_lock); }
static void pool_unlock_fork(void) { pthread_mutex_unlock(&pool_lock); }

/* A new thread for slot s (pool_lock held); 0 or -errno. */
static int pool_grow(slot *s)
{
    memset(s, 0, sizeof *s);
    pthread_mutex_init(&s->m, 0);
    pthread_cond_init(&s->cv, 0);
    sigset_t all, old;
    sigfillset(&all);
    static const int faults[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGSYS, SIGABRT};
    for (size_t i = 0; i < sizeof faults / sizeof faults[0]; i++)
        sigdelset(&all, faults[i]);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    int e = pthread_create(&s->t, 0, pool_thread, s);
    pthread_sigmask(SIG_SETMASK, &old, 0);
    if (e) {
        pthread_cond_destroy(&s->cv);
        pthread_mutex_destroy(&s->m);
        return -e;
    }
    return 0;
}

int fx_posix_pool_start(fx_posix_batch *b, void *(*fn)(void *), void *arg, int n)
{
    int err = 0;
    b->n = 0;
    if (n > POOL_MAX)
        n = POOL_MAX;
    pthread_mutex_lock(&pool_lock);
    b->gen = pool_gen;
    if (pool_closed)
        n = 0;
    if (!pool_hooks) {
        pool_hooks = 1;
        atexit(pool_stop);
        pthread_atfork(pool_lock_fork, pool_unlock_fork, pool_forget);
    }
    for (int i = 0; i < pool_n && b->n < n; i++)
        if (!pool[i].busy) {
            pool[i].busy = 1;
            b->slot[b->n++] = i;
        }
    while (b->n < n && pool_n < POOL_MAX) {
        err = pool_grow(&pool[pool_n]);
        if (err)
            break;
        pool[pool_n].busy = 1;
        b->slot[b->n++] = pool_n++;
    }
    pthread_mutex_unlock(&pool_lock);
    for (int i = 0; i < b->n; i++) {
        slot *s = &pool[b->slot[i]];
        pthread_mutex_lock(&s->m);
        s->fn = fn;
        s->arg = arg;
        s->state = SLOT_RUN;
        pthread_cond_signal(&s->cv);
        pthread_mutex_unlock(&s->m);
    }
    return err;
}

void fx_posix_pool_wait(fx_posix_batch *b)
{
    pthread_mutex_lock(&pool_lock);
    int gone = b->gen != pool_gen;
    pthread_mutex_unlock(&pool_lock);
    if (gone) { /* forked during the call: those threads are the parent's */
        b->n = 0;
        return;
    }
    for (int i = 0; i < b->n; i++) {
        slot *s = &pool[b->slot[i]];
        pthread_mutex_lock(&s->m);
        while (s->state != SLOT_DONE)
            pthread_cond_wait(&s->cv, &s->m);
        s->state = SLOT_IDLE;
        pthread_mutex_unlock(&s->m);
    }
    pthread_mutex_lock(&pool_lock);
    for (int i = 0; i < b->n; i++)
        pool[b->slot[i]].busy = 0;
    pthread_mutex_unlock(&pool_lock);
    b->n = 0;
}

int fx_posix_pool_size(void)
{
    pthread_mutex_lock(&pool_lock);
    int n = pool_n;
    pthread_mutex_unlock(&pool_lock);
    return n;
}

int fx_posix_workers(void *(*fn)(void *), void *arg, int nthreads)
{
    fx_posix_batch b;
    int err = fx_posix_pool_start(&b, fn, arg, nthreads > 64 ? 63 : nthreads - 1);
    fn(arg);
    fx_posix_pool_wait(&b);
    return err;
}
