/* SPDX-License-Identifier: MIT */
/* fixel — iterated function systems: the chaos game and the deterministic
 * "copier" iteration.
 *
 * A map sends (x, y) to (a x + b y + e, c x + d y + f); coefficients are
 * Q16.16 and p is the map's probability in Q16.16 (the maps' p sum to 1.0).
 * The world window [wx0, wx1] x [wy0, wy1] (y up) is mapped onto the
 * destination rectangle (y down), point (x, y) to the pixel whose square
 * contains its image (floor).
 */
#ifndef FIXEL_IFS_H
#define FIXEL_IFS_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_ifs_map {
    fx16 a, b, c, d, e, f;
    fx16 p;
} fx_ifs_map;

#define FX_IFS_MAX_MAPS 16

typedef struct fx_ifs {
    const fx_ifs_map *maps;
    int n; /* 1..FX_IFS_MAX_MAPS */
    fx16 wx0, wy0, wx1, wy1;
} fx_ifs;

/* Built-in systems: the Sierpinski triangle (three maps of ratio 1/2 on the
 * triangle (0,0) (1,0) (1/2,1)) and Barnsley's fern (his published
 * coefficients and probabilities 0.01, 0.85, 0.07, 0.07). */
extern const fx_ifs fx_ifs_sierpinski;
extern const fx_ifs fx_ifs_fern;

/* 0 or -FX_EINVAL (no maps, too many, an empty window or one wider or
 * taller than 16384, probabilities not summing to 1.0 within n units). */
int fx_ifs_check(const fx_ifs *s);

/* The chaos game: from (0, 0), apply a map chosen by probability (16 bits of
 * a xorshift32 stream seeded with seed) npoints + 20 times and plot every
 * point after the first 20 in the context's colour. Returns the points that
 * landed inside dest (or a negative error). */
int32_t fx_ifs_chaos(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t npoints,
                     uint32_t seed);

/* The copier: the outline of the world window under every composition of
 * `depth` maps (n^depth quadrilaterals, at most 2^20). Returns the number
 * drawn or a negative error. */
int32_t fx_ifs_copier(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t depth);

/* The copier started from any picture (issue #44): what is drawn in dest
 * (every pixel not of colour bg, a script-drawn shape or an image) is the
 * machine's input; its images under every composition of `depth` maps
 * replace it, each pixel's centre mapped as a world point (the window
 * spread over dest) and plotted in its colour. Whatever the picture, the
 * output tends to the same attractor: that is the notes' point. work holds
 * cap pixels (-FX_ENOSPC for a bigger picture); the plots, pixels x n^depth,
 * are at most FX_IFS_PICTURE_WORK (-FX_E2BIG). Returns the picture's
 * pixel count, or -FX_EINVAL. */
#define FX_IFS_PICTURE_WORK (1u << 24)
typedef struct fx_ifs_pixel {
    fx16 x, y; /* world point, Q16.16 */
    fx_color color;
} fx_ifs_pixel;
int32_t fx_ifs_copier_picture(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t depth, fx_color bg,
                              fx_ifs_pixel *work, uint32_t cap);

/* The pixel of world point (x, y) (Q16.16) in dest, for callers and tests. */
void fx_ifs_to_pixel(const fx_ifs *s, fx_rect dest, int64_t x, int64_t y, int32_t *px,
                     int32_t *py);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
