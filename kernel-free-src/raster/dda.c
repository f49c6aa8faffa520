/* SPDX-License-Identifier: MIT */
/* fixel — the fixed-point DDA line, clipped exactly, with its trace. */
#include "fixel/line.h"
#include "../base/fx_internal.h"

void fx_dda_init(fx_dda_iter *d, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    uint32_t adx = (uint32_t)(dx < 0 ? -dx : dx), ady = (uint32_t)(dy < 0 ? -dy : dy);
    d->x0 = x0;
    d->y0 = y0;
    d->sx = dx > 0 ? 1 : dx < 0 ? -1 : 0;
    d->sy = dy > 0 ? 1 : dy < 0 ? -1 : 0;
    d->ymajor = ady > adx;
    d->major = d->ymajor ? ady : adx;
    d->minor = d->ymajor ? adx : ady;
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

/* Steps whose coordinate start + s*k lies in [lo, hi]. */
static int axis_range(int32_t start, int32_t s, int64_t lo, int64_t hi, int64_t *a, int64_t *b)
{
    if (s > 0) {
        *a = lo - start;
        *b = hi - start;
    } else if (s < 0) {
        *a = start - hi;
        *b = start - lo;
    } else {
        if (start < lo || start > hi)
            return 0;
        *a = INT64_MIN;
        *b = INT64_MAX;
    }
    return *a <= *b;
}

static uint32_t first_k_with_minor(const fx_dda_iter *d, uint32_t m)
{
    uint32_t lo = 0, hi = d->major;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        if (minor_at(d, mid) >= m)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

static int dda_clip(const fx_dda_iter *d, fx_rect clip, uint32_t *k0, uint32_t *k1)
{
    if (fx_rect_empty(clip))
        return 0;
    int64_t lo = 0, hi = d->major, a0, a1, m0, m1;
    int32_t ma_start = d->ymajor ? d->y0 : d->x0, ma_s = d->ymajor ? d->sy : d->sx;
    int32_t mi_start = d->ymajor ? d->x0 : d->y0, mi_s = d->ymajor ? d->sx : d->sy;
    int64_t ma_lo = d->ymajor ? clip.y0 : clip.x0, ma_hi = (d->ymajor ? clip.y1 : clip.x1) - 1;
    int64_t mi_lo = d->ymajor ? clip.x0 : clip.y0, mi_hi = (d->ymajor ? clip.x1 : clip.y1) - 1;
    if (!axis_range(ma_start, ma_s, ma_lo, ma_hi, &a0, &a1))
        return 0;
    lo = FX_MAX(lo, a0);
    hi = FX_MIN(hi, a1);
    if (lo > hi || !axis_range(mi_start, mi_s, mi_lo, mi_hi, &m0, &m1))
        return 0;
    if (mi_s != 0) {
        if (m1 < 0 || m0 > d->minor)
            return 0;
        if (m0 > 0)
            lo = FX_MAX(lo, (int64_t)first_k_with_minor(d, (uint32_t)m0));
        if (m1 < d->minor)
            hi = FX_MIN(hi, (int64_t)first_k_with_minor(d, (uint32_t)m1 + 1) - 1);
    }
    if (lo > hi)
        return 0;
    *k0 = (uint32_t)lo;
    *k1 = (uint32_t)hi;
    return 1;
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
#define FX_WALK(T)                          \
    for (;;) {                              \
        *(T *)(void *)p = (T)v;             \
        if (--n == 0)                       \
            break;                          \
        p += step_major;                    \
        uint32_t nf = frac + inc_lo;        \
        if (nf < frac)                      \
            p += step_minor;                \
        frac = nf;                          \
    }
    if (bpp == 32)
        FX_WALK(uint32_t)
    else if (bpp == 16)
        FX_WALK(uint16_t)
    else
        FX_WALK(uint8_t)
#undef FX_WALK
}
