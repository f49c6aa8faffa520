/* SPDX-License-Identifier: MIT */
/* fixel — textures: bitmap lookup (nearest, bilinear), affine texture mapping
 * onto triangles and convex polygons, procedural textures in integer
 * arithmetic, and linear/radial gradients. Everything here can also colour
 * any fill through an fx_fill_style of kind FX_FILL_SHADER (fill.h).
 *
 * Texture coordinates (s, t) are Q16.16 with the unit square [0, 1) covering
 * the whole image. The course's lookup is
 *     texture(s, t) = txtr[(int)(s * C)][(int)(t * R)]
 * for an image of C columns and R rows, i.e. texel column floor(s * C), row
 * floor(t * R), exactly in fixed point: for R = 400, C = 600,
 * texture(0.261, 0.783) reads column 156, row 313. Outside [0, 1) the
 * coordinates repeat (FX_TEX_REPEAT) or clamp to the edge (FX_TEX_CLAMP).
 * Bilinear sampling puts texel (i, j)'s centre at ((i + 1/2)/C, (j + 1/2)/R)
 * and mixes the four nearest texels with 8-bit weights, each channel (alpha
 * too) rounded to nearest.
 */
#ifndef FIXEL_TEXTURE_H
#define FIXEL_TEXTURE_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fill.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

enum { FX_TEX_REPEAT = 0, FX_TEX_CLAMP = 1 };
enum { FX_TEX_NEAREST = 0, FX_TEX_BILINEAR = 1 };

typedef struct fx_texture {
    fx_surface img; /* any format, read through fx_unpack; w, h >= 1 */
    uint8_t wrap;   /* FX_TEX_REPEAT or FX_TEX_CLAMP */
    uint8_t filter; /* FX_TEX_NEAREST or FX_TEX_BILINEAR */
} fx_texture;

/* The course's lookup: texel (floor(s*C), floor(t*R)) after wrapping. */
fx_color fx_tex_lookup(const fx_texture *tx, fx16 s, fx16 t);
/* Nearest (= fx_tex_lookup) or bilinear, as tx->filter says. */
fx_color fx_tex_sample(const fx_texture *tx, fx16 s, fx16 t);

/* Affine texture mapping: (s, t) at each vertex, interpolated linearly over
 * the triangle like a Gouraud attribute (coverage as fx_fill_tri). Integer
 * pixel-centre vertices; the 8 variant takes fx8. Blending is honoured (the
 * texel's alpha under FX_BLEND_OVER). */
void fx_fill_tri_tex(const fx_ctx *c, const int32_t *xy, const fx16 *st, const fx_texture *tx);
void fx_fill_tri_tex8(const fx_ctx *c, const fx8 *xy, const fx16 *st, const fx_texture *tx);
/* Convex polygon mapped as the fan (v0, vi, vi+1). */
void fx_fill_poly_tex(const fx_ctx *c, const int32_t *xy, const fx16 *st, int32_t n, const fx_texture *tx);

/* A texture in surface space, as a fill style: pixel (x, y) samples
 * s = s0 + dsdx*x + dsdy*y, t = t0 + dtdx*x + dtdy*y. Point
 * style->shade at fx_tex_shade and style->user at the fx_tex_map. */
typedef struct fx_tex_map {
    const fx_texture *tex;
    fx16 s0, dsdx, dsdy, t0, dtdx, dtdy;
} fx_tex_map;
void fx_tex_shade(const void *map, int32_t y, int32_t x, int32_t n, fx_color *out);

/* A checkerboard image for a texture: img (the caller's pixels, any
 * format) gets squares of cell x cell texels, c0 where the square's column
 * plus row is even (the one at texel (0, 0)), c1 where it is odd.
 * cell < 1 counts as 1. */
void fx_tex_checker(const fx_surface *img, int32_t cell, fx_color c0, fx_color c1);

/* ---- procedural textures: (s, t) -> intensity in [0, 1] (Q16.16) ---- */

/* The course's fakesphere: 1 at the centre (1/2, 1/2) falling linearly to 0
 * at distance 0.3, and 0.2 outside that circle. */
fx16 fx_proc_fakesphere(fx16 s, fx16 t);
/* Value noise: a hashed random value in [0, 1) at every integer lattice
 * point, smoothstep-interpolated in between. */
fx16 fx_proc_noise(fx16 s, fx16 t, uint32_t seed);
/* Turbulence: sum over octaves k of |2 noise(2^k p) - 1| / 2^k, normalised
 * to [0, 1]. */
fx16 fx_proc_turbulence(fx16 s, fx16 t, int octaves, uint32_t seed);
/* Wood grain: rings around (1/2, 1/2), 8 per unit, bent by turbulence. */
fx16 fx_proc_wood(fx16 s, fx16 t, uint32_t seed);
/* Marble: 1/2 + sin(2 pi (4 s + turbulence)) / 2 veins. */
fx16 fx_proc_marble(fx16 s, fx16 t, uint32_t seed);

enum {
    FX_PROC_FAKESPHERE,
    FX_PROC_NOISE,
    FX_PROC_TURBULENCE,
    FX_PROC_WOOD,
    FX_PROC_MARBLE,
    FX_PROC_COUNT
};
/* The texture of kind FX_PROC_* at (s, t), in [0, 1] (one entry for the above). */
fx16 fx_proc_eval(int kind, fx16 s, fx16 t, uint32_t seed);

/* A procedural texture as a fill style: pixel (x, y) maps to
 * s = (x - x0) / size, t = (y - y0) / size, and the intensity v mixes
 * c0 (v = 0) to c1 (v = 1) per channel. */
typedef struct fx_proc_map {
    int kind;
    uint32_t seed;
    int32_t x0, y0, size; /* size >= 1 pixels per texture unit */
    fx_color c0, c1;
} fx_proc_map;
void fx_proc_shade(const void *map, int32_t y, int32_t x, int32_t n, fx_color *out);

/* ---- gradients ----
 * Linear: the parameter runs 0 -> 1 from (x0, y0) to (x1, y1) (projection
 * onto the axis, clamped). Radial: 0 at (x0, y0) to 1 at distance r. The
 * colour is interpolated between nstops (2..16) evenly spaced stops, each
 * channel rounded to nearest. Coordinates are pixel centres. */
#define FX_GRADIENT_MAX_STOPS 16
typedef struct fx_gradient {
    uint8_t radial;
    int32_t x0, y0, x1, y1; /* linear */
    int32_t r;              /* radial: x0, y0 centre, r >= 1 */
    int32_t nstops;
    fx_color stops[FX_GRADIENT_MAX_STOPS];
} fx_gradient;
/* Colour at parameter u (Q16.16, clamped to [0, 1]). */
fx_color fx_gradient_at(const fx_gradient *g, fx16 u);
void fx_gradient_shade(const void *gradient, int32_t y, int32_t x, int32_t n, fx_color *out);

/* Mix a (w = 0) and b (w = 65536) per ARGB channel, rounded to nearest. */
fx_color fx_color_lerp(fx_color a, fx_color b, fx16 w);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
