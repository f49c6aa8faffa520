/* SPDX-License-Identifier: MIT */
/* fixel — coverage masks blended through a context (mask.h has the rule).
 *
 * Every pixel goes through fx_coverage_blend: one rule, whatever the format,
 * so the exhaustive per-format test of that function covers the drawing too
 * (the drawing test then checks only placement, rotation and clipping). */
#include "fixel/mask.h"
#include "fixel/colour.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

static inline uint32_t div255(uint32_t x) { return (x + 128 + ((x + 128) >> 8)) >> 8; }

uint32_t fx_coverage_blend(fx_format f, uint32_t dst, fx_color c, uint32_t cov, unsigned flags)
{
    if (cov > 255)
        cov = 255;
    uint32_t a = div255((c >> 24) * cov);
    if (a == 0)
        return dst;
    if (!(flags & FX_MASK_GAMMA) || a == 255)
        return fx_blend_over(f, dst, (c & 0xFFFFFFu) | a << 24);
    fx_color d = fx_unpack(f, dst);
    uint32_t out = 0;
    for (int sh = 0; sh < 24; sh += 8) {
        uint32_t ls = (uint32_t)fx_srgb_to_linear((uint8_t)(c >> sh));
        uint32_t ld = (uint32_t)fx_srgb_to_linear((uint8_t)(d >> sh));
        /* <= 65536 * 255 < 2^25: no overflow; 255 is odd, so no ties. */
        uint32_t l = (ls * a + ld * (255 - a) + 127) / 255;
        out |= (uint32_t)fx_linear_to_srgb((fx16)l) << sh;
    }
    out |= (a + div255((d >> 24) * (255 - a))) << 24;
    return fx_pack(f, out);
}

int fx_mask_blend(const fx_ctx *c, int32_t x, int32_t y, const fx_mask *m, unsigned rot, unsigned flags)
{
    if (!c || !m || m->w < 0 || m->h < 0 || rot > 3 || (flags & ~FX_MASK_GAMMA))
        return -FX_EINVAL;
    if (m->w == 0 || m->h == 0)
        return 0;
    int64_t st = m->stride;
    if (!m->cov || (st < 0 ? -st : st) < m->w)
        return -FX_EINVAL;
    /* The rotated box [x, x+bw) x [y, y+bh), met with the clip in 64 bits so
     * that a box reaching past INT32_MAX is cut, not wrapped. */
    int64_t bw = (rot & 1) ? m->h : m->w, bh = (rot & 1) ? m->w : m->h;
    int64_t x0 = FX_MAX((int64_t)x, (int64_t)c->clip.x0), x1 = FX_MIN((int64_t)x + bw, (int64_t)c->clip.x1);
    int64_t y0 = FX_MAX((int64_t)y, (int64_t)c->clip.y0), y1 = FX_MIN((int64_t)y + bh, (int64_t)c->clip.y1);
    if (x0 >= x1 || y0 >= y1)
        return 0;
    fx_color col = c->blend == FX_BLEND_OVER ? c->color : (c->color | 0xFF000000u);
    fx_format f = c->surf.format;
    for (int64_t py = y0; py < y1; py++) {
        int64_t v = py - y;
        for (int64_t px = x0; px < x1; px++) {
            if (c->exterior && px >= c->exterior_rect.x0 && px < c->exterior_rect.x1 &&
                py >= c->exterior_rect.y0 && py < c->exterior_rect.y1)
                continue;
            int64_t u = px - x, mx, my;
            switch (rot) {
            case FX_ROT_0: mx = u, my = v; break;
            case FX_ROT_90: mx = v, my = m->h - 1 - u; break;
            case FX_ROT_180: mx = m->w - 1 - u, my = m->h - 1 - v; break;
            default: mx = m->w - 1 - v, my = u; break;
            }
            uint32_t cov = m->cov[my * st + mx];
            if (!cov)
                continue;
            uint32_t d = fx_surface_get_native(&c->surf, (int32_t)px, (int32_t)py);
            fx_surface_put_native(&c->surf, (int32_t)px, (int32_t)py, fx_coverage_blend(f, d, col, cov, flags));
        }
    }
    return 0;
}
