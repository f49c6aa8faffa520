/* SPDX-License-Identifier: MIT */
/* Screen power without a screen (the DPMS enum on fake property data is in
 * test_plane.c with the other property helpers): a sysfs backlight in a
 * directory the test builds
 * (boards/linux/display/backlight.c), and fx_display_set_power on the
 * memory backend (remembered; the rig checks the restore at close). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../boards/display/display_int.h"
#include "fixel/app.h"
#include "fixel/backlight.h"
#include "fixel/error.h"
#include "fx_test.h"

static void put(const char *dir, const char *file, const char *text)
{
    char p[512];
    snprintf(p, sizeof p, "%s/%s", dir, file);
    FILE *f = fopen(p, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
}

static int get(const char *dir, const char *file)
{
    char p[512];
    int v = -1;
    snprintf(p, sizeof p, "%s/%s", dir, file);
    FILE *f = fopen(p, "r");
    if (f) {
        if (fscanf(f, "%d", &v) != 1)
            v = -2;
        fclose(f);
    }
    return v;
}

static void rm_tree(const char *root)
{
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", root);
}

FX_TEST(backlight_fake_sysfs_scaling_power_restore)
{
    char root[] = "/tmp/fx-backlight-XXXXXX", dev[300], dev2[300];
    FX_CHECK(mkdtemp(root) != NULL);
    /* Two devices: the first by name is taken when none is named. */
    snprintf(dev, sizeof dev, "%s/rpi_backlight", root);
    snprintf(dev2, sizeof dev2, "%s/zz_other", root);
    FX_CHECK(mkdir(dev, 0755) == 0);
    FX_CHECK(mkdir(dev2, 0755) == 0);
    put(dev, "max_brightness", "255\n");
    put(dev, "brightness", "200\n");
    put(dev, "bl_power", "0\n");
    put(dev2, "max_brightness", "10\n");
    put(dev2, "brightness", "3\n");

    fx_backlight b;
    FX_CHECK_EQ(fx_backlight_open(&b, root, NULL), 0);
    FX_CHECK_EQ(b.max, 255);
    FX_CHECK_EQ(fx_backlight_brightness(&b), 78); /* 200/255 */
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, 40), 0);
    FX_CHECK_EQ(get(dev, "brightness"), 102); /* 40% of 255, rounded */
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, 100), 0);
    FX_CHECK_EQ(get(dev, "brightness"), 255);
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, 0), 0);
    FX_CHECK_EQ(get(dev, "brightness"), 0);
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, 101), -FX_EINVAL);
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, -1), -FX_EINVAL);
    FX_CHECK_EQ(get(dev, "brightness"), 0);
    FX_CHECK_EQ(fx_backlight_set_power(&b, 0), 0);
    FX_CHECK_EQ(get(dev, "bl_power"), 4);
    FX_CHECK_EQ(fx_backlight_set_power(&b, 1), 0);
    FX_CHECK_EQ(get(dev, "bl_power"), 0);
    FX_CHECK_EQ(fx_backlight_set_power(&b, 0), 0);
    fx_backlight_restore(&b);
    FX_CHECK_EQ(get(dev, "brightness"), 200);
    FX_CHECK_EQ(get(dev, "bl_power"), 0);

    /* Named, without bl_power: brightness only; small ranges round. */
    FX_CHECK_EQ(fx_backlight_open(&b, root, "zz_other"), 0);
    FX_CHECK_EQ(fx_backlight_set_power(&b, 0), -FX_ENOTSUP);
    FX_CHECK_EQ(fx_backlight_set_brightness(&b, 44), 0);
    FX_CHECK_EQ(get(dev2, "brightness"), 4);
    FX_CHECK_EQ(fx_backlight_brightness(&b), 40);

    /* Missing device, names with a slash, a broken max_brightness. */
    FX_CHECK_EQ(fx_backlight_open(&b, root, "nope"), -FX_ENOENT);
    FX_CHECK_EQ(fx_backlight_open(&b, root, "../etc"), -FX_EINVAL);
    put(dev2, "max_brightness", "0\n");
    FX_CHECK_EQ(fx_backlight_open(&b, root, "zz_other"), -FX_EINVAL);
    put(dev2, "max_brightness", "many\n");
    FX_CHECK_EQ(fx_backlight_open(&b, root, "zz_other"), -FX_EINVAL);
    rm_tree(root);
    FX_CHECK_EQ(fx_backlight_open(&b, root, NULL), -FX_ENOENT);
}

