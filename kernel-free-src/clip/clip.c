/* SPDX-License-Identifier: MIT */
/* fixel — line clipping (Cohen-Sutherland, Liang-Barsky, Nicholl-Lee-Nicholl)
 * with exact rational parameters, the conversion to Bresenham steps that
 * keeps every pixel where the unclipped line puts it, exterior clipping for
 * lines, and the clip-window stack.
 *
 * All three algorithms work on doubled coordinates, so the pixel-square
 * region [xwmin - 1/2, xwmax + 1/2] has integer bounds 2*xwmin - 1 and
 * 2*xwmax + 1. A parameter is a rational p/q (q > 0) of such integers (at
 * most 35 bits each); comparing two of them or placing a point against a
 * bound multiplies two of them, which needs 128 bits (fx_smul64_wide). No
 * intersection is ever rounded, so the algorithms' decisions are exact for
 * every int32 endpoint pair. */
#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

typedef struct {
    int64_t p, q; /* q > 0 */
} rat;

/* sign(a*b - c*d) for |a|, |b|, |c|, |d| < 2^62. */
static int mulcmp(int64_t a, int64_t b, int64_t c, int64_t d)
{
    int64_t h1, h2;
    uint64_t l1, l2;
    fx_smul64_wide(a, b, &h1, &l1);
    fx_smul64_wide(c, d, &h2, &l2);
    if (h1 != h2)
        return h1 < h2 ? -1 : 1;
    return l1 < l2 ? -1 : l1 > l2;
}

static rat mkrat(int64_t p, int64_t q)
{
    rat r = {p, q};
    if (q < 0) {
        r.p = -p;
        r.q = -q;
    }
    return r;
}

static int ratcmp(rat a, rat b) { return mulcmp(a.p, b.q, b.p, a.q); }

/* floor(p * m / q) for 0 <= p <= q, q > 0: below 2^32 since p/q <= 1.
 * *exact is set when there is no remainder. */
static uint32_t scale_floor(rat u, uint32_t m, int *exact)
{
    uint64_t hi, lo, q = (uint64_t)u.q, rem, quo = 0;
    fx_umul64_wide((uint64_t)u.p, m, &hi, &lo);
    if (!hi) {
        quo = lo / q;
        rem = lo % q;
    } else {
        /* hi < q because the quotient fits in 64 bits; q < 2^36, so the
         * shifted remainder cannot overflow. */
        rem = hi;
        for (int i = 63; i >= 0; i--) {
            rem = (rem << 1) | ((lo >> i) & 1);
            if (rem >= q) {
                rem -= q;
                quo |= (uint64_t)1 << i;
            }
        }
    }
    *exact = rem == 0;
    return (uint32_t)quo;
}

/* ---- the segment in doubled coordinates ---- */

typedef struct {
    int64_t ax, ay, dx, dy;         /* P(u) = A + u D */
    int64_t xmin, xmax, ymin, ymax; /* the pixel-square region, closed */
} seg;

/* notes: the course notes' window instead, edges through the centres of
 * the outermost pixels (xwmin..xwmax = x0..x1-1), in plain (undoubled)
 * coordinates, so a trace prints the numbers worked by hand. Only traces
 * use it: the pixels come from the pixel-square region. */
static seg make_seg_notes(fx_rect w, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    seg s;
    s.ax = x0;
    s.ay = y0;
    s.dx = (int64_t)x1 - x0;
    s.dy = (int64_t)y1 - y0;
    s.xmin = w.x0;
    s.xmax = (int64_t)w.x1 - 1;
    s.ymin = w.y0;
    s.ymax = (int64_t)w.y1 - 1;
    return s;
}

static seg make_seg(fx_rect w, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    seg s;
    s.ax = 2 * (int64_t)x0;
    s.ay = 2 * (int64_t)y0;
    s.dx = 2 * ((int64_t)x1 - x0);
    s.dy = 2 * ((int64_t)y1 - y0);
    s.xmin = 2 * (int64_t)w.x0 - 1;
    s.xmax = 2 * (int64_t)w.x1 - 1;
    s.ymin = 2 * (int64_t)w.y0 - 1;
    s.ymax = 2 * (int64_t)w.y1 - 1;
    return s;
}

