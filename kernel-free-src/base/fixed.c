/* SPDX-License-Identifier: MIT */
/* fixel — fixed-point arithmetic (see fixel/fixed.h for the contracts). */
#include "fixel/fixed.h"
#include "fixel/error.h"
#include "fixed_tables.h"

static uint64_t uabs64(int64_t v) { return v < 0 ? 0 - (uint64_t)v : (uint64_t)v; }

/* Rounded quotient of magnitudes, then signed and saturated: the common core
 * of fx16_div and fx16_from_ratio. */
static int32_t div_round_sat(int64_t num, int64_t den)
{
    if (den == 0)
        return num > 0 ? INT32_MAX : num < 0 ? INT32_MIN : 0;
    uint64_t un = uabs64(num), ud = uabs64(den);
    uint64_t q = (2 * un + ud) / (2 * ud);
    int neg = (num < 0) != (den < 0);
    if (neg)
        return q > (uint64_t)INT32_MAX + 1 ? INT32_MIN : (int32_t)(0 - (int64_t)q);
    return q > INT32_MAX ? INT32_MAX : (int32_t)q;
}

fx16 fx16_div(fx16 a, fx16 b) { return div_round_sat((int64_t)a * FX16_ONE, b); }
fx16 fx16_from_ratio(int32_t p, int32_t q) { return div_round_sat((int64_t)p * FX16_ONE, q); }

/* Digit-by-digit square root on T, from the highest even bit TOP down (the
 * one loop of both widths, so each stays in its own register size). */
#define ISQRT_BODY(T, TOP)                  \
    do {                                    \
        T r = 0, bit = (T)1 << (TOP);       \
        while (bit > n)                     \
            bit >>= 2;                      \
        while (bit) {                       \
            if (n >= r + bit) {             \
                n -= r + bit;               \
                r = (r >> 1) + bit;         \
            } else {                        \
                r >>= 1;                    \
            }                               \
            bit >>= 2;                      \
        }                                   \
        return (uint32_t)r;                 \
    } while (0)

uint32_t fx_isqrt64(uint64_t n) { ISQRT_BODY(uint64_t, 62); }
uint32_t fx_isqrt32(uint32_t n) { ISQRT_BODY(uint32_t, 30); }
#undef ISQRT_BODY

fx16 fx16_sqrt(fx16 a) { return a <= 0 ? 0 : (fx16)fx_isqrt64((uint64_t)a << 16); }

uint32_t fx_hypot(int32_t dx, int32_t dy)
{
    uint64_t ax = uabs64(dx), ay = uabs64(dy);
    uint64_t n = ax * ax + ay * ay;
    uint64_t r = fx_isqrt64(n);
    /* (r + 1/2)^2 = r^2 + r + 1/4, so round up exactly when n - r^2 > r. */
    if (n - r * r > r)
        r++;
    return (uint32_t)r;
}

fx_angle fx_angle_from_deg(int32_t deg)
{
    int32_t d = deg % 360;
    if (d < 0)
        d += 360;
    return (fx_angle)((((uint64_t)d << 32) + 180) / 360);
}

fx_angle fx_angle_from_deg16(fx16 deg)
{
    const int64_t turn = (int64_t)360 << 16;
    int64_t d = (int64_t)deg % turn;
    if (d < 0)
        d += turn;
    return (fx_angle)((((uint64_t)d << 32) + (uint64_t)turn / 2) / (uint64_t)turn);
}

fx16 fx_angle_to_deg16(fx_angle a)
{
    const uint64_t turn = (uint64_t)360 << 16;
    uint64_t d = ((uint64_t)a * turn + ((uint64_t)1 << 31)) >> 32;
    return (fx16)(d % turn);
}

/* Quarter-wave lookup: p in [0, 2^30] maps to [0, 90] degrees. */
static int32_t sin_quarter(uint32_t p)
{
    uint32_t i = p >> 20, frac = p & 0xFFFFF;
    if (i >= 1024)
        return fx_sin_quarter[1024];
    int64_t a = fx_sin_quarter[i], b = fx_sin_quarter[i + 1];
    return (int32_t)(a + (((b - a) * frac + (1 << 19)) >> 20));
}

