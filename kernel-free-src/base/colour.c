/* SPDX-License-Identifier: MIT */
/* fixel — colour models (see fixel/colour.h for the contracts). */
#include "fixel/colour.h"
#include "fx_internal.h"
#include "fixel/error.h"

#define DEG60 ((int64_t)60 << 16)
#define DEG360 ((int64_t)360 << 16)

static int64_t div_round(int64_t n, int64_t d) /* d > 0, to nearest, ties up */
{
    int64_t q = n / d, r = n % d;
    if (r < 0) {
        q--;
        r += d;
    }
    return q + (2 * r >= d);
}

static uint8_t clamp255(int64_t v) { return (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v); }
static fx16 clamp01(fx16 v) { return v < 0 ? 0 : v > FX16_ONE ? FX16_ONE : v; }

static fx_color rgb(int64_t r, int64_t g, int64_t b)
{
    return 0xFF000000u | (uint32_t)clamp255(r) << 16 | (uint32_t)clamp255(g) << 8 | clamp255(b);
}

fx_cmy fx_rgb_to_cmy(fx_color c)
{
    fx_cmy o = {(uint8_t)(255 - ((c >> 16) & 0xFF)), (uint8_t)(255 - ((c >> 8) & 0xFF)), (uint8_t)(255 - (c & 0xFF))};
    return o;
}

fx_color fx_cmy_to_rgb(fx_cmy c) { return rgb(255 - c.c, 255 - c.m, 255 - c.y); }

/* Hue of (r, g, b) with max mx and spread d > 0, fx16 degrees in [0, 360). */
static fx16 hue(int32_t r, int32_t g, int32_t b, int32_t mx, int32_t d)
{
    int64_t h;
    if (mx == r)
        h = div_round(DEG60 * (g - b), d);
    else if (mx == g)
        h = 2 * DEG60 + div_round(DEG60 * (b - r), d);
    else
        h = 4 * DEG60 + div_round(DEG60 * (r - g), d);
    if (h < 0)
        h += DEG360;
    if (h >= DEG360)
        h -= DEG360;
    return (fx16)h;
}

/* Back from hue and the largest and smallest channel, both in channel
 * units times 2^16; channels rounded to nearest. */
static fx_color from_hue(fx16 h, int64_t mx, int64_t mn)
{
    int64_t hh = (int64_t)h % DEG360;
    if (hh < 0)
        hh += DEG360;
    int sector = (int)(hh / DEG60);
    int64_t f = hh - sector * DEG60;
    int64_t d = mx - mn;
    int64_t rise = mn + div_round(d * f, DEG60), fall = mx - div_round(d * f, DEG60);
    int64_t r, g, b;
    switch (sector) {
    case 0: r = mx, g = rise, b = mn; break;
    case 1: r = fall, g = mx, b = mn; break;
    case 2: r = mn, g = mx, b = rise; break;
    case 3: r = mn, g = fall, b = mx; break;
    case 4: r = rise, g = mn, b = mx; break;
    default: r = mx, g = mn, b = fall; break;
    }
    const int64_t half = 1 << 15;
    return rgb((r + half) >> 16, (g + half) >> 16, (b + half) >> 16);
}

#define SPLIT(c)                                                                         \
    int32_t r = (int32_t)((c) >> 16) & 0xFF, g = (int32_t)((c) >> 8) & 0xFF, b = (int32_t)(c) & 0xFF; \
    int32_t mx = FX_MAX(r, FX_MAX(g, b)), mn = FX_MIN(r, FX_MIN(g, b)), d = mx - mn

fx_hsv fx_rgb_to_hsv(fx_color c)
{
    SPLIT(c);
    fx_hsv o;
    o.v = (fx16)div_round((int64_t)mx << 16, 255);
    o.s = mx ? (fx16)div_round((int64_t)d << 16, mx) : 0;
    o.h = d ? hue(r, g, b, mx, d) : 0;
    return o;
}

fx_color fx_hsv_to_rgb(fx_hsv c)
{
    int64_t v = clamp01(c.v), s = clamp01(c.s);
    int64_t mx = v * 255;                 /* channel units * 2^16 */
    int64_t mn = mx - div_round(mx * s, 1 << 16);
    return from_hue(c.h, mx, mn);
}

fx_hls fx_rgb_to_hls(fx_color c)
{
    SPLIT(c);
    fx_hls o;
    o.l = (fx16)div_round((int64_t)(mx + mn) << 15, 255);
    if (d == 0) {
        o.s = 0;
        o.h = 0;
        return o;
    }
    int32_t den = mx + mn <= 255 ? mx + mn : 510 - mx - mn;
    o.s = (fx16)div_round((int64_t)d << 16, den);
    o.h = hue(r, g, b, mx, d);
    return o;
}

