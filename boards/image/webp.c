/* SPDX-License-Identifier: MIT */
/* WebP (lossy and lossless, still) through libwebp: the header is read
 * first so the size limits apply before any pixel memory. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* clock_gettime under -std=c11, whoever compiles it */
#endif
#include <stdlib.h>

#include "fixel/error.h"
#include "image_int.h"

#ifndef FX_NO_WEBP
#include <webp/decode.h>

int fx_webp_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen)
{
    WebPBitstreamFeatures ft;
    VP8StatusCode st = WebPGetFeatures(data, len, &ft);
    if (st != VP8_STATUS_OK) {
        fx_image_why(why, whylen, "WebP: %s", st == VP8_STATUS_NOT_ENOUGH_DATA ? "truncated header" : "malformed header");
        return -FX_EBADMSG;
    }
    if (ft.has_animation) {
        fx_image_why(why, whylen, "WebP: animated WebP is not supported (use GIF)");
        return -FX_ENOTSUP;
    }
    int r = fx_image_check_size("WebP", (uint64_t)ft.width, (uint64_t)ft.height, l, why, whylen);
    if (r < 0)
        return r;
    size_t stride = (size_t)ft.width * 3, bytes = stride * (size_t)ft.height;
    uint8_t *buf = malloc(bytes);
    if (!buf)
        return -FX_ENOMEM;
    if (!WebPDecodeRGBInto(data, len, buf, bytes, (int)stride)) {
        free(buf);
        fx_image_why(why, whylen, "WebP: malformed or truncated data");
        return -FX_EBADMSG;
    }
    *rgb = buf;
    *w = ft.width;
    *h = ft.height;
    return 0;
}

#else /* FX_NO_WEBP */
int fx_webp_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen)
{
    (void)data, (void)len, (void)l, (void)rgb, (void)w, (void)h;
    fx_image_why(why, whylen, "WebP: built without libwebp (FX_NO_WEBP; install libwebp-dev)");
    return -FX_ENOTSUP;
}
#endif
