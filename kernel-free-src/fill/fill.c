/* SPDX-License-Identifier: MIT */
/* fixel — area fills: the span writer with fill styles and blending, the
 * edge-table polygon filler (even-odd and nonzero), the row filler of
 * clipped Q16.16 pieces (fx_poly_fill16), triangles with exact
 * integer edge stepping, Gouraud shading and the 2D triangle set-up.
 *
 * Every edge walks the exact crossing ceil(xc) with an integer quotient and
 * remainder (Quake's FloorDivMod stepping): per row one add, one subtract and
 * one compare, no division and no drift, so the pixels are exactly those of
 * the rational pixel-centre definition in fill.h (fx_poly_fill16 divides
 * per crossing instead; see fill.h). */
#include "fixel/fill.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"
#include "../base/fx_span.h"
#include "../base/fx_wide.h"
#include "tri_walk.h"

/* ---- span loops ---- */

static inline void run_native(const fx_surface *s, int bpp, int32_t y, int32_t x0, int32_t x1, uint32_t v)
{
    if (bpp == 32)
        fx_run32((uint32_t *)fx_row(s, y) + x0, x1 - x0, v);
    else if (bpp == 16)
        fx_run16((uint16_t *)fx_row(s, y) + x0, x1 - x0, (uint16_t)v);
    else
        fx_span_fill(s, y, x0, x1, v);
}

/* ---- spans with styles and blending ---- */

static void put_color(const fx_ctx *c, int32_t x, int32_t y, fx_color col)
{
    if (c->blend == FX_BLEND_OVER)
        fx_surface_put_native(&c->surf, x, y,
                              fx_blend_over(c->surf.format, fx_surface_get_native(&c->surf, x, y), col));
    else
        fx_surface_put_native(&c->surf, x, y, fx_pack(c->surf.format, col));
}

static void solid_span(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1, fx_color col, uint32_t native)
{
    if (c->blend == FX_BLEND_OVER && (col >> 24) != 255) {
        if ((col >> 24) == 0)
            return;
        for (int32_t x = x0; x < x1; x++)
            fx_surface_put_native(&c->surf, x, y,
                                  fx_blend_over(c->surf.format, fx_surface_get_native(&c->surf, x, y), col));
        return;
    }
    fx_span_fill(&c->surf, y, x0, x1, native);
}

static int32_t mod_pos(int64_t a, int32_t m)
{
    int64_t r = a % m;
    return (int32_t)(r < 0 ? r + m : r);
}

/* [x0, x1) inside the clip and outside the exterior rectangle. */
static void styled_span(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1)
{
    const fx_fill_style *st = c->fill_style;
    if (!st || st->kind == FX_FILL_SOLID || (st->kind == FX_FILL_PATTERN && (!st->bits || st->w < 1 || st->h < 1)) ||
        (st->kind == FX_FILL_SHADER && !st->shade)) {
        solid_span(c, y, x0, x1, c->color, c->native);
        return;
    }
    if (st->kind == FX_FILL_PATTERN) {
        const uint8_t *row = st->bits + (size_t)mod_pos((int64_t)y - st->ay, st->h) * (size_t)st->stride;
        int32_t i = mod_pos((int64_t)x0 - st->ax, st->w);
        int over = c->blend == FX_BLEND_OVER;
        uint32_t nbg = fx_pack(c->surf.format, st->bg);
        for (int32_t x = x0; x < x1; x++) {
            if ((row[i >> 3] >> (7 - (i & 7))) & 1) {
                if (over)
                    put_color(c, x, y, c->color);
                else
                    fx_surface_put_native(&c->surf, x, y, c->native);
            } else if (!st->bg_transparent) {
                if (over)
                    put_color(c, x, y, st->bg);
                else
                    fx_surface_put_native(&c->surf, x, y, nbg);
            }
            if (++i == st->w)
                i = 0;
        }
        return;
    }
    fx_color buf[64];
    for (int32_t x = x0; x < x1;) {
        int32_t n = FX_MIN(x1 - x, (int32_t)FX_ARRAY_LEN(buf));
        st->shade(st->user, y, x, n, buf);
        for (int32_t k = 0; k < n; k++)
            put_color(c, x + k, y, buf[k]);
        x += n;
    }
}

void fx_fill_span(const fx_ctx *c, int32_t y, int32_t x0, int32_t x1)
{
    fx_clip_span(c, y, x0, x1, styled_span);
}

/* Spans already clipped to c->clip: the fast loops when no style, exterior
 * or blending is involved, fx_fill_span otherwise. */
static int plain_solid(const fx_ctx *c)
{
    return !c->exterior && (!c->fill_style || c->fill_style->kind == FX_FILL_SOLID) &&
           (c->blend == FX_BLEND_SRC || (c->color >> 24) == 255);
}

/* ---- general polygons: edge table + active edge list ---- */

static void sort_by_ystart(fx_fill_edge *e, int32_t n)
{
    /* Shell sort: in place, no memory, fast on the small tables of real use. */
    static const int32_t gaps[] = {701, 301, 132, 57, 23, 10, 4, 1};
    for (unsigned g = 0; g < FX_ARRAY_LEN(gaps); g++) {
        int32_t gap = gaps[g];
        for (int32_t i = gap; i < n; i++) {
            fx_fill_edge t = e[i];
            int32_t j = i;
            while (j >= gap && e[j - gap].ystart > t.ystart) {
                e[j] = e[j - gap];
                j -= gap;
            }
            e[j] = t;
        }
    }
}

