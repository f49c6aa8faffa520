/* SPDX-License-Identifier: MIT */
/* fixel — lines.
 *
 * The 1-pixel line is Bresenham's: from (x0, y0) to (x1, y1) it lights
 * max(|dx|, |dy|) + 1 pixels, endpoints included, one per step of the major
 * axis. At step k the minor-axis offset is round_half_up(k * minor / major),
 * i.e. the course's decision rule "p_k >= 0 -> step the minor axis" with
 * p_0 = 2*minor - major, increments 2*minor and 2*minor - 2*major.
 *
 * The walk is a seekable iterator: fx_bres_seek computes the decision state
 * of any step in O(1) (64-bit arithmetic for every int32 endpoint pair), which
 * gives exact clipping (a clipped line lights exactly the pixels of the
 * unclipped one inside the window, with work bounded by the visible part)
 * and the parallel line algorithm (pieces rendered independently).
 */
#ifndef FIXEL_LINE_H
#define FIXEL_LINE_H

#include <stdint.h>
#include "fixel/draw.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_bres {
    int32_t x0, y0;        /* first pixel */
    int32_t sx, sy;        /* -1, 0 or +1 */
    uint32_t major, minor; /* |d| along the major and minor axis */
    uint8_t ymajor;        /* 1 when |dy| > |dx| */
    /* walking state, valid after init/seek */
    uint32_t k; /* step index, 0..major */
    int32_t x, y;
    int64_t p; /* decision p_k (decides pixel k+1) */
} fx_bres;

/* Bresenham's walk from (x0, y0) to (x1, y1), both end points included,
 * ready at step 0. */
