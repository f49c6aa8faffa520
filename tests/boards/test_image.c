/* SPDX-License-Identifier: MIT */
/* boards/image/ (issue #41): JPEG, GIF and WebP written here by their own
 * encoders (libjpeg, giflib's EGif, libwebp) and read back through the
 * magic-byte dispatch; exact pixels for lossless WebP and GIF, JPEG equal
 * to libjpeg's own decode of the same bytes; GIF frames composited with
 * each disposal method, delays and loop count; hostile files (every
 * truncation, 65535-pixel sides, 16384x16384 WebP, 10,000 frames) refused
 * with the limit named. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/image.h"
#include "fx_test.h"

#if !defined(FX_NO_JPEG) && !defined(FX_NO_GIF) && !defined(FX_NO_WEBP)
#include <setjmp.h>
#include <stdio.h>
#include <gif_lib.h>
#include <jpeglib.h>
#include <webp/encode.h>

/* ---- JPEG ---- */
static uint8_t *jpeg_encode(const uint8_t *rgb, int w, int h, int progressive, unsigned long *len)
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr e;
    c.err = jpeg_std_error(&e);
    jpeg_create_compress(&c);
    uint8_t *out = NULL;
    *len = 0;
    jpeg_mem_dest(&c, &out, len);
    c.image_width = (JDIMENSION)w;
    c.image_height = (JDIMENSION)h;
    c.input_components = 3;
    c.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 85, TRUE);
    if (progressive)
        jpeg_simple_progression(&c);
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = (JSAMPROW)(rgb + (size_t)c.next_scanline * (size_t)w * 3);
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    return out;
}

/* libjpeg's own decode with its defaults: the reference */
static uint8_t *jpeg_reference(const uint8_t *data, unsigned long len, int *w, int *h)
{
    struct jpeg_decompress_struct d;
    struct jpeg_error_mgr e;
    d.err = jpeg_std_error(&e);
    jpeg_create_decompress(&d);
    jpeg_mem_src(&d, data, len);
    jpeg_read_header(&d, TRUE);
    d.out_color_space = JCS_RGB;
    jpeg_start_decompress(&d);
    *w = (int)d.output_width, *h = (int)d.output_height;
    uint8_t *buf = malloc((size_t)*w * (size_t)*h * 3);
    while (d.output_scanline < d.output_height) {
        JSAMPROW row = buf + (size_t)d.output_scanline * (size_t)*w * 3;
        jpeg_read_scanlines(&d, &row, 1);
    }
    jpeg_finish_decompress(&d);
    jpeg_destroy_decompress(&d);
    return buf;
}

static uint8_t *test_picture(int w, int h)
{
    uint8_t *p = malloc((size_t)w * (size_t)h * 3);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t *q = p + ((size_t)y * (size_t)w + (size_t)x) * 3;
            q[0] = (uint8_t)(x * 255 / (w - 1)), q[1] = (uint8_t)(y * 255 / (h - 1)), q[2] = (uint8_t)((x ^ y) * 8);
        }
    return p;
}

FX_TEST(image_jpeg_matches_libjpeg)
{
    for (int prog = 0; prog < 2; prog++) {
        uint8_t *src = test_picture(37, 21);
        unsigned long len;
        uint8_t *jpg = jpeg_encode(src, 37, 21, prog, &len);
        int rw, rh;
        uint8_t *ref = jpeg_reference(jpg, len, &rw, &rh);
        uint8_t *got = NULL;
        int32_t w = 0, h = 0;
        char why[200] = "";
        int r = fx_image_decode_rgb(jpg, len, NULL, &got, &w, &h, why, sizeof why);
        FX_CHECK_MSG(r == 0, "progressive %d: %d %s", prog, r, why);
        FX_CHECK_EQ(w, 37);
        FX_CHECK_EQ(h, 21);
        FX_CHECK(r == 0 && !memcmp(got, ref, (size_t)37 * 21 * 3));
        FX_CHECK(r == 0 && memcmp(got, src, (size_t)37 * 21 * 3) != 0); /* lossy: the reference is what counts */
        free(got);
        /* every truncation refused, never a crash */
        int accepted = 0;
        for (unsigned long cut = 0; cut < len; cut += 7) {
            got = NULL;
            r = fx_image_decode_rgb(jpg, cut, NULL, &got, &w, &h, why, sizeof why);
            accepted += r == 0;
            free(got);
        }
        FX_CHECK_EQ(accepted, 0);
        free(ref), free(src), free(jpg);
    }
}

