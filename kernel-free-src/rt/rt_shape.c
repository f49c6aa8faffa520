/* SPDX-License-Identifier: MIT */
/* fixel — the ray tracer's generic shapes: where a ray, already in object
 * space, crosses a sphere, cube, square, plane or tapered cylinder.
 *
 * Object-space points S are Q16.16 and directions c Q8.24 (8 more bits:
 * a shape scaled up by 16 still gets a direction good to 2^-28). Under the
 * scene-scale limit (fixel/rt.h) a point is below 2^14.3 units (|S| < 2^30.4
 * raw) and a direction below 48 units (2^29.6 raw), so the quadric
 * coefficients A = c.c (Q48), B = S.c (Q40, < 2^61) and C = S.S - 1 (Q32,
 * < 2^62) are exact in int64, the discriminant B^2 - AC (Q80, < 2^124) is
 * exact in 128 bits, its floor square root (Q40) is exact, and each root
 * (-B -+ sqrt) / A is rounded once to Q16.16. docs/RAYTRACE.md has the
 * bounds and the measured errors. */
#include "rt_int.h"

#define ONE ((int64_t)FX16_ONE)

fx_vec3 fx_rt_xform(const fx_mat4 *m, fx_vec3 p, int w)
{
    fx16 r[3];
    for (int i = 0; i < 3; i++) {
        int64_t acc = (int64_t)m->m[i][0] * p.x + (int64_t)m->m[i][1] * p.y + (int64_t)m->m[i][2] * p.z;
        if (w)
            acc += (int64_t)m->m[i][3] * ONE;
        r[i] = rt_sat((acc + 0x8000) >> 16);
    }
    return fx_vec3_make(r[0], r[1], r[2]);
}

fx_vec3 fx_rt_xform_dir24(const fx_mat4 *m, fx_vec3 d)
{
    fx16 r[3];
    for (int i = 0; i < 3; i++) {
        int64_t acc = (int64_t)m->m[i][0] * d.x + (int64_t)m->m[i][1] * d.y + (int64_t)m->m[i][2] * d.z;
        r[i] = rt_sat((acc + 0x80) >> 8);
    }
    return fx_vec3_make(r[0], r[1], r[2]);
}

fx_vec3 fx_rt_normal_to_world(const fx_mat4 *inv, fx_vec3 n)
{
    fx16 r[3];
    for (int i = 0; i < 3; i++) {
        int64_t acc = (int64_t)inv->m[0][i] * n.x + (int64_t)inv->m[1][i] * n.y + (int64_t)inv->m[2][i] * n.z;
        r[i] = rt_sat((acc + 0x8000) >> 16);
    }
    return fx_vec3_make(r[0], r[1], r[2]);
}

uint64_t fx_rt_isqrt128(fx_s128 n)
{
    if (n.hi < 0)
        return 0;
    if (n.hi == 0)
        return fx_isqrt64(n.lo);
    /* A 64-bit root of the top bits, one Newton step (which lands on or just
     * above the root), then an exact correction by squaring. */
    int bits = 128 - __builtin_clzll((uint64_t)n.hi);
    int k = (bits - 64 + 1) / 2;
    uint64_t top = ((uint64_t)n.hi << (64 - 2 * k)) | (n.lo >> (2 * k));
    uint64_t r = (uint64_t)fx_isqrt64(top) << k;
    if (r > (uint64_t)n.hi) {
        uint64_t rem, q = fx_w_udivmod((uint64_t)n.hi, n.lo, r, &rem);
        r = (r >> 1) + (q >> 1) + (r & q & 1);
    }
    if (r > ((uint64_t)1 << 63) - 1)
        r = ((uint64_t)1 << 63) - 1;
    for (int i = 0; i < 4 && fx_w_cmp(fx_w_mul((int64_t)r, (int64_t)r), n) > 0; i++)
        r--;
    for (int i = 0; i < 4 && fx_w_cmp(fx_w_mul((int64_t)(r + 1), (int64_t)(r + 1)), n) <= 0; i++)
        r++;
    return r;
}

fx16 fx_rt_div_shift(fx_s128 n, int64_t d, unsigned shift)
{
    return rt_sat(fx_w_rounddiv_away(fx_w_shl(n, shift), d));
}

