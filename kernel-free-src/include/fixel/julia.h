/* SPDX-License-Identifier: MIT */
/* fixel — the Julia set J_c itself and the dynamics around it: J_c by
 * inverse iteration, the fixed points of z -> z^2 + c with their kind, and
 * the basins of attraction of the attracting cycle and of infinity.
 *
 * J_c is the boundary of the filled-in set K_c (fractal.h draws K_c by
 * escape time). It is invariant under the two inverse branches
 * z -> +-sqrt(z - c) and repels forward orbits, so it attracts backward
 * ones: starting on J_c (at the repelling fixed point) and applying the
 * inverse branches traces it. The square roots are taken in Q4.28 with
 * fx_isqrt64 (principal root: re >= 0), all products exact in 64 bits.
 *
 * Views are fx_fractal_view (julia = 1), so these pictures line up pixel
 * for pixel with the `julia` escape-time rendering of the same view.
 * Every function here needs |jre|, |jim| <= 2 (where the escape radius 2
 * holds and the Q4.28 squares fit) and a frame width of at least 2^-28.
 */
#ifndef FIXEL_JULIA_H
#define FIXEL_JULIA_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fractal.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 0 or -FX_EINVAL: a valid Julia view (fx_fractal_check) within the limits above. */
int fx_julia_check(const fx_fractal_view *v);

/* The frame pixel containing the point re + im i (Q8.56; |re|, |im| <= 16). */
void fx_julia_to_pixel(const fx_fractal_view *v, fx56 re, fx56 im, int32_t *x, int32_t *y);

/* One square root of z in Q4.28 (principal: re >= 0, im >= 0 when re == 0),
 * for |re|, |im| < 8. */
void fx_csqrt28(int64_t re, int64_t im, int64_t *sre, int64_t *sim);

enum { FX_FIXED_ATTRACTING, FX_FIXED_NEUTRAL, FX_FIXED_REPELLING };

typedef struct fx_julia_fixed {
    fx56 re, im;    /* the fixed point z* = 1/2 +- sqrt(1/4 - c) (Q4.28 precision) */
    fx16 mult;      /* |f'(z*)| = |2 z*| in Q16.16 */
    int kind;       /* attracting (|2z*| < 1), neutral (within 2^-12 of 1), repelling */
} fx_julia_fixed;

/* The two fixed points of z^2 + c, c = cre + cim i (|cre|, |cim| <= 2); the
 * one with the larger multiplier first. Returns 0 or -FX_EINVAL. */
int fx_julia_fixed_points(fx56 cre, fx56 cim, fx_julia_fixed out[2]);

/* J_c by inverse iteration, plotted in the context's colour (clipped).
 * random: npoints steps of one branch chosen by a bit of a xorshift32 stream
 * seeded with seed (at most 2^24). tree: every point of the complete binary
 * tree of both branches down to depth (at most 20: 2^21 - 1 points). Both
 * start at the first fixed point of fx_julia_fixed_points, which lies on
 * J_c. Returns the points plotted inside the clip, or -FX_EINVAL. */
#define FX_JULIA_MAX_POINTS (1u << 24)
#define FX_JULIA_MAX_DEPTH 20
int32_t fx_julia_inverse_random(const fx_ctx *c, const fx_fractal_view *v, uint32_t npoints, uint32_t seed);
int32_t fx_julia_inverse_tree(const fx_ctx *c, const fx_fractal_view *v, uint32_t depth);

/* The attracting cycle of z^2 + c, if any: the orbit of the critical point 0
 * (which every attracting cycle attracts) followed for up to 8192 + 64
 * steps, a cycle of period 1..FX_JULIA_MAX_PERIOD accepted once it closes
 * to within 2^-20 and its multiplier |prod 2 z_k| is at most 1 + 2^-10
 * (parabolic cycles count: their basins exist). Returns the period (0: none
 * found, e.g. c outside M, or c = i whose critical orbit lands on a
 * repelling cycle) and the cycle points from the one the orbit reached first. */
#define FX_JULIA_MAX_PERIOD 16
typedef struct fx_julia_cycle {
    int period;
    int64_t re[FX_JULIA_MAX_PERIOD], im[FX_JULIA_MAX_PERIOD]; /* Q4.28 */
} fx_julia_cycle;
int fx_julia_attractor(fx56 cre, fx56 cim, fx_julia_cycle *out);

/* The orbit of 0 (orbit.c), the notes' way into the Mandelbrot set:
 * z_0 = 0, z_(k+1) = z_k^2 + c, in Q8.56, for up to n values (zre / zim, if
 * not NULL, get z_0 .. z_steps: n entries at most), classified as
 *   ESCAPES  |z_k| > 2 at k = steps: it explodes, c is outside M;
 *   FIXED    z_(n-1) = z_(n-2) to within 2^-20 and z* real (c real: the
 *            orbit settles along the real line, or lands on it exactly);
 *   SPIRAL   the same with z* not real: 2 z*, the multiplier, turns each
 *            step, so the orbit spirals in;
 *   CYCLE    the smallest p in 2..FX_JULIA_MAX_PERIOD with z_(n-1) =
 *            z_(n-1-p) to within 2^-20;
 *   BOUNDED  none of these within n values (a slow or chaotic orbit).
 * re / im: the last value (the escaping one, or the point reached).
 * Returns the kind, or -FX_EINVAL (n outside 1..FX_ORBIT0_MAX, |c| parts
 * above 16, out NULL). */
#define FX_ORBIT0_MAX 65536
typedef enum fx_orbit0_kind {
    FX_ORBIT0_ESCAPES,
    FX_ORBIT0_FIXED,
    FX_ORBIT0_SPIRAL,
    FX_ORBIT0_CYCLE,
    FX_ORBIT0_BOUNDED
} fx_orbit0_kind;
typedef struct fx_orbit0_info {
    fx_orbit0_kind kind;
    uint32_t steps; /* the escape step, or the last step followed */
    int period;     /* FIXED / SPIRAL: 1; CYCLE: p; else 0 */
    fx56 re, im;
} fx_orbit0_info;
int fx_orbit0(fx56 cre, fx56 cim, uint32_t n, fx56 *zre, fx56 *zim, fx_orbit0_info *out);

/* Basins of attraction over frame pixels r (clipped to the frame and s):
 * points that escape take esc's colour for their dwell (the basin of
 * infinity, exactly as fx_fractal_render colours them); points whose orbit
 * comes within 2^-7 of the attracting cycle take basin[k % nbasin], k the
 * cycle point their orbit is in phase with at step 0 (the p immediate basins
 * of a period-p cycle and all their preimages), darkened by the steps the
 * orbit took (by 1/64 per step, at most half); the rest take esc->inside.
 * Returns the period of the cycle (0: none) or -FX_EINVAL. */
int fx_julia_basins(const fx_surface *s, fx_rect r, const fx_fractal_view *v, const fx_dwell_pal *esc,
                    const fx_color *basin, uint32_t nbasin);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
