/* SPDX-License-Identifier: MIT */
/* fixel — image files people have (boards/image/): PNG and PPM through
 * fixel/memfb.h, JPEG (libjpeg-turbo), GIF with its frames (giflib) and
 * WebP (libwebp), chosen by the file's first bytes. Every decoder is
 * bounded by an fx_image_limits and refuses what exceeds it with a reason
 * naming the limit; a build without one of the libraries (FX_NO_JPEG,
 * FX_NO_GIF, FX_NO_WEBP, FX_NO_PNG) refuses that format by name. */
#ifndef FIXEL_IMAGE_H
#define FIXEL_IMAGE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The defaults (fx_image_limits_init) are the FX_IMAGE_DEFAULT_* below; a
 * program lowers or raises a field before reading. */
#define FX_IMAGE_DEFAULT_MAX_SIDE 16384u
#define FX_IMAGE_DEFAULT_MAX_PIXELS ((size_t)1 << 26) /* 64 Mpixels, 192 MiB as RGB */
#define FX_IMAGE_DEFAULT_MAX_BYTES ((size_t)64 << 20) /* the file */
#define FX_IMAGE_DEFAULT_MAX_FRAMES 2000u
#define FX_IMAGE_DEFAULT_MAX_MS 5000u /* one decode (a frame for GIF) */

typedef struct fx_image_limits {
    uint32_t max_side;   /* pixels a side */
    size_t max_pixels;   /* width x height */
    size_t max_bytes;    /* file size, read whole into memory first */
    uint32_t max_frames; /* GIF frames (also bounds the frame table) */
    uint32_t max_ms;     /* wall time of one decode, checked per row / scan */
} fx_image_limits;

/* Fills l with the FX_IMAGE_DEFAULT_* limits; change a field after it. */
void fx_image_limits_init(fx_image_limits *l);

typedef enum fx_image_kind {
    FX_IMAGE_UNKNOWN = 0,
    FX_IMAGE_PNG,
    FX_IMAGE_PPM,
    FX_IMAGE_JPEG,
    FX_IMAGE_GIF,
    FX_IMAGE_WEBP,
} fx_image_kind;

/* By magic bytes (at least 12 of them for WebP). */
fx_image_kind fx_image_sniff(const uint8_t *p, size_t n);
const char *fx_image_kind_name(fx_image_kind k);

/* Decode the image in memory (frame 0 of a GIF) as 8-bit RGB, alpha
 * dropped (GIF transparency shows black). *rgb is malloc'd, w*h*3 bytes.
 * Returns 0, -FX_EFBIG (a limit), -FX_EBADMSG (malformed or truncated),
 * -FX_ENOTSUP (unknown format or built without its library), -FX_ENOMEM;
 * on failure why (if not NULL) holds the reason, e.g. "GIF: 10000 frames,
 * more than the limit of 2000 (fx_image_limits.max_frames)". */
int fx_image_decode_rgb(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w,
                        int32_t *h, char *why, size_t whylen);
/* The same from an open file (read whole, at most l->max_bytes). */
int fx_image_read_rgb(FILE *f, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h, char *why,
                      size_t whylen);

/* An animated image (the data is copied): frame n composited on the logical screen with the
 * GIF disposal methods (none/keep, background, previous). Memory held: the
 * file, two canvases and one frame's indices, whatever the frame count;
 * frames are decoded in order, so asking for an earlier frame restarts from
 * frame 0 (playback in order costs one frame each). Any format opens: a
 * still image is one frame with delay 0. */
typedef struct fx_anim fx_anim;
int fx_anim_open(fx_anim **out, const uint8_t *data, size_t len, const fx_image_limits *l, char *why,
                 size_t whylen);
int32_t fx_anim_width(const fx_anim *a);
int32_t fx_anim_height(const fx_anim *a);
int fx_anim_frames(const fx_anim *a);
/* How many times the animation plays: 0 forever; a NETSCAPE2.0 repeat
 * count n plays n + 1 times; 1 without the extension. */
int fx_anim_loops(const fx_anim *a);
/* Frame n's delay in milliseconds (GIF centiseconds x 10; 0 and 10 ms are
 * shown as 100 ms, as browsers do). */
int fx_anim_delay_ms(const fx_anim *a, int n);
/* The canvas after frame n (w*h*3 RGB, owned by a, valid until the next
 * call). Returns 0 or a negative errno with the reason in why. */
int fx_anim_frame(fx_anim *a, int n, const uint8_t **rgb, char *why, size_t whylen);
void fx_anim_close(fx_anim *a);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