int32_t fx_sin30(fx_angle a)
{
    uint32_t p = a & 0x3FFFFFFFu;
    switch (a >> 30) {
    case 0: return sin_quarter(p);
    case 1: return sin_quarter(0x40000000u - p);
    case 2: return -sin_quarter(p);
    default: return -sin_quarter(0x40000000u - p);
    }
}

int32_t fx_cos30(fx_angle a) { return fx_sin30(a + FX_ANGLE_90); }
fx16 fx_sin(fx_angle a) { return (fx16)(((int64_t)fx_sin30(a) + (1 << 13)) >> 14); }
fx16 fx_cos(fx_angle a) { return fx_sin(a + FX_ANGLE_90); }

fx_angle fx_atan2(int32_t y, int32_t x)
{
    if (x == 0 && y == 0)
        return 0;
    int64_t X = x, Y = y;
    uint32_t base = 0;
    if (X < 0) {
        X = -X;
        Y = -Y;
        base = FX_ANGLE_180;
    }
    /* Scale the vector up to ~2^40 so the shifted terms keep 40 bits. */
    uint64_t m = (uint64_t)X > uabs64(Y) ? (uint64_t)X : uabs64(Y);
    while (m < ((uint64_t)1 << 40)) {
        X *= 2;
        Y *= 2;
        m <<= 1;
    }
    uint32_t z = 0;
    for (int i = 0; i < 32; i++) {
        int64_t nx, ny;
        if (Y > 0) {
            nx = X + (Y >> i);
            ny = Y - (X >> i);
            z += fx_atan_cordic[i];
        } else {
            nx = X - (Y >> i);
            ny = Y + (X >> i);
            z -= fx_atan_cordic[i];
        }
        X = nx;
        Y = ny;
    }
    return base + z;
}

