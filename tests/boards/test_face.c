/* SPDX-License-Identifier: MIT */
/* Smooth text (fixel/face.h): shaping equals HarfBuzz's own output in five
 * scripts, visual order equals FriBiDi's, the pixels equal FreeType's
 * bitmap composited by a double-precision reference of mask.h's rule,
 * rotation turns glyphs, the cache keeps its bound, layout (wrap, align,
 * ellipsis, fit) and bad input (files, sizes, UTF-8, huge strings, missing
 * glyphs, features). Fonts: fonts-dejavu-core and fonts-freefont-ttf
 * (TEST_DEB_PKGS). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include <fribidi.h>
#include <hb-ft.h>
#include <hb.h>

#include "fixel/error.h"
#include "fixel/face.h"
#include "fx_test.h"

#define DEJAVU "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#define FREESERIF "/usr/share/fonts/truetype/freefont/FreeSerif.ttf"

static fx_face *open_file(const char *path, int32_t px)
{
    fx_face_opts o = {0};
    o.no_fallback = 1;
    fx_face *f = NULL;
    char err[256];
    int r = fx_face_open(path, px, &o, &f, err, sizeof err);
    FX_CHECK_MSG(r == 0, "%s: %s (install fonts-dejavu-core fonts-freefont-ttf)", path, err);
    return f;
}

/* HarfBuzz alone: the same font file and size, the whole string in one
 * buffer with guessed properties. */
static void hb_reference(const char *path, int32_t px, const char *s, const fx_glyph *g, int n)
{
    FT_Library lib;
    FT_Face ft;
    FX_CHECK(FT_Init_FreeType(&lib) == 0);
    FX_CHECK(FT_New_Face(lib, path, 0, &ft) == 0);
    FT_Set_Pixel_Sizes(ft, 0, (FT_UInt)px);
    hb_font_t *hf = hb_ft_font_create_referenced(ft);
    hb_ft_font_set_load_flags(hf, FT_LOAD_DEFAULT);
    hb_buffer_t *b = hb_buffer_create();
    hb_buffer_add_utf8(b, s, -1, 0, -1);
    hb_buffer_guess_segment_properties(b);
    hb_shape(hf, b, NULL, 0);
    unsigned m;
    hb_glyph_info_t *gi = hb_buffer_get_glyph_infos(b, &m);
    hb_glyph_position_t *gp = hb_buffer_get_glyph_positions(b, &m);
    FX_CHECK_MSG((int)m == n, "'%s': %d glyphs, HarfBuzz %u", s, n, m);
    int bad = 0;
    for (unsigned i = 0; i < m && (int)i < n; i++)
        if (gi[i].codepoint != g[i].id || gi[i].cluster != g[i].cluster || gp[i].x_advance != g[i].x_advance ||
            gp[i].y_advance != g[i].y_advance || gp[i].x_offset != g[i].x_offset ||
            gp[i].y_offset != g[i].y_offset)
            if (bad++ < 3)
                FX_CHECK_MSG(0, "'%s' glyph %u: fixel %u@%u adv %d off %d,%d; HarfBuzz %u@%u adv %d off %d,%d", s, i,
                             g[i].id, g[i].cluster, g[i].x_advance, g[i].x_offset, g[i].y_offset, gi[i].codepoint,
                             gi[i].cluster, gp[i].x_advance, gp[i].x_offset, gp[i].y_offset);
    hb_buffer_destroy(b);
    hb_font_destroy(hf);
    FT_Done_Face(ft);
    FT_Done_FreeType(lib);
}

