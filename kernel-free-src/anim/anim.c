/* SPDX-License-Identifier: MIT */
/* fixel — animation: in-betweens of key frames, ease functions, morphing by
 * adding vertices, the bouncing ball, the accumulation buffer (anim.h). */
#include "fixel/anim.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

/* ---- ease functions ---- */

fx16 fx_anim_ease_apply(fx_anim_ease e, fx16 s)
{
    if (s <= 0)
        return 0;
    if (s >= FX16_ONE)
        return FX16_ONE;
    /* s in (0, 1): s << 14 is s quarter turns of a 2^32 turn */
    fx_angle q = (fx_angle)s << 14;
    switch (e) {
    case FX_EASE_IN: return FX16_ONE - fx_cos(q);
    case FX_EASE_OUT: return fx_sin(q);
    case FX_EASE_INOUT: return (FX16_ONE - fx_cos(q << 1) + 1) >> 1;
    case FX_EASE_SMOOTH: {
        int64_t s2 = (int64_t)s * s; /* Q32 */
        return (fx16)((s2 * (3 * FX16_ONE - 2 * (int64_t)s) + ((int64_t)1 << 31)) >> 32);
    }
    default: return s;
    }
}

fx16 fx_anim_lerp(fx16 a, fx16 b, fx16 s)
{
    return fx_sat32((int64_t)a + fx_mul64_shift((int64_t)b - a, s, 16));
}

fx_color fx_anim_color_lerp(fx_color a, fx_color b, fx16 s)
{
    if (s < 0)
        s = 0;
    if (s > FX16_ONE)
        s = FX16_ONE;
    fx_color out = 0;
    for (int sh = 0; sh < 32; sh += 8) {
        int32_t ca = (int32_t)(a >> sh & 255), cb = (int32_t)(b >> sh & 255);
        int32_t c = ca + (int32_t)(((int64_t)(cb - ca) * s + 32768) >> 16);
        out |= (fx_color)c << sh;
    }
    return out;
}

/* ---- key frames ---- */

static int track_ok(const fx_anim_track *tr)
{
    if (!tr || !tr->keys || tr->n < 1 || tr->nch < 1 || tr->nch > FX_ANIM_MAX_CH)
        return 0;
    for (int32_t i = 1; i < tr->n; i++)
        if (tr->keys[i].t <= tr->keys[i - 1].t)
            return 0;
    return 1;
}

/* Hermite tangent at key i scaled to the segment of length h: h * m_i. */
static int64_t tangent(const fx_anim_track *tr, int32_t i, int c, int64_t h)
{
    const fx_anim_key *k = tr->keys;
    int32_t lo = i > 0 ? i - 1 : i, hi = i < tr->n - 1 ? i + 1 : i;
    int64_t span = (int64_t)k[hi].t - k[lo].t; /* >= h > 0 */
    int64_t diff = (int64_t)k[hi].v[c] - k[lo].v[c];
    int64_t ratio = ((h << 30) + span / 2) / span; /* h / span in Q30, <= 1 */
    return fx_mul64_shift(diff, ratio, 30);
}

/* The un-eased track at u (clamped to the keys): the segment index. */
static int32_t eval_raw(const fx_anim_track *tr, int64_t u, fx16 *out)
{
    const fx_anim_key *k = tr->keys;
    int32_t n = tr->n, i;
    if (u <= k[0].t || n == 1) {
        i = 0;
        u = k[0].t;
    } else if (u >= k[n - 1].t) {
        i = n - 1;
        u = k[n - 1].t;
    } else {
        int32_t lo = 0, hi = n - 1; /* k[lo].t <= u < k[hi].t */
        while (hi - lo > 1) {
            int32_t mid = lo + (hi - lo) / 2;
            if (k[mid].t <= u)
                lo = mid;
            else
                hi = mid;
        }
        i = lo;
    }
    if (i == n - 1 || u == k[i].t || tr->interp == FX_ANIM_STEP) {
        for (int c = 0; c < tr->nch; c++)
            out[c] = k[i].v[c];
        return i;
    }
    int64_t h = (int64_t)k[i + 1].t - k[i].t;
    int64_t s = (((u - k[i].t) << 30) + h / 2) / h; /* Q30, in [0, 1) */
    int64_t s2 = (s * s + (1 << 29)) >> 30, s3 = (s2 * s + (1 << 29)) >> 30;
    for (int c = 0; c < tr->nch; c++) {
        int64_t p0 = k[i].v[c], d = (int64_t)k[i + 1].v[c] - p0, r;
        if (tr->interp == FX_ANIM_LINEAR) {
            r = p0 + fx_mul64_shift(d, s, 30);
        } else {
            int64_t m0 = tangent(tr, i, c, h), m1 = tangent(tr, i + 1, c, h);
            r = p0 + fx_mul64_shift(d, 3 * s2 - 2 * s3, 30) + fx_mul64_shift(m0, s3 - 2 * s2 + s, 30) +
                fx_mul64_shift(m1, s3 - s2, 30);
        }
        out[c] = fx_sat32(r);
    }
    return i;
}

