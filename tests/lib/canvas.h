/* SPDX-License-Identifier: MIT */
/* Shared test helper: a zeroed XRGB8888 canvas (pixel memory plus the
 * surface over it), the one every line/clip/stroke/transform/font test drew
 * on with its own copy. Free mem when done. */
#ifndef FX_TEST_CANVAS_H
#define FX_TEST_CANVAS_H

#include <stdint.h>

#include "fixel/surface.h"

typedef struct {
    fx_surface s;
    uint32_t *mem; /* w * h pixels, stride w * 4, zeroed */
    int w, h;
} canvas;

canvas canvas_make(int w, int h);

#endif
