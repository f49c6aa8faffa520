/* SPDX-License-Identifier: MIT */
/* fixel — escape-time fractals: the Mandelbrot set and filled Julia sets in
 * fixed point (the contract is in fractal.h).
 *
 * All per-pixel work is integer. The pixel grid is walked with an exact
 * quotient/remainder term (no division per pixel, and no drift, so a tile
 * starting anywhere reproduces the coordinates of the whole frame). */
#include "fixel/fractal.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

#define TWO56  ((int64_t)2 << 56)
#define FOUR56 ((int64_t)4 << 56)
#define TWO28  ((int64_t)2 << 28)

/* Signed (a*b) >> s, rounded to nearest with ties toward +inf: exactly
 * fx_mul64_shift for products that fit (every caller here keeps |a|, |b| <= 2
 * in Q8.56, or values of similar size). __int128 is just the fast spelling of
 * the same portable 128-bit product. */
static inline int64_t mulsh(int64_t a, int64_t b, unsigned s)
{
#if defined(__SIZEOF_INT128__) && !defined(FX_NO_INT128)
    __extension__ typedef __int128 i128;
    return (int64_t)(((i128)a * b + ((i128)1 << (s - 1))) >> s);
#else
    return fx_mul64_shift(a, b, s);
#endif
}

/* INT64_MIN, whose negation overflows, reads as INT64_MAX: past every limit. */
static inline int64_t abs64(int64_t v) { return v == INT64_MIN ? INT64_MAX : v < 0 ? -v : v; }

/* ---- the view and its grid ---- */

fx_fractal_view fx_mandel_view(fx56 cre, fx56 cim, fx56 width, int32_t w, int32_t h,
                               uint32_t maxiter)
{
    fx_fractal_view v;
    fx_memset(&v, 0, sizeof v);
    v.cre = cre;
    v.cim = cim;
    v.width = width;
    v.fw = w;
    v.fh = h;
    v.maxiter = maxiter;
    return v;
}

fx_fractal_view fx_julia_view(fx56 cre, fx56 cim, fx56 jre, fx56 jim, fx56 width, int32_t w,
                              int32_t h, uint32_t maxiter)
{
    fx_fractal_view v = fx_mandel_view(cre, cim, width, w, h, maxiter);
    v.julia = 1;
    v.jre = jre;
    v.jim = jim;
    return v;
}

#define LIM16 ((int64_t)16 << 56)

int fx_fractal_check(const fx_fractal_view *v)
{
    if (!v || v->fw < 1 || v->fh < 1 || v->fw > 32768 || v->fh > 32768)
        return -FX_EINVAL;
    if (v->width <= 0 || v->width > LIM16 || v->maxiter > FX_FRACTAL_MAX_ITER)
        return -FX_EINVAL;
    if (abs64(v->cre) > LIM16 || abs64(v->cim) > LIM16)
        return -FX_EINVAL;
    if (v->julia && (abs64(v->jre) > LIM16 || abs64(v->jim) > LIM16))
        return -FX_EINVAL;
    if (v->precision != 0 && v->precision != 32 && v->precision != 64)
        return -FX_EINVAL;
    /* The frame's half-extent along each axis: width/2 * (fh/fw) at most
     * 48, so corners stay within 64 of the origin and every sum below fits. */
    int64_t step = v->width / v->fw + 1;
    int32_t big = v->fw > v->fh ? v->fw : v->fh;
    if (step > ((int64_t)96 << 56) / big)
        return -FX_EINVAL;
    return 0;
}

int fx_fractal_precision(const fx_fractal_view *v)
{
    if (fx_fractal_check(v) < 0)
        return 0;
    if (v->precision)
        return v->precision;
    if (v->julia && (abs64(v->jre) > TWO56 || abs64(v->jim) > TWO56))
        return 64;
    /* Rounding z to 2^-29 at each step is amplified along the orbit like
     * the orbit's derivative, which grows with the dwell: measured against
     * long double, Q4.28 keeps >= 99.5 % of Mandelbrot dwells (99.98 % of
     * W9's colours) and >= 99.4 % of Julia dwells for pixel steps >= 2^-12
     * and at most 512 iterations, and falls to ~95 % at 1000 iterations
     * and 2^-13. */
    if (v->maxiter > 512)
        return 64;
    return v->width / v->fw >= ((int64_t)1 << 44) ? 32 : 64;
}

