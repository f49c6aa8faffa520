/* SPDX-License-Identifier: MIT */
/* The core's one 128-bit arithmetic module, for exact geometry (fill set-up,
 * clip, polyclip, stroke, xform); not installed. Built on fx_smul64_wide so
 * 32-bit targets need no __int128. Values are two's complement, hi:lo.
 *
 * Rounding rule, one per operation (the name says it):
 *   fx_w_floordiv, fx_w_floordivmod  toward minus infinity
 *   fx_w_ceildiv                     toward plus infinity
 *   fx_w_rounddiv_away               to nearest, ties away from zero
 *   fx_w_rounddiv_up                 to nearest, ties toward plus infinity
 * The two nearest forms differ only on exact negative halves; each caller
 * keeps the one its pixels were defined with (clip/xform/stroke: away;
 * the fill's attribute planes: up). Quotients that do not fit saturate
 * unless the function says its caller guarantees the fit. */
#ifndef FIXEL_WIDE_H
#define FIXEL_WIDE_H

#include <stdint.h>
#include "fixel/fixed.h"

typedef struct {
    int64_t hi;
    uint64_t lo;
} fx_s128;

/* Where the compiler has a 128-bit type the product is its one multiply
 * instruction, inline (the triangle set-up forms several per attribute);
 * elsewhere fx_smul64_wide. Both give the same bits. */
static inline fx_s128 fx_w_mul(int64_t a, int64_t b)
{
    fx_s128 r;
#if defined(__SIZEOF_INT128__) && !defined(FX_NO_INT128)
    __extension__ typedef __int128 i128;
    i128 p = (i128)a * b;
    r.hi = (int64_t)(p >> 64);
    r.lo = (uint64_t)p;
#else
    fx_smul64_wide(a, b, &r.hi, &r.lo);
#endif
    return r;
}

/* The unsigned full product, the same way (fx_umul64_wide's bits). */
static inline void fx_w_umul(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#if defined(__SIZEOF_INT128__) && !defined(FX_NO_INT128)
    __extension__ typedef unsigned __int128 u128;
    u128 p = (u128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
#else
    fx_umul64_wide(a, b, hi, lo);
#endif
}

static inline fx_s128 fx_w_from(int64_t a)
{
    fx_s128 r = {a < 0 ? -1 : 0, (uint64_t)a};
    return r;
}

static inline fx_s128 fx_w_add(fx_s128 a, fx_s128 b)
{
    fx_s128 r;
    r.lo = a.lo + b.lo;
    r.hi = (int64_t)((uint64_t)a.hi + (uint64_t)b.hi + (r.lo < a.lo));
    return r;
}

static inline fx_s128 fx_w_neg(fx_s128 a)
{
    fx_s128 r;
    r.lo = ~a.lo + 1;
    r.hi = (int64_t)(~(uint64_t)a.hi + (r.lo == 0));
    return r;
}

static inline fx_s128 fx_w_sub(fx_s128 a, fx_s128 b) { return fx_w_add(a, fx_w_neg(b)); }

static inline int fx_w_cmp(fx_s128 a, fx_s128 b)
{
    if (a.hi != b.hi)
        return a.hi < b.hi ? -1 : 1;
    return a.lo < b.lo ? -1 : a.lo > b.lo;
}

static inline int fx_w_sign(fx_s128 a) { return a.hi < 0 ? -1 : (a.hi || a.lo) ? 1 : 0; }

/* sign(a*b - c*d). */
static inline int fx_w_mulcmp(int64_t a, int64_t b, int64_t c, int64_t d)
{
    return fx_w_cmp(fx_w_mul(a, b), fx_w_mul(c, d));
}

static inline fx_s128 fx_w_shl(fx_s128 a, unsigned n) /* 0 < n < 64 */
{
    fx_s128 r = {(int64_t)(((uint64_t)a.hi << n) | (a.lo >> (64 - n))), a.lo << n};
    return r;
}

/* (hi:lo) / d for d != 0: quotient and remainder, exact when hi < d (Hacker's
 * Delight divlu on 32-bit digits); when hi >= d the quotient does not fit and
 * saturates to UINT64_MAX with remainder 0. */
static inline uint64_t fx_w_udivmod(uint64_t hi, uint64_t lo, uint64_t d, uint64_t *rem)
{
    if (!hi) {
        *rem = lo % d;
        return lo / d;
    }
    if (hi >= d) {
        *rem = 0;
        return UINT64_MAX;
    }
#if defined(__x86_64__) && !defined(FX_NO_ASM)
    /* x86-64's divide takes the 128-bit dividend itself, and hi < d is
     * exactly its no-overflow condition: one instruction for the digit
     * loop below (the triangle set-up divides eight times a triangle). */
    uint64_t q, r;
    __asm__("divq %4" : "=a"(q), "=d"(r) : "a"(lo), "d"(hi), "rm"(d) : "cc");
    *rem = r;
    return q;
#endif
    const uint64_t b = (uint64_t)1 << 32;
    unsigned s = (unsigned)__builtin_clzll(d);
    uint64_t v = d << s;
    uint64_t vn1 = v >> 32, vn0 = v & 0xFFFFFFFFu;
    uint64_t un32 = (hi << s) | (s ? lo >> (64 - s) : 0), un10 = lo << s;
    uint64_t un1 = un10 >> 32, un0 = un10 & 0xFFFFFFFFu;
    uint64_t q1 = un32 / vn1, rhat = un32 - q1 * vn1;
    while (q1 >= b || q1 * vn0 > b * rhat + un1) {
        q1--;
        rhat += vn1;
        if (rhat >= b)
            break;
    }
    uint64_t un21 = un32 * b + un1 - q1 * v;
    uint64_t q0 = un21 / vn1;
    rhat = un21 - q0 * vn1;
    while (q0 >= b || q0 * vn0 > b * rhat + un0) {
        q0--;
        rhat += vn1;
        if (rhat >= b)
            break;
    }
    *rem = (un21 * b + un0 - q0 * v) >> s;
    return q1 * b + q0;
}

/* floor(n / d) and n - d*q for d > 0; the caller guarantees the quotient
 * fits in int64 (no saturation). */
static inline void fx_w_floordivmod(fx_s128 n, int64_t d, int64_t *q, int64_t *r)
{
    int neg = n.hi < 0;
    fx_s128 m = neg ? fx_w_neg(n) : n;
    uint64_t rem, uq = fx_w_udivmod((uint64_t)m.hi, m.lo, (uint64_t)d, &rem);
    if (!neg) {
        *q = (int64_t)uq;
        *r = (int64_t)rem;
    } else if (rem == 0) {
        *q = -(int64_t)uq;
        *r = 0;
    } else {
        *q = -(int64_t)uq - 1;
        *r = d - (int64_t)rem;
    }
}

/* floor(n / d), d > 0, saturated to int64. */
static inline int64_t fx_w_floordiv(fx_s128 n, int64_t d)
{
    int neg = n.hi < 0;
    fx_s128 a = neg ? fx_w_neg(n) : n;
    uint64_t rem, q = fx_w_udivmod((uint64_t)a.hi, a.lo, (uint64_t)d, &rem);
    if (!neg)
        return q > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)q;
    q += rem != 0;
    return q > (uint64_t)INT64_MAX ? INT64_MIN : -(int64_t)q;
}

