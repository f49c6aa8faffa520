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

#endif
