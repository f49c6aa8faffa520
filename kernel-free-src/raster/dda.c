/* SPDX-License-Identifier: MIT */
/* fixel — the fixed-point DDA line, clipped exactly, with its trace. */
#include "fixel/line.h"
#include "../base/fx_internal.h"
#include "line_internal.h"

void fx_dda_init(fx_dda_iter *d, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    FX_LINE_AXES_INIT(d, x0, y0, x1, y1);
    int neg = (d->ymajor ? d->sx : d->sy) < 0;
    d->inc = 0;
    if (d->major) {
        /* Up for a positive minor direction, down for a negative one: the
         * accumulated error then never crosses a tie the wrong way. */
        uint64_t n = (uint64_t)d->minor << 32;
        d->inc = n / d->major + (!neg && n % d->major != 0);
    }
    /* floor(v + 1/2) going up is (off + 2^31) >> 32 on the offset; going
     * down the coordinate is start - ceil(off - 1/2) = start - ((off + 2^31 - 1) >> 32). */
    d->bias = neg ? ((uint64_t)1 << 31) - 1 : (uint64_t)1 << 31;
}

/* For lines longer than 2^31 the accumulated increment error can reach a
 * pixel, so the result is clamped to [0, minor] (where the exact rounding
 * always lies) and the last step is the endpoint by definition. */
static uint32_t minor_at(const fx_dda_iter *d, uint32_t k)
{
    if (k >= d->major)
        return d->minor;
    uint64_t m = (d->bias + (uint64_t)k * d->inc) >> 32;
    return m > d->minor ? d->minor : (uint32_t)m;
}

void fx_dda_point(const fx_dda_iter *d, uint32_t k, int32_t *x, int32_t *y)
{
    int64_t m = minor_at(d, k);
    if (d->ymajor) {
        *x = (int32_t)(d->x0 + d->sx * m);
        *y = (int32_t)(d->y0 + d->sy * (int64_t)k);
    } else {
        *x = (int32_t)(d->x0 + d->sx * (int64_t)k);
        *y = (int32_t)(d->y0 + d->sy * m);
    }
}

static uint32_t dda_minor_at(const void *d, uint32_t k) { return minor_at(d, k); }

static int dda_clip(const fx_dda_iter *d, fx_rect clip, uint32_t *k0, uint32_t *k1)
{
    fx_line_axes g = {d->x0, d->y0, d->sx, d->sy, d->major, d->minor, d->ymajor, dda_minor_at, d};
    return fx_line_axes_clip(&g, clip, k0, k1);
}

/* "start +- off/2^32" as a decimal with 4 places, for the trace. */
static void fmt_coord(char *buf, size_t n, int32_t start, int s, uint64_t off)
{
    int64_t ip = (int64_t)(off >> 32);
    uint64_t fr = off & 0xFFFFFFFFu;
    int64_t whole;
    uint64_t frac;
    if (s >= 0) {
        whole = start + ip;
        frac = fr;
    } else {
        whole = (int64_t)start - ip - (fr != 0);
        frac = fr ? ((uint64_t)1 << 32) - fr : 0;
    }
    /* value = whole + frac/2^32; print sign-magnitude with 4 decimals */
    uint64_t f4 = (frac * 10000 + ((uint64_t)1 << 31)) >> 32;
    if (f4 == 10000) {
        whole++;
        f4 = 0;
    }
    int neg = whole < 0 && f4;
    if (neg) {
        whole = -whole - 1;
        f4 = 10000 - f4;
    }
    fx_fmt(buf, n, "%s%lld.%04u", neg ? "-" : "", (long long)whole, (unsigned)f4);
}

static void trace_steps(const fx_ctx *c, const fx_dda_iter *d, uint32_t k0, uint32_t k1)
{
    char xs[32], ys[32], inc[32];
    int32_t mi_s = d->ymajor ? d->sx : d->sy;
    fmt_coord(inc, sizeof inc, 0, mi_s, d->inc);
    fx_trace(c, "dda: steps=%u %s=%s%s %s=%s", d->major, d->ymajor ? "yinc" : "xinc",
             (d->ymajor ? d->sy : d->sx) < 0 ? "-" : "", "1.0000", d->ymajor ? "xinc" : "yinc", inc);
    fx_trace(c, "%-4s %-14s %-14s %s", "k", "x_k", "y_k", "pixel");
    for (uint32_t k = k0;; k++) {
        uint64_t off = (uint64_t)k * d->inc;
        int32_t px, py;
        fx_dda_point(d, k, &px, &py);
        if (d->ymajor) {
            fmt_coord(xs, sizeof xs, d->x0, d->sx, off);
            fmt_coord(ys, sizeof ys, d->y0, d->sy, (uint64_t)k << 32);
        } else {
            fmt_coord(xs, sizeof xs, d->x0, d->sx, (uint64_t)k << 32);
            fmt_coord(ys, sizeof ys, d->y0, d->sy, off);
        }
        fx_trace(c, "%-4u %-14s %-14s (%d, %d)", k, xs, ys, px, py);
        fx_plot(c, px, py);
        if (k == k1)
            break;
    }
}

void fx_dda(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    fx_dda_iter d;
    uint32_t k0, k1;
    fx_dda_init(&d, x0, y0, x1, y1);
    if (c->trace)
        fx_trace(c, "dda (%d,%d)->(%d,%d)", x0, y0, x1, y1);
    if (!dda_clip(&d, c->clip, &k0, &k1))
        return;
    unsigned bpp = fx_format_get(c->surf.format)->bits_per_pixel;
    if (c->trace || c->exterior || (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255) ||
        bpp < 8 || bpp == 24 || d.major >= (1u << 31)) {
        if (c->trace) {
            trace_steps(c, &d, k0, k1);
            return;
        }
        for (uint32_t k = k0;; k++) {
            int32_t px, py;
            fx_dda_point(&d, k, &px, &py);
            fx_plot(c, px, py);
            if (k == k1)
                break;
        }
        return;
    }
    /* Row-pointer walk: the carry out of the 32-bit fraction is the minor step. */
    int32_t px, py;
    fx_dda_point(&d, k0, &px, &py);
    ptrdiff_t bytes = (ptrdiff_t)(bpp / 8);
    ptrdiff_t step_x = d.sx * bytes, step_y = d.sy * (ptrdiff_t)c->surf.stride;
    ptrdiff_t step_major = d.ymajor ? step_y : step_x, step_minor = d.ymajor ? step_x : step_y;
    uint8_t *p = fx_row(&c->surf, py) + (ptrdiff_t)px * bytes;
    uint64_t acc = d.bias + (uint64_t)k0 * d.inc;
    uint32_t frac = (uint32_t)acc, inc_lo = (uint32_t)d.inc;
    if (d.inc >> 32) /* diagonal: every step moves both axes */
        step_major += step_minor;
    uint32_t n = k1 - k0 + 1, v = c->native;
    FX_LINE_WALK_BPP(bpp, 1, fx_carry32(&frac, inc_lo), (void)0);
}