static void fill_row_spans(const fx_ctx *c, int32_t y, const fx_fill_edge *a, int32_t n,
                           fx_fill_rule rule, int fast)
{
    int bpp = fast ? fx_format_get(c->surf.format)->bits_per_pixel : 0;
    int32_t cx0 = c->clip.x0, cx1 = c->clip.x1;
    if (rule == FX_FILL_EVENODD) {
        for (int32_t i = 0; i + 1 < n; i += 2) {
            int32_t xa = (int32_t)clamp64(a[i].g.x, cx0, cx1), xb = (int32_t)clamp64(a[i + 1].g.x, cx0, cx1);
            if (xa < xb) {
                if (fast)
                    run_native(&c->surf, bpp, y, xa, xb, c->native);
                else
                    fx_fill_span(c, y, xa, xb);
            }
        }
        return;
    }
    int32_t w = 0;
    int64_t xa = 0;
    for (int32_t i = 0; i < n; i++) {
        int32_t was = w;
        w += a[i].dir;
        if (was == 0)
            xa = a[i].g.x;
        else if (w == 0) {
            int32_t x0 = (int32_t)clamp64(xa, cx0, cx1), x1 = (int32_t)clamp64(a[i].g.x, cx0, cx1);
            if (x0 < x1) {
                if (fast)
                    run_native(&c->surf, bpp, y, x0, x1, c->native);
                else
                    fx_fill_span(c, y, x0, x1);
            }
        }
    }
}

/* ---- y-monotone polygons (every convex one): two chains ----
 * When the edges' vertical directions change exactly twice around the
 * polygon, every row meets exactly one edge of each chain from the top
 * vertex to the bottom one, so both rules fill between the two crossings:
 * walked like a triangle, no edge table, no sorting. */
typedef struct {
    const int32_t *xy;
    int32_t n, i, step; /* current edge from vertex i to i + step (mod n) */
    int32_t yend;       /* first row past the current edge */
    fx_tri_edge g;
} chain_t;

static int32_t wrapi(int32_t i, int32_t n) { return i < 0 ? i + n : i >= n ? i - n : i; }

/* Move to the edge covering row y (rows are covered in order) and set it up. */
static void chain_seek(chain_t *ch, int32_t y, unsigned s)
{
    for (;;) {
        int32_t j = wrapi(ch->i + ch->step, ch->n);
        int64_t ay = ch->xy[2 * ch->i + 1], by = ch->xy[2 * j + 1];
        int64_t ye = ceil_shift(by, s);
        if (by > ay && ye > y) {
            edge_setup(&ch->g, ch->xy[2 * ch->i], ay, ch->xy[2 * j], by, s, y);
            ch->yend = (int32_t)FX_MIN(ye, (int64_t)INT32_MAX);
            return;
        }
        ch->i = j;
    }
}

static int monotone_fill(const fx_ctx *c, const int32_t *xy, int32_t n, unsigned s)
{
    int changes = 0, last = 0;
    int32_t top = 0;
    for (int32_t k = 0; k < 2 * n && changes <= 2; k++) { /* twice round: catch the wrap */
        int32_t i = k % n, j = wrapi(i + 1, n);
        int d = xy[2 * j + 1] > xy[2 * i + 1] ? 1 : xy[2 * j + 1] < xy[2 * i + 1] ? -1 : 0;
        if (k < n && xy[2 * i + 1] < xy[2 * top + 1])
            top = i;
        if (d && last && d != last && k >= n)
            changes++;
        if (d)
            last = d;
    }
    if (changes != 2)
        return 0;
    int32_t bot = 0;
    for (int32_t i = 1; i < n; i++)
        if (xy[2 * i + 1] > xy[2 * bot + 1])
            bot = i;
    int64_t y0 = ceil_shift(xy[2 * top + 1], s), y1 = ceil_shift(xy[2 * bot + 1], s);
    if (y0 < c->clip.y0)
        y0 = c->clip.y0;
    if (y1 > c->clip.y1)
        y1 = c->clip.y1;
    if (y0 >= y1)
        return 1;
    chain_t a = {xy, n, top, 1, 0, {0, 0, 0, 0, 0}}, b = {xy, n, top, -1, 0, {0, 0, 0, 0, 0}};
    chain_seek(&a, (int32_t)y0, s);
    chain_seek(&b, (int32_t)y0, s);
    int fast = plain_solid(c);
    int bpp = fast ? fx_format_get(c->surf.format)->bits_per_pixel : 0;
    int32_t cx0 = c->clip.x0, cx1 = c->clip.x1;
    for (int32_t y = (int32_t)y0; y < y1; y++) {
        if (y >= a.yend)
            chain_seek(&a, y, s);
        if (y >= b.yend)
            chain_seek(&b, y, s);
        int64_t lo = FX_MIN(a.g.x, b.g.x), hi = FX_MAX(a.g.x, b.g.x);
        int32_t xa = (int32_t)clamp64(lo, cx0, cx1), xb = (int32_t)clamp64(hi, cx0, cx1);
        if (xa < xb) {
            if (bpp == 32)
                fx_run32((uint32_t *)fx_row(&c->surf, y) + xa, xb - xa, c->native);
            else if (bpp == 16)
                fx_run16((uint16_t *)fx_row(&c->surf, y) + xa, xb - xa, (uint16_t)c->native);
            else if (fast)
                fx_span_fill(&c->surf, y, xa, xb, c->native);
            else
                fx_fill_span(c, y, xa, xb);
        }
        edge_step(&a.g);
        edge_step(&b.g);
    }
    return 1;
}

/* ---- small polygons: 32-bit edges, rows in bands ----
 * The common polygon has a handful of edges a few hundred pixels long. Its
 * edges are stepped as 32-bit records (five values, no yend test per row),
 * and the rows are taken in bands between the rows where an edge starts or
 * ends, so the active list changes only at band ends; within a band only a
 * crossing of two edges reorders it, which the stepping pass catches by
 * comparing neighbours. Same walkers as the edge table, so same pixels. */
#define SMALL_EDGES 16
#define SMALL_XLIM ((int64_t)1 << 28) /* |vertex x|: x + qs + 1 fits int32 */
#define SMALL_DLIM ((int64_t)1 << 30) /* dy << s: e - rs and e + d fit */

typedef struct {
    int32_t x, e, d, rs, qs, yend, dir, pad_;
} small_edge;

/* a[0, k) sorted by x: move a[k] down to its place (insertion sort's step). */
static inline void small_sink(small_edge *a, int32_t k)
{
    small_edge t = a[k];
    int32_t j = k;
    while (j > 0 && a[j - 1].x > t.x) {
        a[j] = a[j - 1];
        j--;
    }
    a[j] = t;
}