FX_TEST(face_shaping_equals_harfbuzz_in_five_scripts)
{
    static const struct {
        const char *font, *text;
        int min_glyphs;
    } cases[] = {
        {DEJAVU, "Typography: AVA Wo fi 0123", 20},
        {DEJAVU, "\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7 \xd8\xa8\xd8\xa7\xd9\x84\xd8\xb9\xd8\xa7\xd9\x84\xd9\x85", 8},
        {DEJAVU, "\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d \xd7\xa2\xd7\x95\xd7\x9c\xd7\x9d", 8},
        {FREESERIF, "\xe0\xa4\xa8\xe0\xa4\xae\xe0\xa4\xb8\xe0\xa5\x8d\xe0\xa4\xa4\xe0\xa5\x87 "
                    "\xe0\xa4\xa6\xe0\xa5\x81\xe0\xa4\xa8\xe0\xa4\xbf\xe0\xa4\xaf\xe0\xa4\xbe", 6},
        {FREESERIF, "\xe0\xb8\xaa\xe0\xb8\xa7\xe0\xb8\xb1\xe0\xb8\xaa\xe0\xb8\x94\xe0\xb8\xb5"
                    "\xe0\xb8\x8a\xe0\xb8\xb2\xe0\xb8\xa7\xe0\xb9\x82\xe0\xb8\xa5\xe0\xb8\x81", 8},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        fx_face *f = open_file(cases[k].font, 23);
        if (!f)
            continue;
        const fx_glyph *g;
        int n = fx_face_shape(f, cases[k].text, strlen(cases[k].text), &g);
        FX_CHECK_MSG(n >= cases[k].min_glyphs, "case %zu: %d glyphs", k, n);
        for (int i = 0; i < n; i++)
            FX_CHECK_MSG(g[i].id != 0, "case %zu glyph %d is .notdef: the font lacks the script", k, i);
        hb_reference(cases[k].font, 23, cases[k].text, g, n);
        fx_face_close(f);
    }
}

FX_TEST(face_visual_order_equals_fribidi)
{
    static const char *const lines[] = {
        "abc \xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d 123 def",
        "\xd7\xa9\xd7\x9c\xd7\x95\xd7\x9d abc 45 \xd7\xa2\xd7\x95\xd7\x9c\xd7\x9d!",
        "(\xd7\x90[b]) x \xd7\x91 7.5%",
        "\xd7\x90\xd7\x91 \xe2\x80\xaexyz\xe2\x80\xac \xd7\x92",
    };
    fx_face *f = open_file(DEJAVU, 16);
    if (!f)
        return;
    for (size_t k = 0; k < sizeof lines / sizeof lines[0]; k++) {
        const char *s = lines[k];
        FriBidiChar u[128];
        FriBidiStrIndex n = fribidi_charset_to_unicode(FRIBIDI_CHAR_SET_UTF8, s, (FriBidiStrIndex)strlen(s), u);
        FriBidiStrIndex v2l[128];
        FriBidiCharType types[128];
        FriBidiBracketType br[128];
        FriBidiLevel lev[128];
        FriBidiParType dir = FRIBIDI_PAR_ON;
        fribidi_get_bidi_types(u, n, types);
        fribidi_get_bracket_types(u, n, types, br);
        FX_CHECK(fribidi_get_par_embedding_levels_ex(types, br, n, &dir, lev) > 0);
        for (FriBidiStrIndex i = 0; i < n; i++)
            v2l[i] = i;
        FX_CHECK(fribidi_reorder_line(FRIBIDI_FLAGS_DEFAULT, types, n, 0, dir, lev, NULL, v2l) > 0);
        /* Byte offset of each code point, to read fixel's clusters. */
        int at[128], bytes = 0;
        for (FriBidiStrIndex i = 0; i < n; i++) {
            at[i] = bytes;
            bytes += u[i] < 0x80 ? 1 : u[i] < 0x800 ? 2 : u[i] < 0x10000 ? 3 : 4;
        }
        const fx_glyph *g;
        int m = fx_face_shape(f, s, strlen(s), &g);
        /* Explicit embedding controls (RLO, PDF) make no glyph in FriBiDi's
         * order either; compare the code points that have glyphs. */
        int j = 0, bad = 0;
        for (FriBidiStrIndex i = 0; i < n; i++) {
            if (u[v2l[i]] == 0x202E || u[v2l[i]] == 0x202C) {
                if (j < m && g[j].cluster == (uint32_t)at[v2l[i]])
                    j++;
                continue;
            }
            if (j >= m || g[j].cluster != (uint32_t)at[v2l[i]])
                bad++;
            j++;
        }
        FX_CHECK_MSG(bad == 0 && j == m, "line %zu: %d code points out of FriBiDi's order (%d glyphs, %d cps)", k,
                     bad, m, (int)n);
    }
    fx_face_close(f);
}

