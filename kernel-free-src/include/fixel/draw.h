/* SPDX-License-Identifier: MIT */
/* fixel — the drawing context.
 *
 * Everything a primitive needs besides its own arguments travels in an
 * fx_ctx: the surface, the colour, the clip rectangle and optional styles.
 * The context holds no pointers to hidden state and the library has no
 * globals, so two contexts on two surfaces never interfere, and a context is
 * cheap to copy (copy one to change the colour for a single call).
 *
 * Styles are caller-owned structs referenced by pointer; NULL means the
 * default (solid, 1 pixel, no pattern, identity transform). Each module that
 * defines a style documents it in its own header.
 */
#ifndef FIXEL_DRAW_H
#define FIXEL_DRAW_H

#include <stdint.h>
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How a primitive's colour meets what is already on the surface. */
typedef enum fx_blend {
    FX_BLEND_SRC = 0, /* replace the pixel (the default) */
    FX_BLEND_OVER = 1 /* source-over with the colour's alpha, exact /255 rounding */
} fx_blend;

/* Algorithm-step tracing: the core formats one line of text (no newline) and
 * hands it to the caller, who prints it, logs it or tests it. */
typedef void (*fx_trace_fn)(void *user, const char *line);

struct fx_line_style; /* line.h */
struct fx_text_style; /* font.h */
struct fx_fill_style; /* fill.h */
struct fx_xform2;     /* xform.h */

typedef struct fx_ctx {
    fx_surface surf;
    fx_rect clip;        /* always inside the surface; see fx_ctx_set_clip */
    fx_color color;      /* 0xAARRGGBB */
    uint32_t native;     /* colour packed for surf.format, kept in step by fx_ctx_set_color */
    uint8_t blend;       /* fx_blend */
    uint8_t line_clipper; /* which line clipper (clip.h); the pixels are the same for all */
    uint8_t exterior;    /* 1: draw only outside exterior_rect (clip.h) */
    uint8_t coords;      /* fx_coords; set only through fx_ctx_set_coords (it fills
                          * what was padding, so the layout is unchanged) */
    fx_rect exterior_rect;
    const struct fx_line_style *line_style; /* NULL: solid, 1 px */
    const struct fx_text_style *text_style; /* NULL: built-in font, scale 1 */
    const struct fx_fill_style *fill_style; /* NULL: solid colour */
    const struct fx_xform2 *xform;          /* NULL: identity */
    fx_trace_fn trace;                      /* NULL: no tracing */
    void *trace_user;
} fx_ctx;

/* Which way y points for everything drawn through a context.
 *
 * FX_COORDS_SCREEN (the default): the surface's own frame, origin at the
 * top-left pixel, y growing downwards (docs/CONVENTIONS.md).
 * FX_COORDS_COURSE: the course notes' (and GLUT/OpenGL's) frame, origin at
 * the bottom-left pixel, y growing upwards: pixel (x, y) is the surface's
 * (x, H-1-y). The mapping is made once, in the context's view of the surface
 * (row 0 is the bottom row, the stride negated), so every primitive,
 * transform, clip window and trace of the core works in the chosen frame
 * with the same algorithm: a drawing in course mode is exactly the same
 * drawing in screen mode mirrored top to bottom, and the numbers a trace
 * prints are the ones a student works out by hand in y-up coordinates.
 * One exception keeps text readable: fx_text draws its glyphs upright, with
 * (x, y) still the text's top-left corner (see font.h). */
typedef enum fx_coords { FX_COORDS_SCREEN = 0, FX_COORDS_COURSE = 1 } fx_coords;

/* Switch c to mode. The clip and exterior rectangles are carried over so
 * that they keep covering the same pixels of the surface (their y is
 * mirrored); the colour and styles are unchanged. Switching to the mode c is
 * in does nothing. -FX_EINVAL for c NULL or an unknown mode. */
int fx_ctx_set_coords(fx_ctx *c, fx_coords mode);
static inline fx_coords fx_ctx_coords(const fx_ctx *c) { return (fx_coords)c->coords; }

/* A context on s: clip = whole surface, colour opaque white, SRC blending.
 * c NULL: nothing happens; s NULL: an empty context that draws nothing. */
void fx_ctx_init(fx_ctx *c, const fx_surface *s);
void fx_ctx_set_color(fx_ctx *c, fx_color color);
/* Clip to r intersected with the surface (r is half-open). */
void fx_ctx_set_clip(fx_ctx *c, fx_rect r);
void fx_ctx_reset_clip(fx_ctx *c);

/* One pixel / one horizontal span [x0, x1) of the current colour, clipped,
 * honouring blend mode and exterior clipping. The building blocks for
 * primitives that have no faster path of their own. */
void fx_plot(const fx_ctx *c, int32_t x, int32_t y);
void fx_hspan(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1);
/* Alias of fx_plot, the name other libraries give it. */
static inline void fx_put_pixel(const fx_ctx *c, int32_t x, int32_t y) { fx_plot(c, x, y); }

/* Rectangles with the top-left corner (x, y) and size w x h in pixels.
 * fx_fill_rect covers [x, x+w) x [y, y+h); fx_rect_outline draws its
 * 1-pixel border (the pixels of the filled rectangle that touch its edge).
 * Arguments anywhere in int32 are fine: work is bounded by the visible part. */
void fx_fill_rect(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h);
void fx_rect_outline(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h);
void fx_clear(const fx_ctx *c); /* fill the clip rectangle */

/* Exact source-over of colour c (alpha in its top byte) onto the native pixel
 * value dst of format f: each channel (s*a + d*(255-a)) / 255 rounded to nearest. */
uint32_t fx_blend_over(fx_format f, uint32_t dst, fx_color c);

/* Format a trace line printf-style (%d %u %x %s %c %ld %lld %%, widths, the '-'
 * and '0' flags, and %.Ns / %.*s) and pass it to c->trace when set. */
void fx_trace(const fx_ctx *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The formatter behind fx_trace, for any caller: writes at most size-1 chars
 * plus a NUL, returns the length it would have written. */
#include <stdarg.h>
#include <stddef.h>
int fx_vfmt(char *buf, size_t size, const char *fmt, va_list ap);
int fx_fmt(char *buf, size_t size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
