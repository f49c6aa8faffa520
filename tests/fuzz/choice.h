/* SPDX-License-Identifier: MIT */
/* The grammar-aware targets (fuzz_g*.c, fuzz_png.c) read their input as a
 * stream of choices, not as the file itself: which line, which field, and
 * for each number one of its corners (min, max, 0, +-1, one past each
 * bound, near 2^15, 2^16, 2^24, 2^31, 2^63) or a value inside its range.
 * Every generated file is thus well formed up to one hostile value, what
 * byte mutation of the file itself rarely reaches. Past the end of the
 * input every choice is 0. */
#ifndef FX_FUZZ_CHOICE_H
#define FX_FUZZ_CHOICE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

typedef struct in {
    const uint8_t *p;
    size_t n;
} in;

static uint32_t take(in *s, int bytes)
{
    uint32_t v = 0;
    for (int i = 0; i < bytes; i++) {
        v = v << 8 | (s->n ? *s->p : 0);
        if (s->n)
            s->p++, s->n--;
    }
    return v;
}

/* A corner of min..max (or just outside it), or a value inside. */
static int64_t corner(in *s, int64_t min, int64_t max)
{
    static const int64_t near[] = {32767, 32768, 65535, 65536, 16777215, 16777216, 2147483647, 2147483648LL,
                                   -32768, -32769, -2147483648LL, -2147483649LL, INT64_MAX, INT64_MIN};
    uint32_t cls = take(s, 1);
    switch (cls % 10) {
    case 0: return min;
    case 1: return max;
    case 2: return 0;
    case 3: return 1;
    case 4: return -1;
    case 5: return min > INT64_MIN ? min - 1 : min;
    case 6: return max < INT64_MAX ? max + 1 : max;
    case 7: return near[take(s, 1) % (sizeof near / sizeof near[0])];
    default: {
        uint64_t span = (uint64_t)max - (uint64_t)min;
        uint64_t r = (uint64_t)take(s, 4) << 32 | take(s, 4);
        unsigned bits = take(s, 1) % 64;
        r &= bits == 63 ? ~(uint64_t)0 : (((uint64_t)1 << (bits + 1)) - 1);
        return (int64_t)((uint64_t)min + (span == UINT64_MAX ? r : r % (span + 1)));
    }
    }
}

/* Growing text output; silently stops at the capacity. */
typedef struct out {
    char *b;
    size_t n, cap;
} out;

static void put(out *o, const char *s)
{
    size_t k = strlen(s);
    if (o->n + k + 1 < o->cap) {
        memcpy(o->b + o->n, s, k);
        o->n += k;
        o->b[o->n] = 0;
    }
}

static void putc1(out *o, char c)
{
    if (o->n + 2 < o->cap) {
        o->b[o->n++] = c;
        o->b[o->n] = 0;
    }
}

/* raw / 10^dec as a decimal ("-12.345"); dec 0: an integer. */
static void put_dec(out *o, int64_t raw, int dec)
{
    char t[48];
    uint64_t m = raw < 0 ? 0 - (uint64_t)raw : (uint64_t)raw, p = 1;
    for (int i = 0; i < dec; i++)
        p *= 10;
    if (dec)
        snprintf(t, sizeof t, "%s%llu.%0*llu", raw < 0 ? "-" : "", (unsigned long long)(m / p), dec,
                 (unsigned long long)(m % p));
    else
        snprintf(t, sizeof t, "%s%llu", raw < 0 ? "-" : "", (unsigned long long)m);
    put(o, t);
}

#endif
