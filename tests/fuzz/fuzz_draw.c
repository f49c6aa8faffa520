/* SPDX-License-Identifier: MIT */
/* libFuzzer target: draw calls with hostile arguments. The bytes choose a
 * surface (any format, 1..64 pixels a side, top-down or bottom-up memory,
 * between guard pages) and then a sequence of primitives whose int32
 * arguments are often extreme (INT32_MIN/MAX, +-2^30, far off-screen).
 * Any write outside the pixels faults; UBSan aborts on any overflow. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/circle.h"
#include "fixel/clip.h"
#include "fixel/fill.h"
#include "fixel/font.h"
#include "fixel/fractal.h"
#include "fixel/koch.h"
#include "fixel/line.h"
#include "guard.h"

typedef struct rd {
    const uint8_t *p;
    size_t n;
} rd;

static uint32_t u8(rd *r)
{
    if (!r->n)
        return 0;
    r->n--;
    return *r->p++;
}

static uint32_t u32(rd *r)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
        v = v << 8 | u8(r);
    return v;
}

/* Mostly near the surface, often extreme, sometimes anything. */
static int32_t coord(rd *r)
{
    uint32_t k = u8(r);
    switch (k & 7) {
    case 0: return INT32_MIN;
    case 1: return INT32_MAX;
    case 2: return (int32_t)(u32(r) | 0x40000000u) * (k & 8 ? 1 : -1) / 2;
    case 3: return (int32_t)u32(r);
    default: return (int32_t)(k >> 3) * 5 - 40 + (int32_t)(u8(r) & 7);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rd r = {data, size};
    fx_format f = (fx_format)(u8(&r) % FX_FMT_COUNT);
    int32_t w = 1 + (int32_t)(u8(&r) % 64), h = 1 + (int32_t)(u8(&r) % 64);
    guarded g;
    if (guarded_make(&g, w, h, f, (int)(u8(&r) & 1)) < 0)
        return 0;
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    static uint8_t work[1 << 16];
    for (int ops = 0; r.n && ops < 64; ops++) {
        fx_ctx_set_color(&c, u32(&r));
        int32_t v[8];
        uint32_t op = u8(&r);
        for (int i = 0; i < 8; i++)
            v[i] = coord(&r);
        switch (op % 24) {
        case 0: fx_plot(&c, v[0], v[1]); break;
        case 1: fx_line(&c, v[0], v[1], v[2], v[3]); break;
        case 2: fx_fill_rect(&c, v[0], v[1], v[2], v[3]); break;
        case 3: fx_rect_outline(&c, v[0], v[1], v[2], v[3]); break;
        case 4: fx_circle(&c, v[0], v[1], v[2]); break;
        case 5: fx_disc(&c, v[0], v[1], v[2]); break;
        case 6: fx_arc(&c, v[0], v[1], v[2], (fx_angle)v[3], (fx_angle)v[4]); break;
        case 7: fx_pie(&c, v[0], v[1], v[2], (fx_angle)v[3], (fx_angle)v[4]); break;
        case 8: fx_aacircle(&c, v[0], v[1], v[2]); break;
        case 9: fx_ellipse(&c, v[0], v[1], v[2], v[3]); break;
        case 10: fx_fill_ellipse(&c, v[0], v[1], v[2], v[3]); break;
        case 11: fx_fill_poly(&c, v, 4, (fx_fill_rule)(op >> 7)); break;
        case 12: fx_fill_tri(&c, v[0], v[1], v[2], v[3], v[4], v[5]); break;
        case 13: {
            fx_color col[3] = {u32(&r), u32(&r), u32(&r)};
            fx_fill_tri_gouraud(&c, v, col);
            break;
        }
        case 14: fx_polygon(&c, v, 4); break;
        case 15: fx_koch(&c, v[0], v[1], v[2], v[3], u8(&r) % 7); break;
        case 16: fx_hilbert(&c, v[0], v[1], v[2], u8(&r) % 7); break;
        case 17: fx_text(&c, v[0], v[1], "fixel \xE2\x82\xAC"); break;
        case 18: fx_ctx_set_clip(&c, (fx_rect){v[0], v[1], v[2], v[3]}); break;
        case 19:
            c.blend = (uint8_t)(op >> 7);
            fx_ctx_set_coords(&c, (op >> 6) & 1 ? FX_COORDS_COURSE : FX_COORDS_SCREEN); /* issue #23 */
            break;
        case 20:
            c.exterior = (uint8_t)(op >> 7);
            c.exterior_rect = (fx_rect){v[0], v[1], v[2], v[3]};
            break;
        case 21:
            if (fx_seed_work_size(&c) <= sizeof work)
                fx_flood_fill(&c, v[0], v[1], op & 128 ? 8 : 4, work, sizeof work);
            break;
        case 22:
            c.line_clipper = (uint8_t)(op % FX_CLIP_COUNT);
            fx_clip_draw_line(&c, v[0], v[1], v[2], v[3]);
            break;
        default: {
            fx56 cre = (fx56)v[0] * (1 << 28), cim = (fx56)v[1] * (1 << 28), wd = (fx56)(uint32_t)v[2] << 20;
            fx_fractal_view fv = fx_mandel_view(cre, cim, wd, w, h, 1 + u8(&r) % 64);
            uint32_t lut[65];
            fx_dwell_pal pal;
            fx_dwell_pal_w9(&pal, lut, f);
            if (fx_fractal_check(&fv) == 0)
                fx_fractal_render(&g.s, (fx_rect){v[3], v[4], v[5], v[6]}, &fv, &pal);
            break;
        }
        }
    }
    guarded_free(&g);
    return 0;
}
