/* SPDX-License-Identifier: MIT */
/* fixel — paraboloid, hyperboloids and Barr's superquadrics as closed
 * meshes (contracts in fixel/objects.h). */
#include "fixel/objects.h"
#include "fixel/error.h"
#include "objects_int.h"

#define MAXLEN (1024 * FX16_ONE)

/* log2 of x > 0 (Q16.16) with 30 fraction bits: the integer part from the
 * leading bit, the fraction bit by bit by squaring the mantissa. */
static int64_t log2_q30(uint32_t x)
{
    int lead = 31;
    while (!(x >> lead))
        lead--;
    uint64_t m = lead >= 30 ? (uint64_t)x >> (lead - 30) : (uint64_t)x << (30 - lead); /* [1, 2) Q30 */
    int64_t r = (int64_t)(lead - 16) * ((int64_t)1 << 30);
    for (int i = 1; i <= 30; i++) {
        m = (m * m) >> 30;
        if (m >= ((uint64_t)2 << 30)) {
            m >>= 1;
            r += (int64_t)1 << (30 - i);
        }
    }
    return r;
}

fx16 fx_signed_pow(fx16 x, fx16 e)
{
    if (x == 0)
        return 0;
    uint32_t ax = x < 0 ? (uint32_t)-(int64_t)x : (uint32_t)x;
    if (ax > FX16_ONE)
        ax = FX16_ONE;
    int64_t l = log2_q30(ax) * e; /* Q46, <= 0 */
    fx16 p = fx16_exp2((fx16)-((-l + ((int64_t)1 << 29)) >> 30));
    return x < 0 ? -p : p;
}

void fx_obj_trig(fx_angle a, fx16 *s, fx16 *c)
{
    /* Exact at quarter turns: a power with a small exponent turns the one
     * unit of error fx_sin may have there into a visible step. */
    if ((a & (FX_ANGLE_90 - 1)) == 0) {
        static const fx16 S[4] = {0, FX16_ONE, 0, -FX16_ONE};
        *s = S[(a >> 30) & 3];
        *c = S[((a >> 30) + 1) & 3];
        return;
    }
    *s = fx_sin(a);
    *c = fx_cos(a);
}

fx_vec3 fx_obj_unit64(int64_t x, int64_t y, int64_t z)
{
    uint64_t m = 0;
    int64_t c[3] = {x, y, z};
    for (int i = 0; i < 3; i++)
        m |= c[i] < 0 ? (uint64_t)-(c[i] + 1) : (uint64_t)c[i];
    int sh = 0;
    while ((m >> sh) >= ((uint64_t)1 << 28))
        sh++;
    fx_vec3 v = fx_vec3_make((fx16)(x >> sh), (fx16)(y >> sh), (fx16)(z >> sh));
    /* Short vectors lose precision in the normalization: scale them up. */
    while (v.x > -(1 << 26) && v.x < (1 << 26) && v.y > -(1 << 26) && v.y < (1 << 26) && v.z > -(1 << 26) &&
           v.z < (1 << 26) && (v.x || v.y || v.z))
        v.x *= 2, v.y *= 2, v.z *= 2;
    if (fx_vec3_normalize(&v) < 0)
        return fx_vec3_make(0, FX16_ONE, 0);
    return v;
}

static fx_angle turn(int32_t i, int32_t n, unsigned sh)
{
    return (fx_angle)((((uint64_t)i) << sh) / (uint64_t)n);
}

static int64_t mul(int64_t a, int64_t b) { return (a * b) >> 16; }

static int seg_ok(int32_t n, int32_t lo) { return n >= lo && n <= FX_MESH_MAX_SEG; }
static int len_ok(fx16 v) { return v > 0 && v <= MAXLEN; }
static int exp_ok(fx16 e) { return e >= FX_SQ_EXP_MIN && e <= FX_SQ_EXP_MAX; }

/* h / c for the hyperboloids, and whether the rim stays within the
 * coordinate bound. */
static int hyper_ok(const fx_quadric *q)
{
    if (!len_ok(q->c) || !len_ok(q->h) || (int64_t)q->h > 256 * (int64_t)q->c)
        return 0;
    int64_t t = ((int64_t)q->h << 16) / q->c;
    int64_t r = fx_isqrt64((uint64_t)(((int64_t)1 << 32) + t * t)); /* Q16 */
    int64_t ab = q->a > q->b ? q->a : q->b;
    return mul(ab, r) <= MAXLEN;
}

