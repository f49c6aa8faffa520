/* SPDX-License-Identifier: MIT */
/* Colour models: exhaustive RGB round trips (every 24-bit colour in the
 * plain build, a stride under the sanitizers), worked values, and the
 * forward conversions against double-precision formulas. */
#include <math.h>

#include "fixel/colour.h"
#include "fx_test.h"

#if defined(__SANITIZE_ADDRESS__)
#define STEP 7
#else
#define STEP 1
#endif

static int round_trips(fx_color (*trip)(fx_color))
{
    int bad = 0;
    for (uint32_t r = 0; r < 256; r += STEP)
        for (uint32_t g = 0; g < 256; g += STEP)
            for (uint32_t b = 0; b < 256; b++) {
                fx_color c = 0xFF000000u | r << 16 | g << 8 | b;
                bad += trip(c) != c;
            }
    return bad;
}

static fx_color trip_hsv(fx_color c) { return fx_hsv_to_rgb(fx_rgb_to_hsv(c)); }
static fx_color trip_hls(fx_color c) { return fx_hls_to_rgb(fx_rgb_to_hls(c)); }
static fx_color trip_yiq(fx_color c) { return fx_yiq_to_rgb(fx_rgb_to_yiq(c)); }
static fx_color trip_xyz(fx_color c) { return fx_xyz_to_rgb(fx_rgb_to_xyz(c)); }
static fx_color trip_cmy(fx_color c) { return fx_cmy_to_rgb(fx_rgb_to_cmy(c)); }

FX_TEST(colour_round_trips_every_rgb)
{
    FX_CHECK_EQ(round_trips(trip_cmy), 0);
    FX_CHECK_EQ(round_trips(trip_hsv), 0);
    FX_CHECK_EQ(round_trips(trip_hls), 0);
    FX_CHECK_EQ(round_trips(trip_yiq), 0);
    FX_CHECK_EQ(round_trips(trip_xyz), 0);
}

FX_TEST(colour_worked_values)
{
    fx_hsv h = fx_rgb_to_hsv(0xFFFF0000u);
    FX_CHECK_EQ(h.h, 0);
    FX_CHECK_EQ(h.s, FX16_ONE);
    FX_CHECK_EQ(h.v, FX16_ONE);
    h = fx_rgb_to_hsv(0xFF00FF00u);
    FX_CHECK_EQ(h.h, 120 << 16);
    h = fx_rgb_to_hsv(0xFF0000FFu);
    FX_CHECK_EQ(h.h, 240 << 16);
    h = fx_rgb_to_hsv(0xFFFF00FFu); /* magenta */
    FX_CHECK_EQ(h.h, 300 << 16);
    h = fx_rgb_to_hsv(0xFF808080u);
    FX_CHECK_EQ(h.s, 0);
    FX_CHECK_EQ(fx_hsv_to_rgb((fx_hsv){60 << 16, FX16_ONE, FX16_ONE}), 0xFFFFFF00u);
    FX_CHECK_EQ(fx_hsv_to_rgb((fx_hsv){(360 + 180) << 16, FX16_ONE, FX16_ONE}), 0xFF00FFFFu); /* hue wraps */
    FX_CHECK_EQ(fx_hsv_to_rgb((fx_hsv){-(120 << 16), 2 * FX16_ONE, FX16_ONE}), 0xFF0000FFu); /* clamps */
    fx_hls l = fx_rgb_to_hls(0xFFFF0000u);
    FX_CHECK_EQ(l.l, FX16_ONE / 2);
    FX_CHECK_EQ(l.s, FX16_ONE);
    FX_CHECK_EQ(fx_hls_to_rgb((fx_hls){0, FX16_ONE, 0}), 0xFFFFFFFFu);
    fx_cmy m = fx_rgb_to_cmy(0xFF00FF80u);
    FX_CHECK_EQ(m.c, 255);
    FX_CHECK_EQ(m.m, 0);
    FX_CHECK_EQ(m.y, 127);
    fx_yiq y = fx_rgb_to_yiq(0xFFFFFFFFu);
    FX_CHECK_EQ(y.y, FX16_ONE);
    FX_CHECK_EQ(y.i, 0);
    FX_CHECK_EQ(y.q, 0);
    fx_xyz x = fx_rgb_to_xyz(0xFFFFFFFFu);
    FX_CHECK_EQ(x.x, FX_XYZ_WHITE_X);
    FX_CHECK_EQ(x.y, FX_XYZ_WHITE_Y);
    FX_CHECK_EQ(x.z, FX_XYZ_WHITE_Z);
    x = fx_rgb_to_xyz(0xFF000000u);
    FX_CHECK(x.x == 0 && x.y == 0 && x.z == 0);
    FX_CHECK_EQ(fx_linear_to_srgb(fx_srgb_to_linear(128)), 128);
    FX_CHECK_EQ(fx_linear_to_srgb(-5), 0);
    FX_CHECK_EQ(fx_linear_to_srgb(1 << 20), 255);
}

