/* SPDX-License-Identifier: MIT */
/* fixel — midpoint circle, disc, arc, pie slice and antialiased circle.
 *
 * Everything visible-bounded: a primitive first rejects by bounding box,
 * then works out which part of each octant (or which rows) fall inside the
 * clip rectangle directly from the closed forms in circle.h, and only walks
 * those. Offsets from the centre are kept in 64 bits (an int32 centre plus
 * an int32 radius leaves int32). */
#include "fixel/circle.h"
#include "conic_internal.h"

uint32_t fx_circle_octant_a(uint32_t r, uint32_t b)
{
    uint64_t n = (uint64_t)r * r - (uint64_t)b * b;
    uint64_t s = fx_isqrt64(n);
    /* a(a-1) < n: s always qualifies (s^2 <= n), s+1 when n > s^2 + s. */
    return (uint32_t)(s + (n - s * s > s));
}

uint32_t fx_circle_octant_end(uint32_t r)
{
    /* b <= a(b)  <=>  b(b-1) < r^2 - b^2  <=>  b(2b-1) < r^2. */
    uint64_t r2 = (uint64_t)r * r, b = fx_isqrt64(r2 / 2);
    while ((b + 1) * (2 * b + 1) < r2)
        b++;
    while (b && b * (2 * b - 1) >= r2)
        b--;
    return (uint32_t)b;
}

static uint64_t ceil_sqrt(uint64_t n)
{
    uint64_t s = fx_isqrt64(n);
    return s * s == n ? s : s + 1;
}

/* ---- angular sectors ---- */

typedef struct sector {
    int64_t sx, sy, ex, ey; /* start and end directions, Q2.29 */
    int big;                /* sweep over half a turn: union of half-planes */
} sector;

static void sector_init(sector *s, fx_angle a0, fx_angle a1)
{
    /* Q2.29 keeps cross products of 33-bit offsets below 2^62. Halved
     * towards zero, not by >> 1 (towards -inf), so that a direction and its
     * mirror images stay mirror images: with >> 1 the rays at 135 and 315
     * degrees missed the diagonal they should run along by 2^-30 and took or
     * left the pixel centres on it unlike the rays at 45 and 225. */
    s->sx = fx_cos30(a0) / 2;
    s->sy = fx_sin30(a0) / 2;
    s->ex = fx_cos30(a1) / 2;
    s->ey = fx_sin30(a1) / 2;
    s->big = (uint32_t)(a1 - a0) > FX_ANGLE_180;
}

/* (px, py) is the pixel's offset in the context's own frame; the sector
 * turns from +x towards +y of that frame (circle.h). */
static int in_sector(const sector *s, int64_t px, int64_t py)
{
    int64_t cs = s->sx * py - s->sy * px, ce = s->ex * py - s->ey * px;
    return s->big ? (cs >= 0 || ce <= 0) : (cs >= 0 && ce <= 0);
}

/* ---- the outline ---- */

static void trace_circle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r)
{
    /* The notes start from p0 = 5/4 - r; with an integer r every later
     * p_k differs from it by an integer, so rounding it to 1 - r changes
     * no sign test and hence no pixel: the trace says so, and prints the
     * notes' 2x and 2y columns (the increments are built from them). */
    fx_trace(c, "midpoint circle centre (%d,%d) r=%d: p0=1-r=%lld (the notes' 5/4-r rounded: r is an integer, "
             "so the signs of p_k and every pixel are the same); p<0: x+=1, p+=2x+1; "
             "else x+=1, y-=1, p+=2x+1-2y (points relative to the centre)",
             cx, cy, r, 1 - (long long)r);
    fx_trace(c, "%-4s %-12s %-18s %-10s %s", "k", "p_k", "(x_k+1, y_k+1)", "2x_k+1", "2y_k+1");
    int64_t x = 0, y = r, p = 1 - (int64_t)r;
    for (int k = 0; x < y; k++) {
        if (k == 1000) {
            fx_trace(c, "... (table cut at 1000 rows)");
            break;
        }
        int64_t pk = p;
        x++;
        if (p < 0) {
            p += 2 * x + 1;
        } else {
            y--;
            p += 2 * x + 1 - 2 * y;
        }
        char pt[48];
        fx_fmt(pt, sizeof pt, "(%lld, %lld)", (long long)x, (long long)y);
        fx_trace(c, "%-4d %-12lld %-18s %-10lld %lld", k, (long long)pk, pt, 2 * (long long)x, 2 * (long long)y);
    }
}

