/* SPDX-License-Identifier: MIT */
/* The Bresenham leaf's private interface (bres.c); not installed.
 *
 * The line code is a chain with one-way dependencies:
 *   bres.c    the leaf: fx_bres_* iterator, the step-range clip of both line
 *             iterators (fx_line_axes_clip), the pixel walks, fx_line_steps*
 *   dda.c     the DDA iterator, on the leaf's clip and walk macro
 *   clip.c    the named line clippers (clip.h), on the leaf
 *   stroke.c  patterns and thick strokes, on the leaf
 *   line.c    the dispatcher fx_line, on all of the above
 * Nothing calls back up the chain. */
#ifndef FIXEL_LINE_INTERNAL_H
#define FIXEL_LINE_INTERNAL_H

#include <stdint.h>
#include "fixel/line.h"

/* The geometry both line iterators (fx_bres, fx_dda_iter) share, with the
 * iterator's own minor offset of step k (non-decreasing in k). */
typedef struct fx_line_axes {
    int32_t x0, y0, sx, sy;
    uint32_t major, minor;
    uint8_t ymajor;
    uint32_t (*minor_at)(const void *it, uint32_t k);
    const void *it;
} fx_line_axes;

/* The axes of the line (x0, y0) -> (x1, y1) into *p, any struct with the
 * fields of fx_line_axes (fx_bres, fx_dda_iter): start, signs of the steps,
 * which axis is major, and the extents along both. */
#define FX_LINE_AXES_INIT(p, X0, Y0, X1, Y1)                                                \
    do {                                                                                 \
        int64_t dx_ = (int64_t)(X1) - (X0), dy_ = (int64_t)(Y1) - (Y0);                  \
        uint32_t adx_ = (uint32_t)(dx_ < 0 ? -dx_ : dx_), ady_ = (uint32_t)(dy_ < 0 ? -dy_ : dy_); \
        (p)->x0 = (X0);                                                                  \
        (p)->y0 = (Y0);                                                                  \
        (p)->sx = dx_ > 0 ? 1 : dx_ < 0 ? -1 : 0;                                        \
        (p)->sy = dy_ > 0 ? 1 : dy_ < 0 ? -1 : 0;                                        \
        (p)->ymajor = ady_ > adx_;                                                       \
        (p)->major = (p)->ymajor ? ady_ : adx_;                                          \
        (p)->minor = (p)->ymajor ? adx_ : ady_;                                          \
    } while (0)

/* The steps [*k0, *k1] of the line whose pixels lie inside clip, exactly:
 * the major axis gives a range of steps directly, the minor axis a range of
 * offsets turned into steps by binary search on minor_at. 0 when none. */
int fx_line_axes_clip(const fx_line_axes *g, fx_rect clip, uint32_t *k0, uint32_t *k1);

/* Write steps [k0, k1] of b (all inside c->clip) in the context's colour:
 * fx_plot for traces, blending, exterior clipping and sub-byte formats,
 * otherwise the fast DDA walk, runs, or the pointer walk below. */
void fx_bres_walk(const fx_ctx *c, fx_bres *b, uint32_t k0, uint32_t k1);

/* The Bresenham error step of the pointer walk: whether the minor axis
 * moves, with the decision variable e updated. */
static inline int fx_bres_err_step(int64_t *e, int64_t inc1, int64_t inc2)
{
    if (*e >= 0) {
        *e += inc2;
        return 1;
    }
    *e += inc1;
    return 0;
}

/* The DDA carry: whether adding inc to the 32-bit fraction *frac wraps
 * (the minor axis moves), with *frac updated. */
static inline int fx_carry32(uint32_t *frac, uint32_t inc)
{
    uint32_t nf = *frac + inc;
    int c = nf < *frac;
    *frac = nf;
    return c;
}

/* The one pointer walk of the line code: n (>= 1) native pixels v of type T
 * from the byte pointer p; after each pixel one major step (step_major
 * bytes) and, when MINOR (evaluated once per step) is true, a minor step
 * (step_minor bytes); a pixel is written when KEEP is true; NEXT runs after
 * each step (a pattern position). Uses p, n, v, step_major, step_minor of
 * the enclosing function. */
#define FX_LINE_WALK(T, KEEP, MINOR, NEXT) \
    for (;;) {                             \
        if (KEEP)                          \
            *(T *)(void *)p = (T)v;        \
        if (--n == 0)                      \
            break;                         \
        p += step_major;                   \
        if (MINOR)                         \
            p += step_minor;               \
        NEXT;                              \
    }

/* FX_LINE_WALK on pixels of bpp 32, 16 or 8 bits. */
#define FX_LINE_WALK_BPP(bpp, KEEP, MINOR, NEXT)        \
    do {                                                \
        if ((bpp) == 32)                                \
            FX_LINE_WALK(uint32_t, KEEP, MINOR, NEXT)   \
        else if ((bpp) == 16)                           \
            FX_LINE_WALK(uint16_t, KEEP, MINOR, NEXT)   \
        else                                            \
            FX_LINE_WALK(uint8_t, KEEP, MINOR, NEXT)    \
    } while (0)

#endif
