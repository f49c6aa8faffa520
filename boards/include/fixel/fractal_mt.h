/* SPDX-License-Identifier: MIT */
/* fixel — escape-time fractals on several threads (boards side: pthreads).
 *
 * The frame rectangle is cut into bands of rows that worker threads take in
 * turn from a shared counter. Each pixel of the core renderer depends only
 * on its own (x, y), so the picture is identical to fx_fractal_render on
 * one thread whatever the thread count and scheduling (Julia views lose the
 * in-rectangle mirroring, not a pixel). */
#ifndef FIXEL_FRACTAL_MT_H
#define FIXEL_FRACTAL_MT_H

#include "fixel/fractal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Render r of the view onto s with nthreads threads (1..64; 1 runs on the
 * caller's thread only). Returns 0, -FX_EINVAL, or a negative errno when a
 * thread cannot be started (the threads that did start finish the picture). */
int fx_fractal_render_mt(const fx_surface *s, fx_rect r, const fx_fractal_view *v,
                         const fx_dwell_pal *pal, int nthreads);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
