/* SPDX-License-Identifier: MIT */
/* fixel — Q32.32 arithmetic, GL matrices and the lighting equation for the
 * GLUT layer (see fixel/glcore.h). Integer only, freestanding. */
#include "fixel/glcore.h"
#include "../base/fx_wide.h"


static inline uint64_t uabs64(int64_t v) { return v < 0 ? 0 - (uint64_t)v : (uint64_t)v; }

int64_t fx_muldiv64(int64_t a, int64_t b, int64_t c)
{
    int neg = (a < 0) ^ (b < 0) ^ (c < 0);
    uint64_t ua = uabs64(a), ub = uabs64(b), uc = uabs64(c);
    if (ua == 0 || ub == 0)
        return 0;
    if (uc == 0)
        return neg ^ (c < 0) ? INT64_MIN : INT64_MAX;
    if ((128 - __builtin_clzll(ua) - __builtin_clzll(ub)) <= 62) {
        /* the product fits in 62 bits: one 64-bit division, same rounding */
        uint64_t q = (ua * ub + uc / 2) / uc;
        return neg ? -(int64_t)q : (int64_t)q;
    }
    uint64_t hi, lo;
    fx_w_umul(ua, ub, &hi, &lo);
    /* + c/2 for rounding to nearest (ties away from zero) */
    uint64_t lo2 = lo + uc / 2;
    hi += lo2 < lo;
    lo = lo2;
    if (hi >= uc) /* quotient does not fit in 64 bits */
        return neg ? INT64_MIN : INT64_MAX;
    uint64_t r, q = fx_w_udivmod(hi, lo, uc, &r);
    if (q > (uint64_t)INT64_MAX)
        return neg ? INT64_MIN : INT64_MAX;
    return neg ? -(int64_t)q : (int64_t)q;
}

fx32 fx32_sqrt(fx32 a)
{
    if (a <= 0)
        return 0;
    /* sqrt(a * 2^32): scale a by 4^k into [2^60, 2^62) */
    uint64_t u = (uint64_t)a;
    int k = 0;
    while (u < ((uint64_t)1 << 60)) {
        u <<= 2;
        k++;
    }
    while (u >= ((uint64_t)1 << 62)) {
        u >>= 2;
        k--;
    }
    uint64_t r = fx_isqrt64(u); /* sqrt(a) * 2^k */
    int sh = 16 - k;            /* sqrt(a * 2^32) = sqrt(a) * 2^16 */
    return sh >= 0 ? (fx32)(r << sh) : (fx32)(r >> -sh);
}

/* sin of x in [0, pi/4] (Q2.62) by its Taylor series to x^13. */
static int64_t sin_q62(int64_t x)
{
    int64_t x2 = fx_mul64_shift(x, x, 62), term = x, sum = x;
    for (int n = 2; n <= 12; n += 2) {
        term = fx_mul64_shift(term, x2, 62) / (n * (n + 1));
        sum += (n / 2) & 1 ? -term : term;
    }
    return sum;
}
static int64_t cos_q62(int64_t x)
{
    int64_t x2 = fx_mul64_shift(x, x, 62), term = (int64_t)1 << 62, sum = term;
    for (int n = 1; n <= 11; n += 2) {
        term = fx_mul64_shift(term, x2, 62) / (n * (n + 1));
        sum += ((n + 1) / 2) & 1 ? -term : term;
    }
    return sum;
}

fx32 fx32_sin(fx_angle a)
{
    unsigned oct = a >> 29;
    uint32_t r = a & 0x1FFFFFFFu;
    if (oct & 1)
        r = 0x20000000u - r; /* mirrored within the quadrant */
    int64_t x = fx_mul64_shift((int64_t)r, 1727108826179LL, 8); /* r * 2 pi / 2^32, Q62 */
    int64_t v;
    /* quadrant q = oct / 2: sin = +s, +c, -s, -c with the octant choosing sin or cos */
    int use_cos = (oct == 1 || oct == 2 || oct == 5 || oct == 6);
    v = use_cos ? cos_q62(x) : sin_q62(x);
    if (oct >= 4)
        v = -v;
    return (fx32)((v + ((int64_t)1 << 29)) >> 30);
}

fx32 fx32_cos(fx_angle a) { return fx32_sin(a + 0x40000000u); }

