/* SPDX-License-Identifier: MIT */
/* fixel-bench — the clock and the sort order every table of it times and
 * takes medians with (TABLE 1's trials, the extras, --frames, --w3-classes). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include "bench.h"
#include <time.h>

double bench_secs(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}
