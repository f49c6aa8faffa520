/* SPDX-License-Identifier: MIT */
/* fixel — 2D homogeneous transforms in Q16.16: constructors, composition,
 * inversion, application to points, and rectangles drawn through a
 * context's transform. Every entry is computed from exact 128-bit sums and
 * rounded once (see xform.h for the error bounds). */
#include "fixel/xform.h"
#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"
#include "../base/fx_wide.h"

#define ONE ((int64_t)FX16_ONE)

/* round(n / 2^16), ties toward +inf, saturated to int32. */
static fx16 round16(fx_s128 n)
{
    int64_t v = fx_w_floordiv(fx_w_add(n, fx_w_from(FX16_HALF)), ONE);
    return fx_sat32(v);
}

static void affine(fx_xform2 *o, fx16 a, fx16 b, fx16 tx, fx16 c, fx16 d, fx16 ty)
{
    o->m[0][0] = a, o->m[0][1] = b, o->m[0][2] = tx;
    o->m[1][0] = c, o->m[1][1] = d, o->m[1][2] = ty;
    o->m[2][0] = 0, o->m[2][1] = 0, o->m[2][2] = FX16_ONE;
}

void fx_xform2_identity(fx_xform2 *o) { affine(o, FX16_ONE, 0, 0, 0, FX16_ONE, 0); }

void fx_xform2_translation(fx_xform2 *o, fx16 tx, fx16 ty) { affine(o, FX16_ONE, 0, tx, 0, FX16_ONE, ty); }

/* round((p * (1 - k) + q * l) / 2^16): the translation P - M P of a
 * transform about a point, formed without intermediate rounding. */
static fx16 about(fx16 p, fx16 k, fx16 q, fx16 l)
{
    return round16(fx_w_add(fx_w_mul(p, ONE - k), fx_w_mul(q, l)));
}

void fx_xform2_scaling(fx_xform2 *o, fx16 sx, fx16 sy, fx16 px, fx16 py)
{
    affine(o, sx, 0, about(px, sx, 0, 0), 0, sy, about(py, sy, 0, 0));
}

void fx_xform2_rotation(fx_xform2 *o, fx_angle a, fx16 px, fx16 py)
{
    fx16 c = fx_cos(a), s = fx_sin(a);
    /* P - R P = (px (1 - c) + py s, py (1 - c) - px s) */
    affine(o, c, -s, about(px, c, py, s), s, c, about(py, c, px, -s));
}

void fx_xform2_shear_x(fx_xform2 *o, fx16 sh, fx16 yref)
{
    affine(o, FX16_ONE, sh, round16(fx_w_mul(-(int64_t)sh, yref)), 0, FX16_ONE, 0);
}

void fx_xform2_shear_y(fx_xform2 *o, fx16 sh, fx16 xref)
{
    affine(o, FX16_ONE, 0, 0, sh, FX16_ONE, round16(fx_w_mul(-(int64_t)sh, xref)));
}

void fx_xform2_reflection(fx_xform2 *o, fx_reflect axis)
{
    switch (axis) {
    case FX_REFLECT_X_AXIS: affine(o, FX16_ONE, 0, 0, 0, -FX16_ONE, 0); break;
    case FX_REFLECT_Y_AXIS: affine(o, -FX16_ONE, 0, 0, 0, FX16_ONE, 0); break;
    case FX_REFLECT_ORIGIN: affine(o, -FX16_ONE, 0, 0, 0, -FX16_ONE, 0); break;
    default: affine(o, 0, FX16_ONE, 0, FX16_ONE, 0, 0); break;
    }
}

void fx_xform2_reflection_line(fx_xform2 *o, fx16 px, fx16 py, fx_angle a)
{
    fx_angle a2 = a * 2u; /* wraps modulo a turn, as angles do */
    fx16 c = fx_cos(a2), s = fx_sin(a2);
    /* M = [c s; s -c]; P - M P = (px (1 - c) - py s, py (1 + c) - px s) */
    affine(o, c, s, about(px, c, py, -s), s, -c, about(py, -c, px, -s));
}

static int64_t rdiv64(int64_t n, int64_t d) { return fx_w_rounddiv_away(fx_w_from(n), d); }

