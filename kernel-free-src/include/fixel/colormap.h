/* SPDX-License-Identifier: MIT */
/* fixel — colour maps: scalar in [0, 1] -> colour, for fractal dwell
 * colouring and pseudo-colour plots.
 *
 * The parameter t is Q0.16 (65536 = 1.0); values above 1.0 clamp, except
 * for the cyclic HSV map, which wraps (t and t + 65536 give one colour).
 * The maps are defined here, once, as integer formulas or control points:
 *
 *  grey     v = round(255 t) on R, G and B
 *  hot      black -> red -> yellow -> white: R = 255 clamp(3t),
 *           G = 255 clamp(3t - 1), B = 255 clamp(3t - 2) (rounded)
 *  viridis  piecewise linear through nine sRGB control points taken from
 *           matplotlib's viridis at t = i/8: 440154 472C7A 3B518B 2C718E
 *           21908D 27AD81 5CC863 AADC32 FDE725 (dark purple -> yellow,
 *           luminance rising monotonically)
 *  hsv      hue = 360 t at full saturation and value: red, yellow, green,
 *           cyan, blue, magenta, back to red; channels linear per sextant
 * Every result is opaque (alpha FF).
 */
#ifndef FIXEL_COLORMAP_H
#define FIXEL_COLORMAP_H

#include <stdint.h>
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fx_cmap {
    FX_CMAP_GREY,
    FX_CMAP_HOT,
    FX_CMAP_VIRIDIS,
    FX_CMAP_HSV,
    FX_CMAP_COUNT
} fx_cmap;

#define FX_CMAP_T_ONE 65536u

/* The colour of map m at t (Q0.16). An unknown m gives grey. */
fx_color fx_cmap_color(fx_cmap m, uint32_t t);

/* n samples of map m into out: t_i = i / (n - 1) for the clamped maps (both
 * ends included), i / n for the cyclic HSV map (so a table repeats without
 * a doubled colour). n == 1 gives the colour at t = 0. */
void fx_cmap_table(fx_cmap m, fx_color *out, uint32_t n);

/* "grey" (also "gray"), "hot", "viridis", "hsv"; case-insensitive.
 * Returns FX_CMAP_COUNT when unknown. */
fx_cmap fx_cmap_from_name(const char *name);
const char *fx_cmap_name(fx_cmap m);
/* 1 for maps that wrap around (HSV). */
int fx_cmap_cyclic(fx_cmap m);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