/* Region code of P(u): x(u) < xmin <=> dx*p < (xmin - ax)*q. */
static unsigned code_at(const seg *s, rat u)
{
    unsigned c = 0;
    if (mulcmp(s->dx, u.p, s->xmin - s->ax, u.q) < 0)
        c |= FX_CODE_LEFT;
    else if (mulcmp(s->dx, u.p, s->xmax - s->ax, u.q) > 0)
        c |= FX_CODE_RIGHT;
    if (mulcmp(s->dy, u.p, s->ymin - s->ay, u.q) < 0)
        c |= FX_CODE_BELOW;
    else if (mulcmp(s->dy, u.p, s->ymax - s->ay, u.q) > 0)
        c |= FX_CODE_ABOVE;
    return c;
}

unsigned fx_clip_region_code(fx_rect w, int32_t x, int32_t y)
{
    return (x < w.x0 ? FX_CODE_LEFT : 0) | (x >= w.x1 ? FX_CODE_RIGHT : 0) |
           (y < w.y0 ? FX_CODE_BELOW : 0) | (y >= w.y1 ? FX_CODE_ABOVE : 0);
}

/* The notes' other way to the same code: the sign bits of the four
 * differences, bit 1 (L) of x - xwmin, bit 2 (R) of xwmax - x, bit 3 (B) of
 * y - ywmin and bit 4 (T) of ywmax - y, a negative difference meaning
 * outside on that side. int64 differences: no int32 coordinate overflows. */
static unsigned sign_bit(int64_t d) { return (unsigned)((uint64_t)d >> 63); }

unsigned fx_clip_region_code_signs(fx_rect w, int32_t x, int32_t y, int64_t diff[4])
{
    int64_t d[4] = {(int64_t)w.y1 - 1 - y, (int64_t)y - w.y0, (int64_t)w.x1 - 1 - x, (int64_t)x - w.x0};
    if (diff)
        for (int i = 0; i < 4; i++)
            diff[i] = d[i];
    return sign_bit(d[0]) << 3 | sign_bit(d[1]) << 2 | sign_bit(d[2]) << 1 | sign_bit(d[3]);
}

int fx_clip_trivial(unsigned c0, unsigned c1)
{
    if (!(c0 | c1))
        return 1;
    return (c0 & c1) ? -1 : 0;
}

/* ---- tracing helpers ---- */

static void bits4(char *b, unsigned c)
{
    for (int i = 0; i < 4; i++)
        b[i] = (char)('0' + ((c >> (3 - i)) & 1));
    b[4] = 0;
}

static uint64_t gcd64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* "p/q (0.123456)" reduced, into buf. */
static const char *ratstr(char *buf, size_t n, rat u)
{
    if (u.q <= 0) { /* a degenerate one-pixel notes' window can divide by 0 */
        fx_fmt(buf, n, "undefined");
        return buf;
    }
    uint64_t ap = u.p < 0 ? 0 - (uint64_t)u.p : (uint64_t)u.p, g = gcd64(ap, (uint64_t)u.q);
    if (!g)
        g = 1;
    int64_t p = u.p / (int64_t)g, q = u.q / (int64_t)g;
    uint64_t whole = ap / (uint64_t)u.q, frac = (ap % (uint64_t)u.q) * 1000000 / (uint64_t)u.q;
    fx_fmt(buf, n, "%lld/%lld (%s%llu.%06llu)", (long long)p, (long long)q, u.p < 0 ? "-" : "",
           (unsigned long long)whole, (unsigned long long)frac);
    return buf;
}

static const fx_ctx quiet; /* a context without tracing (constant, not state) */
/* The arguments (ratstr formatting) are evaluated only when tracing. */
#define TRACE(t, ...)                   \
    do {                                \
        if ((t)->trace)                 \
            fx_trace((t), __VA_ARGS__); \
    } while (0)
