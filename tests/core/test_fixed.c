/* SPDX-License-Identifier: MIT */
/* Fixed-point arithmetic against double-precision references. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/fixed.h"
#include "fx_test.h"

FX_TEST(fx16_conversions_name_their_rounding)
{
    FX_CHECK_EQ(fx16_from_int(3), 3 * 65536);
    FX_CHECK_EQ(fx16_from_int(-32768), INT32_MIN);
    FX_CHECK_EQ(fx16_from_int(40000), INT32_MAX); /* saturates */
    FX_CHECK_EQ(fx16_floor(-1), -1);
    FX_CHECK_EQ(fx16_ceil(-65535), 0);
    FX_CHECK_EQ(fx16_ceil(65537), 2);
    FX_CHECK_EQ(fx16_round(FX16_HALF), 1);
    FX_CHECK_EQ(fx16_round(-FX16_HALF), 0); /* ties toward +inf */
    FX_CHECK_EQ(fx16_round(INT32_MAX), 32768);
    uint32_t s = 1;
    for (int i = 0; i < 200000; i++) {
        fx16 a = (fx16)fx_test_rand(&s);
        double v = a / 65536.0;
        FX_CHECK_EQ(fx16_floor(a), (long long)floor(v));
        FX_CHECK_EQ(fx16_ceil(a), (long long)ceil(v));
        FX_CHECK_EQ(fx16_round(a), (long long)floor(v + 0.5));
    }
}

FX_TEST(fx16_mul_and_div_are_rounded_to_nearest_and_saturate)
{
    uint32_t s = 7;
    for (int i = 0; i < 500000; i++) {
        fx16 a = (fx16)fx_test_rand(&s), b = (fx16)fx_test_rand(&s);
        if (i & 1) { /* also exercise small magnitudes */
            a >>= fx_test_rand(&s) % 24;
            b >>= fx_test_rand(&s) % 24;
        }
        double exact = (double)a * b / 65536.0;
        fx16 m = fx16_mul(a, b);
        if (exact >= INT32_MAX)
            FX_CHECK_EQ(m, INT32_MAX);
        else if (exact < INT32_MIN)
            FX_CHECK_EQ(m, INT32_MIN);
        else
            FX_CHECK_MSG(fabs(m - exact) <= 0.5, "mul %d %d -> %d, exact %f", a, b, m, exact);
        if (b == 0)
            continue;
        double q = (double)a * 65536.0 / b;
        fx16 d = fx16_div(a, b);
        if (q >= INT32_MAX)
            FX_CHECK_EQ(d, INT32_MAX);
        else if (q <= INT32_MIN)
            FX_CHECK_EQ(d, INT32_MIN);
        else
            FX_CHECK_MSG(fabs(d - q) <= 0.5, "div %d %d -> %d, exact %f", a, b, d, q);
    }
    FX_CHECK_EQ(fx16_div(FX16_ONE, 0), INT32_MAX);
    FX_CHECK_EQ(fx16_div(-FX16_ONE, 0), INT32_MIN);
    FX_CHECK_EQ(fx16_div(0, 0), 0);
    FX_CHECK_EQ(fx16_from_ratio(1, 3), 21845);
    FX_CHECK_EQ(fx16_from_ratio(-1, 2), -32768);
    FX_CHECK_EQ(fx16_from_ratio(-11, 2), -11 * 32768); /* -5.5 translation of the course */
    FX_CHECK_EQ(fx16_from_ratio(15, 4), 245760);       /* 3.75 */
}