FX_TEST(image_jpeg_huge_refused)
{
    uint8_t *src = test_picture(8, 8);
    unsigned long len;
    uint8_t *jpg = jpeg_encode(src, 8, 8, 0, &len);
    int patched = 0;
    for (unsigned long i = 0; i + 8 < len; i++)
        if (jpg[i] == 0xFF && jpg[i + 1] == 0xC0) {
            jpg[i + 5] = 0xFF, jpg[i + 6] = 0xDC, jpg[i + 7] = 0xFF, jpg[i + 8] = 0xDC; /* 65500 x 65500 */
            patched = 1;
            break;
        }
    FX_CHECK(patched);
    uint8_t *got = NULL;
    int32_t w, h;
    char why[200] = "";
    int r = fx_image_decode_rgb(jpg, len, NULL, &got, &w, &h, why, sizeof why);
    FX_CHECK_EQ(r, -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "JPEG") && strstr(why, "max_side"), "%s", why);
    free(src), free(jpg), free(got);
}

/* ---- GIF ---- */
typedef struct gbuf {
    uint8_t *p;
    size_t n, cap;
} gbuf;

static int gwrite(GifFileType *g, const GifByteType *d, int n)
{
    gbuf *b = g->UserData;
    if (b->n + (size_t)n > b->cap) {
        b->cap = (b->n + (size_t)n) * 2;
        b->p = realloc(b->p, b->cap);
    }
    memcpy(b->p + b->n, d, (size_t)n);
    b->n += (size_t)n;
    return n;
}

static const GifColorType pal[8] = {{0, 0, 0}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255},
                                    {9, 9, 9}, {9, 9, 9}, {9, 9, 9}};

static GifFileType *gif_begin(gbuf *b, int w, int h, int loop)
{
    int err;
    GifFileType *g = EGifOpen(b, gwrite, &err);
    EGifSetGifVersion(g, true);
    ColorMapObject *cm = GifMakeMapObject(8, pal);
    EGifPutScreenDesc(g, w, h, 8, 0, cm);
    GifFreeMapObject(cm);
    if (loop >= 0) {
        uint8_t nb[3] = {1, (uint8_t)loop, (uint8_t)(loop >> 8)};
        EGifPutExtensionLeader(g, APPLICATION_EXT_FUNC_CODE);
        EGifPutExtensionBlock(g, 11, "NETSCAPE2.0");
        EGifPutExtensionBlock(g, 3, nb);
        EGifPutExtensionTrailer(g);
    }
    return g;
}

static void gif_frame(GifFileType *g, int x, int y, int w, int h, const uint8_t *idx, int delay, int disposal,
                      int transparent)
{
    GraphicsControlBlock gcb = {disposal, false, delay, transparent};
    GifByteType ext[4];
    size_t n = EGifGCBToExtension(&gcb, ext);
    EGifPutExtension(g, GRAPHICS_EXT_FUNC_CODE, (int)n, ext);
    EGifPutImageDesc(g, x, y, w, h, false, NULL);
    for (int r = 0; r < h; r++)
        EGifPutLine(g, (GifPixelType *)(idx + r * w), w);
}

static void gif_end(GifFileType *g)
{
    int err;
    EGifCloseFile(g, &err);
}

/* 4x4: red; a green 2x2 with one transparent pixel, disposal "previous";
 * a blue pixel at 0,0 with disposal "background"; a white pixel at 3,3. */
static gbuf gif_anim(void)
{
    gbuf b = {0};
    GifFileType *g = gif_begin(&b, 4, 4, 0);
    uint8_t red[16], green[4] = {2, 2, 2, 4}, blue[1] = {3}, white[1] = {4};
    memset(red, 1, sizeof red);
    gif_frame(g, 0, 0, 4, 4, red, 5, DISPOSE_DO_NOT, NO_TRANSPARENT_COLOR);
    gif_frame(g, 1, 1, 2, 2, green, 20, DISPOSE_PREVIOUS, 4);
    gif_frame(g, 0, 0, 1, 1, blue, 0, DISPOSE_BACKGROUND, NO_TRANSPARENT_COLOR);
    gif_frame(g, 3, 3, 1, 1, white, 7, DISPOSE_DO_NOT, NO_TRANSPARENT_COLOR);
    gif_end(g);
    return b;
}