/* Solid runs for the band loops, p aligned to its pixel. A polygon's runs
 * are of every length, mostly short, so each length class is one straight
 * sequence of overlapping stores (8-byte ones for fewer than L pixels) and
 * long runs take an aligned loop of four stores between two overlapping
 * pairs at each end: a single loop exit per run. fx_run32's byte loop,
 * second loop and length tests mispredicted often here. */
#define SMALL_RUN(NAME, T, V, L)                                                                   \
    static inline void NAME(T *p, int32_t n, T v)                                                  \
    {                                                                                              \
        V q = (V){0} + v; /* broadcast here: aarch64 cannot pass vectors without SIMD */           \
        if (n < 2 * L) {                                                                           \
            if (n >= L) {                                                                          \
                fx_memcpy(p, &q, 16);                                                              \
                fx_memcpy(p + n - L, &q, 16);                                                      \
            } else if (n >= L / 2) {                                                               \
                fx_memcpy(p, &q, 8);                                                               \
                fx_memcpy(p + n - L / 2, &q, 8);                                                   \
            } else {                                                                               \
                p[0] = v;                                                                          \
                p[n >> 1] = v;                                                                     \
                p[n - 1] = v;                                                                      \
            }                                                                                      \
            return;                                                                                \
        }                                                                                          \
        T *e = p + n - 2 * L;                                                                      \
        fx_memcpy(p, &q, 16);                                                                      \
        fx_memcpy(p + L, &q, 16);                                                                  \
        if (n > 4 * L) {                                                                           \
            T *a = (T *)(((uintptr_t)p + 32) & ~(uintptr_t)15), *f = e - 2 * L;                    \
            for (; a < f; a += 4 * L) {                                                            \
                *(V *)(void *)a = q;                                                               \
                *(V *)(void *)(a + L) = q;                                                         \
                *(V *)(void *)(a + 2 * L) = q;                                                     \
                *(V *)(void *)(a + 3 * L) = q;                                                     \
            }                                                                                      \
            fx_memcpy(e - 2 * L, &q, 16);                                                          \
            fx_memcpy(e - L, &q, 16);                                                              \
        }                                                                                          \
        fx_memcpy(e, &q, 16);                                                                      \
        fx_memcpy(e + L, &q, 16);                                                                  \
    }
SMALL_RUN(small_run32, uint32_t, fx_v4u32, 4)
SMALL_RUN(small_run16, uint16_t, fx_v8u16, 8)

/* Rows [y, yb) with the active edges a[0, m) fixed and sorted by x. The
 * constant arguments of the callers below select the loops at compile time:
 * bpp 32 or 16 with clampx == 0 is the W7-style polygon inside the clip. */
static inline __attribute__((always_inline)) void small_band(const fx_ctx *c, small_edge *a, int32_t m,
                                                             int32_t y, int32_t yb, int evenodd, int bpp,
                                                             int clampx, int fast)
{
    const fx_surface *sf = &c->surf;
    int32_t cx0 = c->clip.x0, cx1 = c->clip.x1;
    uint32_t v = c->native;
    uint16_t v16 = (uint16_t)v;
    uint8_t *row = bpp ? fx_row(sf, y) : 0;
    for (; y < yb; y++) {
        int32_t w = 0, xs = 0;
        for (int32_t i = 0; i < m; i++) {
            int32_t xa, xb;
            if (evenodd) {
                if (i + 1 >= m)
                    break;
                xa = a[i].x;
                xb = a[++i].x;
            } else {
                int32_t was = w;
                w += a[i].dir;
                if (was == 0)
                    xs = a[i].x;
                if (was == 0 || w != 0)
                    continue;
                xa = xs;
                xb = a[i].x;
            }
            if (clampx) {
                xa = xa < cx0 ? cx0 : xa > cx1 ? cx1 : xa;
                xb = xb < cx0 ? cx0 : xb > cx1 ? cx1 : xb;
            }
            if (xa < xb) {
                if (bpp == 32)
                    small_run32((uint32_t *)row + xa, xb - xa, v);
                else if (bpp == 16)
                    small_run16((uint16_t *)row + xa, xb - xa, v16);
                else if (fast)
                    fx_span_fill(sf, y, xa, xb, v);
                else
                    fx_fill_span(c, y, xa, xb);
            }
        }
        if (bpp)
            row += sf->stride;
        /* step as edge_step, keeping a[0, k] sorted as we go */
        for (int32_t k = 0; k < m; k++) {
            int32_t e = a[k].e - a[k].rs, msk = -(int32_t)(e < 0);
            a[k].e = e + (a[k].d & msk);
            a[k].x += a[k].qs - msk;
            if (k > 0 && a[k - 1].x > a[k].x)
                small_sink(a, k);
        }
    }
}

/* Bands of two or four edges, the usual case, keep the walkers in
 * registers in fixed slots: each row sorts a copy of the crossings with a
 * min/max network instead of reordering the records, so the loop has no
 * branch but the runs'. Inside the clip, 32- or 16-bit pixels; four edges
 * for even-odd, two for both rules (closed contours cross every row up as
 * often as down, so two crossings always wind +1 and -1). */
#define SMALL_STEP(x, e, d, r, q)                                                                  \
    do {                                                                                           \
        int32_t t_ = (e) - (r), m_ = -(int32_t)(t_ < 0);                                           \
        (e) = t_ + ((d) & m_);                                                                     \
        (x) += (q) - m_;                                                                           \
    } while (0)
#define SMALL_SORT2(a, b)                                                                          \
    do {                                                                                           \
        int32_t lo_ = (a) < (b) ? (a) : (b), hi_ = (a) < (b) ? (b) : (a);                          \
        (a) = lo_;                                                                                 \
        (b) = hi_;                                                                                 \
    } while (0)