FX_TEST(isqrt_is_floor_of_the_square_root)
{
    for (uint32_t n = 0; n < (1u << 22); n++) {
        uint32_t r = fx_isqrt32(n);
        if (!((uint64_t)r * r <= n && (uint64_t)(r + 1) * (r + 1) > n)) {
            FX_CHECK_MSG(0, "isqrt32(%u) = %u", n, r);
            break;
        }
    }
    uint32_t s = 3;
    for (int i = 0; i < 300000; i++) {
        uint32_t n = fx_test_rand(&s);
        uint32_t r = fx_isqrt32(n);
        FX_CHECK((uint64_t)r * r <= n && (uint64_t)(r + 1) * (r + 1) > n);
        uint64_t m = ((uint64_t)fx_test_rand(&s) << 32 | fx_test_rand(&s)) >> (fx_test_rand(&s) % 64);
        uint64_t q = fx_isqrt64(m);
        FX_CHECK_MSG(q * q <= m && (q + 1) * (q + 1) > m, "isqrt64(%llu) = %llu",
                     (unsigned long long)m, (unsigned long long)q);
    }
    FX_CHECK_EQ(fx_isqrt32(UINT32_MAX), 65535);
    FX_CHECK_EQ(fx_isqrt64(UINT64_MAX), 4294967295u);
    FX_CHECK_EQ(fx16_sqrt(4 * FX16_ONE), 2 * FX16_ONE);
    FX_CHECK_EQ(fx16_sqrt(FX16_ONE / 4), FX16_ONE / 2);
    FX_CHECK_EQ(fx16_sqrt(-5), 0);
    FX_CHECK_EQ(fx16_sqrt(2 * FX16_ONE), 92681); /* floor(sqrt(2) * 65536) */
}

FX_TEST(hypot_rounds_to_nearest_for_every_int32_pair)
{
    uint32_t s = 11;
    for (int i = 0; i < 300000; i++) {
        int32_t dx = (int32_t)fx_test_rand(&s), dy = (int32_t)fx_test_rand(&s);
        if (i & 1)
            dx >>= 16, dy >>= 16;
        long double e = sqrtl((long double)dx * dx + (long double)dy * dy);
        uint32_t h = fx_hypot(dx, dy);
        FX_CHECK_MSG(fabsl(h - e) <= 0.5L, "hypot(%d,%d) = %u, exact %Lf", dx, dy, h, e);
    }
    FX_CHECK_EQ(fx_hypot(3, 4), 5);
    FX_CHECK_EQ(fx_hypot(INT32_MIN, INT32_MIN), 3037000500u);
}

FX_TEST(sin_cos_meet_their_stated_error)
{
    double worst30 = 0, worst16 = 0;
    for (uint64_t a = 0; a < (1ull << 32); a += 4093) {
        double ref = sin((double)a * (2 * M_PI / 4294967296.0));
        double e30 = fabs(fx_sin30((fx_angle)a) / 1073741824.0 - ref);
        double e16 = fabs(fx_sin((fx_angle)a) / 65536.0 - ref);
        if (e30 > worst30)
            worst30 = e30;
        if (e16 > worst16)
            worst16 = e16;
        double c = cos((double)a * (2 * M_PI / 4294967296.0));
        FX_CHECK(fabs(fx_cos30((fx_angle)a) / 1073741824.0 - c) <= 1.0 / (1 << 21));
    }
    FX_CHECK_MSG(worst30 <= 1.0 / (1 << 21), "sin30 worst error %g", worst30);
    FX_CHECK_MSG(worst16 <= 1.0 / 65536, "sin worst error %g", worst16);
    FX_CHECK_EQ(fx_sin(FX_ANGLE_90), FX16_ONE);
    FX_CHECK_EQ(fx_sin(FX_ANGLE_270), -FX16_ONE);
    FX_CHECK_EQ(fx_sin(FX_ANGLE_180), 0);
    FX_CHECK_EQ(fx_cos(0), FX16_ONE);
    FX_CHECK_EQ(fx_cos(FX_ANGLE_90), 0);
    FX_CHECK_EQ(fx_cos30(FX_ANGLE_180), -(1 << 30));
}

FX_TEST(atan2_within_2_pow_minus_24_turn)
{
    uint32_t s = 5;
    double worst = 0;
    for (int i = 0; i < 200000; i++) {
        int32_t y = (int32_t)fx_test_rand(&s), x = (int32_t)fx_test_rand(&s);
        if (i % 3 == 1)
            y >>= 20, x >>= 20;
        if (i % 3 == 2)
            y >>= 28, x >>= 28;
        if (!x && !y)
            continue;
        double ref = atan2((double)y, (double)x) / (2 * M_PI) * 4294967296.0;
        if (ref < 0)
            ref += 4294967296.0;
        double d = fabs((double)fx_atan2(y, x) - ref);
        if (d > 2147483648.0)
            d = 4294967296.0 - d;
        if (d > worst)
            worst = d;
    }
    FX_CHECK_MSG(worst <= 256, "atan2 worst error %g units of 2^-32 turn", worst);
    FX_CHECK_EQ(fx_atan2(0, 0), 0);
    FX_CHECK(fx_atan2(1, 0) - FX_ANGLE_90 + 64u <= 128u);
    FX_CHECK(fx_atan2(0, -1) - FX_ANGLE_180 + 64u <= 128u);
    FX_CHECK(fx_atan2(-5, 0) - FX_ANGLE_270 + 64u <= 128u);
}

