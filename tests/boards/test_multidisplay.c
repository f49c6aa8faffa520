/* SPDX-License-Identifier: MIT */
/* Several displays open at once (docs/displays.md): two memory displays
 * keep their own size, rotation, presentation mode and damage; closing one
 * leaves the other working. Public API only. */
#include <stdint.h>
#include <string.h>
#include "fixel/display.h"
#include "fixel/error.h"
#include "fixel/surface.h"
#include "fx_test.h"

static fx_display *open_mem(int32_t w, int32_t h, int rot, fx_present_mode pm)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_MEMORY;
    o.present = pm;
    o.rotation = rot;
    o.memory_w = w;
    o.memory_h = h;
    o.log_priority = -1;
    fx_display *d = NULL;
    FX_CHECK_EQ(fx_display_open(&d, &o), 0);
    return d;
}

/* Pixels of the screen (physical, what is shown) equal to c. */
static int64_t count(const fx_display *d, fx_color c)
{
    fx_surface s = fx_display_screen(d);
    int64_t n = 0;
    for (int32_t y = 0; y < s.h; y++)
        for (int32_t x = 0; x < s.w; x++)
            n += fx_surface_get(&s, x, y) == c;
    return n;
}

FX_TEST(two_memory_displays_are_independent)
{
    fx_display *a = open_mem(40, 24, 0, FX_PRESENT_SHADOW);
    fx_display *b = open_mem(30, 50, 90, FX_PRESENT_SHADOW);
    if (!a || !b) {
        fx_display_close(a);
        fx_display_close(b);
        return;
    }
    fx_surface sa = fx_display_surface(a), sb = fx_display_surface(b);
    FX_CHECK(sa.w == 40 && sa.h == 24);
    FX_CHECK(sb.w == 50 && sb.h == 30); /* rotated 90: logical is the turned size */
    FX_CHECK(sa.pixels != sb.pixels);

    fx_surface_clear(&sa, 0xFF0000FF);
    fx_surface_clear(&sb, 0xFF00FF00);
    FX_CHECK_EQ(fx_display_present(a, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_present(b, NULL, 0), 0);
    FX_CHECK_EQ(count(a, 0xFF0000FF), 40 * 24);
    FX_CHECK_EQ(count(b, 0xFF00FF00), 30 * 50);

    /* Damage is per display: b presents one rectangle, a nothing new. */
    sa = fx_display_surface(a);
    sb = fx_display_surface(b);
    fx_surface_clear(&sa, 0xFFFFFFFF); /* drawn but never presented */
    fx_surface_clear(&sb, 0xFFFFFFFF);
    fx_rect r = {2, 3, 7, 5};
    FX_CHECK_EQ(fx_display_present(b, &r, 1), 0);
    FX_CHECK_EQ(count(b, 0xFFFFFFFF), 5 * 2);
    FX_CHECK_EQ(count(a, 0xFF0000FF), 40 * 24);
    /* Where b's rectangle lands: rotated 90 clockwise on the 30x50 panel,
     * logical (x, y) is physical (30 - 1 - y, x). */
    fx_surface pb = fx_display_screen(b);
    FX_CHECK_EQ_HEX(fx_surface_get(&pb, 30 - 1 - 3, 2), 0xFFFFFFFF);
    FX_CHECK_EQ_HEX(fx_surface_get(&pb, 30 - 1 - 5, 2), 0xFF00FF00);

    fx_display_info ia, ib;
    fx_display_get_info(a, &ia);
    fx_display_get_info(b, &ib);
    FX_CHECK(ia.width == 40 && ia.height == 24 && ia.rotation == 0);
    FX_CHECK(ib.width == 30 && ib.height == 50 && ib.rotation == 90);

    /* Closing one leaves the other drawing. */
    fx_display_close(a);
    sb = fx_display_surface(b);
    fx_surface_clear(&sb, 0xFF123456);
    FX_CHECK_EQ(fx_display_present(b, NULL, 0), 0);
    FX_CHECK_EQ(count(b, 0xFF123456), 30 * 50);
    fx_display_close(b);
}

FX_TEST(two_memory_displays_direct_and_rgb565)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_MEMORY;
    o.memory_w = 16;
    o.memory_h = 8;
    o.format = FX_FMT_RGB565;
    o.log_priority = -1;
    fx_display *a = NULL;
    FX_CHECK_EQ(fx_display_open(&a, &o), 0);
    fx_display *b = open_mem(20, 10, 180, FX_PRESENT_SHADOW);
    if (!a || !b) {
        fx_display_close(a);
        fx_display_close(b);
        return;
    }
    fx_display_info ia, ib;
    fx_display_get_info(a, &ia);
    fx_display_get_info(b, &ib);
    FX_CHECK_EQ(ia.format, FX_FMT_RGB565);
    FX_CHECK_EQ(ib.format, FX_FMT_XRGB8888);
    fx_surface sa = fx_display_surface(a), sb = fx_display_surface(b);
    fx_surface_clear(&sa, 0xFFFFFFFF);
    fx_surface_clear(&sb, 0xFF000000);
    fx_surface_put(&sb, 0, 0, 0xFFFFFFFF);
    FX_CHECK_EQ(fx_display_present(a, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_present(b, NULL, 0), 0);
    FX_CHECK_EQ(count(a, 0xFFFFFFFF), 16 * 8);
    /* 180: the logical top-left pixel is the physical bottom-right */
    fx_surface pb = fx_display_screen(b);
    FX_CHECK_EQ_HEX(fx_surface_get(&pb, 19, 9), 0xFFFFFFFF);
    FX_CHECK_EQ(count(b, 0xFFFFFFFF), 1);
    fx_display_close(b);
    fx_display_close(a);
}
