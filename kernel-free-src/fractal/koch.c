/* SPDX-License-Identifier: MIT */
/* fixel — Koch curves, midpoint displacement, terrain and space-filling
 * curves (contracts in koch.h). */
#include "fixel/koch.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

#define F 24
#define ONE ((int64_t)1 << F)
#define ANGLE_60 ((fx_angle)0x2AAAAAABu) /* 2^32 / 6, rounded */

typedef struct pt {
    int64_t x, y;
} pt;

static inline int32_t to_px(int64_t v) { return (int32_t)((v + (ONE >> 1)) >> F); }
static inline int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

/* Round-to-nearest division by 3, symmetric in sign. */
static inline int64_t third(int64_t v) { return v >= 0 ? (v + 1) / 3 : -((-v + 1) / 3); }

/* Is the box [x0, x1] x [y0, y1] (in 40.24) disjoint from the clip? */
static int off_clip(const fx_ctx *c, int64_t x0, int64_t y0, int64_t x1, int64_t y1)
{
    return x1 < (int64_t)c->clip.x0 * ONE || x0 >= (int64_t)c->clip.x1 * ONE ||
           y1 < (int64_t)c->clip.y0 * ONE || y0 >= (int64_t)c->clip.y1 * ONE;
}

static void seg(const fx_ctx *c, pt a, pt b)
{
    fx_line(c, to_px(a.x), to_px(a.y), to_px(b.x), to_px(b.y));
}

/* Rotate t by h from +x towards +y of the frame, the one angle rule of
 * fx_rotate, fx_arc and the turtle (CONVENTIONS.md "Angles"), so K_n from
 * left to right bulges towards +y: above the base line after 'coords
 * course', as in the notes, below it on the y-down screen (issue #44). */
static pt turn(pt t, fx_angle h)
{
    int32_t co = fx_cos30(h), si = fx_sin30(h);
    pt r = {fx_mul64_shift(t.x, co, 30) - fx_mul64_shift(t.y, si, 30),
            fx_mul64_shift(t.x, si, 30) + fx_mul64_shift(t.y, co, 30)};
    return r;
}

static uint64_t koch_rec(const fx_ctx *c, pt s, pt e, uint32_t m)
{
    int64_t dx = e.x - s.x, dy = e.y - s.y;
    /* the curve stays within sqrt(3)/6 |SE| < 0.3 (|dx| + |dy|) of its chord */
    int64_t g = (abs64(dx) + abs64(dy)) / 10 * 3 + ONE;
    if (off_clip(c, FX_MIN(s.x, e.x) - g, FX_MIN(s.y, e.y) - g, FX_MAX(s.x, e.x) + g,
                 FX_MAX(s.y, e.y) + g))
        return 0;
    if (m == 0 || (abs64(dx) < ONE && abs64(dy) < ONE)) {
        seg(c, s, e);
        return 1;
    }
    /* the turtle: forward, +60, forward, -120, forward, +60, forward */
    pt t = {third(dx), third(dy)};
    fx_angle h = 0;
    pt a = {s.x + t.x, s.y + t.y};
    h += ANGLE_60;
    pt u = turn(t, h);
    pt p = {a.x + u.x, a.y + u.y};
    h -= 2 * ANGLE_60;
    u = turn(t, h);
    pt b = {p.x + u.x, p.y + u.y};
    return koch_rec(c, s, a, m - 1) + koch_rec(c, a, p, m - 1) + koch_rec(c, p, b, m - 1) +
           koch_rec(c, b, e, m - 1);
}

uint64_t fx_koch(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t order)
{
    pt s = {(int64_t)x0 * ONE, (int64_t)y0 * ONE}, e = {(int64_t)x1 * ONE, (int64_t)y1 * ONE};
    return koch_rec(c, s, e, order);
}

uint64_t fx_koch_snowflake(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r, uint32_t order)
{
    pt v[3];
    for (int i = 0; i < 3; i++) {
        /* 90, 330, 210 degrees (counter-clockwise, y up); y grows downward */
        fx_angle a = FX_ANGLE_90 + (fx_angle)i * 2 * ANGLE_60 * 2;
        v[i].x = (int64_t)cx * ONE + fx_mul64_shift((int64_t)r * ONE, fx_cos30(a), 30);
        v[i].y = (int64_t)cy * ONE - fx_mul64_shift((int64_t)r * ONE, fx_sin30(a), 30);
    }
    uint64_t n = 0;
    /* top, lower left, lower right (on the y-down screen): from each side's
     * start, +60 turns towards the outside. The vertices stay where they
     * were before issue #44 turned the bumps over; the flake is the same
     * in both frames by its six-fold symmetry. */
    for (int i = 0; i < 3; i++)
        n += koch_rec(c, v[(3 - i) % 3], v[(5 - i) % 3], order);
    return n;
}

