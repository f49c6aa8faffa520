/* SPDX-License-Identifier: MIT */
/* fixel — fixed-point arithmetic.
 *
 * One scalar type per precision, chosen once for the whole library:
 *   fx16      Q16.16 in an int32_t: geometry, transforms, 3D, parameters.
 *   fx8       24.8 in an int32_t: sub-pixel positions inside rasterizers.
 *   fx56      Q8.56 in an int64_t: deep-zoom fractal coordinates.
 *   fx_angle  binary angle, uint32_t, one full turn = 2^32 (wraps for free).
 *
 * Rounding is named by every function. Products and quotients saturate to the
 * type's range instead of wrapping, so an out-of-range result is wrong by a
 * bounded amount rather than by a sign flip. Right shifts of negative values
 * are arithmetic (true of every compiler fixel supports: gcc and clang).
 */
#ifndef FIXEL_FIXED_H
#define FIXEL_FIXED_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t fx16;
typedef int32_t fx8;
typedef int64_t fx56;
typedef uint32_t fx_angle;

#define FX16_SHIFT 16
#define FX16_ONE   ((fx16)0x10000)
#define FX16_HALF  ((fx16)0x8000)
#define FX16_MAX   ((fx16)INT32_MAX)
#define FX16_MIN   ((fx16)INT32_MIN)
#define FX8_ONE    256
#define FX56_SHIFT 56
#define FX56_ONE   ((fx56)1 << 56)

#define FX_ANGLE_TURN_BITS 32
#define FX_ANGLE_0   ((fx_angle)0)
#define FX_ANGLE_45  ((fx_angle)0x20000000u)
#define FX_ANGLE_90  ((fx_angle)0x40000000u)
#define FX_ANGLE_180 ((fx_angle)0x80000000u)
#define FX_ANGLE_270 ((fx_angle)0xC0000000u)

/* Clamp a 64-bit intermediate into int32_t. */
static inline int32_t fx_sat32(int64_t v)
{
    return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : (int32_t)v;
}

/* int -> Q16.16, saturating (|i| >= 32768 saturates). */
static inline fx16 fx16_from_int(int32_t i) { return fx_sat32((int64_t)i * FX16_ONE); }

/* Q16.16 -> int with the rounding in the name. round: half-way goes up (+inf). */
static inline int32_t fx16_floor(fx16 a) { return a >> 16; }
static inline int32_t fx16_ceil(fx16 a) { return (int32_t)(((int64_t)a + 0xFFFF) >> 16); }
static inline int32_t fx16_round(fx16 a) { return (int32_t)(((int64_t)a + 0x8000) >> 16); }

/* Rational p/q -> Q16.16, rounded to nearest (ties away from zero), saturating.
 * q == 0 saturates by the sign of p (0/0 gives 0). */
fx16 fx16_from_ratio(int32_t p, int32_t q);

/* a*b, rounded to nearest (ties toward +inf), saturating. */
static inline fx16 fx16_mul(fx16 a, fx16 b)
{
    return fx_sat32(((int64_t)a * b + 0x8000) >> 16);
}

/* a/b, rounded to nearest (ties away from zero), saturating; b == 0 gives
 * FX16_MAX or FX16_MIN by the sign of a (0 for a == 0). */
fx16 fx16_div(fx16 a, fx16 b);

/* Integer square roots, floor. */
uint32_t fx_isqrt32(uint32_t n);
uint32_t fx_isqrt64(uint64_t n);

/* sqrt of a Q16.16 value, floor, in Q16.16 (exact: floor(sqrt(a * 2^16))).
 * Negative input gives 0. */
fx16 fx16_sqrt(fx16 a);

/* sqrt(dx^2 + dy^2) rounded to nearest, exact for every int32 pair. */
uint32_t fx_hypot(int32_t dx, int32_t dy);

/* Binary angles from degrees, rounded to nearest unit (exact for multiples of
 * 45 degrees); any int32 input is reduced modulo 360 first. */
fx_angle fx_angle_from_deg(int32_t deg);
fx_angle fx_angle_from_deg16(fx16 deg);
/* Degrees in Q16.16, in [0, 360), rounded to nearest. */
fx16 fx_angle_to_deg16(fx_angle a);

/* Sine and cosine by a quarter-wave table with linear interpolation.
 * fx_sin30/fx_cos30: Q2.30 (1.0 = 2^30), |error| <= 2^-21.
 * fx_sin/fx_cos:     Q16.16, |error| <= 1 unit (2^-16).
 * Exact (0, +-1) at multiples of 90 degrees. */
int32_t fx_sin30(fx_angle a);
int32_t fx_cos30(fx_angle a);
fx16 fx_sin(fx_angle a);
fx16 fx_cos(fx_angle a);

/* atan2(y, x) as a binary angle (counter-clockwise from +x, y up), by CORDIC
 * on 62-bit intermediates. |error| <= 2^-24 turn (about 2.1e-5 degrees).
 * atan2(0, 0) is 0. */
fx_angle fx_atan2(int32_t y, int32_t x);

/* Portable 64x64 -> 128 multiplication on 32-bit limbs (no __int128, so it
 * also runs on 32-bit ARM). */
void fx_umul64_wide(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo);
void fx_smul64_wide(int64_t a, int64_t b, int64_t *hi, uint64_t *lo);

/* (a*b) >> shift for shift in 1..63, rounded to nearest (ties toward +inf),
 * saturating to int64_t. */
int64_t fx_mul64_shift(int64_t a, int64_t b, unsigned shift);

/* Q8.56 product, rounded to nearest, saturating. */
static inline fx56 fx56_mul(fx56 a, fx56 b) { return fx_mul64_shift(a, b, FX56_SHIFT); }
static inline fx56 fx56_from_int(int32_t i)
{
    return i >= 128 ? INT64_MAX : i < -128 ? INT64_MIN : (fx56)i * FX56_ONE;
}
static inline fx56 fx56_from_fx16(fx16 a) { return (fx56)a * ((fx56)1 << 40); }

/* ---- exponentials and pseudo-random numbers (caller-held state) ---- */
/* xorshift32 (a zero state is replaced by a fixed non-zero one). */
uint32_t fx_rand32(uint32_t *state);
/* A standard normal variate in Q16.16 (range +-6). */
fx16 fx_gauss16(uint32_t *state);
/* 2^x for x in Q16.16, result in Q16.16, rounded (x in [-16, 14]; outside,
 * saturates to 0 or FX16_MAX). Exact at integers. */
fx16 fx16_exp2(fx16 x);

/* Exact decimal parsing without floating point: "-0.743643887037151",
 * "3", "+.5", "1e-3" is not accepted. The value is rounded to nearest in the
 * target type. Returns the number of characters consumed (> 0), or a negative
 * error: -FX_EINVAL for no number, -FX_ERANGE when it does not fit. */
int fx16_parse(const char *s, int len, fx16 *out);
int fx56_parse(const char *s, int len, fx56 *out);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
