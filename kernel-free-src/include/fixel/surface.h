/* SPDX-License-Identifier: MIT */
/* fixel — surfaces and pixel formats.
 *
 * A surface is plain data: a pointer to row 0, a size, a stride in bytes
 * (negative for bottom-up memory, larger than a row for padded memory) and a
 * format. It never owns its pixels; whoever made the memory frees it.
 *
 * Colour in the API is 0xAARRGGBB (fx_color). Each format packs and unpacks
 * with one rule, documented in the table below and tested exhaustively:
 *
 *  format    memory layout (little-endian words, DRM fourcc naming)
 *  XRGB8888  u32 [31:0] x:R:G:B          pack: X byte written 0; unpack: A=FF
 *  ARGB8888  u32 [31:0] A:R:G:B          exact both ways
 *  XBGR8888  u32 [31:0] x:B:G:R          pack: X byte 0; unpack: A=FF
 *  RGB565    u16 [15:0] R5:G6:B5         pack truncates (r>>3, g>>2, b>>3);
 *  BGR565    u16 [15:0] B5:G6:R5           unpack replicates top bits (r5<<3|r5>>2)
 *  RGB888    bytes B,G,R (u24 R:G:B)     exact, A=FF on unpack
 *  BGR888    bytes R,G,B (u24 B:G:R)     exact, A=FF on unpack
 *  GRAY8     u8 luma                     pack: (77R + 150G + 29B + 128) >> 8;
 *                                          unpack: R=G=B=luma
 *  MONO1     1 bit per pixel, LSB first  pack: luma >= 128 -> 1 (lit);
 *            (pixel x in bit x%8 of        unpack: 1 -> FFFFFF, 0 -> 000000
 *            byte x/8, after bit_offset)
 */
#ifndef FIXEL_SURFACE_H
#define FIXEL_SURFACE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef uint32_t fx_color; /* 0xAARRGGBB */

typedef enum fx_format {
    FX_FMT_XRGB8888,
    FX_FMT_ARGB8888,
    FX_FMT_XBGR8888,
    FX_FMT_RGB565,
    FX_FMT_BGR565,
    FX_FMT_RGB888,
    FX_FMT_BGR888,
    FX_FMT_GRAY8,
    FX_FMT_MONO1,
    FX_FMT_COUNT
} fx_format;

typedef struct fx_format_info {
    const char *name;     /* "XRGB8888", as in the table above */
    uint32_t drm_fourcc;  /* DRM_FORMAT_* code, 0 where DRM has none (MONO1) */
    uint8_t bits_per_pixel;
    uint8_t has_alpha;
} fx_format_info;

typedef struct fx_surface {
    uint8_t *pixels;    /* row 0, first byte holding pixel (0, 0) */
    int32_t w, h;       /* in pixels */
    int32_t stride;     /* bytes from one row to the next; may be negative */
    fx_format format;
    uint8_t bit_offset; /* MONO1 only: bit of pixel 0 within its byte (0..7) */
    /* Set by fx_surface_init: the widest vector stores this CPU and OS allow
     * for solid rectangles (0: the portable loops, always safe). A surface
     * set up field by field must zero it. */
    uint8_t fill_isa;
    /* Set by fx_surface_init on x86-64: the MiB an operation must touch
     * before a whole-frame fill or copy bypasses the cache (0: the
     * built-in 6 MiB). */
    uint8_t stream_mib;
} fx_surface;

/* Half-open rectangle [x0, x1) x [y0, y1); empty when x0 >= x1 or y0 >= y1. */
typedef struct fx_rect {
    int32_t x0, y0, x1, y1;
} fx_rect;

/* The description of pixel format f (name, DRM code, bits per pixel);
 * NULL for a value that is no format. */
const fx_format_info *fx_format_get(fx_format f);
/* Case-insensitive lookup by name; returns FX_FMT_COUNT when unknown or
 * NULL. */
fx_format fx_format_from_name(const char *name);
/* Smallest stride in bytes for w pixels (MONO1 rounds up to whole bytes);
 * INT32_MAX when it does not fit; 0 for an unknown format or w < 0. */
int32_t fx_format_min_stride(fx_format f, int32_t w);

/* Wrap caller memory. Preconditions, each checked (-FX_EINVAL): s and pixels
 * not NULL, w and h >= 1, a known format, |stride| at least the row size
 * computed in 64 bits (fx_format_min_stride), and stride and pixels aligned
 * to the format's word size. */
int fx_surface_init(fx_surface *s, void *pixels, int32_t w, int32_t h, int32_t stride,
                    fx_format format);
/* A view of a rectangle of s sharing its pixels; the rectangle is clipped to
 * s (an empty result has w == 0 or h == 0). */
fx_surface fx_surface_sub(fx_surface s, fx_rect r);

/* Pack 0xAARRGGBB to the format's native value, and back. */
uint32_t fx_pack(fx_format f, fx_color c);
fx_color fx_unpack(fx_format f, uint32_t native);

/* Raw access to one pixel's native value; no bounds checks (callers clip). */
uint32_t fx_surface_get_native(const fx_surface *s, int32_t x, int32_t y);
void fx_surface_put_native(const fx_surface *s, int32_t x, int32_t y, uint32_t native);

/* Bounds-checked single pixels: out-of-surface writes are ignored and reads
 * return 0. */
void fx_surface_put(const fx_surface *s, int32_t x, int32_t y, fx_color c);
fx_color fx_surface_get(const fx_surface *s, int32_t x, int32_t y);

/* Spans and rectangles of one native value, already clipped by the caller
 * (x0 <= x1, inside the surface): the hot loops every rasterizer ends in. */
void fx_span_fill(const fx_surface *s, int32_t y, int32_t x0, int32_t x1, uint32_t native);
void fx_rect_fill_native(const fx_surface *s, fx_rect r, uint32_t native);

/* Clipped conveniences. */
void fx_surface_fill(const fx_surface *s, fx_rect r, fx_color c);
void fx_surface_clear(const fx_surface *s, fx_color c);

/* Copy src (any format) onto dst at (dx, dy), clipped to dst, converting
 * through fx_unpack/fx_pack. Same-format copies are plain row copies.
 * Overlapping memory is handled (rows are moved in a safe order). dst or src
 * NULL: nothing is copied. */
void fx_blit(const fx_surface *dst, int32_t dx, int32_t dy, const fx_surface *src);

/* Convert one row of w pixels to 8-bit RGB triplets (for PNG/PPM output). */
void fx_surface_row_to_rgb(const fx_surface *s, int32_t y, uint8_t *rgb);

/* Rectangle helpers. */
fx_rect fx_rect_intersect(fx_rect a, fx_rect b);
/* The physical rectangle covered by logical rectangle r; phys_w/phys_h are the
 * physical surface's size. Mapping of a logical pixel (x, y), W x H physical:
 *    0: (x, y)          90: (W-1-y, x)
 *  180: (W-1-x, H-1-y) 270: (y, H-1-x)                                    */
fx_rect fx_rect_rotate(fx_rect r, int rotation, int32_t phys_w, int32_t phys_h);
static inline int fx_rect_empty(fx_rect r) { return r.x0 >= r.x1 || r.y0 >= r.y1; }
static inline fx_rect fx_surface_rect(const fx_surface *s)
{
    fx_rect r = {0, 0, s->w, s->h};
    return r;
}

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
