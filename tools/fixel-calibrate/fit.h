/* SPDX-License-Identifier: MIT */
/* fixel-calibrate's arithmetic: the affine map from raw touch units to
 * physical screen pixels fitted to touched targets, tslib's pointercal form
 * of it, and where fixel puts a raw point with that file. */
#ifndef FIXEL_CALIBRATE_FIT_H
#define FIXEL_CALIBRATE_FIT_H

#include <stdint.h>

typedef struct cal_point {
    double rx, ry; /* raw device units (mean of one touch) */
    double sx, sy; /* the target, physical screen pixels */
} cal_point;

/* Least squares over n >= 3 points: sx = a[0]*rx + a[1]*ry + a[2],
 * sy = a[3]*rx + a[4]*ry + a[5]. Returns 0, or -1 when the raw points are
 * (nearly) on one line and fix nothing. */
int cal_fit(const cal_point *p, int n, double a[6]);

/* tslib's pointercal integers: a[0..5] scaled by a6 = 65536 and rounded.
 * Returns 0, or -1 when a value does not fit in 32 bits. */
int cal_pointercal(const double a[6], int32_t out[7]);

/* The physical pixel fixel computes from raw (rx, ry) with pointercal c
 * (boards' to_screen: 64-bit integer arithmetic, truncating division). */
void cal_apply(const int32_t c[7], int32_t rx, int32_t ry, int32_t *sx, int32_t *sy);

/* Logical (x, y) on a display rotated clockwise by rot, physical size pw x ph,
 * to the physical pixel showing it (fixel/display.h's convention). */
void cal_logical_to_physical(int rot, int32_t pw, int32_t ph, int32_t x, int32_t y, int32_t *px, int32_t *py);

#endif
