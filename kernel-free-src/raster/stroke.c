/* SPDX-License-Identifier: MIT */
/* fixel — line attributes: patterned 1-pixel lines, thick lines with caps
 * and joins, polylines, and the stroker the curves feed.
 *
 * Thick strokes are unions of convex pieces (segment bodies, dash pieces,
 * square caps, mitre/bevel joins: polygons of 3-4 vertices; round caps and
 * joins: discs), all in 1/256 pixel. A pixel is lit when its centre is inside
 * a piece: polygons by exact edge functions with the top-left rule, discs
 * closed. Rows are scanned once per buffer of pieces: each piece gives one
 * interval per row, the intervals are merged and drawn as spans, so a pixel
 * is blended once. Every decision uses 128-bit intermediates where int32
 * endpoints demand them, and depends on the geometry only, never on the
 * clip: clipping cannot move a pixel, and the rows and the dashes visited
 * are those near the clip rectangle. */
#include "fixel/line.h"
#include "../base/fx_internal.h"
#include "../base/fx_wide.h"
#include "line_internal.h"

void fx_line_style_init(fx_line_style *s)
{
    fx_memset(s, 0, sizeof *s);
    s->width = 1;
}

static int pattern_solid(const fx_line_style *s)
{
    if (!s->pattern_len)
        return 1;
    unsigned len = s->pattern_len > 32 ? 32 : s->pattern_len;
    uint32_t mask = len == 32 ? 0xFFFFFFFFu : (1u << len) - 1;
    return (s->pattern & mask) == mask;
}

int fx_line_style_is_plain(const fx_line_style *s)
{
    return !s || (s->width <= 1 && pattern_solid(s));
}

/* ---- 1-pixel lines with a pattern ---- */

/* Steps [0, kmax] of the Bresenham line from (x0, y0), pattern position
 * pos + k for step k, clipped exactly (the seekable iterator). */
static void bres_pattern(const fx_stroker *s, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                         uint32_t kmax, uint64_t pos)
{
    const fx_ctx *c = &s->c;
    if (pattern_solid(&s->st)) {
        fx_line_steps(c, x0, y0, x1, y1, 0, kmax);
        return;
    }
    fx_bres b;
    uint32_t k0, k1;
    fx_bres_init(&b, x0, y0, x1, y1);
    if (kmax > b.major)
        kmax = b.major;
    if (!fx_bres_clip(&b, c->clip, &k0, &k1) || k0 > kmax)
        return;
    if (k1 > kmax)
        k1 = kmax;
    uint32_t unit = s->st.unit, len = s->st.pattern_len, pat = s->st.pattern;
    uint64_t q = (pos + k0) / unit;
    uint32_t within = (uint32_t)((pos + k0) % unit), bit = (uint32_t)(q % len);
    fx_bres_seek(&b, k0);
    uint32_t n = k1 - k0 + 1;
    unsigned bpp = fx_format_get(c->surf.format)->bits_per_pixel;
#define NEXT_UNIT()                    \
    do {                               \
        if (++within == unit) {        \
            within = 0;                \
            if (++bit == len)          \
                bit = 0;               \
        }                              \
    } while (0)
    if (c->exterior || (c->blend == FX_BLEND_OVER && (c->color >> 24) != 255) || bpp < 8 ||
        bpp == 24) {
        for (;;) {
            if (pat >> bit & 1)
                fx_plot(c, b.x, b.y);
            if (--n == 0)
                break;
            fx_bres_step(&b);
            NEXT_UNIT();
        }
        return;
    }
    ptrdiff_t bytes = (ptrdiff_t)(bpp / 8);
    ptrdiff_t step_x = b.sx * bytes, step_y = b.sy * (ptrdiff_t)c->surf.stride;
    ptrdiff_t step_major = b.ymajor ? step_y : step_x, step_minor = b.ymajor ? step_x : step_y;
    uint8_t *p = fx_row(&c->surf, b.y) + (ptrdiff_t)b.x * bytes;
    int64_t e = b.p, inc1 = 2 * (int64_t)b.minor, inc2 = inc1 - 2 * (int64_t)b.major;
    uint32_t v = c->native;
    FX_LINE_WALK_BPP(bpp, pat >> bit & 1, fx_bres_err_step(&e, inc1, inc2), NEXT_UNIT());
#undef NEXT_UNIT
}