/* ---- random fractals ---- */

typedef struct fract_job {
    const fx_ctx *c;
    fx16 factor;
    int64_t min2; /* squared minimum length in px^2 */
    uint32_t *st;
    uint32_t segs;
} fract_job;

static void fract_rec(fract_job *j, pt a, pt b, fx16 sd, int depth)
{
    int64_t dx = b.x - a.x, dy = b.y - a.y;
    int64_t lx = dx >> (F - 8), ly = dy >> (F - 8); /* 24.8 */
    const int64_t big = (int64_t)1 << 30; /* longer is never a leaf; squares fit below */
    int near = lx < big && lx > -big && ly < big && ly > -big;
    /* depth 16: at most 2^16 pieces even when beta < 1 makes them grow (issue #26) */
    if (depth >= 16 || (near && lx * lx + ly * ly < j->min2 * 65536)) {
        seg(j->c, a, b);
        j->segs++;
        return;
    }
    sd = fx16_mul(sd, j->factor);
    fx16 t = fx16_mul(fx_gauss16(j->st), sd);
    /* Midpoints stay inside the int32 pixel box (clamped): with beta < 1 the
     * displacements grow each level and a.x + dx / 2 - t * dy overflowed
     * int64 (issue #26). Endpoints are within +-2^55, so no sum here can. */
    const int64_t lim = (int64_t)INT32_MAX << F;
    int64_t ox = FX_MAX(FX_MIN(fx_mul64_shift(t, dy, 16), 2 * lim), -2 * lim);
    int64_t oy = FX_MAX(FX_MIN(fx_mul64_shift(t, dx, 16), 2 * lim), -2 * lim);
    pt m = {FX_MAX(FX_MIN(a.x + dx / 2 - ox, lim), -lim), FX_MAX(FX_MIN(a.y + dy / 2 + oy, lim), -lim)};
    fract_rec(j, a, m, sd, depth + 1);
    fract_rec(j, m, b, sd, depth + 1);
}

uint32_t fx_fractline(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                      const fx_fract_params *p, uint32_t *state)
{
    /* The random draws cannot depend on the clip, so the whole line is
     * always walked; pieces of at least 1/2^15 of |dx| + |dy| keep that walk
     * near 2^16 segments however long the line is (2^18 took over a second
     * per coastline side, issue #26). */
    int64_t ddx = (int64_t)x1 - x0, ddy = (int64_t)y1 - y0;
    int64_t span = (ddx < 0 ? -ddx : ddx) + (ddy < 0 ? -ddy : ddy);
    int64_t ml = FX_MAX((int64_t)FX_MAX(p->min_len, 1), span >> 15);
    fract_job j = {c, fx16_exp2((FX16_ONE - p->beta) / 2), ml * ml, state, 0};
    pt a = {(int64_t)x0 * ONE, (int64_t)y0 * ONE}, b = {(int64_t)x1 * ONE, (int64_t)y1 * ONE};
    fract_rec(&j, a, b, p->sd, 0);
    return j.segs;
}

uint32_t fx_coastline(const fx_ctx *c, const int32_t *xy, int n, const fx_fract_params *p)
{
    if (!c || !xy || !p || n < 1 || n > INT32_MAX / 2)
        return 0;
    uint32_t st = p->seed, segs = 0;
    for (int i = 0; i < n; i++) {
        int k = (i + 1) % n;
        segs += fx_fractline(c, xy[2 * i], xy[2 * i + 1], xy[2 * k], xy[2 * k + 1], p, &st);
    }
    return segs;
}

static int32_t noise(uint32_t *st, int32_t amp)
{
    if (amp <= 0)
        return 0;
    uint32_t span = 2 * (uint32_t)amp + 1;
    return (int32_t)((uint64_t)fx_rand32(st) * span >> 32) - amp;
}

