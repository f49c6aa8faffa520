/* SPDX-License-Identifier: MIT */
/* Between image.c (dispatch, limits, animation front end) and the decoders
 * (jpeg.c, gif.c, webp.c), each compiled to a refusal without its library. */
#ifndef FIXEL_IMAGE_INT_H
#define FIXEL_IMAGE_INT_H

#include <stdint.h>
#include <time.h>

#include "fixel/image.h"

void fx_image_why(char *why, size_t n, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* -FX_EFBIG with the reason when w x h is over a limit, else 0. */
int fx_image_check_size(const char *fmt, uint64_t w, uint64_t h, const fx_image_limits *l, char *why, size_t n);
/* Milliseconds since start (CLOCK_MONOTONIC). */
uint32_t fx_image_elapsed_ms(const struct timespec *start);

int fx_jpeg_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen);
int fx_webp_decode(const uint8_t *data, size_t len, const fx_image_limits *l, uint8_t **rgb, int32_t *w, int32_t *h,
                   char *why, size_t whylen);

/* GIF: the frame table is built at open (a pass that skips pixel data). */
typedef struct fx_gif fx_gif;
int fx_gif_open(fx_gif **out, const uint8_t *data, size_t len, const fx_image_limits *l, int32_t *w, int32_t *h,
                int *frames, int *loops, char *why, size_t whylen);
int fx_gif_delay_ms(const fx_gif *g, int n);
int fx_gif_frame(fx_gif *g, int n, uint8_t *canvas, char *why, size_t whylen);
void fx_gif_close(fx_gif *g);

#endif
