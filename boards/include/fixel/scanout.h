/* SPDX-License-Identifier: MIT */
/* fixel — helpers about scanout memory that programs outside the library
 * need too (fixel-info, fixel-shot, fixel-bench): the pixel format of an
 * fbdev layout, and the rotated copy both presentation modes are built on.
 * Pure functions: no device, no allocation. */
#ifndef FIXEL_SCANOUT_H
#define FIXEL_SCANOUT_H

#include <stdint.h>

#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* fbdev pixel layout as FBIOGET_VSCREENINFO reports it, reduced to the
 * fields that decide the format. */
typedef struct fx_fb_bitfields {
    uint32_t bits_per_pixel;
    uint32_t grayscale;        /* 1 = gray, 0 = colour (fourcc values are not handled) */
    uint32_t red_offset, red_length;
    uint32_t green_offset, green_length;
    uint32_t blue_offset, blue_length;
    uint32_t transp_offset, transp_length;
    int mono_inverted;         /* FB_VISUAL_MONO01: a set bit is black */
} fx_fb_bitfields;

/* The fixel format matching the layout, or FX_FMT_COUNT when none does. */
fx_format fx_fb_format_from_bitfields(const fx_fb_bitfields *b);

/* Physical size of a logical w x h surface under rotation, and back: 90 and
 * 270 swap the sides. */
void fx_rotated_size(int rotation, int32_t w, int32_t h, int32_t *rw, int32_t *rh);


/* Copy logical rectangle r of src into dst under rotation. src and dst have
 * the same format; dst is the physical surface (sides swapped for 90/270);
 * r must lie inside src. Every format is supported, MONO1 included. */
void fx_copy_rotated(const fx_surface *dst, const fx_surface *src, fx_rect r, int rotation);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
