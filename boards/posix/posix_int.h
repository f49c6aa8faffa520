/* SPDX-License-Identifier: MIT */
/* Internal to boards/: the bottom layer of the boards side, above the core
 * only. A logger (the display's log function and level, handed down to the
 * console and input layers so they never call up into the display), the
 * permission hint, and a blocking call with a timeout. POSIX and pthreads;
 * no board library, no fixel object. Not installed. */
#ifndef FIXEL_POSIX_INT_H
#define FIXEL_POSIX_INT_H

#include <stdarg.h>
#include <stdint.h>

#include "fixel/log.h"

/* Where a layer's diagnostics go: messages above priority are dropped. */
typedef struct fx_logger {
    fx_log_func fn;
    void *user;
    int priority;
} fx_logger;

void fx_logv(const fx_logger *l, fx_log_priority p, const char *fmt, va_list ap);
void fx_log(const fx_logger *l, fx_log_priority p, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The default log function: "fixel: " and the message on stderr. */
void fx_log_stderr(fx_log_priority p, void *user, const char *fmt, va_list ap);

/* When open() on path fails with EACCES, name the group that owns the node. */
void fx_log_access_hint(const fx_logger *l, const char *path);

/* ---- worker threads (workers.c) ---- */

/* Run fn(arg) on nthreads threads (1..64): nthreads - 1 started, and the
 * caller's; returns when all have returned: 0, or the -errno of a thread
 * that could not start (those that did start still do all the work). */
int fx_posix_workers(void *(*fn)(void *), void *arg, int nthreads);

/* The threads behind it, kept alive between calls: start fn(arg) on up to
 * n (0..63) idle pool threads, starting new ones as needed; b->n says how
 * many took it (fewer when threads cannot be started, the -errno then
 * returned, or when other calls hold the rest). fx_posix_pool_wait returns
 * when they have all returned from fn. */
typedef struct fx_posix_batch {
    int n;
    unsigned gen;
    int slot[63];
} fx_posix_batch;
int fx_posix_pool_start(fx_posix_batch *b, void *(*fn)(void *), void *arg, int n);
void fx_posix_pool_wait(fx_posix_batch *b);
/* Threads in the pool (busy or idle). */
int fx_posix_pool_size(void);

/* ---- band cuts of fx_scene_run_mt (par.c) ---- */

/* New cuts out[0..n] for n bands whose rows were [cut[k], cut[k + 1]) and
 * cost cost[k] each (cut[0] = 0, cut[n] = rows): the cost spread evenly
 * over each band's rows, cut into n equal parts, every band at least one
 * row. Equal bands when the costs say nothing (all zero, negative). */
void fx_par_balance(int n, const int32_t *cut, const int64_t *cost, int32_t *out);
/* The cuts fx_scene_run_mt will use for the last script it ran banded, if
 * that script runs again at the same size, format and band count. */
void fx_par_last_cuts(int32_t *cut, int n);

/* ---- blocking calls with a timeout (waiter.c) ---- */

typedef struct fx_waiter fx_waiter;
/* A helper thread (all signals blocked) that runs fn(arg) on request. */
int fx_waiter_create(fx_waiter **w, int (*fn)(void *arg), void *arg);
/* Run fn and wait at most timeout_ms: 0 when it returned (its value in
 * *result), 1 when it is still running (a later run waits for, or collects,
 * that same call instead of starting another). */
int fx_waiter_run(fx_waiter *w, int timeout_ms, int *result);
/* Stop the thread; one stuck in fn is left to free everything itself. */
void fx_waiter_destroy(fx_waiter *w);

#endif
