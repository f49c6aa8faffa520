/* SPDX-License-Identifier: MIT */
/* uinput devices for the guest programs that inject input (input.c,
 * pointer.c, tools.c): each sets the capabilities its cases need on a
 * libevdev, these helpers add the shared multitouch set and turn it into a
 * device whose node exists. Header-only, like guest.h. */
#ifndef FIXEL_GUEST_UINPUT_H
#define FIXEL_GUEST_UINPUT_H

#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>
#include <string.h>
#include <unistd.h>

#include "guest.h"

/* A direct-touch multitouch screen over 0..4095 on both axes, slots 0 to
 * max_slot: BTN_TOUCH, ABS_X/Y and the MT slot, tracking id and position. */
static void uinput_enable_multitouch(struct libevdev *d, int max_slot) __attribute__((unused));
static void uinput_enable_multitouch(struct libevdev *d, int max_slot)
{
    struct input_absinfo ai = {.minimum = 0, .maximum = 4095};
    struct input_absinfo slot = {.minimum = 0, .maximum = max_slot};
    struct input_absinfo tid = {.minimum = 0, .maximum = 65535};
    libevdev_enable_property(d, INPUT_PROP_DIRECT);
    libevdev_enable_event_code(d, EV_KEY, BTN_TOUCH, NULL);
    libevdev_enable_event_code(d, EV_ABS, ABS_X, &ai);
    libevdev_enable_event_code(d, EV_ABS, ABS_Y, &ai);
    libevdev_enable_event_code(d, EV_ABS, ABS_MT_SLOT, &slot);
    libevdev_enable_event_code(d, EV_ABS, ABS_MT_TRACKING_ID, &tid);
    libevdev_enable_event_code(d, EV_ABS, ABS_MT_POSITION_X, &ai);
    libevdev_enable_event_code(d, EV_ABS, ABS_MT_POSITION_Y, &ai);
}

/* The uinput device of d (named already; d is freed), once devtmpfs has
 * made its node (it does so asynchronously; up to a second); NULL, said
 * on the console, when uinput refuses. */
static struct libevdev_uinput *uinput_create(struct libevdev *d) __attribute__((unused));
static struct libevdev_uinput *uinput_create(struct libevdev *d)
{
    char name[128];
    snprintf(name, sizeof name, "%s", libevdev_get_name(d));
    struct libevdev_uinput *u = NULL;
    int r = libevdev_uinput_create_from_device(d, LIBEVDEV_UINPUT_OPEN_MANAGED, &u);
    libevdev_free(d);
    if (r < 0) {
        printf("  uinput %s: %s\n", name, strerror(-r));
        return NULL;
    }
    for (int i = 0; i < 100 && access(libevdev_uinput_get_devnode(u), R_OK); i++)
        msleep(10);
    return u;
}

/* One tap of slot 0 at raw (x, y) on a device set up by
 * uinput_enable_multitouch: down with a tracking id, then up. */
static void uinput_tap(struct libevdev_uinput *u, int x, int y) __attribute__((unused));
static void uinput_tap(struct libevdev_uinput *u, int x, int y)
{
    static const unsigned type[] = {EV_ABS, EV_ABS, EV_ABS, EV_ABS, EV_ABS, EV_ABS, EV_KEY, EV_SYN,
                                    EV_ABS, EV_KEY, EV_SYN};
    static const unsigned code[] = {ABS_MT_SLOT, ABS_MT_TRACKING_ID, ABS_MT_POSITION_X, ABS_MT_POSITION_Y,
                                    ABS_X, ABS_Y, BTN_TOUCH, SYN_REPORT, ABS_MT_TRACKING_ID, BTN_TOUCH,
                                    SYN_REPORT};
    const int value[] = {0, 11, x, y, x, y, 1, 0, -1, 0, 0};
    for (int i = 0; i < 11; i++)
        libevdev_uinput_write_event(u, type[i], code[i], value[i]);
}

#endif
