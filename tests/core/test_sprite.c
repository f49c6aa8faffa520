/* SPDX-License-Identifier: MIT */
/* The software pointer sprite (kernel-free-src/raster/sprite.c): every pixel format
 * and rotation, clipping at each screen edge, exact save/restore. The
 * expectation is built independently: walk the sprite's logical pixels and
 * map each through the documented logical -> physical rotation. */
#include <stdlib.h>
#include <string.h>

#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"
#include "fx_test.h"

static const fx_format formats[] = {FX_FMT_XRGB8888, FX_FMT_ARGB8888, FX_FMT_XBGR8888,
                                    FX_FMT_RGB565,   FX_FMT_BGR565,   FX_FMT_RGB888,
                                    FX_FMT_BGR888,   FX_FMT_GRAY8,    FX_FMT_MONO1};
static const int rots[] = {0, 90, 180, 270};

/* Transparent, opaque and translucent pixels; hotspot off the corner. */
static const uint32_t test_pixels[5 * 4] = {
    0x00000000, 0xFFFF0000, 0xFF00FF00, 0x80FFFFFF, 0x00FFFFFF,
    0xFF0000FF, 0x40000000, 0xC0102030, 0xFFFFFFFF, 0x00000000,
    0xFF000000, 0x00FF00FF, 0xFF808080, 0x7F123456, 0xFFFEDCBA,
    0x01FFFFFF, 0xFE000000, 0x00000000, 0xFF00FFFF, 0x80808080,
};
static const fx_sprite test_sprite = {test_pixels, 5, 4, 1, 2};

static uint32_t rng = 12345;
static uint32_t next_rand(void)
{
    rng = rng * 1103515245u + 12345u;
    return rng >> 8 ^ rng << 13;
}

typedef struct {
    fx_surface s;
    uint8_t *mem;
    size_t size;
} test_surf;

/* Physical W x H surface with one guard row of padding per row and
 * random content everywhere (padding included, so stray writes show). */
static test_surf make(fx_format f, int32_t w, int32_t h, int bit_offset)
{
    test_surf t;
    int32_t stride = ((fx_format_min_stride(f, w + 8) + 3) & ~3) + 4;
    t.size = (size_t)stride * (size_t)h;
    t.mem = malloc(t.size);
    for (size_t i = 0; i < t.size; i++)
        t.mem[i] = (uint8_t)next_rand();
    if (fx_surface_init(&t.s, t.mem, w, h, stride, f) < 0)
        abort();
    t.s.bit_offset = (uint8_t)bit_offset;
    /* Normalise pixels to valid native values (X bytes zero, etc.). */
    for (int32_t y = 0; y < h; y++)
        for (int32_t x = 0; x < w; x++)
            fx_surface_put_native(&t.s, x, y, fx_pack(f, next_rand() | 0xFF000000u));
    return t;
}

static void phys_of(int rot, int32_t W, int32_t H, int32_t lx, int32_t ly, int32_t *px, int32_t *py)
{
    switch (rot) {
    case 90: *px = W - 1 - ly; *py = lx; break;
    case 180: *px = W - 1 - lx; *py = H - 1 - ly; break;
    case 270: *px = ly; *py = H - 1 - lx; break;
    default: *px = lx; *py = ly; break;
    }
}

