/* SPDX-License-Identifier: MIT */
/* fx_read_png_rgb on every PNG colour type and bit depth (issue #40: a
 * palette PNG with a tRNS chunk was refused as malformed). Each image is
 * written here with libpng from known samples, read back, and every pixel
 * compared with the expansion PNG defines: palette entries, grey scaled to
 * 0..255 (v * 255 / (2^depth - 1)), 16-bit samples to their high byte,
 * alpha and tRNS dropped with the colour kept. Interlaced and not. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fixel/error.h"
#include "fixel/memfb.h"
#include "fx_test.h"

#ifndef FX_NO_PNG
#include <png.h>

enum { W = 7, H = 5 };

typedef struct png_case {
    int ct, depth, interlace, trns;
} png_case;

static const png_color PAL[16] = {
    {0, 0, 0}, {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}, {12, 34, 56}, {200, 100, 50},
    {1, 2, 3}, {250, 251, 252}, {128, 128, 128}, {7, 77, 177}, {90, 80, 70}, {33, 66, 99}, {254, 1, 127},
    {60, 70, 80}, {99, 88, 77},
};

static int channels(int ct)
{
    return ct == PNG_COLOR_TYPE_RGB ? 3 : ct == PNG_COLOR_TYPE_RGB_ALPHA ? 4 : ct == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : 1;
}

/* Sample c of pixel i: the extremes first, then a spread of values. */
static unsigned sample(const png_case *k, int i, int c)
{
    unsigned max = (1u << k->depth) - 1;
    if (k->ct == PNG_COLOR_TYPE_PALETTE && max > 15)
        max = 15; /* the entries PAL defines */
    if (i == 0)
        return 0;
    if (i == 1)
        return max;
    return (unsigned)((i * 2654435761u + (unsigned)c * 40503u) >> 7) % (max + 1);
}

static uint8_t to8(unsigned v, int depth)
{
    return (uint8_t)(depth == 16 ? v >> 8 : depth == 8 ? v : v * 255 / ((1u << depth) - 1));
}

static int write_case(const char *path, const png_case *k)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, W, H, k->depth, k->ct, k->interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (k->ct == PNG_COLOR_TYPE_PALETTE)
        png_set_PLTE(png, info, PAL, 1 << (k->depth < 4 ? k->depth : 4));
    if (k->trns) {
        png_byte alpha[4] = {0, 128, 255, 7};
        png_color_16 tc = {0, (png_uint_16)sample(k, 1, 0), (png_uint_16)sample(k, 1, 1),
                           (png_uint_16)sample(k, 1, 2), (png_uint_16)sample(k, 1, 0)};
        if (k->ct == PNG_COLOR_TYPE_PALETTE)
            png_set_tRNS(png, info, alpha, 4 < (1 << k->depth) ? 4 : 1 << k->depth, NULL);
        else
            png_set_tRNS(png, info, NULL, 0, &tc);
    }
    png_write_info(png, info);
    int ch = channels(k->ct);
    png_bytep rows[H];
    static png_byte data[H][W * 8];
    for (int y = 0; y < H; y++) {
        memset(data[y], 0, sizeof data[y]);
        for (int x = 0; x < W; x++)
            for (int c = 0; c < ch; c++) {
                unsigned v = sample(k, y * W + x, c);
                size_t bit = ((size_t)x * (size_t)ch + (size_t)c) * (size_t)k->depth;
                if (k->depth == 16) {
                    data[y][bit / 8] = (png_byte)(v >> 8);
                    data[y][bit / 8 + 1] = (png_byte)v;
                } else {
                    data[y][bit / 8] |= (png_byte)(v << (8 - k->depth - bit % 8));
                }
            }
        rows[y] = data[y];
    }
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(f);
}

FX_TEST(png_reads_every_colour_type_and_depth)
{
    static const struct {
        int ct, depths[5];
    } kinds[] = {
        {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8, 0}}, {PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}},
        {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16, 0}}, {PNG_COLOR_TYPE_RGB, {8, 16, 0}},
        {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16, 0}},
    };
    char path[64];
    snprintf(path, sizeof path, "/tmp/fx_test_png_%d.png", (int)getpid());
    int cases = 0;
    for (size_t t = 0; t < sizeof kinds / sizeof kinds[0]; t++)
        for (int d = 0; d < 5 && kinds[t].depths[d]; d++)
            for (int il = 0; il < 2; il++)
                for (int tr = 0; tr < 2; tr++) {
                    png_case k = {kinds[t].ct, kinds[t].depths[d], il, tr};
                    if (tr && (k.ct & PNG_COLOR_MASK_ALPHA))
                        continue; /* tRNS is not allowed with an alpha channel */
                    FX_CHECK_EQ(write_case(path, &k), 0);
                    uint8_t *rgb = NULL;
                    int32_t w = 0, h = 0;
                    int r = fx_read_png_rgb(path, &rgb, &w, &h);
                    FX_CHECK_MSG(r == 0 && w == W && h == H, "colour type %d depth %d interlace %d tRNS %d: %d",
                                 k.ct, k.depth, il, tr, r);
                    cases++;
                    if (r != 0)
                        continue;
                    int bad = 0;
                    for (int i = 0; i < W * H && !bad; i++) {
                        uint8_t want[3];
                        if (k.ct == PNG_COLOR_TYPE_PALETTE) {
                            png_color p = PAL[sample(&k, i, 0)];
                            want[0] = p.red, want[1] = p.green, want[2] = p.blue;
                        } else if (k.ct & PNG_COLOR_MASK_COLOR) {
                            for (int c = 0; c < 3; c++)
                                want[c] = to8(sample(&k, i, c), k.depth);
                        } else {
                            want[0] = want[1] = want[2] = to8(sample(&k, i, 0), k.depth);
                        }
                        bad = memcmp(rgb + 3 * i, want, 3) != 0;
                        FX_CHECK_MSG(!bad, "colour type %d depth %d interlace %d tRNS %d pixel %d: %d,%d,%d want %d,%d,%d",
                                     k.ct, k.depth, il, tr, i, rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2], want[0],
                                     want[1], want[2]);
                    }
                    free(rgb);
                }
    FX_CHECK_EQ(cases, 2 * 2 * (4 + 5 + 2) + 2 * (2 + 2));
    unlink(path);
}
#endif
