/* SPDX-License-Identifier: MIT */
/* fixel — Bézier curves and splines: de Casteljau subdivision in fixed
 * point, adaptive flattening, and the stroker for the line style. */
#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

/* Control points in 1/65536 pixel: int32 pixel coordinates need 47 bits and
 * eight times that (the flatness test) still fits in int64. */
typedef struct bez {
    int64_t x[FX_BEZIER_MAX_POINTS], y[FX_BEZIER_MAX_POINTS];
    int depth;
} bez;

typedef struct sink {
    fx_curve_point_fn fn;
    void *user;
    int count;
} sink;

static void emit(sink *k, int64_t x16, int64_t y16)
{
    k->fn(k->user, (x16 + 128) >> 8, (y16 + 128) >> 8);
    k->count++;
}

/* |n*P_i - (n-i)*P_0 - i*P_n| <= n*tol for every inner i: each control point
 * within tol of its evenly spaced place on the chord. */
static int flat(const bez *b, int n, int64_t tol)
{
    int64_t lim = n * tol;
    for (int i = 1; i < n; i++) {
        int64_t dx = n * b->x[i] - (n - i) * b->x[0] - i * b->x[n];
        int64_t dy = n * b->y[i] - (n - i) * b->y[0] - i * b->y[n];
        if (dx > lim || dx < -lim || dy > lim || dy < -lim || dx * dx + dy * dy > lim * lim)
            return 0;
    }
    return 1;
}

/* de Casteljau at t = 1/2: a into left half l and right half r. */
static void split(const bez *a, int n, bez *l, bez *r)
{
    int64_t tx[FX_BEZIER_MAX_POINTS], ty[FX_BEZIER_MAX_POINTS];
    for (int i = 0; i <= n; i++) {
        tx[i] = a->x[i];
        ty[i] = a->y[i];
    }
    l->x[0] = tx[0];
    l->y[0] = ty[0];
    r->x[n] = tx[n];
    r->y[n] = ty[n];
    for (int k = 1; k <= n; k++) {
        for (int i = 0; i <= n - k; i++) {
            tx[i] = (tx[i] + tx[i + 1]) >> 1; /* floor; the error stays below depth/65536 px */
            ty[i] = (ty[i] + ty[i + 1]) >> 1;
        }
        l->x[k] = tx[0];
        l->y[k] = ty[0];
        r->x[n - k] = tx[n - k];
        r->y[n - k] = ty[n - k];
    }
    l->depth = r->depth = a->depth + 1;
}

/* Flatten one curve of degree n (points in 1/65536 px); the first point is
 * emitted only when `first`. */
static void flatten16(const bez *b0, int n, int64_t tol16, int first, sink *k)
{
    bez stack[FX_CURVE_MAX_DEPTH + 2];
    int top = 0;
    stack[top] = *b0;
    stack[top++].depth = 0;
    if (first)
        emit(k, b0->x[0], b0->y[0]);
    while (top) {
        bez cur = stack[--top];
        if (cur.depth >= FX_CURVE_MAX_DEPTH || flat(&cur, n, tol16)) {
            emit(k, cur.x[n], cur.y[n]);
            continue;
        }
        split(&cur, n, &stack[top + 1], &stack[top]); /* left on top: drawn first */
        top += 2;
    }
}

static int64_t tol16_of(uint32_t tol)
{
    if (!tol)
        tol = FX_CURVE_TOLERANCE;
    if (tol > 65536)
        tol = 65536;
    return (int64_t)tol << 8;
}

int fx_bezier_flatten(const int64_t *xy256, int n, uint32_t tol, fx_curve_point_fn fn, void *user)
{
    if (n < 2 || n > FX_BEZIER_MAX_POINTS || !fn)
        return -FX_EINVAL;
    bez b;
    for (int i = 0; i < n; i++) {
        b.x[i] = xy256[2 * i] * 256;
        b.y[i] = xy256[2 * i + 1] * 256;
    }
    sink k = {fn, user, 0};
    flatten16(&b, n - 1, tol16_of(tol), 1, &k);
    return k.count;
}

