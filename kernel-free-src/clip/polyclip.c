/* SPDX-License-Identifier: MIT */
/* fixel — polygon clipping against a rectangular window: Sutherland-Hodgman,
 * Weiler-Atherton (separate pieces for concave polygons). The pieces are
 * filled by fx_poly_fill16 (fill.h, fill/fill.c).
 *
 * Exactness where it matters: an intersection with the window border is a
 * rational that Q16.16 cannot always hold, and rounding it tilts the clipped
 * edge a little. A pixel centre that lay exactly on the original edge could
 * then change sides and flip the top-left rule's decision, so the rounding
 * direction is chosen per edge: outwards for edges whose centres count
 * (left and top edges), inwards for the others. Centres off the edge are at
 * least 1/|edge| away from it, far beyond the 2^-17 tilt for any edge
 * shorter than about 10^4 pixels, so the clipped polygon covers exactly the
 * pixels of the unclipped one inside the window (tested in test_polyclip.c). */
#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"
#include "../base/fx_wide.h"

#define HALF ((int64_t)FX16_HALF)
#define ONE ((int64_t)FX16_ONE)

typedef struct {
    int64_t v[4]; /* L, R, B, T: x >= L, x <= R, y >= B, y <= T (raw Q16.16) */
} win_t;

static win_t window_of(fx_rect w)
{
    win_t r = {{(int64_t)w.x0 * ONE - HALF, (int64_t)w.x1 * ONE - HALF, (int64_t)w.y0 * ONE - HALF,
                (int64_t)w.y1 * ONE - HALF}};
    return r;
}

static int inside_b(fx_pt16 p, int k, int64_t v)
{
    switch (k) {
    case 0: return p.x >= v;
    case 1: return p.x <= v;
    case 2: return p.y >= v;
    default: return p.y <= v;
    }
}

/* Sign of twice the signed area (shoelace), exact. */
static int orientation(const fx_pt16 *p, int n)
{
    fx_s128 s = fx_w_from(0);
    for (int i = 0; i < n; i++) {
        fx_pt16 a = p[i], b = p[(i + 1) % n];
        s = fx_w_add(s, fx_w_sub(fx_w_mul(a.x, b.y), fx_w_mul(b.x, a.y)));
    }
    return fx_w_sign(s);
}

/* The point where edge S->E meets boundary k (value v), S and E on
 * opposite sides (or one on it). The free coordinate is rounded to the side
 * the top-left rule needs (see the file comment); orient is the polygon's
 * orientation sign. */
static fx_pt16 cut(fx_pt16 S, fx_pt16 E, int k, int64_t v, int orient)
{
    int vert = k < 2;
    int64_t sa = vert ? S.x : S.y, ea = vert ? E.x : E.y;
    int64_t sb = vert ? S.y : S.x, eb = vert ? E.y : E.x;
    int64_t den = ea - sa;
    fx_s128 num = fx_w_add(fx_w_mul(sb, den), fx_w_mul(v - sa, eb - sb));
    if (den < 0) {
        num = fx_w_neg(num);
        den = -den;
    }
    int64_t lo = fx_w_floordiv(num, den), hi = fx_w_ceildiv(num, den), pick = lo;
    if (lo != hi) {
        int64_t ex = (int64_t)E.x - S.x, ey = (int64_t)E.y - S.y;
        int64_t nx = orient >= 0 ? -ey : ey, ny = orient >= 0 ? ex : -ex; /* inward normal */
        int incl = nx > 0 || (nx == 0 && ny > 0);
        int64_t px = vert ? v : lo, py = vert ? lo : v;
        int sg = fx_w_sign(fx_w_add(fx_w_mul(nx, px - S.x), fx_w_mul(ny, py - S.y)));
        if (incl ? sg > 0 : sg < 0)
            pick = hi;
    }
    fx_pt16 r;
    if (vert) {
        r.x = fx_sat32(v);
        r.y = fx_sat32(pick);
    } else {
        r.x = fx_sat32(pick);
        r.y = fx_sat32(v);
    }
    return r;
}

/* One Sutherland-Hodgman pass against boundary k. */
static int sh_pass(const fx_pt16 *in, int n, fx_pt16 *out, int cap, int k, int64_t v, int orient)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        fx_pt16 S = in[(i + n - 1) % n], E = in[i];
        int si = inside_b(S, k, v), ei = inside_b(E, k, v);
        if (si != ei) {
            if (m >= cap)
                return -FX_ENOSPC;
            out[m++] = cut(S, E, k, v, orient);
        }
        if (ei) {
            if (m >= cap)
                return -FX_ENOSPC;
            out[m++] = E;
        }
    }
    return m;
}

int fx_clip_poly_sh(fx_rect w, const fx_pt16 *in, int n, fx_pt16 *out, int cap)
{
    if (n < 3 || fx_rect_empty(w))
        return 0;
    win_t win = window_of(w);
    int orient = orientation(in, n);
    /* Ping-pong between the two halves of out: the passes never need more
     * than n + 4 vertices (each boundary adds at most one per crossing pair). */
    int half = cap / 2;
    const fx_pt16 *src = in;
    int m = n;
    for (int k = 0; k < 4; k++) {
        fx_pt16 *dst = out + ((k & 1) ? 0 : half);
        int lim = (k & 1) ? half : cap - half;
        m = sh_pass(src, m, dst, lim, k, win.v[k], orient);
        if (m < 0)
            return m;
        if (m == 0)
            return 0;
        src = dst;
    }
    /* after four passes the result sits in the first half (k = 3 is odd) */
    return m < 3 ? 0 : m;
}