static const fx_ctx *traced(const fx_ctx *t) { return t && t->trace ? t : &quiet; }

static const char *algo_name(fx_line_clipper a)
{
    static const char *const n[] = {"direct", "cohen-sutherland", "liang-barsky",
                                    "nicholl-lee-nicholl"};
    return a < FX_CLIP_COUNT ? n[a] : "?";
}

/* ---- Cohen-Sutherland ---- */

static int cohen(const fx_ctx *t, const seg *s, rat *u1, rat *u2)
{
    rat u[2] = {{0, 1}, {1, 1}};
    unsigned c[2] = {code_at(s, u[0]), code_at(s, u[1])};
    char b0[5], b1[5], b2[5], r1[48];
    for (int iter = 0;; iter++) {
        bits4(b0, c[0]);
        bits4(b1, c[1]);
        int triv = fx_clip_trivial(c[0], c[1]);
        if (triv > 0) {
            TRACE(t, "  codes %s %s: accept", b0, b1);
            break;
        }
        if (triv < 0) {
            bits4(b2, c[0] & c[1]);
            TRACE(t, "  codes %s %s: AND %s != 0000, reject", b0, b1, b2);
            return 0;
        }
        /* Move an outside endpoint onto the boundary its lowest code bit
         * names (left, right, below, above, as in the course). */
        int e = c[0] ? 0 : 1;
        unsigned bit = c[e] & (0u - c[e]);
        const char *name;
        if (bit == FX_CODE_LEFT) {
            u[e] = mkrat(s->xmin - s->ax, s->dx);
            name = "left";
        } else if (bit == FX_CODE_RIGHT) {
            u[e] = mkrat(s->xmax - s->ax, s->dx);
            name = "right";
        } else if (bit == FX_CODE_BELOW) {
            u[e] = mkrat(s->ymin - s->ay, s->dy);
            name = "below";
        } else {
            u[e] = mkrat(s->ymax - s->ay, s->dy);
            name = "above";
        }
        c[e] = code_at(s, u[e]);
        bits4(b2, c[e]);
        TRACE(t, "  codes %s %s: P%d outside, clip at %s boundary: u=%s, new code %s", b0, b1,
                 e, name, ratstr(r1, sizeof r1, u[e]), b2);
    }
    *u1 = u[0];
    *u2 = u[1];
    return 1;
}

/* ---- Liang-Barsky ---- */

static int liang(const fx_ctx *t, const seg *s, rat *u1, rat *u2, int notes)
{
    int64_t p[4] = {-s->dx, s->dx, -s->dy, s->dy};
    int64_t q[4] = {s->ax - s->xmin, s->xmax - s->ax, s->ay - s->ymin, s->ymax - s->ay};
    static const char *const edge[4] = {"left", "right", "below", "above"};
    rat a = {0, 1}, b = {1, 1};
    char r1[48], r2[48], r3[48];
    if (notes)
        TRACE(t, "  p_k, q_k in pixels (the window's edges through its outermost pixel centres)");
    else
        TRACE(t, "  p_k, q_k in half pixels (the window's edges are pixel borders)");
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            TRACE(t, "  k=%d %-5s p=0 q=%lld: parallel, %s", k + 1, edge[k], (long long)q[k],
                     q[k] < 0 ? "outside -> reject" : "inside");
            if (q[k] < 0)
                return 0;
            continue;
        }
        rat r = mkrat(q[k], p[k]);
        if (p[k] < 0) {
            if (ratcmp(r, a) > 0)
                a = r;
        } else if (ratcmp(r, b) < 0) {
            b = r;
        }
        TRACE(t, "  k=%d %-5s p=%lld q=%lld r=%s -> u1=%s u2=%s", k + 1, edge[k],
                 (long long)p[k], (long long)q[k], ratstr(r1, sizeof r1, r),
                 ratstr(r2, sizeof r2, a), ratstr(r3, sizeof r3, b));
        if (ratcmp(a, b) > 0) {
            TRACE(t, "  u1 > u2: reject");
            return 0;
        }
    }
    *u1 = a;
    *u2 = b;
    return 1;
}