/* The clip rectangle in an octant's own coordinates: offsets b along its
 * walking axis in [*lo, *hi] and a across it in [*a0, *a1], before the
 * octant's own limits are applied (a >= 0 is the only one they share).
 * b = 0 is left to the positive side. */
static void octant_window(const fx_rect *cl, int64_t cx, int64_t cy, int swap, int sx, int sy,
                          int64_t *lo, int64_t *hi, int64_t *a0, int64_t *a1)
{
    int64_t bc = swap ? cx : cy, ac = swap ? cy : cx;
    int bs = swap ? sx : sy, as = swap ? sy : sx;
    int64_t bmin_c = swap ? cl->x0 : cl->y0, bmax_c = (int64_t)(swap ? cl->x1 : cl->y1) - 1;
    int64_t amin_c = swap ? cl->y0 : cl->x0, amax_c = (int64_t)(swap ? cl->y1 : cl->x1) - 1;
    *lo = FX_MAX(bs > 0 ? bmin_c - bc : bc - bmax_c, bs < 0 ? 1 : 0);
    *hi = bs > 0 ? bmax_c - bc : bc - bmin_c;
    *a0 = FX_MAX(as > 0 ? amin_c - ac : ac - amax_c, 0);
    *a1 = as > 0 ? amax_c - ac : ac - amin_c;
}

/* One octant: the points (cx + sx*a(b), cy + sy*b) (swap = 0) or
 * (cx + sx*b, cy + sy*a(b)) (swap = 1) for b in [0, bmax], restricted to
 * the clip rectangle before walking. The seams are split so each pixel is
 * written once: b = 0 belongs to the positive side of the b axis, the
 * diagonal point a == b to the swap = 0 octants. */
static void octant(const conic_sink *k, int64_t cx, int64_t cy, uint32_t r, uint32_t bmax, int swap,
                   int sx, int sy, const sector *sec)
{
    int64_t lo, hi, A0, A1;
    octant_window(&k->c->clip, cx, cy, swap, sx, sy, &lo, &hi, &A0, &A1);
    hi = FX_MIN(hi, (int64_t)bmax);
    A1 = FX_MIN(A1, (int64_t)r);
    if (lo > hi || A0 > A1)
        return;
    /* a(b) is non-increasing, so each bound on a is a bound on b:
     * a(b) <= A1 <=> b^2 >= r^2 - A1(A1+1);  a(b) >= A0 <=> b^2 < r^2 - A0(A0-1). */
    uint64_t r2 = (uint64_t)r * r, t = (uint64_t)A1 * (uint64_t)(A1 + 1);
    if (t < r2)
        lo = FX_MAX(lo, (int64_t)ceil_sqrt(r2 - t));
    if (A0 > 0) {
        t = (uint64_t)A0 * (uint64_t)(A0 - 1);
        if (t >= r2)
            return;
        hi = FX_MIN(hi, (int64_t)ceil_sqrt(r2 - t) - 1);
    }
    if (lo > hi)
        return;
    int64_t b = lo, a = fx_circle_octant_a(r, (uint32_t)b);
    /* The W5 decision variable at (a, b): (b+1)^2 + a(a-1) - r^2 (each term < 2^63). */
    int64_t d = (int64_t)((uint64_t)(b + 1) * (uint64_t)(b + 1) + (uint64_t)a * (uint64_t)(a - 1)) -
                (int64_t)r2;
    for (;;) {
        if (!swap || a != b) {
            int64_t ox = swap ? sx * b : sx * a, oy = swap ? sy * a : sy * b;
            if (!sec || in_sector(sec, ox, oy))
                conic_put(k, (int32_t)(cx + ox), (int32_t)(cy + oy));
        }
        if (b == hi)
            break;
        b++;
        if (d < 0) {
            d += 2 * b + 1;
        } else {
            a--;
            d += 2 * (b - a) + 1;
        }
    }
}