/* One axis of the grid: coord(k) = c + round_away(k * width / D), D = 2 fw,
 * k = 2i + 1 - n. width = q D + r splits the product so nothing overflows. */
typedef struct axis {
    int64_t c, q, r, d;
} axis;

static axis axis_of(const fx_fractal_view *v, int64_t centre)
{
    axis a;
    a.c = centre;
    a.d = 2 * (int64_t)v->fw;
    a.q = v->width / a.d;
    a.r = v->width % a.d;
    return a;
}

/* A walk along k = k0, k0 + 2, ... with k r = Q d + R, 0 <= R < d. */
typedef struct walk {
    int64_t k, kq, Q, R;
} walk;

static void walk_init(walk *w, const axis *a, int64_t k)
{
    int64_t n = k * a->r;
    int64_t Q = n / a->d, R = n % a->d;
    if (R < 0) {
        R += a->d;
        Q--;
    }
    w->k = k;
    w->kq = k * a->q;
    w->Q = Q;
    w->R = R;
}

/* Rounded to nearest, ties away from zero: for k r >= 0 a tie (2R == d)
 * rounds up, for k r < 0 it rounds toward Q (away from zero), which makes
 * coord(-k) - c == -(coord(k) - c) exactly. */
static inline int64_t walk_at(const walk *w, const axis *a)
{
    int64_t up = w->k >= 0 ? (2 * w->R >= a->d) : (2 * w->R > a->d);
    return a->c + w->kq + w->Q + up;
}

static inline void walk_step(walk *w, const axis *a, int64_t dk)
{
    /* dk is +2 (next pixel right) or -2 (next row down) */
    w->k += dk;
    if (dk > 0) {
        w->kq += 2 * a->q;
        w->R += 2 * a->r;
        while (w->R >= a->d) {
            w->R -= a->d;
            w->Q++;
        }
    } else {
        w->kq -= 2 * a->q;
        w->R -= 2 * a->r;
        while (w->R < 0) {
            w->R += a->d;
            w->Q--;
        }
    }
}

fx56 fx_fractal_re(const fx_fractal_view *v, int32_t x)
{
    axis a = axis_of(v, v->cre);
    walk w;
    walk_init(&w, &a, 2 * (int64_t)x + 1 - v->fw);
    return walk_at(&w, &a);
}

fx56 fx_fractal_im(const fx_fractal_view *v, int32_t y)
{
    axis a = axis_of(v, v->cim);
    walk w;
    walk_init(&w, &a, (int64_t)v->fh - 2 * (int64_t)y - 1);
    return walk_at(&w, &a);
}

/* ---- the iterations ---- */

/* Q8.56 -> Q4.28, rounded to nearest, ties away from zero (keeps symmetry). */
static inline int32_t to28(int64_t v)
{
    int64_t h = (int64_t)1 << 27;
    return (int32_t)(v >= 0 ? (v + h) >> 28 : -((-v + h) >> 28));
}

/* Escape loop in Q4.28 from z at count n. The squares and the cross product
 * are exact in 64 bits (Q8.56), so the test |z|^2 > 4 is exact for the
 * orbit's points; each new z is rounded once to Q4.28. Callers guarantee
 * |Re z|, |Im z|, |Re c|, |Im c| <= 2, so every later z has components of at
 * most 6 and nothing overflows. An orbit that returns exactly to a saved
 * point is periodic and never escapes (Brent's doubling checkpoints). */
/* Brent's cycle check of both escape loops: z is compared with a saved
 * value re-saved at doubling intervals, and a repeat means z never escapes
 * (the loop returns max). A macro, so each loop keeps its own types. */