/* ---- Nicholl-Lee-Nicholl ----
 *
 * P1's region (inside, edge or corner) is brought to one canonical case by
 * reflections and a swap of the axes, which map the window onto another
 * rectangle and leave the parameter u unchanged. In the canonical frame P1 is
 * inside, in the left edge region (x < xmin, ymin <= y <= ymax), or in the
 * left-above corner region (x < xmin, y > ymax). The rays from P1 to the
 * window corners then name P2's region by the side of the line each corner
 * lies on (one cross product each, no division), and only the intersections
 * that region needs are formed. */

enum { EL, ER, EB, EA }; /* edges: left, right, below, above */

typedef struct {
    seg s;
    char name[4]; /* canonical edge -> original edge letter */
} nln_frame;

static void flip_x(nln_frame *f)
{
    seg *s = &f->s;
    int64_t t = s->xmin;
    s->ax = -s->ax;
    s->dx = -s->dx;
    s->xmin = -s->xmax;
    s->xmax = -t;
    char c = f->name[EL];
    f->name[EL] = f->name[ER];
    f->name[ER] = c;
}

static void flip_y(nln_frame *f)
{
    seg *s = &f->s;
    int64_t t = s->ymin;
    s->ay = -s->ay;
    s->dy = -s->dy;
    s->ymin = -s->ymax;
    s->ymax = -t;
    char c = f->name[EB];
    f->name[EB] = f->name[EA];
    f->name[EA] = c;
}

static void swap_xy(nln_frame *f)
{
    seg *s = &f->s;
    int64_t t;
    t = s->ax, s->ax = s->ay, s->ay = t;
    t = s->dx, s->dx = s->dy, s->dy = t;
    t = s->xmin, s->xmin = s->ymin, s->ymin = t;
    t = s->xmax, s->xmax = s->ymax, s->ymax = t;
    char c = f->name[EL];
    f->name[EL] = f->name[EB];
    f->name[EB] = c;
    c = f->name[ER];
    f->name[ER] = f->name[EA];
    f->name[EA] = c;
}

/* Which side of the line through P1 along D the point (cx, cy) is on:
 * > 0 to the left of D (counter-clockwise), < 0 to the right, 0 on it. */
static int side(const seg *s, int64_t cx, int64_t cy)
{
    return mulcmp(s->dx, cy - s->ay, s->dy, cx - s->ax);
}

static rat edge_u(const seg *s, int e)
{
    switch (e) {
    case EL: return mkrat(s->xmin - s->ax, s->dx);
    case ER: return mkrat(s->xmax - s->ax, s->dx);
    case EB: return mkrat(s->ymin - s->ay, s->dy);
    default: return mkrat(s->ymax - s->ay, s->dy);
    }
}

/* Leaving through edge e, or at P2 when P2 has not reached it. */
static rat exit_u(const seg *s, int e)
{
    int64_t x2 = s->ax + s->dx, y2 = s->ay + s->dy;
    int beyond = e == EL ? x2 < s->xmin : e == ER ? x2 > s->xmax : e == EB ? y2 < s->ymin
                                                                           : y2 > s->ymax;
    rat one = {1, 1};
    return beyond ? edge_u(s, e) : one;
}