int fx_quadric_size(const fx_quadric *q, int32_t *nv, int32_t *nt)
{
    int32_t n = q->n, k = q->k;
    if (!seg_ok(n, 3) || !seg_ok(k, 2) || !len_ok(q->a) || !len_ok(q->b))
        return -FX_EINVAL;
    switch (q->kind) {
    case FX_QUADRIC_PARABOLOID:
        if (!len_ok(q->h))
            return -FX_EINVAL;
        *nv = (k + 1) * (n + 1) + 1 + n, *nt = 2 * n * k;
        return 0;
    case FX_QUADRIC_HYPERBOLOID1:
        if (!hyper_ok(q))
            return -FX_EINVAL;
        *nv = (k + 1) * (n + 1) + 2 * (1 + n), *nt = 2 * n * k + 2 * n;
        return 0;
    case FX_QUADRIC_HYPERBOLOID2:
        if (!hyper_ok(q) || q->h <= q->c)
            return -FX_EINVAL;
        *nv = 2 * ((k + 1) * (n + 1) + 1 + n), *nt = 4 * n * k;
        return 0;
    case FX_QUADRIC_SUPERELLIPSOID:
        if (!len_ok(q->c) || !exp_ok(q->e1) || !exp_ok(q->e2))
            return -FX_EINVAL;
        *nv = (k + 1) * (n + 1), *nt = 2 * n * (k - 1);
        return 0;
    case FX_QUADRIC_SUPERTOROID:
        if (k < 3 || !exp_ok(q->e1) || !exp_ok(q->e2) || (int64_t)q->a + q->b > MAXLEN)
            return -FX_EINVAL;
        *nv = n * k, *nt = 2 * n * k;
        return 0;
    default:
        return -FX_EINVAL;
    }
}

/* Rows 0..k of a surface of revolution, columns 0..n around y (column n
 * repeats column 0), triangles outward when the rows run downward along
 * the outside of the profile. Rows whose radius is 0 are poles: their
 * triangles that would collapse are left out. */
typedef struct profile {
    const fx_quadric *q;
    int sheet; /* hyperboloid of two sheets: +1 top, -1 bottom */
} profile;

/* Radius factor r (the point is (a r sin t, y, b r cos t)) and height of
 * row i, and the scaled normal's radial and axial factors: the normal is
 * (nr sin t * b, ny, nr cos t * a) up to a positive factor. */
static void row(const profile *pf, int32_t i, int64_t *r, int64_t *y, int64_t *nr, int64_t *ny)
{
    const fx_quadric *q = pf->q;
    int32_t k = q->k;
    int64_t one = FX16_ONE;
    switch (q->kind) {
    case FX_QUADRIC_PARABOLOID: {
        /* rim (r = 1, y = h) down to the apex */
        *r = one - (((int64_t)i << 16) + k / 2) / k;
        *y = mul(q->h, mul(*r, *r));
        *nr = 2 * mul(q->h, *r); /* gradient of h(x/a)^2 + h(z/b)^2 - y, times a b */
        *ny = -mul(q->a, q->b);
        return;
    }
    case FX_QUADRIC_HYPERBOLOID1: {
        *y = q->h - (2 * (int64_t)q->h * i + k / 2) / k;
        int64_t t = *y * 65536 / q->c;
        *r = fx_isqrt64((uint64_t)((one << 16) + t * t));
        *nr = mul(*r, q->c); /* (x/a^2, -y/c^2, z/b^2) times a b c */
        *ny = -mul(t, mul(q->a, q->b));
        return;
    }
    default: { /* HYPERBOLOID2: rho from its top value down to 0 (apex) */
        int64_t th = ((int64_t)q->h << 16) / q->c;
        int64_t rmax = fx_isqrt64((uint64_t)(th * th > (one << 16) ? th * th - (one << 16) : 0));
        int32_t j = pf->sheet > 0 ? i : k - i; /* the bottom sheet runs from its apex down */
        int64_t rho = rmax - ((rmax * j + k / 2) / k);
        int64_t t = j == 0 ? th : (int64_t)fx_isqrt64((uint64_t)((one << 16) + rho * rho));
        *r = rho;
        *y = pf->sheet > 0 ? (j == 0 ? q->h : mul(q->c, t)) : (j == 0 ? -q->h : -mul(q->c, t));
        int64_t ty = pf->sheet > 0 ? t : -t;
        *nr = mul(rho, q->c);
        *ny = -mul(ty, mul(q->a, q->b));
        return;
    }
    }
}

static void revolve(fx_mesh *m, const profile *pf)
{
    const fx_quadric *q = pf->q;
    int32_t n = q->n, k = q->k, base = m->nverts;
    for (int32_t i = 0; i <= k; i++) {
        int64_t r, y, nr, ny;
        row(pf, i, &r, &y, &nr, &ny);
        for (int32_t j = 0; j <= n; j++) {
            fx16 s, c;
            fx_obj_trig(turn(j % n, n, 32), &s, &c);
            fx_vec3 p = fx_vec3_make((fx16)mul(mul(q->a, r), s), (fx16)y, (fx16)mul(mul(q->b, r), c));
            fx_vec3 nn = fx_obj_unit64(mul(mul(nr, s), q->b), ny, mul(mul(nr, c), q->a));
            fx_obj_put(m, p, nn);
        }
    }
    /* only the first or the last row can be a pole (radius 0) */
    int64_t r0, rk, t;
    row(pf, 0, &r0, &t, &t, &t);
    row(pf, k, &rk, &t, &t, &t);
    fx_obj_grid_tris(m, base, n, k, r0 == 0, rk == 0);
}