static int pattern_on(const fx_stroker *s, uint64_t pos)
{
    if (pattern_solid(&s->st))
        return 1;
    return s->st.pattern >> ((pos / s->st.unit) % s->st.pattern_len) & 1;
}

/* ---- thick strokes: pieces ---- */

static int64_t fdiv256(int64_t a) { return a >> 8; }      /* floor(a / 256) */
static int64_t cdiv256(int64_t a) { return -((-a) >> 8); } /* ceil(a / 256) */
static int64_t rdiv(int64_t n, int64_t d)                   /* nearest, d > 0 */
{
    int64_t q = n / d, r = n % d;
    if (r < 0) {
        q--;
        r += d;
    }
    return q + (2 * r >= d);
}

/* Rows whose centre 256y+128 lies in [ymin, ymax], clamped to the clip;
 * 0 when none or when [xmin, xmax] misses every pixel centre of the clip. */
static int piece_rows(const fx_stroker *s, fx_stroke_piece *p, int64_t xmin, int64_t xmax,
                      int64_t ymin, int64_t ymax)
{
    const fx_rect *r = &s->c.clip;
    if (xmax < (int64_t)r->x0 * 256 + 128 || xmin > ((int64_t)r->x1 - 1) * 256 + 128)
        return 0;
    int64_t y0 = cdiv256(ymin - 128), y1 = fdiv256(ymax - 128);
    y0 = FX_MAX(y0, (int64_t)r->y0);
    y1 = FX_MIN(y1, (int64_t)r->y1 - 1);
    if (y0 > y1)
        return 0;
    p->row0 = (int32_t)y0;
    p->row1 = (int32_t)y1;
    return 1;
}

static void flush(fx_stroker *s);

static fx_stroke_piece *new_piece(fx_stroker *s)
{
    if (s->npieces == FX_STROKE_PIECES)
        flush(s);
    return &s->piece[s->npieces];
}

static void add_poly(fx_stroker *s, int n, const int64_t *xs, const int64_t *ys)
{
    fx_stroke_piece *p = new_piece(s);
    int64_t xmin = xs[0], xmax = xs[0], ymin = ys[0], ymax = ys[0];
    for (int i = 1; i < n; i++) {
        xmin = FX_MIN(xmin, xs[i]);
        xmax = FX_MAX(xmax, xs[i]);
        ymin = FX_MIN(ymin, ys[i]);
        ymax = FX_MAX(ymax, ys[i]);
    }
    if (!piece_rows(s, p, xmin, xmax, ymin, ymax))
        return;
    /* Orientation: make the signed area positive so that "inside" is
     * "every edge function > 0" (ties by the top-left rule). */
    fx_s128 area = fx_w_from(0);
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        area = fx_w_add(area, fx_w_mul(xs[i] - xs[0], ys[j] - ys[0]));
        area = fx_w_sub(area, fx_w_mul(xs[j] - xs[0], ys[i] - ys[0]));
    }
    int sg = fx_w_sign(area);
    if (!sg)
        return;
    for (int i = 0; i < n; i++) {
        int j = sg > 0 ? i : n - 1 - i;
        p->x[i] = xs[j];
        p->y[i] = ys[j];
    }
    p->n = (uint8_t)n;
    s->npieces++;
}

static void add_disc(fx_stroker *s, int64_t cx, int64_t cy, int64_t r)
{
    fx_stroke_piece *p = new_piece(s);
    if (!piece_rows(s, p, cx - r, cx + r, cy - r, cy + r))
        return;
    p->x[0] = cx;
    p->y[0] = cy;
    p->r = r;
    p->n = 0;
    s->npieces++;
}

