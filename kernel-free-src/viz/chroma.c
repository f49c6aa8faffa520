/* SPDX-License-Identifier: MIT */
/* fixel — the CIE 1931 chromaticity diagram (contract in viz.h). */
#include "fixel/viz.h"
#include "fixel/colour.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/font.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

int32_t fx_spectral_locus(fx16 *xy)
{
    for (int32_t i = 0; i < FX_CIE_N; i++) {
        fx_xyz c = {0, 0, 0};
        /* straight from the table: the sum's scale cancels in x and y */
        c.x = fx_cie1931_cmf[i][0];
        c.y = fx_cie1931_cmf[i][1];
        c.z = fx_cie1931_cmf[i][2];
        if (fx_xyz_to_xy(c, &xy[2 * i], &xy[2 * i + 1]) < 0)
            xy[2 * i] = xy[2 * i + 1] = 0;
    }
    return FX_CIE_N;
}

typedef struct chroma_map {
    fx_rect d;
    int64_t w1, h1; /* width - 1, height - 1 (>= 1) */
} chroma_map;

#define X_SPAN 52429 /* 0.8 in Q16 */
#define Y_SPAN 58982 /* 0.9 in Q16 */

static int64_t rdiv(int64_t n, int64_t d)
{
    return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

/* chromaticity (Q16) -> 24.8 pixel position */
static int64_t map_x(const chroma_map *m, int64_t x) { return (int64_t)m->d.x0 * 256 + rdiv(x * m->w1 * 256, X_SPAN); }
static int64_t map_y(const chroma_map *m, int64_t y)
{
    return ((int64_t)m->d.y0 + m->h1) * 256 - rdiv(y * m->h1 * 256, Y_SPAN);
}

static void shade(const void *user, int32_t y, int32_t x, int32_t n, fx_color *out)
{
    const chroma_map *m = user;
    int64_t cy = rdiv(((int64_t)m->d.y0 + m->h1 - y) * Y_SPAN, m->h1);
    for (int32_t k = 0; k < n; k++) {
        int64_t cx = rdiv(((int64_t)x + k - m->d.x0) * X_SPAN, m->w1);
        if (cy <= 0) {
            out[k] = 0xFF000000u;
            continue;
        }
        /* Y = 1: X = x / y, Z = (1 - x - y) / y, all Q16 */
        fx_xyz c;
        c.x = fx_sat32(rdiv(cx * 65536, cy));
        c.y = FX16_ONE;
        c.z = fx_sat32(rdiv((65536 - cx - cy) * 65536, cy));
        out[k] = fx_xyz_to_rgb_display(c);
    }
}

static int32_t px8(int64_t v) { return fx_sat32((v + 128) >> 8); }

int fx_chromaticity_diagram(const fx_ctx *c, fx_rect dest, int flags)
{
    if (!c || fx_rect_empty(dest))
        return -FX_EINVAL;
    chroma_map m = {dest, (int64_t)dest.x1 - dest.x0 - 1, (int64_t)dest.y1 - dest.y0 - 1};
    if (m.w1 >= (1 << 20) || m.h1 >= (1 << 20))
        return -FX_E2BIG;
    if (m.w1 < 1)
        m.w1 = 1;
    if (m.h1 < 1)
        m.h1 = 1;
    fx16 xy[2 * FX_CIE_N];
    fx_spectral_locus(xy);
    /* the diagram is off the clip: 24.8 positions would not fit fx8. The
     * wavelength labels stand up to ~17 px outside dest (13 px out plus
     * half the 8x16 font), so the margin keeps them when only they reach
     * into the clip (a band, or a clip beside the diagram). */
    const int64_t margin = 32;
    if ((int64_t)dest.x1 + margin < c->clip.x0 || (int64_t)dest.x0 - margin > c->clip.x1 ||
        (int64_t)dest.y1 + margin < c->clip.y0 || (int64_t)dest.y0 - margin > c->clip.y1)
        return 0;
    int32_t pts[2 * FX_CIE_N];
    int32_t pix[2 * FX_CIE_N];
    for (int i = 0; i < FX_CIE_N; i++) {
        int64_t x = map_x(&m, xy[2 * i]), y = map_y(&m, xy[2 * i + 1]);
        pts[2 * i] = fx_sat32(x);
        pts[2 * i + 1] = fx_sat32(y);
        pix[2 * i] = px8(x);
        pix[2 * i + 1] = px8(y);
    }
    if (flags & FX_CHROMA_FILL) {
        fx_fill_style st = {FX_FILL_SHADER, 0, 1, 1, 1, 0, 0, 0, 0, shade, &m};
        fx_ctx f = *c;
        f.fill_style = &st;
        fx_fill_edge edges[FX_CIE_N];
        int32_t count = FX_CIE_N;
        fx_fill_path(&f, pts, &count, 1, 8, FX_FILL_EVENODD, edges, FX_CIE_N);
    }
    if (flags & FX_CHROMA_LOCUS)
        for (int i = 0; i < FX_CIE_N; i++) {
            int j = (i + 1) % FX_CIE_N;
            fx_line(c, pix[2 * i], pix[2 * i + 1], pix[2 * j], pix[2 * j + 1]);
        }
    int64_t wx = map_x(&m, 20493), wy = map_y(&m, 21561); /* D65: 0.3127, 0.3290 */
    if (flags & FX_CHROMA_GAMUT) {
        static const fx16 prim[6] = {41943, 21627, 19661, 39322, 9830, 3932}; /* R, G, B of sRGB */
        for (int i = 0; i < 3; i++) {
            int j = (i + 1) % 3;
            fx_line(c, px8(map_x(&m, prim[2 * i])), px8(map_y(&m, prim[2 * i + 1])),
                    px8(map_x(&m, prim[2 * j])), px8(map_y(&m, prim[2 * j + 1])));
        }
        int32_t x = px8(wx), y = px8(wy);
        fx_line(c, x - 3, y, x + 3, y);
        fx_line(c, x, y - 3, x, y + 3);
    }
    if (flags & FX_CHROMA_TICKS)
        for (int nm = 460; nm <= 620; nm += 20) {
            int i = (nm - FX_CIE_FIRST) / FX_CIE_STEP;
            int64_t x = map_x(&m, xy[2 * i]), y = map_y(&m, xy[2 * i + 1]);
            int64_t dx = x - wx, dy = y - wy;
            uint32_t len = fx_hypot(fx_sat32(dx), fx_sat32(dy));
            if (len == 0)
                continue;
            /* 5 px outward, the label 8 px further on */
            int64_t ex = dx * 1280 / len, ey = dy * 1280 / len;
            fx_line(c, px8(x), px8(y), px8(x + ex), px8(y + ey));
            char buf[4] = {(char)('0' + nm / 100), (char)('0' + nm / 10 % 10), '0', 0};
            int64_t lx = x + ex * 13 / 5, ly = y + ey * 13 / 5;
            /* the 8 x 8 font: centre the three digits on the point */
            fx_text(c, px8(lx) - 12, px8(ly) - 4, buf);
        }
    return 0;
}
