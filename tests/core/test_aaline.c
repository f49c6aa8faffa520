/* SPDX-License-Identifier: MIT */
/* Antialiased lines: the coverage model (255 units per column, centred on
 * the ideal line), the fast blend paths equal to fx_blend_over bit for bit,
 * and exact clipping for any int32 endpoints. */
#include <stdlib.h>
#include <string.h>

#include "fixel/line.h"
#include "fx_test.h"

typedef struct {
    fx_surface s;
    uint8_t *mem;
    int w, h;
} canvas;

static canvas make(int w, int h, fx_format f)
{
    canvas c;
    int32_t stride = fx_format_min_stride(f, w);
    c.mem = calloc((size_t)stride * h, 1);
    c.w = w;
    c.h = h;
    fx_surface_init(&c.s, c.mem, w, h, stride, f);
    return c;
}

FX_TEST(aaline_columns_carry_full_coverage_centred_on_the_line)
{
    uint32_t s = 5;
    for (int i = 0; i < 1500; i++) {
        canvas c = make(96, 80, FX_FMT_XRGB8888);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &c.s);
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 90) + 2, y0 = (int32_t)(fx_test_rand(&s) % 74) + 2;
        int32_t x1 = (int32_t)(fx_test_rand(&s) % 90) + 2, y1 = (int32_t)(fx_test_rand(&s) % 74) + 2;
        fx_aaline(&ctx, x0, y0, x1, y1);
        const uint32_t *px = (const uint32_t *)(void *)c.mem;
        int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
        int ymaj = llabs(dy) > llabs(dx);
        int64_t M = ymaj ? llabs(dy) : llabs(dx);
        int sa = ymaj ? (dy > 0) - (dy < 0) : (dx > 0) - (dx < 0);
        for (int64_t k = 0; k <= M; k++) {
            int64_t a = (ymaj ? y0 : x0) + sa * k;
            /* the ideal minor coordinate at this step */
            double ideal = (ymaj ? x0 : y0) + (double)k * (double)(ymaj ? dx : dy) / (double)(M ? M : 1);
            int64_t sum = 0;
            double mom = 0;
            int lit = 0;
            for (int b = 0; b < (ymaj ? 96 : 80); b++) {
                uint32_t v = ymaj ? px[a * 96 + b] : px[b * 96 + a];
                uint32_t cov = v & 0xFF;
                FX_CHECK(((v >> 8) & 0xFF) == cov && ((v >> 16) & 0xFF) == cov);
                sum += cov;
                mom += (double)cov * b;
                lit += cov != 0;
            }
            FX_CHECK_MSG(sum == 255, "(%d,%d)->(%d,%d) k=%lld sum %lld", x0, y0, x1, y1, (long long)k,
                         (long long)sum);
            FX_CHECK(lit >= 1 && lit <= 2);
            double centre = mom / 255.0;
            FX_CHECK_MSG(centre - ideal < 2.0 / 255 + 1e-9 && ideal - centre < 2.0 / 255 + 1e-9,
                         "(%d,%d)->(%d,%d) k=%lld centre %f ideal %f", x0, y0, x1, y1, (long long)k,
                         centre, ideal);
        }
        /* nothing outside the line's columns */
        int64_t total = 0;
        for (int p = 0; p < 96 * 80; p++)
            total += px[p] & 0xFF;
        FX_CHECK_EQ(total, 255 * (M + 1));
        free(c.mem);
    }
}

/* The fast paths must agree with the generic per-pixel path (forced here by
 * an empty exterior rectangle), which uses fx_blend_over itself. */