/* The pixel centres of row y inside piece p, as [*xa, *xb] within [lo, hi]. */
static int piece_span(const fx_stroke_piece *p, int32_t y, int64_t lo, int64_t hi, int64_t *xa,
                      int64_t *xb)
{
    int64_t Y = (int64_t)y * 256 + 128;
    if (p->n == 0) {
        int64_t dy = Y - p->y[0];
        uint64_t r2 = (uint64_t)(p->r * p->r), d2 = (uint64_t)(dy * dy);
        if (d2 > r2)
            return 0;
        int64_t h = fx_isqrt64(r2 - d2); /* |X - cx| <= h  <=>  (X-cx)^2 <= r^2 - dy^2 */
        lo = FX_MAX(lo, cdiv256(p->x[0] - h - 128));
        hi = FX_MIN(hi, fdiv256(p->x[0] + h - 128));
    } else {
        for (int i = 0; i < p->n; i++) {
            int j = i + 1 == p->n ? 0 : i + 1;
            int64_t ex = p->x[j] - p->x[i], ey = p->y[j] - p->y[i];
            if (ey == 0) {
                int64_t dy = Y - p->y[i];
                /* E = ex * dy: inside when > 0, or 0 on a top edge (ex > 0). */
                if (ex > 0 ? dy < 0 : ex < 0 ? dy >= 0 : 0)
                    return 0;
                continue;
            }
            /* E(X) = N - ey*X with N = ex*(Y - Py) + ey*Px. */
            fx_s128 N = fx_w_add(fx_w_mul(ex, Y - p->y[i]), fx_w_mul(ey, p->x[i]));
            if (ey > 0) { /* right edge, strict: 256*ey*x < N - 128*ey */
                fx_s128 T = fx_w_sub(N, fx_w_from(128 * ey + 1));
                hi = FX_MIN(hi, fx_w_floordiv(T, 256 * ey));
            } else { /* left edge, inclusive: 256*e*x >= -N - 128*e */
                int64_t e = -ey;
                fx_s128 T = fx_w_sub(fx_w_neg(N), fx_w_from(128 * e));
                lo = FX_MAX(lo, fx_w_ceildiv(T, 256 * e));
            }
            if (lo > hi)
                return 0;
        }
    }
    if (lo > hi)
        return 0;
    *xa = lo;
    *xb = hi;
    return 1;
}

static void flush(fx_stroker *s)
{
    int n = s->npieces;
    if (!n)
        return;
    int32_t y0 = s->piece[0].row0, y1 = s->piece[0].row1;
    for (int i = 1; i < n; i++) {
        y0 = FX_MIN(y0, s->piece[i].row0);
        y1 = FX_MAX(y1, s->piece[i].row1);
    }
    int64_t lo = s->c.clip.x0, hi = (int64_t)s->c.clip.x1 - 1;
    int64_t xa[FX_STROKE_PIECES], xb[FX_STROKE_PIECES];
    for (int32_t y = y0; y <= y1; y++) {
        int m = 0;
        for (int i = 0; i < n; i++) {
            const fx_stroke_piece *p = &s->piece[i];
            int64_t a, b;
            if (y < p->row0 || y > p->row1 || !piece_span(p, y, lo, hi, &a, &b))
                continue;
            int j = m++; /* insertion by start */
            while (j > 0 && xa[j - 1] > a) {
                xa[j] = xa[j - 1];
                xb[j] = xb[j - 1];
                j--;
            }
            xa[j] = a;
            xb[j] = b;
        }
        for (int i = 0; i < m;) {
            int64_t a = xa[i], b = xb[i];
            for (i++; i < m && xa[i] <= b + 1; i++)
                b = FX_MAX(b, xb[i]);
            fx_hspan(&s->c, y, (int32_t)a, (int32_t)(b + 1));
        }
        if (y == INT32_MAX)
            break;
    }
    s->npieces = 0;
}