int fx_terrain(int32_t *h, int32_t stride, int k, int32_t amp, fx16 rough, uint32_t seed)
{
    if (!h || k < 1 || k > 12 || amp < 0 || amp > (1 << 28) || stride < (1 << k) + 1)
        return -FX_EINVAL;
    int32_t n = 1 << k;
    uint32_t st = seed;
    fx16 scale = fx16_exp2(-rough);
#define H(x, y) h[(ptrdiff_t)(y) * stride + (x)]
    H(0, 0) = noise(&st, amp);
    H(n, 0) = noise(&st, amp);
    H(0, n) = noise(&st, amp);
    H(n, n) = noise(&st, amp);
    int32_t a = amp;
    for (int32_t s = n; s > 1; s /= 2) {
        int32_t hs = s / 2;
        a = (int32_t)(((int64_t)a * scale + 0x8000) >> 16);
        /* diamond: square centres */
        for (int32_t y = hs; y < n; y += s)
            for (int32_t x = hs; x < n; x += s) {
                int64_t m = (int64_t)H(x - hs, y - hs) + H(x + hs, y - hs) + H(x - hs, y + hs) +
                            H(x + hs, y + hs);
                H(x, y) = (int32_t)((m + 2) >> 2) + noise(&st, a);
            }
        /* square: edge midpoints, averaging the neighbours that exist */
        for (int32_t y = 0; y <= n; y += hs)
            for (int32_t x = (y / hs) % 2 ? 0 : hs; x <= n; x += s) {
                int64_t m = 0;
                int cnt = 0;
                if (x >= hs) m += H(x - hs, y), cnt++;
                if (x + hs <= n) m += H(x + hs, y), cnt++;
                if (y >= hs) m += H(x, y - hs), cnt++;
                if (y + hs <= n) m += H(x, y + hs), cnt++;
                int64_t avg = m >= 0 ? (m + cnt / 2) / cnt : -((-m + cnt / 2) / cnt);
                H(x, y) = (int32_t)avg + noise(&st, a);
            }
    }
#undef H
    return 0;
}

/* ---- space-filling curves ---- */

/* Orders past the maximum (1u << n undefined at 32 for Hilbert; for Peano
 * 3^n past uint32 and the digit array below sized for 20) and steps past
 * the curve's end are refused before anything is written (issue #40). */
int fx_hilbert_d2xy(uint32_t n, uint64_t d, uint32_t *xo, uint32_t *yo)
{
    if (!xo || !yo || n > FX_HILBERT_MAX_ORDER || d >> (2 * n) != 0)
        return -FX_EINVAL;
    uint32_t x = 0, y = 0;
    uint64_t t = d;
    for (uint32_t s = 1; s < (1u << n); s *= 2) {
        uint32_t rx = 1 & (uint32_t)(t / 2), ry = 1 & (uint32_t)(t ^ rx);
        if (ry == 0) {
            if (rx == 1) {
                x = s - 1 - x;
                y = s - 1 - y;
            }
            uint32_t tmp = x;
            x = y;
            y = tmp;
        }
        x += s * rx;
        y += s * ry;
        t /= 4;
    }
    *xo = x;
    *yo = y;
    return 0;
}

/* Peano's own definition: with d = t1 t2 ... t2n in base 3,
 * x digit i = k^(t2 + t4 + ... + t(2i-2)) (t(2i-1)), y digit i =
 * k^(t1 + t3 + ... + t(2i-1)) (t(2i)), where k(t) = 2 - t. */
int fx_peano_d2xy(uint32_t n, uint64_t d, uint32_t *xo, uint32_t *yo)
{
    uint64_t cells = 1; /* 9^n, at most 9^20 < 2^64 */
    for (uint32_t i = 0; i < n && i < FX_PEANO_MAX_ORDER; i++)
        cells *= 9;
    if (!xo || !yo || n > FX_PEANO_MAX_ORDER || d >= cells)
        return -FX_EINVAL;
    uint8_t t[2 * FX_PEANO_MAX_ORDER];
    for (int i = (int)(2 * n) - 1; i >= 0; i--) {
        t[i] = (uint8_t)(d % 3);
        d /= 3;
    }
    uint32_t x = 0, y = 0, se = 0, so = 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t a = t[2 * i], b = t[2 * i + 1];
        so += a;
        x = x * 3 + (se & 1 ? 2 - a : a);
        y = y * 3 + (so & 1 ? 2 - b : b);
        se += b;
    }
    *xo = x;
    *yo = y;
    return 0;
}