static int nln(const fx_ctx *t, const seg *s0, rat *u1, rat *u2)
{
    nln_frame f = {*s0, {'L', 'R', 'B', 'A'}};
    seg *s = &f.s;
    int l = s->ax < s->xmin, r = s->ax > s->xmax, b = s->ay < s->ymin, a = s->ay > s->ymax;
    rat zero = {0, 1}, one = {1, 1};
    char r1[48], r2[48];
    int64_t x2 = s->ax + s->dx, y2 = s->ay + s->dy;
    if (!(l | r | b | a)) {
        /* P1 inside: P2 inside, or in the region L, R, B or A cut out by
         * the rays from P1 to the corners. */
        if (x2 >= s->xmin && x2 <= s->xmax && y2 >= s->ymin && y2 <= s->ymax) {
            TRACE(t, "  P1 inside, P2 inside: accept");
            *u1 = zero;
            *u2 = one;
            return 1;
        }
        int e;
        if (s->dx > 0 && side(s, s->xmax, s->ymax) >= 0 && side(s, s->xmax, s->ymin) <= 0)
            e = ER;
        else if (s->dx < 0 && side(s, s->xmin, s->ymin) >= 0 && side(s, s->xmin, s->ymax) <= 0)
            e = EL;
        else
            e = s->dy > 0 ? EA : EB;
        *u1 = zero;
        *u2 = edge_u(s, e);
        TRACE(t, "  P1 inside, P2 in region %c: u2=%s", f.name[e], ratstr(r2, sizeof r2, *u2));
        return 1;
    }
    if (l + r + b + a == 1) {
        /* Edge region: make it the left one. */
        if (b || a)
            swap_xy(&f);
        if (s->ax > s->xmax)
            flip_x(&f);
        x2 = s->ax + s->dx;
        char p1 = f.name[EL];
        if (x2 < s->xmin) {
            TRACE(t, "  P1 in edge region %c, P2 beyond it too: reject", p1);
            return 0;
        }
        /* Rays to the corners left-above, right-above, right-below,
         * left-below sweep P2's possible regions in order. */
        if (side(s, s->xmin, s->ymax) < 0 || side(s, s->xmin, s->ymin) > 0) {
            TRACE(t, "  P1 in edge region %c, P2 outside the corner rays: reject", p1);
            return 0;
        }
        int e = side(s, s->xmax, s->ymax) < 0 ? EA : side(s, s->xmax, s->ymin) > 0 ? EB : ER;
        *u1 = edge_u(s, EL);
        *u2 = exit_u(s, e);
        TRACE(t, "  P1 in edge region %c, P2 in region %c%c: u1=%s u2=%s", p1, p1, f.name[e],
                 ratstr(r1, sizeof r1, *u1), ratstr(r2, sizeof r2, *u2));
        return 1;
    }
    /* Corner region: make it left-above. */
    if (r)
        flip_x(&f);
    if (b)
        flip_y(&f);
    x2 = s->ax + s->dx;
    y2 = s->ay + s->dy;
    char c1 = f.name[EL], c2 = f.name[EA];
    if (x2 < s->xmin || y2 > s->ymax) {
        TRACE(t, "  P1 in corner region %c%c, P2 on the same side: reject", c1, c2);
        return 0;
    }
    /* dx > 0 and dy < 0 now. The ray to the near corner (xmin, ymax) decides
     * the entry edge; the far rays decide the exit. */
    int entry, e;
    if (side(s, s->xmin, s->ymax) >= 0) {
        entry = EL; /* the line passes below-left of the near corner */
        if (side(s, s->xmin, s->ymin) > 0) {
            TRACE(t, "  P1 in corner region %c%c, P2 outside the corner rays: reject", c1, c2);
            return 0;
        }
        e = side(s, s->xmax, s->ymin) < 0 ? ER : EB;
    } else {
        entry = EA;
        if (side(s, s->xmax, s->ymax) < 0) {
            TRACE(t, "  P1 in corner region %c%c, P2 outside the corner rays: reject", c1, c2);
            return 0;
        }
        e = side(s, s->xmax, s->ymin) < 0 ? ER : EB;
    }
    *u1 = edge_u(s, entry);
    *u2 = exit_u(s, e);
    TRACE(t, "  P1 in corner region %c%c, P2 in region %c%c: u1=%s u2=%s", c1, c2,
             f.name[entry], f.name[e], ratstr(r1, sizeof r1, *u1), ratstr(r2, sizeof r2, *u2));
    return 1;
}

/* The direct clip has no parameters of its own; for the API, the parameter
 * range is that of Liang-Barsky (it is the same region). */
