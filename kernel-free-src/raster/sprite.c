/* SPDX-License-Identifier: MIT */
/* fixel — the software pointer sprite: drawing with save-under on rotated
 * surfaces. Works pixel by pixel through the native accessors: a sprite is
 * at most 64x64, and one code path serves every format and rotation. */
#include "fixel/sprite.h"
#include "fixel/draw.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

#define K 0xFF000000u
#define W 0xFFFFFFFFu
#define _ 0x00000000u
static const uint32_t arrow_pixels[12 * 19] = {
    K, _, _, _, _, _, _, _, _, _, _, _,
    K, K, _, _, _, _, _, _, _, _, _, _,
    K, W, K, _, _, _, _, _, _, _, _, _,
    K, W, W, K, _, _, _, _, _, _, _, _,
    K, W, W, W, K, _, _, _, _, _, _, _,
    K, W, W, W, W, K, _, _, _, _, _, _,
    K, W, W, W, W, W, K, _, _, _, _, _,
    K, W, W, W, W, W, W, K, _, _, _, _,
    K, W, W, W, W, W, W, W, K, _, _, _,
    K, W, W, W, W, W, W, W, W, K, _, _,
    K, W, W, W, W, W, W, W, W, W, K, _,
    K, W, W, W, W, W, W, K, K, K, K, K,
    K, W, W, W, K, W, W, K, _, _, _, _,
    K, W, W, K, K, W, W, K, _, _, _, _,
    K, W, K, _, _, K, W, W, K, _, _, _,
    K, K, _, _, _, K, W, W, K, _, _, _,
    K, _, _, _, _, _, K, W, W, K, _, _,
    _, _, _, _, _, _, K, W, W, K, _, _,
    _, _, _, _, _, _, _, K, K, _, _, _,
};
#undef K
#undef W
#undef _

static const fx_sprite arrow = {arrow_pixels, 12, 19, 0, 0};

const fx_sprite *fx_sprite_arrow(void)
{
    return &arrow;
}

int fx_sprite_check(const fx_sprite *s)
{
    if (!s || !s->pixels || s->w < 1 || s->h < 1 || s->w > FX_SPRITE_MAX || s->h > FX_SPRITE_MAX ||
        s->hot_x < 0 || s->hot_y < 0 || s->hot_x >= s->w || s->hot_y >= s->h)
        return -FX_EINVAL;
    return 0;
}

/* Pointer positions far off-screen only need to stay off-screen; bounding
 * them keeps every rectangle sum below in int32 range. */
static int32_t bound(int32_t v)
{
    const int32_t lim = 1 << 24;
    return v < -lim ? -lim : v > lim ? lim : v;
}

fx_rect fx_sprite_rect(const fx_sprite *s, int32_t x, int32_t y)
{
    fx_rect r;
    r.x0 = bound(x) - s->hot_x;
    r.y0 = bound(y) - s->hot_y;
    r.x1 = r.x0 + s->w;
    r.y1 = r.y0 + s->h;
    return r;
}

static int rotation_ok(int rotation)
{
    return rotation == 0 || rotation == 90 || rotation == 180 || rotation == 270;
}

fx_rect fx_sprite_phys_rect(const fx_surface *dst, int rotation, const fx_sprite *s, int32_t x,
                            int32_t y)
{
    return fx_rect_intersect(fx_rect_rotate(fx_sprite_rect(s, x, y), rotation, dst->w, dst->h),
                             fx_surface_rect(dst));
}

int fx_sprite_draw(const fx_surface *dst, int rotation, const fx_sprite *s, int32_t x, int32_t y,
                   fx_sprite_save *sv)
{
    if (!dst || !sv)
        return -FX_EINVAL;
    sv->r.x0 = sv->r.y0 = sv->r.x1 = sv->r.y1 = 0;
    if (fx_sprite_check(s) < 0 || !rotation_ok(rotation))
        return -FX_EINVAL;
    fx_rect p = fx_sprite_phys_rect(dst, rotation, s, x, y);
    if (fx_rect_empty(p))
        return 0;
    uint32_t n = (uint32_t)(p.x1 - p.x0) * (uint32_t)(p.y1 - p.y0);
    if (!sv->mem || n > sv->cap)
        return -FX_ENOSPC;
    /* Sprite pixel (sx, sy) sits at logical (ox + sx, oy + sy). */
    int32_t ox = bound(x) - s->hot_x, oy = bound(y) - s->hot_y;
    int32_t Wd = dst->w, Hd = dst->h;
    uint32_t *m = sv->mem;
    for (int32_t py = p.y0; py < p.y1; py++) {
        for (int32_t px = p.x0; px < p.x1; px++) {
            int32_t lx, ly;
            switch (rotation) {
            case 90:  lx = py;          ly = Wd - 1 - px; break;
            case 180: lx = Wd - 1 - px; ly = Hd - 1 - py; break;
            case 270: lx = Hd - 1 - py; ly = px;          break;
            default:  lx = px;          ly = py;          break;
            }
            uint32_t under = fx_surface_get_native(dst, px, py);
            *m++ = under;
            fx_color c = s->pixels[(ly - oy) * s->w + (lx - ox)];
            uint32_t a = c >> 24;
            if (a == 255)
                fx_surface_put_native(dst, px, py, fx_pack(dst->format, c));
            else if (a != 0)
                fx_surface_put_native(dst, px, py, fx_blend_over(dst->format, under, c));
        }
    }
    sv->r = p;
    return 0;
}

void fx_sprite_save_apply(const fx_surface *dst, const fx_sprite_save *sv)
{
    fx_rect r = fx_rect_intersect(sv->r, fx_surface_rect(dst));
    if (fx_rect_empty(r) || r.x0 != sv->r.x0 || r.y0 != sv->r.y0 || r.x1 != sv->r.x1 ||
        r.y1 != sv->r.y1)
        return; /* not the surface it was saved from: touch nothing */
    const uint32_t *m = sv->mem;
    for (int32_t py = r.y0; py < r.y1; py++)
        for (int32_t px = r.x0; px < r.x1; px++)
            fx_surface_put_native(dst, px, py, *m++);
}

fx_rect fx_sprite_restore(const fx_surface *dst, fx_sprite_save *sv)
{
    fx_rect r = sv->r;
    fx_sprite_save_apply(dst, sv);
    sv->r.x0 = sv->r.y0 = sv->r.x1 = sv->r.y1 = 0;
    return r;
}