/* ---- thick strokes: geometry ---- */

typedef struct seg {
    int64_t ax, ay, bx, by, dx, dy;
    int64_t ox, oy; /* left normal (-dy, dx) scaled to the half-width */
    int64_t len;    /* length in 1/256 px */
} seg;

/* Direction reduced to < 2^24 per axis (the angle error is < 2^-23 rad), so
 * the normal and the length come out of 64-bit arithmetic; the rounding is
 * fixed by the endpoints alone. */
static void seg_init(seg *g, int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t h)
{
    g->ax = ax;
    g->ay = ay;
    g->bx = bx;
    g->by = by;
    g->dx = bx - ax;
    g->dy = by - ay;
    int sh = 0;
    int64_t rx = g->dx, ry = g->dy;
    while ((rx < 0 ? -rx : rx) >= ((int64_t)1 << 24) || (ry < 0 ? -ry : ry) >= ((int64_t)1 << 24)) {
        rx = g->dx >> ++sh;
        ry = g->dy >> sh;
    }
    uint64_t l7 = fx_isqrt64((uint64_t)(rx * rx + ry * ry) << 14); /* |r| * 2^7 */
    if (!l7) {
        g->ox = g->oy = g->len = 0;
        return;
    }
    g->ox = rdiv(-ry * h * 128, (int64_t)l7);
    g->oy = rdiv(rx * h * 128, (int64_t)l7);
    g->len = sh >= 7 ? (int64_t)(l7 << (sh - 7)) : (int64_t)(l7 >> (7 - sh));
}

/* The point at arc length u (0..len) along g, rounded to nearest. */
static void seg_at(const seg *g, int64_t u, int64_t *x, int64_t *y)
{
    if (u <= 0 || !g->len) {
        *x = g->ax;
        *y = g->ay;
        return;
    }
    if (u >= g->len) {
        *x = g->bx;
        *y = g->by;
        return;
    }
    fx_s128 nx = fx_w_add(fx_w_mul(2 * g->dx, u), fx_w_from(g->len));
    fx_s128 ny = fx_w_add(fx_w_mul(2 * g->dy, u), fx_w_from(g->len));
    *x = g->ax + fx_w_floordiv(nx, 2 * g->len);
    *y = g->ay + fx_w_floordiv(ny, 2 * g->len);
}

/* Body from P to Q (points on g) with optional square extensions. */
static void add_body(fx_stroker *s, const seg *g, int64_t px, int64_t py, int64_t qx, int64_t qy,
                     int capp, int capq)
{
    int64_t tx = g->oy, ty = -g->ox; /* tangent, half-width long */
    if (capp == FX_CAP_SQUARE)
        px -= tx, py -= ty;
    if (capq == FX_CAP_SQUARE)
        qx += tx, qy += ty;
    int64_t xs[4] = {px + g->ox, qx + g->ox, qx - g->ox, px - g->ox};
    int64_t ys[4] = {py + g->oy, qy + g->oy, qy - g->oy, py - g->oy};
    add_poly(s, 4, xs, ys);
    int64_t h = (int64_t)s->st.width * 128;
    if (capp == FX_CAP_ROUND)
        add_disc(s, px, py, h);
    if (capq == FX_CAP_ROUND)
        add_disc(s, qx, qy, h);
}

/* Arc range [*u0, *u1] of g whose centre line lies within the clip grown by
 * the reach of a piece (square corners: sqrt(2) * half-width) plus margin. */
