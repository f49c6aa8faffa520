/* SPDX-License-Identifier: MIT */
/* fixel — the in-memory framebuffer: a surface in ordinary memory, for
 * headless runs and tests, and image files (PNG via libpng, binary PPM). */
#ifndef FIXEL_MEMFB_H
#define FIXEL_MEMFB_H

#include <stdint.h>
#include <stdio.h>
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_memfb {
    fx_surface surf;
    void *mem; /* what to free */
} fx_memfb;

/* Allocate a w x h surface of format f, 64-byte aligned rows, cleared to 0.
 * Returns 0, -FX_EINVAL or -FX_ENOMEM. */
int fx_memfb_create(fx_memfb *fb, int32_t w, int32_t h, fx_format f);
void fx_memfb_destroy(fx_memfb *fb);

/* Write a surface as 8-bit RGB (every format goes through fx_unpack). In a
 * build without libpng (FX_NO_PNG) the PNG functions return -FX_ENOTSUP.
 * Return 0 or a negative errno; on failure no partial file is left behind.
 * An existing file the caller may not write fails with its own error
 * (-EACCES, -EROFS) and is left as it was. */
int fx_write_png(const char *path, const fx_surface *s);
int fx_write_ppm(const char *path, const fx_surface *s);
/* By extension: ".ppm" writes PPM, anything else PNG. */
int fx_write_image(const char *path, const fx_surface *s);
/* What this build of the library left out, for a program to say: "" when
 * nothing, else the libraries it was built without, '/'-separated, in this
 * order: libdrm/libevdev/libgpiod (no DRM/KMS, no input devices, no GPIO
 * buttons), libpng (PPM pictures only),
 * FreeType/HarfBuzz/FriBiDi/fontconfig/libunibreak (no smooth text:
 * fixel/face.h answers -FX_ENOTSUP), libjpeg, giflib, libwebp (that image
 * format refused). */
const char *fx_built_without(void);
/* After a failed picture or display call: when err (a negative fixel error)
 * failed because this build lacks a library (-FX_ENOTSUP from a PNG
 * function without libpng), a note naming it and its packages, starting
 * with a space, to append to the message; "" otherwise. */
const char *fx_built_without_hint(int err);

/* Read a PNG of any colour type and bit depth (palette, grey 1..16 bits,
 * grey+alpha, RGB and RGBA 8/16, tRNS, interlaced) as 8-bit RGB: palettes
 * and grey expanded, 16-bit samples to their high byte, alpha and tRNS
 * dropped with the colour kept.
 * *rgb is malloc'd (w*h*3 bytes); the caller frees it. */
int fx_read_png_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h);
/* The same from an open file, with libpng's limits: at most max_side pixels
 * a side and max_pixels in all (capped at 16384 and 2^26), ancillary chunks
 * skipped unread, chunk allocations at most 8 MiB. -FX_EFBIG when too
 * large, -FX_EBADMSG when not a PNG. Alpha is dropped, not composited. */
int fx_read_png_rgb_stream(FILE *f, uint32_t max_side, size_t max_pixels, uint8_t **rgb, int32_t *w, int32_t *h);
/* Read a binary PPM (P6, maxval 255) as 8-bit RGB; *rgb is malloc'd. */
int fx_read_ppm_rgb(const char *path, uint8_t **rgb, int32_t *w, int32_t *h);
/* Write 8-bit RGB data as a PNG (used for diff images). */
int fx_write_png_rgb(const char *path, const uint8_t *rgb, int32_t w, int32_t h);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