/* ---- Weiler-Atherton ---- */

typedef struct {
    int first, count;   /* points in the chain buffer */
    int64_t pin, pout;  /* perimeter positions of entry and exit */
    int used;
} chain_t;

static size_t align8(size_t v) { return (v + 7) & ~(size_t)7; }

size_t fx_clip_poly_work_size(int n)
{
    if (n < 0)
        n = 0;
    return align8((size_t)n * sizeof(fx_pt16)) + align8((size_t)(2 * n + 2) * sizeof(fx_pt16)) +
           align8((size_t)(n + 1) * sizeof(chain_t));
}

/* Position along the window border, counter-clockwise in the orientation
 * that gives the window corners (L,B) (R,B) (R,T) (L,T) a positive area. */
static int64_t perim(const win_t *w, fx_pt16 p)
{
    int64_t L = w->v[0], R = w->v[1], B = w->v[2], T = w->v[3], W = R - L, H = T - B;
    if (p.y == B)
        return p.x - L;
    if (p.x == R)
        return W + (p.y - B);
    if (p.y == T)
        return W + H + (R - p.x);
    return 2 * W + H + (T - p.y);
}

/* Liang-Barsky on one edge against the closed window: entry and exit
 * parameters as rationals, and the boundaries that set them (-1: none). */
static int edge_clip(const win_t *w, fx_pt16 S, fx_pt16 E, int *kin, int *kout, int64_t t[4])
{
    int64_t dx = (int64_t)E.x - S.x, dy = (int64_t)E.y - S.y;
    int64_t p[4] = {-dx, dx, -dy, dy};
    int64_t q[4] = {S.x - w->v[0], w->v[1] - S.x, S.y - w->v[2], w->v[3] - S.y};
    int64_t ap = 0, aq = 1, bp = 1, bq = 1; /* t0 = ap/aq, t1 = bp/bq */
    *kin = *kout = -1;
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
            continue;
        }
        int64_t rp = q[k], rq = p[k];
        if (rq < 0)
            rp = -rp, rq = -rq;
        if (p[k] < 0) {
            if (fx_w_mulcmp(rp, aq, ap, rq) > 0)
                ap = rp, aq = rq, *kin = k;
        } else if (fx_w_mulcmp(rp, bq, bp, rq) < 0) {
            bp = rp, bq = rq, *kout = k;
        }
    }
    if (fx_w_mulcmp(ap, bq, bp, aq) > 0)
        return 0;
    t[0] = ap, t[1] = aq, t[2] = bp, t[3] = bq;
    return 1;
}

/* Even-odd test of point (cx/2, cy/2) (doubled raw coordinates). */
static int contains2(const fx_pt16 *p, int n, int64_t cx, int64_t cy)
{
    int in = 0;
    for (int i = 0; i < n; i++) {
        int64_t sx = 2 * (int64_t)p[i].x, sy = 2 * (int64_t)p[i].y;
        int64_t ex = 2 * (int64_t)p[(i + 1) % n].x, ey = 2 * (int64_t)p[(i + 1) % n].y;
        if ((sy > cy) == (ey > cy))
            continue;
        /* cx < sx + (cy - sy) (ex - sx) / (ey - sy) */
        int c = fx_w_mulcmp(cx - sx, ey - sy, cy - sy, ex - sx);
        if (ey - sy < 0)
            c = -c;
        in ^= c < 0;
    }
    return in;
}

static int put(fx_pt16 *out, int cap, int *m, fx_pt16 p)
{
    if (*m > 0 && out[*m - 1].x == p.x && out[*m - 1].y == p.y)
        return 0;
    if (*m >= cap)
        return -FX_ENOSPC;
    out[(*m)++] = p;
    return 0;
}

