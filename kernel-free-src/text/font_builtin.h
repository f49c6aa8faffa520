/* SPDX-License-Identifier: MIT */
/* The built-in font's bitmap (font_builtin.c, generated); not installed. */
#ifndef FIXEL_FONT_BUILTIN_H
#define FIXEL_FONT_BUILTIN_H

#include <stdint.h>

#define FX_BUILTIN_W      6
#define FX_BUILTIN_H      10
#define FX_BUILTIN_GLYPHS 96 /* ASCII 32..126, then the box */

extern const uint8_t fx_font_builtin_bits[FX_BUILTIN_GLYPHS * FX_BUILTIN_H];

#endif
