/* SPDX-License-Identifier: MIT */
/* fixel — a software pointer sprite: an ARGB image with a hotspot drawn onto
 * a (possibly rotated) scanout surface, with the pixels under it saved in a
 * caller-provided buffer so they can be put back exactly.
 *
 * The display uses it to draw the mouse pointer on top of the program's
 * picture without the program's surface ever containing it. Everything is
 * integer-only and allocation-free: the save buffer is the caller's.
 *
 * Geometry: the sprite is placed in logical coordinates (the program's view,
 * w x h after rotation); dst is the physical surface, whose sides are swapped
 * for 90/270 (the mapping of fx_copy_rotated: logical (x, y) lands on
 * physical 0: (x, y), 90: (W-1-y, x), 180: (W-1-x, H-1-y), 270: (y, H-1-x)).
 * The sprite is clipped at every screen edge.
 */
#ifndef FIXEL_SPRITE_H
#define FIXEL_SPRITE_H

#include <stdint.h>
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The largest sprite side, so save buffers have a fixed bound. */
#define FX_SPRITE_MAX 64

typedef struct fx_sprite {
    const uint32_t *pixels; /* w*h colours 0xAARRGGBB, row-major: alpha 0 leaves the
                             * screen alone (mask), 255 replaces it, between blends
                             * (exact source-over, as FX_BLEND_OVER) */
    int32_t w, h;           /* 1..FX_SPRITE_MAX each */
    int32_t hot_x, hot_y;   /* the pixel that sits at the pointer position */
} fx_sprite;

/* The pixels under a drawn sprite: a physical rectangle and its native
 * values row by row (mem holds at least cap values; FX_SPRITE_MAX^2 is
 * always enough). An empty r means nothing is saved. */
typedef struct fx_sprite_save {
    fx_rect r;
    uint32_t *mem;
    uint32_t cap;
} fx_sprite_save;

/* The built-in arrow (12x19, black outline, white inside, hotspot at its tip). */
const fx_sprite *fx_sprite_arrow(void);

/* 0 when s is usable, -FX_EINVAL otherwise (NULL pixels, bad size, hotspot outside). */
int fx_sprite_check(const fx_sprite *s);

/* The logical rectangle covered with the hotspot at (x, y), not clipped. */
fx_rect fx_sprite_rect(const fx_sprite *s, int32_t x, int32_t y);

/* The physical rectangle of dst covered with the hotspot at logical (x, y)
 * under rotation, clipped to dst (may be empty). */
fx_rect fx_sprite_phys_rect(const fx_surface *dst, int rotation, const fx_sprite *s, int32_t x,
                            int32_t y);

/* Save the pixels under the sprite into sv (which must be empty: restore
 * first), then draw it. Returns 0, or -FX_ENOSPC when sv->cap is too small
 * or -FX_EINVAL for a bad sprite or rotation (nothing drawn, sv left empty),
 * or a NULL dst, s or sv. */
int fx_sprite_draw(const fx_surface *dst, int rotation, const fx_sprite *s, int32_t x, int32_t y,
                   fx_sprite_save *sv);

/* Put the saved pixels back into dst (the surface they came from, or one
 * with the same size and format) and empty sv. Returns the physical
 * rectangle restored (empty when nothing was saved). */
fx_rect fx_sprite_restore(const fx_surface *dst, fx_sprite_save *sv);

/* Write the saved pixels into dst without emptying sv (to clean a copy of
 * the surface the sprite was drawn on). */
void fx_sprite_save_apply(const fx_surface *dst, const fx_sprite_save *sv);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