/* ---- matrices ---- */
/* a + b + c + d with every partial sum saturating: the plain sum while it
 * stays in int64, else pinned at INT64_MIN or INT64_MAX (the sign of the
 * partial sum that left the range), never an overflow. */
static inline fx32 sum4(fx32 a, fx32 b, fx32 c, fx32 d)
{
    return fx32_add(fx32_add(fx32_add(a, b), c), d);
}
static inline fx32 sum3(fx32 a, fx32 b, fx32 c) { return fx32_add(fx32_add(a, b), c); }
void fx_glm_identity(fx_glm *m)
{
    for (int i = 0; i < 16; i++)
        m->m[i] = (i % 5 == 0) ? FX32_ONE : 0;
}

/* Bound: each product saturates (fx32_mul) and the four-term sums go
 * through fx32_add, so any two int64 matrices give a result in int64. */
void fx_glm_mul(fx_glm *r, const fx_glm *a, const fx_glm *b)
{
    fx_glm t;
    for (int c = 0; c < 4; c++)
        for (int rr = 0; rr < 4; rr++) {
            fx32 s = 0;
            for (int k = 0; k < 4; k++) {
                fx32 x = a->m[k * 4 + rr], y = b->m[c * 4 + k];
                if (x && y)
                    s = fx32_add(s, (x == FX32_ONE) ? y : (y == FX32_ONE) ? x : fx32_mul(x, y));
            }
            t.m[c * 4 + rr] = s;
        }
    *r = t;
}

/* Every vertex passes here (twice when lit): straight products, without
 * fx_glm_mul's shortcuts for 0 and 1, which fx32_mul gives exactly anyway
 * (round(0 * y) = 0, round(2^32 * y / 2^32) = y). Bound: products
 * saturate and the sums are fx32_add's, so any matrix and vector give
 * each coordinate in int64 (pinned at its ends), never an overflow. */
fx_glv4 fx_glm_apply(const fx_glm *m, fx_glv4 v)
{
    const fx32 *a = m->m;
    fx_glv4 o;
    if (v.w == FX32_ONE) {
        /* a point (nearly every vertex): the last column's products are
         * the column itself, exactly */
        o.x = sum4(fx32_mul(a[0], v.x), fx32_mul(a[4], v.y), fx32_mul(a[8], v.z), a[12]);
        o.y = sum4(fx32_mul(a[1], v.x), fx32_mul(a[5], v.y), fx32_mul(a[9], v.z), a[13]);
        o.z = sum4(fx32_mul(a[2], v.x), fx32_mul(a[6], v.y), fx32_mul(a[10], v.z), a[14]);
        o.w = sum4(fx32_mul(a[3], v.x), fx32_mul(a[7], v.y), fx32_mul(a[11], v.z), a[15]);
        return o;
    }
    o.x = sum4(fx32_mul(a[0], v.x), fx32_mul(a[4], v.y), fx32_mul(a[8], v.z), fx32_mul(a[12], v.w));
    o.y = sum4(fx32_mul(a[1], v.x), fx32_mul(a[5], v.y), fx32_mul(a[9], v.z), fx32_mul(a[13], v.w));
    o.z = sum4(fx32_mul(a[2], v.x), fx32_mul(a[6], v.y), fx32_mul(a[10], v.z), fx32_mul(a[14], v.w));
    o.w = sum4(fx32_mul(a[3], v.x), fx32_mul(a[7], v.y), fx32_mul(a[11], v.z), fx32_mul(a[15], v.w));
    return o;
}

void fx_glm_translate(fx_glm *m, fx32 x, fx32 y, fx32 z)
{
    fx_glm_identity(m);
    m->m[12] = x;
    m->m[13] = y;
    m->m[14] = z;
}

void fx_glm_scale(fx_glm *m, fx32 x, fx32 y, fx32 z)
{
    fx_glm_identity(m);
    m->m[0] = x;
    m->m[5] = y;
    m->m[10] = z;
}