/* A quiet memory display of w x h. */
static void mem_options(fx_display_options *o, int32_t w, int32_t h)
{
    fx_display_options_init(o);
    o->backend = FX_BACKEND_MEMORY;
    o->memory_w = w;
    o->memory_h = h;
    o->console = 0;
    o->signals = 0;
    o->log_priority = -1;
}

FX_TEST(display_power_memory_backend)
{
    fx_display_options o;
    mem_options(&o, 32, 16);
    fx_display *d = NULL;
    FX_CHECK_EQ(fx_display_open(&d, &o), 0);
    if (!d)
        return;
    FX_CHECK_EQ(fx_display_power(d), 1);
    FX_CHECK(!strcmp(fx_display_power_method(d), "none"));
    FX_CHECK_EQ(fx_display_set_power(d, 0), 0);
    FX_CHECK_EQ(fx_display_power(d), 0);
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0); /* presents go on while off */
    FX_CHECK_EQ(fx_display_set_power(d, 7), 0);
    FX_CHECK_EQ(fx_display_power(d), 1);
    fx_display_close(d);
}

/* A screen that is off completes no flip: each present while off stands
 * for one until the next vblank would have come (a timer on the display's
 * fd), so a program that draws whenever no flip is pending is paced. */
FX_TEST(display_power_off_paces_presents)
{
    fx_display_options o;
    mem_options(&o, 16, 8);
    fx_display *d = NULL;
    FX_CHECK_EQ(fx_display_open(&d, &o), 0);
    if (!d)
        return;
    /* On, the memory display never has a flip pending and has no fd. */
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 0);
    FX_CHECK_EQ(fx_display_fd(d), -1);
    FX_CHECK_EQ(fx_display_set_power(d, 0), 0);
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 1);
    FX_CHECK(fx_display_fd(d) >= 0);
    /* The wait ends it (one 60 Hz period, well inside a second). */
    FX_CHECK_EQ(fx_display_wait(d, 1000), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 0);
    /* And so does the fd: readable, then dispatch completes it. */
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 1);
    struct pollfd p = {fx_display_fd(d), POLLIN, 0};
    FX_CHECK_EQ(poll(&p, 1, 1000), 1);
    FX_CHECK_EQ(fx_display_dispatch(d), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 0);
    /* Turning the screen on ends a paced present at once. */
    FX_CHECK_EQ(fx_display_present(d, NULL, 0), 0);
    FX_CHECK_EQ(fx_display_set_power(d, 1), 0);
    FX_CHECK_EQ(fx_display_flip_pending(d), 0);
    fx_display_close(d);
}

/* An animating app (a frame asked for in every display callback) whose
 * screen is off: its frames come at most at the refresh rate, not as fast
 * as the loop can turn. Counted over a bounded run, not timed: 300 ms
 * hold at most 18 periods of 60 Hz (bound 40 for scheduling slack); the
 * unpaced loop ran tens of thousands. */
typedef struct anim {
    fx_app *app;
    int frames;
} anim;

static void anim_display(void *u)
{
    anim *a = u;
    fx_surface s = fx_app_surface(a->app);
    fx_surface_clear(&s, 0xFF000000u | (uint32_t)a->frames);
    fx_app_present(a->app, NULL, 0);
    a->frames++;
    fx_app_post_redisplay(a->app);
}

static void anim_stop(void *u, int v)
{
    (void)v;
    fx_app_quit(((anim *)u)->app);
}

FX_TEST(app_screen_off_is_not_busy_looped)
{
    fx_app_options o;
    fx_app_options_init(&o);
    mem_options(&o.display, 16, 8);
    o.input = 0;
    anim a = {NULL, 0};
    FX_CHECK_EQ(fx_app_open(&a.app, &o), 0);
    if (!a.app)
        return;
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.display = anim_display;
    fx_app_set_callbacks(a.app, &cb, &a);
    FX_CHECK_EQ(fx_display_set_power(fx_app_display(a.app), 0), 0);
    fx_app_timer(a.app, 300, anim_stop, 0);
    FX_CHECK_EQ(fx_app_main_loop(a.app), 0);
    FX_CHECK_MSG(a.frames >= 2 && a.frames <= 40, "%d frames in 300 ms with the screen off", a.frames);
    fx_app_close(a.app);
}
