/* SPDX-License-Identifier: MIT */
/* fixel — bitmap fonts and text.
 *
 * Fonts are PSF1 or PSF2 console fonts (the kind in /usr/share/consolefonts)
 * parsed in place from a caller-owned buffer: fx_font_load checks every size
 * and offset against the buffer once, so drawing never reads outside it,
 * whatever the bytes are. Decompression (.psf.gz) is the caller's business;
 * the core never sees files. A small built-in 6x10 font (ASCII 32..126, the
 * project's own drawing) is used when a style names no font.
 *
 * Glyph rows are stored MSB first (bit 7 of the first byte is the leftmost
 * pixel), row_bytes = (width + 7) / 8 bytes per row, as in PSF.
 *
 * Text is drawn from its top-left corner (x, y): each character takes a cell
 * of width x height pixels times the style's integer scale; '\n' starts a new
 * line under the first. Set pixels take the context's colour; with a
 * background colour the unset pixels of each cell take that colour too (each
 * pixel written once, so translucent colours blend evenly). Clipping follows
 * the course's three modes:
 *   FX_TEXT_CLIP_STRING  all or none of the string: drawn only if its whole
 *                        box lies inside the clip rectangle;
 *   FX_TEXT_CLIP_CHAR    all or none of each character cell;
 *   FX_TEXT_CLIP_PIXEL   every pixel clipped on its own (the default).
 */
#ifndef FIXEL_FONT_H
#define FIXEL_FONT_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/draw.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Limits a loaded font must respect (larger values: -FX_ERANGE). */
#define FX_FONT_MAX_DIM    256u   /* width and height in pixels */
#define FX_FONT_MAX_GLYPHS 65536u

typedef struct fx_font {
    const uint8_t *glyphs; /* glyph 0, row 0 */
    uint32_t count;        /* glyphs */
    uint32_t width, height;
    uint32_t row_bytes, glyph_bytes;
    const uint8_t *utab; /* PSF unicode table, NULL when absent */
    size_t utab_len;
    uint8_t version;      /* 1: PSF1, 2: PSF2, 0: the built-in font */
    uint16_t ascii[128];  /* glyph of each ASCII code, resolved at load */
    uint32_t fallback;    /* glyph for characters the font lacks */
    /* The unicode-table index (fx_font_index), NULL until built: a bit per
     * code point, the count of set bits before each 64-bit word, and the
     * glyph of each set bit in code-point order. */
    const uint64_t *ix_bits;
    const uint32_t *ix_rank;
    const uint16_t *ix_glyph;
} fx_font;

enum fx_text_clip { FX_TEXT_CLIP_PIXEL = 0, FX_TEXT_CLIP_CHAR = 1, FX_TEXT_CLIP_STRING = 2 };

typedef struct fx_text_style {
    const fx_font *font; /* NULL: fx_font_builtin() */
    int32_t scale;       /* pixels per font pixel, 1..256; values below 1 mean 1 */
    fx_color bg;         /* background colour when has_bg */
    uint8_t has_bg;
    uint8_t clip;        /* enum fx_text_clip */
} fx_text_style;

/* Parse a PSF1 or PSF2 font in data[0..len) (the buffer must outlive the
 * font). Returns 0, or a negative error:
 *   -FX_EINVAL    NULL arguments
 *   -FX_EBADMSG   not a PSF font (bad magic, header too short for its kind),
 *                 or a header contradicting itself (zero glyphs or size,
 *                 PSF2 bytes per glyph != height * row bytes, header size
 *                 below 32)
 *   -FX_ENOTSUP   a PSF2 version other than 0, or unknown PSF1 mode bits
 *   -FX_ERANGE    width/height above FX_FONT_MAX_DIM, glyph count above
 *                 FX_FONT_MAX_GLYPHS
 *   -FX_EOVERFLOW the glyphs run past the end of the buffer (truncated) */
int fx_font_load(fx_font *f, const void *data, size_t len);

/* Index the unicode table once, so that each lookup is O(1) instead of a walk
 * of the whole table (a 60 MiB table took 171 s to load, issue #26).
 * fx_font_index_bytes(f): the memory the index may need (0: no table);
 * fx_font_index(f, mem, size): builds it in mem (8-byte aligned, kept while
 * the font is used) and returns 0, or -FX_EINVAL / -FX_ENOSPC (lookups then
 * stay linear). Loading walks the table once either way. */
size_t fx_font_index_bytes(const fx_font *f);
int fx_font_index(fx_font *f, void *mem, size_t size);

/* The built-in 6x10 font (constant data; never fails). */
const fx_font *fx_font_builtin(void);

/* Glyph index for a Unicode code point: through the font's unicode table
 * when it has one, else the code point itself when below the glyph count;
 * characters the font lacks get f->fallback ('?' when the font has it). */
uint32_t fx_font_glyph(const fx_font *f, uint32_t codepoint);
/* Row r of glyph g (g < count, r < height): row_bytes bytes. */
static inline const uint8_t *fx_font_row(const fx_font *f, uint32_t g, uint32_t r)
{
    return f->glyphs + (size_t)g * f->glyph_bytes + (size_t)r * f->row_bytes;
}

/* Size in pixels of the box of utf8 drawn with style st (NULL: defaults):
 * the widest line times the number of lines. utf8 NULL is the empty text;
 * w or h may be NULL. */
void fx_text_extent(const fx_text_style *st, const char *utf8, int64_t *w, int64_t *h);

/* Draw NUL-terminated UTF-8 text with c->text_style (NULL: built-in font,
 * scale 1, no background, per-pixel clipping). Malformed UTF-8 shows the
 * fallback glyph. Returns the number of characters drawn at least in part,
 * or -FX_EINVAL when c or utf8 is NULL. */
/* In a course-mode context (draw.h, y up) the glyphs are still drawn
 * upright, reading left to right: (x, y) is the text's top-left corner in
 * course coordinates and the lines go on downwards on the screen, so a
 * label stays readable when the drawing around it is mirrored. */
int fx_text(const fx_ctx *c, int32_t x, int32_t y, const char *utf8);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