/* Length of v, scaled so the squares fit 64 bits. */
static fx32 v3_len(const fx32 v[3])
{
    uint64_t mx = 0;
    for (int i = 0; i < 3; i++)
        if (uabs64(v[i]) > mx)
            mx = uabs64(v[i]);
    if (!mx)
        return 0;
    int sh = 0; /* bring the largest to [2^29, 2^30) */
    while ((mx >> sh) >= ((uint64_t)1 << 30))
        sh++;
    int up = 0;
    while ((mx << up) < ((uint64_t)1 << 29))
        up++;
    uint64_t s = 0;
    for (int i = 0; i < 3; i++) {
        int64_t c = sh ? (v[i] >> sh) : (int64_t)((uint64_t)v[i] << up);
        s += (uint64_t)(c * c);
    }
    uint64_t l = fx_isqrt64(s); /* < 2^30 * sqrt(3) < 2^31 */
    /* the length of a vector of int64 coordinates can pass INT64_MAX
     * (sqrt(3) * 2^63): it saturates, and normalising by it then gives a
     * vector a little short of unit length instead of a negative length */
    if (sh && l > ((uint64_t)INT64_MAX >> sh))
        return INT64_MAX;
    return sh ? (fx32)(l << sh) : (fx32)(l >> up);
}

int fx_glv3_normalize(fx32 v[3])
{
    fx32 l = v3_len(v);
    if (!l)
        return -1;
    for (int i = 0; i < 3; i++)
        v[i] = fx_muldiv64(v[i], FX32_ONE, l);
    return 0;
}

int fx_glm_rotate(fx_glm *m, fx_angle a, fx32 x, fx32 y, fx32 z)
{
    fx_glm_identity(m);
    fx32 v[3] = {x, y, z};
    if (fx_glv3_normalize(v) < 0)
        return -1;
    x = v[0], y = v[1], z = v[2];
    fx32 c = fx32_cos(a), s = fx32_sin(a), ic = FX32_ONE - c;
    fx32 xy = fx32_mul(fx32_mul(x, y), ic), yz = fx32_mul(fx32_mul(y, z), ic),
         zx = fx32_mul(fx32_mul(z, x), ic);
    fx32 xs = fx32_mul(x, s), ys = fx32_mul(y, s), zs = fx32_mul(z, s);
    m->m[0] = fx32_mul(fx32_mul(x, x), ic) + c;
    m->m[1] = xy + zs;
    m->m[2] = zx - ys;
    m->m[4] = xy - zs;
    m->m[5] = fx32_mul(fx32_mul(y, y), ic) + c;
    m->m[6] = yz + xs;
    m->m[8] = zx + ys;
    m->m[9] = yz - xs;
    m->m[10] = fx32_mul(fx32_mul(z, z), ic) + c;
    return 0;
}

/* The extent hi - lo and the sum hi + lo of a pair of planes, exactly:
 * both fit int64 (*sh = 0, the common case, the bits of the plain
 * arithmetic) or both are taken of the halves (*sh = 1): |hi/2 - lo/2| and
 * |hi/2 + lo/2| are below 2^63 for any int64 hi and lo, and the matrix
 * entries are ratios of the two or a product over the extent, so halving
 * costs one bit of 2^-32 units. With the boundary's +-2^31 units the
 * extent reaches 2^32 units (2^64 in Q32.32): glOrtho(-1.1e9, 1.1e9) and
 * a far plane of 2e9 take the halved path and stay right to 2^-31 units. */
static void span(fx32 lo, fx32 hi, fx32 *ext, fx32 *sum, int *sh)
{
    if (!__builtin_sub_overflow(hi, lo, ext) && !__builtin_add_overflow(hi, lo, sum)) {
        *sh = 0;
        return;
    }
    *ext = (hi >> 1) - (lo >> 1);
    *sum = (hi >> 1) + (lo >> 1);
    *sh = 1;
}

/* Bound: every entry is a quotient of span()'s exact extents and sums
 * (fx_muldiv64: 128-bit product, saturating), so any int64 planes give a
 * matrix with no overflow; 2 / ext with ext halved is 1 / (ext / 2). */