/* Whole circle inside the clip, plain stores: the W5 loop itself with eight
 * pointer writes per step (seam pixels are stored twice; same value). */
static void circle_fast(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, unsigned bytes)
{
    ptrdiff_t st = c->surf.stride, bx = (ptrdiff_t)bytes;
    uint8_t *C = fx_row(&c->surf, cy) + (ptrdiff_t)cx * bx;
    int64_t a = r, b = 0, d = 1 - (int64_t)r;
    uint32_t v = c->native;
#define FX_PUT8(T)                                                                        \
    while (b <= a) {                                                                      \
        ptrdiff_t ax = (ptrdiff_t)a * bx, bxx = (ptrdiff_t)b * bx;                        \
        ptrdiff_t ay = (ptrdiff_t)a * st, by = (ptrdiff_t)b * st;                         \
        *(T *)(void *)(C + ax + by) = (T)v;                                               \
        *(T *)(void *)(C - ax + by) = (T)v;                                               \
        *(T *)(void *)(C + ax - by) = (T)v;                                               \
        *(T *)(void *)(C - ax - by) = (T)v;                                               \
        *(T *)(void *)(C + bxx + ay) = (T)v;                                              \
        *(T *)(void *)(C - bxx + ay) = (T)v;                                              \
        *(T *)(void *)(C + bxx - ay) = (T)v;                                              \
        *(T *)(void *)(C - bxx - ay) = (T)v;                                              \
        b++;                                                                              \
        if (d < 0) {                                                                      \
            d += 2 * b + 1;                                                               \
        } else {                                                                          \
            a--;                                                                          \
            d += 2 * (b - a) + 1;                                                         \
        }                                                                                 \
    }
    if (bytes == 4)
        FX_PUT8(uint32_t)
    else if (bytes == 2)
        FX_PUT8(uint16_t)
    else
        FX_PUT8(uint8_t)
#undef FX_PUT8
}

/* 0: the square [cx-r, cx+r]^2 misses the clip; 1: it touches it;
 * 2: it lies inside. */
static int bbox_test(const fx_ctx *c, int64_t cx, int64_t cy, int64_t rx, int64_t ry)
{
    const fx_rect *cl = &c->clip;
    if (fx_rect_empty(*cl) || cx + rx < cl->x0 || cx - rx >= cl->x1 || cy + ry < cl->y0 ||
        cy - ry >= cl->y1)
        return 0;
    return (cx - rx >= cl->x0 && cx + rx < cl->x1 && cy - ry >= cl->y0 && cy + ry < cl->y1) ? 2
                                                                                            : 1;
}

static void circle_pixels(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, const sector *sec)
{
    if (r < 0)
        return;
    int box = bbox_test(c, cx, cy, r, r);
    if (!box)
        return;
    if (r == 0) {
        fx_plot(c, cx, cy);
        return;
    }
    conic_sink k;
    conic_sink_init(&k, c);
    if (box == 2 && !sec && !k.mode && k.bytes) {
        circle_fast(c, cx, cy, r, k.bytes);
        return;
    }
    uint32_t bmax = fx_circle_octant_end((uint32_t)r);
    for (int swap = 0; swap < 2; swap++)
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2)
                octant(&k, cx, cy, (uint32_t)r, bmax, swap, sx, sy, sec);
}

void fx_circle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r)
{
    if (c->trace && r >= 0)
        trace_circle(c, cx, cy, r);
    circle_pixels(c, cx, cy, r, 0);
}

/* draw() on the sector from a0 to a1; equal angles mean the whole turn. */
static inline void draw_sector(void (*draw)(const fx_ctx *, int32_t, int32_t, int32_t, const sector *),
                               const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, fx_angle a0,
                               fx_angle a1)
{
    if (a0 == a1) {
        draw(c, cx, cy, r, 0);
        return;
    }
    sector s;
    sector_init(&s, a0, a1);
    draw(c, cx, cy, r, &s);
}