/* round(num * 2^16 / den) for Q16.16 operands, saturated; den != 0.
 * |num| < 2^46 (the caller's bound). */
static fx16 div16(int64_t num, int64_t den)
{
    int64_t n = num * ONE;
    if (den < 0)
        n = -n, den = -den;
    int64_t q = (n >= 0 ? n + den / 2 : n - den / 2) / den;
    return rt_sat(q);
}

int fx_rt_box_meets(const fx_rt_box *b, fx_vec3 S, fx_vec3 c)
{
    const fx16 s[3] = {S.x, S.y, S.z}, d[3] = {c.x, c.y, c.z};
    int64_t tin = INT64_MIN, tout = INT64_MAX;
    for (int i = 0; i < 3; i++) {
        if (d[i] == 0) {
            if (s[i] < b->lo[i] || s[i] > b->hi[i])
                return 0;
            continue;
        }
        int64_t ta = div16((int64_t)b->lo[i] - s[i], d[i]), tb = div16((int64_t)b->hi[i] - s[i], d[i]);
        if (ta > tb) {
            int64_t x = ta;
            ta = tb;
            tb = x;
        }
        /* one unit of slack for the rounding of each quotient */
        if (ta - 1 > tin)
            tin = ta - 1;
        if (tb + 1 < tout)
            tout = tb + 1;
    }
    return tin <= tout;
}

/* round(num * 2^16 / den) for a Q16.16 numerator and a Q8.24 direction. */
static fx16 div24(int64_t num, int64_t den)
{
    fx_s128 n = fx_w_from(num);
    if (den < 0)
        n = fx_w_neg(n), den = -den;
    return fx_rt_div_shift(n, den, 24);
}

/* S + c t for a Q8.24 direction */
static int64_t at1(fx16 S, fx16 c, fx16 t) { return S + (((int64_t)c * t + ((int64_t)1 << 23)) >> 24); }

static fx_vec3 at(fx_vec3 S, fx_vec3 c, fx16 t)
{
    return fx_vec3_make(rt_sat(at1(S.x, c.x, t)), rt_sat(at1(S.y, c.y, t)), rt_sat(at1(S.z, c.z, t)));
}

static void put(fx_rt_hitlist *out, int idx, fx16 t, int entering, fx_vec3 n)
{
    if (out->n >= FX_RT_MAX_HITS) {
        out->overflow = 1;
        return;
    }
    fx_rt_hit *h = &out->h[out->n++];
    h->t = t;
    h->obj = (int16_t)idx;
    h->entering = (uint8_t)entering;
    h->flip = 0;
    h->normal = n;
}

/* Roots of A t^2 + 2 B t + C = 0 in Q16.16 for A in Q48, B in Q40 and C in
 * Q32, sorted; the number of roots (a tangent gives two equal ones). */
static int quadratic(int64_t A, int64_t B, int64_t C, fx16 *t0, fx16 *t1)
{
    if (A == 0) {
        if (B == 0)
            return 0;
        fx_s128 n = fx_w_from(-C);
        int64_t d = 2 * B;
        if (d < 0)
            n = fx_w_neg(n), d = -d;
        *t0 = *t1 = fx_rt_div_shift(n, d, 24); /* Q32 / Q40 -> Q-8 */
        return 1;
    }
    fx_s128 disc = fx_w_sub(fx_w_mul(B, B), fx_w_mul(A, C));
    if (disc.hi < 0)
        return 0;
    int64_t sq = (int64_t)fx_rt_isqrt128(disc);
    int64_t a = A, n0 = -B - sq, n1 = -B + sq;
    if (a < 0)
        a = -a, n0 = -n0, n1 = -n1;
    fx16 r0 = fx_rt_div_shift(fx_w_from(n0), a, 24), r1 = fx_rt_div_shift(fx_w_from(n1), a, 24); /* Q40 / Q48 */
    *t0 = r0 < r1 ? r0 : r1;
    *t1 = r0 < r1 ? r1 : r0;
    return 2;
}

static int64_t dot64(fx_vec3 a, fx_vec3 b) { return (int64_t)a.x * b.x + (int64_t)a.y * b.y + (int64_t)a.z * b.z; }