void fx_umul64_wide(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *lo = (mid << 32) | (uint32_t)p00;
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

void fx_smul64_wide(int64_t a, int64_t b, int64_t *hi, uint64_t *lo)
{
    uint64_t h, l;
    fx_umul64_wide(uabs64(a), uabs64(b), &h, &l);
    if ((a < 0) != (b < 0)) {
        l = ~l + 1;
        h = ~h + (l == 0);
    }
    *hi = (int64_t)h;
    *lo = l;
}

int64_t fx_mul64_shift(int64_t a, int64_t b, unsigned shift)
{
    int64_t hi;
    uint64_t lo;
    fx_smul64_wide(a, b, &hi, &lo);
    uint64_t lo2 = lo + ((uint64_t)1 << (shift - 1));
    hi += lo2 < lo;
    int64_t top = hi >> (shift - 1);
    if (top > 0)
        return INT64_MAX;
    if (top < -1)
        return INT64_MIN;
    uint64_t r = ((uint64_t)hi << (64 - shift)) | (lo2 >> shift);
    /* top == 0 means r's bit 63 is clear; top == -1 means it is set. */
    if ((top == 0) != !(r >> 63))
        return top == 0 ? INT64_MAX : INT64_MIN;
    return (int64_t)r;
}

/* Exact decimal -> binary fixed point: the fraction's bits come from
 * repeatedly doubling the decimal digit string (no rounding until the end). */
#define MAX_FRAC_DIGITS 96
static int parse_fixed(const char *s, int len, unsigned fracbits, uint64_t maxpos, int64_t *out)
{
    int i = 0, neg = 0, ndig = 0;
    if (i < len && (s[i] == '-' || s[i] == '+'))
        neg = s[i++] == '-';
    uint64_t ip = 0;
    int overflow = 0;
    while (i < len && s[i] >= '0' && s[i] <= '9') {
        if (ip > (maxpos >> fracbits))
            overflow = 1;
        else
            ip = ip * 10 + (uint64_t)(s[i] - '0');
        i++;
        ndig++;
    }
    uint8_t fd[MAX_FRAC_DIGITS];
    int nf = 0;
    if (i < len && s[i] == '.') {
        i++;
        while (i < len && s[i] >= '0' && s[i] <= '9') {
            if (nf < MAX_FRAC_DIGITS)
                fd[nf++] = (uint8_t)(s[i] - '0');
            i++;
            ndig++;
        }
    }
    if (ndig == 0)
        return -FX_EINVAL;
    if (overflow || ip > (maxpos >> fracbits) + 1)
        return -FX_ERANGE;
    uint64_t frac = 0;
    for (unsigned b = 0; b <= fracbits; b++) { /* one extra bit for rounding */
        int carry = 0;
        for (int k = nf - 1; k >= 0; k--) {
            int v = fd[k] * 2 + carry;
            carry = v >= 10;
            fd[k] = (uint8_t)(v - 10 * carry);
        }
        frac = (frac << 1) | (uint64_t)carry;
    }
    uint64_t mag = (ip << fracbits) + (frac >> 1) + (frac & 1);
    if (mag > maxpos + (uint64_t)neg)
        return -FX_ERANGE;
    *out = neg ? (int64_t)(0 - mag) : (int64_t)mag;
    return i;
}

int fx16_parse(const char *s, int len, fx16 *out)
{
    int64_t v;
    int n = parse_fixed(s, len, 16, INT32_MAX, &v);
    if (n > 0)
        *out = (fx16)v;
    return n;
}

int fx56_parse(const char *s, int len, fx56 *out)
{
    int64_t v;
    int n = parse_fixed(s, len, 56, INT64_MAX, &v);
    if (n > 0)
        *out = v;
    return n;
}

const char *fx_strerror(int err)
{
    if (err < 0)
        err = -err;
    switch (err) {
    case FX_OK: return "success";
    case FX_ENOENT: return "no such file or directory";
    case FX_EIO: return "input/output error";
    case FX_E2BIG: return "too many items";
    case FX_ENOMEM: return "not enough memory";
    case FX_EACCES: return "permission denied";
    case FX_EBUSY: return "device busy";
    case FX_ENODEV: return "no such device";
    case FX_ENOTDIR: return "not a directory";
    case FX_EISDIR: return "is a directory";
    case FX_EINVAL: return "invalid argument";
    case FX_EFBIG: return "file too large";
    case FX_ENOSPC: return "out of caller-provided space";
    case FX_ESPIPE: return "not a regular file (a FIFO, socket or device)";
    case FX_EDOM: return "argument out of domain";
    case FX_ERANGE: return "value out of range";
    case FX_EBADMSG: return "malformed data";
    case FX_EOVERFLOW: return "value too large";
    case FX_ENOTSUP: return "not supported";
    default: return "unknown error";
    }
}

/* ---- exponentials and pseudo-random numbers ---- */

uint32_t fx_rand32(uint32_t *state)
{
    uint32_t x = *state ? *state : 0x9E3779B9u;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

fx16 fx_gauss16(uint32_t *state)
{
    int32_t s = 0;
    for (int i = 0; i < 12; i++)
        s += (int32_t)(fx_rand32(state) >> 16);
    return s - 6 * 65536;
}

/* 2^(2^-i) in Q2.30, i = 1..16: 2^f is the product over the set bits of f. */
static const uint32_t exp2_bits[16] = {
    1518500250, 1276901417, 1170923762, 1121280436, 1097253708, 1085434106,
    1079572136, 1076653033, 1075196443, 1074468888, 1074105294, 1073923544,
    1073832680, 1073787251, 1073764537, 1073753181,
};

fx16 fx16_exp2(fx16 x)
{
    int32_t ip = x >> 16;
    uint32_t f = (uint32_t)x & 0xFFFF;
    if (ip >= 15)
        return FX16_MAX;
    if (ip < -17)
        return 0;
    uint64_t m = (uint64_t)1 << 30; /* Q2.30 */
    for (int i = 0; i < 16; i++)
        if (f & (0x8000u >> i))
            m = (m * exp2_bits[i] + ((uint64_t)1 << 29)) >> 30;
    /* m in [1, 2) Q2.30 -> Q16.16 * 2^ip */
    int sh = 14 - ip;
    uint64_t r = sh > 0 ? (m + ((uint64_t)1 << (sh - 1))) >> sh : m << -sh;
    return r > (uint64_t)FX16_MAX ? FX16_MAX : (fx16)r;
}