int fx_glm_ortho(fx_glm *m, fx32 l, fx32 r, fx32 b, fx32 t, fx32 n, fx32 f)
{
    fx_glm_identity(m);
    if (l == r || b == t || n == f)
        return -1;
    fx32 rl, rs, tb, ts, fn, fs;
    int hx, hy, hz;
    span(l, r, &rl, &rs, &hx), span(b, t, &tb, &ts, &hy), span(n, f, &fn, &fs, &hz);
    m->m[0] = fx_muldiv64(hx ? FX32_ONE : 2 * FX32_ONE, FX32_ONE, rl);
    m->m[5] = fx_muldiv64(hy ? FX32_ONE : 2 * FX32_ONE, FX32_ONE, tb);
    m->m[10] = fx_muldiv64(hz ? -FX32_ONE : -2 * FX32_ONE, FX32_ONE, fn);
    m->m[12] = fx_muldiv64(fx32_neg(rs), FX32_ONE, rl);
    m->m[13] = fx_muldiv64(fx32_neg(ts), FX32_ONE, tb);
    m->m[14] = fx_muldiv64(fx32_neg(fs), FX32_ONE, fn);
    return 0;
}

/* Bound: as fx_glm_ortho. 2n / (r - l) is n / ((r - l) / 2) on the halved
 * path and -2fn / (f - n) is -fn / ((f - n) / 2): the product f n is
 * fx_muldiv64's 128-bit one; n > 0 and f > 0, so -f does not overflow. */
int fx_glm_frustum(fx_glm *m, fx32 l, fx32 r, fx32 b, fx32 t, fx32 n, fx32 f)
{
    fx_glm_identity(m);
    if (n <= 0 || f <= 0 || l == r || b == t || n == f)
        return -1;
    fx32 rl, rs, tb, ts, fn, fs;
    int hx, hy, hz;
    span(l, r, &rl, &rs, &hx), span(b, t, &tb, &ts, &hy), span(n, f, &fn, &fs, &hz);
    /* 2n fits when n < 2^62; otherwise halve the extent instead */
    int n2ok = n <= INT64_MAX / 2;
    m->m[0] = hx || !n2ok ? fx_muldiv64(n, FX32_ONE, hx ? rl : rl / 2) : fx_muldiv64(2 * n, FX32_ONE, rl);
    m->m[5] = hy || !n2ok ? fx_muldiv64(n, FX32_ONE, hy ? tb : tb / 2) : fx_muldiv64(2 * n, FX32_ONE, tb);
    m->m[8] = fx_muldiv64(rs, FX32_ONE, rl);
    m->m[9] = fx_muldiv64(ts, FX32_ONE, tb);
    m->m[10] = fx_muldiv64(fx32_neg(fs), FX32_ONE, fn);
    m->m[11] = -FX32_ONE;
    m->m[14] = hz ? fx_muldiv64(-f, n, fn) : fx_muldiv64(f <= INT64_MAX / 2 ? -2 * f : -f, n, f <= INT64_MAX / 2 ? fn : fn / 2);
    m->m[15] = 0;
    return 0;
}

/* Bound: as fx_glm_frustum for the depth entries (n and f any int64: the
 * sign of f - n is that of the exact halves, -f n / ((f - n) / 2) with
 * fx32_neg for f = INT64_MIN). */
int fx_glm_perspective(fx_glm *m, fx_angle fovy, fx32 aspect, fx32 n, fx32 f)
{
    fx_glm_identity(m);
    fx32 s = fx32_sin(fovy / 2), c = fx32_cos(fovy / 2);
    if (s == 0 || aspect == 0 || n == f)
        return -1;
    fx32 cot = fx_muldiv64(c, FX32_ONE, s), fn, fs;
    int hz;
    span(n, f, &fn, &fs, &hz);
    m->m[0] = fx_muldiv64(cot, FX32_ONE, aspect);
    m->m[5] = cot;
    m->m[10] = fx_muldiv64(fx32_neg(fs), FX32_ONE, fn);
    m->m[11] = -FX32_ONE;
    int f2ok = f <= INT64_MAX / 2 && f >= INT64_MIN / 2;
    m->m[14] = hz || !f2ok ? fx_muldiv64(fx32_neg(f), n, hz ? fn : fn / 2) : fx_muldiv64(-2 * f, n, fn);
    m->m[15] = 0;
    return 0;
}

/* Bound: saturating products and differences (the callers pass unit
 * vectors, |r| <= 1, but nothing here relies on it). */
static void cross3(const fx32 a[3], const fx32 b[3], fx32 r[3])
{
    fx32 t[3] = {fx32_sub(fx32_mul(a[1], b[2]), fx32_mul(a[2], b[1])),
                 fx32_sub(fx32_mul(a[2], b[0]), fx32_mul(a[0], b[2])),
                 fx32_sub(fx32_mul(a[0], b[1]), fx32_mul(a[1], b[0]))};
    r[0] = t[0], r[1] = t[1], r[2] = t[2];
}