/* ---- the compositing reference ---- */

static uint32_t dref_blend565(uint32_t dst, uint32_t col, uint32_t cov)
{
    double A = col >> 24, a = floor(A * cov / 255.0 + 0.5);
    if (a == 0)
        return dst;
    uint32_t r5 = dst >> 11, g6 = (dst >> 5) & 63, b5 = dst & 31;
    double d[3] = {r5 * 8 + r5 / 4, g6 * 4 + g6 / 16, b5 * 8 + b5 / 4};
    double s[3] = {(col >> 16) & 255, (col >> 8) & 255, col & 255};
    uint32_t o[3];
    for (int k = 0; k < 3; k++)
        o[k] = (uint32_t)floor((s[k] * a + d[k] * (255 - a)) / 255.0 + 0.5);
    return (o[0] >> 3) << 11 | (o[1] >> 2) << 5 | o[2] >> 3;
}

static uint32_t dref_blend8888(uint32_t dst, uint32_t col, uint32_t cov)
{
    double A = col >> 24, a = floor(A * cov / 255.0 + 0.5);
    if (a == 0)
        return dst;
    uint32_t out = 0;
    for (int sh = 0; sh < 24; sh += 8) {
        double s = (col >> sh) & 255, d = (dst >> sh) & 255;
        out |= (uint32_t)floor((s * a + d * (255 - a)) / 255.0 + 0.5) << sh;
    }
    return out;
}

FX_TEST(face_pixels_equal_freetype_bitmap_composited_by_double_reference)
{
    FT_Library lib;
    FT_Face ft;
    FX_CHECK(FT_Init_FreeType(&lib) == 0);
    if (FT_New_Face(lib, DEJAVU, 0, &ft)) {
        FX_CHECK_MSG(0, "%s missing", DEJAVU);
        return;
    }
    static const uint32_t chars[] = {'g', 'W', '@', 0xE9, 0x416};
    static const int sizes[] = {9, 17, 40};
    uint32_t seed = 99;
    for (size_t si = 0; si < 3; si++)
        for (size_t ci = 0; ci < 5; ci++)
            for (int fmt = 0; fmt < 2; fmt++) {
                FT_Set_Pixel_Sizes(ft, 0, (FT_UInt)sizes[si]);
                FX_CHECK(FT_Load_Char(ft, chars[ci], FT_LOAD_DEFAULT) == 0);
                FX_CHECK(FT_Render_Glyph(ft->glyph, FT_RENDER_MODE_NORMAL) == 0);
                FT_Bitmap *bm = &ft->glyph->bitmap;
                enum { W = 64, H = 64 };
                fx_format ff = fmt ? FX_FMT_RGB565 : FX_FMT_XRGB8888;
                int bpp = fmt ? 2 : 4;
                uint8_t *a = malloc(W * H * 4), *b = malloc(W * H * 4);
                for (int i = 0; i < W * H * bpp; i++)
                    a[i] = b[i] = (uint8_t)fx_test_rand(&seed);
                if (!fmt)
                    for (int i = 0; i < W * H; i++)
                        ((uint32_t *)(void *)a)[i] &= 0xFFFFFF, ((uint32_t *)(void *)b)[i] &= 0xFFFFFF;
                fx_surface s;
                fx_surface_init(&s, a, W, H, W * bpp, ff);
                fx_ctx c;
                fx_ctx_init(&c, &s);
                uint32_t col = fx_test_rand(&seed) | 0x80000000u;
                fx_ctx_set_color(&c, col);
                c.blend = FX_BLEND_OVER;
                fx_face *f = open_file(DEJAVU, sizes[si]);
                char u8[8];
                uint32_t cp = chars[ci];
                size_t ul = cp < 0x80 ? (u8[0] = (char)cp, 1)
                                      : (u8[0] = (char)(0xC0 | cp >> 6), u8[1] = (char)(0x80 | (cp & 63)), 2);
                const int ox = 12, oy = 44;
                FX_CHECK(fx_face_draw(f, &c, ox, oy, u8, ul, 0) > 0);
                fx_face_close(f);
                for (unsigned y = 0; y < bm->rows; y++)
                    for (unsigned x = 0; x < bm->width; x++) {
                        int px = ox + ft->glyph->bitmap_left + (int)x, py = oy - ft->glyph->bitmap_top + (int)y;
                        if (px < 0 || py < 0 || px >= W || py >= H)
                            continue;
                        uint32_t cov = bm->buffer[(int)y * bm->pitch + (int)x];
                        if (fmt) {
                            uint16_t *q = (uint16_t *)(void *)b + py * W + px;
                            *q = (uint16_t)dref_blend565(*q, col, cov);
                        } else {
                            uint32_t *q = (uint32_t *)(void *)b + py * W + px;
                            *q = dref_blend8888(*q, col, cov);
                        }
                    }
                int diff = 0;
                for (int i = 0; i < W * H * bpp; i++)
                    diff += a[i] != b[i];
                FX_CHECK_MSG(diff == 0, "U+%04X at %d px, %s: %d bytes differ", cp, sizes[si], fmt ? "RGB565" : "XRGB8888",
                             diff);
                free(a);
                free(b);
            }
    FT_Done_Face(ft);
    FT_Done_FreeType(lib);
}

