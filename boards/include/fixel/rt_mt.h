/* SPDX-License-Identifier: MIT */
/* fixel — the ray tracer (fixel/rt.h) on several threads (boards side:
 * pthreads).
 *
 * The image is cut into bands of rows that worker threads take in turn from
 * a shared counter; the core renders each band (fx_rt_render draws a tile).
 * Every pixel depends only on its own rays, so the picture equals the
 * one-thread render whatever the thread count and scheduling. A callback
 * may present rows as they finish (progressive display). */
#ifndef FIXEL_RT_MT_H
#define FIXEL_RT_MT_H

#include "fixel/rt.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Rows [y0, y1) are finished. Calls are serialised (one at a time) and come
 * from the worker threads, in the order bands finish. */
typedef void (*fx_rt_rows_fn)(void *user, int32_t y0, int32_t y1);

/* Render the whole surface on nthreads threads (1..64; 1 runs on the
 * caller's thread only), in bands of band_rows rows (1..surface height;
 * 0 picks 4). Returns 0, -FX_EINVAL, or a negative errno when a thread
 * cannot be started (the threads that did start finish the picture). */
int fx_rt_render_mt(const fx_rt_scene *s, const fx_surface *surf, int nthreads, int32_t band_rows,
                    fx_rt_rows_fn done, void *user);

/* The same for the rectangle [x, x + w) x [y, y + h) only, clipped to the
 * surface (the 'raytrace X Y W H' tile): bands are rows of the clipped
 * rectangle, done gets surface rows. band_rows 0 picks 4; a band taller
 * than the rectangle is one band. Returns as fx_rt_render_mt. */
int fx_rt_render_rect_mt(const fx_rt_scene *s, const fx_surface *surf, int32_t x, int32_t y, int32_t w, int32_t h,
                         int nthreads, int32_t band_rows, fx_rt_rows_fn done, void *user);

/* The number of online CPUs (at least 1): the thread count for "all cores". */
int fx_rt_cpu_count(void);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
