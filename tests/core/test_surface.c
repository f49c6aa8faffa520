/* SPDX-License-Identifier: MIT */
/* Surfaces and pixel formats: the documented pack/unpack rules, exhaustively
 * where the domain allows, spans, sub-surfaces, strides and blits. */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/surface.h"
#include "fx_test.h"

static const fx_format all[] = {FX_FMT_XRGB8888, FX_FMT_ARGB8888, FX_FMT_XBGR8888,
                                FX_FMT_RGB565,   FX_FMT_BGR565,   FX_FMT_RGB888,
                                FX_FMT_BGR888,   FX_FMT_GRAY8,    FX_FMT_MONO1};
_Static_assert(sizeof all / sizeof all[0] == FX_FMT_COUNT, "a format is missing from all[]");

static int absd(int a, int b) { return a > b ? a - b : b - a; }
static int chan(fx_color c, int shift) { return (int)((c >> shift) & 0xFF); }
static int ref_luma(fx_color c)
{
    return (77 * chan(c, 16) + 150 * chan(c, 8) + 29 * chan(c, 0) + 128) >> 8;
}

/* Whether got (an unpacked pixel) renders want within what format fi can
 * hold. The precision comes from the table row alone, so a new format needs
 * no entry here: 24 and 32 bits per pixel are 8 bits a channel (exact), 16
 * bits at least 5 (555, 565: truncation loses up to 7), 8 bits and fewer are
 * grey levels (GRAY8, MONO1), judged on luma to within half a level. A
 * format these rules do not describe (RGB332, ARGB4444) fails until the
 * rule is extended, which is the point: it cannot pass unnoticed. */
static int renders(const fx_format_info *fi, fx_color want, fx_color got)
{
    unsigned bpp = fi->bits_per_pixel;
    if ((got >> 24) != (fi->has_alpha ? want >> 24 : 0xFFu))
        return 0;
    if (bpp >= 16) {
        int tol = bpp >= 24 ? 0 : 7;
        for (int sh = 0; sh <= 16; sh += 8)
            if (absd(chan(got, sh), chan(want, sh)) > tol)
                return 0;
        return 1;
    }
    if (chan(got, 16) != chan(got, 8) || chan(got, 8) != chan(got, 0))
        return 0;
    int levels = 1 << bpp;
    return 2 * absd(chan(got, 0), ref_luma(want)) * (levels - 1) <= 255;
}

/* Issue #42: a format missing from fx_pack or fx_unpack packed to 0 and drew
 * black. Every row of the table, reached through fx_format_get, must round
 * trip every probe colour within its precision, and pack a colour to
 * black's value only when black renders it. */
FX_TEST(format_table_every_format_packs_and_unpacks)
{
    static const fx_color probes[] = {
        0xFF000000, 0xFFFFFFFF, 0xFFFF0000, 0xFF00FF00, 0xFF0000FF, 0xFFFFFF00, 0xFF00FFFF,
        0xFFFF00FF, 0xFF808080, 0xFF7F7F7F, 0xFF010101, 0xFF080808, 0xFF123456, 0xFFFEDCBA,
        0x80FF8040, 0x00FFFFFF, 0x40102030, 0x00000000, 0x7F0000FF,
    };
    int nfmt = 0;
    for (fx_format f = 0; fx_format_get(f); f++, nfmt++) {
        const fx_format_info *fi = fx_format_get(f);
        const char *name = fi->name ? fi->name : "(unnamed)";
        uint32_t s = 42;
        int bad = 0;
        for (int i = 0; i < 20000 && bad < 3; i++) {
            fx_color c = i < (int)(sizeof probes / sizeof probes[0]) ? probes[i] : fx_test_rand(&s);
            fx_color black = fi->has_alpha ? c & 0xFF000000u : 0xFF000000u;
            uint32_t v = fx_pack(f, c);
            fx_color back = fx_unpack(f, v);
            if (!renders(fi, c, back)) {
                FX_CHECK_MSG(0, "%s: %08x packs to %x, unpacks to %08x", name, c, v, back);
                bad++;
            }
            if (v == fx_pack(f, black) && !renders(fi, c, black)) {
                FX_CHECK_MSG(0, "%s: %08x packs to black's value %x", name, c, v);
                bad++;
            }
        }
    }
    FX_CHECK_EQ(nfmt, FX_FMT_COUNT);
}