static int clip_param(const fx_ctx *t, fx_line_clipper algo, fx_rect w, int32_t x0, int32_t y0,
                      int32_t x1, int32_t y1, int notes, fx_clip_param *out)
{
    seg s = notes ? make_seg_notes(w, x0, y0, x1, y1) : make_seg(w, x0, y0, x1, y1);
    rat u1, u2;
    int r;
    if (s.dx == 0 && s.dy == 0) {
        r = fx_clip_point(w, x0, y0);
        u1.p = 0;
        u2.p = u1.q = u2.q = 1;
        TRACE(t, "  a single point: %s", r ? "inside" : "outside");
    } else if (algo == FX_CLIP_COHEN) {
        r = cohen(t, &s, &u1, &u2);
    } else if (algo == FX_CLIP_NLN) {
        r = nln(t, &s, &u1, &u2);
    } else {
        r = liang(algo == FX_CLIP_LIANG ? t : &quiet, &s, &u1, &u2, notes);
    }
    if (r) {
        out->u1_num = u1.p;
        out->u1_den = u1.q;
        out->u2_num = u2.p;
        out->u2_den = u2.q;
    }
    return r;
}

/* In a course-mode context the trace is the notes' own computation, against
 * the window's edges xwmin..xwmax (make_seg_notes), followed by the range the
 * pixels need, against the pixel borders half a pixel further out; the
 * result is always the latter, so the pixels do not depend on the mode. */
int fx_clip_line_param(const fx_ctx *t, fx_line_clipper algo, fx_rect w, int32_t x0, int32_t y0,
                       int32_t x1, int32_t y1, fx_clip_param *out)
{
    t = traced(t);
    if (fx_rect_empty(w))
        return 0;
    if (!t->trace || t->coords != FX_COORDS_COURSE)
        return clip_param(t, algo, w, x0, y0, x1, y1, 0, out);
    fx_clip_param notes;
    int rn = clip_param(t, algo, w, x0, y0, x1, y1, 1, &notes);
    int r = clip_param(&quiet, algo, w, x0, y0, x1, y1, 0, out);
    char r1[48], r2[48];
    rat a = {notes.u1_num, notes.u1_den}, b = {notes.u2_num, notes.u2_den};
    if (rn)
        TRACE(t, "  notes' window: u1=%s u2=%s", ratstr(r1, sizeof r1, a), ratstr(r2, sizeof r2, b));
    a = (rat){out->u1_num, out->u1_den};
    b = (rat){out->u2_num, out->u2_den};
    if (r)
        TRACE(t, "  pixel borders (half a pixel outside): u1=%s u2=%s", ratstr(r1, sizeof r1, a),
              ratstr(r2, sizeof r2, b));
    else
        TRACE(t, "  pixel borders (half a pixel outside): nothing inside");
    return r;
}

static int step_inside(const fx_bres *b, fx_rect w, uint32_t k)
{
    uint32_t m = fx_bres_minor_at(b, k);
    int64_t a = (int64_t)k, mm = m;
    int64_t x = b->x0 + (b->ymajor ? b->sx * mm : b->sx * a);
    int64_t y = b->y0 + (b->ymajor ? b->sy * a : b->sy * mm);
    return x >= w.x0 && x < w.x1 && y >= w.y0 && y < w.y1;
}

int fx_clip_line_steps(const fx_ctx *t, fx_line_clipper algo, fx_rect w, int32_t x0, int32_t y0,
                       int32_t x1, int32_t y1, uint32_t *k0, uint32_t *k1)
{
    fx_bres b;
    t = traced(t);
    fx_bres_init(&b, x0, y0, x1, y1);
    if (algo == FX_CLIP_DIRECT)
        return fx_bres_clip(&b, w, k0, k1);
    fx_clip_param cp;
    if (!fx_clip_line_param(t, algo, w, x0, y0, x1, y1, &cp))
        return 0;
    /* u = k / major exactly along the major axis. */
    rat u1 = {cp.u1_num, cp.u1_den}, u2 = {cp.u2_num, cp.u2_den};
    int ex;
    uint32_t a = scale_floor(u1, b.major, &ex);
    if (!ex)
        a++;
    uint32_t z = scale_floor(u2, b.major, &ex);
    /* Only an exact half-pixel tie on the minor axis can put the end steps
     * of the range outside the window (see clip.h): one check per end. */
    int fa = 0, fz = 0;
    if (a <= z && !step_inside(&b, w, a)) {
        a++;
        fa = 1;
    }
    if (a <= z && !step_inside(&b, w, z)) {
        z--;
        fz = 1;
    }
    if (a > z) {
        TRACE(t, "  no pixel inside (steps %u..%u)", a, z);
        return 0;
    }
    TRACE(t, "  steps k=%u..%u of %u%s", a, z, b.major,
             fa || fz ? " (a half-pixel tie at an end moved it one step)" : "");
    *k0 = a;
    *k1 = z;
    return 1;
}