int fx_xform2_window_viewport(fx_xform2 *o, fx16 wx0, fx16 wy0, fx16 wx1, fx16 wy1, fx16 vx0,
                              fx16 vy0, fx16 vx1, fx16 vy1, int keep_aspect)
{
    return fx_xform2_window_viewport_par(o, wx0, wy0, wx1, wy1, vx0, vy0, vx1, vy1, keep_aspect, 1, 1);
}

int fx_xform2_window_viewport_par(fx_xform2 *o, fx16 wx0, fx16 wy0, fx16 wx1, fx16 wy1, fx16 vx0,
                                  fx16 vy0, fx16 vx1, fx16 vy1, int keep_aspect, int32_t par_num,
                                  int32_t par_den)
{
    int64_t ww = (int64_t)wx1 - wx0, wh = (int64_t)wy1 - wy0;
    if (!ww || !wh || par_num < 1 || par_den < 1 || par_num > FX_PAR_MAX || par_den > FX_PAR_MAX)
        return -FX_EINVAL;
    int64_t sx = rdiv64(((int64_t)vx1 - vx0) * ONE, ww), sy = rdiv64(((int64_t)vy1 - vy0) * ONE, wh);
    if (!keep_aspect) {
        fx16 fsx = fx_sat32(sx), fsy = fx_sat32(sy);
        /* the course's form: xv = xvmin + (xw - xwmin) sx */
        affine(o, fsx, 0, round16(fx_w_sub(fx_w_mul(vx0, ONE), fx_w_mul(fsx, wx0))), 0, fsy,
               round16(fx_w_sub(fx_w_mul(vy0, ONE), fx_w_mul(fsy, wy0))));
        return 0;
    }
    /* One scale s for y and s * num/den for x (the pixels' aspect), the
     * largest with which the window still fits: x fits while s <= ax
     * den/num. With num == den this is the plain min(ax, ay). */
    int64_t ax = sx < 0 ? -sx : sx, ay = sy < 0 ? -sy : sy;
    /* 128-bit products: ax reaches ~2^48 (a 65533-px viewport over a
     * window 2^-16 wide) and the ratio's terms 2^16 */
    int64_t axy = par_num == par_den ? ax : fx_w_rounddiv_away(fx_w_mul(ax, par_den), par_num);
    int64_t s = axy < ay ? axy : ay;
    int64_t s_x = par_num == par_den ? s : fx_w_rounddiv_away(fx_w_mul(s, par_num), par_den);
    fx16 fsx = fx_sat32(sx < 0 ? -s_x : s_x), fsy = fx_sat32(sy < 0 ? -s : s);
    /* centre onto centre: t = (v0 + v1)/2 - s (w0 + w1)/2 */
    fx_s128 nx = fx_w_sub(fx_w_mul((int64_t)vx0 + vx1, ONE), fx_w_mul(fsx, (int64_t)wx0 + wx1));
    fx_s128 ny = fx_w_sub(fx_w_mul((int64_t)vy0 + vy1, ONE), fx_w_mul(fsy, (int64_t)wy0 + wy1));
    affine(o, fsx, 0, fx_sat32(fx_w_rounddiv_away(nx, 2 * ONE)), 0, fsy,
           fx_sat32(fx_w_rounddiv_away(ny, 2 * ONE)));
    return 0;
}

void fx_xform2_mul(fx_xform2 *out, const fx_xform2 *a, const fx_xform2 *b)
{
    fx_xform2 r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            fx_s128 s = fx_w_mul(a->m[i][0], b->m[0][j]);
            s = fx_w_add(s, fx_w_mul(a->m[i][1], b->m[1][j]));
            s = fx_w_add(s, fx_w_mul(a->m[i][2], b->m[2][j]));
            r.m[i][j] = round16(s);
        }
    *out = r;
}

void fx_xform2_pre(fx_xform2 *m, const fx_xform2 *t) { fx_xform2_mul(m, m, t); }
void fx_xform2_then(fx_xform2 *m, const fx_xform2 *t) { fx_xform2_mul(m, t, m); }