static int same_name(const char *a, const char *b)
{
    for (;; a++, b++) {
        int x = *a >= 'a' && *a <= 'z' ? *a - 32 : *a, y = *b >= 'a' && *b <= 'z' ? *b - 32 : *b;
        if (x != y)
            return 0;
        if (!x)
            return 1;
    }
}

/* Issue #42: a row with no name made fx_format_from_name read through NULL.
 * Every row has a non-empty name, unique as the case-insensitive lookup
 * sees it, that finds its own format in any case, and a size the pixel
 * accessors know. */
FX_TEST(format_min_stride_refuses_unknown_formats)
{
    FX_CHECK_EQ(fx_format_min_stride(FX_FMT_COUNT, 10), 0);
    FX_CHECK_EQ(fx_format_min_stride((fx_format)-1, 10), 0);
    FX_CHECK_EQ(fx_format_min_stride(FX_FMT_XRGB8888, -1), 0);
    FX_CHECK_EQ(fx_format_min_stride(FX_FMT_XRGB8888, 10), 40);
    FX_CHECK_EQ(fx_format_min_stride(FX_FMT_MONO1, 9), 2);
    FX_CHECK_EQ(fx_format_min_stride(FX_FMT_XRGB8888, INT32_MAX), INT32_MAX);
}

FX_TEST(format_table_rows_are_named_and_unique)
{
    for (fx_format f = 0; f < FX_FMT_COUNT; f++) {
        const fx_format_info *fi = fx_format_get(f);
        FX_CHECK(fi != NULL);
        if (!fi)
            continue;
        FX_CHECK_MSG(fi->name && fi->name[0], "format %d has no name", (int)f);
        if (!fi->name || !fi->name[0])
            continue;
        unsigned b = fi->bits_per_pixel;
        FX_CHECK_MSG(b == 1 || b == 8 || b == 16 || b == 24 || b == 32, "%s: %u bits", fi->name, b);
        FX_CHECK_EQ(fx_format_from_name(fi->name), f);
        char lower[32];
        size_t n = 0;
        for (; fi->name[n] && n < sizeof lower - 1; n++)
            lower[n] = fi->name[n] >= 'A' && fi->name[n] <= 'Z' ? fi->name[n] + 32 : fi->name[n];
        lower[n] = 0;
        FX_CHECK_EQ(fx_format_from_name(lower), f);
        for (fx_format g = 0; g < f; g++) {
            const char *o = fx_format_get(g)->name;
            FX_CHECK_MSG(!o || !same_name(o, fi->name), "formats %d and %d are both %s", (int)g,
                         (int)f, fi->name);
        }
    }
    FX_CHECK(fx_format_get(FX_FMT_COUNT) == NULL);
    FX_CHECK_EQ(fx_format_from_name(NULL), FX_FMT_COUNT);
    FX_CHECK_EQ(fx_format_from_name(""), FX_FMT_COUNT);
}

FX_TEST(rgb565_packs_by_truncation_for_every_colour)
{
    for (uint32_t c = 0; c < (1u << 24); c++) {
        uint32_t r = c >> 16, g = (c >> 8) & 255, b = c & 255;
        uint32_t want = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
        uint32_t v = fx_pack(FX_FMT_RGB565, c), w = fx_pack(FX_FMT_BGR565, c);
        if (v != want || w != (((b >> 3) << 11) | ((g >> 2) << 5) | (r >> 3))) {
            FX_CHECK_MSG(0, "565 pack of %06x", c);
            break;
        }
    }
    FX_CHECK_EQ_HEX(fx_pack(FX_FMT_RGB565, 0x2060A0), 0x2314); /* W1 of docs/BENCHMARK.md */
}

FX_TEST(sixteen_bit_formats_round_trip_every_value)
{
    for (uint32_t v = 0; v < 65536; v++) {
        FX_CHECK(fx_pack(FX_FMT_RGB565, fx_unpack(FX_FMT_RGB565, v)) == v);
        FX_CHECK(fx_pack(FX_FMT_BGR565, fx_unpack(FX_FMT_BGR565, v)) == v);
    }
    /* bit replication: full-scale channels unpack to 0xFF, zero to 0 */
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_RGB565, 0xFFFF), 0xFFFFFFFF);
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_RGB565, 0xF800), 0xFFFF0000);
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_BGR565, 0xF800), 0xFF0000FF);
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_RGB565, 0x0420), 0xFF008600); /* g=33 -> 33<<2|33>>4 = 134 */
}