/* t warped by the track's ease over [first key, last key]. */
static int64_t warp(const fx_anim_track *tr, fx16 t)
{
    int64_t t0 = tr->keys[0].t, t1 = tr->keys[tr->n - 1].t, span = t1 - t0;
    if (tr->ease == FX_EASE_NONE || span <= 0 || t <= t0 || t >= t1)
        return t;
    fx16 s = (fx16)((((int64_t)t - t0) * FX16_ONE + span / 2) / span);
    fx16 w = fx_anim_ease_apply((fx_anim_ease)tr->ease, s);
    return t0 + (span * w + FX16_ONE / 2) / FX16_ONE;
}

int fx_anim_eval(const fx_anim_track *tr, fx16 t, fx16 *out)
{
    if (!track_ok(tr))
        return -FX_EINVAL;
    return eval_raw(tr, warp(tr, t), out);
}

int fx_anim_tangent(const fx_anim_track *tr, fx16 t, fx16 *out)
{
    if (!track_ok(tr))
        return -FX_EINVAL;
    int64_t t0 = tr->keys[0].t, t1 = tr->keys[tr->n - 1].t;
    int64_t u = warp(tr, t), d = (t1 - t0) / 1024;
    if (d < 1)
        d = 1;
    int64_t ua = u - d < t0 ? t0 : u - d, ub = u + d > t1 ? t1 : u + d;
    if (ua > t1)
        ua = t1;
    if (ub < t0)
        ub = t0;
    fx16 a[FX_ANIM_MAX_CH], b[FX_ANIM_MAX_CH];
    eval_raw(tr, ua, a);
    int r = eval_raw(tr, ub, b);
    for (int c = 0; c < tr->nch; c++)
        out[c] = fx_sat32((int64_t)b[c] - a[c]);
    return r;
}

/* ---- morphing ---- */

/* a + (b - a) j / k rounded to nearest (ties away from zero). */
static fx16 section(fx16 a, fx16 b, int64_t j, int64_t k)
{
    int64_t num = ((int64_t)b - a) * j;
    int64_t q = num >= 0 ? (num + k / 2) / k : -((-num + k / 2) / k);
    return fx_sat32(a + q);
}

static void add_vertices(const fx16 *p, int32_t np, int32_t dim, int closed, int32_t lmax, fx16 *out)
{
    int32_t lmin = closed ? np : np - 1, ns = lmax / lmin, ne = lmax % lmin, o = 0;
    for (int32_t i = 0; i < lmin; i++) {
        int64_t k = ns + ((int64_t)(i + 1) * ne / lmin > (int64_t)i * ne / lmin);
        const fx16 *a = p + (size_t)i * dim, *b = p + (size_t)((i + 1) % np) * dim;
        for (int64_t j = 0; j < k; j++, o++)
            for (int32_t c = 0; c < dim; c++)
                out[(size_t)o * dim + c] = section(a[c], b[c], j, k);
    }
    if (!closed)
        for (int32_t c = 0; c < dim; c++)
            out[(size_t)o * dim + c] = p[(size_t)(np - 1) * dim + c];
}

int fx_anim_morph_match(const fx16 *a, int32_t na, const fx16 *b, int32_t nb, int32_t dim, int closed,
                        fx16 *a_out, fx16 *b_out, int32_t max)
{
    int32_t least = closed ? 3 : 2;
    if (!a || !b || !a_out || !b_out || na < least || nb < least || dim < 1 || dim > 4)
        return -FX_EINVAL;
    int32_t n = na > nb ? na : nb;
    if (n > max)
        return -FX_ENOSPC;
    int32_t lmax = closed ? n : n - 1;
    if (na == n)
        fx_memcpy(a_out, a, sizeof *a * (size_t)n * dim);
    else
        add_vertices(a, na, dim, closed, lmax, a_out);
    if (nb == n)
        fx_memcpy(b_out, b, sizeof *b * (size_t)n * dim);
    else
        add_vertices(b, nb, dim, closed, lmax, b_out);
    return n;
}

