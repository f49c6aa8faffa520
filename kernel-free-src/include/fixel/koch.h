/* SPDX-License-Identifier: MIT */
/* fixel — geometric and random fractal curves: Koch curves and snowflakes,
 * midpoint displacement (fractal lines, coastlines), diamond-square terrain,
 * and the Hilbert and Peano space-filling curves.
 *
 * Koch: an integer turtle on 40.24 fixed-point positions. Each segment from
 * S to E of order m > 0 becomes four of order m - 1: forward a third, turn
 * +60 degrees, forward, turn -120, forward, turn +60, forward to E (turning
 * from +x towards +y of the frame, as every angle does: K_n from left to
 * right bulges upward after 'coords course', downward on the screen; turns are
 * binary angles; the last piece always ends exactly at E, so the vertices of
 * a sub-curve depend only on its own S and E). A sub-curve whose bounding
 * box (its chord's box grown by 0.3 of |dx| + |dy| and a pixel) misses the
 * clip rectangle is skipped without changing any visible pixel, and one
 * whose chord is under a pixel is drawn as that chord, so any order draws in
 * time bounded by what is visible. Vertices round to the nearest pixel
 * centre (ties up) and are joined by fx_line.
 *
 * Midpoint displacement is the course's fract(): the midpoint of A C moves
 * along the perpendicular by t |AC| with t ~ N(0, sd), sd scaled by
 * factor = 2^((1 - beta) / 2) at each level, recursing until a piece is
 * shorter than min_len pixels (or 2^-18 of the chord's |dx| + |dy|, which
 * bounds the work for lines reaching far off the surface: the draws cannot
 * depend on the clip, so the whole line is walked). t comes from fx_gauss16 (the sum of twelve
 * uniform 16-bit draws, Irwin-Hall: mean 0, variance 1) on a xorshift32
 * state, so a seed reproduces the line exactly; the random draws never
 * depend on clipping.
 */
#ifndef FIXEL_KOCH_H
#define FIXEL_KOCH_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The Koch curve K_n from (x0, y0) to (x1, y1) (pixel centres). Returns the
 * number of segments drawn (4^n when the whole curve is visible and its
 * pieces are at least a pixel long). */
uint64_t fx_koch(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                 uint32_t order);
/* The Koch snowflake: K_n on the three sides of the equilateral triangle
 * inscribed in the circle of radius r about (cx, cy), first vertex towards
 * -y of the frame (straight up on the screen), bumps pointing outward. Returns the segments drawn (3 * 4^n). */
uint64_t fx_koch_snowflake(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, uint32_t order);

/* fx_rand32, fx_gauss16 and fx16_exp2, which the random fractals use, are
 * general helpers: see fixed.h. */

typedef struct fx_fract_params {
    fx16 beta;      /* spectral exponent, typically 1.2 .. 1.8 */
    fx16 sd;        /* standard deviation of t at the first level */
    int32_t min_len; /* stop below this many pixels (>= 1) */
    uint32_t seed;
} fx_fract_params;

/* A midpoint-displacement line from (x0, y0) to (x1, y1). Returns the
 * segments drawn. The state advances by the draws used (for chaining). */
uint32_t fx_fractline(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                      const fx_fract_params *p, uint32_t *state);
/* A closed fractal coastline: each edge of the polygon xy[0..2n) gets a
 * fractal line, all from one random stream seeded with p->seed. c, xy or p
 * NULL, or n outside 1..INT32_MAX/2: nothing drawn, 0 returned. */
uint32_t fx_coastline(const fx_ctx *c, const int32_t *xy, int n, const fx_fract_params *p);

/* Diamond-square terrain on a (2^k + 1)^2 grid (k = 1..12) into h (row
 * stride in elements): corners and every new point get uniform noise of
 * +-amp, amp scaled by 2^-rough per level (rough = H, 0..1 in Q16.16: 0.5
 * gives rolling hills, 0.9 smooth, 0.2 rugged). Reproducible per seed.
 * Returns 0 or -FX_EINVAL. */
int fx_terrain(int32_t *h, int32_t stride, int k, int32_t amp, fx16 rough, uint32_t seed);

/* Space-filling curves in the square [x, x + size) x [y, y + size): the
 * polyline through the centres of its 2^n x 2^n (Hilbert) or 3^n x 3^n
 * (Peano) cells, in curve order. Orders finer than a pixel are drawn at the
 * finest order whose cells are at least a pixel (the curve then lights every
 * pixel of its square). Blocks of the curve outside the clip are skipped.
 * Returns the segments drawn. */
uint32_t fx_hilbert(const fx_ctx *c, int32_t x, int32_t y, int32_t size, uint32_t order);
uint32_t fx_peano(const fx_ctx *c, int32_t x, int32_t y, int32_t size, uint32_t order);
/* Cell (x, y) of the d-th step of each curve of order n: 0, or -FX_EINVAL
 * with nothing written when n is above the maximum (the cells' coordinates
 * must fit uint32_t), d is past the last step (d >= 4^n or 9^n), or x or y
 * is NULL. */
#define FX_HILBERT_MAX_ORDER 31
#define FX_PEANO_MAX_ORDER 20
int fx_hilbert_d2xy(uint32_t n, uint64_t d, uint32_t *x, uint32_t *y);
int fx_peano_d2xy(uint32_t n, uint64_t d, uint32_t *x, uint32_t *y);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
