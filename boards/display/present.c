/* SPDX-License-Identifier: MIT */
/* The pure half of the display front end: merging damage and copying
 * rectangles under rotation. No OS headers and no allocation, so tests/boards can
 * feed it fake surfaces. */
#include <stddef.h>
#include <string.h>

#include "display_int.h"
#include "fixel/error.h"

/* ---- damage ---------------------------------------------------------- */

static int64_t area(fx_rect r)
{
    return fx_rect_empty(r) ? 0 : (int64_t)(r.x1 - r.x0) * (r.y1 - r.y0);
}

static fx_rect rect_union(fx_rect a, fx_rect b)
{
    fx_rect u = {a.x0 < b.x0 ? a.x0 : b.x0, a.y0 < b.y0 ? a.y0 : b.y0,
                 a.x1 > b.x1 ? a.x1 : b.x1, a.y1 > b.y1 ? a.y1 : b.y1};
    return u;
}

static int intersects(fx_rect a, fx_rect b)
{
    return !fx_rect_empty(fx_rect_intersect(a, b));
}

static void remove_at(fx_damage *d, int i)
{
    d->r[i] = d->r[--d->n];
}

void fx_damage_reset(fx_damage *d)
{
    d->n = 0;
}

void fx_damage_add(fx_damage *d, fx_rect r, fx_rect bounds)
{
    r = fx_rect_intersect(r, bounds);
    if (fx_rect_empty(r))
        return;
    for (;;) {
        /* Absorb every rectangle that overlaps r or costs nothing to join;
         * r grows, so restart the scan after each absorption. */
        int i, again = 1;
        while (again) {
            again = 0;
            for (i = 0; i < d->n; i++) {
                fx_rect u = rect_union(d->r[i], r);
                if (intersects(d->r[i], r) || area(u) <= area(d->r[i]) + area(r)) {
                    r = u;
                    remove_at(d, i);
                    again = 1;
                    break;
                }
            }
        }
        if (d->n < FX_DAMAGE_MAX) {
            d->r[d->n++] = r;
            return;
        }
        /* Full: fold r into the rectangle it joins most cheaply, then
         * re-check overlaps since the union may now touch others. */
        int best = 0;
        int64_t best_cost = -1;
        for (i = 0; i < d->n; i++) {
            int64_t cost = area(rect_union(d->r[i], r)) - area(d->r[i]) - area(r);
            if (best_cost < 0 || cost < best_cost) {
                best_cost = cost;
                best = i;
            }
        }
        r = rect_union(d->r[best], r);
        remove_at(d, best);
    }
}

int64_t fx_damage_area(const fx_damage *d)
{
    int64_t a = 0;
    for (int i = 0; i < d->n; i++)
        a += area(d->r[i]);
    return a;
}

/* ---- rotation -------------------------------------------------------- */

void fx_rotated_size(int rotation, int32_t w, int32_t h, int32_t *rw, int32_t *rh)
{
    if (rotation == 90 || rotation == 270) {
        *rw = h;
        *rh = w;
    } else {
        *rw = w;
        *rh = h;
    }
}

static int bpp_of(fx_format f)
{
    return fx_format_get(f)->bits_per_pixel;
}

/* Destination start pixel and the byte steps taken per source pixel along a
 * source row (dx) and per source row (dy), for the whole-byte formats. */
static void rot_steps(const fx_surface *dst, int rotation, int32_t x, int32_t y, int bytes,
                      uint8_t **start, ptrdiff_t *step_x, ptrdiff_t *step_y)
{
    int32_t W = dst->w, H = dst->h, px, py;
    ptrdiff_t s = dst->stride;
    switch (rotation) {
    case 90:  px = W - 1 - y; py = x;         *step_x = s;      *step_y = -bytes; break;
    case 180: px = W - 1 - x; py = H - 1 - y; *step_x = -bytes; *step_y = -s;     break;
    case 270: px = y;         py = H - 1 - x; *step_x = -s;     *step_y = bytes;  break;
    default:  px = x;         py = y;         *step_x = bytes;  *step_y = s;      break;
    }
    *start = dst->pixels + (ptrdiff_t)py * s + (ptrdiff_t)px * bytes;
}

void fx_copy_rotated(const fx_surface *dst, const fx_surface *src, fx_rect r, int rotation)
{
    int bpp = bpp_of(src->format);
    int32_t w = r.x1 - r.x0;
    if (fx_rect_empty(r))
        return;

    if (bpp == 1) {
        /* Bit-addressed rows: no byte-stepping shortcut, go pixel by pixel
         * through the native accessors (MONO panels are small). */
        for (int32_t y = r.y0; y < r.y1; y++) {
            for (int32_t x = r.x0; x < r.x1; x++) {
                int32_t px, py;
                switch (rotation) {
                case 90:  px = dst->w - 1 - y; py = x; break;
                case 180: px = dst->w - 1 - x; py = dst->h - 1 - y; break;
                case 270: px = y; py = dst->h - 1 - x; break;
                default:  px = x; py = y; break;
                }
                fx_surface_put_native(dst, px, py, fx_surface_get_native(src, x, y));
            }
        }
        return;
    }

    int bytes = bpp / 8;
    const uint8_t *srow = src->pixels + (ptrdiff_t)r.y0 * src->stride + (ptrdiff_t)r.x0 * bytes;
    if (rotation == 0) {
        uint8_t *drow = dst->pixels + (ptrdiff_t)r.y0 * dst->stride + (ptrdiff_t)r.x0 * bytes;
        for (int32_t y = r.y0; y < r.y1; y++) {
            memcpy(drow, srow, (size_t)w * (size_t)bytes);
            drow += dst->stride;
            srow += src->stride;
        }
        return;
    }

    uint8_t *dline;
    ptrdiff_t sx, sy;
    rot_steps(dst, rotation, r.x0, r.y0, bytes, &dline, &sx, &sy);
    /* A turned copy writes one destination row per source column: done row
     * by row, every pixel lands on a different cache line and the copy runs
     * at memory latency (15-25 times slower than in 16 x 16 tiles at
     * 1920x1080). A tile touches 16 lines on each side and uses each line
     * whole while it is still in the L1 cache. */
    enum { T = 16 };
    for (int32_t ty = r.y0; ty < r.y1; ty += T) {
        int32_t yn = r.y1 - ty < T ? r.y1 - ty : T;
        for (int32_t tx = r.x0; tx < r.x1; tx += T) {
            int32_t xn = r.x1 - tx < T ? r.x1 - tx : T;
            const uint8_t *sp = src->pixels + (ptrdiff_t)ty * src->stride + (ptrdiff_t)tx * bytes;
            uint8_t *dp = dline + (ptrdiff_t)(ty - r.y0) * sy + (ptrdiff_t)(tx - r.x0) * sx;
            for (int32_t y = 0; y < yn; y++, sp += src->stride, dp += sy) {
                const uint8_t *s = sp;
                uint8_t *d = dp;
                int32_t n = xn;
                switch (bytes) {
                case 4:
                    /* memcpy of a constant 4 or 2 bytes is one move, and
                     * stays defined for scanout memory of any alignment. */
                    for (; n--; s += 4, d += sx)
                        memcpy(d, s, 4);
                    break;
                case 2:
                    for (; n--; s += 2, d += sx)
                        memcpy(d, s, 2);
                    break;
                default:
                    for (; n--; s += bytes, d += sx)
                        for (int k = 0; k < bytes; k++)
                            d[k] = s[k];
                    break;
                }
            }
        }
    }
}

