/* SPDX-License-Identifier: MIT */
/* fixel — midpoint ellipse (both regions) and filled ellipse.
 *
 * One quadrant, X, Y >= 0, semi-axes rx, ry >= 1. The decision of the
 * midpoint algorithm, made exact by scaling by 4:
 *   region 1 (the flat part, stepping x): the pixel of column X is the
 *     largest y with rx^2 (2y-1)^2 + 4 ry^2 X^2 < 4 rx^2 ry^2, i.e. the
 *     midpoint between y and y-1 lies inside; it lasts while
 *     ry^2 X <= rx^2 y (slope at most 1), up to (Xe, ye);
 *   region 2 (the steep part, stepping y): the pixel of row Y is the largest
 *     x with ry^2 (2x-1)^2 + 4 rx^2 Y^2 < 4 rx^2 ry^2, for the rows
 *     Y = 0 .. ye-1, joined horizontally to the row above when x jumps
 *     (thin ellipses) so the outline stays 8-connected.
 * Region 2 is walked from (rx, 0) upward rather than on from the end of
 * region 1 as in the textbook, so that both regions are the same rule with
 * the axes swapped: rx == ry gives exactly the midpoint circle, and both
 * have closed forms, which is how clipped ellipses of any size compute each
 * visible row's run directly. "No midpoint inside" means the curve passes
 * within half a pixel of the axis: the pixel on the axis (0).
 *
 * The incremental walk (decisions in 64 bits, semi-axes up to 2^14) draws
 * ellipses that lie inside the clip rectangle; every other ellipse goes row
 * by row through the closed forms in 128-bit arithmetic. The two agree
 * pixel for pixel (tests/core/test_conic.c). */
#include "fixel/circle.h"
#include "conic_internal.h"

static uint64_t div_u128(u128 a, uint64_t d) { return a.hi ? u128_div64(a, d) : a.lo / d; }

/* max s >= 0 with q^2 (2s-1)^2 < 4 p^2 (q^2 - t^2), 0 when none; t <= q. */
static int64_t mid_rule(uint64_t p, uint64_t q, uint64_t t)
{
    u128 m = u128_mul(4 * p * p, q * q - t * t);
    if (u128_zero(m))
        return 0;
    /* q^2 k < m  <=>  k <= floor((m - 1) / q^2) */
    uint64_t kmax = div_u128(u128_sub(m, (u128){0, 1}), q * q);
    if (!kmax)
        return 0;
    return ((int64_t)fx_isqrt64(kmax) + 1) / 2;
}

typedef struct ell {
    uint64_t rx, ry;
    int64_t xe, ye; /* last pixel of region 1 */
} ell;

static int64_t y1_at(const ell *e, int64_t x) { return mid_rule(e->ry, e->rx, (uint64_t)x); }
static int64_t x2_at(const ell *e, int64_t y) { return mid_rule(e->rx, e->ry, (uint64_t)y); }

/* Region 1 holds column X while ry^2 X <= rx^2 Y1(X) (true at X = 0). */
static int in_region1(const ell *e, int64_t x)
{
    u128 l = u128_mul(e->ry * e->ry, (uint64_t)x), r = u128_mul(e->rx * e->rx, (uint64_t)y1_at(e, x));
    return !u128_lt(r, l);
}

static void ell_init(ell *e, int32_t rx, int32_t ry)
{
    e->rx = (uint64_t)rx;
    e->ry = (uint64_t)ry;
    int64_t lo = 0, hi = rx; /* in_region1 is a prefix of [0, rx] */
    while (lo < hi) {
        int64_t mid = lo + (hi - lo + 1) / 2;
        if (in_region1(e, mid))
            lo = mid;
        else
            hi = mid - 1;
    }
    e->xe = lo;
    e->ye = y1_at(e, lo);
}

/* Largest X with Y1(X) >= Y (Y >= 1): 4 ry^2 X^2 < rx^2 (4 ry^2 - (2Y-1)^2); -1 if none. */
static int64_t x_hi(const ell *e, int64_t y)
{
    if (y > (int64_t)e->ry)
        return -1;
    uint64_t t = (uint64_t)(2 * y - 1), room = 4 * e->ry * e->ry - t * t;
    u128 m = u128_mul(e->rx * e->rx, room);
    if (u128_zero(m))
        return -1;
    return fx_isqrt64(div_u128(u128_sub(m, (u128){0, 1}), 4 * e->ry * e->ry));
}