static inline __attribute__((always_inline)) void small_band24(const fx_ctx *c, small_edge *a, int32_t m,
                                                               int32_t y, int32_t yb, int bpp)
{
    const fx_surface *sf = &c->surf;
    uint32_t v = c->native;
    uint16_t v16 = (uint16_t)v;
    uint8_t *row = fx_row(sf, y);
    ptrdiff_t stride = sf->stride;
    int32_t x0 = a[0].x, e0 = a[0].e, x1 = a[1].x, e1 = a[1].e;
    const int32_t d0 = a[0].d, r0 = a[0].rs, q0 = a[0].qs, d1 = a[1].d, r1 = a[1].rs, q1 = a[1].qs;
    if (m == 2) {
        for (; y < yb; y++, row += stride) {
            int32_t s0 = x0, s1 = x1;
            SMALL_SORT2(s0, s1);
            if (s0 < s1) {
                if (bpp == 32)
                    small_run32((uint32_t *)row + s0, s1 - s0, v);
                else
                    small_run16((uint16_t *)row + s0, s1 - s0, v16);
            }
            SMALL_STEP(x0, e0, d0, r0, q0);
            SMALL_STEP(x1, e1, d1, r1, q1);
        }
    } else {
        int32_t x2 = a[2].x, e2 = a[2].e, x3 = a[3].x, e3 = a[3].e;
        const int32_t d2 = a[2].d, r2 = a[2].rs, q2 = a[2].qs, d3 = a[3].d, r3 = a[3].rs, q3 = a[3].qs;
        for (; y < yb; y++, row += stride) {
            int32_t s0 = x0, s1 = x1, s2 = x2, s3 = x3;
            SMALL_SORT2(s0, s1);
            SMALL_SORT2(s2, s3);
            SMALL_SORT2(s0, s2);
            SMALL_SORT2(s1, s3);
            SMALL_SORT2(s1, s2);
            if (bpp == 32) {
                if (s0 < s1)
                    small_run32((uint32_t *)row + s0, s1 - s0, v);
                if (s2 < s3)
                    small_run32((uint32_t *)row + s2, s3 - s2, v);
            } else {
                if (s0 < s1)
                    small_run16((uint16_t *)row + s0, s1 - s0, v16);
                if (s2 < s3)
                    small_run16((uint16_t *)row + s2, s3 - s2, v16);
            }
            SMALL_STEP(x0, e0, d0, r0, q0);
            SMALL_STEP(x1, e1, d1, r1, q1);
            SMALL_STEP(x2, e2, d2, r2, q2);
            SMALL_STEP(x3, e3, d3, r3, q3);
        }
        a[2].x = x2, a[2].e = e2, a[3].x = x3, a[3].e = e3;
    }
    a[0].x = x0, a[0].e = e0, a[1].x = x1, a[1].e = e1;
    /* back in x order for the band's end */
    for (int32_t k = 1; k < m; k++)
        small_sink(a, k);
}

/* edges[0, n): sorted by ystart, every value within the SMALL_ limits. */
static void small_fill(const fx_ctx *c, const fx_fill_edge *edges, int32_t n, fx_fill_rule rule, int clampx)
{
    small_edge a[SMALL_EDGES];
    int fast = plain_solid(c);
    int bpp = fast ? fx_format_get(c->surf.format)->bits_per_pixel : 0;
    /* the runs need pixel-aligned rows; others take fx_span_fill */
    if ((bpp == 32 || bpp == 16) && (((uintptr_t)c->surf.pixels | (uintptr_t)c->surf.stride) & (unsigned)(bpp / 8 - 1)))
        bpp = 0;
    int evenodd = rule == FX_FILL_EVENODD;
    int32_t m = 0, pend = 0, y = edges[0].ystart;
    while (m > 0 || pend < n) {
        if (m == 0 && edges[pend].ystart > y)
            y = edges[pend].ystart;
        for (; pend < n && edges[pend].ystart == y; pend++) {
            const fx_fill_edge *f = &edges[pend];
            small_edge t = {(int32_t)f->g.x, (int32_t)f->g.e, (int32_t)f->g.d, (int32_t)f->g.rs,
                            (int32_t)f->g.qs, f->yend, f->dir, 0};
            int32_t j = m++;
            while (j > 0 && a[j - 1].x > t.x) {
                a[j] = a[j - 1];
                j--;
            }
            a[j] = t;
        }
        int32_t yb = pend < n ? edges[pend].ystart : INT32_MAX;
        for (int32_t k = 0; k < m; k++)
            yb = FX_MIN(yb, a[k].yend);
        if (!clampx && (bpp == 32 || bpp == 16) && (m == 2 || (m == 4 && evenodd))) {
            if (bpp == 32)
                small_band24(c, a, m, y, yb, 32);
            else
                small_band24(c, a, m, y, yb, 16);
        } else if (evenodd && !clampx && bpp == 32)
            small_band(c, a, m, y, yb, 1, 32, 0, 1);
        else if (evenodd && !clampx && bpp == 16)
            small_band(c, a, m, y, yb, 1, 16, 0, 1);
        else if (!evenodd && !clampx && bpp == 32)
            small_band(c, a, m, y, yb, 0, 32, 0, 1);
        else if (!evenodd && !clampx && bpp == 16)
            small_band(c, a, m, y, yb, 0, 16, 0, 1);
        else if (bpp == 32 || bpp == 16)
            small_band(c, a, m, y, yb, evenodd, bpp, 1, 1);
        else
            small_band(c, a, m, y, yb, evenodd, 0, 1, fast);
        y = yb;
        int32_t k = 0;
        for (int32_t i = 0; i < m; i++)
            if (a[i].yend > y)
                a[k++] = a[i];
        m = k;
    }
}