#define BRENT_CHECK()              \
    do {                           \
        if (zr == sr && zi == si)  \
            return max;            \
        if (++lap == len) {        \
            sr = zr;               \
            si = zi;               \
            lap = 0;               \
            len += len;            \
        }                          \
    } while (0)

static uint32_t esc32(int32_t zr, int32_t zi, int32_t cr, int32_t ci, uint32_t n, uint32_t max)
{
    int32_t sr = zr, si = zi;
    uint32_t lap = 0, len = 8;
    for (; n < max; n++) {
        int64_t rr = (int64_t)zr * zr, ii = (int64_t)zi * zi;
        if (rr + ii > FOUR56)
            return n;
        int64_t ri = (int64_t)zr * zi;
        zi = (int32_t)((ri + ((int64_t)1 << 26)) >> 27) + ci;
        zr = (int32_t)((rr - ii + ((int64_t)1 << 27)) >> 28) + cr;
        BRENT_CHECK();
    }
    return n;
}

/* The same loop in Q8.56 with rounded 128-bit products. A component above 2
 * already means |z|^2 > 4 (the rounded square of a value > 2 stays > 4), so
 * testing it first changes nothing and keeps every product within range. */
static uint32_t esc64(int64_t zr, int64_t zi, int64_t cr, int64_t ci, uint32_t n, uint32_t max)
{
    int64_t sr = zr, si = zi;
    uint32_t lap = 0, len = 8;
    for (; n < max; n++) {
        if (abs64(zr) > TWO56 || abs64(zi) > TWO56)
            return n;
        int64_t rr = mulsh(zr, zr, 56), ii = mulsh(zi, zi, 56);
        if (rr + ii > FOUR56)
            return n;
        int64_t ri2 = mulsh(zr, zi, 55);
        zi = ri2 + ci;
        zr = rr - ii + cr;
        BRENT_CHECK();
    }
    return n;
}

/* c inside the main cardioid or the period-2 bulb (open sets, closed-form
 * and exact on the Q4.28 point): such c never escape. Cardioid: with
 * a = x - 1/4 and q = a^2 + y^2, inside iff q (q + a) < y^2 / 4, compared
 * exactly in 128 bits (Q.112). Bulb: (x + 1)^2 + y^2 < 1/16 in Q.56.
 * margin (in units of 2^-48, i.e. of the high word of Q.112) shrinks both
 * regions for callers whose true point is the Q4.28 one +- 2^-29: both
 * sides move by less than 16 * 2^-29 in the cardioid box, so 2^-24 keeps
 * the test one-sided (never "inside" for a point outside). */
static int in_main_parts(int32_t x, int32_t y, int64_t margin)
{
    const int32_t one = 1 << 28;
    int64_t yy = (int64_t)y * y;
    int64_t b = (int64_t)x + one;
    if (b * b + yy < ((int64_t)1 << 52) - (margin << 8))
        return 1;
    /* the cardioid lies within -0.75 <= x <= 0.375, |y| <= 0.65 */
    if (x < -(3 * one / 4) || x > 3 * one / 8 || y > one * 2 / 3 || y < -(one * 2 / 3))
        return 0;
    int64_t a = (int64_t)x - one / 4;
    int64_t q = a * a + yy;              /* Q.56, < 1.5 */
    int64_t s = q + a * ((int64_t)1 << 28); /* Q.56 */
    int64_t hi, rhs_hi;
    uint64_t lo, rhs_lo;
    fx_smul64_wide(q, s, &hi, &lo);      /* Q.112 */
    /* y^2 / 4 in Q.112 = yy << 54, split over the two halves */
    rhs_hi = (yy >> 10) - margin;
    rhs_lo = (uint64_t)yy << 54;
    return hi < rhs_hi || (hi == rhs_hi && lo < rhs_lo);
}