FX_TEST(angles_from_degrees)
{
    FX_CHECK_EQ_HEX(fx_angle_from_deg(90), FX_ANGLE_90);
    FX_CHECK_EQ_HEX(fx_angle_from_deg(-90), FX_ANGLE_270);
    FX_CHECK_EQ_HEX(fx_angle_from_deg(720 + 45), FX_ANGLE_45);
    FX_CHECK_EQ_HEX(fx_angle_from_deg(INT32_MIN), fx_angle_from_deg(INT32_MIN % 360 + 360));
    FX_CHECK_EQ_HEX(fx_angle_from_deg16(fx16_from_int(180)), FX_ANGLE_180);
    FX_CHECK_EQ(fx_angle_to_deg16(FX_ANGLE_270), fx16_from_int(270));
    FX_CHECK_EQ(fx_angle_to_deg16(fx_angle_from_deg(60)), fx16_from_int(60));
}

#ifdef __SIZEOF_INT128__
FX_TEST(wide_multiply_matches_int128)
{
    uint32_t s = 9;
    for (int i = 0; i < 300000; i++) {
        int64_t a = (int64_t)((uint64_t)fx_test_rand(&s) << 32 | fx_test_rand(&s));
        int64_t b = (int64_t)((uint64_t)fx_test_rand(&s) << 32 | fx_test_rand(&s));
        if (i & 1)
            a >>= fx_test_rand(&s) % 63, b >>= fx_test_rand(&s) % 63;
        __int128 p = (__int128)a * b;
        int64_t hi;
        uint64_t lo;
        fx_smul64_wide(a, b, &hi, &lo);
        FX_CHECK(hi == (int64_t)(p >> 64) && lo == (uint64_t)p);
        uint64_t uh, ul;
        fx_umul64_wide((uint64_t)a, (uint64_t)b, &uh, &ul);
        unsigned __int128 up = (unsigned __int128)(uint64_t)a * (uint64_t)b;
        FX_CHECK(uh == (uint64_t)(up >> 64) && ul == (uint64_t)up);
        unsigned sh = 1 + fx_test_rand(&s) % 63;
        __int128 r = (p + ((__int128)1 << (sh - 1))) >> sh;
        int64_t want = r > INT64_MAX ? INT64_MAX : r < INT64_MIN ? INT64_MIN : (int64_t)r;
        FX_CHECK_MSG(fx_mul64_shift(a, b, sh) == want, "mul64_shift(%lld, %lld, %u)", (long long)a,
                     (long long)b, sh);
    }
}
#endif

FX_TEST(fx56_products)
{
    fx56 half = FX56_ONE / 2;
    FX_CHECK_EQ(fx56_mul(half, half), FX56_ONE / 4);
    FX_CHECK_EQ(fx56_mul(-half, 3 * FX56_ONE), -3 * half);
    FX_CHECK_EQ(fx56_mul(100 * FX56_ONE, 100 * FX56_ONE), INT64_MAX);
    FX_CHECK_EQ(fx56_mul(-100 * FX56_ONE, 100 * FX56_ONE), INT64_MIN);
    FX_CHECK_EQ(fx56_from_fx16(-FX16_ONE), -FX56_ONE);
}

static int parse16(const char *s, fx16 *v) { return fx16_parse(s, (int)strlen(s), v); }
static int parse56(const char *s, fx56 *v) { return fx56_parse(s, (int)strlen(s), v); }