int fx_fill_path(const fx_ctx *c, const int32_t *xy, const int32_t *counts, int32_t ncontours,
                 unsigned frac_bits, fx_fill_rule rule, fx_fill_edge *edges, int32_t max_edges)
{
    if (ncontours < 0 || (ncontours > 0 && (!counts || !xy)) || (frac_bits != 0 && frac_bits != 8) ||
        max_edges < 0 || (max_edges > 0 && !edges))
        return -FX_EINVAL;
    /* 2 * count indexes the coordinates: a count past INT32_MAX / 2 (no
     * array that large can exist) overflowed before any other check. */
    for (int32_t k = 0; k < ncontours; k++)
        if (counts[k] < 0 || counts[k] > INT32_MAX / 2)
            return -FX_EINVAL;
    fx_rect clip = c->clip;
    if (fx_rect_empty(clip))
        return 0;
    unsigned s = frac_bits;
    if (ncontours == 1 && counts[0] >= 4 && monotone_fill(c, xy, counts[0], s))
        return 0;
    int32_t n = 0;
    int small = 1;
    int64_t xmin = INT64_MAX, xmax = INT64_MIN;
    const int32_t *p = xy;
    for (int32_t k = 0; k < ncontours; k++) {
        int32_t cnt = counts[k];
        if (cnt < 0)
            return -FX_EINVAL;
        for (int32_t i = 0; i < cnt; i++) {
            int32_t j = i + 1 == cnt ? 0 : i + 1;
            int64_t ax = p[2 * i], ay = p[2 * i + 1], bx = p[2 * j], by = p[2 * j + 1];
            if (ay == by)
                continue;
            int32_t dir = 1;
            if (ay > by) {
                int64_t tx = ax, ty = ay;
                ax = bx, ay = by, bx = tx, by = ty;
                dir = -1;
            }
            int64_t ys = ceil_shift(ay, s), ye = ceil_shift(by, s);
            if (ys < clip.y0)
                ys = clip.y0;
            if (ye > clip.y1)
                ye = clip.y1;
            if (ys >= ye)
                continue;
            if (n >= max_edges)
                return -FX_E2BIG;
            fx_fill_edge *e = &edges[n++];
            edge_setup(&e->g, ax, ay, bx, by, s, ys);
            e->ystart = (int32_t)ys;
            e->yend = (int32_t)ye;
            e->dir = dir;
            e->pad_ = 0;
            small &= ax > -SMALL_XLIM && ax < SMALL_XLIM && bx > -SMALL_XLIM && bx < SMALL_XLIM &&
                     ((by - ay) << s) < SMALL_DLIM;
            xmin = FX_MIN(xmin, FX_MIN(ax, bx));
            xmax = FX_MAX(xmax, FX_MAX(ax, bx));
        }
        p += 2 * cnt;
    }
    if (n == 0)
        return 0;
    sort_by_ystart(edges, n);
    if (small && n <= SMALL_EDGES) {
        /* every crossing pixel lies between those of the extreme vertices */
        small_fill(c, edges, n, rule, ceil_shift(xmin, s) < clip.x0 || ceil_shift(xmax, s) > clip.x1);
        return 0;
    }
    int fast = plain_solid(c);
    int fast32 = fast && rule == FX_FILL_EVENODD && fx_format_get(c->surf.format)->bits_per_pixel == 32;
    int32_t cx0 = clip.x0, cx1 = clip.x1;
    int32_t nact = 0, pend = 0;
    int32_t y = edges[0].ystart;
    /* edges[0, nact): active, sorted by x; edges[pend, n): waiting, sorted
     * by first row; the slots between are free. */
    while (nact > 0 || pend < n) {
        if (nact == 0 && edges[pend].ystart > y)
            y = edges[pend].ystart;
        for (; pend < n && edges[pend].ystart == y; pend++) {
            fx_fill_edge t = edges[pend];
            int32_t j = nact++;
            while (j > 0 && edges[j - 1].g.x > t.g.x) {
                edges[j] = edges[j - 1];
                j--;
            }
            edges[j] = t;
        }
        if (fast32) {
            uint32_t *row = (uint32_t *)fx_row(&c->surf, y);
            for (int32_t i = 0; i + 1 < nact; i += 2) {
                int32_t xa = (int32_t)clamp64(edges[i].g.x, cx0, cx1);
                int32_t xb = (int32_t)clamp64(edges[i + 1].g.x, cx0, cx1);
                if (xa < xb)
                    fx_run32(row + xa, xb - xa, c->native);
            }
        } else {
            fill_row_spans(c, y, edges, nact, rule, fast);
        }
        y++;
        /* step, drop finished edges and keep the list sorted in one pass:
         * the order changes only where edges cross, so moves are rare */
        int32_t k = 0;
        for (int32_t i = 0; i < nact; i++) {
            if (edges[i].yend <= y)
                continue;
            edge_step(&edges[i].g);
            if (k > 0 && edges[k - 1].g.x > edges[i].g.x) {
                fx_fill_edge t = edges[i];
                int32_t j = k;
                while (j > 0 && edges[j - 1].g.x > t.g.x) {
                    edges[j] = edges[j - 1];
                    j--;
                }
                edges[j] = t;
            } else if (k != i) {
                edges[k] = edges[i];
            }
            k++;
        }
        nact = k;
    }
    return 0;
}

/* ---- Q16.16 pieces (the clipped and transformed polygons) ----
 * Row by row, every edge's crossing by one exact 128-bit division: no edge
 * table, so any number of vertices up to FX_POLY_FILL_MAX fits in a 4 KB
 * crossing buffer (see fill.h for why it is not fx_fill_path). */

int fx_poly_fill16(const fx_ctx *c, const fx_pt16 *pts, const int *starts, int npieces)
{
    int total = npieces > 0 ? starts[npieces] - starts[0] : 0;
    if (total > FX_POLY_FILL_MAX)
        return -FX_E2BIG;
    if (total < 3)
        return 0;
    int64_t ymin = INT64_MAX, ymax = INT64_MIN;
    for (int i = starts[0]; i < starts[npieces]; i++) {
        ymin = FX_MIN(ymin, (int64_t)pts[i].y);
        ymax = FX_MAX(ymax, (int64_t)pts[i].y);
    }
    /* Rows whose centre Y satisfies ymin <= Y < ymax, inside the clip. */
    int64_t r0 = -((-ymin) >> 16), r1 = -((-ymax) >> 16); /* ceil */
    r0 = FX_MAX(r0, (int64_t)c->clip.y0);
    r1 = FX_MIN(r1, (int64_t)c->clip.y1);
    int64_t xs[FX_POLY_FILL_MAX];
    for (int64_t y = r0; y < r1; y++) {
        int64_t Y = y * FX16_ONE;
        int nx = 0;
        for (int pc = 0; pc < npieces; pc++) {
            int a = starts[pc], cnt = starts[pc + 1] - a;
            for (int i = 0; i < cnt; i++) {
                fx_pt16 p = pts[a + i], q = pts[a + (i + 1) % cnt];
                if (p.y == q.y)
                    continue;
                if (p.y > q.y) {
                    fx_pt16 t = p;
                    p = q;
                    q = t;
                }
                if (Y < p.y || Y >= q.y) /* top row in, bottom row out */
                    continue;
                /* ceil of the crossing in pixels: x = p.x + (Y - p.y) dx / dy */
                int64_t dy = (int64_t)q.y - p.y, dx = (int64_t)q.x - p.x;
                fx_s128 num = fx_w_add(fx_w_mul(p.x, dy), fx_w_mul(Y - p.y, dx));
                int64_t xc = fx_w_ceildiv(num, dy * FX16_ONE);
                int j = nx++;
                while (j > 0 && xs[j - 1] > xc) {
                    xs[j] = xs[j - 1];
                    j--;
                }
                xs[j] = xc;
            }
        }
        for (int i = 0; i + 1 < nx; i += 2)
            if (xs[i] < xs[i + 1])
                fx_hspan(c, (int32_t)y, fx_sat32(xs[i]), fx_sat32(xs[i + 1]));
    }
    return 0;
}