FX_TEST(colour_forward_matches_formulas)
{
    uint32_t seed = 8;
    int bad = 0;
    for (int i = 0; i < 20000; i++) {
        fx_color c = fx_test_rand(&seed) | 0xFF000000u;
        double r = ((c >> 16) & 0xFF) / 255.0, g = ((c >> 8) & 0xFF) / 255.0, b = (c & 0xFF) / 255.0;
        double mx = fmax(r, fmax(g, b)), mn = fmin(r, fmin(g, b)), d = mx - mn, hh = 0;
        if (d > 0) {
            if (mx == r)
                hh = fmod(60 * (g - b) / d + 360, 360);
            else if (mx == g)
                hh = 60 * (2 + (b - r) / d);
            else
                hh = 60 * (4 + (r - g) / d);
        }
        fx_hsv h = fx_rgb_to_hsv(c);
        bad += fabs(h.h / 65536.0 - hh) > 1.0 / 65536 && fabs(h.h / 65536.0 - hh) < 359;
        bad += fabs(h.v / 65536.0 - mx) > 1.0 / 65536;
        bad += fabs(h.s / 65536.0 - (mx > 0 ? d / mx : 0)) > 1.0 / 65536;
        fx_hls l = fx_rgb_to_hls(c);
        double L = (mx + mn) / 2, S = d == 0 ? 0 : L <= 0.5 ? d / (mx + mn) : d / (2 - mx - mn);
        bad += fabs(l.l / 65536.0 - L) > 1.0 / 65536 || fabs(l.s / 65536.0 - S) > 1.0 / 65536;
        fx_yiq y = fx_rgb_to_yiq(c);
        bad += fabs(y.y / 65536.0 - (0.299 * r + 0.587 * g + 0.114 * b)) > 1e-4;
        bad += fabs(y.i / 65536.0 - (0.596 * r - 0.274 * g - 0.322 * b)) > 1e-4;
        bad += fabs(y.q / 65536.0 - (0.211 * r - 0.523 * g + 0.312 * b)) > 1e-4;
        double lr = r <= 0.04045 ? r / 12.92 : pow((r + 0.055) / 1.055, 2.4);
        double lg = g <= 0.04045 ? g / 12.92 : pow((g + 0.055) / 1.055, 2.4);
        double lb = b <= 0.04045 ? b / 12.92 : pow((b + 0.055) / 1.055, 2.4);
        fx_xyz x = fx_rgb_to_xyz(c);
        bad += fabs(x.y / 65536.0 - (0.2126 * lr + 0.7152 * lg + 0.0722 * lb)) > 1e-4;
        bad += fabs(x.x / 65536.0 - (0.4124 * lr + 0.3576 * lg + 0.1805 * lb)) > 1e-4;
    }
    FX_CHECK_EQ(bad, 0);
}
