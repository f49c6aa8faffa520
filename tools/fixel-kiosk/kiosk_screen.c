/* SPDX-License-Identifier: MIT */
/* The screen hooks of kiosk_screen.h: power through the display (boards/),
 * brightness and backlight power through sysfs. */
#include <stdio.h>
#include <string.h>

#include "fixel/error.h"
#include "kiosk.h"
#include "kiosk_screen.h"

static int hw_power(void *ctx, int on)
{
    kiosk_screen_hw *hw = ctx;
    /* Light off before the signal, on after it: no flash of a white or
     * stale panel. */
    if (hw->have_bl && !on) fx_backlight_set_power(&hw->bl, 0);
    int r = hw->d ? fx_display_set_power(hw->d, on) : 0;
    if (hw->have_bl && on) {
        int b = fx_backlight_set_power(&hw->bl, 1);
        if (r == 0 && b < 0 && b != -FX_ENOTSUP) r = b;
    }
    return r;
}

static int hw_brightness(void *ctx, int pct)
{
    kiosk_screen_hw *hw = ctx;
    return fx_backlight_set_brightness(&hw->bl, pct);
}

int kiosk_screen_open(kiosk_screen_hw *hw, kiosk_screen_ops *ops, fx_display *d, const kiosk_screen_cfg *c,
                      char *err, size_t errsize)
{
    memset(hw, 0, sizeof *hw);
    hw->d = d;
    const char *root = c->sysfs[0] ? c->sysfs : NULL;
    if (strcmp(c->backlight, "none")) {
        int automatic = !strcmp(c->backlight, "auto");
        int r = fx_backlight_open(&hw->bl, root, automatic ? NULL : c->backlight);
        if (r == 0) hw->have_bl = 1;
        else if (!automatic || r != -FX_ENOENT) {
            snprintf(err, errsize, "screen backlight=%s (in %s): %s", c->backlight,
                     root ? root : "/sys/class/backlight", r == -FX_ENOENT ? "no such backlight" : strerror(-r));
            return -1;
        }
    }
    /* The kiosk starts with the screen on: a light left off (bl_power 4)
     * by a kiosk that crashed while dark must come on with it. */
    if (hw->have_bl) {
        int r = fx_backlight_set_power(&hw->bl, 1);
        if (r < 0 && r != -FX_ENOTSUP) {
            snprintf(err, errsize, "screen: cannot write %s/bl_power: %s", hw->bl.dir, strerror(-r));
            return -1;
        }
    }
    if (hw->have_bl && c->brightness >= 0) {
        int r = fx_backlight_set_brightness(&hw->bl, c->brightness);
        if (r < 0) {
            snprintf(err, errsize, "screen brightness=%d: cannot write %s/brightness: %s", c->brightness,
                     hw->bl.dir, strerror(-r));
            return -1;
        }
    }
    const char *m = d ? fx_display_power_method(d) : "none";
    if (hw->have_bl)
        snprintf(hw->name, sizeof hw->name, "%s%s", strcmp(m, "none") ? m : "", strcmp(m, "none") ? "+backlight" : "backlight");
    else
        snprintf(hw->name, sizeof hw->name, "%s", m);
    *ops = (kiosk_screen_ops){hw->name, hw_power, hw->have_bl ? hw_brightness : NULL, hw};
    return 0;
}

void kiosk_screen_close(kiosk_screen_hw *hw)
{
    if (hw->have_bl) fx_backlight_restore(&hw->bl);
    hw->have_bl = 0;
}
