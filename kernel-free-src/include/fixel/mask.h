/* SPDX-License-Identifier: MIT */
/* fixel — coverage masks: 8-bit anti-aliased glyphs (or any alpha mask)
 * blended through a context.
 *
 * The core never rasterizes an outline for text: the boards side (FreeType,
 * boards/text) renders each glyph into an 8-bit coverage mask, 0 = not
 * covered, 255 = fully covered, and hands it here with the integer pixel
 * position of its top-left corner. Nothing here allocates.
 *
 * The rule, one per channel (docs/CONVENTIONS.md, "Coverage masks"):
 *   A  = the colour's alpha under FX_BLEND_OVER, 255 under FX_BLEND_SRC
 *        (coverage always blends, as the anti-aliased lines do);
 *   a  = (A * cov) / 255 rounded to nearest;
 *   a == 0: the pixel is not touched.
 *   Otherwise the destination pixel is unpacked by the surface format's rule
 *   (surface.h), each colour channel becomes
 *     plain (the default):  (s*a + d*(255-a)) / 255 rounded to nearest
 *     FX_MASK_GAMMA:        E((L(s)*a + L(d)*(255-a)) / 255), the quotient
 *                           rounded to nearest, L = fx_srgb_to_linear (Q16
 *                           linear light, the sRGB curve's 256-entry table),
 *                           E = fx_linear_to_srgb (the nearest code)
 *   the alpha byte (seen only by ARGB8888) becomes a + (dA*(255-a))/255
 *   rounded to nearest in both modes (alpha is not gamma-encoded), and the
 *   result is packed by the format's rule. The plain rule is exactly
 *   fx_blend_over of the colour with alpha a, and a coverage of 255 with an
 *   opaque colour stores the colour itself.
 *
 * Plain is the default because it is what FreeType's coverage, its hinting
 * and every peer a user compares with (cairo's default, SDL_ttf, the
 * Linux console's and browsers' grey-scale text) assume: the same glyph
 * looks the same weight as elsewhere, and dark text on a light background,
 * the common case, keeps its weight. FX_MASK_GAMMA blends in linear light,
 * which keeps thin light text on a dark dashboard from looking starved
 * (plain blending darkens the edge pixels of light-on-dark text); it costs
 * a table look-up and an 8-step search per channel.
 *
 * Rotation: rot is the number of quarter turns clockwise on screen (y
 * down) applied to the mask, for text on a panel mounted at 90/180/270
 * degrees. Mask pixel (mx, my) of a w x h mask lands on
 *   FX_ROT_0:   (x + mx,         y + my)
 *   FX_ROT_90:  (x + h - 1 - my, y + mx)
 *   FX_ROT_180: (x + w - 1 - mx, y + h - 1 - my)
 *   FX_ROT_270: (x + my,         y + w - 1 - mx)
 * so (x, y) is always the top-left corner of the rotated box (h x w for 90
 * and 270). Placing a rotated glyph's box relative to a rotated baseline is
 * the layout's business (boards/text does it). Pixels outside the clip
 * rectangle or inside the exterior rectangle are not touched, and work is
 * bounded by the visible part of the box.
 */
#ifndef FIXEL_MASK_H
#define FIXEL_MASK_H

#include <stdint.h>
#include "fixel/draw.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fx_rot { FX_ROT_0 = 0, FX_ROT_90 = 1, FX_ROT_180 = 2, FX_ROT_270 = 3 } fx_rot;

/* Flags of fx_mask_blend / fx_coverage_blend. */
#define FX_MASK_GAMMA 1u /* blend in linear light (see above) */

/* An 8-bit coverage mask: w x h bytes, row r at cov + r * stride (stride may
 * be negative, as FreeType's upward-flowing bitmaps are). */
typedef struct fx_mask {
    const uint8_t *cov;
    int32_t w, h;
    int32_t stride;
} fx_mask;

/* One pixel of the rule above: the native value dst of format f, colour c
 * whose alpha byte is A, coverage cov (0..255). Returns the new native value. */
uint32_t fx_coverage_blend(fx_format f, uint32_t dst, fx_color c, uint32_t cov, unsigned flags);

/* Blend mask m at (x, y) rotated by rot through c's clip, exterior clip,
 * colour and blend mode. Returns 0; -FX_EINVAL for a NULL c or m, a NULL
 * cov with a non-empty size, a negative size, |stride| < w, rot > 3 or
 * unknown flags (nothing is drawn then). An empty mask draws nothing. */
int fx_mask_blend(const fx_ctx *c, int32_t x, int32_t y, const fx_mask *m, unsigned rot, unsigned flags);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
