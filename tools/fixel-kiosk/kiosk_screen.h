/* SPDX-License-Identifier: MIT */
/* How fixel-kiosk turns its screen on and off and sets its brightness
 * (MQTT control, later schedules and idle blanking). The kiosk keeps the
 * requested state, shows it in its status and calls these hooks; a backend
 * (DRM DPMS, fbdev FBIOBLANK, a sysfs backlight) fills them in. With a hook
 * NULL the state is only kept and published, and "screen_hw" in the status
 * says "none". */
#ifndef FIXEL_KIOSK_SCREEN_H
#define FIXEL_KIOSK_SCREEN_H

typedef struct kiosk_screen_ops {
    const char *name;                         /* "none", "dpms", "backlight"... */
    int (*set_power)(void *ctx, int on);      /* 0 or -errno */
    int (*set_brightness)(void *ctx, int pct);/* 0..100; 0 or -errno */
    void *ctx;
} kiosk_screen_ops;

/* The hooks filled in (kiosk_screen.c): the display's power switch
 * (fx_display_set_power: DPMS, CRTC off or FBIOBLANK) and a sysfs backlight
 * when there is one (brightness; bl_power with the display's switch). */
#include <stddef.h>

#include "fixel/backlight.h"
#include "fixel/display.h"

struct kiosk_screen_cfg;
typedef struct kiosk_screen_hw {
    fx_display *d;
    fx_backlight bl;
    int have_bl;
    char name[40];
} kiosk_screen_hw;

/* Fills hw and ops (ops->ctx = hw). -1 with err when a backlight named in
 * the config is not there or cannot be set to the configured brightness. */
int kiosk_screen_open(kiosk_screen_hw *hw, kiosk_screen_ops *ops, fx_display *d,
                      const struct kiosk_screen_cfg *c, char *err, size_t errsize);
/* The backlight as found at open (the display's power comes back with
 * fx_display_close). */
void kiosk_screen_close(kiosk_screen_hw *hw);

#endif