FX_TEST(face_rotation_turns_the_glyphs_about_the_origin)
{
    fx_face *f = open_file(DEJAVU, 20);
    if (!f)
        return;
    enum { N = 120 };
    static uint32_t px[4][N * N];
    memset(px, 0, sizeof px);
    const int x = 60, y = 60;
    for (unsigned rot = 0; rot < 4; rot++) {
        fx_surface s;
        fx_surface_init(&s, (uint8_t *)px[rot], N, N, N * 4, FX_FMT_XRGB8888);
        fx_ctx c;
        fx_ctx_init(&c, &s);
        FX_CHECK(fx_face_draw(f, &c, x, y, "Rg7", 3, rot) > 0);
    }
    int lit = 0, bad = 0;
    for (int py = 0; py < N; py++)
        for (int pxx = 0; pxx < N; pxx++) {
            uint32_t v = px[0][py * N + pxx];
            lit += v != 0;
            int dx = pxx - x, dy = py - y;
            /* Pixel (dx, dy) of the upright text, turned clockwise. */
            int p90x = x - dy - 1, p90y = y + dx, p180x = x - dx - 1, p180y = y - dy - 1, p270x = x + dy,
                p270y = y - dx - 1;
            if (p90x < 0 || p90y < 0 || p90x >= N || p90y >= N || p180x < 0 || p180y < 0 || p180x >= N ||
                p180y >= N || p270x < 0 || p270y < 0 || p270x >= N || p270y >= N)
                continue;
            bad += px[1][p90y * N + p90x] != v;
            bad += px[2][p180y * N + p180x] != v;
            bad += px[3][p270y * N + p270x] != v;
        }
    FX_CHECK(lit > 100);
    FX_CHECK_EQ(bad, 0);
    fx_face_close(f);
}