static int seg_visible(const fx_stroker *s, const seg *g, int64_t *u0, int64_t *u1)
{
    int64_t m = (int64_t)s->st.width * 256 + 512;
    int64_t lo = 0, hi = g->len;
    const fx_rect *r = &s->c.clip;
    int64_t bx0 = (int64_t)r->x0 * 256 - m, bx1 = (int64_t)r->x1 * 256 + m;
    int64_t by0 = (int64_t)r->y0 * 256 - m, by1 = (int64_t)r->y1 * 256 + m;
    for (int axis = 0; axis < 2; axis++) {
        int64_t a = axis ? g->ay : g->ax, d = axis ? g->dy : g->dx;
        int64_t b0 = axis ? by0 : bx0, b1 = axis ? by1 : bx1;
        if (d == 0) {
            if (a < b0 || a > b1)
                return 0;
            continue;
        }
        /* u = (b - a) * len / d, rounded outwards */
        int64_t e0 = d > 0 ? b0 : b1, e1 = d > 0 ? b1 : b0, ad = d < 0 ? -d : d;
        fx_s128 n0 = fx_w_mul(d > 0 ? e0 - a : a - e0, g->len);
        fx_s128 n1 = fx_w_mul(d > 0 ? e1 - a : a - e1, g->len);
        lo = FX_MAX(lo, fx_w_floordiv(n0, ad) - 1);
        hi = FX_MIN(hi, fx_w_ceildiv(n1, ad) + 1);
    }
    if (lo > hi)
        return 0;
    *u0 = lo;
    *u1 = hi;
    return 1;
}

/* Segment g starting at pattern position s->pos (1/256 px). */
static void emit_segment(fx_stroker *s, const seg *g, int first, int last)
{
    int cap = s->st.cap;
    if (pattern_solid(&s->st)) {
        add_body(s, g, g->ax, g->ay, g->bx, g->by, first ? cap : FX_CAP_BUTT,
                 last ? cap : FX_CAP_BUTT);
        return;
    }
    int64_t v0, v1;
    if (!seg_visible(s, g, &v0, &v1))
        return;
    int64_t a0 = (int64_t)s->pos, a1 = a0 + g->len;
    int64_t U = (int64_t)s->st.unit * 256, P = U * s->st.pattern_len;
    /* Runs [R0, R1) of the periodic pattern that meet [a0 + v0, a0 + v1]. */
    int64_t lo = a0 + v0, hi = a0 + v1;
    for (int64_t k = lo / P - 1;; k++) {
        int64_t base = k * P;
        if (base > hi)
            break;
        for (int i = 0; i < s->nruns; i++) {
            int64_t R0 = base + s->run0[i] * U, R1 = base + s->run1[i] * U;
            if (R1 <= a0 || R0 >= a1 || R1 < lo || R0 > hi)
                continue;
            int64_t u = FX_MAX(R0, a0) - a0, v = FX_MIN(R1, a1) - a0;
            int64_t px, py, qx, qy;
            seg_at(g, u, &px, &py);
            seg_at(g, v, &qx, &qy);
            add_body(s, g, px, py, qx, qy, (R0 >= a0 || first) ? cap : FX_CAP_BUTT,
                     (R1 <= a1 || last) ? cap : FX_CAP_BUTT);
        }
    }
}

/* 1 when the pattern is lit on both sides of position a (a vertex inside a dash). */
static int lit_through(const fx_stroker *s, int64_t a)
{
    if (pattern_solid(&s->st))
        return 1;
    int64_t U = (int64_t)s->st.unit * 256, P = U * s->st.pattern_len;
    int64_t k = a / P;
    for (int i = 0; i < s->nruns; i++)
        for (int64_t base = (k - 1) * P; base <= k * P; base += P)
            if (base + s->run0[i] * U < a && a < base + s->run1[i] * U)
                return 1;
    return 0;
}