int fx_fill_poly(const fx_ctx *c, const int32_t *xy, int32_t n, fx_fill_rule rule)
{
    if (!c || n < 0 || n > INT32_MAX / 2 || (n > 0 && !xy))
        return -FX_EINVAL;
    if (n == 3 && (rule == FX_FILL_EVENODD || rule == FX_FILL_NONZERO)) {
        fx_fill_tri(c, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5]);
        return 0;
    }
    fx_fill_edge edges[FX_FILL_STACK_EDGES];
    return fx_fill_path(c, xy, &n, 1, 0, rule, edges, FX_FILL_STACK_EDGES);
}

int fx_fill_poly8(const fx_ctx *c, const fx8 *xy, int32_t n, fx_fill_rule rule)
{
    if (n < 0 || (n > 0 && !xy))
        return -FX_EINVAL;
    fx_fill_edge edges[FX_FILL_STACK_EDGES];
    return fx_fill_path(c, xy, &n, 1, 8, rule, edges, FX_FILL_STACK_EDGES);
}

#include "fixel/line.h"

void fx_polygon(const fx_ctx *c, const int32_t *xy, int32_t n)
{
    if (n <= 0 || !xy)
        return;
    if (n == 1) {
        fx_plot(c, xy[0], xy[1]);
        return;
    }
    int drawn = 0;
    for (int32_t i = 0; i < n; i++) {
        int32_t j = i + 1 == n ? 0 : i + 1;
        int32_t x0 = xy[2 * i], y0 = xy[2 * i + 1], x1 = xy[2 * j], y1 = xy[2 * j + 1];
        if (x0 == x1 && y0 == y1)
            continue;
        fx_bres b;
        fx_bres_init(&b, x0, y0, x1, y1);
        fx_line_steps(c, x0, y0, x1, y1, 0, b.major - 1);
        drawn = 1;
    }
    if (!drawn) /* every vertex the same point: it is still lit once (issue #26) */
        fx_plot(c, xy[0], xy[1]);
}

/* ---- triangles ---- */

#define TRI_LIMIT ((int32_t)1 << 30)

static int in_limit(const fx8 *xy)
{
    for (int i = 0; i < 6; i++)
        if (xy[i] >= TRI_LIMIT || xy[i] <= -TRI_LIMIT)
            return 0;
    return 1;
}

#if defined(__SIZEOF_INT128__) && defined(__x86_64__) && !defined(FX_NO_INT128) && !defined(FX_NO_ASM)
/* The attribute planes in the compiler's 128-bit type with one divq a
 * gradient: the operations of the portable code below (fx_w_rounddiv_up of
 * the numerator shifted by 40, modulo 2^128 like fx_wide.h), so the same
 * bits; set-up is a large part of a small triangle's cost (the GL layer's
 * meshes). */
#define TRI_I128 1
__extension__ typedef __int128 tri_i128;
__extension__ typedef unsigned __int128 tri_u128;
static inline int64_t plane_grad(tri_i128 n, int64_t d)
{
    tri_u128 m = (tri_u128)n << 40;
    if (d < 0) {
        m = -m;
        d = -d;
    }
    m = (m << 1) + (tri_u128)(tri_i128)d; /* 2n + d over 2d, floored: ties up */
    int neg = (tri_i128)m < 0;
    if (neg)
        m = -m;
    uint64_t d2 = (uint64_t)d * 2, hi = (uint64_t)(m >> 64), lo = (uint64_t)m, q, r;
    if (hi >= d2)
        return neg ? INT64_MIN : INT64_MAX;
    __asm__("divq %4" : "=a"(q), "=d"(r) : "a"(lo), "d"(hi), "rm"(d2) : "cc");
    if (!neg)
        return q > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)q;
    q += r != 0; /* floor of a negative quotient */
    return q > (uint64_t)INT64_MAX ? INT64_MIN : -(int64_t)q;
}
#endif

