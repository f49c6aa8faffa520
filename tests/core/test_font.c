/* SPDX-License-Identifier: MIT */
/* Fonts and text: PSF1/PSF2 parsing (valid, every truncation, malformed
 * headers, random mutations; buffers are exact-size heap copies so ASan
 * sees any read past the end), unicode tables, glyph pixels at any scale
 * with background, the three text-clipping modes and UTF-8 handling. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/font.h"
#include "canvas.h"
#include "fx_test.h"

static void put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

/* A PSF2 font of n glyphs, w x h, glyph i row r = (i * 7 + r * 3) pattern,
 * with a unicode table when utab: glyph i <- 'A' + i (single chars), glyph 1
 * also U+20AC, glyph 2 a sequence "A" U+0301 only. */
static uint8_t *make_psf2(uint32_t n, uint32_t w, uint32_t h, int utab, size_t *len)
{
    uint32_t rb = (w + 7) / 8, gb = rb * h;
    size_t cap = 32 + (size_t)n * gb + 64 + (size_t)n * 8;
    uint8_t *d = calloc(cap, 1);
    put32(d, 0x864ab572u);
    put32(d + 4, 0);
    put32(d + 8, 32);
    put32(d + 12, utab ? 1 : 0);
    put32(d + 16, n);
    put32(d + 20, gb);
    put32(d + 24, h);
    put32(d + 28, w);
    for (uint32_t i = 0; i < n; i++)
        for (uint32_t k = 0; k < gb; k++)
            d[32 + i * gb + k] = (uint8_t)(i * 7 + k * 3 + 1);
    size_t p = 32 + (size_t)n * gb;
    if (utab) {
        for (uint32_t i = 0; i < n; i++) {
            if (i == 2) { /* only a combining sequence */
                d[p++] = 0xFE;
                d[p++] = 'Z';
                d[p++] = 0xCC;
                d[p++] = 0x81;
            } else {
                d[p++] = (uint8_t)('A' + i % 26);
            }
            if (i == 1) {
                d[p++] = 0xE2;
                d[p++] = 0x82;
                d[p++] = 0xAC;
            }
            d[p++] = 0xFF;
        }
    }
    *len = p;
    return d;
}

static uint8_t *make_psf1(int glyphs512, uint8_t h, int utab, size_t *len)
{
    uint32_t n = glyphs512 ? 512 : 256;
    size_t cap = 4 + (size_t)n * h + (size_t)n * 6;
    uint8_t *d = calloc(cap, 1);
    d[0] = 0x36;
    d[1] = 0x04;
    d[2] = (uint8_t)((glyphs512 ? 1 : 0) | (utab ? 2 : 0));
    d[3] = h;
    for (uint32_t i = 0; i < n * h; i++)
        d[4 + i] = (uint8_t)(i * 13 + 5);
    size_t p = 4 + (size_t)n * h;
    if (utab)
        for (uint32_t i = 0; i < n; i++) {
            /* glyph i <- U+0100 + i, and glyph 5 also <- 'x' */
            uint32_t u = 0x100 + i;
            d[p++] = (uint8_t)u;
            d[p++] = (uint8_t)(u >> 8);
            if (i == 5) {
                d[p++] = 'x';
                d[p++] = 0;
            }
            d[p++] = 0xFF;
            d[p++] = 0xFF;
        }
    *len = p;
    return d;
}

/* Load from an exact-size copy of data[0..len). */
static int load_exact(fx_font *f, const uint8_t *data, size_t len, uint8_t **copy)
{
    *copy = malloc(len ? len : 1);
    memcpy(*copy, data, len);
    return fx_font_load(f, *copy, len);
}

/* Touch everything a font lets a caller reach: lookups and every glyph row. */
static unsigned exercise(const fx_font *f)
{
    unsigned sum = 0;
    static const uint32_t cps[] = {0, 'A', 'x', '?', 0x7F, 0x80, 0xE9, 0x100, 0x105, 0x20AC,
                                   0x301, 0xFFFD, 0x10FFFF, 0xFFFFFFFFu};
    for (size_t i = 0; i < sizeof cps / sizeof cps[0]; i++) {
        uint32_t g = fx_font_glyph(f, cps[i]);
        if (g >= f->count)
            return 0xDEAD;
        for (uint32_t r = 0; r < f->height; r++)
            for (uint32_t k = 0; k < f->row_bytes; k++)
                sum += fx_font_row(f, g, r)[k];
    }
    return sum;
}

