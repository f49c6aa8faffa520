/* SPDX-License-Identifier: MIT */
/* The image entry point: sniff the first bytes, hand the buffer to the
 * decoder for that format, with the caller's limits. PNG and PPM go to
 * boards/memory/memfb.c's readers, unchanged. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/memfb.h"
#include "image_int.h"

void fx_image_limits_init(fx_image_limits *l)
{
    l->max_side = FX_IMAGE_DEFAULT_MAX_SIDE;
    l->max_pixels = FX_IMAGE_DEFAULT_MAX_PIXELS;
    l->max_bytes = FX_IMAGE_DEFAULT_MAX_BYTES;
    l->max_frames = FX_IMAGE_DEFAULT_MAX_FRAMES;
    l->max_ms = FX_IMAGE_DEFAULT_MAX_MS;
}

void fx_image_why(char *why, size_t n, const char *fmt, ...)
{
    if (!why || !n)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, n, fmt, ap);
    va_end(ap);
}

int fx_image_check_size(const char *fmt, uint64_t w, uint64_t h, const fx_image_limits *l, char *why, size_t n)
{
    if (w == 0 || h == 0) {
        fx_image_why(why, n, "%s: empty image (%llux%llu)", fmt, (unsigned long long)w, (unsigned long long)h);
        return -FX_EBADMSG;
    }
    if (w > l->max_side || h > l->max_side) {
        fx_image_why(why, n, "%s: %llux%llu pixels, a side over the limit of %u (fx_image_limits.max_side)", fmt,
                     (unsigned long long)w, (unsigned long long)h, l->max_side);
        return -FX_EFBIG;
    }
    if (w * h > l->max_pixels) {
        fx_image_why(why, n, "%s: %llux%llu pixels, over the limit of %zu (fx_image_limits.max_pixels)", fmt,
                     (unsigned long long)w, (unsigned long long)h, l->max_pixels);
        return -FX_EFBIG;
    }
    return 0;
}

uint32_t fx_image_elapsed_ms(const struct timespec *start)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    int64_t ms = (int64_t)(t.tv_sec - start->tv_sec) * 1000 + (t.tv_nsec - start->tv_nsec) / 1000000;
    return ms < 0 ? 0 : ms > UINT32_MAX ? UINT32_MAX : (uint32_t)ms;
}

fx_image_kind fx_image_sniff(const uint8_t *p, size_t n)
{
    if (n >= 8 && !memcmp(p, "\x89PNG\r\n\x1a\n", 8))
        return FX_IMAGE_PNG;
    if (n >= 3 && p[0] == 0xFF && p[1] == 0xD8 && p[2] == 0xFF)
        return FX_IMAGE_JPEG;
    if (n >= 6 && (!memcmp(p, "GIF87a", 6) || !memcmp(p, "GIF89a", 6)))
        return FX_IMAGE_GIF;
    if (n >= 12 && !memcmp(p, "RIFF", 4) && !memcmp(p + 8, "WEBP", 4))
        return FX_IMAGE_WEBP;
    if (n >= 2 && p[0] == 'P' && p[1] == '6')
        return FX_IMAGE_PPM;
    return FX_IMAGE_UNKNOWN;
}

const char *fx_image_kind_name(fx_image_kind k)
{
    static const char *const names[] = {"unknown", "PNG", "PPM", "JPEG", "GIF", "WebP"};
    return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "unknown";
}

/* PNG and PPM: memfb.c reads them from a FILE; a memory stream hands it
 * the buffer without a temporary file. */
static int decode_memfb(fx_image_kind k, const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb,
                        int32_t *w, int32_t *h, char *why, size_t whylen)
{
    if (k == FX_IMAGE_PPM) {
        /* P6 W H 255\n: the header is parsed here, the pixels copied */
        unsigned W = 0, H = 0, maxval = 0;
        int off = 0;
        char head[64] = {0};
        memcpy(head, data, len < sizeof head - 1 ? len : sizeof head - 1);
        if (sscanf(head, "P6 %u %u %u%n", &W, &H, &maxval, &off) != 3 || maxval != 255 || (size_t)off >= len) {
            fx_image_why(why, whylen, "PPM: not a binary PPM with maxval 255");
            return -FX_EBADMSG;
        }
        int r = fx_image_check_size("PPM", W, H, l, why, whylen);
        if (r < 0)
            return r;
        size_t bytes = (size_t)W * H * 3;
        if (len - (size_t)off - 1 < bytes) {
            fx_image_why(why, whylen, "PPM: truncated (%zu bytes of pixels, %zu needed)", len - (size_t)off - 1,
                         bytes);
            return -FX_EBADMSG;
        }
        if (!(*rgb = malloc(bytes)))
            return -FX_ENOMEM;
        memcpy(*rgb, data + off + 1, bytes);
        *w = (int32_t)W;
        *h = (int32_t)H;
        return 0;
    }
    FILE *f = fmemopen((void *)data, len, "rb");
    if (!f)
        return -FX_ENOMEM;
    uint32_t side = l->max_side;
    int r = fx_read_png_rgb_stream(f, side, l->max_pixels, rgb, w, h);
    fclose(f);
    if (r == -FX_ENOTSUP)
        fx_image_why(why, whylen, "PNG: built without libpng (FX_NO_PNG)");
    else if (r == -FX_EFBIG)
        fx_image_why(why, whylen, "PNG: over the limits of %u a side, %zu pixels (fx_image_limits)", side,
                     l->max_pixels);
    else if (r < 0)
        fx_image_why(why, whylen, "PNG: malformed or truncated data");
    return r;
}