static int px_is(const uint8_t *rgb, int x, int y, int r, int g, int b)
{
    const uint8_t *p = rgb + (y * 4 + x) * 3;
    return p[0] == r && p[1] == g && p[2] == b;
}

static int expect(const uint8_t *rgb, int frame)
{
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            int r = 255, g = 0, b = 0; /* red */
            if (frame == 1 && x >= 1 && x <= 2 && y >= 1 && y <= 2 && !(x == 2 && y == 2))
                r = 0, g = 255;
            if (frame == 2 && x == 0 && y == 0)
                r = 0, b = 255;
            if (frame == 3 && x == 0 && y == 0)
                r = 0; /* disposed to the background: black */
            if (frame == 3 && x == 3 && y == 3)
                r = g = b = 255;
            if (!px_is(rgb, x, y, r, g, b))
                return 0;
        }
    return 1;
}

FX_TEST(image_gif_frames_disposal_timing)
{
    gbuf b = gif_anim();
    fx_anim *a;
    char why[200] = "";
    int r = fx_anim_open(&a, b.p, b.n, NULL, why, sizeof why);
    FX_CHECK_MSG(r == 0, "%d %s", r, why);
    if (r) {
        free(b.p);
        return;
    }
    FX_CHECK_EQ(fx_anim_width(a), 4);
    FX_CHECK_EQ(fx_anim_frames(a), 4);
    FX_CHECK_EQ(fx_anim_loops(a), 0);
    FX_CHECK_EQ(fx_anim_delay_ms(a, 0), 50);
    FX_CHECK_EQ(fx_anim_delay_ms(a, 1), 200);
    FX_CHECK_EQ(fx_anim_delay_ms(a, 2), 100); /* 0 plays at 100 ms */
    FX_CHECK_EQ(fx_anim_delay_ms(a, 3), 70);
    /* in order, then backwards (restarts), then skipping */
    static const int order[] = {0, 1, 2, 3, 0, 3, 1, 1, 2};
    for (size_t i = 0; i < sizeof order / sizeof order[0]; i++) {
        const uint8_t *px;
        r = fx_anim_frame(a, order[i], &px, why, sizeof why);
        FX_CHECK_MSG(r == 0 && expect(px, order[i]), "frame %d: %d %s", order[i], r, why);
    }
    const uint8_t *px;
    FX_CHECK_EQ(fx_anim_frame(a, 4, &px, why, sizeof why), -FX_ERANGE);
    fx_anim_close(a);
    /* the still entry point gives frame 0 */
    uint8_t *rgb = NULL;
    int32_t w, h;
    FX_CHECK_EQ(fx_image_decode_rgb(b.p, b.n, NULL, &rgb, &w, &h, why, sizeof why), 0);
    FX_CHECK(rgb && expect(rgb, 0));
    free(rgb);
    /* every truncation: refused or (cut after a frame's end) fewer frames; never a crash */
    for (size_t cut = 0; cut < b.n; cut++) {
        r = fx_anim_open(&a, b.p, cut, NULL, why, sizeof why);
        FX_CHECK_MSG(r < 0, "cut at %zu accepted", cut);
        if (r == 0)
            fx_anim_close(a);
    }
    free(b.p);
}

