/* SPDX-License-Identifier: MIT */
/* Screen power without a screen (the DPMS enum on fake property data is in
 * test_plane.c with the other property helpers): a sysfs backlight in a
 * directory the test builds
 * (boards/linux/display/backlight.c), and fx_display_set_power on the
 * memory backend (remembered; the rig checks the restore at close). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../boards/display/display_int.h"
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
    /* Found dark (a kiosk that crashed with the screen off): the restore
     * lights it, it does not put the darkness back (issue #24 review). */
    put(dev, "bl_power", "4\n");
    FX_CHECK_EQ(fx_backlight_open(&b, root, "rpi_backlight"), 0);
    FX_CHECK_EQ(b.saved_power, 4);
    fx_backlight_restore(&b);
    FX_CHECK_EQ(get(dev, "bl_power"), 0);
    FX_CHECK_EQ(get(dev, "brightness"), 200);

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

FX_TEST(display_power_memory_backend)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_MEMORY;
    o.memory_w = 32;
    o.memory_h = 16;
    o.console = 0;
    o.signals = 0;
    o.log_priority = -1;
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
