/* SPDX-License-Identifier: MIT */
/* fixel — geometric and random fractal curves: Koch curves and snowflakes,
 * midpoint displacement (fractal lines, coastlines), diamond-square terrain,
 * fractional Brownian curves by spectral synthesis, and the Hilbert and
 * Peano space-filling curves.
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

/* Fractional Brownian curves by spectral synthesis (issue #44): the
 * course's 1/f^beta curve, whose graph has the box-counting dimension
 * D = (5 - beta) / 2 for 1 < beta < 3 (Hurst exponent H = (beta - 1) / 2).
 * Unlike midpoint displacement, which builds the curve from the top level
 * down and is smooth below the scale where its displacements shrink
 * (fx_fractline measures D near 1 for every beta), every scale is present
 * at once: the height is the sum of sinusoids
 *   y(t) = sum_{k=1..terms} k^(-beta/2) sin(2 pi k t + phi_k),  t in [0, 1],
 * so the power at frequency k falls as k^-beta. The phases phi_k are
 * uniform binary angles from a xorshift32 stream seeded with seed (drawn
 * in order k = 1, 2, ...), so a seed gives the same curve on every target.
 * y is scaled to unit standard deviation (the RMS over t of the sum) and
 * shifted so that y(0) = y(1) = 0 (y has period 1), so the curve leaves
 * and ends on its chord. Amplitudes are Q2.30 from fx16_exp2 and the sines
 * fx_sin30; each term is rounded to Q16.16 once, so a height is within
 * terms * 2^-16 of the exact sum for those amplitudes and phases. */
#define FX_FBM_MAX_TERMS 4096        /* frequencies k = 1..terms */
#define FX_FBM_MAX_SAMPLES (1 << 20) /* heights computed (work: samples x terms) */

typedef struct fx_fbm_params {
    fx16 beta;      /* spectral exponent, 0..4 (D = (5 - beta) / 2 holds for 1 < beta < 3) */
    fx16 sd;        /* standard deviation of the height, in chord lengths, 0..1 */
    uint32_t terms; /* sinusoids summed, 1..FX_FBM_MAX_TERMS, at most (n - 1) / 2 */
    uint32_t seed;
} fx_fbm_params;

/* The heights of a fractional Brownian curve: y(i / (n - 1)),
 * i = 0..n-1, into h[0..n) in Q16.16 units of the standard deviation
 * (|h[i]| <= 2 sqrt(2 terms), so at most 182); p->sd is not used. Cost n x terms sines. Returns 0, or -FX_EINVAL with
 * nothing written when h or p is NULL, n is outside 3..FX_FBM_MAX_SAMPLES,
 * beta outside 0..4, or terms outside 1..FX_FBM_MAX_TERMS or above
 * (n - 1) / 2 (a frequency above half the sampling rate would alias). */
int fx_fbm_heights(fx16 *h, int32_t n, const fx_fbm_params *p);

/* Draws heights along a chord: the polyline through the n points
 * P(t) + sd * h[i] * (-(y1 - y0), x1 - x0), t = i / (n - 1), where P runs from (x0, y0) to (x1, y1): heights from
 * fx_fbm_heights, displaced at right angles to the chord (towards +y of the
 * frame for a chord along +x, so upward after 'coords course') by sd
 * chord lengths per unit. Points are computed in 48.16 and rounded to the
 * nearest pixel (ties up), saturating at the int32 range; segments are
 * fx_line. Any int32 end points. Returns the segments drawn (n - 1), or
 * -FX_EINVAL when c or h is NULL, n is outside 2..FX_FBM_MAX_SAMPLES or sd
 * is outside 0..1 (FX16_ONE). */
int32_t fx_fbm_draw(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const fx16 *h, int32_t n,
                    fx16 sd);

/* A fractional Brownian curve from (x0, y0) to (x1, y1): heights into the
 * caller's work[0..n) by fx_fbm_heights (n samples; a few per pixel of the
 * chord keep it rough down to the pixel), then fx_fbm_draw with p->sd.
 * Returns the segments drawn or -FX_EINVAL (either function's
 * conditions; nothing drawn). */
int32_t fx_fbm_spectral(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const fx_fbm_params *p,
                        fx16 *work, int32_t n);

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