void fx_arc(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, fx_angle a0, fx_angle a1)
{
    draw_sector(circle_pixels, c, cx, cy, r, a0, a1);
}

/* ---- discs and pie slices ---- */

/* The half-width w = floor(sqrt(n)) of the next row from the previous one:
 * neighbouring rows differ by a step or two except near the poles of huge
 * discs, where one isqrt is cheaper than walking. */
static uint32_t half_width(uint64_t n, uint32_t w)
{
    for (int i = 0; i < 8; i++) {
        if ((uint64_t)(w + 1) * (w + 1) <= n)
            w++;
        else if ((uint64_t)w * w > n)
            w--;
        else
            return w;
    }
    return fx_isqrt64(n);
}

typedef struct span {
    int64_t lo, hi;
} span;

static span sp_and(span a, span b)
{
    span r = {FX_MAX(a.lo, b.lo), FX_MIN(a.hi, b.hi)};
    return r;
}

/* The px (py = dy, the context's frame) with cross(s, p) >= 0, and those with
 * cross(e, p) <= 0, as intervals on one row. */
static span half_start(const sector *s, int64_t py)
{
    span all = {INT64_MIN, INT64_MAX}, none = {1, 0};
    if (s->sy > 0)
        return (span){INT64_MIN, conic_floor_div(s->sx * py, s->sy)};
    if (s->sy < 0)
        return (span){conic_ceil_div(s->sx * py, s->sy), INT64_MAX};
    return s->sx * py >= 0 ? all : none;
}

static span half_end(const sector *s, int64_t py)
{
    span all = {INT64_MIN, INT64_MAX}, none = {1, 0};
    if (s->ey > 0)
        return (span){conic_ceil_div(s->ex * py, s->ey), INT64_MAX};
    if (s->ey < 0)
        return (span){INT64_MIN, conic_floor_div(s->ex * py, s->ey)};
    return s->ex * py <= 0 ? all : none;
}

static void disc_rows(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, const sector *sec)
{
    if (r < 0 || !bbox_test(c, cx, cy, r, r))
        return;
    conic_sink k;
    conic_sink_init(&k, c);
    int64_t y0 = FX_MAX((int64_t)cy - r, (int64_t)c->clip.y0);
    int64_t y1 = FX_MIN((int64_t)cy + r, (int64_t)c->clip.y1 - 1);
    uint64_t r2 = (uint64_t)r * (uint64_t)r;
    int64_t dy0 = y0 - cy;
    uint32_t w = fx_isqrt64(r2 - (uint64_t)(dy0 * dy0));
    for (int64_t y = y0; y <= y1; y++) {
        int64_t dy = y - cy;
        w = half_width(r2 - (uint64_t)(dy * dy), w);
        span d = {-(int64_t)w, w};
        if (!sec) {
            conic_span(&k, y, cx + d.lo, cx + d.hi);
            continue;
        }
        span h1 = sp_and(d, half_start(sec, dy)), h2 = sp_and(d, half_end(sec, dy));
        if (!sec->big) {
            span s = sp_and(h1, h2);
            if (s.lo <= s.hi)
                conic_span(&k, y, cx + s.lo, cx + s.hi);
            continue;
        }
        /* Union of two intervals, each pixel once. */
        int e1 = h1.lo > h1.hi, e2 = h2.lo > h2.hi;
        if (!e1 && !e2 && h2.lo <= h1.hi + 1 && h1.lo <= h2.hi + 1) {
            h1.lo = FX_MIN(h1.lo, h2.lo);
            h1.hi = FX_MAX(h1.hi, h2.hi);
            e2 = 1;
        }
        if (!e1)
            conic_span(&k, y, cx + h1.lo, cx + h1.hi);
        if (!e2)
            conic_span(&k, y, cx + h2.lo, cx + h2.hi);
    }
}

void fx_disc(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r) { disc_rows(c, cx, cy, r, 0); }