typedef struct job {
    const fx_fractal_view *v;
    int prec;
    int symmetric; /* Julia centred at 0: (x, y) and its mirror agree */
    axis ax, ay;
    /* the sink: either a dwell array or a surface with a palette */
    uint32_t *out;
    int32_t ostride;
    fx_rect r;
    const fx_surface *s;
    const fx_dwell_pal *pal;
} job;

static uint32_t dwell_at(const job *j, int64_t re, int64_t im)
{
    const fx_fractal_view *v = j->v;
    uint32_t max = v->maxiter;
    if (max == 0)
        return 0;
    if (!v->julia) {
        /* z1 = c; a component above 2 escapes at the first test */
        if (abs64(re) > TWO56 || abs64(im) > TWO56)
            return 1;
        if (j->prec == 32) {
            int32_t x = to28(re), y = to28(im);
            if (in_main_parts(x, y, 0))
                return max;
            return esc32(x, y, x, y, 1, max);
        }
        if (in_main_parts(to28(re), to28(im), (int64_t)1 << 24))
            return max;
        return esc64(re, im, re, im, 1, max);
    }
    if (abs64(re) > TWO56 || abs64(im) > TWO56)
        return 0;
    if (j->prec == 32)
        return esc32(to28(re), to28(im), to28(v->jre), to28(v->jim), 0, max);
    return esc64(re, im, v->jre, v->jim, 0, max);
}

/* ---- sinks ---- */

static uint32_t color_of(const fx_dwell_pal *p, uint32_t d, uint32_t max)
{
    if (d >= max)
        return p->inside;
    uint64_t i = ((uint64_t)d * p->mul) >> 16;
    if (p->wrap)
        i %= p->len;
    else if (i >= p->len)
        i = p->len - 1;
    return p->lut[i];
}

static void sink_row(const job *j, int32_t y, int32_t x0, int32_t n, const uint32_t *d)
{
    if (j->out) {
        uint32_t *o = j->out + (ptrdiff_t)(y - j->r.y0) * j->ostride + (x0 - j->r.x0);
        fx_memcpy(o, d, (size_t)n * sizeof *d);
        return;
    }
    const fx_surface *s = j->s;
    uint32_t max = j->v->maxiter;
    uint8_t *row = fx_row(s, y);
    switch (s->format) {
    case FX_FMT_XRGB8888:
    case FX_FMT_ARGB8888:
    case FX_FMT_XBGR8888: {
        uint32_t *p = (uint32_t *)(void *)row + x0;
        for (int32_t i = 0; i < n; i++)
            p[i] = color_of(j->pal, d[i], max);
        break;
    }
    case FX_FMT_RGB565:
    case FX_FMT_BGR565: {
        uint16_t *p = (uint16_t *)(void *)row + x0;
        for (int32_t i = 0; i < n; i++)
            p[i] = (uint16_t)color_of(j->pal, d[i], max);
        break;
    }
    default:
        for (int32_t i = 0; i < n; i++)
            fx_surface_put_native(s, x0 + i, y, color_of(j->pal, d[i], max));
    }
}

/* (x, y) <- (fw-1-x, ym) for x in [xa, xb): the mirror row is already done. */
static void sink_mirror(const job *j, int32_t y, int32_t ym, int32_t xa, int32_t xb)
{
    int32_t fw = j->v->fw;
    if (j->out) {
        uint32_t *o = j->out + (ptrdiff_t)(y - j->r.y0) * j->ostride - j->r.x0;
        const uint32_t *m = j->out + (ptrdiff_t)(ym - j->r.y0) * j->ostride - j->r.x0;
        for (int32_t x = xa; x < xb; x++)
            o[x] = m[fw - 1 - x];
        return;
    }
    for (int32_t x = xa; x < xb; x++)
        fx_surface_put_native(j->s, x, y, fx_surface_get_native(j->s, fw - 1 - x, ym));
}

#define CHUNK 64