typedef struct sfc {
    const fx_ctx *c;
    uint32_t base, n;
    int32_t x, y, size;
    uint64_t cells; /* base^n per side */
    int (*d2xy)(uint32_t, uint64_t, uint32_t *, uint32_t *);
    int have_prev;
    int32_t px, py;
    uint32_t segs;
} sfc;

/* Pixel of cell i's centre; squares reaching past int32 give far points
 * that the clipped line drawing handles. */
static int32_t cell_px(const sfc *s, int32_t org, uint32_t i)
{
    return fx_sat32(org + (int64_t)(((2 * (uint64_t)i + 1) * (uint64_t)s->size) / (2 * s->cells)));
}

static void sfc_point(sfc *s, uint64_t d)
{
    uint32_t cx, cy;
    s->d2xy(s->n, d, &cx, &cy);
    int32_t x = cell_px(s, s->x, cx), y = cell_px(s, s->y, cy);
    if (s->have_prev) {
        fx_line(s->c, s->px, s->py, x, y);
        s->segs++;
    }
    s->have_prev = 1;
    s->px = x;
    s->py = y;
}

/* Indices [d, d + count) form a block of base^m x base^m cells (count =
 * base^(2m), d aligned). Off-clip blocks only move the pen to their last
 * point (the segment leaving the block is drawn from there). */
static void sfc_block(sfc *s, uint64_t d, uint64_t count, uint64_t side)
{
    uint32_t cx, cy;
    s->d2xy(s->n, d, &cx, &cy);
    uint32_t bx = (uint32_t)(cx / side * side), by = (uint32_t)(cy / side * side);
    int64_t x0 = (int64_t)cell_px(s, s->x, bx) - 1, y0 = (int64_t)cell_px(s, s->y, by) - 1;
    int64_t x1 = (int64_t)cell_px(s, s->x, bx + (uint32_t)side - 1) + 1;
    int64_t y1 = (int64_t)cell_px(s, s->y, by + (uint32_t)side - 1) + 1;
    if (x1 < s->c->clip.x0 || x0 >= s->c->clip.x1 || y1 < s->c->clip.y0 || y0 >= s->c->clip.y1) {
        /* the segment entering the block may still cross the clip */
        sfc_point(s, d);
        uint32_t lx, ly;
        s->d2xy(s->n, d + count - 1, &lx, &ly);
        s->px = cell_px(s, s->x, lx);
        s->py = cell_px(s, s->y, ly);
        return;
    }
    if (count <= s->base * s->base * 16) {
        for (uint64_t i = 0; i < count; i++)
            sfc_point(s, d + i);
        return;
    }
    uint64_t sub = count / (s->base * s->base);
    for (uint32_t i = 0; i < s->base * s->base; i++)
        sfc_block(s, d + i * sub, sub, side / s->base);
}

static uint32_t sfc_draw(const fx_ctx *c, int32_t x, int32_t y, int32_t size, uint32_t order,
                         uint32_t base, int (*d2xy)(uint32_t, uint64_t, uint32_t *, uint32_t *))
{
    if (size < 1)
        return 0;
    /* the finest order whose cells are still >= 1 pixel */
    uint32_t n = 0;
    uint64_t cells = 1;
    while (n < order && cells * base <= (uint64_t)size && n < (base == 2 ? FX_HILBERT_MAX_ORDER : FX_PEANO_MAX_ORDER - 1)) {
        n++;
        cells *= base;
    }
    sfc s = {c, base, n, x, y, size, cells, d2xy, 0, 0, 0, 0};
    if (n == 0) {
        fx_plot(c, fx_sat32((int64_t)x + size / 2), fx_sat32((int64_t)y + size / 2));
        return 0;
    }
    sfc_block(&s, 0, cells * cells, cells);
    return s.segs;
}

uint32_t fx_hilbert(const fx_ctx *c, int32_t x, int32_t y, int32_t size, uint32_t order)
{
    return sfc_draw(c, x, y, size, order, 2, fx_hilbert_d2xy);
}

uint32_t fx_peano(const fx_ctx *c, int32_t x, int32_t y, int32_t size, uint32_t order)
{
    return sfc_draw(c, x, y, size, order, 3, fx_peano_d2xy);
}