int fx_glm_lookat(fx_glm *m, const fx32 eye[3], const fx32 at[3], const fx32 up[3])
{
    fx_glm_identity(m);
    /* Bound: at - eye saturates (eye and at anywhere in int64); the
     * direction of a saturated difference is off only for points more than
     * 2^31 units apart on an axis, which the boundary cannot produce. */
    fx32 f[3] = {fx32_sub(at[0], eye[0]), fx32_sub(at[1], eye[1]), fx32_sub(at[2], eye[2])};
    fx32 u[3] = {up[0], up[1], up[2]};
    if (fx_glv3_normalize(f) < 0)
        return -1;
    fx_glv3_normalize(u);
    fx32 s[3];
    cross3(f, u, s);
    if (fx_glv3_normalize(s) < 0)
        return -1;
    fx32 uu[3];
    cross3(s, f, uu);
    for (int i = 0; i < 3; i++) {
        m->m[i * 4 + 0] = s[i];
        m->m[i * 4 + 1] = uu[i];
        m->m[i * 4 + 2] = -f[i];
    }
    fx_glm tr, r = *m;
    fx_glm_translate(&tr, fx32_neg(eye[0]), fx32_neg(eye[1]), fx32_neg(eye[2]));
    fx_glm_mul(m, &r, &tr);
    return 0;
}

int fx_glm_normal_matrix(const fx_glm *m, fx32 n[9])
{
    /* a[r][c] of the upper 3x3 */
#define A(r, c) m->m[(c) * 4 + (r)]
    fx32 cof[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = fx32_sub(fx32_mul(A(r1, c1), A(r2, c2)), fx32_mul(A(r1, c2), A(r2, c1)));
        }
    /* Bound: products and sums saturate; a matrix whose 2x2 minors pass
     * 2^31 (scales beyond 46341) gets a normal matrix off in length only,
     * and the lighting uses normals as given anyway. */
    fx32 det = sum3(fx32_mul(A(0, 0), cof[0][0]), fx32_mul(A(0, 1), cof[0][1]),
                    fx32_mul(A(0, 2), cof[0][2]));
#undef A
    if (det == 0) {
        for (int i = 0; i < 9; i++)
            n[i] = (i % 4 == 0) ? FX32_ONE : 0;
        return -1;
    }
    /* inverse transpose = cofactor matrix / det; column-major n[c*3+r] */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            n[c * 3 + r] = fx_muldiv64(cof[r][c], FX32_ONE, det);
    return 0;
}

/* ---- lighting ---- */

/* log2(x) for x in (0, 1] Q16.16, result Q20 (<= 0). */
static int64_t log2_q20(fx16 x)
{
    int ip = 0;
    uint64_t m = (uint64_t)x; /* Q16 */
    while (m < 0x10000) {
        m <<= 1;
        ip--;
    }
    uint64_t m30 = m << 14; /* [1, 2) in Q30 */
    int64_t frac = 0;
    /* branch-free: each bit is as likely 0 as 1, and every lit vertex
     * with a highlight comes here (m30 is in [1, 4) after squaring, so
     * bit 31 is the test m30 >= 2) */
    for (int i = 1; i <= 20; i++) {
        m30 = (m30 * m30) >> 30;
        uint64_t b = m30 >> 31;
        m30 >>= b;
        frac |= (int64_t)b << (20 - i);
    }
    return (int64_t)ip * (1 << 20) + frac;
}

static const uint32_t exp2_frac[20] = {
    1518500250u, 1276901417u, 1170923762u, 1121280436u, 1097253708u, 1085434106u, 1079572136u,
    1076653033u, 1075196443u, 1074468888u, 1074105294u, 1073923544u, 1073832680u, 1073787251u,
    1073764537u, 1073753181u, 1073747502u, 1073744663u, 1073743244u, 1073742534u};