/* The run [*x0, *x1] of quadrant row Y (0 <= Y <= ry). */
static void row_run(const ell *e, int64_t y, int64_t *x0, int64_t *x1)
{
    if (y >= e->ye) {
        *x0 = x_hi(e, y + 1) + 1;
        *x1 = FX_MIN(x_hi(e, y), e->xe);
        return;
    }
    int64_t x = x2_at(e, y), prev = y + 1 < e->ye ? x2_at(e, y + 1) : e->xe;
    *x0 = x > prev + 1 ? prev + 1 : x;
    *x1 = x;
}

/* Quadrant run [x0, x1] on screen row sy, mirrored to the left half (the
 * column X = 0 only once). */
static void emit(const conic_sink *k, int64_t cx, int64_t sy, int64_t x0, int64_t x1)
{
    if (x0 > x1)
        return;
    conic_span(k, sy, cx + x0, cx + x1);
    if (x0 == 0)
        x0 = 1;
    if (x0 <= x1)
        conic_span(k, sy, cx - x1, cx - x0);
}

static void emit_rows(const conic_sink *k, int64_t cx, int64_t cy, int64_t y, int64_t x0, int64_t x1)
{
    emit(k, cx, cy + y, x0, x1);
    if (y)
        emit(k, cx, cy - y, x0, x1);
}

/* The textbook form: decision variables updated by differences. Used when
 * the whole ellipse is visible and small enough for 64-bit decisions. */
static void ellipse_walk(const conic_sink *k, int64_t cx, int64_t cy, int64_t rx, int64_t ry, int trace)
{
    const fx_ctx *c = k->c;
    int64_t rx2 = rx * rx, ry2 = ry * ry;
    /* Region 1: q = rx^2 (2y-1)^2 + 4 ry^2 X^2 - 4 rx^2 ry^2 < 0 keeps y. */
    int64_t X = 0, y = ry, q = rx2 * (2 * ry - 1) * (2 * ry - 1) - 4 * rx2 * ry2;
    int64_t run0 = 0, runy = ry;
    if (trace) {
        fx_trace(c, "midpoint ellipse rx=%lld ry=%lld, region 1 (step x; keep y while "
                 "p_k = 4[ry^2(x_k+1)^2 + rx^2(y_k-1/2)^2 - rx^2ry^2] < 0, the course's p1_k "
                 "times 4, exact):",
                 (long long)rx, (long long)ry);
        fx_trace(c, "%-4s %-16s %s", "k", "p_k", "(x_k+1, y_k+1)");
    }
    for (;;) {
        int64_t p0 = q;
        while (q >= 0 && y > 0) {
            q += rx2 * (8 - 8 * y);
            y--;
        }
        if (ry2 * X > rx2 * y)
            break;
        if (trace && X > 0 && X <= 1000)
            fx_trace(c, "%-4lld %-16lld (%lld, %lld)", (long long)(X - 1), (long long)p0,
                     (long long)X, (long long)y);
        if (y != runy) {
            emit_rows(k, cx, cy, runy, run0, X - 1);
            run0 = X;
            runy = y;
        }
        q += 4 * ry2 * (2 * X + 1);
        X++;
    }
    int64_t xe = X - 1, ye = runy;
    emit_rows(k, cx, cy, runy, run0, xe);
    /* Region 2: q = ry^2 (2x-1)^2 + 4 rx^2 Y^2 - 4 rx^2 ry^2 < 0 keeps x. */
    if (trace) {
        fx_trace(c, "region 2 (from (rx, 0) up to y=%lld; keep x while "
                 "p_k = 4[ry^2(x-1/2)^2 + rx^2y^2 - rx^2ry^2] < 0):",
                 (long long)(ye - 1));
        fx_trace(c, "%-4s %-16s %s", "k", "p_k", "(x_k, y_k)");
    }
    int64_t x = rx, Y = 0, prev = 0;
    q = ry2 * (2 * rx - 1) * (2 * rx - 1) - 4 * rx2 * ry2;
    /* Rows are produced bottom-up, but the join rule needs the row above:
     * remember each row's x and emit it once the next one is known. */
    for (; Y < ye; Y++) {
        int64_t p0 = q;
        while (q >= 0 && x > 0) {
            q += ry2 * (8 - 8 * x);
            x--;
        }
        if (trace && Y <= 1000)
            fx_trace(c, "%-4lld %-16lld (%lld, %lld)", (long long)Y, (long long)p0, (long long)x,
                     (long long)Y);
        if (Y > 0)
            emit_rows(k, cx, cy, Y - 1, prev > x + 1 ? x + 1 : prev, prev);
        prev = x;
        q += 4 * rx2 * (2 * Y + 1);
    }
    if (ye > 0)
        emit_rows(k, cx, cy, ye - 1, prev > xe + 1 ? xe + 1 : prev, prev);
}