/* Compute pixels [xa, xb) of row y at imaginary part im. */
static void run_span(const job *j, int32_t y, int64_t im, int32_t xa, int32_t xb)
{
    uint32_t d[CHUNK];
    walk w;
    walk_init(&w, &j->ax, 2 * (int64_t)xa + 1 - j->v->fw);
    for (int32_t x = xa; x < xb;) {
        int32_t n = xb - x < CHUNK ? xb - x : CHUNK;
        for (int32_t i = 0; i < n; i++) {
            d[i] = dwell_at(j, walk_at(&w, &j->ax), im);
            walk_step(&w, &j->ax, 2);
        }
        sink_row(j, y, x, n, d);
        x += n;
    }
}

static int run(job *j)
{
    const fx_fractal_view *v = j->v;
    fx_rect fr = {0, 0, v->fw, v->fh};
    j->r = fx_rect_intersect(j->r, fr);
    if (fx_rect_empty(j->r))
        return 0;
    j->prec = fx_fractal_precision(v);
    j->symmetric = v->julia && v->cre == 0 && v->cim == 0;
    j->ax = axis_of(v, v->cre);
    j->ay = axis_of(v, v->cim);
    const fx_rect r = j->r;
    walk wy;
    walk_init(&wy, &j->ay, (int64_t)v->fh - 2 * (int64_t)r.y0 - 1);
    for (int32_t y = r.y0; y < r.y1; y++, walk_step(&wy, &j->ay, -2)) {
        int64_t im = walk_at(&wy, &j->ay);
        int32_t ym = v->fh - 1 - y;
        if (j->symmetric && ym < y && ym >= r.y0) {
            /* mirrored columns available in this rectangle */
            int32_t ma = FX_MAX(r.x0, v->fw - r.x1), mb = FX_MIN(r.x1, v->fw - r.x0);
            if (ma < mb) {
                if (r.x0 < ma)
                    run_span(j, y, im, r.x0, ma);
                sink_mirror(j, y, ym, ma, mb);
                if (mb < r.x1)
                    run_span(j, y, im, mb, r.x1);
                continue;
            }
        }
        run_span(j, y, im, r.x0, r.x1);
    }
    return 0;
}

int fx_fractal_dwell(const fx_fractal_view *v, fx_rect r, uint32_t *out, int32_t stride)
{
    if (fx_fractal_check(v) < 0 || !out)
        return -FX_EINVAL;
    job j;
    fx_memset(&j, 0, sizeof j);
    j.v = v;
    j.r = r;
    fx_rect fr = {0, 0, v->fw, v->fh};
    fr = fx_rect_intersect(r, fr);
    /* dwell lands relative to the caller's r, not the clipped one */
    if (!fx_rect_empty(fr) && stride < fr.x1 - fr.x0)
        return -FX_EINVAL;
    j.out = out + (ptrdiff_t)(fr.y0 - r.y0) * stride + (fr.x0 - r.x0);
    j.ostride = stride;
    j.r = fr;
    return run(&j);
}

int fx_fractal_render(const fx_surface *s, fx_rect r, const fx_fractal_view *v,
                      const fx_dwell_pal *pal)
{
    if (fx_fractal_check(v) < 0 || !s || !pal || !pal->lut || pal->len == 0)
        return -FX_EINVAL;
    job j;
    fx_memset(&j, 0, sizeof j);
    j.v = v;
    j.s = s;
    j.pal = pal;
    j.r = fx_rect_intersect(r, fx_surface_rect(s));
    return run(&j);
}

void fx_dwell_pal_w9(fx_dwell_pal *pal, uint32_t lut[65], fx_format f)
{
    for (uint32_t n = 0; n < 65; n++) {
        uint32_t g = 4 * n > 255 ? 255 : 4 * n;
        lut[n] = fx_pack(f, 0xFF000000u | g * 0x010101u);
    }
    pal->lut = lut;
    pal->len = 65;
    pal->mul = 65536;
    pal->wrap = 0;
    pal->inside = fx_pack(f, 0xFF000000u);
}