int fx_tri_begin(fx_tri *t, fx_rect clip, const fx8 *xy, const int32_t *attr, int32_t nattr)
{
    if (nattr < 0 || nattr > FX_TRI_MAX_ATTR || (nattr > 0 && !attr))
        return -FX_EINVAL;
    if (!in_limit(xy))
        return -FX_ERANGE;
    int o[3] = {0, 1, 2};
    /* sort by y (stable order of equal y does not matter for coverage) */
    if (xy[2 * o[1] + 1] < xy[2 * o[0] + 1]) { int k = o[0]; o[0] = o[1]; o[1] = k; }
    if (xy[2 * o[2] + 1] < xy[2 * o[1] + 1]) { int k = o[1]; o[1] = o[2]; o[2] = k; }
    if (xy[2 * o[1] + 1] < xy[2 * o[0] + 1]) { int k = o[0]; o[0] = o[1]; o[1] = k; }
    for (int i = 0; i < 3; i++) {
        t->vx[i] = xy[2 * o[i]];
        t->vy[i] = xy[2 * o[i] + 1];
    }
    int64_t x0 = t->vx[0], y0 = t->vy[0], x1 = t->vx[1], y1 = t->vy[1], x2 = t->vx[2], y2 = t->vy[2];
    int64_t cross = (x2 - x0) * (y1 - y0) - (x1 - x0) * (y2 - y0);
    t->nattr = 0;
    t->clip = clip;
    if (cross == 0 || fx_rect_empty(clip))
        return 0;
    t->long_left = cross < 0; /* mid vertex right of the long edge */
    int64_t ys = ceil_shift(y0, 8), ym = ceil_shift(y1, 8), ye = ceil_shift(y2, 8);
    if (ys < clip.y0)
        ys = clip.y0;
    if (ye > clip.y1)
        ye = clip.y1;
    if (ys >= ye)
        return 0;
    t->y = (int32_t)ys;
    t->yend = (int32_t)ye;
    t->ymid = (int32_t)(ym < ys ? ys : ym > ye ? ye : ym);
    edge_setup(&t->lng, x0, y0, x2, y2, 8, ys);
    if (ys < ym) {
        edge_setup(&t->sht, x0, y0, x1, y1, 8, ys);
    } else {
        edge_setup(&t->sht, x1, y1, x2, y2, 8, ys);
        t->ymid = INT32_MIN;
    }
    if (nattr > 0) {
        /* plane through the attributes in the original vertex order */
        int64_t px = xy[0], py = xy[1];
        int64_t e1x = (int64_t)xy[2] - px, e1y = (int64_t)xy[3] - py;
        int64_t e2x = (int64_t)xy[4] - px, e2y = (int64_t)xy[5] - py;
        int64_t area = e1x * e2y - e1y * e2x;
        for (int32_t k = 0; k < nattr; k++) {
            int64_t a0 = attr[k], da1 = (int64_t)attr[nattr + k] - a0, da2 = (int64_t)attr[2 * nattr + k] - a0;
#ifdef TRI_I128
            tri_i128 nx = (tri_i128)da1 * e2y - (tri_i128)da2 * e1y;
            tri_i128 ny = (tri_i128)da2 * e1x - (tri_i128)da1 * e2x;
            int64_t gx = plane_grad(nx, area), gy = plane_grad(ny, area);
            tri_i128 sum = (tri_i128)gx * px + (tri_i128)gy * py + 128;
            t->c[k] = ((uint64_t)a0 << 32) - (uint64_t)(sum >> 8);
            t->gx[k] = (uint64_t)gx;
            t->gy[k] = (uint64_t)gy;
#else
            fx_s128 nx = fx_w_sub(fx_w_mul(da1, e2y), fx_w_mul(da2, e1y));
            fx_s128 ny = fx_w_sub(fx_w_mul(da2, e1x), fx_w_mul(da1, e2x));
            int64_t gx = fx_w_rounddiv_up(fx_w_shl(nx, 40), area);
            int64_t gy = fx_w_rounddiv_up(fx_w_shl(ny, 40), area);
            /* c = a0 * 2^32 - round((gx*px + gy*py) / 256), modulo 2^64 */
            fx_s128 sum = fx_w_add(fx_w_add(fx_w_mul(gx, px), fx_w_mul(gy, py)), fx_w_from(128));
            uint64_t shifted = (sum.lo >> 8) | ((uint64_t)sum.hi << 56);
            t->c[k] = ((uint64_t)a0 << 32) - shifted;
            t->gx[k] = (uint64_t)gx;
            t->gy[k] = (uint64_t)gy;
#endif
        }
        t->nattr = nattr;
    }
    return 1;
}

int fx_tri_next_span(fx_tri *t, fx_tri_span *s) { return tri_next(t, s); }

/* Rows of one part of a flat triangle between edges l and r, with the
 * walkers in locals (registers) and a row pointer: no multiply per row. */
#define TRI_PART(TYPE, RUN)                                                                      \
    static void part_##TYPE(uint8_t *row, int32_t stride, int32_t n, fx_tri_edge *pl, fx_tri_edge *pr, \
                            int32_t cx0, int32_t cx1, uint32_t v)                                \
    {                                                                                            \
        int64_t lx = pl->x, le = pl->e, ld = pl->d, lq = pl->qs, lr = pl->rs;                   \
        int64_t rx = pr->x, re = pr->e, rd = pr->d, rq = pr->qs, rr = pr->rs;                   \
        for (; n > 0; n--, row += stride) {                                                      \
            int64_t a = lx < cx0 ? cx0 : lx, b = rx > cx1 ? cx1 : rx;                            \
            if (a < b)                                                                           \
                RUN((TYPE *)row + a, (int32_t)(b - a), (TYPE)v);                                 \
            /* branch-free, as edge_step */                                                     \
            le -= lr;                                                                            \
            re -= rr;                                                                            \
            int64_t lm = -(int64_t)(le < 0), rm = -(int64_t)(re < 0);                            \
            le += ld & lm;                                                                       \
            re += rd & rm;                                                                       \
            lx += lq - lm;                                                                       \
            rx += rq - rm;                                                                       \
        }                                                                                        \
        pl->x = lx, pl->e = le, pr->x = rx, pr->e = re;                                          \
    }
TRI_PART(uint32_t, fx_run32)
TRI_PART(uint16_t, fx_run16)

static void tri_flat(const fx_ctx *c, const fx8 *xy)
{
    fx_tri t;
    if (fx_tri_begin(&t, c->clip, xy, 0, 0) <= 0)
        return;
    fx_tri_span s;
    int bpp = fx_format_get(c->surf.format)->bits_per_pixel;
    if (!plain_solid(c) || (bpp != 32 && bpp != 16)) {
        int fast = plain_solid(c);
        while (tri_next(&t, &s)) {
            if (fast)
                fx_span_fill(&c->surf, s.y, s.x0, s.x1, c->native);
            else
                fx_fill_span(c, s.y, s.x0, s.x1);
        }
        return;
    }
    const fx_surface *sf = &c->surf;
    int32_t y = t.y, yend = t.yend;
    int32_t nA = t.ymid == INT32_MIN ? 0 : FX_MIN(t.ymid, yend) - y;
    for (int part = 0; part < 2; part++) {
        int32_t n = part ? yend - y : nA;
        if (n <= 0)
            continue;
        if (part && nA > 0) /* the lower short edge starts where the upper ends */
            edge_setup(&t.sht, t.vx[1], t.vy[1], t.vx[2], t.vy[2], 8, y);
        fx_tri_edge *l = t.long_left ? &t.lng : &t.sht, *r = t.long_left ? &t.sht : &t.lng;
        if (bpp == 32)
            part_uint32_t(fx_row(sf, y), sf->stride, n, l, r, c->clip.x0, c->clip.x1, c->native);
        else
            part_uint16_t(fx_row(sf, y), sf->stride, n, l, r, c->clip.x0, c->clip.x1, c->native);
        y += n;
    }
}