static int is_affine(const fx_xform2 *m)
{
    return m->m[2][0] == 0 && m->m[2][1] == 0 && m->m[2][2] == FX16_ONE;
}

int fx_xform2_is_identity(const fx_xform2 *m)
{
    return is_affine(m) && m->m[0][0] == FX16_ONE && m->m[0][1] == 0 && m->m[0][2] == 0 &&
           m->m[1][0] == 0 && m->m[1][1] == FX16_ONE && m->m[1][2] == 0;
}

static fx_s128 shl16(fx_s128 a)
{
    fx_s128 r;
    r.hi = (int64_t)(((uint64_t)a.hi << 16) | (a.lo >> 48));
    r.lo = a.lo << 16;
    return r;
}

static int fits32(int64_t v) { return v >= INT32_MIN && v <= INT32_MAX; }

int fx_xform2_invert(fx_xform2 *out, const fx_xform2 *in)
{
    if (!is_affine(in))
        return -FX_ENOTSUP;
    int64_t a = in->m[0][0], b = in->m[0][1], c = in->m[1][0], d = in->m[1][1];
    int64_t tx = in->m[0][2], ty = in->m[1][2];
    fx_s128 det128 = fx_w_sub(fx_w_mul(a, d), fx_w_mul(b, c)); /* Q32 */
    if (!fx_w_sign(det128))
        return -FX_EDOM;
    if (det128.hi != ((int64_t)det128.lo < 0 ? -1 : 0))
        return -FX_ERANGE; /* |det| >= 2^31: entries of the inverse round to 0 */
    int64_t det = (int64_t)det128.lo;
    /* A^-1 = adj(A) / det; entries in Q16 are adj * 2^32 / det. */
    int64_t ia = fx_w_rounddiv_away(fx_w_mul(d, ONE * ONE), det);
    int64_t ib = fx_w_rounddiv_away(fx_w_mul(-b, ONE * ONE), det);
    int64_t ic = fx_w_rounddiv_away(fx_w_mul(-c, ONE * ONE), det);
    int64_t id = fx_w_rounddiv_away(fx_w_mul(a, ONE * ONE), det);
    /* t' = -A^-1 t = -(d tx - b ty, a ty - c tx) / det, exact until rounding */
    fx_s128 nx = fx_w_sub(fx_w_mul(b, ty), fx_w_mul(d, tx));
    fx_s128 ny = fx_w_sub(fx_w_mul(c, tx), fx_w_mul(a, ty));
    int64_t itx = fx_w_rounddiv_away(shl16(nx), det), ity = fx_w_rounddiv_away(shl16(ny), det);
    if (!fits32(ia) || !fits32(ib) || !fits32(ic) || !fits32(id) || !fits32(itx) || !fits32(ity))
        return -FX_ERANGE;
    affine(out, (fx16)ia, (fx16)ib, (fx16)itx, (fx16)ic, (fx16)id, (fx16)ity);
    return 0;
}

/* Raw Q16.16 coordinates of any int64 size in, Q32 sums out. */
static void apply_raw(const fx_xform2 *m, int64_t x, int64_t y, fx_s128 *X, fx_s128 *Y)
{
    *X = fx_w_add(fx_w_add(fx_w_mul(m->m[0][0], x), fx_w_mul(m->m[0][1], y)),
                  fx_w_mul(m->m[0][2], ONE));
    *Y = fx_w_add(fx_w_add(fx_w_mul(m->m[1][0], x), fx_w_mul(m->m[1][1], y)),
                  fx_w_mul(m->m[1][2], ONE));
}

fx_pt16 fx_xform2_apply(const fx_xform2 *m, fx_pt16 p)
{
    fx_s128 X, Y;
    apply_raw(m, p.x, p.y, &X, &Y);
    fx_pt16 r = {round16(X), round16(Y)};
    if (!is_affine(m)) {
        fx_s128 W = fx_w_add(fx_w_add(fx_w_mul(m->m[2][0], p.x), fx_w_mul(m->m[2][1], p.y)),
                             fx_w_mul(m->m[2][2], ONE));
        fx16 w = round16(W);
        r.x = fx16_div(r.x, w);
        r.y = fx16_div(r.y, w);
    }
    return r;
}