static void sphere(int idx, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    fx16 t0, t1;
    if (quadratic(dot64(c, c), dot64(S, c), dot64(S, S) - (ONE << 16), &t0, &t1) < 2) /* Q48, Q40, Q32 */
        return;
    put(out, idx, t0, 1, at(S, c, t0));
    put(out, idx, t1, 0, at(S, c, t1));
}

static void cube(int idx, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    const fx16 s[3] = {S.x, S.y, S.z}, d[3] = {c.x, c.y, c.z};
    int64_t tin = INT64_MIN, tout = INT64_MAX;
    int fin = -1, fout = -1, sin_ = 0, sout = 0;
    for (int i = 0; i < 3; i++) {
        if (d[i] == 0) {
            if (s[i] < -ONE || s[i] > ONE)
                return;
            continue;
        }
        fx16 ta = div24(-ONE - s[i], d[i]), tb = div24(ONE - s[i], d[i]);
        int sa = -1, sb = 1;
        if (d[i] < 0) {
            fx16 x = ta;
            ta = tb, tb = x, sa = 1, sb = -1;
        }
        if (ta > tin)
            tin = ta, fin = i, sin_ = sa;
        if (tb < tout)
            tout = tb, fout = i, sout = sb;
    }
    if (fin < 0 || fout < 0 || tin > tout)
        return;
    fx16 nin[3] = {0, 0, 0}, nout[3] = {0, 0, 0};
    nin[fin] = sin_ * FX16_ONE;
    nout[fout] = sout * FX16_ONE;
    put(out, idx, (fx16)tin, 1, fx_vec3_make(nin[0], nin[1], nin[2]));
    put(out, idx, (fx16)tout, 0, fx_vec3_make(nout[0], nout[1], nout[2]));
}

static void square(int idx, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    if (c.z == 0)
        return;
    fx16 t = div24(-(int64_t)S.z, c.z);
    fx_vec3 p = at(S, c, t);
    if (p.x < -FX16_ONE || p.x > FX16_ONE || p.y < -FX16_ONE || p.y > FX16_ONE)
        return;
    fx16 nz = c.z > 0 ? -FX16_ONE : FX16_ONE; /* faces the ray */
    put(out, idx, t, 1, fx_vec3_make(0, 0, nz));
    put(out, idx, t, 0, fx_vec3_make(0, 0, -nz));
}

static void plane(int idx, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    if (c.z == 0) {
        out->inside0 = S.z <= 0;
        return;
    }
    out->inside0 = c.z > 0; /* going up: it came from below, inside */
    put(out, idx, div24(-(int64_t)S.z, c.z), c.z < 0, fx_vec3_make(0, 0, FX16_ONE));
}

/* Crossings may be found a hair outside their patch (z just beyond the
 * side's range, or a cap point just beyond its rim) where the ray passes
 * through the rim: with this slack both of a ray's crossings are always
 * found, and the extra candidates lie within the slack of the true ones. */
#define RIM 64 /* 2^-10 */

static void cylinder(int idx, fx16 s, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    int64_t k = (int64_t)s - ONE;                         /* radius 1 + k z, |k| <= 1 */
    int64_t kc = ((int64_t)k * c.z + 0x8000) >> 16;       /* Q24 */
    int64_t F = ONE + rt_mul(k, S.z);                     /* Q16: radius at the start height */
    int64_t A = (int64_t)c.x * c.x + (int64_t)c.y * c.y - kc * kc;      /* Q48 */
    int64_t B = (int64_t)S.x * c.x + (int64_t)S.y * c.y - F * kc;       /* Q40 */
    int64_t C = (int64_t)S.x * S.x + (int64_t)S.y * S.y - F * F;        /* Q32 */
    fx16 tc[4];
    fx_vec3 nc[4];
    int n = 0;
    fx16 r[2];
    int nr = quadratic(A, B, C, &r[0], &r[1]);
    for (int i = 0; i < nr; i++) {
        fx_vec3 p = at(S, c, r[i]);
        if (p.z < -RIM || p.z > FX16_ONE + RIM)
            continue;
        tc[n] = r[i];
        nc[n++] = fx_vec3_make(p.x, p.y, rt_sat(-rt_mul(k, ONE + rt_mul(k, p.z))));
    }
    if (c.z != 0) {
        for (int cap = 0; cap < 2; cap++) {
            fx16 t = div24((cap ? ONE : 0) - S.z, c.z);
            fx_vec3 p = at(S, c, t);
            int64_t rim = (cap ? (int64_t)s : ONE) + RIM;
            /* a crossing far out (a ray almost parallel to the cap) has a
             * saturated point whose squares would overflow their sum */
            if (p.x < -rim || p.x > rim || p.y < -rim || p.y > rim ||
                (int64_t)p.x * p.x + (int64_t)p.y * p.y > rim * rim)
                continue;
            tc[n] = t;
            nc[n++] = fx_vec3_make(0, 0, cap ? FX16_ONE : -FX16_ONE);
        }
    }
    if (n == 0)
        return;
    int lo = 0, hi = 0;
    for (int i = 1; i < n; i++) {
        if (tc[i] < tc[lo])
            lo = i;
        if (tc[i] > tc[hi])
            hi = i;
    }
    put(out, idx, tc[lo], 1, nc[lo]);
    put(out, idx, tc[hi], 0, nc[hi]);
}

