/* SPDX-License-Identifier: MIT */
/* fixel — J_c by inverse iteration, fixed points and basins of attraction
 * (contracts in julia.h). All arithmetic is Q4.28 in int64: with
 * |c| components <= 2 and points tested against |z|^2 <= 4 before they are
 * squared, every square and sum stays below 2^63. */
#include "fixel/julia.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

#define Q 28
#define ONE28 ((int64_t)1 << Q)
#define LIM2 ((int64_t)2 << 56)

/* |v|, with INT64_MIN (whose negation overflows) as INT64_MAX: still past
 * every limit it is compared with. */
static inline int64_t abs64(int64_t v) { return v == INT64_MIN ? INT64_MAX : v < 0 ? -v : v; }
/* Q8.56 to Q4.28 rounded half up, as (v + 2^27) >> 28 without the sum,
 * which overflows within 2^27 of INT64_MAX. */
static inline int64_t to28(fx56 v) { return (v >> 28) + ((v >> 27) & 1); }

int fx_julia_check(const fx_fractal_view *v)
{
    if (fx_fractal_check(v) < 0 || !v->julia || abs64(v->jre) > LIM2 || abs64(v->jim) > LIM2)
        return -FX_EINVAL;
    return v->width >> 28 >= 1 ? 0 : -FX_EINVAL;
}

static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

/* Pixel of a Q4.28 point: the inverse of the view's grid (fractal.h):
 * x = floor((re - cre) fw / width + fw / 2), y likewise with im upward.
 * |re - cre| < 2^5 and fw <= 2^15 keep the products under 2^49. */
static void pix28(const fx_fractal_view *v, int64_t re, int64_t im, int32_t *x, int32_t *y)
{
    /* a width under 2^-28 (which fx_fractal_check lets through, and
     * fx_julia_check does not) has no Q4.28 size: take the smallest one,
     * so a point maps far out (saturated) instead of dividing by zero */
    int64_t w = v->width >> 28;
    if (w < 1)
        w = 1;
    int64_t dx = re - to28(v->cre), dy = im - to28(v->cim);
    *x = fx_sat32(floor_div(2 * dx * v->fw + (int64_t)v->fw * w, 2 * w));
    *y = fx_sat32(floor_div((int64_t)v->fh * w - 2 * dy * v->fw, 2 * w));
}

void fx_julia_to_pixel(const fx_fractal_view *v, fx56 re, fx56 im, int32_t *x, int32_t *y)
{
    pix28(v, to28(re), to28(im), x, y);
}

void fx_csqrt28(int64_t a, int64_t b, int64_t *sre, int64_t *sim)
{
    /* |w| = sqrt(a^2 + b^2) with the squares in Q56 (< 2^63 for |a|, |b| < 8),
     * then the half-angle formulas; the smaller part comes from b / 2u,
     * which keeps its precision when it is tiny */
    uint64_t r = fx_isqrt64((uint64_t)(a * a) + (uint64_t)(b * b));
    if (a >= 0) {
        int64_t u = fx_isqrt64((uint64_t)(((int64_t)r + a) / 2) << Q);
        *sre = u;
        *sim = u ? b * ONE28 / (2 * u) : 0;
    } else {
        int64_t v = fx_isqrt64((uint64_t)(((int64_t)r - a) / 2) << Q);
        if (b < 0)
            v = -v;
        *sim = v;
        *sre = v ? b * ONE28 / (2 * v) : 0;
    }
}

int fx_julia_fixed_points(fx56 cre, fx56 cim, fx_julia_fixed out[2])
{
    if (abs64(cre) > LIM2 || abs64(cim) > LIM2)
        return -FX_EINVAL;
    int64_t sr, si;
    fx_csqrt28(ONE28 / 4 - to28(cre), -to28(cim), &sr, &si);
    for (int k = 0; k < 2; k++) {
        int64_t zr = ONE28 / 2 + (k ? -sr : sr), zi = k ? -si : si;
        out[k].re = zr * ONE28;
        out[k].im = zi * ONE28;
        /* |2z| = 2 sqrt(zr^2 + zi^2): Q56 under the root, Q28 out, to Q16 */
        uint64_t m = 2 * (uint64_t)fx_isqrt64((uint64_t)(zr * zr) + (uint64_t)(zi * zi));
        out[k].mult = (fx16)((m + (1u << 11)) >> 12);
        int64_t d = (int64_t)out[k].mult - FX16_ONE;
        out[k].kind = d < -16 ? FX_FIXED_ATTRACTING : d > 16 ? FX_FIXED_REPELLING : FX_FIXED_NEUTRAL;
    }
    /* the re >= 0 root gives the larger |z| (Re(1/2 * conj(s)) >= 0) except
     * for rounding; sort so the first is the one surely on J_c */
    if (out[1].mult > out[0].mult) {
        fx_julia_fixed t = out[0];
        out[0] = out[1];
        out[1] = t;
    }
    return 0;
}