void fx_anim_morph_at(const fx16 *a, const fx16 *b, int32_t n, fx16 s, fx16 *out)
{
    for (int32_t i = 0; i < n; i++)
        out[i] = fx_anim_lerp(a[i], b[i], s);
}

/* ---- the bouncing ball ---- */

#define POSMAX ((int64_t)FX_ANIM_BALL_POS << 16)
#define SPDMAX ((int64_t)FX_ANIM_BALL_SPEED << 16)

static int in(int64_t v, int64_t lo, int64_t hi) { return v >= lo && v <= hi; }

static int ball_ok(const fx_anim_ball *b)
{
    return in(b->x, -POSMAX, POSMAX) && in(b->y, -POSMAX, POSMAX) && in(b->vx, -SPDMAX, SPDMAX) &&
           in(b->vy, -SPDMAX, SPDMAX) && in(b->g, 0, (int64_t)FX_ANIM_BALL_G << 16) && in(b->e, 0, FX16_ONE) &&
           in(b->left, -POSMAX, POSMAX) && in(b->right, b->left, POSMAX) && in(b->floor, -POSMAX, POSMAX) &&
           in(b->x, b->left, b->right) && b->y <= b->floor;
}

/* A flight from d >= 0 above the floor with vertical speed v (Q16): the
 * time to the floor (Q16, -1: never) and the speed there (*u). */
static int64_t flight(int64_t d, int64_t v, int64_t g, int64_t *u)
{
    if (g == 0) {
        *u = v > 0 ? v : 0;
        if (d == 0 && v >= 0)
            return 0;
        return v > 0 ? ((d << 16) + v / 2) / v : -1;
    }
    /* v^2 + 2 g d in Q32: v^2 <= 2^58, 2 g d <= 2^62 (the limits) */
    uint64_t disc = (uint64_t)(v * v) + (uint64_t)(2 * g) * (uint64_t)d;
    int64_t root = fx_isqrt64(disc); /* the speed at the floor, floor-rounded */
    *u = root;
    if (v > 0) /* falling: 2d / (v + root) has no cancellation */
        return ((2 * d << 16) + (v + root) / 2) / (v + root);
    return (((root - v) << 16) + g / 2) / g;
}

/* y0 + v t + g t^2 / 2 and v + g t, saturated (t Q16 seconds). */
static void fly(int64_t y0, int64_t v, int64_t g, int64_t t, fx16 *y, fx16 *vy)
{
    int64_t gt = fx_mul64_shift(g, t, 16);
    *y = fx_sat32(y0 + fx_mul64_shift(v, t, 16) + fx_mul64_shift(gt, t, 17));
    *vy = fx_sat32(v + gt);
}

/* Runs the ball to time t, or (stop_k > 0) to its stop_k-th impact, whose
 * time goes to *impact (-1 when it never comes). */
static void ball_run(const fx_anim_ball *b, int64_t t, int32_t stop_k, fx_anim_ball_state *st, int64_t *impact)
{
    int64_t g = b->g, F = b->floor, y0 = b->y, v = b->vy, at = 0;
    int32_t k = 0, rest = 0;
    if (impact)
        *impact = -1;
    for (;;) {
        int64_t u, tau = rest ? -1 : flight(F - y0, v, g, &u);
        if (tau < 0 || (!stop_k && at + tau > t)) {
            if (stop_k)
                return;
            if (rest) {
                st->y = fx_sat32(F);
                st->vy = 0;
            } else {
                fly(y0, v, g, t - at, &st->y, &st->vy);
            }
            break;
        }
        at += tau;
        k++;
        if (stop_k && k == stop_k) {
            *impact = at;
            return;
        }
        int64_t u2 = (u * b->e) >> 16; /* rounded down: the energy only falls */
        y0 = F;
        v = -u2;
        if (u2 == 0 || (u2 < u && k >= FX_ANIM_BALL_MAX_BOUNCES) || (g > 0 && ((2 * u2 << 16) + g / 2) / g == 0)) {
            rest = 1;
            v = 0;
            continue;
        }
        if (u2 == u && g > 0) {
            /* e = 1: every later flight is this one; skip whole periods */
            int64_t p = flight(0, v, g, &u);
            if (stop_k) {
                int64_t m = stop_k - k;
                *impact = p > 0 && m > (INT64_MAX / 4 - at) / p ? INT64_MAX / 4 : at + m * p;
                return;
            }
            if (p > 0 && t - at > p) {
                int64_t m = (t - at) / p;
                if (m > INT32_MAX - k)
                    m = INT32_MAX - k;
                at += m * p;
                k += (int32_t)m;
            }
        }
    }
    st->bounces = k;
    st->resting = rest;
    /* the walls: x unfolded over a period of 2W and folded back */
    int64_t W = (int64_t)b->right - b->left;
    int64_t p = (int64_t)b->x - b->left + fx_mul64_shift(b->vx, t, 16);
    if (W == 0) {
        st->x = b->left;
        st->vx = 0;
    } else {
        int64_t m = p % (2 * W);
        if (m < 0)
            m += 2 * W;
        st->x = fx_sat32(b->left + (m <= W ? m : 2 * W - m));
        st->vx = m <= W ? b->vx : -b->vx;
    }
}