int fx_clip_poly_pieces(fx_rect wr, const fx_pt16 *in, int n, fx_pt16 *out, int cap, int *starts,
                        int max_pieces, void *work, size_t work_size)
{
    if (n < 3 || fx_rect_empty(wr) || max_pieces < 1)
        return 0;
    if (!work || work_size < fx_clip_poly_work_size(n))
        return -FX_ENOSPC;
    win_t w = window_of(wr);
    uint8_t *wp = work;
    fx_pt16 *v = (fx_pt16 *)(void *)wp;
    fx_pt16 *cp = (fx_pt16 *)(void *)(wp + align8((size_t)n * sizeof(fx_pt16)));
    chain_t *ch = (chain_t *)(void *)(wp + align8((size_t)n * sizeof(fx_pt16)) +
                                      align8((size_t)(2 * n + 2) * sizeof(fx_pt16)));
    int orient = orientation(in, n);
    if (!orient)
        return 0;
    /* Counter-clockwise (positive) like the window's border walk. */
    for (int i = 0; i < n; i++)
        v[i] = orient > 0 ? in[i] : in[n - 1 - i];
    int s = -1;
    for (int i = 0; i < n && s < 0; i++)
        if (v[i].x < w.v[0] || v[i].x > w.v[1] || v[i].y < w.v[2] || v[i].y > w.v[3])
            s = i;
    int m = 0;
    if (s < 0) { /* entirely inside */
        for (int i = 0; i < n; i++)
            if (put(out, cap, &m, v[i]) < 0)
                return -FX_ENOSPC;
        starts[0] = 0;
        starts[1] = m;
        return 1;
    }
    /* Chains: the runs of the polygon inside the window, each from an entry
     * point on the border to an exit point on the border. */
    int nc = 0, np = 0, open = 0;
    for (int j = 0; j < n; j++) {
        fx_pt16 S = v[(s + j) % n], E = v[(s + j + 1) % n];
        int kin, kout;
        int64_t t[4];
        if (!edge_clip(&w, S, E, &kin, &kout, t))
            continue;
        if (kin >= 0 || !open) { /* S outside: a new chain starts */
            ch[nc].first = np;
            ch[nc].count = 0;
            open = 1;
            cp[np++] = kin >= 0 ? cut(S, E, kin, w.v[kin], 1) : S;
            ch[nc].count = 1;
        }
        fx_pt16 x = kout >= 0 ? cut(S, E, kout, w.v[kout], 1) : E;
        fx_pt16 *last = &cp[np - 1];
        if (last->x != x.x || last->y != x.y) {
            cp[np++] = x;
            ch[nc].count++;
        }
        if (kout >= 0) { /* left the window: the chain is complete */
            open = 0;
            if (ch[nc].count >= 2) {
                ch[nc].pin = perim(&w, cp[ch[nc].first]);
                ch[nc].pout = perim(&w, cp[np - 1]);
                ch[nc].used = 0;
                nc++;
            } else {
                np = ch[nc].first; /* a touch at one point adds no area */
            }
        }
    }
    if (!nc) {
        /* No run inside: the window is inside the polygon or apart from it. */
        if (!contains2(v, n, w.v[0] + w.v[1], w.v[2] + w.v[3]))
            return 0;
        fx_pt16 c[4] = {{fx_sat32(w.v[0]), fx_sat32(w.v[2])}, {fx_sat32(w.v[1]), fx_sat32(w.v[2])},
                        {fx_sat32(w.v[1]), fx_sat32(w.v[3])}, {fx_sat32(w.v[0]), fx_sat32(w.v[3])}};
        for (int i = 0; i < 4; i++)
            if (put(out, cap, &m, c[i]) < 0)
                return -FX_ENOSPC;
        starts[0] = 0;
        starts[1] = m;
        return 1;
    }
    int64_t W = w.v[1] - w.v[0], H = w.v[3] - w.v[2], P = 2 * W + 2 * H;
    int64_t cpos[4] = {0, W, W + H, 2 * W + H};
    fx_pt16 cpt[4] = {{fx_sat32(w.v[0]), fx_sat32(w.v[2])}, {fx_sat32(w.v[1]), fx_sat32(w.v[2])},
                      {fx_sat32(w.v[1]), fx_sat32(w.v[3])}, {fx_sat32(w.v[0]), fx_sat32(w.v[3])}};
    int pieces = 0;
    for (int c0 = 0; c0 < nc; c0++) {
        if (ch[c0].used)
            continue;
        if (pieces >= max_pieces)
            return -FX_ENOSPC;
        starts[pieces] = m;
        int cur = c0;
        for (int guard = 0; guard <= nc; guard++) {
            ch[cur].used = 1;
            for (int i = 0; i < ch[cur].count; i++)
                if (put(out, cap, &m, cp[ch[cur].first + i]) < 0)
                    return -FX_ENOSPC;
            /* Walk the border forward from the exit to the nearest entry. */
            int64_t pe = ch[cur].pout, best = -1;
            int next = -1;
            for (int i = 0; i < nc; i++) {
                if (ch[i].used && i != c0)
                    continue;
                int64_t d = ((ch[i].pin - pe) % P + P) % P;
                if (best < 0 || d < best)
                    best = d, next = i;
            }
            for (int pass = 0; pass < 2; pass++) /* corners in border order */
                for (int i = 0; i < 4; i++) {
                    int64_t d = ((cpos[i] - pe) % P + P) % P;
                    if (d > 0 && d < best && (pass == 0 ? cpos[i] >= pe : cpos[i] < pe))
                        if (put(out, cap, &m, cpt[i]) < 0)
                            return -FX_ENOSPC;
                }
            if (next == c0 || next < 0)
                break;
            cur = next;
        }
        if (m > starts[pieces] + 1 && out[m - 1].x == out[starts[pieces]].x &&
            out[m - 1].y == out[starts[pieces]].y)
            m--; /* the closing vertex repeats the first */
        if (m - starts[pieces] >= 3)
            pieces++;
        else
            m = starts[pieces];
    }
    starts[pieces] = m;
    return pieces;
}
