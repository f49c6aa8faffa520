/* SPDX-License-Identifier: MIT */
/* fixel — a panel's backlight through sysfs (/sys/class/backlight/NAME:
 * brightness, max_brightness, bl_power), for kiosks that dim at night or
 * switch the light off with the screen. DSI panels (the Raspberry Pi touch
 * displays) and laptop panels have one; HDMI monitors do not, and get only
 * on/off through fx_display_set_power.
 *
 *     fx_backlight b;
 *     if (fx_backlight_open(&b, NULL, NULL) == 0) {   // the first one found
 *         fx_backlight_set_brightness(&b, 40);        // percent
 *         ...
 *         fx_backlight_restore(&b);                   // brightness as found, light on
 *     }
 *
 * Writing needs the file's group (udev rules usually give "video" write
 * access) or root. */
#ifndef FIXEL_BACKLIGHT_H
#define FIXEL_BACKLIGHT_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_backlight {
    char dir[256];      /* ROOT/NAME */
    int max;            /* max_brightness, >= 1 */
    int saved;          /* brightness when opened */
    int saved_power;    /* bl_power when opened; -1: the device has none */
} fx_backlight;

/* root: the class directory (NULL: /sys/class/backlight; tests give a
 * directory of their own); name: the device (NULL or "": the first in name
 * order). Returns 0, -FX_ENOENT (no backlight), -FX_EINVAL (name too long,
 * unreadable max_brightness) or -errno. */
int fx_backlight_open(fx_backlight *b, const char *root, const char *name);
/* 0..100 percent, rounded to the device's steps (0 is the device's 0, which
 * on some panels is dark). Returns 0, -FX_EINVAL or -errno. */
int fx_backlight_set_brightness(const fx_backlight *b, int pct);
/* The brightness now in percent (rounded), or -errno. */
int fx_backlight_brightness(const fx_backlight *b);
/* bl_power: 0 (FB_BLANK_UNBLANK) on, 4 (FB_BLANK_POWERDOWN) off. Returns 0,
 * -FX_ENOTSUP when the device has no bl_power, or -errno. */
int fx_backlight_set_power(const fx_backlight *b, int on);
/* Put back the brightness found at open, and bl_power on (0) even when it
 * was off at open: the next program or the console must not find it dark. */
void fx_backlight_restore(const fx_backlight *b);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