static inline int64_t fx_w_ceildiv(fx_s128 n, int64_t d)
{
    int64_t f = fx_w_floordiv(fx_w_neg(n), d);
    return f == INT64_MIN ? INT64_MAX : -f;
}

/* n / d rounded to nearest, ties away from zero, for d != 0; saturated. */
static inline int64_t fx_w_rounddiv_away(fx_s128 n, int64_t d)
{
    if (d < 0) {
        n = fx_w_neg(n);
        d = -d;
    }
    int neg = n.hi < 0;
    fx_s128 a = neg ? fx_w_neg(n) : n;
    uint64_t rem, q = fx_w_udivmod((uint64_t)a.hi, a.lo, (uint64_t)d, &rem);
    if (q != UINT64_MAX && rem >= (uint64_t)d - rem)
        q++;
    if (q > (uint64_t)INT64_MAX)
        return neg ? INT64_MIN : INT64_MAX;
    return neg ? -(int64_t)q : (int64_t)q;
}

/* n / d rounded to nearest, ties toward plus infinity (floor((2n + d) / 2d)),
 * for d != 0; saturated. */
static inline int64_t fx_w_rounddiv_up(fx_s128 n, int64_t d)
{
    if (d < 0) {
        n = fx_w_neg(n);
        d = -d;
    }
    fx_s128 t = fx_w_add(fx_w_shl(n, 1), fx_w_from(d));
    int neg = t.hi < 0;
    fx_s128 m = neg ? fx_w_neg(t) : t;
    uint64_t d2 = (uint64_t)d * 2;
    if ((uint64_t)m.hi >= d2)
        return neg ? INT64_MIN : INT64_MAX;
    uint64_t rem, uq = fx_w_udivmod((uint64_t)m.hi, m.lo, d2, &rem);
    if (!neg)
        return uq > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)uq;
    uint64_t fq = uq + (rem != 0); /* floor of a negative quotient */
    return fq > (uint64_t)INT64_MAX ? INT64_MIN : -(int64_t)fq;
}

#endif