FX_TEST(font_psf2_parses_and_maps_unicode)
{
    size_t len;
    uint8_t *d = make_psf2(30, 12, 14, 1, &len), *c;
    fx_font f;
    FX_CHECK_EQ(load_exact(&f, d, len, &c), 0);
    FX_CHECK_EQ(f.count, 30);
    FX_CHECK_EQ(f.width, 12);
    FX_CHECK_EQ(f.height, 14);
    FX_CHECK_EQ(f.row_bytes, 2);
    FX_CHECK_EQ(fx_font_glyph(&f, 'A'), 0);
    FX_CHECK_EQ(fx_font_glyph(&f, 'B'), 1);
    FX_CHECK_EQ(fx_font_glyph(&f, 0x20AC), 1);
    FX_CHECK_EQ(fx_font_glyph(&f, 'D'), 3);
    /* 'Z' appears only inside glyph 2's sequence and as glyph 25's own */
    FX_CHECK_EQ(fx_font_glyph(&f, 'Z'), 25);
    /* no '?' in the table: the fallback is glyph 0 */
    FX_CHECK_EQ(fx_font_glyph(&f, 0x4E2D), 0);
    FX_CHECK(fx_font_row(&f, 3, 2) == c + 32 + 3 * 28 + 2 * 2);
    free(c);
    free(d);
    /* without a table, code point = glyph index */
    d = make_psf2(300, 9, 5, 0, &len);
    FX_CHECK_EQ(load_exact(&f, d, len, &c), 0);
    FX_CHECK_EQ(fx_font_glyph(&f, 299), 299);
    FX_CHECK_EQ(fx_font_glyph(&f, '?'), '?');
    FX_CHECK_EQ(fx_font_glyph(&f, 300), '?');
    free(c);
    free(d);
}

FX_TEST(font_psf1_parses_and_maps_unicode)
{
    size_t len;
    uint8_t *d = make_psf1(1, 16, 1, &len), *c;
    fx_font f;
    FX_CHECK_EQ(load_exact(&f, d, len, &c), 0);
    FX_CHECK_EQ(f.count, 512);
    FX_CHECK_EQ(f.width, 8);
    FX_CHECK_EQ(f.height, 16);
    FX_CHECK_EQ(fx_font_glyph(&f, 0x100), 0);
    FX_CHECK_EQ(fx_font_glyph(&f, 0x1FF), 255);
    FX_CHECK_EQ(fx_font_glyph(&f, 0x2FF), 511);
    FX_CHECK_EQ(fx_font_glyph(&f, 'x'), 5);
    FX_CHECK_EQ(fx_font_glyph(&f, 'y'), 0);
    free(c);
    free(d);
}

FX_TEST(font_shipped_test_fonts_load)
{
    static const char *paths[] = {"tests/data/fixel-8x10.psf", "tests/data/fixel-12x14.psf"};
    for (int i = 0; i < 2; i++) {
        FILE *fp = fopen(paths[i], "rb");
        FX_CHECK_MSG(fp != NULL, "%s", paths[i]);
        if (!fp)
            continue;
        uint8_t buf[8192];
        size_t n = fread(buf, 1, sizeof buf, fp);
        fclose(fp);
        fx_font f;
        uint8_t *c;
        FX_CHECK_EQ(load_exact(&f, buf, n, &c), 0);
        FX_CHECK_EQ(f.version, i + 1);
        FX_CHECK_EQ(f.height, i ? 14 : 10);
        /* 'e acute' shares 'e' in the PSF1 file; the euro has its own glyph in PSF2 */
        if (i == 0)
            FX_CHECK_EQ(fx_font_glyph(&f, 0xE9), fx_font_glyph(&f, 'e'));
        else
            FX_CHECK(fx_font_glyph(&f, 0x20AC) != fx_font_glyph(&f, '?'));
        free(c);
    }
}