int fx_anim_ball_at(const fx_anim_ball *b, fx16 t, fx_anim_ball_state *out)
{
    if (!b || !out || !ball_ok(b) || t < 0)
        return -FX_ERANGE;
    fx_memset(out, 0, sizeof *out);
    ball_run(b, t, 0, out, 0);
    return 0;
}

int fx_anim_ball_impact(const fx_anim_ball *b, int32_t k, fx16 *t)
{
    if (!b || !t || !ball_ok(b) || k < 1)
        return -FX_ERANGE;
    fx_anim_ball_state st;
    int64_t at;
    ball_run(b, 0, k, &st, &at);
    if (at < 0)
        return -FX_ENOENT;
    if (at > INT32_MAX)
        return -FX_ERANGE;
    *t = (fx16)at;
    return 0;
}

/* Each term fits 64 bits for any int32 fields (|g (floor - y)| < 2^63,
 * vy^2 / 2 <= 2^61) but their sum need not when g is past the limits, so it
 * saturates. */
int64_t fx_anim_ball_energy(const fx_anim_ball *b, const fx_anim_ball_state *s)
{
    if (!b || !s)
        return 0;
    int64_t pot = (int64_t)b->g * ((int64_t)b->floor - s->y), kin = (int64_t)s->vy * s->vy / 2;
    return pot > INT64_MAX - kin ? INT64_MAX : pot + kin;
}

/* ---- the accumulation buffer ---- */

size_t fx_accum_size(int32_t w, int32_t h)
{
    if (w < 1 || h < 1 || w > 16384 || h > 16384)
        return 0;
    return (size_t)w * (size_t)h * 4 * sizeof(uint32_t);
}

int fx_accum_init(fx_accum *a, void *mem, size_t bytes, int32_t w, int32_t h)
{
    size_t need = fx_accum_size(w, h);
    if (!a || !mem || !need)
        return -FX_EINVAL;
    if (bytes < need)
        return -FX_ENOSPC;
    a->sum = mem;
    a->w = w;
    a->h = h;
    fx_accum_clear(a);
    return 0;
}

void fx_accum_clear(fx_accum *a)
{
    fx_memset(a->sum, 0, (size_t)a->w * (size_t)a->h * 4 * sizeof(uint32_t));
    a->n = 0;
}

int fx_accum_add(fx_accum *a, const fx_surface *s)
{
    if (s->w < a->w || s->h < a->h)
        return -FX_EINVAL;
    if (a->n >= FX_ACCUM_MAX)
        return -FX_E2BIG;
    uint32_t *p = a->sum;
    for (int32_t y = 0; y < a->h; y++)
        for (int32_t x = 0; x < a->w; x++, p += 4) {
            fx_color c = fx_surface_get(s, x, y);
            p[0] += c >> 24;
            p[1] += c >> 16 & 255;
            p[2] += c >> 8 & 255;
            p[3] += c & 255;
        }
    a->n++;
    return 0;
}

int fx_accum_resolve(const fx_accum *a, const fx_surface *s)
{
    if (!a->n || s->w < a->w || s->h < a->h)
        return -FX_EINVAL;
    const uint32_t *p = a->sum;
    uint32_t n = a->n, half = n / 2;
    for (int32_t y = 0; y < a->h; y++)
        for (int32_t x = 0; x < a->w; x++, p += 4) {
            fx_color c = (p[0] + half) / n << 24 | (p[1] + half) / n << 16 | (p[2] + half) / n << 8 |
                         (p[3] + half) / n;
            fx_surface_put_native(s, x, y, fx_pack(s->format, c));
        }
    return 0;
}