fx_color fx_hls_to_rgb(fx_hls c)
{
    int64_t l = clamp01(c.l), s = clamp01(c.s);
    int64_t lc = l * 255; /* channel units * 2^16 */
    int64_t mx = l <= (1 << 15) ? lc + div_round(lc * s, 1 << 16) : lc + s * 255 - div_round(lc * s, 1 << 16);
    int64_t mn = 2 * lc - mx;
    return from_hue(c.h, mx, mn);
}

static const int32_t yiq_fwd[3][3] = {{19595, 38470, 7471}, {39060, -17957, -21103}, {13828, -34275, 20447}};
static const int32_t yiq_inv[3][3] = {{65536, 62663, 40727}, {65536, -17870, -42389}, {65536, -72334, 111453}};
static const int32_t xyz_fwd[3][3] = {{27027, 23436, 11829}, {13933, 46871, 4732}, {1265, 7812, 62292}};
static const int32_t xyz_inv[3][3] = {{212380, -100746, -32677}, {-63501, 122932, 2720}, {3651, -13371, 69271}};

/* sRGB code -> linear light, Q16 (tools/gen/gen_colour.py). */
static const uint16_t srgb_lin[256] = {
    0, 20, 40, 60, 80, 99, 119, 139, 159, 179, 199, 219, 241, 264, 288, 313,
    340, 367, 396, 427, 458, 491, 526, 562, 599, 637, 677, 718, 761, 805, 851, 898,
    947, 997, 1048, 1101, 1156, 1212, 1270, 1330, 1391, 1453, 1517, 1583, 1651, 1720, 1791, 1863,
    1937, 2013, 2090, 2170, 2250, 2333, 2418, 2504, 2592, 2681, 2773, 2866, 2961, 3058, 3157, 3258,
    3360, 3464, 3570, 3678, 3788, 3900, 4014, 4129, 4247, 4366, 4488, 4611, 4736, 4864, 4993, 5124,
    5257, 5392, 5530, 5669, 5810, 5953, 6099, 6246, 6395, 6547, 6701, 6856, 7014, 7174, 7336, 7500,
    7666, 7834, 8004, 8177, 8352, 8529, 8708, 8889, 9072, 9258, 9446, 9636, 9828, 10022, 10219, 10418,
    10619, 10822, 11028, 11236, 11446, 11658, 11873, 12090, 12309, 12531, 12754, 12981, 13209, 13440, 13673, 13909,
    14147, 14387, 14629, 14874, 15122, 15372, 15624, 15878, 16135, 16394, 16656, 16920, 17187, 17456, 17727, 18001,
    18278, 18556, 18838, 19121, 19408, 19696, 19988, 20281, 20578, 20876, 21178, 21481, 21788, 22096, 22408, 22722,
    23038, 23357, 23679, 24003, 24329, 24659, 24991, 25325, 25662, 26002, 26344, 26689, 27036, 27387, 27739, 28095,
    28453, 28813, 29177, 29543, 29911, 30283, 30657, 31033, 31413, 31795, 32180, 32567, 32957, 33350, 33746, 34144,
    34545, 34949, 35355, 35765, 36177, 36591, 37009, 37429, 37852, 38278, 38707, 39138, 39572, 40009, 40449, 40892,
    41337, 41786, 42237, 42691, 43147, 43607, 44069, 44534, 45003, 45474, 45947, 46424, 46904, 47386, 47871, 48360,
    48851, 49345, 49842, 50342, 50844, 51350, 51859, 52370, 52884, 53402, 53922, 54445, 54972, 55501, 56033, 56568,
    57106, 57647, 58191, 58738, 59288, 59841, 60397, 60956, 61518, 62083, 62651, 63222, 63796, 64373, 64953, 65535,
};

fx_yiq fx_rgb_to_yiq(fx_color c)
{
    int64_t v[3] = {(c >> 16) & 0xFF, (c >> 8) & 0xFF, c & 0xFF};
    fx16 o[3];
    for (int k = 0; k < 3; k++)
        o[k] = (fx16)div_round(yiq_fwd[k][0] * v[0] + yiq_fwd[k][1] * v[1] + yiq_fwd[k][2] * v[2], 255);
    fx_yiq y = {o[0], o[1], o[2]};
    return y;
}

fx_color fx_yiq_to_rgb(fx_yiq c)
{
    int64_t v[3] = {c.y, c.i, c.q}, o[3];
    for (int k = 0; k < 3; k++)
        o[k] = div_round((yiq_inv[k][0] * v[0] + yiq_inv[k][1] * v[1] + yiq_inv[k][2] * v[2]) * 255,
                         (int64_t)1 << 32);
    return rgb(o[0], o[1], o[2]);
}

fx16 fx_srgb_to_linear(uint8_t v) { return v == 255 ? FX16_ONE : srgb_lin[v]; }