void fx_clip_draw_line(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    fx_line_clipper algo = c->line_clipper < FX_CLIP_COUNT ? (fx_line_clipper)c->line_clipper
                                                           : FX_CLIP_DIRECT;
    if (c->trace) {
        char b0[5], b1[5];
        bits4(b0, fx_clip_region_code(c->clip, x0, y0));
        bits4(b1, fx_clip_region_code(c->clip, x1, y1));
        fx_trace(c, "%s (%d,%d)->(%d,%d) window x %d..%d y %d..%d: codes %s %s",
                 algo_name(algo), x0, y0, x1, y1, c->clip.x0, c->clip.x1 - 1, c->clip.y0,
                 c->clip.y1 - 1, b0, b1);
        if (algo == FX_CLIP_COHEN) {
            /* the codes again as the notes compute them: sign bits, no comparisons */
            for (int e = 0; e < 2; e++) {
                int64_t d[4];
                char b[5];
                bits4(b, fx_clip_region_code_signs(c->clip, e ? x1 : x0, e ? y1 : y0, d));
                fx_trace(c, "  P%d sign bits of ywmax-y=%lld y-ywmin=%lld xwmax-x=%lld x-xwmin=%lld: %s", e + 1,
                         (long long)d[0], (long long)d[1], (long long)d[2], (long long)d[3], b);
            }
        }
    }
    uint32_t k0, k1, e0, e1;
    if (!fx_clip_line_steps(c, algo, c->clip, x0, y0, x1, y1, &k0, &k1))
        return;
    fx_ctx q = *c;
    q.trace = 0; /* the walk's own decision table would drown the clipper's steps */
    q.exterior = 0;
    if (c->exterior && fx_clip_line_steps(0, algo, c->exterior_rect, x0, y0, x1, y1, &e0, &e1)) {
        /* A line meets a rectangle in one run of steps: what is left outside
         * is at most a run before it and a run after it. */
        if (e0 > k0)
            fx_line_steps_inside(&q, x0, y0, x1, y1, k0, FX_MIN(k1, e0 - 1));
        if (e1 < k1)
            fx_line_steps_inside(&q, x0, y0, x1, y1, FX_MAX(k0, e1 + 1), k1);
        return;
    }
    fx_line_steps_inside(&q, x0, y0, x1, y1, k0, k1);
}

/* ---- clip stack ---- */

void fx_clip_stack_init(fx_clip_stack *s, fx_rect *mem, uint32_t cap)
{
    s->saved = mem;
    s->cap = mem ? cap : 0;
    s->n = 0;
}

int fx_clip_push(fx_clip_stack *s, fx_ctx *c, fx_rect r)
{
    if (s->n >= s->cap)
        return -FX_ENOSPC;
    s->saved[s->n++] = c->clip;
    fx_rect in = fx_rect_intersect(c->clip, r);
    if (fx_rect_empty(in)) /* keep it well-formed: an empty window at the old corner */
        in.x1 = in.x0, in.y1 = in.y0;
    c->clip = in;
    return 0;
}

int fx_clip_pop(fx_clip_stack *s, fx_ctx *c)
{
    if (!s->n)
        return -FX_EINVAL;
    c->clip = s->saved[--s->n];
    return 0;
}