FX_TEST(byte_formats_are_exact_and_gray_is_bt601_luma)
{
    uint32_t s = 17;
    for (int i = 0; i < 1000000; i++) {
        uint32_t c = fx_test_rand(&s);
        FX_CHECK(fx_unpack(FX_FMT_ARGB8888, fx_pack(FX_FMT_ARGB8888, c)) == c);
        uint32_t o = c | 0xFF000000u;
        FX_CHECK(fx_unpack(FX_FMT_XRGB8888, fx_pack(FX_FMT_XRGB8888, c)) == o);
        FX_CHECK(fx_unpack(FX_FMT_XBGR8888, fx_pack(FX_FMT_XBGR8888, c)) == o);
        FX_CHECK(fx_unpack(FX_FMT_RGB888, fx_pack(FX_FMT_RGB888, c)) == o);
        FX_CHECK(fx_unpack(FX_FMT_BGR888, fx_pack(FX_FMT_BGR888, c)) == o);
        FX_CHECK((fx_pack(FX_FMT_XRGB8888, c) >> 24) == 0); /* X byte written as 0 */
    }
    for (uint32_t c = 0; c < (1u << 24); c += 7) {
        uint32_t r = c >> 16, g = (c >> 8) & 255, b = c & 255;
        uint32_t y = fx_pack(FX_FMT_GRAY8, c);
        uint32_t lo = r < g ? (r < b ? r : b) : (g < b ? g : b);
        uint32_t hi = r > g ? (r > b ? r : b) : (g > b ? g : b);
        if (y < lo || y > hi || y != (77 * r + 150 * g + 29 * b + 128) >> 8) {
            FX_CHECK_MSG(0, "gray of %06x = %u", c, y);
            break;
        }
        if (fx_pack(FX_FMT_MONO1, c) != (y >= 128)) {
            FX_CHECK_MSG(0, "mono of %06x", c);
            break;
        }
    }
    for (uint32_t v = 0; v < 256; v++)
        FX_CHECK(fx_pack(FX_FMT_GRAY8, fx_unpack(FX_FMT_GRAY8, v)) == v);
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_MONO1, 1), 0xFFFFFFFF);
    FX_CHECK_EQ_HEX(fx_unpack(FX_FMT_MONO1, 0), 0xFF000000);
}

