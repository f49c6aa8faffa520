/* SPDX-License-Identifier: MIT */
/* fixel — GL-rules rasterization for the GLUT layer: points, diamond-exit
 * lines and triangles with llvmpipe's ties, the per-fragment operations
 * (scissor, depth, texture, blend, mask) and clip-space clipping. See
 * fixel/glcore.h for the rules. Integer only, freestanding. */
#include "fixel/fill.h"
#include "fixel/glcore.h"
#include "../base/fx_internal.h"
#include "../fill/tri_walk.h"

static inline int64_t floordiv(int64_t a, int64_t b) /* b > 0 */
{
    int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
static inline int64_t ceildiv(int64_t a, int64_t b) { return -floordiv(-a, b); }

static inline int32_t level(fx16 c) /* [0, 1] -> 0..255, round(c * 255) */
{
    if (c <= 0)
        return 0;
    if (c >= FX16_ONE)
        return 255;
    return (int32_t)(((int64_t)c * 255 + 0x8000) >> 16);
}

/* round((c + w) * k / w) for any c and w > 0: c + w overflows only for
 * c beyond 2^63 - w, and then (c + w) k / w = c k / w + k is taken apart
 * (k an integer, so the rounding is the same but for an exact tie). */
static int64_t ndc_scale(fx32 c, fx32 w, int64_t k)
{
    fx32 s;
    if (!__builtin_add_overflow(c, w, &s))
        return fx_muldiv64(s, k, w);
    int64_t q = fx_muldiv64(c, k, w);
    return q > INT64_MAX - k ? INT64_MAX : q + k;
}
static inline int64_t clamp_win(int64_t v)
{
    return v < -FX_GL_WIN_MAX ? -FX_GL_WIN_MAX : v > FX_GL_WIN_MAX ? FX_GL_WIN_MAX : v;
}

/* Bound: vx, vy, vw, vh are int32 (vw * 128 < 2^38); the quotient is
 * saturating and the window coordinates are clamped to +-FX_GL_WIN_MAX
 * (2^29 in 1/256 pixel: 2^21 pixels, twice the guard band), the range the
 * rasterizers below are proved for. */
int fx_gl_to_window(const fx_glv4 *p, int32_t vx, int32_t vy, int32_t vw, int32_t vh,
                    fx_gl_wvert *o)
{
    if (p->w <= 0)
        return -1;
    o->x = clamp_win(clamp_win((int64_t)vx * 256) + clamp_win(ndc_scale(p->x, p->w, (int64_t)vw * 128)));
    o->y = clamp_win(clamp_win((int64_t)vy * 256) + clamp_win(ndc_scale(p->y, p->w, (int64_t)vh * 128)));
    int64_t z = ndc_scale(p->z, p->w, (int64_t)1 << 23);
    o->z = z < 0 ? 0 : z > 0xFFFFFF ? 0xFFFFFF : (int32_t)z;
    o->w = p->w;
    return 0;
}

/* Bound: window coordinates within +-2^29 (fx_gl_to_window's clamp):
 * differences < 2^30, products < 2^60, the difference of two < 2^61. */
int64_t fx_gl_area2(const fx_gl_wvert *a, const fx_gl_wvert *b, const fx_gl_wvert *c)
{
    return (b->x - a->x) * (c->y - a->y) - (c->x - a->x) * (b->y - a->y);
}

/* ---- fragments ---- */

static inline int32_t wrap_coord(int64_t i, int32_t n, int clamp)
{
    if (clamp)
        return i < 0 ? 0 : i >= n ? n - 1 : (int32_t)i;
    int64_t m = i % n;
    return (int32_t)(m < 0 ? m + n : m);
}

static void tex_sample(const fx_gl_texture *tx, fx16 s, fx16 t, int32_t out[4])
{
    if (!tx->linear) {
        int32_t i = wrap_coord(((int64_t)s * tx->w) >> 16, tx->w, tx->clamp_s);
        int32_t j = wrap_coord(((int64_t)t * tx->h) >> 16, tx->h, tx->clamp_t);
        const uint8_t *p = tx->rgba + ((size_t)j * tx->w + i) * 4;
        for (int k = 0; k < 4; k++)
            out[k] = p[k];
        return;
    }
    /* u = s * w - 1/2 in Q16 */
    int64_t u = (int64_t)s * tx->w - 0x8000, v = (int64_t)t * tx->h - 0x8000;
    int64_t i0 = u >> 16, j0 = v >> 16;
    int32_t fu = (int32_t)(u & 0xFFFF), fv = (int32_t)(v & 0xFFFF);
    int32_t ia = wrap_coord(i0, tx->w, tx->clamp_s), ib = wrap_coord(i0 + 1, tx->w, tx->clamp_s);
    int32_t ja = wrap_coord(j0, tx->h, tx->clamp_t), jb = wrap_coord(j0 + 1, tx->h, tx->clamp_t);
    const uint8_t *p00 = tx->rgba + ((size_t)ja * tx->w + ia) * 4;
    const uint8_t *p10 = tx->rgba + ((size_t)ja * tx->w + ib) * 4;
    const uint8_t *p01 = tx->rgba + ((size_t)jb * tx->w + ia) * 4;
    const uint8_t *p11 = tx->rgba + ((size_t)jb * tx->w + ib) * 4;
    for (int k = 0; k < 4; k++) {
        int64_t top = (int64_t)p00[k] * (0x10000 - fu) + (int64_t)p10[k] * fu;
        int64_t bot = (int64_t)p01[k] * (0x10000 - fu) + (int64_t)p11[k] * fu;
        out[k] = (int32_t)((top * (0x10000 - fv) + bot * fv + ((int64_t)1 << 31)) >> 32);
    }
}

static inline int32_t mul255(int32_t a, int32_t b) { return (a * b + 127) / 255; }

static int32_t bfactor(int f, int ch, const int32_t s[4], const int32_t d[4])
{
    switch (f) {
    case FX_GL_BF_ZERO: return 0;
    case FX_GL_BF_ONE: return 255;
    case FX_GL_BF_SRC_COLOR: return s[ch];
    case FX_GL_BF_ONE_MINUS_SRC_COLOR: return 255 - s[ch];
    case FX_GL_BF_SRC_ALPHA: return s[3];
    case FX_GL_BF_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
    case FX_GL_BF_DST_ALPHA: return d[3];
    case FX_GL_BF_ONE_MINUS_DST_ALPHA: return 255 - d[3];
    case FX_GL_BF_DST_COLOR: return d[ch];
    case FX_GL_BF_ONE_MINUS_DST_COLOR: return 255 - d[ch];
    case FX_GL_BF_SRC_ALPHA_SATURATE:
        if (ch == 3)
            return 255;
        return s[3] < 255 - d[3] ? s[3] : 255 - d[3];
    default: return 255;
    }
}

/* The depth test alone (frag, plain_frag, and the triangle loop before the colour is computed). */
static inline int depth_pass(const fx_gl_target *t, uint32_t z, uint32_t d)
{
    switch (t->depth_func) {
    case FX_GL_DEPTH_NEVER: return 0;
    case FX_GL_DEPTH_LESS: return z < d;
    case FX_GL_DEPTH_EQUAL: return z == d;
    case FX_GL_DEPTH_LEQUAL: return z <= d;
    case FX_GL_DEPTH_GREATER: return z > d;
    case FX_GL_DEPTH_NOTEQUAL: return z != d;
    case FX_GL_DEPTH_GEQUAL: return z >= d;
    default: return 1;
    }
}
/* One fragment at window pixel (X, Y) (inside t->clip); c: 0..255 rgba. */
static void frag(fx_gl_target *t, int32_t X, int32_t Y, uint32_t z, int32_t c[4], fx16 s,
                 fx16 tt)
{
    int32_t row = t->surf.h - 1 - Y;
    if (t->depth && t->depth_test) {
        uint32_t *dp = &t->depth[(size_t)row * (size_t)t->surf.w + (size_t)X];
        if (!depth_pass(t, z, *dp))
            return;
        if (t->depth_write)
            *dp = z;
    }
    if (t->tex) {
        int32_t tc[4];
        tex_sample(t->tex, s, tt, tc);
        switch (t->tex_env) {
        case FX_GL_TEX_REPLACE:
            for (int k = 0; k < 4; k++)
                c[k] = tc[k];
            break;
        case FX_GL_TEX_DECAL:
            for (int k = 0; k < 3; k++)
                c[k] = mul255(c[k], 255 - tc[3]) + mul255(tc[k], tc[3]);
            break;
        case FX_GL_TEX_ADD:
            for (int k = 0; k < 3; k++)
                c[k] = c[k] + tc[k] > 255 ? 255 : c[k] + tc[k];
            c[3] = mul255(c[3], tc[3]);
            break;
        case FX_GL_TEX_BLEND:
            for (int k = 0; k < 3; k++)
                c[k] = mul255(c[k], 255 - tc[k]) + mul255(level(t->tex_env_color[k]), tc[k]);
            c[3] = mul255(c[3], tc[3]);
            break;
        default:
            for (int k = 0; k < 4; k++)
                c[k] = mul255(c[k], tc[k]);
            break;
        }
    }
    uint32_t mask = t->color_mask ? t->color_mask : 0xF;
    if (t->blend || mask != 0xF) {
        fx_color dc = fx_unpack(t->surf.format, fx_surface_get_native(&t->surf, X, row));
        int32_t d[4] = {(int32_t)(dc >> 16) & 255, (int32_t)(dc >> 8) & 255, (int32_t)dc & 255,
                        (int32_t)(dc >> 24) & 255};
        if (t->blend) {
            int32_t r[4];
            for (int k = 0; k < 4; k++) {
                int32_t v = (c[k] * bfactor(t->bf_src, k, c, d) +
                             d[k] * bfactor(t->bf_dst, k, c, d) + 127) / 255;
                r[k] = v > 255 ? 255 : v;
            }
            for (int k = 0; k < 4; k++)
                c[k] = r[k];
        }
        for (int k = 0; k < 4; k++)
            if (!(mask & (1u << k)))
                c[k] = d[k];
    }
    fx_color out = ((fx_color)c[3] << 24) | ((fx_color)c[0] << 16) | ((fx_color)c[1] << 8) |
                   (fx_color)c[2];
    if (t->surf.format == FX_FMT_XRGB8888) /* the layer's own buffers: a plain store */
        ((uint32_t *)(t->surf.pixels + (intptr_t)row * t->surf.stride))[X] = out & 0xFFFFFFu; /* fx_pack's XRGB */
    else
        fx_surface_put_native(&t->surf, X, row, fx_pack(t->surf.format, out));
}

static inline int in_clip(const fx_gl_target *t, int64_t X, int64_t Y)
{
    return X >= t->clip.x0 && X < t->clip.x1 && Y >= t->clip.y0 && Y < t->clip.y1;
}

/* ---- points ---- */
/* Bound: size clamped to [1, FX_GL_MAX_SIZE], so h < 2^23 and v +- h
 * stays in int64 for any v; the loops run over the clip rectangle only. */
void fx_gl_point(fx_gl_target *t, const fx_gl_wvert *v, int32_t size)
{
    if (size < 1)
        size = 1;
    if (size > FX_GL_MAX_SIZE)
        size = FX_GL_MAX_SIZE;
    int64_t h = (int64_t)size * 128;
    int64_t x0 = floordiv(v->x - h - 128, 256) + 1, x1 = floordiv(v->x + h - 128, 256);
    int64_t y0 = floordiv(v->y - h - 128, 256) + 1, y1 = floordiv(v->y + h - 128, 256);
    if (x0 < t->clip.x0) x0 = t->clip.x0;
    if (y0 < t->clip.y0) y0 = t->clip.y0;
    if (x1 >= t->clip.x1) x1 = t->clip.x1 - 1;
    if (y1 >= t->clip.y1) y1 = t->clip.y1 - 1;
    int32_t c[4];
    for (int64_t Y = y0; Y <= y1; Y++)
        for (int64_t X = x0; X <= x1; X++) {
            for (int k = 0; k < 4; k++)
                c[k] = level(v->c[k]);
            frag(t, (int32_t)X, (int32_t)Y, (uint32_t)v->z, c, v->s, v->t);
        }
}

/* ---- lines ---- */
static inline int64_t iabs64(int64_t v) { return v < 0 ? -v : v; }

/* Bound: end points within +-2^29 (fx_gl_to_window's clamp; others are
 * clamped here too) and width <= FX_GL_MAX_SIZE: adu < 2^30, so
 * v0 * adu < 2^59, (uc - u0) * dv < 2^61 and (hw + 128) * adu < 2^54.
 * The walk visits only the columns inside the clip rectangle (the
 * stipple counter is advanced over the others), so its work is bounded
 * by the surface, not by the line's length. */
void fx_gl_line(fx_gl_target *t, const fx_gl_wvert *a_in, const fx_gl_wvert *b_in, int32_t width,
                const fx16 *flat)
{
    fx_gl_wvert ac = *a_in, bc = *b_in;
    ac.x = clamp_win(ac.x), ac.y = clamp_win(ac.y), bc.x = clamp_win(bc.x), bc.y = clamp_win(bc.y);
    const fx_gl_wvert *a = &ac, *b = &bc;
    int64_t dx = b->x - a->x, dy = b->y - a->y;
    if (dx == 0 && dy == 0)
        return;
    if (width < 1)
        width = 1;
    if (width > FX_GL_MAX_SIZE)
        width = FX_GL_MAX_SIZE;
    int xmajor = iabs64(dx) >= iabs64(dy);
    /* u: major axis, v: minor axis */
    int64_t u0 = xmajor ? a->x : a->y, v0 = xmajor ? a->y : a->x;
    int64_t u1 = xmajor ? b->x : b->y, v1 = xmajor ? b->y : b->x;
    int64_t du = u1 - u0, dv = v1 - v0;
    int dir = du > 0 ? 1 : -1;
    int64_t adu = iabs64(du);
    /* rows whose centre is on the upper edge are in for rising x-major lines */
    int incl_high = xmajor && ((dx > 0) == (dy > 0)) && dy != 0;
    int64_t ulo = xmajor ? t->clip.x0 : t->clip.y0, uhi = xmajor ? t->clip.x1 : t->clip.y1;
    int64_t vlo = xmajor ? t->clip.y0 : t->clip.x0, vhi = xmajor ? t->clip.y1 : t->clip.x1;
    /* crossed columns: centres in [u0, u1) or (u1, u0] */
    int64_t cfirst, clast;
    if (dir > 0) {
        cfirst = ceildiv(u0 - 128, 256);
        clast = ceildiv(u1 - 128, 256) - 1;
    } else {
        cfirst = floordiv(u0 - 128, 256);
        clast = floordiv(u1 - 128, 256) + 1;
    }
    /* the start pixel when the line starts past its centre: lit iff inside its diamond */
    int64_t c0 = floordiv(u0, 256), c1 = floordiv(u1, 256);
    int64_t cen0 = c0 * 256 + 128, cen1 = c1 * 256 + 128;
    if ((dir > 0 && cen0 < u0) || (dir < 0 && cen0 > u0)) {
        int64_t vc = floordiv(v0, 256) * 256 + 128;
        if (iabs64(u0 - cen0) + iabs64(v0 - vc) < 128)
            cfirst = c0;
    }
    /* the end pixel, crossed, is left out when the line ends inside its diamond */
    if ((dir > 0 && cen1 < u1) || (dir < 0 && cen1 > u1)) {
        int64_t vc = floordiv(v1, 256) * 256 + 128;
        if (iabs64(u1 - cen1) + iabs64(v1 - vc) < 128)
            clast = c1 - dir;
    }
    if ((clast - cfirst) * dir < 0)
        return;
    int64_t n = (clast - cfirst) * dir + 1;
    int64_t hw = (int64_t)width * 128;
    int32_t cflat[4];
    if (flat)
        for (int k = 0; k < 4; k++)
            cflat[k] = level(flat[k]);
    /* the columns inside [ulo, uhi): i in [ifirst, ilast] */
    int64_t ifirst = 0, ilast = n - 1;
    if (dir > 0) {
        if (ulo - cfirst > ifirst)
            ifirst = ulo - cfirst;
        if (uhi - 1 - cfirst < ilast)
            ilast = uhi - 1 - cfirst;
    } else {
        if (cfirst - (uhi - 1) > ifirst)
            ifirst = cfirst - (uhi - 1);
        if (cfirst - ulo < ilast)
            ilast = cfirst - ulo;
    }
    if (ifirst > ilast) {
        if (t->stipple_on)
            t->stipple_count += (uint32_t)n;
        return;
    }
    /* the stipple pattern counts every pixel of the line, seen or not */
    if (t->stipple_on)
        t->stipple_count += (uint32_t)ifirst;
    for (int64_t i = ifirst; i <= ilast; i++) {
        int64_t col = cfirst + i * dir;
        if (t->stipple_on) {
            uint32_t f = t->stipple_factor > 0 ? (uint32_t)t->stipple_factor : 1u;
            uint32_t bit = (t->stipple_count / f) & 15u;
            t->stipple_count++;
            if (!((t->stipple_pattern >> bit) & 1u))
                continue;
        }
        if (col < ulo || col >= uhi)
            continue;
        int64_t uc = col * 256 + 128;
        /* line's v at uc: num / adu with num = v0*adu + (uc - u0)*dv*dir */
        int64_t num = v0 * adu + (uc - u0) * dv * dir;
        int64_t rlo, rhi;
        if (incl_high) {
            rlo = floordiv(num - (hw + 128) * adu, 256 * adu) + 1;
            rhi = floordiv(num + (hw - 128) * adu, 256 * adu);
        } else {
            rlo = ceildiv(num - (hw + 128) * adu, 256 * adu);
            rhi = ceildiv(num + (hw - 128) * adu, 256 * adu) - 1;
        }
        if (rlo < vlo)
            rlo = vlo;
        if (rhi >= vhi)
            rhi = vhi - 1;
        if (rlo > rhi)
            continue;
        /* attributes at parameter (uc - u0) / du, clamped to [0, 1] */
        int64_t pn = (uc - u0) * dir;
        if (pn < 0)
            pn = 0;
        if (pn > adu)
            pn = adu;
        int32_t c[4];
        if (flat) {
            for (int k = 0; k < 4; k++)
                c[k] = cflat[k];
        }
        uint32_t z = (uint32_t)(a->z + fx_muldiv64(b->z - a->z, pn, adu));
        fx16 s = (fx16)(a->s + fx_muldiv64(b->s - a->s, pn, adu));
        fx16 tt = (fx16)(a->t + fx_muldiv64(b->t - a->t, pn, adu));
        for (int64_t r = rlo; r <= rhi; r++) {
            if (!flat)
                for (int k = 0; k < 4; k++)
                    c[k] = level((fx16)(a->c[k] + fx_muldiv64(b->c[k] - a->c[k], pn, adu)));
            int32_t cc[4] = {c[0], c[1], c[2], c[3]};
            if (xmajor)
                frag(t, (int32_t)col, (int32_t)r, z, cc, s, tt);
            else
                frag(t, (int32_t)r, (int32_t)col, z, cc, s, tt);
        }
    }
    if (t->stipple_on)
        t->stipple_count += (uint32_t)(n - 1 - ilast);
}

/* ---- triangles ---- */
/* The common fragment: no texture, no blending, all channels written, the
 * layer's XRGB8888 buffer: depth test and store inline (frag() does the
 * same, generally). */
static inline int plain_target(const fx_gl_target *t)
{
    return !t->tex && !t->blend && (t->color_mask == 0 || t->color_mask == 0xF) &&
           t->surf.format == FX_FMT_XRGB8888;
}
static inline void plain_frag(const fx_gl_target *t, uint32_t *px, uint32_t *dp, uint32_t z,
                              const int32_t c[4])
{
    if (dp) {
        if (!depth_pass(t, z, *dp))
            return;
        if (t->depth_write)
            *dp = z;
    }
    *px = ((uint32_t)c[0] << 16) | ((uint32_t)c[1] << 8) | (uint32_t)c[2];
}

/* The perspective-correct weights of vertices 1 and 2 (Q16, clamped to
 * the triangle) from the interpolated q, l1 q, l2 q at val[kq..kq+2]: one
 * division, Q and the L (<= Q inside) shifted so that Q has 31 bits, times
 * 2^62 / Q. */
static inline void persp_weights(const uint64_t *val, int kq, int64_t *w1, int64_t *w2)
{
    int64_t Qv = (int64_t)val[kq], L1 = (int64_t)val[kq + 1], L2 = (int64_t)val[kq + 2];
    if (Qv < 1)
        Qv = 1;
    int sh = 33 - __builtin_clzll((uint64_t)Qv);
    if (sh < 0)
        sh = 0;
    uint64_t qn = (uint64_t)Qv >> sh;
    if (qn == 0)
        qn = 1;
    uint64_t inv = ((uint64_t)1 << 62) / qn;
    L1 = L1 < 0 ? 0 : L1 > Qv ? Qv : L1;
    L2 = L2 < 0 ? 0 : L2 > Qv ? Qv : L2;
    int64_t l1 = (int64_t)((((uint64_t)L1 >> sh) * inv) >> 46);
    int64_t l2 = (int64_t)((((uint64_t)L2 >> sh) * inv) >> 46);
    l1 = l1 < 0 ? 0 : l1 > FX16_ONE ? FX16_ONE : l1;
    l2 = l2 < 0 ? 0 : l2 > FX16_ONE - l1 ? FX16_ONE - l1 : l2;
    *w1 = l1, *w2 = l2;
}
/* The depth comparison with the function as a constant where the caller
 * passes one (the span loops below are specialised per function, so the
 * switch of depth_pass leaves the per-pixel path); -1: t's function. */
static inline __attribute__((always_inline)) int depth_cmp(const fx_gl_target *t, int func,
                                                           uint32_t z, uint32_t d)
{
    switch (func) {
    case FX_GL_DEPTH_LESS: return z < d;
    case FX_GL_DEPTH_LEQUAL: return z <= d;
    default: return depth_pass(t, z, d);
    }
}

/* One span of a perspective-correct Gouraud triangle on the plain target
 * with the depth test: the general loop of persp_triangle with the
 * attributes in registers, the depth function fixed, no alpha (the XRGB
 * store drops it), and what cannot change a value left out (same bits):
 *  - no colour clamp: with both weights in [0, 1] and their sum <= 1
 *    every level is a convex combination of the vertex levels, in
 *    [0, 255 * 2^16] after rounding;
 *  - persp_weights inline for q >= 2^31 (always, inside the triangle: q is
 *    at least 2^32 there), where its guards on q and the shift are idle,
 *    and without the clamp of l1 to [0, 1]: L1 <= Q makes
 *    (L1 >> sh) * inv <= (Q >> sh) * (2^62 / (Q >> sh)) <= 2^62;
 *  - the depth's rounding bias added once, the clamp as a rare branch;
 *  - only the depth stepped along the span: a pixel that passes takes q,
 *    l1 q, l2 q as their row value (c + gy y) plus x gradients, the value
 *    fx_tri_attr_at gives (products modulo 2^64, the same bits as stepping
 *    pixel by pixel), so a hidden pixel costs the depth test alone; the
 *    depth function and depth writes are constants of each copy of the
 *    loop.
 * (Two passes, the depth tests first and then the colours of the pixels
 * that passed, ran slower here: the spans are a few pixels long.) */
static inline __attribute__((always_inline)) void
persp_span_plain(const fx_gl_target *t, int func, int dw, uint32_t *prow, uint32_t *drow,
                 int32_t x0, int32_t x1, uint64_t vz, const uint64_t row[3], const uint64_t g[4],
                 const int64_t c0h[3], const int64_t d1[3], const int64_t d2[3])
{
    vz += 0x80000000u;
    const uint64_t gz = g[0];
    for (int32_t x = x0; x < x1; x++, vz += gz) {
        int32_t zz = (int32_t)((int64_t)vz >> 32); /* fx_tri_attr_round */
        uint32_t z = (uint32_t)zz;
        if (__builtin_expect(z > 0xFFFFFF, 0))
            z = zz < 0 ? 0 : 0xFFFFFF;
        if (!depth_cmp(t, func, z, drow[x]))
            continue;
        if (dw)
            drow[x] = z;
        const uint64_t ux = (uint64_t)(int64_t)x;
        const uint64_t vq = row[0] + g[1] * ux, v1 = row[1] + g[2] * ux, v2 = row[2] + g[3] * ux;
        int64_t l1, l2, Qv = (int64_t)vq;
        if (__builtin_expect(Qv >= ((int64_t)1 << 31), 1)) {
            int sh = 33 - __builtin_clzll((uint64_t)Qv);
            uint64_t inv = ((uint64_t)1 << 62) / ((uint64_t)Qv >> sh);
            int64_t L1 = (int64_t)v1, L2 = (int64_t)v2;
            L1 = L1 < 0 ? 0 : L1 > Qv ? Qv : L1;
            L2 = L2 < 0 ? 0 : L2 > Qv ? Qv : L2;
            l1 = (int64_t)((((uint64_t)L1 >> sh) * inv) >> 46);
            l2 = (int64_t)((((uint64_t)L2 >> sh) * inv) >> 46);
            l2 = l2 > FX16_ONE - l1 ? FX16_ONE - l1 : l2;
        } else {
            uint64_t q3[3] = {vq, v1, v2};
            persp_weights(q3, 0, &l1, &l2);
        }
        uint32_t r = (uint32_t)((c0h[0] + ((l1 * d1[0] + l2 * d2[0] + 0x8000) >> 16)) >> 16);
        uint32_t gg = (uint32_t)((c0h[1] + ((l1 * d1[1] + l2 * d2[1] + 0x8000) >> 16)) >> 16);
        uint32_t b = (uint32_t)((c0h[2] + ((l1 * d1[2] + l2 * d2[2] + 0x8000) >> 16)) >> 16);
        prow[x] = (r << 16) | (gg << 8) | b;
    }
}

/* The spans of such a triangle, the walk stepped inline (tri_walk.h). */
static inline __attribute__((always_inline)) void
persp_plain(const fx_gl_target *t, int func, int dw, fx_tri *tri, const int64_t c0[4],
            const int64_t d1[6], const int64_t d2[6])
{
    const int64_t c0h[3] = {c0[0] + 0x8000, c0[1] + 0x8000, c0[2] + 0x8000};
    const int64_t e1[3] = {d1[0], d1[1], d1[2]}, e2[3] = {d2[0], d2[1], d2[2]};
    const uint64_t g[4] = {tri->gx[0], tri->gx[1], tri->gx[2], tri->gx[3]};
    uint8_t *pixels = t->surf.pixels;
    const int32_t h1 = t->surf.h - 1, stride = t->surf.stride;
    uint32_t *depth = t->depth;
    const size_t dstride = (size_t)t->surf.w;
    fx_tri_span sp;
    while (tri_next(tri, &sp)) {
        const uint64_t uy = (uint64_t)(int64_t)sp.y;
        const uint64_t rowv[3] = {tri->c[1] + tri->gy[1] * uy, tri->c[2] + tri->gy[2] * uy,
                                  tri->c[3] + tri->gy[3] * uy};
        int32_t row = h1 - sp.y;
        uint32_t *prow = (uint32_t *)(pixels + (intptr_t)row * stride);
        uint32_t *drow = depth + (size_t)row * dstride;
        persp_span_plain(t, func, dw, prow, drow, sp.x0, sp.x1, fx_tri_attr_at(tri, 0, sp.x0, sp.y),
                         rowv, g, c0h, e1, e2);
    }
}

/* Perspective-correct colours and texture coordinates: the attributes
 * interpolated in window space are 1/w (q, normalised to 2^22 at the
 * nearest vertex, which keeps sliver triangles' gradients in range) and the
 * barycentric weights of vertices 1 and 2 times q; per pixel the weights
 * are their quotients (Q16), clamped to the triangle (a covered centre is
 * inside; only rounding takes a weight out), and every attribute is
 * a0 + l1 (a1 - a0) + l2 (a2 - a0). */
static void persp_triangle(fx_gl_target *t, const fx_gl_wvert *const v[3], const fx8 xy[6],
                           int use_z, int use_c, int use_t, const fx16 *flat)
{
    fx32 wmin = v[0]->w;
    for (int i = 1; i < 3; i++)
        if (v[i]->w < wmin)
            wmin = v[i]->w;
    int32_t q[3];
    for (int i = 0; i < 3; i++) {
        int64_t qi = fx_muldiv64(wmin, (int64_t)1 << 22, v[i]->w);
        q[i] = qi < 1 ? 1 : (int32_t)qi;
    }
    int na = use_z ? 4 : 3, kq = use_z ? 1 : 0;
    int32_t attr[3 * 4];
    for (int i = 0; i < 3; i++) {
        int32_t *p = attr + i * na;
        if (use_z)
            p[0] = v[i]->z;
        p[kq] = q[i];
        p[kq + 1] = i == 1 ? q[1] : 0;
        p[kq + 2] = i == 2 ? q[2] : 0;
    }
    /* attribute deltas from vertex 0: colour levels in Q16, s and t */
    int64_t c0[4] = {0, 0, 0, 0}, d1[6] = {0}, d2[6] = {0};
    int64_t s0 = v[0]->s, t0 = v[0]->t;
    int plain = plain_target(t);
    /* the plain depth-tested Gouraud loop stores no alpha */
    int nc = plain && use_z && !use_t ? 3 : 4;
    if (use_c)
        for (int k = 0; k < nc; k++) {
            int64_t l[3];
            for (int i = 0; i < 3; i++) {
                fx16 cc = v[i]->c[k];
                l[i] = (int64_t)(cc < 0 ? 0 : cc > FX16_ONE ? FX16_ONE : cc) * 255;
            }
            c0[k] = l[0], d1[k] = l[1] - l[0], d2[k] = l[2] - l[0];
        }
    if (use_t) {
        d1[4] = (int64_t)v[1]->s - s0, d2[4] = (int64_t)v[2]->s - s0;
        d1[5] = (int64_t)v[1]->t - t0, d2[5] = (int64_t)v[2]->t - t0;
    }
    fx_tri tri;
    if (fx_tri_begin(&tri, t->clip, xy, attr, na) <= 0)
        return;
    int32_t cf[4] = {0, 0, 0, 0};
    if (flat)
        for (int k = 0; k < 4; k++)
            cf[k] = level(flat[k]);
    fx_tri_span sp;
    if (plain && use_z && use_c && !use_t) {
        if (t->depth_func == FX_GL_DEPTH_LESS && t->depth_write)
            persp_plain(t, FX_GL_DEPTH_LESS, 1, &tri, c0, d1, d2);
        else if (t->depth_func == FX_GL_DEPTH_LEQUAL && t->depth_write)
            persp_plain(t, FX_GL_DEPTH_LEQUAL, 1, &tri, c0, d1, d2);
        else
            persp_plain(t, -1, t->depth_write, &tri, c0, d1, d2);
        return;
    }
    while (tri_next(&tri, &sp)) {
        uint64_t val[4];
        for (int k = 0; k < na; k++)
            val[k] = fx_tri_attr_at(&tri, k, sp.x0, sp.y);
        int32_t row = t->surf.h - 1 - sp.y;
        uint32_t *prow = (uint32_t *)(t->surf.pixels + (intptr_t)row * t->surf.stride);
        uint32_t *drow = use_z ? t->depth + (size_t)row * (size_t)t->surf.w : 0;
        for (int32_t x = sp.x0; x < sp.x1; x++) {
            int32_t col[4] = {cf[0], cf[1], cf[2], cf[3]};
            uint32_t z = 0;
            fx16 s = 0, tt = 0;
            if (use_z) {
                int32_t zz = fx_tri_attr_round(val[0]);
                z = zz < 0 ? 0 : zz > 0xFFFFFF ? 0xFFFFFF : (uint32_t)zz;
                /* early depth test: a hidden fragment costs no division */
                if (plain && !depth_pass(t, z, drow[x])) {
                    for (int k = 0; k < na; k++)
                        val[k] += tri.gx[k];
                    continue;
                }
            }
            int64_t l1, l2;
            persp_weights(val, kq, &l1, &l2);
            if (use_c)
                for (int k = 0; k < 4; k++) {
                    int64_t l = c0[k] + ((l1 * d1[k] + l2 * d2[k] + 0x8000) >> 16); /* level, Q16 */
                    l = (l + 0x8000) >> 16;
                    col[k] = l < 0 ? 0 : l > 255 ? 255 : (int32_t)l;
                }
            if (use_t) {
                s = (fx16)(s0 + ((l1 * d1[4] + l2 * d2[4] + 0x8000) >> 16));
                tt = (fx16)(t0 + ((l1 * d1[5] + l2 * d2[5] + 0x8000) >> 16));
            }
            if (plain)
                plain_frag(t, prow + x, drow ? drow + x : 0, z, col);
            else
                frag(t, x, sp.y, z, col, s, tt);
            for (int k = 0; k < na; k++)
                val[k] += tri.gx[k];
        }
    }
}

/* 1 when a GL_LESS / GL_LEQUAL depth-tested triangle cannot pass the test
 * anywhere: every stored depth in its bounding box is at or before its
 * nearest vertex. Its fragments' depths are values of the plane through
 * the vertices' z at pixel centres inside it, so at least the smallest
 * vertex z (less one for the rounding). Such a triangle changes no pixel
 * and is left out before its set-up: hidden back faces of a closed mesh
 * cost a scan of stored depths instead of edges, planes and spans. The
 * scan stops at the first depth behind the triangle (a visible triangle
 * costs a few reads) and is not tried where the box is much larger than
 * the triangle (slivers) or large. */
static int hidden_by_depth(const fx_gl_target *t, const fx_gl_wvert *const v[3], const fx8 xy[6])
{
    int32_t zmin = v[0]->z;
    for (int i = 1; i < 3; i++)
        zmin = v[i]->z < zmin ? v[i]->z : zmin;
    int64_t need = (int64_t)zmin - 1 - (t->depth_func == FX_GL_DEPTH_LEQUAL);
    if (need < 0)
        return 0;
    fx8 xmin = xy[0], xmax = xy[0], ymin = xy[1], ymax = xy[1];
    for (int i = 1; i < 3; i++) {
        xmin = xy[2 * i] < xmin ? xy[2 * i] : xmin, xmax = xy[2 * i] > xmax ? xy[2 * i] : xmax;
        ymin = xy[2 * i + 1] < ymin ? xy[2 * i + 1] : ymin;
        ymax = xy[2 * i + 1] > ymax ? xy[2 * i + 1] : ymax;
    }
    /* a covered pixel X has its (shifted) centre X in [xmin, xmax] / 256 */
    int64_t X0 = ((int64_t)xmin + 255) >> 8, X1 = (int64_t)xmax >> 8;
    int64_t Y0 = ((int64_t)ymin + 255) >> 8, Y1 = (int64_t)ymax >> 8;
    X0 = X0 < t->clip.x0 ? t->clip.x0 : X0, X1 = X1 >= t->clip.x1 ? t->clip.x1 - 1 : X1;
    Y0 = Y0 < t->clip.y0 ? t->clip.y0 : Y0, Y1 = Y1 >= t->clip.y1 ? t->clip.y1 - 1 : Y1;
    if (X0 > X1 || Y0 > Y1)
        return 0;
    int64_t box = (X1 - X0 + 1) * (Y1 - Y0 + 1);
    int64_t area2 = ((int64_t)(xy[2] - xy[0]) * (xy[5] - xy[1]) - (int64_t)(xy[4] - xy[0]) * (xy[3] - xy[1])) >> 16;
    if (area2 < 0)
        area2 = -area2;
    if (box > 4096 || box > 4 * area2 + 64) /* pixels; area2 is twice the area */
        return 0;
    const uint32_t lim = (uint32_t)need;
    for (int64_t Y = Y0; Y <= Y1; Y++) {
        const uint32_t *d = t->depth + (size_t)(t->surf.h - 1 - Y) * (size_t)t->surf.w;
        for (int64_t X = X0; X <= X1; X++)
            if (d[X] > lim)
                return 0;
    }
    return 1;
}

/* Bound: vertices come from fx_gl_to_window, within +-FX_GL_WIN_MAX =
 * 2^29 (1/256 pixel), so x - 128 fits the fx8 (int32) the span walker
 * takes, whose edge setup is exact for any int32 vertex (fill.c's
 * triangles); the GL layer clips to its guard band (+-2^28) before. */
void fx_gl_triangle(fx_gl_target *t, const fx_gl_wvert *a, const fx_gl_wvert *b,
                    const fx_gl_wvert *c, const fx16 *flat)
{
    const fx_gl_wvert *v[3] = {a, b, c};
    fx8 xy[6];
    for (int i = 0; i < 3; i++) {
        xy[2 * i] = (fx8)(v[i]->x - 128);
        xy[2 * i + 1] = (fx8)(v[i]->y - 128);
    }
    if (t->depth && t->depth_test &&
        (t->depth_func == FX_GL_DEPTH_LESS || t->depth_func == FX_GL_DEPTH_LEQUAL) &&
        hidden_by_depth(t, v, xy))
        return;
    int use_z = t->depth && t->depth_test;
    int use_c = flat == 0;
    int use_t = t->tex != 0;
    if ((use_c || use_t) && a->w > 0 && b->w > 0 && c->w > 0 && (a->w != b->w || a->w != c->w)) {
        persp_triangle(t, v, xy, use_z, use_c, use_t, flat);
        return;
    }
    int na = 0, kz = -1, kc = -1, kt = -1;
    if (use_z)
        kz = na, na += 1;
    if (use_c)
        kc = na, na += 4;
    if (use_t)
        kt = na, na += 2;
    int32_t attr[3 * FX_TRI_MAX_ATTR];
    for (int i = 0; i < 3; i++) {
        int32_t *p = attr + i * na;
        if (kz >= 0)
            p[kz] = v[i]->z;
        if (kc >= 0)
            for (int k = 0; k < 4; k++) {
                fx16 cc = v[i]->c[k];
                cc = cc < 0 ? 0 : cc > FX16_ONE ? FX16_ONE : cc;
                p[kc + k] = cc * 255;
            }
        if (kt >= 0) {
            p[kt] = v[i]->s;
            p[kt + 1] = v[i]->t;
        }
    }
    fx_tri tri;
    if (fx_tri_begin(&tri, t->clip, xy, attr, na) <= 0)
        return;
    int32_t cf[4] = {0, 0, 0, 0};
    if (flat)
        for (int k = 0; k < 4; k++)
            cf[k] = level(flat[k]);
    int plain = plain_target(t);
    fx_tri_span sp;
    while (tri_next(&tri, &sp)) {
        uint64_t val[FX_TRI_MAX_ATTR];
        for (int k = 0; k < na; k++)
            val[k] = fx_tri_attr_at(&tri, k, sp.x0, sp.y);
        int32_t row = t->surf.h - 1 - sp.y;
        uint32_t *prow = (uint32_t *)(t->surf.pixels + (intptr_t)row * t->surf.stride);
        uint32_t *drow = kz >= 0 ? t->depth + (size_t)row * (size_t)t->surf.w : 0;
        for (int32_t x = sp.x0; x < sp.x1; x++) {
            int32_t col[4] = {cf[0], cf[1], cf[2], cf[3]};
            uint32_t z = 0;
            fx16 s = 0, tt = 0;
            if (kz >= 0) {
                int32_t zz = fx_tri_attr_round(val[kz]);
                z = zz < 0 ? 0 : zz > 0xFFFFFF ? 0xFFFFFF : (uint32_t)zz;
            }
            if (kc >= 0)
                for (int k = 0; k < 4; k++) {
                    int64_t l = ((int64_t)(val[kc + k] + ((uint64_t)1 << 47))) >> 48;
                    col[k] = l < 0 ? 0 : l > 255 ? 255 : (int32_t)l;
                }
            if (kt >= 0) {
                s = fx_tri_attr_round(val[kt]);
                tt = fx_tri_attr_round(val[kt + 1]);
            }
            if (plain)
                plain_frag(t, prow + x, drow ? drow + x : 0, z, col);
            else
                frag(t, x, sp.y, z, col, s, tt);
            for (int k = 0; k < na; k++)
                val[k] += tri.gx[k];
        }
    }
}

void fx_gl_clear(fx_gl_target *t, fx_rect r, fx_color c, int color, uint32_t depth, int depth_on)
{
    fx_rect s = {0, 0, t->surf.w, t->surf.h};
    r = fx_rect_intersect(r, s);
    if (fx_rect_empty(r))
        return;
    /* window rows r.y0..r.y1 are surface rows h - r.y1 .. h - r.y0 */
    fx_rect sr = {r.x0, t->surf.h - r.y1, r.x1, t->surf.h - r.y0};
    if (color)
        fx_rect_fill_native(&t->surf, sr, fx_pack(t->surf.format, c));
    /* the colour's solid runs for the depth rows too: a whole-width clear
     * (every frame's glClear) is one run over the buffer */
    if (depth_on && t->depth) {
        size_t w = (size_t)t->surf.w;
        if (sr.x0 == 0 && sr.x1 == t->surf.w && (size_t)(sr.y1 - sr.y0) * w <= INT32_MAX)
            fx_run32(t->depth + (size_t)sr.y0 * w, (int32_t)((size_t)(sr.y1 - sr.y0) * w), depth);
        else
            for (int32_t y = sr.y0; y < sr.y1; y++)
                fx_run32(t->depth + (size_t)y * w + (size_t)sr.x0, sr.x1 - sr.x0, depth);
    }
}

/* ---- clipping ---- */
/* Bound: clip coordinates anywhere in int64; the distances saturate (a
 * saturated distance keeps its sign, which is all the clipper tests, and
 * the interpolation parameter da / (da - db) stays in [0, 1]). */
static fx32 plane_dist(const fx_glv4 *p, int i, fx32 g)
{
    fx32 gw = g == FX32_ONE ? p->w : fx32_mul(g, p->w);
    switch (i) {
    case 0: return fx32_sub(gw, p->x);
    case 1: return fx32_add(gw, p->x);
    case 2: return fx32_sub(gw, p->y);
    case 3: return fx32_add(gw, p->y);
    case 4: return fx32_sub(p->w, p->z);
    default: return fx32_add(p->w, p->z);
    }
}

static void lerp_cvert(const fx_gl_cvert *a, const fx_gl_cvert *b, fx32 num, fx32 den,
                       fx_gl_cvert *o)
{
    /* 0 <= num <= den: a + (b - a) num / den lies between a and b when
     * b - a fits; when it saturates the sum is saturating too */
    o->p.x = fx32_add(a->p.x, fx_muldiv64(fx32_sub(b->p.x, a->p.x), num, den));
    o->p.y = fx32_add(a->p.y, fx_muldiv64(fx32_sub(b->p.y, a->p.y), num, den));
    o->p.z = fx32_add(a->p.z, fx_muldiv64(fx32_sub(b->p.z, a->p.z), num, den));
    o->p.w = fx32_add(a->p.w, fx_muldiv64(fx32_sub(b->p.w, a->p.w), num, den));
    /* colours and texture coordinates take any fx16 (a texture coordinate
     * of -2^31 units came from the fuzzer): the difference in 64 bits, the
     * result between a and b, so it fits again */
    for (int k = 0; k < 4; k++) {
        o->c[k] = (fx16)(a->c[k] + fx_muldiv64((int64_t)b->c[k] - a->c[k], num, den));
        o->bc[k] = (fx16)(a->bc[k] + fx_muldiv64((int64_t)b->bc[k] - a->bc[k], num, den));
    }
    o->s = (fx16)(a->s + fx_muldiv64((int64_t)b->s - a->s, num, den));
    o->t = (fx16)(a->t + fx_muldiv64((int64_t)b->t - a->t, num, den));
}

int fx_gl_clip_line(fx_gl_cvert *a, fx_gl_cvert *b, fx32 g)
{
    for (int i = 0; i < 6; i++) {
        fx32 da = plane_dist(&a->p, i, g), db = plane_dist(&b->p, i, g);
        if (da < 0 && db < 0)
            return 0;
        if (da >= 0 && db >= 0)
            continue;
        fx_gl_cvert n;
        lerp_cvert(a, b, da, fx32_sub(da, db), &n);
        if (da < 0)
            *a = n;
        else
            *b = n;
    }
    return 1;
}

int fx_gl_clip_poly(const fx_gl_cvert *in, int n, fx_gl_cvert *out, fx_gl_cvert *tmp, fx32 g)
{
    /* quick accept */
    int all = 1;
    for (int j = 0; j < n && all; j++)
        for (int i = 0; i < 6; i++)
            if (plane_dist(&in[j].p, i, g) < 0) {
                all = 0;
                break;
            }
    if (all) {
        for (int j = 0; j < n; j++)
            out[j] = in[j];
        return n;
    }
    const fx_gl_cvert *src = in;
    fx_gl_cvert *bufs[2] = {out, tmp};
    int cur = 0, m = n;
    for (int i = 0; i < 6; i++) {
        /* alternate so that the result of plane 5 lands in out */
        fx_gl_cvert *dst = bufs[(i + 1) & 1 ? 1 : 0];
        (void)cur;
        int k = 0;
        for (int j = 0; j < m; j++) {
            const fx_gl_cvert *p = &src[j], *q = &src[(j + 1) % m];
            fx32 dp = plane_dist(&p->p, i, g), dq = plane_dist(&q->p, i, g);
            if (dp >= 0)
                dst[k++] = *p;
            if ((dp >= 0) != (dq >= 0))
                lerp_cvert(p, q, dp, fx32_sub(dp, dq), &dst[k++]);
        }
        m = k;
        src = dst;
        if (m < 3)
            return 0;
    }
    if (src != out)
        for (int j = 0; j < m; j++)
            out[j] = src[j];
    return m;
}

int fx_gl_point_visible(const fx_glv4 *p)
{
    return p->w > 0 && p->z <= p->w && p->z >= -p->w;
}