static int ellipse_degenerate(const fx_ctx *c, int32_t cx, int32_t cy, int32_t rx, int32_t ry)
{
    if (rx < 0 || ry < 0)
        return 1;
    if (rx && ry)
        return 0;
    conic_sink k;
    conic_sink_init(&k, c);
    if (!ry) {
        conic_span(&k, cy, (int64_t)cx - rx, (int64_t)cx + rx);
        return 1;
    }
    int64_t y0 = FX_MAX((int64_t)cy - ry, (int64_t)c->clip.y0);
    int64_t y1 = FX_MIN((int64_t)cy + ry, (int64_t)c->clip.y1 - 1);
    for (int64_t y = y0; y <= y1; y++)
        conic_span(&k, y, cx, cx);
    return 1;
}

static int visible_rows(const fx_ctx *c, int64_t cx, int64_t cy, int64_t rx, int64_t ry, int64_t *y0,
                        int64_t *y1)
{
    const fx_rect *cl = &c->clip;
    if (fx_rect_empty(*cl) || cx + rx < cl->x0 || cx - rx >= cl->x1 || cy + ry < cl->y0 ||
        cy - ry >= cl->y1)
        return 0;
    *y0 = FX_MAX(cy - ry, (int64_t)cl->y0);
    *y1 = FX_MIN(cy + ry, (int64_t)cl->y1 - 1);
    return 1;
}

void fx_ellipse(const fx_ctx *c, int32_t cx, int32_t cy, int32_t rx, int32_t ry)
{
    if (ellipse_degenerate(c, cx, cy, rx, ry))
        return;
    int64_t y0, y1;
    int vis = visible_rows(c, cx, cy, rx, ry, &y0, &y1);
    if (!vis && !c->trace)
        return;
    conic_sink k;
    conic_sink_init(&k, c);
    const fx_rect *cl = &c->clip;
    int inside = vis && (int64_t)cx - rx >= cl->x0 && (int64_t)cx + rx < cl->x1 &&
                 (int64_t)cy - ry >= cl->y0 && (int64_t)cy + ry < cl->y1;
    int small = rx <= (1 << 14) && ry <= (1 << 14);
    if (small && (inside || c->trace)) {
        /* Tracing walks the whole curve; spans outside the clip are dropped. */
        ellipse_walk(&k, cx, cy, rx, ry, c->trace != 0);
        return;
    }
    if (!vis)
        return;
    ell e;
    ell_init(&e, rx, ry);
    for (int64_t y = y0; y <= y1; y++) {
        int64_t x0, x1, Y = y >= cy ? y - cy : cy - y;
        row_run(&e, Y, &x0, &x1);
        emit(&k, cx, y, x0, x1);
    }
}

void fx_fill_ellipse(const fx_ctx *c, int32_t cx, int32_t cy, int32_t rx, int32_t ry)
{
    if (ellipse_degenerate(c, cx, cy, rx, ry))
        return;
    int64_t y0, y1;
    if (!visible_rows(c, cx, cy, rx, ry, &y0, &y1))
        return;
    conic_sink k;
    conic_sink_init(&k, c);
    uint64_t rx2 = (uint64_t)rx * (uint64_t)rx, ry2 = (uint64_t)ry * (uint64_t)ry;
    for (int64_t y = y0; y <= y1; y++) {
        uint64_t Y = (uint64_t)(y >= cy ? y - cy : cy - y);
        /* ry^2 x^2 <= rx^2 (ry^2 - Y^2)  <=>  x^2 <= floor(rx^2 (ry^2 - Y^2) / ry^2) */
        int64_t w = fx_isqrt64(div_u128(u128_mul(rx2, ry2 - Y * Y), ry2));
        conic_span(&k, y, (int64_t)cx - w, (int64_t)cx + w);
    }
}
