/* SPDX-License-Identifier: MIT */
/* 128-bit helpers for exact geometry (clip, polyclip, xform); not installed.
 * Built on fx_smul64_wide so 32-bit targets need no __int128. */
#ifndef FIXEL_WIDE_H
#define FIXEL_WIDE_H

#include <stdint.h>
#include "fixel/fixed.h"

typedef struct {
    int64_t hi;
    uint64_t lo;
} fx_s128;

static inline fx_s128 fx_w_mul(int64_t a, int64_t b)
{
    fx_s128 r;
    fx_smul64_wide(a, b, &r.hi, &r.lo);
    return r;
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

/* |n| / d for d > 0: quotient (saturated to UINT64_MAX when it does not fit)
 * and remainder. */
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
    uint64_t r = hi, q = 0;
    for (int i = 63; i >= 0; i--) {
        uint64_t top = r >> 63;
        r = (r << 1) | ((lo >> i) & 1);
        if (top || r >= d) {
            r -= d;
            q |= (uint64_t)1 << i;
        }
    }
    *rem = r;
    return q;
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
static inline int64_t fx_w_rounddiv(fx_s128 n, int64_t d)
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

#endif