FX_TEST(memory_layout_follows_drm_fourcc)
{
    uint8_t mem[16] __attribute__((aligned(4)));
    fx_surface s;
    struct {
        fx_format f;
        uint8_t bytes[4];
        int n;
    } cases[] = {
        {FX_FMT_XRGB8888, {0x33, 0x22, 0x11, 0x00}, 4}, {FX_FMT_ARGB8888, {0x33, 0x22, 0x11, 0x80}, 4},
        {FX_FMT_XBGR8888, {0x11, 0x22, 0x33, 0x00}, 4}, {FX_FMT_RGB888, {0x33, 0x22, 0x11}, 3},
        {FX_FMT_BGR888, {0x11, 0x22, 0x33}, 3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        memset(mem, 0xEE, sizeof mem);
        FX_CHECK_EQ(fx_surface_init(&s, mem, 1, 1, 4, cases[i].f), 0);
        fx_surface_put(&s, 0, 0, 0x80112233);
        FX_CHECK_MSG(memcmp(mem, cases[i].bytes, (size_t)cases[i].n) == 0, "%s",
                     fx_format_get(cases[i].f)->name);
    }
    FX_CHECK_EQ(fx_format_get(FX_FMT_XRGB8888)->drm_fourcc, 0x34325258); /* 'XR24' */
    FX_CHECK_EQ(fx_format_get(FX_FMT_RGB565)->drm_fourcc, 0x36314752);   /* 'RG16' */
    FX_CHECK_EQ(fx_format_from_name("rgb565"), FX_FMT_RGB565);
    FX_CHECK_EQ(fx_format_from_name("RGB56"), FX_FMT_COUNT);
}

FX_TEST(surface_init_rejects_bad_geometry)
{
    uint32_t mem[64];
    fx_surface s;
    FX_CHECK_EQ(fx_surface_init(&s, mem, 8, 8, 31, FX_FMT_XRGB8888), -FX_EINVAL); /* too small */
    FX_CHECK_EQ(fx_surface_init(&s, mem, 8, 8, 34, FX_FMT_XRGB8888), -FX_EINVAL); /* misaligned */
    FX_CHECK_EQ(fx_surface_init(&s, (uint8_t *)mem + 1, 4, 4, 8, FX_FMT_RGB565), -FX_EINVAL);
    FX_CHECK_EQ(fx_surface_init(&s, mem, 0, 8, 32, FX_FMT_XRGB8888), -FX_EINVAL);
    FX_CHECK_EQ(fx_surface_init(&s, NULL, 8, 8, 32, FX_FMT_XRGB8888), -FX_EINVAL);
    FX_CHECK_EQ(fx_surface_init(&s, mem, 8, 8, 32, FX_FMT_COUNT), -FX_EINVAL);
    FX_CHECK_EQ(fx_surface_init(&s, mem, 9, 2, 2, FX_FMT_MONO1), 0); /* 9 bits fit in 2 bytes */
    FX_CHECK_EQ(fx_surface_init(&s, mem, 17, 2, 2, FX_FMT_MONO1), -FX_EINVAL);
}

/* Every format: a span writes exactly [x0, x1) of its row, nothing else. */
FX_TEST(spans_write_exactly_their_pixels_in_every_format)
{
    for (size_t f = 0; f < sizeof all / sizeof all[0]; f++) {
        enum { W = 37, H = 5 };
        fx_surface s;
        int32_t stride = fx_format_get(all[f])->bits_per_pixel == 32 ? 160 : 128;
        uint8_t *mem = calloc(1, (size_t)stride * H);
        FX_CHECK_EQ(fx_surface_init(&s, mem, W, H, stride, all[f]), 0);
        uint32_t white = fx_pack(all[f], 0xFFFFFF);
        for (int x0 = 0; x0 < W; x0 += 3)
            for (int x1 = x0; x1 <= W; x1 += 5) {
                memset(mem, 0, (size_t)s.stride * H);
                fx_span_fill(&s, 2, x0, x1, white);
                for (int y = 0; y < H; y++)
                    for (int x = 0; x < W; x++) {
                        int in = y == 2 && x >= x0 && x < x1;
                        if ((fx_surface_get_native(&s, x, y) == white) != in ||
                            (!in && fx_surface_get_native(&s, x, y) != 0)) {
                            FX_CHECK_MSG(0, "%s span [%d,%d) pixel %d,%d",
                                         fx_format_get(all[f])->name, x0, x1, x, y);
                            goto next;
                        }
                    }
            }
    next:
        free(mem);
    }
}

FX_TEST(sub_surfaces_share_pixels_and_clip)
{
    uint32_t mem[8 * 8] = {0};
    fx_surface s, t;
    fx_surface_init(&s, mem, 8, 8, 32, FX_FMT_XRGB8888);
    fx_rect r = {2, 3, 20, 5};
    t = fx_surface_sub(s, r);
    FX_CHECK_EQ(t.w, 6);
    FX_CHECK_EQ(t.h, 2);
    fx_surface_put(&t, 0, 0, 0xABCDEF);
    fx_surface_put(&t, 6, 0, 0x123456); /* outside the view: ignored */
    FX_CHECK_EQ_HEX(mem[3 * 8 + 2], 0xABCDEF);
    FX_CHECK_EQ(fx_surface_get(&t, -1, 0), 0);
    fx_rect none = {9, 9, 12, 12};
    FX_CHECK_EQ(fx_surface_sub(s, none).w, 0);

    /* MONO1 views start mid-byte */
    uint8_t bits[4] = {0};
    fx_surface m, v;
    fx_surface_init(&m, bits, 16, 2, 2, FX_FMT_MONO1);
    fx_rect rv = {5, 1, 16, 2};
    v = fx_surface_sub(m, rv);
    fx_span_fill(&v, 0, 0, 6, 1); /* pixels 5..10 of row 1 */
    FX_CHECK_EQ_HEX(bits[2], 0xE0);
    FX_CHECK_EQ_HEX(bits[3], 0x07);
    FX_CHECK_EQ(fx_surface_get_native(&v, 5, 0), 1);
    FX_CHECK_EQ(fx_surface_get_native(&v, 6, 0), 0);
}

FX_TEST(negative_and_padded_strides)
{
    uint16_t mem[4 * 10] = {0}; /* 4 rows, 10 u16 per row, 6 pixels used */
    fx_surface s;
    /* bottom-up: row 0 is the last row in memory */
    FX_CHECK_EQ(fx_surface_init(&s, mem + 3 * 10, 6, 4, -20, FX_FMT_RGB565), 0);
    fx_surface_fill(&s, (fx_rect){0, 0, 6, 1}, 0xFFFFFF);
    fx_surface_put(&s, 5, 3, 0xFF0000);
    for (int i = 0; i < 6; i++)
        FX_CHECK_EQ_HEX(mem[30 + i], 0xFFFF);
    FX_CHECK_EQ_HEX(mem[5], 0xF800);
    FX_CHECK_EQ(mem[6], 0); /* padding untouched */
    FX_CHECK_EQ(mem[36], 0);
}

FX_TEST(blit_converts_clips_and_handles_overlap)
{
    enum { W = 13, H = 9 };
    uint32_t src_mem[W * H];
    fx_surface src;
    fx_surface_init(&src, src_mem, W, H, W * 4, FX_FMT_ARGB8888);
    uint32_t s = 21;
    for (int i = 0; i < W * H; i++)
        src_mem[i] = fx_test_rand(&s);
    for (size_t f = 0; f < sizeof all / sizeof all[0]; f++) {
        uint32_t dmem[20 * 20];
        memset(dmem, 0, sizeof dmem);
        fx_surface d;
        fx_surface_init(&d, dmem, 20, 20, 80, all[f]);
        fx_blit(&d, -3, 15, &src); /* clipped left and bottom */
        for (int y = 0; y < 20; y++)
            for (int x = 0; x < 20; x++) {
                int sx = x + 3, sy = y - 15;
                uint32_t want = sx >= 0 && sx < W && sy >= 0 && sy < H
                                    ? fx_pack(all[f], src_mem[sy * W + sx])
                                    : 0;
                if (fx_surface_get_native(&d, x, y) != want) {
                    FX_CHECK_MSG(0, "%s blit at %d,%d", fx_format_get(all[f])->name, x, y);
                    y = 20;
                    break;
                }
            }
    }
    /* scrolling a surface onto itself, both directions */
    uint32_t mem[16 * 4], orig[16 * 4];
    for (int i = 0; i < 64; i++)
        orig[i] = mem[i] = (uint32_t)i;
    fx_surface a;
    fx_surface_init(&a, mem, 16, 4, 64, FX_FMT_XRGB8888);
    fx_surface view = fx_surface_sub(a, (fx_rect){0, 0, 16, 3});
    fx_blit(&a, 0, 1, &view); /* move rows 0..2 down by one */
    for (int y = 1; y < 4; y++)
        for (int x = 0; x < 16; x++)
            FX_CHECK_EQ(mem[y * 16 + x], orig[(y - 1) * 16 + x]);
    fx_surface right = fx_surface_sub(a, (fx_rect){1, 0, 16, 4});
    fx_blit(&a, 0, 0, &right); /* move columns left by one */
    FX_CHECK_EQ(mem[16 + 0], orig[1]);
    FX_CHECK_EQ(mem[16 + 14], orig[15]);
}

/* Long runs take another store path on some targets (rep stosq on x86-64
 * from 2 KiB, in 512 KiB pieces): every length around the switch and one
 * over a piece, at every alignment of the start within 8 bytes, fills
 * exactly its pixels with the exact pattern. */
FX_TEST(long_runs_fill_exactly_their_pixels_at_every_alignment)
{
    static const int32_t lens[] = {1, 7, 8, 9, 255, 511, 512, 513, 1023, 1024, 1025, 1026, 1027,
                                   1029, 2047, 2048, 2049, 3000, 4099,
                                   /* over 512 KiB: rep stosq in pieces */
                                   262147};
    static const fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_RGB565};
    enum { GUARD = 8, MAXN = 262147 };
    static uint8_t mem[(MAXN + 2 * GUARD + 8) * 4];
    for (size_t f = 0; f < 2; f++) {
        int bytes = fx_format_get(fmts[f])->bits_per_pixel / 8;
        uint32_t v = fmts[f] == FX_FMT_RGB565 ? 0xA5C3u : 0x12345678u;
        for (size_t l = 0; l < sizeof lens / sizeof lens[0]; l++)
            for (int off = 0; off < 8 / bytes; off++) {
                int32_t w = GUARD + off + lens[l] + GUARD;
                fx_surface s;
                memset(mem, 0xEE, sizeof mem);
                FX_CHECK_EQ(fx_surface_init(&s, mem, w, 1, w * bytes, fmts[f]), 0);
                fx_span_fill(&s, 0, GUARD + off, GUARD + off + lens[l], v);
                for (int32_t x = 0; x < w; x++) {
                    int in = x >= GUARD + off && x < GUARD + off + lens[l];
                    uint32_t want = in ? v : (bytes == 4 ? 0xEEEEEEEEu : 0xEEEEu);
                    if (fx_surface_get_native(&s, x, 0) != want) {
                        FX_CHECK_MSG(0, "%s run of %d at +%d: pixel %d is %x", fx_format_get(fmts[f])->name,
                                     lens[l], off, x, fx_surface_get_native(&s, x, 0));
                        break;
                    }
                }
                FX_CHECK_EQ(mem[(size_t)w * (size_t)bytes], 0xEE); /* nothing past the row */
            }
    }
}