static void emit_join(fx_stroker *s, const seg *g1, const seg *g2)
{
    int64_t vx = g1->bx, vy = g1->by, h = (int64_t)s->st.width * 128;
    int64_t cr = g1->ox * g2->oy - g1->oy * g2->ox, dot = g1->ox * g2->ox + g1->oy * g2->oy;
    if (cr == 0 && dot > 0)
        return;
    if (s->st.join == FX_JOIN_ROUND) {
        add_disc(s, vx, vy, h);
        return;
    }
    if (cr == 0)
        return; /* a reversal: the butt ends already meet */
    int64_t sg = cr > 0 ? -1 : 1;
    int64_t p1x = vx + sg * g1->ox, p1y = vy + sg * g1->oy;
    int64_t p2x = vx + sg * g2->ox, p2y = vy + sg * g2->oy;
    if (s->st.join == FX_JOIN_MITER) {
        /* The outer edges meet at V + sg*(o1 + o2) * h^2 / (h^2 + o1.o2); the
         * mitre ratio is sqrt(2 h^2 / (h^2 + o1.o2)), kept <= the limit L. */
        int64_t h2 = h * h, den = h2 + dot;
        int64_t L8 = (s->st.miter_limit ? s->st.miter_limit : 4 * FX16_ONE) >> 8;
        fx_s128 lhs = fx_w_mul(2 * h2, 65536), rhs = fx_w_mul(L8 * L8, den);
        if (den > 0 && fx_w_sign(fx_w_sub(rhs, lhs)) >= 0) {
            int64_t mx = vx + sg * rdiv((g1->ox + g2->ox) * h2, den);
            int64_t my = vy + sg * rdiv((g1->oy + g2->oy) * h2, den);
            int64_t xs[4] = {vx, p1x, mx, p2x}, ys[4] = {vy, p1y, my, p2y};
            add_poly(s, 4, xs, ys);
            return;
        }
    }
    int64_t xs[3] = {vx, p1x, p2x}, ys[3] = {vy, p1y, p2y};
    add_poly(s, 3, xs, ys);
}

/* ---- the stroker ---- */

void fx_stroke_begin(fx_stroker *s, const fx_ctx *c)
{
    s->c = *c;
    s->c.trace = 0;
    s->c.line_style = 0;
    if (c->line_style)
        s->st = *c->line_style;
    else
        fx_line_style_init(&s->st);
    if (s->st.width < 1)
        s->st.width = 1;
    if (s->st.width > FX_LINE_MAX_WIDTH)
        s->st.width = FX_LINE_MAX_WIDTH;
    if (s->st.pattern_len > 32)
        s->st.pattern_len = 32;
    if (!s->st.unit)
        s->st.unit = (uint16_t)s->st.width;
    if (s->st.cap > FX_CAP_ROUND)
        s->st.cap = FX_CAP_BUTT;
    if (s->st.join > FX_JOIN_BEVEL)
        s->st.join = FX_JOIN_MITER;
    s->thick = s->st.width > 1;
    s->npts = 0;
    s->npieces = 0;
    s->nruns = 0;
    if (!pattern_solid(&s->st)) {
        /* Runs of lit units in one period; a run touching the period end
         * continues into the next period's first run, which is then dropped. */
        unsigned len = s->st.pattern_len;
        uint32_t pat = s->st.pattern;
        for (unsigned i = 0; i < len;) {
            if (!(pat >> i & 1)) {
                i++;
                continue;
            }
            unsigned j = i;
            while (j < len && (pat >> j & 1))
                j++;
            s->run0[s->nruns] = (uint8_t)i;
            s->run1[s->nruns++] = (uint8_t)j;
            i = j;
        }
        if (s->nruns > 1 && s->run0[0] == 0 && s->run1[s->nruns - 1] == len) {
            s->run1[s->nruns - 1] = (uint8_t)(len + s->run1[0]);
            for (int i = 1; i < s->nruns; i++) {
                s->run0[i - 1] = s->run0[i];
                s->run1[i - 1] = s->run1[i];
            }
            s->nruns--;
        }
        uint64_t period = (uint64_t)s->st.unit * len;
        s->pos = s->st.phase % period;
        if (s->thick)
            s->pos *= 256;
    } else {
        s->pos = 0;
    }
}

