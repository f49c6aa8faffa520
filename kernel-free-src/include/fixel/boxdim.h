/* SPDX-License-Identifier: MIT */
/* fixel — fractal dimension by box counting.
 *
 * Cover a picture with a grid of s x s boxes and count N(s), the boxes that
 * hold at least one pixel of the figure; for a self-similar figure
 * N(s) ~ s^-D, so D is the slope of log N(s) against log(1/s). The slope is
 * the least-squares fit over several box sizes, in Q16.16 with integer
 * base-2 logarithms (the base cancels in the slope). On a drawn figure the
 * finest boxes see pixels, not the fractal: pick sizes from a few pixels up
 * to a fraction of the figure (tests/core/test_fractal_dim.c measures the
 * course's figures within stated tolerances).
 */
#ifndef FIXEL_BOXDIM_H
#define FIXEL_BOXDIM_H

#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* log2(v) in Q16.16 for v >= 1 (0 for v == 0), within 2^-15. */
fx16 fx_log2_16(uint64_t v);

/* The boxes of the grid of box x box cells anchored at r's top-left corner
 * (the last row and column may be partial) that contain a pixel of s inside
 * r whose native value differs from bg. r is clipped to s; box >= 1.
 * Returns the count or -FX_EINVAL. */
int32_t fx_boxcount(const fx_surface *s, fx_rect r, uint32_t bg, int32_t box);

/* The least-squares slope of log2 counts[i] against -log2 sizes[i] over n
 * sizes (2..FX_BOXDIM_MAX_SIZES, distinct, each size >= 1 and count >= 1)
 * into *dim (Q16.16). Returns 0 or -FX_EINVAL. */
#define FX_BOXDIM_MAX_SIZES 24
int fx_boxdim_fit(const int32_t *sizes, const int32_t *counts, int n, fx16 *dim);

/* Both: boxes of sizes smin, 2 smin, 4 smin ... <= smax (at least two
 * sizes) over r; counts (FX_BOXDIM_MAX_SIZES entries) and *nsizes receive
 * the measurements when not NULL. Returns 0 or -FX_EINVAL. */
int fx_boxdim_surface(const fx_surface *s, fx_rect r, uint32_t bg, int32_t smin, int32_t smax, fx16 *dim,
                      int32_t *counts, int *nsizes);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
