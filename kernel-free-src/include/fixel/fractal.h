/* SPDX-License-Identifier: MIT */
/* fixel — escape-time fractals: the Mandelbrot set and filled Julia sets.
 *
 * A view maps a frame of fw x fh pixels onto the complex plane: the frame is
 * `width` wide, centred at cre + cim i, with square pixels, and pixel (x, y)
 * samples its centre
 *     re = cre + (2x + 1 - fw) * width / (2 fw)
 *     im = cim + (fh - 2y - 1) * width / (2 fw)        (y grows downward)
 * computed exactly in Q8.56 (fx56) and rounded to nearest, ties away from
 * zero, so the grid of a view centred at 0 is exactly symmetric.
 *
 * The dwell of a point is the iteration count of the course's loop
 *     z = z0; n = 0;
 *     while (n < maxiter && |z|^2 <= 4) { z = z^2 + c; n++; }
 * (Mandelbrot: z0 = 0, c = the pixel; Julia: z0 = the pixel, c fixed), so
 * dwell == maxiter means "did not escape" and is drawn in the inside colour.
 *
 * Two arithmetic paths, chosen from the zoom (fx_fractal_precision):
 *  - 32: Q4.28 coordinates with exact 64-bit squares and products (the
 *    escape test sees exact |z|^2); pixel steps of at least 2^-12 and at
 *    most 512 iterations, where it keeps >= 99.5 % of the dwells of an
 *    exact computation (W9: 99.98 % of the colours of the double loop).
 *  - 64: Q8.56 with 128-bit products (fx_mul64_shift, portable to 32-bit
 *    ARM; __int128 where the compiler has it, with identical rounding), for
 *    views down to ~10^-13 wide (about 2^-56 * 4 per pixel at 1920 px).
 * For the Mandelbrot set, points of the main cardioid and the period-2 bulb
 * are recognised in closed form (they never escape: the result is the same
 * as iterating), and exact cycles of the fixed-point orbit end the loop
 * early (a repeating orbit never escapes), so neither changes a pixel.
 *
 * Rendering works on any rectangle of the frame and every pixel depends only
 * on its own (x, y): tiles rendered separately, in any order or on several
 * threads, assemble the identical picture. Julia views centred at 0 use the
 * symmetry of K_c about the origin (pixel (x, y) = pixel (fw-1-x, fh-1-y))
 * inside the rectangle being drawn.
 */
#ifndef FIXEL_FRACTAL_H
#define FIXEL_FRACTAL_H

#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_fractal_view {
    fx56 cre, cim;     /* centre of the frame */
    fx56 width;        /* width of the frame in the plane, > 0 */
    int32_t fw, fh;    /* frame size in pixels, 1..32768 */
    uint32_t maxiter;  /* 0..2^24 */
    uint8_t julia;     /* 0: Mandelbrot; 1: filled Julia set of c = jre + jim i */
    uint8_t precision; /* 0: automatic; 32 or 64 forces a path */
    fx56 jre, jim;
} fx_fractal_view;

/* Limits of a valid view: |cre|, |cim|, |jre|, |jim| <= 16, 0 < width <= 16,
 * and the frame's far corner within 64 of the origin. */
#define FX_FRACTAL_MAX_ITER (1u << 24)

/* A view: Mandelbrot, automatic precision, frame w x h. */
fx_fractal_view fx_mandel_view(fx56 cre, fx56 cim, fx56 width, int32_t w, int32_t h,
                               uint32_t maxiter);
fx_fractal_view fx_julia_view(fx56 cre, fx56 cim, fx56 jre, fx56 jim, fx56 width, int32_t w,
                              int32_t h, uint32_t maxiter);

/* 0 or -FX_EINVAL for a view outside the limits above. */
int fx_fractal_check(const fx_fractal_view *v);
/* The arithmetic path the view uses: 32 or 64 (0 for an invalid view). The
 * automatic choice is 32 when the pixel step is >= 2^-12, maxiter <= 512
 * and the Julia c has |jre|, |jim| <= 2; 64 otherwise. */
int fx_fractal_precision(const fx_fractal_view *v);

/* Pixel centre coordinates of frame pixel (x, y) in Q8.56 (the grid above). */
fx56 fx_fractal_re(const fx_fractal_view *v, int32_t x);
fx56 fx_fractal_im(const fx_fractal_view *v, int32_t y);

/* How dwell becomes colour. Escaped points (dwell d < maxiter) take
 * lut[i] with i = (d * mul) >> 16, clamped to len - 1 (wrap == 0) or taken
 * modulo len (wrap == 1); points that did not escape take `inside`. The
 * table holds native values of the target surface's format. */
typedef struct fx_dwell_pal {
    const uint32_t *lut;
    uint32_t len;  /* >= 1 */
    uint32_t mul;  /* Q16.16 entries per iteration; 65536: one entry per dwell */
    uint8_t wrap;
    uint32_t inside;
} fx_dwell_pal;

/* Dwell of frame pixels r (clipped to the frame) into out: the dwell of
 * (x, y) goes to out[(y - r.y0) * stride + (x - r.x0)] (stride in elements).
 * Returns 0 or -FX_EINVAL. */
int fx_fractal_dwell(const fx_fractal_view *v, fx_rect r, uint32_t *out, int32_t stride);

/* Draw frame pixels r (clipped to the frame and to s) onto s: frame pixel
 * (x, y) lands on surface pixel (x, y). Returns 0 or -FX_EINVAL. */
int fx_fractal_render(const fx_surface *s, fx_rect r, const fx_fractal_view *v,
                      const fx_dwell_pal *pal);

/* The W9 palette of docs/BENCHMARK.md for maxiter 256 (pal[n] = min(255, 4n) grey,
 * black inside) packed for format f: fills lut[0..64] (65 entries) and *pal.
 * Library API rather than benchmark code: the scene's default Mandelbrot
 * colouring and `colormap w9` use it. */
void fx_dwell_pal_w9(fx_dwell_pal *pal, uint32_t lut[65], fx_format f);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