/* Keep the pattern position small: only its value modulo the period counts. */
static void advance(fx_stroker *s, uint64_t d)
{
    if (pattern_solid(&s->st))
        return;
    uint64_t period = (uint64_t)s->st.unit * s->st.pattern_len * (s->thick ? 256 : 1);
    s->pos = (s->pos + d) % period;
}

void fx_stroke_point(fx_stroker *s, int64_t x, int64_t y)
{
    if (!s->thick) {
        int32_t px = (int32_t)fdiv256(x), py = (int32_t)fdiv256(y);
        if (s->npts && px == s->lx[1] && py == s->ly[1])
            return;
        if (s->npts >= 2) {
            fx_bres b;
            fx_bres_init(&b, s->lx[0], s->ly[0], s->lx[1], s->ly[1]);
            bres_pattern(s, s->lx[0], s->ly[0], s->lx[1], s->ly[1], b.major - 1, s->pos);
            advance(s, b.major);
        }
        s->lx[0] = s->lx[1];
        s->ly[0] = s->ly[1];
        s->lx[1] = px;
        s->ly[1] = py;
        s->npts++;
        return;
    }
    if (s->npts && x == s->px[1] && y == s->py[1])
        return;
    if (s->npts >= 2) {
        int64_t h = (int64_t)s->st.width * 128;
        seg g1, g2;
        seg_init(&g1, s->px[0], s->py[0], s->px[1], s->py[1], h);
        seg_init(&g2, s->px[1], s->py[1], x, y, h);
        emit_segment(s, &g1, s->npts == 2, 0);
        advance(s, (uint64_t)g1.len);
        if (lit_through(s, (int64_t)s->pos))
            emit_join(s, &g1, &g2);
    }
    s->px[0] = s->px[1];
    s->py[0] = s->py[1];
    s->px[1] = x;
    s->py[1] = y;
    s->npts++;
}

void fx_stroke_end(fx_stroker *s)
{
    if (!s->thick) {
        if (s->npts == 1 && pattern_on(s, s->pos))
            fx_plot(&s->c, s->lx[1], s->ly[1]);
        if (s->npts >= 2) {
            fx_bres b;
            fx_bres_init(&b, s->lx[0], s->ly[0], s->lx[1], s->ly[1]);
            bres_pattern(s, s->lx[0], s->ly[0], s->lx[1], s->ly[1], b.major, s->pos);
            advance(s, b.major);
        }
        s->npts = 0;
        return;
    }
    int64_t h = (int64_t)s->st.width * 128;
    if (s->npts == 1 && pattern_on(s, s->pos / 256)) {
        /* A lone point: a dot for round and square caps, nothing for butt. */
        int64_t cx = s->px[1], cy = s->py[1];
        if (s->st.cap == FX_CAP_ROUND)
            add_disc(s, cx, cy, h);
        else if (s->st.cap == FX_CAP_SQUARE) {
            int64_t xs[4] = {cx - h, cx + h, cx + h, cx - h}, ys[4] = {cy - h, cy - h, cy + h, cy + h};
            add_poly(s, 4, xs, ys);
        }
    }
    if (s->npts >= 2) {
        seg g;
        seg_init(&g, s->px[0], s->py[0], s->px[1], s->py[1], h);
        emit_segment(s, &g, s->npts == 2, 1);
        advance(s, (uint64_t)g.len);
    }
    flush(s);
    s->npts = 0;
}

void fx_polyline(const fx_ctx *c, const int32_t *xy, int n)
{
    if (!c || !xy || n < 1 || n > INT32_MAX / 2)
        return;
    fx_stroker s;
    fx_stroke_begin(&s, c);
    for (int i = 0; i < n; i++)
        fx_stroke_point(&s, (int64_t)xy[2 * i] * 256 + 128, (int64_t)xy[2 * i + 1] * 256 + 128);
    fx_stroke_end(&s);
}