uint8_t fx_linear_to_srgb(fx16 l)
{
    if (l <= 0)
        return 0;
    if (l >= FX16_ONE)
        return 255;
    int lo = 0, hi = 255; /* largest k with table[k] <= l */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (fx_srgb_to_linear((uint8_t)mid) <= l)
            lo = mid;
        else
            hi = mid - 1;
    }
    if (lo < 255 && (int64_t)fx_srgb_to_linear((uint8_t)(lo + 1)) - l < l - (int64_t)fx_srgb_to_linear((uint8_t)lo))
        lo++;
    return (uint8_t)lo;
}

fx_xyz fx_rgb_to_xyz(fx_color c)
{
    int64_t v[3] = {fx_srgb_to_linear((uint8_t)(c >> 16)), fx_srgb_to_linear((uint8_t)(c >> 8)),
                    fx_srgb_to_linear((uint8_t)c)};
    fx16 o[3];
    for (int k = 0; k < 3; k++)
        o[k] = (fx16)div_round(xyz_fwd[k][0] * v[0] + xyz_fwd[k][1] * v[1] + xyz_fwd[k][2] * v[2], 1 << 16);
    fx_xyz x = {o[0], o[1], o[2]};
    return x;
}

fx_color fx_xyz_to_rgb(fx_xyz c)
{
    int64_t v[3] = {c.x, c.y, c.z};
    uint8_t o[3];
    for (int k = 0; k < 3; k++) {
        int64_t l = div_round(xyz_inv[k][0] * v[0] + xyz_inv[k][1] * v[1] + xyz_inv[k][2] * v[2], 1 << 16);
        o[k] = fx_linear_to_srgb((fx16)(l < 0 ? 0 : l > FX16_ONE ? FX16_ONE : l));
    }
    return 0xFF000000u | (uint32_t)o[0] << 16 | (uint32_t)o[1] << 8 | o[2];
}

/* ---- colour from wavelength ---- */

fx_xyz fx_wavelength_to_xyz(fx16 nm)
{
    fx_xyz o = {0, 0, 0};
    int64_t off = (int64_t)nm - (int64_t)FX_CIE_FIRST * 65536; /* Q16 nm from 380 */
    int64_t span = (int64_t)(FX_CIE_N - 1) * FX_CIE_STEP * 65536;
    if (off < 0 || off > span)
        return o;
    int32_t i = (int32_t)(off / (FX_CIE_STEP * 65536));
    int64_t f = off - (int64_t)i * FX_CIE_STEP * 65536; /* [0, 5 nm) in Q16 */
    if (i == FX_CIE_N - 1) {
        i--;
        f = FX_CIE_STEP * 65536;
    }
    int32_t v[3];
    for (int k = 0; k < 3; k++) {
        /* table * 2^16 / 10^6, interpolated: (t0 * (5 - f) + t1 * f) / 5 */
        int64_t a = fx_cie1931_cmf[i][k], b = fx_cie1931_cmf[i + 1][k];
        int64_t t = a * (FX_CIE_STEP * 65536 - f) + b * f; /* < 2^21 * 2^19 */
        /* t / (5 * 2^16) is the table value: times 2^16 / 10^6 for Q16 */
        v[k] = (int32_t)div_round(t, (int64_t)FX_CIE_STEP * 1000000);
    }
    o.x = v[0];
    o.y = v[1];
    o.z = v[2];
    return o;
}

int fx_xyz_to_xy(fx_xyz c, fx16 *x, fx16 *y)
{
    int64_t s = (int64_t)c.x + c.y + c.z;
    if (s <= 0)
        return -FX_EDOM;
    *x = (fx16)div_round((int64_t)c.x * 65536, s);
    *y = (fx16)div_round((int64_t)c.y * 65536, s);
    return 0;
}

fx_color fx_xyz_to_rgb_display(fx_xyz c)
{
    int64_t v[3] = {c.x, c.y, c.z}, l[3];
    for (int k = 0; k < 3; k++)
        l[k] = div_round(xyz_inv[k][0] * v[0] + xyz_inv[k][1] * v[1] + xyz_inv[k][2] * v[2], 1 << 16);
    int64_t mn = l[0] < l[1] ? l[0] : l[1];
    mn = mn < l[2] ? mn : l[2];
    if (mn < 0)
        for (int k = 0; k < 3; k++)
            l[k] -= mn;
    int64_t mx = l[0] > l[1] ? l[0] : l[1];
    mx = mx > l[2] ? mx : l[2];
    if (mx <= 0)
        return 0xFF000000u;
    uint8_t o[3];
    for (int k = 0; k < 3; k++)
        o[k] = fx_linear_to_srgb((fx16)div_round(l[k] * 65536, mx));
    return 0xFF000000u | (uint32_t)o[0] << 16 | (uint32_t)o[1] << 8 | o[2];
}

fx_color fx_wavelength_to_rgb(fx16 nm) { return fx_xyz_to_rgb_display(fx_wavelength_to_xyz(nm)); }