FX_TEST(face_cache_keeps_its_bound_and_counts)
{
    fx_face_opts o = {0};
    o.no_fallback = 1;
    o.cache_bytes = 6000;
    fx_face *f = NULL;
    FX_CHECK(fx_face_open(DEJAVU, 30, &o, &f, NULL, 0) == 0);
    if (!f)
        return;
    fx_text_metrics m;
    const char *s = "The quick brown fox jumps over the lazy dog 0123456789";
    FX_CHECK(fx_face_measure(f, s, strlen(s), &m) == 0);
    fx_face_stats st;
    fx_face_cache_stats(f, &st);
    FX_CHECK(st.bytes <= 6000 && st.limit == 6000);
    FX_CHECK(st.misses > 20);
    FX_CHECK(st.evictions > 0);
    uint64_t miss0 = st.misses, hit0 = st.hits;
    FX_CHECK(fx_face_measure(f, "QQ", 2, &m) == 0);
    fx_face_cache_stats(f, &st);
    FX_CHECK_EQ(st.misses, miss0 + 1); /* 'Q' (not in s) once, then a hit */
    FX_CHECK_EQ(st.hits, hit0 + 1);
    fx_face_close(f);
    /* The default bound, a warm repeat: all hits. */
    f = open_file(DEJAVU, 14);
    FX_CHECK(fx_face_measure(f, s, strlen(s), &m) == 0);
    fx_face_cache_stats(f, &st);
    miss0 = st.misses;
    FX_CHECK_EQ(st.limit, FX_FACE_CACHE_DEFAULT);
    FX_CHECK(fx_face_measure(f, s, strlen(s), &m) == 0);
    fx_face_cache_stats(f, &st);
    FX_CHECK_EQ(st.misses, miss0);
    fx_face_close(f);
}