void fx_pie(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, fx_angle a0, fx_angle a1)
{
    draw_sector(disc_rows, c, cx, cy, r, a0, a1);
}

/* ---- antialiased circle ---- */

/* floor(256 * sqrt(n)): exact below 2^47; above, the remainder is spread
 * linearly over the gap to the next square (error < 2^-16 pixel there). */
static uint64_t sqrt256(uint64_t n)
{
    if (n < ((uint64_t)1 << 47))
        return fx_isqrt64(n << 16);
    uint64_t s = fx_isqrt64(n), rem = n - s * s;
    return (s << 8) + (rem << 8) / (2 * s + 1);
}

static void aa_put(const fx_ctx *c, int64_t x, int64_t y, uint32_t cov)
{
    const fx_rect *cl = &c->clip;
    if (!cov || x < cl->x0 || x >= cl->x1 || y < cl->y0 || y >= cl->y1)
        return;
    if (c->exterior && x >= c->exterior_rect.x0 && x < c->exterior_rect.x1 &&
        y >= c->exterior_rect.y0 && y < c->exterior_rect.y1)
        return;
    uint32_t a = ((c->color >> 24) * cov + 127) / 255;
    if (!a)
        return;
    fx_color col = (c->color & 0xFFFFFFu) | (a << 24);
    int32_t xi = (int32_t)x, yi = (int32_t)y;
    fx_surface_put_native(
        &c->surf, xi, yi,
        fx_blend_over(c->surf.format, fx_surface_get_native(&c->surf, xi, yi), col));
}

/* Octant of the AA circle: along b (0..bend) the exact offset s(b) =
 * sqrt(r^2 - b^2) falls between two pixels of the a axis. The swap = 1
 * octants keep only pixels beyond bend on the a axis, so the two halves of
 * each quadrant never blend the same pixel twice. */
static void aa_octant(const fx_ctx *c, int64_t cx, int64_t cy, uint32_t r, uint32_t bend, int swap,
                      int sx, int sy)
{
    int64_t lo, hi, A0, A1;
    octant_window(&c->clip, cx, cy, swap, sx, sy, &lo, &hi, &A0, &A1);
    hi = FX_MIN(hi, (int64_t)bend);
    A1 = FX_MIN(A1, (int64_t)r + 1);
    if (lo > hi || A0 > A1)
        return;
    /* A superset of the b whose pixel pair can touch [A0, A1]; the pixels
     * themselves are clipped in aa_put. */
    uint64_t r2 = (uint64_t)r * r, t = (uint64_t)(A1 + 1) * (uint64_t)(A1 + 1);
    if (t < r2)
        lo = FX_MAX(lo, (int64_t)fx_isqrt64(r2 - t));
    if (A0 > 1) {
        t = (uint64_t)(A0 - 1) * (uint64_t)(A0 - 1);
        if (t > r2)
            return;
        hi = FX_MIN(hi, (int64_t)fx_isqrt64(r2 - t) + 1);
    }
    for (int64_t b = lo; b <= hi; b++) {
        uint64_t s = sqrt256(r2 - (uint64_t)b * (uint64_t)b);
        int64_t i = (int64_t)(s >> 8);
        uint32_t f = (uint32_t)(s & 255);
        for (int j = 0; j < 2; j++) {
            int64_t a = i + j;
            uint32_t cov = j ? f : 255 - f;
            if (swap && a <= (int64_t)bend)
                continue;
            if (swap)
                aa_put(c, cx + sx * b, cy + sy * a, cov);
            else
                aa_put(c, cx + sx * a, cy + sy * b, cov);
        }
    }
}

void fx_aacircle(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r)
{
    if (r < 0 || !bbox_test(c, cx, cy, (int64_t)r + 1, (int64_t)r + 1))
        return;
    if (r == 0) {
        aa_put(c, cx, cy, 255);
        return;
    }
    uint32_t bend = fx_isqrt64((uint64_t)r * (uint64_t)r / 2);
    for (int swap = 0; swap < 2; swap++)
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2)
                aa_octant(c, cx, cy, (uint32_t)r, bend, swap, sx, sy);
}