typedef struct inv {
    fx_ctx c;
    const fx_fractal_view *v;
    int64_t cr, ci;
    int32_t hits;
} inv;

static void inv_plot(inv *j, int64_t re, int64_t im)
{
    int32_t x, y;
    pix28(j->v, re, im, &x, &y);
    if (x >= j->c.clip.x0 && x < j->c.clip.x1 && y >= j->c.clip.y0 && y < j->c.clip.y1) {
        fx_plot(&j->c, x, y);
        j->hits++;
    }
}

static int inv_init(inv *j, const fx_ctx *c, const fx_fractal_view *v, int64_t *zr, int64_t *zi)
{
    fx_julia_fixed fp[2];
    if (!c || fx_julia_check(v) < 0 || fx_julia_fixed_points(v->jre, v->jim, fp) < 0)
        return -FX_EINVAL;
    j->c = *c;
    j->v = v;
    j->cr = to28(v->jre);
    j->ci = to28(v->jim);
    j->hits = 0;
    *zr = to28(fp[0].re);
    *zi = to28(fp[0].im);
    return 0;
}

int32_t fx_julia_inverse_random(const fx_ctx *c, const fx_fractal_view *v, uint32_t npoints, uint32_t seed)
{
    inv j;
    int64_t zr, zi;
    if (npoints > FX_JULIA_MAX_POINTS || inv_init(&j, c, v, &zr, &zi) < 0)
        return -FX_EINVAL;
    uint32_t st = seed ? seed : 1;
    inv_plot(&j, zr, zi);
    uint32_t bits = 0;
    for (uint32_t k = 0; k < npoints; k++) {
        if (k % 32 == 0)
            bits = fx_rand32(&st);
        /* z - c: |z| <= 2 on J_c and |c| components <= 2, so the root's
         * argument stays within 4 per component */
        fx_csqrt28(zr - j.cr, zi - j.ci, &zr, &zi);
        if (bits & 1) {
            zr = -zr;
            zi = -zi;
        }
        bits >>= 1;
        inv_plot(&j, zr, zi);
    }
    return j.hits;
}

static void tree_rec(inv *j, int64_t zr, int64_t zi, uint32_t depth)
{
    inv_plot(j, zr, zi);
    if (depth == 0)
        return;
    int64_t sr, si;
    fx_csqrt28(zr - j->cr, zi - j->ci, &sr, &si);
    tree_rec(j, sr, si, depth - 1);
    tree_rec(j, -sr, -si, depth - 1);
}

int32_t fx_julia_inverse_tree(const fx_ctx *c, const fx_fractal_view *v, uint32_t depth)
{
    inv j;
    int64_t zr, zi;
    if (depth > FX_JULIA_MAX_DEPTH || inv_init(&j, c, v, &zr, &zi) < 0)
        return -FX_EINVAL;
    tree_rec(&j, zr, zi, depth);
    return j.hits;
}

/* One step of z^2 + c in Q4.28; 1 when z had escaped (|z|^2 > 4) instead. */
static inline int step(int64_t *zr, int64_t *zi, int64_t cr, int64_t ci)
{
    int64_t x = *zr, y = *zi;
    if (abs64(x) > 2 * ONE28 || abs64(y) > 2 * ONE28)
        return 1;
    int64_t x2 = x * x, y2 = y * y;
    if (x2 + y2 > (int64_t)4 << 56)
        return 1;
    *zr = ((x2 - y2 + ((int64_t)1 << 27)) >> Q) + cr;
    *zi = ((2 * x * y + ((int64_t)1 << 27)) >> Q) + ci;
    return 0;
}