FX_TEST(face_layout_measure_wrap_align_ellipsis_fit)
{
    fx_face *f = open_file(DEJAVU, 16);
    if (!f)
        return;
    fx_text_metrics m;
    FX_CHECK(fx_face_measure(f, "Hello", 5, &m) == 0);
    FX_CHECK(m.advance > 30 && m.advance < 60);
    FX_CHECK(m.ascent > 10 && m.descent > 2 && m.line_height >= m.ascent + m.descent);
    FX_CHECK(m.ink.y0 < 0 && m.ink.y0 >= -m.ascent && m.ink.x1 <= m.advance + 1);
    const char *para = "one two three four five six seven eight nine ten eleven twelve";
    fx_textbox b = {{0, 0, 100, 1000}, FX_ALIGN_LEFT, 0, 0, 0};
    int32_t lines;
    int ov;
    FX_CHECK(fx_face_draw_box(f, NULL, &b, para, strlen(para), &lines, &ov) == 0);
    FX_CHECK(lines >= 4 && lines <= 8);
    FX_CHECK_EQ(ov, 0);
    /* Right-aligned: the ink of every line ends at the box's right edge. */
    enum { W = 140, H = 200 };
    static uint32_t px[W * H];
    memset(px, 0, sizeof px);
    fx_surface s;
    fx_surface_init(&s, (uint8_t *)px, W, H, W * 4, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    b = (fx_textbox){{10, 10, 130, 190}, FX_ALIGN_RIGHT, 0, 0, 0};
    FX_CHECK(fx_face_draw_box(f, &c, &b, para, strlen(para), &lines, &ov) == 0);
    int maxx = 0, minx = W;
    for (int i = 0; i < W * H; i++)
        if (px[i]) {
            maxx = i % W > maxx ? i % W : maxx;
            minx = i % W < minx ? i % W : minx;
        }
    FX_CHECK(maxx >= 125 && maxx < 131);
    FX_CHECK(minx >= 10);
    /* Two lines' height with ellipsis: overflow reported, last line ends in … */
    b = (fx_textbox){{0, 0, 100, 40}, FX_ALIGN_LEFT, 1, 0, 0};
    FX_CHECK(fx_face_draw_box(f, NULL, &b, para, strlen(para), &lines, &ov) == 0);
    FX_CHECK_EQ(ov, 1);
    FX_CHECK(lines >= 1 && lines <= 2);
    /* Fit: the size found fits, one pixel more does not. */
    b = (fx_textbox){{0, 0, 200, 60}, FX_ALIGN_CENTRE, 0, 0, 0};
    int32_t px_fit = fx_face_fit(f, &b, "17.9", 4, 4, 400);
    FX_CHECK(px_fit > 20 && px_fit < 80);
    FX_CHECK(fx_face_draw_box(f, NULL, &b, "17.9", 4, &lines, &ov) == 0 && ov == 0);
    FX_CHECK(fx_face_set_size(f, px_fit + 1) == 0);
    FX_CHECK(fx_face_draw_box(f, NULL, &b, "17.9", 4, &lines, &ov) == 0 && ov != 0);
    fx_face_close(f);
}

FX_TEST(face_features_by_name)
{
    fx_face *f = open_file(DEJAVU, 20);
    if (!f)
        return;
    const fx_glyph *g;
    int liga = fx_face_shape(f, "ffi", 3, &g);
    FX_CHECK(fx_face_set_features(f, "-liga") == 0);
    int noliga = fx_face_shape(f, "ffi", 3, &g);
    FX_CHECK_MSG(liga < noliga && noliga == 3, "ffi: %d glyphs with liga, %d without", liga, noliga);
    FX_CHECK(fx_face_set_features(f, "tnum, kern=0") == 0);
    FX_CHECK(fx_face_set_features(f, "t\x01num") == -FX_EINVAL);
    FX_CHECK(strstr(fx_face_error(f), "not an OpenType feature") != NULL);
    fx_face_close(f);
}

static const char *write_tmp(const char *name, const void *data, size_t n)
{
    static char path[4][256];
    static int k;
    char *p = path[k++ & 3];
    snprintf(p, 256, "/tmp/fixel-test-face-%d-%s", (int)getpid(), name);
    FILE *fp = fopen(p, "wb");
    if (fp) {
        fwrite(data, 1, n, fp);
        fclose(fp);
    }
    return p;
}

FX_TEST(face_bad_input_gives_clear_errors_and_replacement_glyphs)
{
    fx_face *f = NULL;
    char err[256];
    FX_CHECK(fx_face_open("/nonexistent/font.ttf", 12, NULL, &f, err, sizeof err) == -FX_ENOENT && !f);
    FX_CHECK(strstr(err, "/nonexistent/font.ttf") != NULL);
    /* Truncated and garbage files. */
    FILE *fp = fopen(DEJAVU, "rb");
    static uint8_t buf[4096];
    size_t got = fp ? fread(buf, 1, sizeof buf, fp) : 0;
    if (fp)
        fclose(fp);
    FX_CHECK(got == sizeof buf);
    static const size_t cuts[] = {0, 1, 12, 100, 1000, 4096};
    for (size_t i = 0; i < sizeof cuts / sizeof cuts[0]; i++) {
        const char *p = write_tmp("cut.ttf", buf, cuts[i]);
        int r = fx_face_open(p, 12, NULL, &f, err, sizeof err);
        FX_CHECK_MSG(r == -FX_EBADMSG && !f, "cut at %zu: %d", cuts[i], r);
        FX_CHECK(strstr(err, p) != NULL);
        fx_face_close(f);
        unlink(p);
    }
    uint32_t seed = 3;
    for (int i = 0; i < 16; i++) {
        uint8_t junk[2048];
        for (size_t k = 0; k < sizeof junk; k++)
            junk[k] = (uint8_t)fx_test_rand(&seed);
        if (i & 1)
            memcpy(junk, buf, 12); /* a plausible sfnt header over garbage */
        const char *p = write_tmp("junk.ttf", junk, sizeof junk);
        int r = fx_face_open(p, 12, NULL, &f, err, sizeof err);
        if (!r) { /* FreeType may accept a header; then drawing must still be safe */
            fx_text_metrics m;
            fx_face_measure(f, "abc", 3, &m);
            fx_face_close(f);
        } else
            FX_CHECK(strstr(err, p) != NULL);
        unlink(p);
    }
    /* Sizes. */
    static const int32_t bad_px[] = {0, -1, 100000, INT32_MIN};
    for (size_t i = 0; i < 4; i++) {
        FX_CHECK(fx_face_open(DEJAVU, bad_px[i], NULL, &f, err, sizeof err) == -FX_ERANGE && !f);
        FX_CHECK(strstr(err, "out of range") != NULL);
    }
    f = open_file(DEJAVU, 12);
    if (!f)
        return;
    FX_CHECK(fx_face_set_size(f, 100000) == -FX_ERANGE && fx_face_size(f) == 12);
    FX_CHECK(fx_face_set_size(f, 0) == -FX_ERANGE);
    /* Invalid UTF-8: each bad byte is one U+FFFD glyph. */
    const fx_glyph *g;
    int n = fx_face_shape(f, "a\xff\xc3(\xed\xa0\x80z", 8, &g);
    FX_CHECK_EQ(n, 8);
    if (n == 8) {
        FX_CHECK(g[1].id != 0 && g[1].id == g[2].id && g[1].id == g[4].id);
        FX_CHECK_EQ(g[1].cluster, 1);
        FX_CHECK_EQ(g[7].cluster, 7);
    }
    /* Invalid UTF-8 in a box: libunibreak 1.1's own UTF-8 reader asserts
     * on this (fuzz_face found it); fixel hands it decoded code points. */
    {
        static const char bad[] = "Hello,pppppppppppppppppppp\xd5\x01pppp pp\xff\xff\xef\xff\xff\xe2\x80";
        fx_textbox bb = {{0, 0, 60, 200}, FX_ALIGN_LEFT, 1, 0, 0};
        int32_t nl;
        int ovf;
        FX_CHECK(fx_face_draw_box(f, NULL, &bb, bad, sizeof bad - 1, &nl, &ovf) == 0 && nl >= 2);
    }
    /* A code point no font of the chain has: the .notdef box, not nothing. */
    n = fx_face_shape(f, "\xe4\xb8\xad", 3, &g);
    FX_CHECK(n == 1 && g[0].id == 0);
    fx_text_metrics m;
    FX_CHECK(fx_face_measure(f, "\xe4\xb8\xad", 3, &m) == 0 && m.advance > 0 && m.ink.x1 > m.ink.x0);
    /* 1 MB strings: measured, and laid out in a box in bounded time. */
    size_t big = 1u << 20;
    char *s = malloc(big);
    for (size_t i = 0; i < big; i++)
        s[i] = (i % 7 == 6) ? ' ' : (char)('a' + i % 26);
    clock_t t0 = clock();
    FX_CHECK(fx_face_measure(f, s, big, &m) == 0 && m.advance > 1000000);
    fx_textbox b = {{0, 0, 300, 200}, FX_ALIGN_LEFT, 1, 0, 0};
    int32_t lines;
    int ov;
    FX_CHECK(fx_face_draw_box(f, NULL, &b, s, big, &lines, &ov) == 0 && ov == 1 && lines > 3);
    memset(s, 'x', big); /* one enormous word */
    FX_CHECK(fx_face_draw_box(f, NULL, &b, s, big, &lines, &ov) == 0 && ov == 1 && lines > 3);
    memset(s, '\xff', big);
    FX_CHECK(fx_face_draw_box(f, NULL, &b, s, big, &lines, &ov) == 0 && lines > 3);
    double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
    FX_CHECK_MSG(secs < 20, "1 MB strings took %.1f s", secs);
    free(s);
    FX_CHECK(fx_face_shape(f, "x", FX_FACE_MAX_TEXT + 1u, &g) == -FX_E2BIG);
    FX_CHECK(fx_face_draw(f, NULL, 0, 0, "x", 1, 0) == -FX_EINVAL);
    fx_face_close(f);
    fx_face_shutdown(); /* fontconfig's configuration, for the leak checker */
}

FX_TEST(face_fontconfig_family_and_fallback_chain)
{
    fx_face *f = NULL;
    char err[256];
    fx_face_opts o = {0};
    o.weight = 700;
    FX_CHECK_MSG(fx_face_open("DejaVu Sans", 18, &o, &f, err, sizeof err) == 0, "%s", err);
    if (!f)
        return;
    FX_CHECK(strstr(fx_face_file(f, 0), "DejaVuSans-Bold") != NULL);
    /* Devanagari is not in DejaVu: a fallback of the chain draws it. */
    const fx_glyph *g;
    int n = fx_face_shape(f, "a\xe0\xa4\xa8", 4, &g);
    FX_CHECK(n == 2 && g[0].font == 0 && g[1].font > 0 && g[1].id != 0);
    fx_face_close(f);
    fx_face_shutdown();
}
