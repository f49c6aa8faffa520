/* SPDX-License-Identifier: MIT */
/* fixel — colour models: integer conversions between RGB and CMY, HSV, HLS,
 * YIQ and CIE XYZ.
 *
 * RGB is the API's 0xAARRGGBB; alpha is ignored on the way in and every
 * conversion back to RGB returns an opaque colour. The other models use
 * Q16.16 (fx16): hue in degrees [0, 360), the other HSV/HLS components and
 * luma in [0, 1] (0x10000 = 1), chroma components I and Q signed.
 *
 * Precision. Forward conversions are exact rationals rounded to nearest
 * (2^-17 of the unit). Back to RGB every channel is rounded to nearest, and
 * RGB -> model -> RGB returns the same colour for every one of the 2^24
 * colours (HSV, HLS, YIQ: tested exhaustively; XYZ: tested exhaustively too,
 * through the sRGB curve). Inputs out of range are brought in: hue is taken
 * modulo 360, S/V/L clamp to [0, 1], RGB results clamp to [0, 255].
 *
 * YIQ is the NTSC 1953 matrix (Y = 0.299R + 0.587G + 0.114B,
 * I = 0.596R - 0.274G - 0.322B, Q = 0.211R - 0.523G + 0.312B) in Q16 with
 * grey giving I = Q = 0 exactly; R, G, B are taken in [0, 1].
 *
 * CIE XYZ treats RGB as sRGB (IEC 61966-2-1): each channel is decoded by the
 * sRGB transfer curve (a 256-entry table), then mixed by the sRGB primaries
 * matrix for the D65 white point, normalised so white has Y = 1:
 * white = (0.9505, 1.0000, 1.0890) = FX_XYZ_WHITE_X/Y/Z. Going back, the
 * linear value is encoded to the nearest table entry (colours outside the
 * sRGB gamut clamp). The inverse matrices are computed exactly from the
 * forward ones (tools/gen/gen_colour.py).
 */
#ifndef FIXEL_COLOUR_H
#define FIXEL_COLOUR_H

#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_cmy { uint8_t c, m, y; } fx_cmy;
typedef struct fx_hsv { fx16 h, s, v; } fx_hsv;
typedef struct fx_hls { fx16 h, l, s; } fx_hls;
typedef struct fx_yiq { fx16 y, i, q; } fx_yiq;
typedef struct fx_xyz { fx16 x, y, z; } fx_xyz;

#define FX_XYZ_WHITE_X 62292 /* 0.9505 */
#define FX_XYZ_WHITE_Y 65536 /* 1.0 */
#define FX_XYZ_WHITE_Z 71369 /* 1.0890 */

/* CMY is the subtractive complement: C = 255 - R etc. (exact both ways). */
fx_cmy fx_rgb_to_cmy(fx_color c);
fx_color fx_cmy_to_rgb(fx_cmy c);

/* HSV (hexcone): hue in degrees, saturation and value in [0, 1]. */
fx_hsv fx_rgb_to_hsv(fx_color c);
fx_color fx_hsv_to_rgb(fx_hsv c);

/* HLS (double hexcone): hue in degrees, lightness and saturation in [0, 1]. */
fx_hls fx_rgb_to_hls(fx_color c);
fx_color fx_hls_to_rgb(fx_hls c);

/* YIQ, the NTSC matrix above: luma in [0, 1], I and Q signed. */
fx_yiq fx_rgb_to_yiq(fx_color c);
fx_color fx_yiq_to_rgb(fx_yiq c);

/* CIE XYZ of an sRGB colour (D65 white has Y = 1), and back (out of gamut clamps). */
fx_xyz fx_rgb_to_xyz(fx_color c);
fx_color fx_xyz_to_rgb(fx_xyz c);

/* The sRGB transfer curve: 8-bit code -> linear light in Q16 (exact table
 * entry), and linear Q16 -> nearest code. */
fx16 fx_srgb_to_linear(uint8_t v);
uint8_t fx_linear_to_srgb(fx16 l);

/* ---- colour from wavelength (CIE 1931) ----
 *
 * fx_cie1931_cmf: the CIE 1931 2-degree standard observer's colour-matching
 * functions x-bar, y-bar, z-bar (CIE 15:2004) at FX_CIE_N wavelengths from
 * FX_CIE_FIRST nm every FX_CIE_STEP nm, times 10^6 (exact: the CIE tabulates
 * six decimals; y-bar(555) = 10^6).
 *
 * fx_wavelength_to_xyz: the three functions at nm (Q16.16 nanometres),
 * linearly interpolated between table rows, in Q16 (y-bar = 1 is 0x10000);
 * outside [380, 780] nm all are 0.
 *
 * fx_xyz_to_xy: chromaticity x = X / (X + Y + Z), y = Y / (X + Y + Z)
 * (and z = 1 - x - y), each rounded to nearest Q16; -FX_EDOM when
 * X + Y + Z <= 0.
 *
 * fx_xyz_to_rgb_display: a colour for a chromaticity that sRGB may not
 * hold (spectral colours never are): XYZ by the sRGB matrix to linear RGB;
 * a negative channel is lifted to 0 by adding the same amount to all three
 * (desaturating toward white along the sRGB primaries), then the largest
 * channel is scaled to 1 and the channels encoded by the sRGB curve. Hue is
 * kept, lightness is not (the diagram's convention). Black for X=Y=Z=0.
 * fx_wavelength_to_rgb is that of fx_wavelength_to_xyz: 700 nm gives a red,
 * 520 nm a green, 450 nm a blue; black outside [380, 780] nm. */
#define FX_CIE_FIRST 380
#define FX_CIE_STEP 5
#define FX_CIE_N 81
extern const int32_t fx_cie1931_cmf[FX_CIE_N][3];

/* The spectrum (CIE 1931 2-degree observer, fx_cie1931_cmf every 5 nm from
 * 380 nm): the XYZ of a pure wavelength in nm (Q16.16, interpolated), its
 * chromaticity (x, y) (0, or -FX_EDOM for black), its display colour (out of
 * gamut: white added until no channel is negative, then scaled so the
 * brightest channel is full), and that colour of a wavelength. */
fx_xyz fx_wavelength_to_xyz(fx16 nm);
int fx_xyz_to_xy(fx_xyz c, fx16 *x, fx16 *y);
fx_color fx_xyz_to_rgb_display(fx_xyz c);
fx_color fx_wavelength_to_rgb(fx16 nm);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