void fx_fill_tri8(const fx_ctx *c, const fx8 *xy)
{
    if (!in_limit(xy)) {
        int32_t n = 3;
        fx_fill_edge edges[3];
        fx_fill_path(c, xy, &n, 1, 8, FX_FILL_EVENODD, edges, 3);
        return;
    }
    tri_flat(c, xy);
}

#define INT_TRI_LIMIT ((int32_t)1 << 22)

void fx_fill_tri(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t x2,
                 int32_t y2)
{
    int32_t v[6] = {x0, y0, x1, y1, x2, y2};
    for (int i = 0; i < 6; i++) {
        if (v[i] >= INT_TRI_LIMIT || v[i] <= -INT_TRI_LIMIT) {
            int32_t n = 3;
            fx_fill_edge edges[3];
            fx_fill_path(c, v, &n, 1, 0, FX_FILL_EVENODD, edges, 3);
            return;
        }
    }
    fx8 w[6];
    for (int i = 0; i < 6; i++)
        w[i] = v[i] * FX8_ONE;
    tri_flat(c, w);
}

/* ---- Gouraud ---- */

static void gouraud(const fx_ctx *c, const fx8 *xy, const fx_color *col)
{
    int32_t attr[12];
    int alpha = (col[0] >> 24) != 255 || (col[1] >> 24) != 255 || (col[2] >> 24) != 255;
    int na = alpha ? 4 : 3;
    for (int i = 0; i < 3; i++) {
        attr[i * na + 0] = (col[i] >> 16) & 0xFF;
        attr[i * na + 1] = (col[i] >> 8) & 0xFF;
        attr[i * na + 2] = col[i] & 0xFF;
        if (alpha)
            attr[i * na + 3] = (int32_t)(col[i] >> 24);
    }
    fx_tri t;
    if (fx_tri_begin(&t, c->clip, xy, attr, na) <= 0)
        return;
    const fx_surface *sf = &c->surf;
    fx_format f = sf->format;
    int direct = !c->exterior && (c->blend == FX_BLEND_SRC || !alpha);
    fx_tri_span s;
    while (tri_next(&t, &s)) {
        uint64_t r = fx_tri_attr_at(&t, 0, s.x0, s.y) + 0x80000000u, g = fx_tri_attr_at(&t, 1, s.x0, s.y) + 0x80000000u,
                 b = fx_tri_attr_at(&t, 2, s.x0, s.y) + 0x80000000u;
        uint64_t a = alpha ? fx_tri_attr_at(&t, 3, s.x0, s.y) + 0x80000000u
                     : f == FX_FMT_ARGB8888 ? (uint64_t)0xFF << 32 : 0;
        uint64_t gr = t.gx[0], gg = t.gx[1], gb = t.gx[2], ga = alpha ? t.gx[3] : 0;
        int32_t n = s.x1 - s.x0;
        if (direct && (f == FX_FMT_XRGB8888 || f == FX_FMT_ARGB8888)) {
            uint32_t *p = (uint32_t *)fx_row(sf, s.y) + s.x0;
            for (int32_t i = 0; i < n; i++) {
                p[i] = (uint32_t)(uint8_t)(a >> 32) << 24 | (uint32_t)(uint8_t)(r >> 32) << 16 |
                       (uint32_t)(uint8_t)(g >> 32) << 8 | (uint8_t)(b >> 32);
                r += gr, g += gg, b += gb, a += ga;
            }
        } else if (direct && f == FX_FMT_RGB565) {
            uint16_t *p = (uint16_t *)fx_row(sf, s.y) + s.x0;
            for (int32_t i = 0; i < n; i++) {
                p[i] = (uint16_t)(((uint32_t)(uint8_t)(r >> 32) >> 3 << 11) | ((uint32_t)(uint8_t)(g >> 32) >> 2 << 5) |
                                  ((uint32_t)(uint8_t)(b >> 32) >> 3));
                r += gr, g += gg, b += gb;
            }
        } else {
            for (int32_t i = 0; i < n; i++) {
                fx_color cc = (alpha ? (uint32_t)(uint8_t)(a >> 32) << 24 : 0xFF000000u) |
                              (uint32_t)(uint8_t)(r >> 32) << 16 | (uint32_t)(uint8_t)(g >> 32) << 8 |
                              (uint8_t)(b >> 32);
                int32_t x = s.x0 + i;
                if (!(c->exterior && x >= c->exterior_rect.x0 && x < c->exterior_rect.x1 &&
                      s.y >= c->exterior_rect.y0 && s.y < c->exterior_rect.y1))
                    put_color(c, x, s.y, cc);
                r += gr, g += gg, b += gb, a += ga;
            }
        }
    }
}

void fx_fill_tri_gouraud8(const fx_ctx *c, const fx8 *xy, const fx_color *col)
{
    if (in_limit(xy))
        gouraud(c, xy, col);
}

void fx_fill_tri_gouraud(const fx_ctx *c, const int32_t *xy, const fx_color *col)
{
    if (!c || !xy || !col)
        return;
    fx8 w[6];
    for (int i = 0; i < 6; i++) {
        if (xy[i] >= INT_TRI_LIMIT || xy[i] <= -INT_TRI_LIMIT)
            return;
        w[i] = xy[i] * FX8_ONE;
    }
    gouraud(c, w, col);
}

void fx_fill_poly_gouraud(const fx_ctx *c, const int32_t *xy, const fx_color *col, int32_t n)
{
    if (!c || !xy || !col || n > INT32_MAX / 2)
        return;
    for (int32_t i = 1; i + 1 < n; i++) {
        int32_t v[6] = {xy[0], xy[1], xy[2 * i], xy[2 * i + 1], xy[2 * i + 2], xy[2 * i + 3]};
        fx_color cc[3] = {col[0], col[i], col[i + 1]};
        fx_fill_tri_gouraud(c, v, cc);
    }
}