/* Unpadded surfaces are blitted as one block: same pixels as the row by
 * row copy of padded ones, and overlapping scrolls in both directions. */
FX_TEST(unpadded_blits_match_padded_ones_and_scroll_both_ways)
{
    enum { W = 600, H = 7, PAD = 3 };
    static uint32_t a[W * H], b[(W + PAD) * H], orig[W * H];
    uint32_t seed = 5;
    for (int i = 0; i < W * H; i++)
        orig[i] = fx_test_rand(&seed);
    fx_surface src, dpad, dflat;
    fx_surface_init(&src, orig, W, H, W * 4, FX_FMT_XRGB8888);
    fx_surface_init(&dpad, b, W, H, (W + PAD) * 4, FX_FMT_XRGB8888);
    fx_surface_init(&dflat, a, W, H, W * 4, FX_FMT_XRGB8888);
    fx_blit(&dflat, 0, 2, &src);
    fx_blit(&dpad, 0, 2, &src);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (fx_surface_get_native(&dflat, x, y) != fx_surface_get_native(&dpad, x, y) ||
                (y >= 2 && a[y * W + x] != orig[(y - 2) * W + x])) {
                FX_CHECK_MSG(0, "pixel %d,%d", x, y);
                y = H;
                break;
            }
    for (int dir = -1; dir <= 1; dir += 2) {
        memcpy(a, orig, sizeof a);
        /* up by one (rows 1..H-1 to 0), then down by one (rows 0..H-2 to 1) */
        fx_rect from = dir < 0 ? (fx_rect){0, 1, W, H} : (fx_rect){0, 0, W, H - 1};
        fx_surface rows = fx_surface_sub(dflat, from);
        fx_blit(&dflat, 0, dir < 0 ? 0 : 1, &rows);
        for (int y = 0; y < H - 1; y++) {
            int dy = dir > 0 ? y + 1 : y, sy = dir > 0 ? y : y + 1;
            FX_CHECK_EQ(a[dy * W + 17], orig[sy * W + 17]);
            FX_CHECK_EQ(a[dy * W + W - 1], orig[sy * W + W - 1]);
        }
    }
}