FX_TEST(decimal_parsing_is_exact)
{
    fx16 v;
    fx56 w;
    FX_CHECK_EQ(parse16("3", &v), 1);
    FX_CHECK_EQ(v, 3 * 65536);
    FX_CHECK_EQ(parse16("-5.5", &v), 4);
    FX_CHECK_EQ(v, -360448);
    FX_CHECK_EQ(parse16("+.5", &v), 3);
    FX_CHECK_EQ(v, 32768);
    FX_CHECK_EQ(parse16("0.261", &v), 5);
    FX_CHECK_EQ(v, 17105); /* 0.261 * 65536 = 17104.9 */
    FX_CHECK_EQ(parse16("32767.99999", &v), 11);
    FX_CHECK_EQ(parse16("32768", &v), -FX_ERANGE);
    FX_CHECK_EQ(parse16("-32768", &v), 6);
    FX_CHECK_EQ(v, INT32_MIN);
    FX_CHECK_EQ(parse16("", &v), -FX_EINVAL);
    FX_CHECK_EQ(parse16("-", &v), -FX_EINVAL);
    FX_CHECK_EQ(parse16("x1", &v), -FX_EINVAL);
    FX_CHECK_EQ(parse16("1e3", &v), 1); /* stops at 'e': callers reject the rest */
    FX_CHECK_EQ(parse56("0.5", &w), 3);
    FX_CHECK_EQ(w, (fx56)1 << 55);
    FX_CHECK_EQ(parse56("128", &w), -FX_ERANGE);
    FX_CHECK_EQ(parse56("-128", &w), 4);
    FX_CHECK_EQ(w, INT64_MIN);
#ifdef __SIZEOF_INT128__
    /* -0.743643887037151 * 2^56, rounded, by exact integer arithmetic */
    unsigned __int128 num = (unsigned __int128)743643887037151ull << 56;
    unsigned __int128 den = 1000000000000000ull;
    int64_t want = -(int64_t)((num + den / 2) / den);
    FX_CHECK_EQ(parse56("-0.743643887037151", &w), 18);
    FX_CHECK_EQ(w, want);
    uint32_t s = 13;
    for (int i = 0; i < 20000; i++) {
        uint64_t frac = ((uint64_t)fx_test_rand(&s) << 32 | fx_test_rand(&s)) % 10000000000000000000ull;
        char buf[40];
        int n = snprintf(buf, sizeof buf, "1.%019llu", (unsigned long long)frac);
        unsigned __int128 f = ((unsigned __int128)frac << 56) + 5000000000000000000ull;
        int64_t exp = (int64_t)(f / 10000000000000000000ull) + FX56_ONE;
        FX_CHECK_EQ(parse56(buf, &w), n);
        FX_CHECK_MSG(w == exp, "%s -> %lld, want %lld", buf, (long long)w, (long long)exp);
    }
#endif
}

FX_TEST(strerror_covers_every_code)
{
    FX_CHECK(strcmp(fx_strerror(-FX_EINVAL), "invalid argument") == 0);
    FX_CHECK(strcmp(fx_strerror(FX_EACCES), "permission denied") == 0);
    FX_CHECK(strcmp(fx_strerror(-9999), "unknown error") == 0);
    FX_CHECK(strcmp(fx_strerror(-FX_ENOENT), "no such file or directory") == 0);
    FX_CHECK(strcmp(fx_strerror(-FX_ESPIPE), "not a regular file (a FIFO, socket or device)") == 0);
    static const int codes[] = {FX_ENOENT, FX_EIO,    FX_E2BIG,  FX_ENOMEM,    FX_EACCES,
                                FX_EBUSY,  FX_ENODEV, FX_ENOTDIR, FX_EISDIR,   FX_EINVAL,
                                FX_EFBIG,  FX_ENOSPC, FX_EDOM,   FX_ERANGE,    FX_EBADMSG,
                                FX_EOVERFLOW, FX_ENOTSUP, FX_ESPIPE};
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; i++) {
        FX_CHECK_MSG(strcmp(fx_strerror(-codes[i]), "unknown error") != 0, "code %d", codes[i]);
        for (size_t j = 0; j < i; j++) /* each message tells its code apart */
            FX_CHECK(strcmp(fx_strerror(codes[i]), fx_strerror(codes[j])) != 0);
    }
}
