/* SPDX-License-Identifier: MIT */
/* fixel — whole frames on several threads, in bands (boards side: pthreads).
 *
 * A frame is cut into horizontal bands of rows, one per thread. Each thread
 * draws the WHOLE frame's drawing with its clip rectangle narrowed to its
 * band. fixel's primitives step exactly as on the whole surface and only
 * store the pixels inside the clip, so the bands together are the
 * one-thread picture, pixel for pixel; what a band repeats is the set-up
 * work (parsing, vertex transforms), not the pixels.
 *
 * Scene scripts (fx_scene_run_mt): each band has its own fx_scene (own
 * arena: its own depth buffer, 3D and ray-tracer state); the ray tracer's
 * 'raytrace' is not cut by band but traced once by all threads together
 * (a barrier, rows taken from a shared counter, a barrier), since its rows
 * cost unevenly. A script with a command flagged FX_SCENE_SERIAL (seed
 * fills that read the picture, 'present', the visible-surface renderers
 * that paint unclipped, clip-dependent text and polygon clipping) or with
 * tracing on runs on one thread.
 *
 * Drawing functions (fx_par_bands): the function is called once per band
 * with a context whose clip is the band; it must draw only through that
 * context (narrowing its clip with fx_rect_intersect, never widening it)
 * and must not read pixels outside it. */
#ifndef FIXEL_PAR_H
#define FIXEL_PAR_H

#include "fixel/draw.h"
#include "fixel/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Draw band number band (0..nbands-1) through c (its clip = the caller's
 * clip and the band's rows). Calls come from several threads at once. */
typedef void (*fx_par_draw_fn)(void *user, fx_ctx *c, int band);

/* Cut c's clip into nbands bands of rows (1..1024; 0: one per thread) and
 * draw them on nthreads threads (1..64; 1: the caller's thread only), each
 * thread taking the next band from a shared counter. Returns 0, -FX_EINVAL,
 * or a negative errno when a thread cannot be started (the threads that did
 * start draw every band). */
int fx_par_bands(const fx_ctx *c, int nbands, int nthreads, fx_par_draw_fn draw, void *user);

/* Start ahead the threads a call on nthreads threads (1..64) takes from
 * the kept pool (docs/ARCHITECTURE.md "The threads"), so that its first
 * call does not pay for starting them: a program drawing short frames on
 * N threads calls it once at start-up. Returns how many threads such a
 * call has now, the caller's included (1..nthreads): fewer when threads
 * cannot be started (or other calls hold them at this moment); -FX_EINVAL.
 * Nothing to stop: the pool's threads wait idle between calls and are
 * stopped at exit. */
int fx_par_start(int nthreads);

/* Run a whole script as fx_scene_run does, on nthreads threads (1..64) in
 * nthreads bands (as many as threads could be started), with the same
 * pixels. The bands are equal the first time; the same script run again at
 * the same size is cut by the last run's cost per band (docs/ARCHITECTURE.md),
 * which changes its speed, never its pixels. sc is fresh (initialised, nothing
 * run yet); the other bands get scenes like it, with arenas of sc's size
 * (allocated here and, to spare the next frame the page faults of fresh
 * memory, kept after returning: (nthreads - 1) arenas, the largest set so
 * far, until exit or fx_par_trim), and call sc's host functions
 * one at a time (a mutex), make_surface only once; a file or image the
 * script names is loaded once and its data shared by the bands (it is
 * only read). On return sc holds band
 * 0's state, unbanded; sc->err as fx_scene_run sets it (the first band's
 * error). *bands (NULL: not wanted) is the number of bands drawn: 1 when
 * the script ran on one thread (nthreads 1, a serial command, tracing, or
 * no memory for the other arenas). Returns 0 or a negative error. */
int fx_scene_run_mt(fx_scene *sc, const char *text, size_t len, int nthreads, int *bands);

/* Free the arenas fx_scene_run_mt keeps for the next frame (a program
 * done with banded scripts, or one checking its heap); returns the bytes
 * freed, 0 when none were kept. The next banded run allocates anew. Safe
 * at any time, also while another thread runs a script (it keeps its own
 * arenas until it returns, and those are kept after it). */
size_t fx_par_trim(void);

/* The number of online CPUs (1..64). */
int fx_par_cpu_count(void);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