void fx_xform2_apply_pts(const fx_xform2 *m, const fx_pt16 *in, fx_pt16 *out, int n)
{
    for (int i = 0; i < n; i++)
        out[i] = fx_xform2_apply(m, in[i]);
}

void fx_xform2_apply_int(const fx_xform2 *m, int32_t x, int32_t y, int32_t *ox, int32_t *oy)
{
    if (!is_affine(m)) {
        fx_pt16 p = {fx16_from_int(x), fx16_from_int(y)};
        p = fx_xform2_apply(m, p);
        *ox = fx16_round(p.x);
        *oy = fx16_round(p.y);
        return;
    }
    fx_s128 X, Y;
    apply_raw(m, (int64_t)x * ONE, (int64_t)y * ONE, &X, &Y);
    /* Q32 -> nearest integer, ties toward +inf */
    fx_s128 h = fx_w_mul(ONE / 2, ONE);
    *ox = fx_sat32(fx_w_floordiv(fx_w_add(X, h), ONE * ONE));
    *oy = fx_sat32(fx_w_floordiv(fx_w_add(Y, h), ONE * ONE));
}

int fx_ctx_transformed(const fx_ctx *c) { return c->xform && !fx_xform2_is_identity(c->xform); }

void fx_ctx_map(const fx_ctx *c, int32_t x, int32_t y, int32_t *ox, int32_t *oy)
{
    if (!c->xform) {
        *ox = x;
        *oy = y;
        return;
    }
    fx_xform2_apply_int(c->xform, x, y, ox, oy);
}

/* A corner in raw Q16.16 (any int64), mapped and saturated into fx_pt16. */
static fx_pt16 map_corner(const fx_xform2 *m, int64_t x, int64_t y)
{
    fx_s128 X, Y;
    apply_raw(m, x, y, &X, &Y);
    fx_pt16 r = {round16(X), round16(Y)};
    return r;
}

void fx_xform_fill_rect(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (!fx_ctx_transformed(c)) {
        fx_fill_rect(c, x, y, w, h);
        return;
    }
    if (w <= 0 || h <= 0)
        return;
    /* The pixel-edge rectangle [x - 1/2, x + w - 1/2] x [y - 1/2, y + h - 1/2]
     * in centre coordinates: the region whose centres fx_fill_rect covers. */
    int64_t x0 = (int64_t)x * ONE - ONE / 2, y0 = (int64_t)y * ONE - ONE / 2;
    int64_t x1 = x0 + (int64_t)w * ONE, y1 = y0 + (int64_t)h * ONE;
    fx_pt16 p[4] = {map_corner(c->xform, x0, y0), map_corner(c->xform, x1, y0),
                    map_corner(c->xform, x1, y1), map_corner(c->xform, x0, y1)};
    int starts[2] = {0, 4};
    fx_poly_fill16(c, p, starts, 1);
}

void fx_xform_rect_outline(const fx_ctx *c, int32_t x, int32_t y, int32_t w, int32_t h)
{
    if (!fx_ctx_transformed(c)) {
        fx_rect_outline(c, x, y, w, h);
        return;
    }
    if (w <= 0 || h <= 0)
        return;
    int32_t xr = fx_sat32((int64_t)x + w - 1), yb = fx_sat32((int64_t)y + h - 1);
    int32_t px[4], py[4];
    fx_ctx_map(c, x, y, &px[0], &py[0]);
    fx_ctx_map(c, xr, y, &px[1], &py[1]);
    fx_ctx_map(c, xr, yb, &px[2], &py[2]);
    fx_ctx_map(c, x, yb, &px[3], &py[3]);
    if (w == 1 || h == 1) {
        fx_line(c, px[0], py[0], px[2], py[2]);
        return;
    }
    /* Each side without its last pixel, so every corner is drawn once (it
     * matters with blending). */
    for (int i = 0; i < 4; i++) {
        int j = (i + 1) & 3;
        fx_bres b;
        fx_bres_init(&b, px[i], py[i], px[j], py[j]);
        if (b.major)
            fx_line_steps(c, px[i], py[i], px[j], py[j], 0, b.major - 1);
        else
            fx_plot(c, px[i], py[i]);
    }
}