void fx_bres_init(fx_bres *b, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
/* Jump to step k (0 <= k <= major). */
void fx_bres_seek(fx_bres *b, uint32_t k);
/* Advance to the next pixel. */
static inline void fx_bres_step(fx_bres *b)
{
    if (b->ymajor)
        b->y += b->sy;
    else
        b->x += b->sx;
    if (b->p >= 0) {
        if (b->ymajor)
            b->x += b->sx;
        else
            b->y += b->sy;
        b->p += 2 * (int64_t)b->minor - 2 * (int64_t)b->major;
    } else {
        b->p += 2 * (int64_t)b->minor;
    }
    b->k++;
}
/* Minor-axis offset (0..minor) at step k. */
uint32_t fx_bres_minor_at(const fx_bres *b, uint32_t k);
/* Steps [*k0, *k1] (inclusive) whose pixels lie inside clip; returns 1, or 0
 * when no pixel of the line is inside. */
int fx_bres_clip(const fx_bres *b, fx_rect clip, uint32_t *k0, uint32_t *k1);

/* The 1-pixel Bresenham line in the context's colour, clipped exactly.
 * With c->trace set, prints the course's decision table (k, p_k, next pixel). */
void fx_line(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);

/* Steps [k0, k1] of the line only (the parallel line algorithm: pieces drawn
 * by different threads or at different times light exactly the pixels of the
 * whole line). Clipped to the context like fx_line. */
void fx_line_steps(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t k0,
                   uint32_t k1);

/* Like fx_line_steps for steps the caller has already clipped (the line
 * clippers of clip.h): every pixel of steps [k0, k1] must lie inside c->clip,
 * nothing is checked again. */
void fx_line_steps_inside(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                          uint32_t k0, uint32_t k1);

/* ---- DDA ----
 * The digital differential analyser in fixed point: the minor coordinate is
 * a Q32.32 accumulator stepped by minor/major per pixel, the major one moves
 * by exactly 1. Same rules as Bresenham: max(|dx|, |dy|) + 1 pixels,
 * endpoints included, one per major step, clipped exactly.
 *
 * Rounding: the DDA rounds the *absolute* coordinate half up (towards
 * +infinity), x_k = floor(x0 + k*dx/major + 1/2); Bresenham rounds the
 * offset from the start half up (away from the start). The two differ
 * exactly at ties (k*minor/major an odd multiple of 1/2) on lines whose
 * minor direction is negative, where the DDA picks the pixel nearer
 * +infinity (towards the start). The increment is rounded towards the true
 * value's rounding side (up when the minor direction is positive, down when
 * negative), which keeps every pixel equal to that exact rounding for
 * major <= 46340; longer lines may differ from it by one pixel at near-ties
 * (accumulated increment error < major * 2^-32), never at the endpoints. */
typedef struct fx_dda_iter {
    int32_t x0, y0, sx, sy;
    uint32_t major, minor;
    uint8_t ymajor;
    uint64_t inc;  /* minor step in Q32.32 (<= 2^32) */
    uint64_t bias; /* 2^31 or 2^31 - 1: the half for the rounding above */
} fx_dda_iter;

/* The DDA from (x0, y0) to (x1, y1), rounding as described above. */
void fx_dda_init(fx_dda_iter *d, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
/* The pixel of step k (0 <= k <= major), in O(1). */
void fx_dda_point(const fx_dda_iter *d, uint32_t k, int32_t *x, int32_t *y);
/* The DDA line in the context's colour, clipped exactly; with c->trace set
 * prints k, the fixed-point x_k and y_k, and the pixel lit. */
void fx_dda(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);

/* ---- line attributes ----
 * A caller-owned style referenced by fx_ctx.line_style (NULL: solid, 1 px).
 *
 * Pattern: bit i (LSB first) of `pattern` says whether pattern unit i is
 * lit; pattern_len (1..32) units make one period, 0 means solid. A unit is
 * `unit` pixels (0: the line width, at least 1), measured along the major
 * axis in pixels for 1-pixel lines (the course's pixel mask) and along the
 * Euclidean length for thick lines. `phase` (pixels) shifts the start; the
 * phase continues across the segments of a polyline and along curves.
 *
 * Width: <= 1 draws the 1-pixel Bresenham line. Wider lines are the set of
 * pixel centres inside the stroke outline (segment bodies of half-width w/2
 * with offsets rounded to 1/256 pixel, caps, joins), top-left rule on
 * polygon edges; discs (round caps and joins) are closed. The decision for
 * every pixel depends on the geometry only, so clipping never moves one. */
enum { FX_CAP_BUTT, FX_CAP_SQUARE, FX_CAP_ROUND };
enum { FX_JOIN_MITER, FX_JOIN_ROUND, FX_JOIN_BEVEL };

#define FX_LINE_MAX_WIDTH 4096

typedef struct fx_line_style {
    uint32_t pattern;
    uint8_t pattern_len; /* 0: solid */
    uint8_t cap;         /* FX_CAP_* (thick lines and dash ends) */
    uint8_t join;        /* FX_JOIN_* (thick polylines) */
    uint16_t unit;       /* pixels per pattern unit; 0: the width */
    int32_t width;       /* pixels, clamped to 1..FX_LINE_MAX_WIDTH */
    uint32_t phase;      /* pixels into the pattern at the start */
    fx16 miter_limit;    /* mitre length / width above which a mitre is
                            beveled; 0: 4.0 (as SVG) */
} fx_line_style;

/* Named patterns: (pattern, length) for solid, dashed (6 on 3 off), dotted
 * (1 on 1 off), dash-dot (6 on 2 off 1 on 2 off). */
#define FX_PATTERN_DASHED 0x3Fu, 9
#define FX_PATTERN_DOTTED 0x1u, 2
#define FX_PATTERN_DASHDOT 0x13Fu, 11

/* Solid, 1 pixel, butt caps, mitre joins. */
void fx_line_style_init(fx_line_style *s);
/* 1 when s draws exactly the plain 1-pixel solid line (NULL included). */
int fx_line_style_is_plain(const fx_line_style *s);

/* A polyline through n points (xy holds x0, y0, x1, y1, ...), in the
 * context's colour and line style; the shared vertex of two segments is lit
 * once (1 px) and thick segments meet with the style's join. c or xy NULL,
 * or n outside 1..INT32_MAX/2: nothing is drawn. */
void fx_polyline(const fx_ctx *c, const int32_t *xy, int n);

/* The styled stroker behind fx_line (when a style is set), fx_polyline and
 * the curves: points in 1/256 pixel (pixel centre of pixel x is 256x+128),
 * fed one by one. Thick pieces are buffered and each buffer is drawn as a
 * union (one blend per pixel); a stroke longer than the buffer may blend a
 * pixel twice where pieces of two buffers overlap (OVER with alpha only). */
#define FX_STROKE_PIECES 48
typedef struct fx_stroke_piece {
    int64_t x[4], y[4]; /* polygon (n = 3 or 4) or disc centre in x[0], y[0] */
    int64_t r;          /* disc radius (n == 0) */
    int32_t row0, row1; /* visible rows, inclusive */
    uint8_t n;
} fx_stroke_piece;

typedef struct fx_stroker {
    fx_ctx c; /* a copy: no trace, no style (the pieces are plain spans) */
    fx_line_style st;
    int thick;
    int npts;                 /* distinct points so far */
    int64_t px[2], py[2];     /* the last two points (1/256 px) */
    uint64_t pos;             /* pattern position at px[1] (1 px: pixels; thick: 1/256 px) */
    int32_t lx[2], ly[2];     /* 1 px: the last two pixels */
    uint8_t nruns;            /* lit runs of one pattern period, in units */
    uint8_t run0[16], run1[16]; /* (a run may reach into the next period) */
    int npieces;
    fx_stroke_piece piece[FX_STROKE_PIECES];
} fx_stroker;

/* Start a stroke in c's colour and line style, add its points (1/256 px),
 * and end it (draws what is buffered). */
void fx_stroke_begin(fx_stroker *s, const fx_ctx *c);
void fx_stroke_point(fx_stroker *s, int64_t x256, int64_t y256);
void fx_stroke_end(fx_stroker *s);

/* ---- antialiased lines ----
 * Xiaolin Wu's line between pixel centres: at each major step the ideal
 * minor position (Q32.32, stepped exactly as a DDA) splits 255 units of
 * coverage between the two nearest pixels, and each is blended over the
 * surface with fx_blend_over semantics (colour alpha scaled by coverage,
 * exact /255 rounding). Endpoint columns are full (the line has
 * max(|dx|, |dy|) + 1 columns, like Bresenham's). Clipped exactly; ignores
 * the line style. */
void fx_aaline(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
