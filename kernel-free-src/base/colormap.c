/* SPDX-License-Identifier: MIT */
/* fixel — the project's colour maps (see colormap.h for their definitions). */
#include "fixel/colormap.h"

#define RGB(r, g, b) (0xFF000000u | (uint32_t)(r) << 16 | (uint32_t)(g) << 8 | (uint32_t)(b))

/* 255 * clamp(u, 0, 1) for u in Q0.16, rounded to nearest. */
static uint32_t ramp(int64_t u)
{
    if (u <= 0)
        return 0;
    if (u >= 65536)
        return 255;
    return (uint32_t)((u * 255 + 32768) >> 16);
}

static const uint32_t viridis_pts[9] = {
    0x440154, 0x472C7A, 0x3B518B, 0x2C718E, 0x21908D, 0x27AD81, 0x5CC863, 0xAADC32, 0xFDE725,
};

/* Linear interpolation of one 8-bit channel, f in Q0.13 (one segment of the
 * viridis map is 1/8 = 8192 units of t). */
static uint32_t lerp8(uint32_t a, uint32_t b, uint32_t f)
{
    int32_t d = (int32_t)b - (int32_t)a;
    return (uint32_t)((int32_t)a + ((d * (int32_t)f + (d >= 0 ? 4096 : -4096)) / 8192));
}

static fx_color viridis(uint32_t t)
{
    if (t >= 65536)
        return 0xFF000000u | viridis_pts[8];
    uint32_t seg = t >> 13, f = t & 8191;
    uint32_t a = viridis_pts[seg], b = viridis_pts[seg + 1];
    return RGB(lerp8(a >> 16 & 255, b >> 16 & 255, f), lerp8(a >> 8 & 255, b >> 8 & 255, f),
               lerp8(a & 255, b & 255, f));
}

static fx_color hsv(uint32_t t)
{
    uint32_t h6 = (t & 65535) * 6; /* sextant in the top bits, position below */
    uint32_t sec = h6 >> 16;
    uint32_t up = ramp(h6 & 65535), down = 255 - up;
    switch (sec) {
    case 0: return RGB(255, up, 0);
    case 1: return RGB(down, 255, 0);
    case 2: return RGB(0, 255, up);
    case 3: return RGB(0, down, 255);
    case 4: return RGB(up, 0, 255);
    default: return RGB(255, 0, down);
    }
}

fx_color fx_cmap_color(fx_cmap m, uint32_t t)
{
    switch (m) {
    case FX_CMAP_HOT: {
        int64_t u = (int64_t)(t > 65536 ? 65536 : t) * 3;
        return RGB(ramp(u), ramp(u - 65536), ramp(u - 131072));
    }
    case FX_CMAP_VIRIDIS:
        return viridis(t);
    case FX_CMAP_HSV:
        return hsv(t);
    default: {
        uint32_t v = ramp(t);
        return RGB(v, v, v);
    }
    }
}

void fx_cmap_table(fx_cmap m, fx_color *out, uint32_t n)
{
    if (n == 0)
        return;
    uint32_t den = fx_cmap_cyclic(m) ? n : n - 1;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t t = den ? (uint32_t)(((uint64_t)i * 65536 + den / 2) / den) : 0;
        out[i] = fx_cmap_color(m, t);
    }
}

static const char *const names[FX_CMAP_COUNT] = {"grey", "hot", "viridis", "hsv"};

static int same_word(const char *a, const char *b)
{
    for (;; a++, b++) {
        char x = *a, y = *b;
        if (x >= 'A' && x <= 'Z')
            x = (char)(x - 'A' + 'a');
        if (x != y)
            return 0;
        if (!x)
            return 1;
    }
}

fx_cmap fx_cmap_from_name(const char *name)
{
    if (same_word(name, "gray"))
        return FX_CMAP_GREY;
    for (int i = 0; i < FX_CMAP_COUNT; i++)
        if (same_word(name, names[i]))
            return (fx_cmap)i;
    return FX_CMAP_COUNT;
}

const char *fx_cmap_name(fx_cmap m)
{
    return (unsigned)m < FX_CMAP_COUNT ? names[m] : "?";
}

int fx_cmap_cyclic(fx_cmap m) { return m == FX_CMAP_HSV; }
