/* SPDX-License-Identifier: MIT */
/* fixel-bench --frames (frames.c): the frames table on o; self is argv[0]
 * (fixel-kiosk is looked for next to it); nthreads the banded runs' thread
 * count (0: every core, at least 2); reps frames per median (1..64); only NULL or a comma-separated list of
 * parts of row labels ("demo", "script 3d-teapot", "kiosk", "present"). Returns 0; 1 when a script
 * failed; 2 for a bad nthreads. */
#ifndef FIXEL_BENCH_FRAMES_H
#define FIXEL_BENCH_FRAMES_H
#include <stdio.h>
int frames_run(FILE *o, const char *self, int nthreads, int reps, const char *only);
#endif