/* Draw at (x, y); compare with the reference; restore; compare bytes. */
static int one_case(fx_format f, int rot, int32_t W, int32_t H, int32_t x, int32_t y, int bit_offset)
{
    int ok = 1;
    test_surf a = make(f, W, H, bit_offset);
    uint8_t *orig = malloc(a.size);
    memcpy(orig, a.mem, a.size);
    test_surf ref = {a.s, malloc(a.size), a.size};
    memcpy(ref.mem, a.mem, a.size);
    ref.s.pixels = ref.mem;

    int32_t LW = (rot == 90 || rot == 270) ? H : W, LH = (rot == 90 || rot == 270) ? W : H;
    fx_rect want = {0, 0, 0, 0};
    int any = 0;
    for (int32_t sy = 0; sy < test_sprite.h; sy++)
        for (int32_t sx = 0; sx < test_sprite.w; sx++) {
            /* 64-bit: the far-away cases would overflow int32 here. */
            int64_t lx = (int64_t)x - test_sprite.hot_x + sx, ly = (int64_t)y - test_sprite.hot_y + sy;
            int32_t px, py;
            if (lx < 0 || ly < 0 || lx >= LW || ly >= LH)
                continue;
            phys_of(rot, W, H, (int32_t)lx, (int32_t)ly, &px, &py);
            if (!any)
                want = (fx_rect){px, py, px + 1, py + 1}, any = 1;
            want.x0 = px < want.x0 ? px : want.x0;
            want.y0 = py < want.y0 ? py : want.y0;
            want.x1 = px + 1 > want.x1 ? px + 1 : want.x1;
            want.y1 = py + 1 > want.y1 ? py + 1 : want.y1;
            fx_color c = test_pixels[sy * test_sprite.w + sx];
            uint32_t d = fx_surface_get_native(&ref.s, px, py);
            if (c >> 24 == 255)
                d = fx_pack(f, c);
            else if (c >> 24)
                d = fx_blend_over(f, d, c);
            fx_surface_put_native(&ref.s, px, py, d);
        }

    uint32_t mem[FX_SPRITE_MAX * FX_SPRITE_MAX];
    fx_sprite_save sv = {{0, 0, 0, 0}, mem, FX_SPRITE_MAX * FX_SPRITE_MAX};
    ok &= fx_sprite_draw(&a.s, rot, &test_sprite, x, y, &sv) == 0;
    ok &= memcmp(a.mem, ref.mem, a.size) == 0;
    if (any)
        ok &= memcmp(&sv.r, &want, sizeof want) == 0;
    else
        ok &= fx_rect_empty(sv.r);
    fx_rect p = fx_sprite_phys_rect(&a.s, rot, &test_sprite, x, y);
    ok &= any ? memcmp(&p, &want, sizeof want) == 0 : fx_rect_empty(p);
    fx_rect back = fx_sprite_restore(&a.s, &sv);
    ok &= any ? memcmp(&back, &want, sizeof want) == 0 : fx_rect_empty(back);
    ok &= fx_rect_empty(sv.r);
    ok &= memcmp(a.mem, orig, a.size) == 0;
    free(a.mem);
    free(ref.mem);
    free(orig);
    return ok;
}

FX_TEST(sprite_every_format_rotation_and_edge)
{
    const int32_t W = 23, H = 17;
    for (unsigned fi = 0; fi < sizeof formats / sizeof formats[0]; fi++)
        for (unsigned ri = 0; ri < 4; ri++) {
            int rot = rots[ri];
            int32_t LW = (rot == 90 || rot == 270) ? H : W, LH = (rot == 90 || rot == 270) ? W : H;
            /* Inside, across each edge and corner, and just off each edge. */
            const int32_t xs[] = {-5, -3, -1, 0, 1, 7, LW - 4, LW - 2, LW, LW + 1, LW + 4};
            const int32_t ys[] = {-3, -2, -1, 0, 2, 9, LH - 2, LH - 1, LH, LH + 2};
            int fails = 0;
            for (unsigned i = 0; i < sizeof xs / sizeof xs[0]; i++)
                for (unsigned j = 0; j < sizeof ys / sizeof ys[0]; j++)
                    fails += !one_case(formats[fi], rot, W, H, xs[i], ys[j], 0);
            FX_CHECK_MSG(fails == 0, "%s rotation %d: %d cases differ",
                         fx_format_get(formats[fi])->name, rot, fails);
        }
}

FX_TEST(sprite_mono_with_bit_offset)
{
    for (unsigned ri = 0; ri < 4; ri++)
        for (int off = 1; off < 8; off += 3)
            FX_CHECK(one_case(FX_FMT_MONO1, rots[ri], 19, 13, 3, 4, off));
}

FX_TEST(sprite_far_positions_stay_off_screen)
{
    FX_CHECK(one_case(FX_FMT_XRGB8888, 0, 16, 16, INT32_MIN, INT32_MAX, 0));
    FX_CHECK(one_case(FX_FMT_RGB565, 90, 16, 16, INT32_MAX, INT32_MIN, 0));
}

