/* SPDX-License-Identifier: MIT */
/* fixel — which display an input device belongs to (docs/displays.md,
 * "Input devices and displays"): the configured bindings first, then two
 * guesses from what the kernel says about the device and the display's
 * card, else the app's own display. Pure apart from realpath() of a
 * configured device path; tests/boards/test_bind.c runs it on fake
 * devices and displays. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "app_int.h"
#include "fixel/error.h"

/* The linux/input.h bus numbers the guesses look at. */
enum { BUS_USB_ = 0x03, BUS_BLUETOOTH_ = 0x05, BUS_I2C_ = 0x18, BUS_HOST_ = 0x19, BUS_SPI_ = 0x1C };

static int device_matches(const fx_bind_dev *dev, const char *spec)
{
    if (spec[0] == '/') {
        if (dev->path[0] && !strcmp(spec, dev->path))
            return 1;
        /* a /dev/input/by-path or by-id link */
        char real[PATH_MAX];
        return dev->path[0] && realpath(spec, real) && !strcmp(real, dev->path);
    }
    return !strcmp(spec, dev->name);
}

/* The display a rule names: its number (0 the app's own, then the added
 * ones in order), or its connector ("DSI-1", or "CARD:DSI-1": the part
 * after the last ':'). -1 when none of disp[] is it. */
static int display_named(const fx_bind_disp *disp, int n, const char *spec)
{
    const char *p = spec;
    while (*p >= '0' && *p <= '9')
        p++;
    if (!*p && p != spec && p - spec < 4) {
        int i = atoi(spec);
        return i < n ? i : -1;
    }
    const char *colon = strrchr(spec, ':');
    const char *name = colon ? colon + 1 : spec;
    for (int i = 0; i < n; i++)
        if (disp[i].connector[0] && !strcasecmp(disp[i].connector, name))
            return i;
    return -1;
}

/* "3-1.2": a USB device in a sysfs path (not a root hub "usb3", not an
 * interface "3-1.2:1.0"). */
static int usb_device_component(const char *s, size_t len)
{
    size_t i = 0;
    if (!len || s[0] < '0' || s[0] > '9')
        return 0;
    while (i < len && s[i] >= '0' && s[i] <= '9')
        i++;
    if (i == len || s[i] != '-')
        return 0;
    if (++i == len)
        return 0;
    for (; i < len; i++)
        if (!((s[i] >= '0' && s[i] <= '9') || s[i] == '.'))
            return 0;
    return 1;
}

/* The length of the sysfs path prefix that makes a USB display's "own"
 * devices: the hub it sits behind when that is a USB device too (a
 * monitor with a touch controller has an internal hub), else the USB
 * device itself; 0 when the card is not on USB. */
static size_t usb_anchor(const char *path)
{
    size_t dev_end = 0, dev_start = 0, prev_end = 0;
    const char *p = path;
    while (*p) {
        if (*p == '/') {
            p++;
            continue;
        }
        const char *e = strchr(p, '/');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (usb_device_component(p, len)) {
            prev_end = dev_end;
            dev_start = (size_t)(p - path);
            dev_end = dev_start + len;
        }
        p += len;
    }
    if (!dev_end)
        return 0;
    /* the device's parent is a USB hub when the component right before it is a USB device */
    if (prev_end && prev_end + 1 == dev_start)
        return prev_end;
    return dev_end;
}

/* "DSI-1" -> a panel built into the device (its touch controller hangs on
 * I2C or SPI, not on USB). */
static int builtin_panel(const char *connector)
{
    static const char *const types[] = {"DSI", "DPI", "eDP", "LVDS", "SPI"};
    const char *dash = strrchr(connector, '-');
    if (!dash)
        return 0;
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strlen(types[i]) == (size_t)(dash - connector) && !strncmp(connector, types[i], (size_t)(dash - connector)))
            return 1;
    return 0;
}

int fx_bind_choose(const fx_bind_dev *dev, const fx_bind_disp *disp, int n, const fx_bind_rule *rules,
                   int nrules, const char **why)
{
    for (int r = 0; r < nrules; r++) {
        if (!device_matches(dev, rules[r].device))
            continue;
        int i = display_named(disp, n, rules[r].display);
        *why = i >= 0 ? "configured" : "configured for a display not open: the app's own";
        return i >= 0 ? i : 0;
    }
    *why = "the app's own display";
    if (!(dev->cls & (FX_DEV_TOUCH | FX_DEV_TABLET | FX_DEV_MT)))
        return 0; /* keyboards and mice follow the configuration only */
    /* A USB monitor with its own touch controller: both under one USB hub
     * or device. */
    if (dev->sysfs[0])
        for (int i = 0; i < n; i++) {
            size_t k = disp[i].wants_input ? usb_anchor(disp[i].card_sysfs) : 0;
            if (k && !strncmp(dev->sysfs, disp[i].card_sysfs, k) && dev->sysfs[k] == '/') {
                *why = "same USB device as the display's card";
                return i;
            }
        }
    /* A touch controller on I2C/SPI belongs to the panel built in: the one
     * DSI/DPI/eDP/LVDS/SPI display, when there is exactly one. */
    if ((dev->cls & FX_DEV_TOUCH) &&
        (dev->bus == BUS_I2C_ || dev->bus == BUS_SPI_ || dev->bus == BUS_HOST_)) {
        int found = -1, count = 0;
        for (int i = 0; i < n; i++)
            if (disp[i].wants_input && builtin_panel(disp[i].connector))
                found = i, count++;
        if (count == 1) {
            *why = "built-in touch controller on the one built-in panel";
            return found;
        }
    }
    (void)BUS_USB_, (void)BUS_BLUETOOTH_;
    return 0;
}

int fx_bind_parse(const char *spec, fx_bind_rule *rules, int max, int *n, char *err, size_t errlen)
{
    int item = 0, k = *n;
    for (const char *p = spec; p && *p;) {
        const char *end = strchr(p, ';');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        item++;
        char buf[256];
        if (len >= sizeof buf) {
            snprintf(err, errlen, "item %d is too long", item);
            return -FX_EINVAL;
        }
        memcpy(buf, p, len);
        buf[len] = 0;
        p = end ? end + 1 : NULL;
        char *s = buf;
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            continue;
        char *eq = strrchr(s, '=');
        if (!eq) {
            snprintf(err, errlen, "item %d '%s' is not DEVICE=DISPLAY", item, s);
            return -FX_EINVAL;
        }
        *eq = 0;
        char *dv = s, *ds = eq + 1;
        for (char *t = eq - 1; t >= dv && (*t == ' ' || *t == '\t'); t--)
            *t = 0;
        while (*ds == ' ' || *ds == '\t')
            ds++;
        for (char *t = ds + strlen(ds); t > ds && (t[-1] == ' ' || t[-1] == '\t');)
            *--t = 0;
        if (!*dv || !*ds || strlen(dv) >= sizeof rules->device || strlen(ds) >= sizeof rules->display) {
            snprintf(err, errlen, "item %d: the device and the display must be given (at most %d and %d characters)",
                     item, (int)sizeof rules->device - 1, (int)sizeof rules->display - 1);
            return -FX_EINVAL;
        }
        if (k >= max) {
            snprintf(err, errlen, "item %d: at most %d bindings", item, max);
            return -FX_ENOSPC;
        }
        snprintf(rules[k].device, sizeof rules->device, "%s", dv);
        snprintf(rules[k].display, sizeof rules->display, "%s", ds);
        k++;
    }
    *n = k; /* all or nothing */
    return 0;
}