static int near28(int64_t ar, int64_t ai, int64_t br, int64_t bi, int64_t eps)
{
    int64_t dr = ar - br, di = ai - bi;
    if (abs64(dr) >= eps || abs64(di) >= eps)
        return 0;
    return dr * dr + di * di < eps * eps;
}

int fx_julia_attractor(fx56 cre, fx56 cim, fx_julia_cycle *out)
{
    if (!out || abs64(cre) > LIM2 || abs64(cim) > LIM2)
        return -FX_EINVAL;
    int64_t cr = to28(cre), ci = to28(cim), zr = 0, zi = 0;
    out->period = 0;
    for (int n = 0; n < 8192; n++)
        if (step(&zr, &zi, cr, ci))
            return 0;
    int64_t wr = zr, wi = zi;
    const int64_t eps = ONE28 >> 20;
    for (int p = 1; p <= FX_JULIA_MAX_PERIOD; p++) {
        if (step(&zr, &zi, cr, ci))
            return 0;
        if (near28(zr, zi, wr, wi, eps)) {
            /* the multiplier |prod 2 z_k| (Q28, renormalised each step):
             * a preperiodic critical orbit (c = i) lands exactly on a
             * repelling cycle, which attracts nothing */
            uint64_t lam = ONE28;
            for (int k = 0; k < p; k++) {
                out->re[k] = wr;
                out->im[k] = wi;
                uint64_t m = 2 * (uint64_t)fx_isqrt64((uint64_t)(wr * wr) + (uint64_t)(wi * wi));
                lam = lam > ((uint64_t)1 << 32) ? lam : (lam * m) >> Q; /* m <= 2^30: |z| <= 2 */
                step(&wr, &wi, cr, ci);
            }
            if (lam > ONE28 + (ONE28 >> 10))
                return 0;
            out->period = p;
            return p;
        }
    }
    return 0;
}

static uint32_t dwell_colour(const fx_dwell_pal *p, uint32_t d)
{
    uint64_t i = ((uint64_t)d * p->mul) >> 16;
    if (p->wrap)
        i %= p->len;
    else if (i >= p->len)
        i = p->len - 1;
    return p->lut[i];
}

int fx_julia_basins(const fx_surface *s, fx_rect r, const fx_fractal_view *v, const fx_dwell_pal *esc,
                    const fx_color *basin, uint32_t nbasin)
{
    if (!s || !esc || !esc->lut || esc->len < 1 || !basin || nbasin < 1 || fx_julia_check(v) < 0)
        return -FX_EINVAL;
    fx_julia_cycle cyc;
    fx_julia_attractor(v->jre, v->jim, &cyc);
    int p = cyc.period;
    fx_rect fr = {0, 0, v->fw, v->fh};
    r = fx_rect_intersect(fx_rect_intersect(r, fr), fx_surface_rect(s));
    int64_t cr = to28(v->jre), ci = to28(v->jim);
    const int64_t eps = ONE28 >> 7;
    for (int32_t y = r.y0; y < r.y1; y++) {
        int64_t im0 = to28(fx_fractal_im(v, y));
        for (int32_t x = r.x0; x < r.x1; x++) {
            int64_t zr = to28(fx_fractal_re(v, x)), zi = im0;
            uint32_t n = 0, px = esc->inside;
            for (;;) {
                int k = 0;
                while (k < p && !near28(zr, zi, cyc.re[k], cyc.im[k], eps))
                    k++;
                if (k < p) {
                    /* the orbit is at cycle point k after n steps, so it
                     * started in phase with point (k - n) mod p */
                    uint32_t lab = (uint32_t)((k + p - (int)(n % (uint32_t)p)) % p);
                    fx_color c = basin[lab % nbasin];
                    uint32_t dim = n > 32 ? 32 : n;
                    uint32_t rr = (c >> 16 & 255) * (64 - dim) / 64, gg = (c >> 8 & 255) * (64 - dim) / 64,
                             bb = (c & 255) * (64 - dim) / 64;
                    px = fx_pack(s->format, (c & 0xFF000000u) | rr << 16 | gg << 8 | bb);
                    break;
                }
                if (n == v->maxiter)
                    break;
                if (step(&zr, &zi, cr, ci)) {
                    px = dwell_colour(esc, n);
                    break;
                }
                n++;
            }
            fx_surface_put_native(s, x, y, px);
        }
    }
    return p;
}