FX_TEST(font_malformed_headers_give_clear_errors)
{
    size_t len;
    uint8_t *good = make_psf2(4, 8, 8, 1, &len), *c;
    uint8_t d[4096];
    fx_font f;
#define CASE(mutate, err)                                     \
    do {                                                      \
        memcpy(d, good, len);                                 \
        size_t l_ = len;                                      \
        mutate;                                               \
        FX_CHECK_EQ(load_exact(&f, d, l_, &c), err);          \
        free(c);                                              \
    } while (0)
    CASE((void)0, 0);
    CASE(d[0] ^= 1, -FX_EBADMSG);
    CASE(put32(d + 4, 1), -FX_ENOTSUP);
    CASE(put32(d + 8, 31), -FX_EBADMSG);
    CASE(put32(d + 8, 0xFFFFFFF0u), -FX_EOVERFLOW);
    CASE(put32(d + 16, 0), -FX_EBADMSG);
    CASE(put32(d + 16, 0xFFFFFFFFu), -FX_ERANGE);
    CASE(put32(d + 16, 65536), -FX_EOVERFLOW);
    CASE(put32(d + 16, 1000), -FX_EOVERFLOW);
    CASE(put32(d + 20, 9), -FX_EBADMSG);
    CASE(put32(d + 20, 0xFFFFFFFFu), -FX_EBADMSG);
    CASE(put32(d + 24, 0), -FX_EBADMSG);
    CASE(put32(d + 28, 0), -FX_EBADMSG);
    CASE((put32(d + 28, 0x80000000u), put32(d + 20, 0)), -FX_ERANGE);
    CASE((put32(d + 24, 257), put32(d + 20, 257)), -FX_ERANGE);
    CASE(l_ = 31, -FX_EBADMSG);
    CASE(l_ = 3, -FX_EBADMSG);
    CASE(l_ = 0, -FX_EBADMSG);
    CASE(l_ = 32 + 4 * 8 - 1, -FX_EOVERFLOW);
    free(good);
    good = make_psf1(0, 8, 0, &len);
    CASE((void)0, 0);
    CASE(l_ = 3, -FX_EBADMSG);
    CASE(l_ = 1, -FX_EBADMSG);
    CASE(d[2] = 0x08, -FX_ENOTSUP);
    CASE(d[3] = 0, -FX_EBADMSG);
    CASE(d[2] = 1, -FX_EOVERFLOW); /* claims 512 glyphs, holds 256 */
    CASE(l_ = len - 1, -FX_EOVERFLOW);
    FX_CHECK_EQ(fx_font_load(&f, NULL, 10), -FX_EINVAL);
    FX_CHECK_EQ(fx_font_load(NULL, good, len), -FX_EINVAL);
#undef CASE
    free(good);
}

/* Every prefix of valid fonts (with tables), and thousands of random byte
 * mutations: either a clean error or a font whose every reachable byte lies
 * inside the buffer (ASan would stop the run otherwise). */
FX_TEST(font_truncations_and_mutations_stay_in_bounds)
{
    size_t l1, l2;
    uint8_t *a = make_psf2(40, 10, 6, 1, &l1), *b = make_psf1(0, 6, 1, &l2), *c;
    int ok = 0, err = 0;
    for (int which = 0; which < 2; which++) {
        uint8_t *src = which ? b : a;
        size_t len = which ? l2 : l1;
        for (size_t n = 0; n <= len; n++) {
            fx_font f;
            int r = load_exact(&f, src, n, &c);
            if (r == 0) {
                ok++;
                FX_CHECK(exercise(&f) != 0xDEAD);
            } else {
                err++;
                FX_CHECK(r == -FX_EBADMSG || r == -FX_EOVERFLOW);
            }
            free(c);
        }
    }
    FX_CHECK(ok > 100 && err > 100);
    uint32_t seed = 1234;
    uint8_t *m = malloc(l1 > l2 ? l1 : l2);
    uint32_t w = 64, h = 48;
    uint32_t *px = calloc(w * h, 4);
    fx_surface s;
    fx_surface_init(&s, px, (int32_t)w, (int32_t)h, (int32_t)w * 4, FX_FMT_XRGB8888);
    for (int i = 0; i < 3000; i++) {
        int which = i & 1;
        size_t len = which ? l2 : l1;
        memcpy(m, which ? b : a, len);
        int k = 1 + (int)(fx_test_rand(&seed) % 6);
        while (k--) {
            size_t at = fx_test_rand(&seed) % (i % 3 ? len : 32);
            m[at] = (uint8_t)fx_test_rand(&seed);
        }
        size_t n = i % 5 == 0 ? fx_test_rand(&seed) % (len + 1) : len;
        fx_font f;
        int r = load_exact(&f, m, n, &c);
        if (r == 0) {
            FX_CHECK(exercise(&f) != 0xDEAD);
            fx_text_style st = {&f, 1, 0xFF000000u, 1, FX_TEXT_CLIP_PIXEL};
            fx_ctx ctx;
            fx_ctx_init(&ctx, &s);
            ctx.text_style = &st;
            fx_text(&ctx, -3, 2, "AB\xE2\x82\xAC\xFF\xC3x\nZ?");
        }
        free(c);
    }
    free(px);
    free(m);
    free(a);
    free(b);
}

