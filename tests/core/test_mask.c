/* SPDX-License-Identifier: MIT */
/* Coverage masks (mask.h): the per-pixel rule checked exhaustively in every
 * format (every coverage 0..255 x colour/alpha classes x destination
 * classes, plain and gamma) against a reference written here from the
 * documented rule alone (its own pack/unpack from surface.h's table, exact
 * rational rounding, the sRGB curve from its formula in double precision);
 * then placement, the four rotations, clipping and bad arguments. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/mask.h"
#include "fixel/error.h"
#include "fx_test.h"

/* ---- the reference ---- */

typedef struct { uint32_t a, r, g, b; } rgba;

static rgba ref_unpack(fx_format f, uint32_t n)
{
    rgba o = {255, 0, 0, 0};
    switch (f) {
    case FX_FMT_ARGB8888: o.a = n >> 24; /* fall through */
    case FX_FMT_XRGB8888:
    case FX_FMT_RGB888: o.r = (n >> 16) & 255, o.g = (n >> 8) & 255, o.b = n & 255; break;
    case FX_FMT_XBGR8888:
    case FX_FMT_BGR888: o.b = (n >> 16) & 255, o.g = (n >> 8) & 255, o.r = n & 255; break;
    case FX_FMT_RGB565:
    case FX_FMT_BGR565: {
        uint32_t hi = n >> 11, g6 = (n >> 5) & 63, lo = n & 31;
        uint32_t h8 = hi * 8 + hi / 4, l8 = lo * 8 + lo / 4;
        o.g = g6 * 4 + g6 / 16;
        if (f == FX_FMT_RGB565)
            o.r = h8, o.b = l8;
        else
            o.b = h8, o.r = l8;
        break;
    }
    case FX_FMT_GRAY8: o.r = o.g = o.b = n & 255; break;
    default: o.r = o.g = o.b = n ? 255 : 0; break;
    }
    return o;
}

static uint32_t ref_pack(fx_format f, rgba c)
{
    switch (f) {
    case FX_FMT_XRGB8888:
    case FX_FMT_RGB888: return c.r << 16 | c.g << 8 | c.b;
    case FX_FMT_ARGB8888: return c.a << 24 | c.r << 16 | c.g << 8 | c.b;
    case FX_FMT_XBGR8888:
    case FX_FMT_BGR888: return c.b << 16 | c.g << 8 | c.r;
    case FX_FMT_RGB565: return (c.r / 8) << 11 | (c.g / 4) << 5 | c.b / 8;
    case FX_FMT_BGR565: return (c.b / 8) << 11 | (c.g / 4) << 5 | c.r / 8;
    case FX_FMT_GRAY8: return (77 * c.r + 150 * c.g + 29 * c.b + 128) / 256;
    default: return (77 * c.r + 150 * c.g + 29 * c.b + 128) / 256 >= 128;
    }
}

/* n / d rounded to nearest, ties up (d > 0, n >= 0). */
static uint64_t ref_div(uint64_t n, uint64_t d) { return (2 * n + d) / (2 * d); }