FX_TEST(aaline_fast_paths_equal_fx_blend_over)
{
    fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_XBGR8888, FX_FMT_RGB565, FX_FMT_BGR565};
    for (int f = 0; f < 4; f++) {
        canvas a = make(120, 90, fmts[f]), b = make(120, 90, fmts[f]);
        uint32_t s = 11 + f;
        int32_t stride = a.s.stride;
        for (int i = 0; i < stride * 90; i++)
            a.mem[i] = b.mem[i] = (uint8_t)fx_test_rand(&s);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        cb.exterior = 1; /* exterior_rect is empty: excludes nothing */
        for (int i = 0; i < 400; i++) {
            fx_color col = 0xFF000000u | fx_test_rand(&s);
            fx_ctx_set_color(&ca, col);
            fx_ctx_set_color(&cb, col);
            int32_t v[4];
            for (int j = 0; j < 4; j++)
                v[j] = (int32_t)(fx_test_rand(&s) % 160) - 20;
            fx_aaline(&ca, v[0], v[1], v[2], v[3]);
            fx_aaline(&cb, v[0], v[1], v[2], v[3]);
        }
        FX_CHECK_MSG(memcmp(a.mem, b.mem, (size_t)stride * 90) == 0, "format %d", f);
        free(a.mem);
        free(b.mem);
    }
}

/* A clipped line computes exactly the pixels of the unclipped one that fall
 * inside the window, also for endpoints anywhere in int32. */
FX_TEST(aaline_clipping_never_changes_a_pixel)
{
    uint32_t s = 99;
    fx_rect win = {7, 5, 53, 40};
    for (int i = 0; i < 3000; i++) {
        fx_format f = i % 3 == 0 ? FX_FMT_XRGB8888 : i % 3 == 1 ? FX_FMT_RGB565 : FX_FMT_GRAY8;
        canvas a = make(64, 48, f), b = make(64, 48, f);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_ctx_set_clip(&cb, win);
        int32_t v[4];
        for (int j = 0; j < 4; j++) {
            uint32_t r = fx_test_rand(&s);
            v[j] = i % 4 == 0 ? (int32_t)r : i % 4 == 1 ? (int32_t)(r % 200) - 70 :
                   i % 4 == 2 ? (int32_t)(r % 100000) - 50000 : (j & 1 ? (int32_t)(r % 48) : (int32_t)r);
        }
        fx_aaline(&ca, v[0], v[1], v[2], v[3]);
        fx_aaline(&cb, v[0], v[1], v[2], v[3]);
        int bpp = fx_format_get(f)->bits_per_pixel / 8;
        for (int y = 0; y < 48; y++)
            for (int x = 0; x < 64; x++) {
                int in = x >= win.x0 && x < win.x1 && y >= win.y0 && y < win.y1;
                const uint8_t *pa = a.mem + y * a.s.stride + x * bpp, *pb = b.mem + y * b.s.stride + x * bpp;
                int zero = 1;
                for (int q = 0; q < bpp; q++)
                    zero &= pb[q] == 0;
                if (in ? memcmp(pa, pb, (size_t)bpp) != 0 : !zero) {
                    FX_CHECK_MSG(0, "(%d,%d)->(%d,%d) pixel %d,%d", v[0], v[1], v[2], v[3], x, y);
                    y = 48;
                    break;
                }
            }
        free(a.mem);
        free(b.mem);
    }
}

FX_TEST(aaline_blends_colour_alpha_under_over)
{
    canvas c = make(40, 10, FX_FMT_XRGB8888);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_ctx_set_color(&ctx, 0xFF204060u);
    fx_clear(&ctx);
    ctx.blend = FX_BLEND_OVER;
    fx_ctx_set_color(&ctx, 0x80FFFFFFu);
    fx_aaline(&ctx, 0, 2, 39, 2); /* level: full coverage, alpha 0x80 */
    const uint32_t *px = (const uint32_t *)(void *)c.mem;
    uint32_t want = fx_blend_over(FX_FMT_XRGB8888, fx_pack(FX_FMT_XRGB8888, 0xFF204060u), 0x80FFFFFFu);
    for (int x = 0; x < 40; x++)
        FX_CHECK_EQ_HEX(px[2 * 40 + x], want);
    FX_CHECK_EQ_HEX(px[3 * 40 + 5], fx_pack(FX_FMT_XRGB8888, 0xFF204060u));
    free(c.mem);
}