/* ---- drawing ---- */

static uint32_t at(const canvas *k, int x, int y) { return k->mem[y * k->w + x] & 0xFFFFFF; }

FX_TEST(font_glyph_pixels_scale_and_background)
{
    canvas k = canvas_make(200, 120);
    const fx_font *f = fx_font_builtin();
    FX_CHECK_EQ(f->width, 6);
    FX_CHECK_EQ(f->height, 10);
    for (int scale = 1; scale <= 4; scale++) {
        memset(k.mem, 0, (size_t)k.w * k.h * 4);
        fx_text_style st = {NULL, scale, 0xFF102030u, 1, FX_TEXT_CLIP_PIXEL};
        fx_ctx c;
        fx_ctx_init(&c, &k.s);
        fx_ctx_set_color(&c, 0xFFFFC000u);
        c.text_style = &st;
        const char *str = "Hg@~";
        FX_CHECK_EQ(fx_text(&c, 3, 5, str), 4);
        int bad = 0;
        for (int i = 0; i < 4; i++) {
            uint32_t g = fx_font_glyph(f, (uint8_t)str[i]);
            for (int r = 0; r < 10; r++)
                for (int j = 0; j < 6; j++) {
                    int set = (fx_font_row(f, g, (uint32_t)r)[0] >> (7 - j)) & 1;
                    for (int dy = 0; dy < scale; dy++)
                        for (int dx = 0; dx < scale; dx++)
                            bad += at(&k, 3 + (i * 6 + j) * scale + dx, 5 + r * scale + dy) !=
                                   (set ? 0xFFC000u : 0x102030u);
                }
        }
        FX_CHECK_EQ(bad, 0);
        /* nothing outside the text box */
        int64_t w, h;
        fx_text_extent(&st, str, &w, &h);
        FX_CHECK_EQ(w, 24 * scale);
        FX_CHECK_EQ(h, 10 * scale);
        int outside = 0;
        for (int y = 0; y < k.h; y++)
            for (int x = 0; x < k.w; x++)
                if (x < 3 || y < 5 || x >= 3 + w || y >= 5 + h)
                    outside += at(&k, x, y) != 0;
        FX_CHECK_EQ(outside, 0);
    }
    /* the built-in font's glyphs differ from each other (all 95 drawn) */
    for (uint32_t a = 32; a < 127; a++)
        for (uint32_t b = a + 1; b < 127; b++)
            FX_CHECK_MSG(memcmp(fx_font_row(f, fx_font_glyph(f, a), 0), fx_font_row(f, fx_font_glyph(f, b), 0), 10) != 0 || a == ' ',
                         "'%c' and '%c' look the same", a, b);
    free(k.mem);
}

static void draw(canvas *k, fx_rect clip, int mode, int x, int y, const char *s, int *count)
{
    memset(k->mem, 0, (size_t)k->w * k->h * 4);
    fx_text_style st = {NULL, 2, 0, 0, (uint8_t)mode};
    fx_ctx c;
    fx_ctx_init(&c, &k->s);
    fx_ctx_set_clip(&c, clip);
    c.text_style = &st;
    *count = fx_text(&c, x, y, s);
}