static void to_stroker(void *u, int64_t x, int64_t y) { fx_stroke_point(u, x, y); }

/* Pixel centre in 1/65536 pixel. */
static int64_t c16(int32_t v) { return (int64_t)v * 65536 + 32768; }

int fx_bezier(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol)
{
    if (!c || !xy || n < 2 || n > FX_BEZIER_MAX_POINTS)
        return -FX_EINVAL;
    bez b;
    for (int i = 0; i < n; i++) {
        b.x[i] = c16(xy[2 * i]);
        b.y[i] = c16(xy[2 * i + 1]);
    }
    fx_stroker s;
    fx_stroke_begin(&s, c);
    sink k = {to_stroker, &s, 0};
    flatten16(&b, n - 1, tol16_of(tol), 1, &k);
    fx_stroke_end(&s);
    return 0;
}

/* nearest v / 6 */
static int64_t div6(int64_t v) { return v >= 0 ? (v + 3) / 6 : -((-v + 3) / 6); }

/* The cubic pieces 0 .. npieces-1 of a spline through xy, each turned into
 * a Bézier by piece(), stroked as one path. */
static void stroke_pieces(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol, int npieces,
                          void (*piece)(bez *b, const int32_t *xy, int n, int i))
{
    fx_stroker s;
    fx_stroke_begin(&s, c);
    sink k = {to_stroker, &s, 0};
    int64_t t16 = tol16_of(tol);
    for (int i = 0; i < npieces; i++) {
        bez b;
        piece(&b, xy, n, i);
        flatten16(&b, 3, t16, i == 0, &k);
    }
    fx_stroke_end(&s);
}

/* Uniform cubic B-spline piece to Bézier: the classic 1-4-1 / 4-2 / 2-4 /
 * 1-4-1 sixths of the control points. */
static void bspline_piece(bez *b, const int32_t *xy, int n, int i)
{
    (void)n;
    for (int a = 0; a < 2; a++) {
        int64_t p0 = c16(xy[2 * i + a]), p1 = c16(xy[2 * i + 2 + a]);
        int64_t p2 = c16(xy[2 * i + 4 + a]), p3 = c16(xy[2 * i + 6 + a]);
        int64_t *d = a ? b->y : b->x;
        d[0] = div6(p0 + 4 * p1 + p2);
        d[1] = div6(4 * p1 + 2 * p2);
        d[2] = div6(2 * p1 + 4 * p2);
        d[3] = div6(p1 + 4 * p2 + p3);
    }
}

/* Catmull-Rom: tangent at P_i is (P_{i+1} - P_{i-1}) / 2, so the Bézier
 * handles are P_i + that / 3; ends repeat their point. */
static void catmull_piece(bez *b, const int32_t *xy, int n, int i)
{
    int im = i ? i - 1 : 0, ip = i + 2 < n ? i + 2 : n - 1;
    for (int a = 0; a < 2; a++) {
        int64_t pm = c16(xy[2 * im + a]), p0 = c16(xy[2 * i + a]);
        int64_t p1 = c16(xy[2 * i + 2 + a]), pp = c16(xy[2 * ip + a]);
        int64_t *d = a ? b->y : b->x;
        d[0] = p0;
        d[1] = p0 + div6(p1 - pm);
        d[2] = p1 - div6(pp - p0);
        d[3] = p1;
    }
}

int fx_bspline(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol)
{
    if (n < 4)
        return -FX_EINVAL;
    stroke_pieces(c, xy, n, tol, n - 3, bspline_piece);
    return 0;
}

int fx_spline(const fx_ctx *c, const int32_t *xy, int n, uint32_t tol)
{
    if (n < 2)
        return -FX_EINVAL;
    stroke_pieces(c, xy, n, tol, n - 1, catmull_piece);
    return 0;
}
