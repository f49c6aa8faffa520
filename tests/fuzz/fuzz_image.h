/* SPDX-License-Identifier: MIT */
/* The body of the image decoders' libFuzzer targets (issue #41), one per
 * format (fuzz_jpeg.c, fuzz_gif.c, fuzz_webp.c): the input, prefixed with
 * the format's magic bytes so the fuzzer spends its time inside that
 * decoder, goes through the magic-byte entry point and, for every input,
 * the animation API (frame 0 and the last frame, as fixel-draw's PATH#N and
 * the kiosk ask). Small limits keep each input fast; whatever is accepted
 * must have a size within them. */
#ifndef FIXEL_FUZZ_IMAGE_H
#define FIXEL_FUZZ_IMAGE_H
#include <stdlib.h>
#include <string.h>

#include "fixel/image.h"

static int fuzz_image(const char *magic, size_t m, const uint8_t *data, size_t size)
{
    static uint8_t buf[1 << 16];
    if (size > sizeof buf - m)
        size = sizeof buf - m;
    memcpy(buf, magic, m);
    memcpy(buf + m, data, size);
    fx_image_limits l;
    fx_image_limits_init(&l);
    l.max_side = 1024;
    l.max_pixels = 1 << 18;
    l.max_frames = 64;
    l.max_ms = 2000;
    uint8_t *rgb = NULL;
    int32_t w = 0, h = 0;
    char why[256];
    if (fx_image_decode_rgb(buf, size + m, &l, &rgb, &w, &h, why, sizeof why) == 0) {
        if (w < 1 || h < 1 || w > 1024 || h > 1024 || (size_t)w * (size_t)h > l.max_pixels)
            abort();
        volatile uint8_t sink = rgb[(size_t)w * (size_t)h * 3 - 1];
        (void)sink;
        free(rgb);
    }
    fx_anim *a;
    if (fx_anim_open(&a, buf, size + m, &l, why, sizeof why) == 0) {
        const uint8_t *px;
        int n = fx_anim_frames(a);
        if (n < 1 || n > 64)
            abort();
        fx_anim_frame(a, n - 1, &px, why, sizeof why);
        fx_anim_frame(a, 0, &px, why, sizeof why);
        fx_anim_close(a);
    }
    return 0;
}
#endif