static double ref_srgb_lin(int v)
{
    double x = v / 255.0;
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

static uint32_t L[256]; /* Q16 linear light; 255 -> exactly 1.0 */
static void ref_encode_table(void);

static void ref_tables(void)
{
    for (int i = 0; i < 256; i++)
        L[i] = i == 255 ? 65536 : (uint32_t)lround(ref_srgb_lin(i) * 65536.0);
    ref_encode_table();
}

/* The nearest code to linear value l (ties to the lower code): a full
 * search over the 256 codes, done once for every l into a table (the
 * exhaustive test asks for it millions of times). */
static uint8_t enc[65537];

static void ref_encode_table(void)
{
    for (uint32_t l = 0; l <= 65536; l++) {
        uint32_t best = 0;
        for (uint32_t k = 1; k < 256; k++) {
            int64_t dk = (int64_t)L[k] - l, db = (int64_t)L[best] - l;
            if (llabs(dk) < llabs(db))
                best = k;
        }
        enc[l] = (uint8_t)best;
    }
}

static uint32_t ref_encode(uint32_t l) { return enc[l]; }

static uint32_t ref_chan(uint32_t s, uint32_t d, uint32_t a, int gamma)
{
    if (!gamma)
        return (uint32_t)ref_div(s * a + d * (255 - a), 255);
    return ref_encode((uint32_t)ref_div((uint64_t)L[s] * a + (uint64_t)L[d] * (255 - a), 255));
}

static uint32_t ref_blend(fx_format f, uint32_t dst, fx_color c, uint32_t cov, int gamma)
{
    uint32_t a = (uint32_t)ref_div((c >> 24) * cov, 255);
    if (a == 0)
        return dst;
    rgba d = ref_unpack(f, dst), o;
    o.r = ref_chan((c >> 16) & 255, d.r, a, gamma);
    o.g = ref_chan((c >> 8) & 255, d.g, a, gamma);
    o.b = ref_chan(c & 255, d.b, a, gamma);
    o.a = a + (uint32_t)ref_div(d.a * (255 - a), 255);
    return ref_pack(f, o);
}

/* ---- value classes ---- */

static const uint32_t chan_class[] = {0, 1, 7, 8, 127, 128, 200, 254, 255};
#define NCH (sizeof chan_class / sizeof chan_class[0])

/* Destination natives of format f: every value for GRAY8 and MONO1, and for
 * the others each channel class in turn on each channel (the rest mid grey),
 * the greys, and the format's extremes. */
static int dst_classes(fx_format f, uint32_t *out)
{
    int n = 0;
    if (f == FX_FMT_GRAY8) {
        for (uint32_t v = 0; v < 256; v++)
            out[n++] = v;
        return n;
    }
    if (f == FX_FMT_MONO1) {
        out[n++] = 0, out[n++] = 1;
        return n;
    }
    for (size_t i = 0; i < NCH; i++) {
        uint32_t v = chan_class[i];
        rgba g = {v, v, v, v}, r = {v, v, 90, 170}, gr = {255 - v, 40, v, 220}, b = {v, 250, 3, v};
        out[n++] = ref_pack(f, g);
        out[n++] = ref_pack(f, r);
        out[n++] = ref_pack(f, gr);
        out[n++] = ref_pack(f, b);
    }
    if (f == FX_FMT_RGB565 || f == FX_FMT_BGR565) {
        static const uint32_t raw[] = {0x0000, 0xFFFF, 0x0821, 0xF800, 0x07E0, 0x001F, 0x7BEF, 0x8410};
        for (size_t i = 0; i < sizeof raw / sizeof raw[0]; i++)
            out[n++] = raw[i];
    }
    return n;
}

static int src_classes(fx_color *out)
{
    static const uint32_t alphas[] = {255, 254, 128, 1, 0};
    int n = 0;
    for (size_t ai = 0; ai < sizeof alphas / sizeof alphas[0]; ai++)
        for (size_t i = 0; i < NCH; i++) {
            uint32_t v = chan_class[i];
            out[n++] = alphas[ai] << 24 | v << 16 | v << 8 | v;
            out[n++] = alphas[ai] << 24 | v << 16 | (255 - v) << 8 | 77;
            out[n++] = alphas[ai] << 24 | 13u << 16 | 250u << 8 | v;
        }
    return n;
}

FX_TEST(mask_coverage_rule_equals_reference_every_format_every_coverage)
{
    ref_tables();
    static uint32_t dsts[512];
    fx_color srcs[256];
    int ns = src_classes(srcs);
    long checked = 0;
    for (int f = 0; f < FX_FMT_COUNT; f++) {
        int nd = dst_classes((fx_format)f, dsts);
        for (int gamma = 0; gamma < 2; gamma++) {
            int bad = 0;
            for (int si = 0; si < ns; si++)
                for (int di = 0; di < nd; di++)
                    for (uint32_t cov = 0; cov < 256; cov++) {
                        uint32_t want = ref_blend((fx_format)f, dsts[di], srcs[si], cov, gamma);
                        uint32_t got = fx_coverage_blend((fx_format)f, dsts[di], srcs[si], cov,
                                                         gamma ? FX_MASK_GAMMA : 0);
                        checked++;
                        if (want != got && bad++ < 5)
                            FX_CHECK_MSG(0, "%s gamma %d dst 0x%x src 0x%08x cov %u: 0x%x, want 0x%x",
                                         fx_format_get((fx_format)f)->name, gamma, dsts[di], srcs[si],
                                         cov, got, want);
                    }
        }
    }
    FX_CHECK(checked > 2000000);
}

FX_TEST(mask_gamma_differs_from_plain_where_it_should)
{
    /* White text at half coverage on black: plain gives 128, linear light
     * gives the code of 50 % light, 188: the gamma option is not a no-op. */
    FX_CHECK_EQ(fx_coverage_blend(FX_FMT_XRGB8888, 0, 0xFFFFFFFFu, 128, 0), 0x808080);
    FX_CHECK_EQ(fx_coverage_blend(FX_FMT_XRGB8888, 0, 0xFFFFFFFFu, 128, FX_MASK_GAMMA), 0xBCBCBC);
    /* Full and zero coverage are the same in both. */
    FX_CHECK_EQ(fx_coverage_blend(FX_FMT_RGB565, 0x1234, 0xFF00FF00u, 255, FX_MASK_GAMMA), 0x07E0);
    FX_CHECK_EQ(fx_coverage_blend(FX_FMT_RGB565, 0x1234, 0xFF00FF00u, 0, FX_MASK_GAMMA), 0x1234);
}

/* ---- drawing ---- */

typedef struct {
    fx_surface s;
    uint8_t *mem;
} canvas;

static canvas make(int w, int h, fx_format f)
{
    canvas c;
    int32_t stride = fx_format_min_stride(f, w);
    c.mem = calloc((size_t)stride * (size_t)h, 1);
    fx_surface_init(&c.s, c.mem, w, h, stride, f);
    return c;
}

/* Where mask pixel (mx, my) lands, written from the header's table. */
static void ref_place(unsigned rot, int w, int h, int mx, int my, int *u, int *v)
{
    switch (rot) {
    case 0: *u = mx, *v = my; break;
    case 1: *u = h - 1 - my, *v = mx; break;
    case 2: *u = w - 1 - mx, *v = h - 1 - my; break;
    default: *u = my, *v = w - 1 - mx; break;
    }
}

FX_TEST(mask_rotations_place_each_pixel_per_the_table)
{
    enum { W = 5, H = 3 };
    uint8_t cov[H][W];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            cov[y][x] = (uint8_t)(10 + y * W + x); /* all distinct, none 0 */
    for (int neg = 0; neg < 2; neg++)
        for (unsigned rot = 0; rot < 4; rot++) {
            canvas c = make(20, 20, FX_FMT_XRGB8888);
            fx_ctx ctx;
            fx_ctx_init(&ctx, &c.s);
            /* A negative stride walks the rows bottom up, as FreeType's
             * "flow up" bitmaps do: the same picture stored upside down. */
            uint8_t flip[H][W];
            for (int y = 0; y < H; y++)
                memcpy(flip[y], cov[H - 1 - y], W);
            fx_mask m = neg ? (fx_mask){&flip[H - 1][0], W, H, -W} : (fx_mask){&cov[0][0], W, H, W};
            FX_CHECK_EQ(fx_mask_blend(&ctx, 7, 4, &m, rot, 0), 0);
            int lit = 0;
            for (int my = 0; my < H; my++)
                for (int mx = 0; mx < W; mx++) {
                    int u, v;
                    ref_place(rot, W, H, mx, my, &u, &v);
                    uint32_t k = cov[my][mx];
                    FX_CHECK_EQ_HEX(fx_surface_get_native(&c.s, 7 + u, 4 + v), k << 16 | k << 8 | k);
                }
            for (int y = 0; y < 20; y++)
                for (int x = 0; x < 20; x++)
                    lit += fx_surface_get_native(&c.s, x, y) != 0;
            FX_CHECK_EQ(lit, W * H);
            free(c.mem);
        }
}

FX_TEST(mask_clipping_and_exterior_equal_per_pixel_reference)
{
    uint32_t seed = 77;
    uint8_t cov[9 * 13];
    for (int i = 0; i < 9 * 13; i++)
        cov[i] = (uint8_t)fx_test_rand(&seed);
    for (int it = 0; it < 600; it++) {
        fx_format f = (fx_format)(fx_test_rand(&seed) % FX_FMT_COUNT);
        canvas c = make(24, 18, f), r = make(24, 18, f);
        for (int y = 0; y < 18; y++)
            for (int x = 0; x < 24; x++) {
                uint32_t v = fx_test_rand(&seed);
                fx_surface_put_native(&c.s, x, y, fx_pack(f, v));
                fx_surface_put_native(&r.s, x, y, fx_pack(f, v));
            }
        fx_ctx ctx;
        fx_ctx_init(&ctx, &c.s);
        fx_ctx_set_color(&ctx, fx_test_rand(&seed));
        ctx.blend = (uint8_t)(fx_test_rand(&seed) & 1);
        fx_rect clip = {(int32_t)(fx_test_rand(&seed) % 12), (int32_t)(fx_test_rand(&seed) % 9),
                        (int32_t)(12 + fx_test_rand(&seed) % 13), (int32_t)(9 + fx_test_rand(&seed) % 10)};
        fx_ctx_set_clip(&ctx, clip);
        if (fx_test_rand(&seed) & 1) {
            ctx.exterior = 1;
            ctx.exterior_rect = (fx_rect){5, 5, 11, 9};
        }
        int w = 1 + (int)(fx_test_rand(&seed) % 13), h = 1 + (int)(fx_test_rand(&seed) % 9);
        fx_mask m = {cov, w, h, 13};
        int32_t x = (int32_t)(fx_test_rand(&seed) % 40) - 14, y = (int32_t)(fx_test_rand(&seed) % 34) - 12;
        unsigned rot = fx_test_rand(&seed) & 3, flags = fx_test_rand(&seed) & 1;
        FX_CHECK_EQ(fx_mask_blend(&ctx, x, y, &m, rot, flags), 0);
        fx_color col = ctx.blend == FX_BLEND_OVER ? ctx.color : ctx.color | 0xFF000000u;
        for (int my = 0; my < h; my++)
            for (int mx = 0; mx < w; mx++) {
                int u, v;
                ref_place(rot, w, h, mx, my, &u, &v);
                int px = x + u, py = y + v;
                if (px < ctx.clip.x0 || px >= ctx.clip.x1 || py < ctx.clip.y0 || py >= ctx.clip.y1)
                    continue;
                if (ctx.exterior && px >= 5 && px < 11 && py >= 5 && py < 9)
                    continue;
                fx_surface_put_native(&r.s, px, py,
                                      fx_coverage_blend(f, fx_surface_get_native(&r.s, px, py), col,
                                                        cov[my * 13 + mx], flags));
            }
        int diff = 0;
        for (int y2 = 0; y2 < 18; y2++)
            for (int x2 = 0; x2 < 24; x2++)
                diff += fx_surface_get_native(&c.s, x2, y2) != fx_surface_get_native(&r.s, x2, y2);
        FX_CHECK_MSG(diff == 0, "case %d (%s rot %u): %d pixels differ", it, fx_format_get(f)->name, rot, diff);
        free(c.mem);
        free(r.mem);
    }
}

FX_TEST(mask_far_positions_and_bad_arguments)
{
    canvas c = make(8, 8, FX_FMT_RGB565);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    uint8_t cov[4] = {255, 255, 255, 255};
    fx_mask m = {cov, 2, 2, 2};
    /* Boxes reaching past the int32 range are cut, not wrapped. */
    FX_CHECK_EQ(fx_mask_blend(&ctx, INT32_MAX, INT32_MAX, &m, 0, 0), 0);
    FX_CHECK_EQ(fx_mask_blend(&ctx, INT32_MIN, INT32_MIN, &m, 1, 0), 0);
    for (int i = 0; i < 64; i++)
        FX_CHECK_EQ(fx_surface_get_native(&c.s, i % 8, i / 8), 0);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &m, 4, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &m, 0, 2), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(NULL, 0, 0, &m, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, NULL, 0, 0), -FX_EINVAL);
    fx_mask thin = {cov, 2, 2, 1}, neg = {cov, -1, 2, 2}, nul = {NULL, 2, 2, 2}, empty = {NULL, 0, 0, 0};
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &thin, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &neg, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &nul, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 0, 0, &empty, 0, 0), 0);
    for (int i = 0; i < 64; i++)
        FX_CHECK_EQ(fx_surface_get_native(&c.s, i % 8, i / 8), 0);
    FX_CHECK_EQ(fx_mask_blend(&ctx, 3, 3, &m, 0, 0), 0);
    FX_CHECK_EQ_HEX(fx_surface_get_native(&c.s, 4, 4), 0xFFFF);
    free(c.mem);
}