FX_TEST(image_gif_hostile)
{
    char why[200] = "";
    fx_anim *a = NULL;
    /* 65535 x 65535 */
    gbuf b = {0};
    GifFileType *g = gif_begin(&b, 65535, 65535, -1);
    uint8_t one = 1;
    gif_frame(g, 0, 0, 1, 1, &one, 0, 0, NO_TRANSPARENT_COLOR);
    gif_end(g);
    FX_CHECK_EQ(fx_anim_open(&a, b.p, b.n, NULL, why, sizeof why), -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "65535x65535") && strstr(why, "max_side"), "%s", why);
    free(b.p);
    /* 2,001 frames of one pixel each: one past the default limit (giflib
     * grows its frame array one realloc a frame, quadratic under ASan: 10,000
     * frames took 18 s of the sanitized unit run) */
    memset(&b, 0, sizeof b);
    g = gif_begin(&b, 1, 1, 0);
    for (int i = 0; i < 2001; i++)
        gif_frame(g, 0, 0, 1, 1, &one, 1, 0, NO_TRANSPARENT_COLOR);
    gif_end(g);
    FX_CHECK_EQ(fx_anim_open(&a, b.p, b.n, NULL, why, sizeof why), -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "2000 frames") && strstr(why, "max_frames"), "%s", why);
    fx_image_limits l;
    fx_image_limits_init(&l);
    l.max_frames = 2001; /* the documented way to allow it */
    FX_CHECK_EQ(fx_anim_open(&a, b.p, b.n, &l, why, sizeof why), 0);
    if (a) {
        FX_CHECK_EQ(fx_anim_frames(a), 2001);
        const uint8_t *px;
        FX_CHECK_EQ(fx_anim_frame(a, 2000, &px, why, sizeof why), 0);
        FX_CHECK_EQ(fx_anim_frame(a, 2001, &px, why, sizeof why), -FX_ERANGE);
        fx_anim_close(a);
    }
    free(b.p);
    /* a frame larger than max_pixels: the limit named */
    memset(&b, 0, sizeof b);
    g = gif_begin(&b, 4, 4, -1);
    uint8_t red[16];
    memset(red, 1, sizeof red);
    gif_frame(g, 0, 0, 4, 4, red, 0, 0, NO_TRANSPARENT_COLOR);
    gif_end(g);
    l.max_pixels = 15;
    uint8_t *rgb = NULL;
    int32_t w, h;
    FX_CHECK_EQ(fx_image_decode_rgb(b.p, b.n, &l, &rgb, &w, &h, why, sizeof why), -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "max_pixels"), "%s", why);
    free(rgb);
    free(b.p);
}

/* ---- WebP ---- */
FX_TEST(image_webp_lossless_exact)
{
    uint8_t *src = test_picture(23, 9), *webp = NULL;
    size_t len = WebPEncodeLosslessRGB(src, 23, 9, 23 * 3, &webp);
    FX_CHECK(len > 0);
    uint8_t *got = NULL;
    int32_t w = 0, h = 0;
    char why[200] = "";
    int r = fx_image_decode_rgb(webp, len, NULL, &got, &w, &h, why, sizeof why);
    FX_CHECK_MSG(r == 0, "%d %s", r, why);
    FX_CHECK(r == 0 && w == 23 && h == 9 && !memcmp(got, src, (size_t)23 * 9 * 3));
    free(got);
    int accepted = 0;
    for (size_t cut = 0; cut < len; cut++) {
        got = NULL;
        accepted += fx_image_decode_rgb(webp, cut, NULL, &got, &w, &h, why, sizeof why) == 0;
        free(got);
    }
    FX_CHECK_EQ(accepted, 0);
    /* the VP8L header's sizes at their largest: 16384 x 16384 */
    FX_CHECK(len > 25 && !memcmp(webp + 12, "VP8L", 4));
    webp[21] = 0xFF, webp[22] = 0xFF, webp[23] = 0xFF, webp[24] |= 0x0F;
    r = fx_image_decode_rgb(webp, len, NULL, &got, &w, &h, why, sizeof why);
    FX_CHECK_EQ(r, -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "WebP") && strstr(why, "16384x16384"), "%s", why);
    WebPFree(webp);
    free(src);
}

#endif

FX_TEST(image_sniff_and_unknown)
{
    FX_CHECK_EQ(fx_image_sniff((const uint8_t *)"GIF89a", 6), FX_IMAGE_GIF);
    FX_CHECK_EQ(fx_image_sniff((const uint8_t *)"\xff\xd8\xff\xe0", 4), FX_IMAGE_JPEG);
    FX_CHECK_EQ(fx_image_sniff((const uint8_t *)"RIFF\1\0\0\0WEBPVP8L", 16), FX_IMAGE_WEBP);
    FX_CHECK_EQ(fx_image_sniff((const uint8_t *)"RIFF\1\0\0\0WAVE", 12), FX_IMAGE_UNKNOWN);
    uint8_t *rgb = NULL;
    int32_t w, h;
    char why[200] = "";
    FX_CHECK_EQ(fx_image_decode_rgb((const uint8_t *)"BM whatever", 11, NULL, &rgb, &w, &h, why, sizeof why),
                -FX_ENOTSUP);
    FX_CHECK_MSG(strstr(why, "JPEG") != NULL, "%s", why);
    fx_image_limits l;
    fx_image_limits_init(&l);
    l.max_bytes = 4;
    FX_CHECK_EQ(fx_image_decode_rgb((const uint8_t *)"GIF89a", 6, &l, &rgb, &w, &h, why, sizeof why), -FX_EFBIG);
    FX_CHECK_MSG(strstr(why, "max_bytes") != NULL, "%s", why);
}