int fx_image_decode_rgb(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w,
                        int32_t *h, char *why, size_t whylen)
{
    fx_image_limits def;
    if (!l) {
        fx_image_limits_init(&def);
        l = &def;
    }
    *rgb = NULL;
    if (len > l->max_bytes) {
        fx_image_why(why, whylen, "%zu bytes, over the limit of %zu (fx_image_limits.max_bytes)", len, l->max_bytes);
        return -FX_EFBIG;
    }
    fx_image_kind k = fx_image_sniff(data, len);
    switch (k) {
    case FX_IMAGE_PNG:
    case FX_IMAGE_PPM:
        return decode_memfb(k, data, len, l, rgb, w, h, why, whylen);
    case FX_IMAGE_JPEG:
        return fx_jpeg_decode(data, len, l, rgb, w, h, why, whylen);
    case FX_IMAGE_WEBP:
        return fx_webp_decode(data, len, l, rgb, w, h, why, whylen);
    case FX_IMAGE_GIF: {
        fx_anim *a;
        int r = fx_anim_open(&a, data, len, l, why, whylen);
        if (r < 0)
            return r;
        const uint8_t *px;
        r = fx_anim_frame(a, 0, &px, why, whylen);
        if (r == 0) {
            size_t bytes = (size_t)fx_anim_width(a) * (size_t)fx_anim_height(a) * 3;
            if (!(*rgb = malloc(bytes)))
                r = -FX_ENOMEM;
            else {
                memcpy(*rgb, px, bytes);
                *w = fx_anim_width(a);
                *h = fx_anim_height(a);
            }
        }
        fx_anim_close(a);
        return r;
    }
    default:
        fx_image_why(why, whylen, "not an image this build reads (PNG, JPEG, GIF, WebP, PPM)");
        return -FX_ENOTSUP;
    }
}

int fx_image_read_rgb(FILE *f, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h, char *why,
                      size_t whylen)
{
    fx_image_limits def;
    if (!l) {
        fx_image_limits_init(&def);
        l = &def;
    }
    size_t cap = l->max_bytes, n = 0, size = 1 << 16;
    uint8_t *buf = malloc(size);
    if (!buf)
        return -FX_ENOMEM;
    for (;;) {
        if (n == size) {
            if (size > cap) {
                free(buf);
                fx_image_why(why, whylen, "more than %zu bytes (fx_image_limits.max_bytes)", cap);
                return -FX_EFBIG;
            }
            uint8_t *nb = realloc(buf, size * 2);
            if (!nb) {
                free(buf);
                return -FX_ENOMEM;
            }
            buf = nb;
            size *= 2;
        }
        size_t got = fread(buf + n, 1, size - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f)) {
        free(buf);
        fx_image_why(why, whylen, "read error");
        return -FX_EIO;
    }
    int r = fx_image_decode_rgb(buf, n, l, rgb, w, h, why, whylen);
    free(buf);
    return r;
}

struct fx_anim {
    int32_t w, h;
    int frames, loops, cur;
    uint8_t *canvas;
    uint8_t *data; /* the caller's file, copied: frames are decoded from it later */
    fx_gif *gif; /* NULL: a still image, decoded into canvas at open */
};

int fx_anim_open(fx_anim **out, const uint8_t *data, size_t len, const fx_image_limits *l, char *why, size_t whylen)
{
    fx_image_limits def;
    if (!l) {
        fx_image_limits_init(&def);
        l = &def;
    }
    *out = NULL;
    fx_anim *a = calloc(1, sizeof *a);
    if (!a)
        return -FX_ENOMEM;
    int r;
    if (fx_image_sniff(data, len) == FX_IMAGE_GIF) {
        if (len > l->max_bytes) {
            fx_image_why(why, whylen, "%zu bytes, over the limit of %zu (fx_image_limits.max_bytes)", len,
                         l->max_bytes);
            free(a);
            return -FX_EFBIG;
        }
        if (!(a->data = malloc(len))) {
            free(a);
            return -FX_ENOMEM;
        }
        memcpy(a->data, data, len);
        r = fx_gif_open(&a->gif, a->data, len, l, &a->w, &a->h, &a->frames, &a->loops, why, whylen);
        if (r == 0 && !(a->canvas = malloc((size_t)a->w * (size_t)a->h * 3)))
            r = -FX_ENOMEM;
        a->cur = -1;
    } else {
        r = fx_image_decode_rgb(data, len, l, &a->canvas, &a->w, &a->h, why, whylen);
        a->frames = 1;
        a->loops = 1;
        a->cur = 0;
    }
    if (r < 0) {
        fx_anim_close(a);
        return r;
    }
    *out = a;
    return 0;
}

int32_t fx_anim_width(const fx_anim *a) { return a->w; }
int32_t fx_anim_height(const fx_anim *a) { return a->h; }
int fx_anim_frames(const fx_anim *a) { return a->frames; }
int fx_anim_loops(const fx_anim *a) { return a->loops; }

int fx_anim_delay_ms(const fx_anim *a, int n)
{
    if (!a->gif || n < 0 || n >= a->frames)
        return 0;
    return fx_gif_delay_ms(a->gif, n);
}

int fx_anim_frame(fx_anim *a, int n, const uint8_t **rgb, char *why, size_t whylen)
{
    if (n < 0 || n >= a->frames) {
        fx_image_why(why, whylen, "frame %d of %d frames", n, a->frames);
        return -FX_ERANGE;
    }
    if (a->gif && a->cur != n) {
        int r = fx_gif_frame(a->gif, n, a->canvas, why, whylen);
        if (r < 0) {
            a->cur = -1;
            return r;
        }
        a->cur = n;
    }
    *rgb = a->canvas;
    return 0;
}

void fx_anim_close(fx_anim *a)
{
    if (!a)
        return;
    if (a->gif)
        fx_gif_close(a->gif);
    free(a->canvas);
    free(a->data);
    free(a);
}