FX_TEST(sprite_small_save_buffer_draws_nothing)
{
    test_surf a = make(FX_FMT_XRGB8888, 20, 20, 0);
    uint8_t *orig = malloc(a.size);
    memcpy(orig, a.mem, a.size);
    uint32_t mem[20];
    fx_sprite_save sv = {{0, 0, 0, 0}, mem, 19}; /* one short of 5 x 4 */
    FX_CHECK_EQ(fx_sprite_draw(&a.s, 0, &test_sprite, 5, 5, &sv), -FX_ENOSPC);
    FX_CHECK(fx_rect_empty(sv.r));
    FX_CHECK(memcmp(a.mem, orig, a.size) == 0);
    sv.cap = 20;
    FX_CHECK_EQ(fx_sprite_draw(&a.s, 0, &test_sprite, 5, 5, &sv), 0);
    FX_CHECK(memcmp(a.mem, orig, a.size) != 0);
    fx_sprite_restore(&a.s, &sv);
    FX_CHECK(memcmp(a.mem, orig, a.size) == 0);
    free(a.mem);
    free(orig);
}

FX_TEST(sprite_bad_arguments)
{
    uint32_t mem[16];
    fx_sprite_save sv = {{0, 0, 0, 0}, mem, 16};
    test_surf a = make(FX_FMT_XRGB8888, 8, 8, 0);
    fx_sprite s = test_sprite;
    FX_CHECK_EQ(fx_sprite_check(&s), 0);
    s.hot_x = 5;
    FX_CHECK_EQ(fx_sprite_check(&s), -FX_EINVAL);
    s = test_sprite;
    s.w = FX_SPRITE_MAX + 1;
    FX_CHECK_EQ(fx_sprite_check(&s), -FX_EINVAL);
    s = test_sprite;
    s.pixels = NULL;
    FX_CHECK_EQ(fx_sprite_draw(&a.s, 0, &s, 1, 1, &sv), -FX_EINVAL);
    FX_CHECK_EQ(fx_sprite_draw(&a.s, 45, &test_sprite, 1, 1, &sv), -FX_EINVAL);
    FX_CHECK_EQ(fx_sprite_check(NULL), -FX_EINVAL);
    free(a.mem);
}

/* The save can clean a second buffer holding the same picture plus the
 * sprite (what direct presentation does after copying the front buffer). */
FX_TEST(sprite_save_applies_to_a_copy)
{
    test_surf a = make(FX_FMT_RGB888, 30, 20, 0);
    uint8_t *orig = malloc(a.size), *copy = malloc(a.size);
    memcpy(orig, a.mem, a.size);
    uint32_t mem[FX_SPRITE_MAX * FX_SPRITE_MAX];
    fx_sprite_save sv = {{0, 0, 0, 0}, mem, FX_SPRITE_MAX * FX_SPRITE_MAX};
    FX_CHECK_EQ(fx_sprite_draw(&a.s, 180, fx_sprite_arrow(), 10, 3, &sv), 0);
    memcpy(copy, a.mem, a.size);
    fx_surface c = a.s;
    c.pixels = copy;
    fx_sprite_save_apply(&c, &sv);
    FX_CHECK(memcmp(copy, orig, a.size) == 0);
    FX_CHECK(!fx_rect_empty(sv.r)); /* the original still has its sprite */
    FX_CHECK(memcmp(a.mem, orig, a.size) != 0);
    free(a.mem);
    free(orig);
    free(copy);
}

FX_TEST(sprite_default_arrow)
{
    const fx_sprite *s = fx_sprite_arrow();
    FX_CHECK_EQ(fx_sprite_check(s), 0);
    /* The tip is the hotspot and is an opaque outline pixel; the top row
     * has nothing else, and the widest row spans the whole sprite. */
    FX_CHECK_EQ_HEX(s->pixels[s->hot_y * s->w + s->hot_x], 0xFF000000u);
    int top = 0, opaque = 0, white = 0;
    for (int32_t x = 0; x < s->w; x++)
        top += s->pixels[x] >> 24 != 0;
    for (int32_t i = 0; i < s->w * s->h; i++) {
        opaque += s->pixels[i] >> 24 == 255;
        white += s->pixels[i] == 0xFFFFFFFFu;
    }
    FX_CHECK_EQ(top, 1);
    FX_CHECK(s->pixels[11 * s->w + s->w - 1] >> 24 == 255);
    /* Black outline around a white body: both are present, and the rest of
     * the box is see-through. */
    FX_CHECK(white > 40 && opaque - white > 30 && opaque < s->w * s->h * 2 / 3);
    fx_rect r = fx_sprite_rect(s, 100, 50);
    FX_CHECK_EQ(r.x0, 100);
    FX_CHECK_EQ(r.y1, 50 + s->h);
}