/* 2^p for p <= 0 in Q20; result Q16.16. */
static fx16 exp2_q20(int64_t p)
{
    int64_t k = p >> 20; /* floor */
    uint32_t f = (uint32_t)(p - k * (1 << 20));
    if (k < -40)
        return 0;
    uint64_t r = (uint64_t)1 << 30;
    /* a clear bit multiplies by 1.0 (2^30), which rounds back to r
     * exactly: the same r without a branch per bit */
    for (int i = 0; i < 20; i++) {
        uint64_t bit = (f >> (19 - i)) & 1u;
        uint64_t fi = ((uint64_t)1 << 30) + ((exp2_frac[i] - ((uint64_t)1 << 30)) & (0 - bit));
        r = (r * fi + ((uint64_t)1 << 29)) >> 30;
    }
    /* r in Q30, times 2^k, to Q16 */
    int sh = 14 - (int)k;
    if (sh >= 64)
        return 0;
    return (fx16)((r + ((uint64_t)1 << (sh - 1))) >> sh);
}

fx16 fx_gl_pow(fx16 x, fx16 e)
{
    if (e <= 0)
        return FX16_ONE;
    if (x <= 0)
        return 0;
    if (x >= FX16_ONE)
        return FX16_ONE;
    int64_t l = log2_q20(x);
    int64_t p = (l * e) >> 16;
    return exp2_q20(p);
}

static fx16 clamp01(int64_t v) { return v < 0 ? 0 : v > FX16_ONE ? FX16_ONE : (fx16)v; }

/* The per-light vectors that do not depend on the vertex, computed the
 * way the per-vertex code computed them (so the cache changes no bit) and
 * kept with the light parameters they came from. */
static const fx_gl_shade_light *cached_light(const fx_gl_light *li, fx_gl_shade_light *c)
{
    int same = c->valid;
    for (int k = 0; k < 4 && same; k++)
        same = c->pos[k] == li->pos[k];
    for (int k = 0; k < 3 && same; k++)
        same = c->spot_dir[k] == li->spot_dir[k];
    if (same)
        return c;
    for (int k = 0; k < 4; k++)
        c->pos[k] = li->pos[k];
    for (int k = 0; k < 3; k++)
        c->spot_dir[k] = c->sd[k] = li->spot_dir[k];
    fx_glv3_normalize(c->sd);
    for (int k = 0; k < 3; k++)
        c->vp[k] = li->pos[k];
    fx_glv3_normalize(c->vp);
    c->h[0] = c->vp[0], c->h[1] = c->vp[1], c->h[2] = c->vp[2] + FX32_ONE;
    fx_glv3_normalize(c->h);
    c->valid = 1;
    return c;
}

void fx_gl_shade(const fx_gl_lighting *L, const fx_gl_material *m, const fx32 p[4],
                 const fx32 n[3], fx16 out[4])
{
    fx_gl_shade_cache c;
    for (int i = 0; i < FX_GL_MAX_LIGHTS; i++)
        c.light[i].valid = 0;
    fx_gl_shade_cached(L, &c, m, p, n, out);
}