FX_TEST(font_three_clipping_modes)
{
    canvas a = canvas_make(160, 80), b = canvas_make(160, 80);
    fx_rect full = {0, 0, 160, 80}, clip = {20, 10, 100, 60};
    int n, m;
    /* "ABCDEFGH" at scale 2: cells 12 x 20 from x = 10: A straddles x = 20,
     * cells end at 10 + 8*12 = 106 > 100 so H straddles too. */
    const char *s = "ABCDEFGH";
    /* pixel: the unclipped picture restricted to the clip */
    draw(&a, full, FX_TEXT_CLIP_PIXEL, 10, 15, s, &n);
    draw(&b, clip, FX_TEXT_CLIP_PIXEL, 10, 15, s, &m);
    FX_CHECK_EQ(n, 8);
    FX_CHECK_EQ(m, 8);
    int bad = 0, lit_in = 0;
    for (int y = 0; y < 80; y++)
        for (int x = 0; x < 160; x++) {
            int in = x >= 20 && x < 100 && y >= 10 && y < 60;
            bad += at(&b, x, y) != (in ? at(&a, x, y) : 0u);
            lit_in += in && at(&b, x, y);
        }
    FX_CHECK_EQ(bad, 0);
    FX_CHECK(lit_in > 50);
    /* string: all or nothing */
    draw(&b, clip, FX_TEXT_CLIP_STRING, 10, 15, s, &m);
    FX_CHECK_EQ(m, 0);
    for (int i = 0; i < 160 * 80; i++)
        FX_CHECK_EQ(b.mem[i], 0);
    draw(&b, clip, FX_TEXT_CLIP_STRING, 22, 15, "ABCDEF", &m); /* 72 wide: fits in 20..100 */
    draw(&a, full, FX_TEXT_CLIP_STRING, 22, 15, "ABCDEF", &n);
    FX_CHECK_EQ(m, 6);
    FX_CHECK(memcmp(a.mem, b.mem, 160 * 80 * 4) == 0);
    /* char: the cells inside the clip (B..G at x = 22..94) drawn whole,
     * A and H not at all */
    draw(&b, clip, FX_TEXT_CLIP_CHAR, 10, 15, s, &m);
    draw(&a, full, FX_TEXT_CLIP_PIXEL, 22, 15, "BCDEFG", &n);
    FX_CHECK_EQ(m, 6);
    FX_CHECK(memcmp(a.mem, b.mem, 160 * 80 * 4) == 0);
    /* a cell cut at the bottom is dropped in char mode */
    draw(&b, clip, FX_TEXT_CLIP_CHAR, 22, 45, "BC", &m);
    FX_CHECK_EQ(m, 0);
    free(a.mem);
    free(b.mem);
}

FX_TEST(font_utf8_newlines_and_far_positions)
{
    canvas a = canvas_make(100, 60), b = canvas_make(100, 60);
    int n, m;
    /* malformed UTF-8 shows the fallback glyph (the built-in box), one per bad byte */
    draw(&a, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_PIXEL, 0, 0, "\xC3(\xED\xA0\x80", &n);
    FX_CHECK_EQ(n, 5);
    fx_text_style st = {NULL, 1, 0, 0, FX_TEXT_CLIP_PIXEL};
    int64_t w, h;
    fx_text_extent(&st, "ab\ncde\n", &w, &h);
    FX_CHECK_EQ(w, 18);
    FX_CHECK_EQ(h, 30);
    fx_text_extent(&st, "\xE2\x82\xAC\xC3\xA9", &w, &h);
    FX_CHECK_EQ(w, 12);
    /* a second line starts under the first */
    draw(&a, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_PIXEL, 4, 4, "ab\ncd", &n);
    draw(&b, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_PIXEL, 4, 24, "cd", &m);
    FX_CHECK_EQ(n, 4);
    for (int y = 24; y < 60; y++)
        for (int x = 0; x < 100; x++)
            FX_CHECK_EQ(at(&a, x, y), at(&b, x, y));
    /* text far outside in every direction draws nothing and returns at once */
    draw(&a, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_PIXEL, INT32_MIN, INT32_MIN, "far away", &n);
    FX_CHECK_EQ(n, 0);
    draw(&a, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_PIXEL, INT32_MAX - 5, 10, "far away", &n);
    FX_CHECK_EQ(n, 0);
    draw(&a, (fx_rect){0, 0, 100, 60}, FX_TEXT_CLIP_CHAR, -100, 0, "0123456789ABCDEFGHIJ", &n);
    FX_CHECK_EQ(n, 7); /* whole cells k with -100 + 12k >= 0 and -100 + 12k + 12 <= 100: k = 9..15 */
    free(a.mem);
    free(b.mem);
}