/* A flat cap over row i of the profile, facing up (dir > 0) or down. */
static void cap(fx_mesh *m, const profile *pf, int32_t i, int dir)
{
    const fx_quadric *q = pf->q;
    int32_t n = q->n, c0 = m->nverts;
    int64_t r, y, t;
    row(pf, i, &r, &y, &t, &t);
    fx_vec3 nn = fx_vec3_make(0, dir > 0 ? FX16_ONE : -FX16_ONE, 0);
    fx_obj_put(m, fx_vec3_make(0, (fx16)y, 0), nn);
    for (int32_t j = 0; j < n; j++) {
        fx16 s, c;
        fx_obj_trig(turn(j, n, 32), &s, &c);
        fx_obj_put(m, fx_vec3_make((fx16)mul(mul(q->a, r), s), (fx16)y, (fx16)mul(mul(q->b, r), c)), nn);
    }
    for (int32_t j = 0; j < n; j++) {
        int32_t a = c0 + 1 + j, b = c0 + 1 + (j + 1) % n;
        if (dir > 0)
            fx_obj_tri(m, c0, a, b);
        else
            fx_obj_tri(m, c0, b, a);
    }
}

static void superellipsoid(fx_mesh *m, const fx_quadric *q)
{
    int32_t n = q->n, k = q->k;
    fx16 f1 = 2 * FX16_ONE - q->e1, f2 = 2 * FX16_ONE - q->e2;
    for (int32_t i = 0; i <= k; i++) {
        fx16 sp, cp;
        fx_obj_trig(turn(i, k, 31), &sp, &cp);
        int64_t rad = fx_signed_pow(sp, q->e1), y = fx_signed_pow(cp, q->e1);
        int64_t nrad = fx_signed_pow(sp, f1), ny = fx_signed_pow(cp, f1);
        for (int32_t j = 0; j <= n; j++) {
            fx16 st, ct;
            fx_obj_trig(turn(j % n, n, 32), &st, &ct);
            int64_t px = fx_signed_pow(st, q->e2), pz = fx_signed_pow(ct, q->e2);
            fx_vec3 p = fx_vec3_make((fx16)mul(q->a, mul(rad, px)), (fx16)mul(q->b, y),
                                     (fx16)mul(q->c, mul(rad, pz)));
            /* Barr's normal (C^(2-e) products over the radii), times a b c. */
            int64_t nx = mul(nrad, fx_signed_pow(st, f2)), nz = mul(nrad, fx_signed_pow(ct, f2));
            fx_vec3 nn = fx_obj_unit64(mul(nx, mul(q->b, q->c)), mul(ny, mul(q->a, q->c)), mul(nz, mul(q->a, q->b)));
            fx_obj_put(m, p, nn);
        }
    }
    fx_obj_grid_tris(m, 0, n, k, 1, 1);
}

static void supertoroid(fx_mesh *m, const fx_quadric *q)
{
    int32_t n = q->n, k = q->k;
    fx16 f1 = 2 * FX16_ONE - q->e1, f2 = 2 * FX16_ONE - q->e2;
    for (int32_t i = 0; i < k; i++) {
        fx16 st, ct;
        fx_obj_trig(turn(i, k, 32), &st, &ct);
        int64_t dx = fx_signed_pow(st, q->e2), dz = fx_signed_pow(ct, q->e2);
        int64_t ndx = fx_signed_pow(st, f2), ndz = fx_signed_pow(ct, f2);
        for (int32_t j = 0; j < n; j++) {
            fx16 sp, cp;
            fx_obj_trig(turn(j, n, 32), &sp, &cp);
            int64_t rr = q->a + mul(q->b, fx_signed_pow(cp, q->e1));
            fx_vec3 p = fx_vec3_make((fx16)mul(rr, dx), (fx16)mul(q->b, fx_signed_pow(sp, q->e1)), (fx16)mul(rr, dz));
            int64_t nc = fx_signed_pow(cp, f1);
            fx_vec3 nn = fx_obj_unit64(mul(nc, ndx), fx_signed_pow(sp, f1), mul(nc, ndz));
            fx_obj_put(m, p, nn);
        }
    }
    fx_obj_ring_tris(m, n, k);
}

int fx_quadric_make(fx_mesh *m, const fx_quadric *q)
{
    int32_t nv = 0, nt = 0;
    int e = fx_quadric_size(q, &nv, &nt);
    e = fx_obj_mesh_begin(m, e, nv, nt);
    if (e < 0)
        return e;
    profile top = {q, 1}, bottom = {q, -1};
    switch (q->kind) {
    case FX_QUADRIC_PARABOLOID:
        revolve(m, &top);
        cap(m, &top, 0, 1);
        break;
    case FX_QUADRIC_HYPERBOLOID1:
        revolve(m, &top);
        cap(m, &top, 0, 1);
        cap(m, &top, q->k, -1);
        break;
    case FX_QUADRIC_HYPERBOLOID2:
        revolve(m, &top);
        cap(m, &top, 0, 1);
        revolve(m, &bottom);
        cap(m, &bottom, q->k, -1);
        break;
    case FX_QUADRIC_SUPERELLIPSOID: superellipsoid(m, q); break;
    case FX_QUADRIC_SUPERTOROID: supertoroid(m, q); break;
    default: return -FX_EINVAL;
    }
    return 0;
}