void fx_gl_shade_cached(const fx_gl_lighting *L, fx_gl_shade_cache *cache,
                        const fx_gl_material *m, const fx32 p[4], const fx32 n[3], fx16 out[4])
{
    int64_t acc[3];
    for (int k = 0; k < 3; k++)
        acc[k] = (int64_t)m->emission[k] + fx16_mul(m->ambient[k], L->model_ambient[k]);
    /* eye position as a point */
    fx32 P[3] = {p[0], p[1], p[2]};
    if (p[3] != FX32_ONE && p[3] != 0)
        for (int i = 0; i < 3; i++)
            P[i] = fx_muldiv64(p[i], FX32_ONE, p[3]);
    /* the unit vector to the eye: (0, 0, 1) for the infinite viewer GL
     * assumes by default, towards the origin with a local viewer (a
     * vertex at the origin keeps (0, 0, 1), fx_glv3_normalize's -1 case) */
    fx32 E[3] = {0, 0, FX32_ONE};
    if (L->local_viewer) {
        fx32 t[3] = {fx32_neg(P[0]), fx32_neg(P[1]), fx32_neg(P[2])};
        if (fx_glv3_normalize(t) == 0)
            E[0] = t[0], E[1] = t[1], E[2] = t[2];
    }
    for (int i = 0; i < FX_GL_MAX_LIGHTS; i++) {
        const fx_gl_light *li = &L->light[i];
        if (!li->enabled)
            continue;
        const fx_gl_shade_light *cl = cached_light(li, &cache->light[i]);
        fx32 VP[3];
        fx32 att = FX32_ONE;
        int directional = li->pos[3] == 0;
        if (directional) {
            VP[0] = cl->vp[0], VP[1] = cl->vp[1], VP[2] = cl->vp[2];
        } else {
            fx32 lp[3] = {li->pos[0], li->pos[1], li->pos[2]};
            if (li->pos[3] != FX32_ONE)
                for (int k = 0; k < 3; k++)
                    lp[k] = fx_muldiv64(lp[k], FX32_ONE, li->pos[3]);
            /* Bound: light and vertex anywhere in int64 (a light at 1e30
             * is at 2^31 units): the difference saturates, its direction
             * stays that of the light for any vertex within 2^31 units */
            for (int k = 0; k < 3; k++)
                VP[k] = fx32_sub(lp[k], P[k]);
            fx32 d = v3_len(VP);
            fx_glv3_normalize(VP);
            if (li->att[0] != FX32_ONE || li->att[1] || li->att[2]) {
                fx32 den = sum3(li->att[0], fx32_mul(li->att[1], d),
                                fx32_mul(li->att[2], fx32_mul(d, d)));
                att = den > 0 ? fx_muldiv64(FX32_ONE, FX32_ONE, den) : FX32_ONE;
                /* Bound: a denominator near 0 makes att up to 2^63; the
                 * factor is clamped to 2^14 so that term * a16 below stays
                 * below 3 * 2^31 * 2^30 < 2^63. Any att above 1 already
                 * saturates a lit colour unless its terms are below
                 * 2^-14, so the clamp changes no colour in [0, 1]. */
                if (att > ((fx32)1 << 46))
                    att = (fx32)1 << 46;
            }
            if (li->spot_cut) {
                const fx32 *sd = cl->sd;
                fx32 c = fx32_neg(sum3(fx32_mul(VP[0], sd[0]), fx32_mul(VP[1], sd[1]),
                                       fx32_mul(VP[2], sd[2])));
                if (c < li->spot_cos)
                    att = 0;
                else if (li->spot_exp > 0)
                    att = fx32_mul(att, (fx32)fx_gl_pow(clamp01(c >> 16), li->spot_exp) << 16);
            }
        }
        if (att == 0)
            continue;
        /* Bound: the normal is the caller's, anywhere in int64 (glNormal3d
         * of 1e30), so the dot products saturate; dif and b are clamped to
         * what an fx16 holds before the narrowing */
        fx32 ndl = sum3(fx32_mul(n[0], VP[0]), fx32_mul(n[1], VP[1]), fx32_mul(n[2], VP[2]));
        fx16 dif = ndl <= 0 ? 0 : ndl >= (fx32)INT32_MAX << 16 ? INT32_MAX : (fx16)(ndl >> 16);
        fx16 spec = 0;
        if (ndl > 0) {
            fx32 H[3] = {VP[0] + E[0], VP[1] + E[1], VP[2] + E[2]};
            if (directional && !L->local_viewer)
                H[0] = cl->h[0], H[1] = cl->h[1], H[2] = cl->h[2];
            else
                fx_glv3_normalize(H);
            fx32 ndh = sum3(fx32_mul(n[0], H[0]), fx32_mul(n[1], H[1]), fx32_mul(n[2], H[2]));
            if (ndh > 0) {
                fx16 b = ndh >= FX32_ONE ? FX16_ONE : (fx16)(ndh >> 16);
                spec = m->shininess > 0 ? fx_gl_pow(b, m->shininess) : FX16_ONE;
            }
        }
        fx16 a16 = (fx16)(att >> 16);
        for (int k = 0; k < 3; k++) {
            int64_t term = (int64_t)fx16_mul(m->ambient[k], li->ambient[k]) +
                           fx16_mul(fx16_mul(m->diffuse[k], li->diffuse[k]), dif) +
                           fx16_mul(fx16_mul(m->specular[k], li->specular[k]), spec);
            if (a16 != FX16_ONE)
                term = (term * a16 + 0x8000) >> 16;
            acc[k] += term;
        }
    }
    for (int k = 0; k < 3; k++)
        out[k] = clamp01(acc[k]);
    out[3] = clamp01(m->diffuse[3]);
}
