/* SPDX-License-Identifier: MIT */
/* Test pictures drawn identically in the guest (on a real display) and on
 * the host (in memory, as the expectation). Each is asymmetric in both axes
 * so a wrong rotation or mirror cannot match by accident. Only the core
 * surface API is used, so the pictures do not depend on the drawing modules
 * under test elsewhere. */
#ifndef FIXEL_GUEST_SCENES_H
#define FIXEL_GUEST_SCENES_H

#include <stdlib.h>
#include <string.h>

#include "fixel/sprite.h"
#include "fixel/surface.h"

static void scene_bars(const fx_surface *s)
{
    static const fx_color bars[8] = {0xFFFFFFFF, 0xFFFFFF00, 0xFF00FFFF, 0xFF00FF00,
                                     0xFFFF00FF, 0xFFFF0000, 0xFF0000FF, 0xFF000000};
    int32_t w = s->w, h = s->h;
    for (int i = 0; i < 8; i++) {
        fx_rect r = {w * i / 8, 0, w * (i + 1) / 8, h / 2};
        fx_surface_fill(s, r, bars[i]);
    }
    /* Grey ramp and a red-green ramp: every channel value appears. */
    for (int32_t x = 0; x < w; x++) {
        uint32_t v = (uint32_t)(x * 255 / (w > 1 ? w - 1 : 1));
        fx_rect a = {x, h / 2, x + 1, h * 3 / 4};
        fx_rect b = {x, h * 3 / 4, x + 1, h};
        fx_surface_fill(s, a, 0xFF000000u | v << 16 | v << 8 | v);
        fx_surface_fill(s, b, 0xFF000000u | v << 16 | (255 - v) << 8 | (uint32_t)((x * 7) & 255));
    }
    /* Corner markers of different sizes and colours. */
    fx_rect tl = {4, 4, 20, 12}, br = {w - 30, h - 10, w - 4, h - 4};
    fx_surface_fill(s, tl, 0xFF102030);
    fx_surface_fill(s, br, 0xFFC08040);
}

static void scene_checker(const fx_surface *s)
{
    int32_t cell = 16;
    for (int32_t y = 0; y < s->h; y += cell)
        for (int32_t x = 0; x < s->w; x += cell) {
            fx_rect r = {x, y, x + cell, y + cell};
            uint32_t k = (uint32_t)((x / cell + y / cell) & 1);
            fx_surface_fill(s, r, k ? 0xFF2050A0u + (uint32_t)(x & 0xF0) : 0xFFE0C010u + (uint32_t)(y & 0xF0));
        }
    fx_rect mark = {8, 24, 40, 32};
    fx_surface_fill(s, mark, 0xFFFF3300);
}

/* Returns 0, or -1 for an unknown scene name. "SCENE@X.Y" is SCENE with
 * the default pointer arrow's hotspot at logical (X, Y) (guest/pointer.c). */
static int scene_draw(const char *name, const fx_surface *s)
{
    const char *at = strchr(name, '@');
    if (at) {
        char base[32];
        size_t n = (size_t)(at - name);
        char *end;
        long x = strtol(at + 1, &end, 10), y = *end == '.' ? strtol(end + 1, &end, 10) : 0;
        if (n >= sizeof base || *end)
            return -1;
        memcpy(base, name, n);
        base[n] = 0;
        uint32_t mem[FX_SPRITE_MAX * FX_SPRITE_MAX];
        fx_sprite_save sv = {{0, 0, 0, 0}, mem, FX_SPRITE_MAX * FX_SPRITE_MAX};
        if (scene_draw(base, s) < 0 ||
            fx_sprite_draw(s, 0, fx_sprite_arrow(), (int32_t)x, (int32_t)y, &sv) < 0)
            return -1;
        return 0;
    }
    if (!strcmp(name, "bars"))
        scene_bars(s);
    else if (!strcmp(name, "checker"))
        scene_checker(s);
    else if (!strcmp(name, "black"))
        fx_surface_clear(s, 0xFF000000);
    else
        return -1;
    return 0;
}

#endif
