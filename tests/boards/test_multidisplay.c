/* SPDX-License-Identifier: MIT */
/* Several displays open at once (docs/displays.md): two memory displays
 * keep their own size, rotation, presentation mode and damage; closing one
 * leaves the other working. Public API only. */
#include <stdint.h>
#include <string.h>
#include "fixel/app.h"
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

/* ---- fx_app with a second display ---------------------------------------- */

struct two {
    fx_app *app;
    fx_display *second;
    int main_frames, second_frames;
    int32_t second_w, second_h;
};

static void draw_main(void *user)
{
    struct two *t = user;
    fx_surface s = fx_app_surface(t->app);
    fx_surface_clear(&s, 0xFF0000FF);
    fx_app_present(t->app, NULL, 0);
    if (++t->main_frames == 2)
        fx_app_post_redisplay_on(t->app, t->second); /* one more of the second */
}

static void draw_second(fx_app *a, fx_display *d, void *user)
{
    struct two *t = user;
    fx_surface s = fx_display_surface(d);
    t->second_w = s.w;
    t->second_h = s.h;
    fx_surface_clear(&s, t->second_frames ? 0xFFFFFF00 : 0xFF00FF00);
    fx_display_present(d, NULL, 0);
    if (++t->second_frames == 1)
        fx_app_post_redisplay(a); /* the app's own display draws again */
    else
        fx_app_quit(a);
}

FX_TEST(app_draws_a_second_display_with_its_own_callback)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.input = 0;
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 32;
    o.display.memory_h = 20;
    o.display.log_priority = -1;
    struct two t = {0};
    FX_CHECK_EQ(fx_app_open(&t.app, &o), 0);
    if (!t.app)
        return;
    fx_callbacks cb = {.display = draw_main};
    fx_app_set_callbacks(t.app, &cb, &t);
    fx_display_options d2 = o.display;
    d2.memory_w = 12;
    d2.memory_h = 30;
    d2.rotation = 270;
    FX_CHECK_EQ(fx_app_add_display(t.app, &d2, draw_second, &t, &t.second), 0);
    FX_CHECK(t.second != NULL && t.second != fx_app_display(t.app));
    if (!t.second) {
        fx_app_close(t.app);
        return;
    }
    FX_CHECK_EQ(fx_app_main_loop(t.app), 0);
    /* each asks the other for a frame once: the main display's first
     * frame, the second's first, the main's second (asked by the second's
     * callback), the second's second (asked by the main's) */
    FX_CHECK_EQ(t.main_frames, 2);
    FX_CHECK_EQ(t.second_frames, 2);
    FX_CHECK(t.second_w == 30 && t.second_h == 12);
    FX_CHECK_EQ(count(fx_app_display(t.app), 0xFF0000FF), 32 * 20);
    FX_CHECK_EQ(count(t.second, 0xFFFFFF00), 12 * 30);
    int32_t w, h;
    fx_app_size(t.app, &w, &h);
    FX_CHECK(w == 32 && h == 20); /* the app's size is its own display's */

    /* a full app refuses more */
    int r = 0;
    for (int i = 0; i < FX_APP_MAX_DISPLAYS && r == 0; i++)
        r = fx_app_add_display(t.app, &d2, draw_second, &t, NULL);
    FX_CHECK_EQ(r, -FX_ENOSPC);
    fx_app_close(t.app);
}