/* ---- the torus: a quartic, solved by isolating its roots ----
 *
 * f(t) = g^2 - 4 (px^2 + py^2), g = |p|^2 + 1 - r^2, p = S + c t, is
 * negative inside. Its derivatives along the ray are
 *     f'   = 2 g g' - 8 (px cx + py cy),  g' = 2 p.c
 *     f''  = 2 g'^2 + 2 g g'' - 8 (cx^2 + cy^2),  g'' = 2 c.c
 *     f''' = 6 g' g''
 * so f''' changes sign once, where p.c = 0: f'' is monotone on each side
 * of that point, its roots split the ray into pieces where f' is
 * monotone, and those roots into pieces where f is monotone: each holds at
 * most one root of f, found by bisection on the sign. Signs are exact:
 * p is Q28 (|p| < 3 units inside the box), c Q24 (< 48 units), and every
 * term is one 64 x 64-bit product in 128 bits (below 2^125). No closed
 * form is used, so a double root (a grazing ray) is a root of f' where f
 * is 0 or positive: the ray touches or misses, never a spurious pair. */
typedef struct torus_ray {
    fx_vec3 S, c; /* object space: Q16.16, Q8.24 */
    int64_t k;    /* 1 - r^2, Q56 */
    int64_t cc;   /* c.c, Q48 */
    int64_t cxy;  /* cx^2 + cy^2, Q48 */
} torus_ray;

/* the sign (-1, or 1 for >= 0) of f (which 0), f'/2 (1) or f''/2 (2) at t */
static int torus_sign(const torus_ray *R, int64_t t, int which)
{
    const int64_t S[3] = {R->S.x, R->S.y, R->S.z}, c[3] = {R->c.x, R->c.y, R->c.z};
    int64_t p[3];
    for (int i = 0; i < 3; i++)
        p[i] = (S[i] * ((int64_t)1 << 24) + c[i] * t + (1 << 11)) >> 12; /* Q40 -> Q28 */
    int64_t rho2 = p[0] * p[0] + p[1] * p[1], g = rho2 + p[2] * p[2] + R->k; /* Q56 */
    fx_s128 v;
    if (which == 0) {
        v = fx_w_sub(fx_w_mul(g, g), fx_w_mul(rho2, (int64_t)1 << 58)); /* Q112 */
    } else {
        int64_t pc = p[0] * c[0] + p[1] * c[1], gp = 2 * (pc + p[2] * c[2]); /* Q52 */
        if (which == 1)
            v = fx_w_sub(fx_w_mul(g, gp), fx_w_mul(pc, (int64_t)1 << 58)); /* Q108 */
        else
            v = fx_w_sub(fx_w_add(fx_w_mul(gp, gp), fx_w_mul(g, 2 * R->cc)),
                         fx_w_mul(R->cxy, (int64_t)1 << 58)); /* Q104 */
    }
    return fx_w_sign(v) < 0 ? -1 : 1;
}

/* Between consecutive points of pts (sorted, n of them) where the sign of
 * the which-th function changes, its crossing (the first t of the new
 * sign) by bisection; pts and the crossings merged into out, sorted. */
