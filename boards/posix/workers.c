/* SPDX-License-Identifier: MIT */
/* fixel — the worker threads the tiled renderers share (posix_int.h). */
#include <pthread.h>

#include "posix_int.h"

int fx_posix_workers(void *(*fn)(void *), void *arg, int nthreads)
{
    pthread_t t[64];
    int started = 0, spawn_err = 0;
    for (int i = 1; i < nthreads && i < 64; i++) {
        int e = pthread_create(&t[started], 0, fn, arg);
        if (e) {
            spawn_err = -e;
            break;
        }
        started++;
    }
    fn(arg);
    for (int i = 0; i < started; i++)
        pthread_join(t[i], 0);
    return spawn_err;
}