/* Frames whose fill or copy touches 6 MiB or more (and three quarters of
 * the last-level cache, fx_internal.h fx_stream_min) take streaming stores
 * on x86-64: a clear of such a frame and a
 * blit of one, at every pixel alignment of the start within 16 bytes and
 * with lengths that leave a head, whole 64-byte blocks, 16-byte blocks and a
 * tail, write exactly their pixels and nothing around them; the overlapping
 * scroll of a frame this size still copies right (memmove, never streamed). */
FX_TEST(frame_sized_clears_and_blits_write_exactly_their_pixels)
{
    enum { GUARD = 64, MAXB = (7 << 20) + 4096 };
    static const fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_RGB565};
    uint8_t *mem = malloc(MAXB + 2 * GUARD), *src = malloc(MAXB);
    FX_CHECK(mem && src);
    if (!mem || !src) {
        free(mem);
        free(src);
        return;
    }
    uint32_t seed = 9;
    for (size_t i = 0; i < MAXB; i++)
        src[i] = (uint8_t)fx_test_rand(&seed);
    for (size_t f = 0; f < 2; f++) {
        int bytes = fx_format_get(fmts[f])->bits_per_pixel / 8;
        uint32_t v = fmts[f] == FX_FMT_RGB565 ? 0xA5C3u : 0x12345678u;
        /* width 1000: 4000- and 2000-byte rows; the heights make blocks over
         * 6 MiB (a fill) or 3 MiB (a copy) with tails of 16n + 2k bytes */
        const int32_t W = 1000, hs[] = {1601, 1799, 3147, 3600};
        for (int off = 0; off < 16 / bytes; off++)
            for (size_t k = 0; k < sizeof hs / sizeof hs[0]; k++) {
                int32_t H = hs[k] / (bytes == 4 ? 2 : 1) + (int32_t)k, w = W + (int32_t)k * 3;
                size_t n = (size_t)w * (size_t)H * (size_t)bytes;
                if (n + (size_t)off * (size_t)bytes > MAXB)
                    continue;
                uint8_t *p = mem + GUARD + off * bytes;
                fx_surface s, t;
                /* pass 1: the portable choice of a surface built field by
                 * field (fill_isa 0: the 16-byte streaming loop on x86-64) */
                for (int pass = 0; pass < 2; pass++) {
                memset(mem, 0xEE, MAXB + 2 * GUARD);
                FX_CHECK_EQ(fx_surface_init(&s, p, w, H, w * bytes, fmts[f]), 0);
                /* where this CPU's cache would keep such a frame cached,
                 * the built-in 6 MiB threshold still takes the streaming
                 * loops under test */
                FX_CHECK(s.stream_mib == 0 || s.stream_mib >= 6); /* never below the 6 MiB floor */
                s.stream_mib = 0;
                if (pass)
                    s.fill_isa = 0;
                fx_surface_fill(&s, fx_surface_rect(&s), fmts[f] == FX_FMT_RGB565 ? fx_unpack(fmts[f], v) : 0xFF000000u | v);
                size_t bad = 0;
                for (size_t i = 0; i < n && !bad; i += (size_t)bytes) {
                    uint32_t got = bytes == 4 ? (uint32_t)p[i] | (uint32_t)p[i + 1] << 8 |
                                                    (uint32_t)p[i + 2] << 16 | (uint32_t)p[i + 3] << 24
                                              : (uint32_t)p[i] | (uint32_t)p[i + 1] << 8;
                    if ((got & (bytes == 4 ? 0xFFFFFFu : 0xFFFFu)) != (v & (bytes == 4 ? 0xFFFFFFu : 0xFFFFu)))
                        bad = i + 1;
                }
                FX_CHECK_MSG(!bad, "%s fill %dx%d at +%d (pass %d): byte %zu", fx_format_get(fmts[f])->name, w, H, off, pass,
                             bad - 1);
                for (int i = 0; i < GUARD + off * bytes; i++)
                    FX_CHECK_EQ(mem[i], 0xEE);
                for (int i = 0; i < GUARD; i++)
                    FX_CHECK_EQ(p[n + (size_t)i], 0xEE);
                }
                /* the blit, the source at another alignment */
                memset(mem, 0xEE, MAXB + 2 * GUARD);
                FX_CHECK_EQ(fx_surface_init(&t, src + (size_t)(k & 1) * (size_t)bytes, w, H, w * bytes, fmts[f]), 0);
                fx_blit(&s, 0, 0, &t);
                FX_CHECK_MSG(!memcmp(p, t.pixels, n), "%s blit %dx%d at +%d", fx_format_get(fmts[f])->name, w, H, off);
                for (int i = 0; i < GUARD + off * bytes; i++)
                    FX_CHECK_EQ(mem[i], 0xEE);
                for (int i = 0; i < GUARD; i++)
                    FX_CHECK_EQ(p[n + (size_t)i], 0xEE);
            }
    }
    /* a 7 MB frame scrolled down by one row within itself */
    {
        int32_t w = 1000, H = 1800;
        size_t n = (size_t)w * (size_t)H * 4;
        memcpy(mem, src, n);
        fx_surface s;
        fx_surface_init(&s, mem, w, H, w * 4, FX_FMT_XRGB8888);
        fx_surface rows = fx_surface_sub(s, (fx_rect){0, 0, w, H - 1});
        fx_blit(&s, 0, 1, &rows);
        FX_CHECK(!memcmp(mem + (size_t)w * 4, src, n - (size_t)w * 4));
    }
    free(mem);
    free(src);
}