static int torus_split(const torus_ray *R, int which, const int64_t *pts, int n, int64_t *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        out[m++] = pts[i];
        if (i + 1 == n)
            break;
        int64_t lo = pts[i], hi = pts[i + 1];
        int slo = torus_sign(R, lo, which);
        if (hi - lo < 2 || slo == torus_sign(R, hi, which))
            continue;
        while (hi - lo > 1) {
            int64_t mid = lo + (hi - lo) / 2;
            if (torus_sign(R, mid, which) == slo)
                lo = mid;
            else
                hi = mid;
        }
        out[m++] = hi;
    }
    return m;
}

static void torus(int idx, fx16 r, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    /* the ray's stretch inside the box, 2^-10 beyond the surface so that
     * f > 0 at both ends */
    const int64_t half[3] = {ONE + r + RIM, ONE + r + RIM, (int64_t)r + RIM};
    const fx16 s[3] = {S.x, S.y, S.z}, d[3] = {c.x, c.y, c.z};
    int64_t tin = INT32_MIN, tout = INT32_MAX;
    for (int i = 0; i < 3; i++) {
        if (d[i] == 0) {
            if (s[i] < -half[i] || s[i] > half[i])
                return;
            continue;
        }
        int64_t ta = div24(-half[i] - s[i], d[i]), tb = div24(half[i] - s[i], d[i]);
        if (ta > tb) {
            int64_t x = ta;
            ta = tb, tb = x;
        }
        if (ta > tin)
            tin = ta;
        if (tb < tout)
            tout = tb;
    }
    if (tin >= tout)
        return;
    torus_ray R = {S, c, 0, 0, 0};
    R.k = (ONE << 40) - (int64_t)r * r * ((int64_t)1 << 24);
    R.cc = (int64_t)c.x * c.x + (int64_t)c.y * c.y + (int64_t)c.z * c.z;
    R.cxy = (int64_t)c.x * c.x + (int64_t)c.y * c.y;
    /* f''' = 0 where p.c = 0: t3 = -(S.c) / (c.c) (Q40 / Q48, 24 more bits) */
    int64_t sc = (int64_t)S.x * c.x + (int64_t)S.y * c.y + (int64_t)S.z * c.z;
    int64_t t3 = R.cc ? fx_rt_div_shift(fx_w_from(-sc), R.cc, 24) : tin;
    int64_t p0[3] = {tin, t3, tout}, p1[8], p2[16], p3[32];
    int n0 = t3 > tin && t3 < tout ? 3 : 2;
    if (n0 == 2)
        p0[1] = tout;
    int n1 = torus_split(&R, 2, p0, n0, p1);
    int n2 = torus_split(&R, 1, p1, n1, p2);
    int n3 = torus_split(&R, 0, p2, n2, p3);
    /* the new points of the last split are the crossings of f */
    int ip = 0;
    for (int i = 0; i < n3; i++) {
        if (ip < n2 && p3[i] == p2[ip]) {
            ip++;
            continue;
        }
        fx16 t = (fx16)p3[i];
        int entering = torus_sign(&R, t, 0) < 0;
        fx_vec3 p = at(S, c, t);
        /* grad f / 4 = ((g - 2) px, (g - 2) py, g pz), g in Q16 */
        int64_t g = (((int64_t)p.x * p.x + (int64_t)p.y * p.y + (int64_t)p.z * p.z) >> 16) + (R.k >> 40);
        put(out, idx, t, entering,
            fx_vec3_make(rt_sat(rt_mul(g - 2 * ONE, p.x)), rt_sat(rt_mul(g - 2 * ONE, p.y)), rt_sat(rt_mul(g, p.z))));
    }
}

void fx_rt_leaf_hits(const fx_rt_object *o, int idx, fx_vec3 S, fx_vec3 c, fx_rt_hitlist *out)
{
    switch (o->kind) {
    case FX_RT_SPHERE: sphere(idx, S, c, out); break;
    case FX_RT_CUBE: cube(idx, S, c, out); break;
    case FX_RT_SQUARE: square(idx, S, c, out); break;
    case FX_RT_PLANE: plane(idx, S, c, out); break;
    case FX_RT_CYLINDER: cylinder(idx, o->taper, S, c, out); break;
    case FX_RT_TORUS: torus(idx, o->taper, S, c, out); break;
    default: break;
    }
}
