/* SPDX-License-Identifier: MIT */
/* fixel — evdev input through libevdev: discovery, classification, reading
 * (with SYN_DROPPED resynchronisation), hotplug through inotify. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <libevdev/libevdev.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/inotify.h>
#include <unistd.h>

#include "fixel/error.h"
#include "input_int.h"

static unsigned classify(struct libevdev *d)
{
    unsigned cls = 0;
    if (libevdev_has_event_code(d, EV_KEY, KEY_A) || libevdev_has_event_code(d, EV_KEY, KEY_ENTER) ||
        libevdev_has_event_code(d, EV_KEY, KEY_UP))
        cls |= FX_DEV_KEYBOARD;
    if (libevdev_has_event_code(d, EV_REL, REL_X) && libevdev_has_event_code(d, EV_REL, REL_Y))
        cls |= FX_DEV_MOUSE;
    int direct = libevdev_has_property(d, INPUT_PROP_DIRECT);
    if (libevdev_has_event_code(d, EV_ABS, ABS_X) && libevdev_has_event_code(d, EV_ABS, ABS_Y)) {
        if (libevdev_has_event_code(d, EV_KEY, BTN_TOOL_PEN))
            cls |= FX_DEV_TABLET;
        else if (direct || libevdev_has_event_code(d, EV_KEY, BTN_TOUCH))
            cls |= FX_DEV_TOUCH;
        else
            cls |= FX_DEV_TABLET; /* an absolute pointer, e.g. a VM's tablet */
    }
    if (libevdev_has_event_code(d, EV_ABS, ABS_MT_SLOT) &&
        libevdev_has_event_code(d, EV_ABS, ABS_MT_POSITION_X))
        cls |= FX_DEV_MT | (direct ? FX_DEV_TOUCH : 0u);
    return cls;
}

static const char *class_name(unsigned cls, char *buf, size_t n)
{
    snprintf(buf, n, "%s%s%s%s%s", cls & FX_DEV_KEYBOARD ? " keyboard" : "",
             cls & FX_DEV_MOUSE ? " mouse" : "", cls & FX_DEV_TOUCH ? " touchscreen" : "",
             cls & FX_DEV_MT ? " multitouch" : "", cls & FX_DEV_TABLET ? " tablet" : "");
    return buf;
}

int fx_evdev_open(fx_evdev_set *a, const char *path, int quiet)
{
    for (int i = 0; i < a->ndevs; i++)
        if (!strcmp(a->devs[i]->path, path))
            return 0;
    if (a->ndevs == FX_EVDEV_MAX)
        return -FX_ENOSPC;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        int e = errno;
        if (e == EACCES && !a->access_logged) {
            a->access_logged = 1;
            fx_log_access_hint(&a->log, path);
        } else if (!quiet) {
            fx_log(&a->log, FX_LOG_DEBUG, "input: cannot open %s: %s", path, strerror(e));
        }
        return -e;
    }
    struct libevdev *dev = NULL;
    int r = libevdev_new_from_fd(fd, &dev);
    if (r < 0) {
        close(fd);
        return r;
    }
    unsigned cls = classify(dev);
    if (!cls) {
        libevdev_free(dev);
        close(fd);
        return 0;
    }
    fx_evdev *e = calloc(1, sizeof *e);
    if (!e) {
        libevdev_free(dev);
        close(fd);
        return -FX_ENOMEM;
    }
    e->fd = fd;
    e->dev = dev;
    snprintf(e->path, sizeof e->path, "%s", path);
    snprintf(e->name, sizeof e->name, "%s", libevdev_get_name(dev) ? libevdev_get_name(dev) : "");
    e->bus = (unsigned)libevdev_get_id_bustype(dev);
    const char *base = strrchr(path, '/');
    char link[160], real[PATH_MAX];
    snprintf(link, sizeof link, "/sys/class/input/%s/device/device", base ? base + 1 : path);
    if (realpath(link, real) && strlen(real) < sizeof e->sysfs)
        memcpy(e->sysfs, real, strlen(real) + 1);
    fx_input_dev_init(&e->st, cls);
    if (cls & (FX_DEV_TOUCH | FX_DEV_TABLET | FX_DEV_MT)) {
        e->st.calib = a->calib;
        if (!(cls & FX_DEV_TOUCH))
            e->st.calib.valid = 0; /* pointercal belongs to touchscreens */
    }
    const struct input_absinfo *ax = libevdev_get_abs_info(dev, ABS_X), *ay = libevdev_get_abs_info(dev, ABS_Y);
    if (ax && ay) {
        e->st.abs_min[0] = ax->minimum, e->st.abs_max[0] = ax->maximum;
        e->st.abs_min[1] = ay->minimum, e->st.abs_max[1] = ay->maximum;
    }
    const struct input_absinfo *mx = libevdev_get_abs_info(dev, ABS_MT_POSITION_X),
                               *my = libevdev_get_abs_info(dev, ABS_MT_POSITION_Y);
    if (mx && my) {
        e->st.mt_min[0] = mx->minimum, e->st.mt_max[0] = mx->maximum;
        e->st.mt_min[1] = my->minimum, e->st.mt_max[1] = my->maximum;
    }
    if (a->grab && (cls & FX_DEV_KEYBOARD) && libevdev_grab(dev, LIBEVDEV_GRAB) < 0)
        fx_log(&a->log, FX_LOG_INFO, "input: cannot grab %s (another program holds it)", path);
    a->devs[a->ndevs++] = e;
    char cn[80];
    fx_log(&a->log, FX_LOG_INFO, "input: %s \"%s\":%s", path, libevdev_get_name(dev),
                   class_name(cls, cn, sizeof cn));
    return 1;
}

static void drop(fx_evdev_set *a, int i, const char *why)
{
    fx_evdev *e = a->devs[i];
    fx_log(&a->log, FX_LOG_INFO, "input: %s %s", e->path, why);
    libevdev_free(e->dev);
    close(e->fd);
    free(e);
    a->devs[i] = a->devs[--a->ndevs];
}

void fx_evdev_read(fx_evdev_set *a, int i)
{
    fx_evdev *e = a->devs[i];
    int flag = LIBEVDEV_READ_FLAG_NORMAL;
    for (int guard = 0; guard < 4096; guard++) {
        struct input_event ev;
        int r = libevdev_next_event(e->dev, flag, &ev);
        if (r == -EAGAIN) {
            if (flag == LIBEVDEV_READ_FLAG_SYNC) {
                flag = LIBEVDEV_READ_FLAG_NORMAL;
                continue;
            }
            return;
        }
        if (r < 0) {
            drop(a, i, r == -ENODEV ? "was unplugged" : "failed; closed");
            return;
        }
        fx_raw_event raw = {(uint64_t)ev.input_event_sec * 1000000u + (uint64_t)ev.input_event_usec,
                            ev.type, ev.code, ev.value};
        if (r == LIBEVDEV_READ_STATUS_SYNC && flag == LIBEVDEV_READ_FLAG_NORMAL) {
            /* SYN_DROPPED: forget the partial frame, then take libevdev's
             * resynchronised state as ordinary events. */
            a->sink.fn(a->sink.user, &e->st, &raw);
            fx_raw_event rep = {raw.time_us, FX_IN_SYN, FX_IN_SYN_REPORT, 0};
            a->sink.fn(a->sink.user, &e->st, &rep);
            flag = LIBEVDEV_READ_FLAG_SYNC;
            continue;
        }
        a->sink.fn(a->sink.user, &e->st, &raw);
    }
}

void fx_evdev_scan(fx_evdev_set *a)
{
    DIR *d = opendir(a->dir);
    if (!d) {
        /* No /dev/input at all (a container, a headless board) is normal:
         * only a directory that exists and cannot be read is worth a line. */
        fx_log(&a->log, errno == ENOENT ? FX_LOG_DEBUG : FX_LOG_INFO, "input: cannot read %s: %s",
               a->dir, strerror(errno));
        return;
    }
    struct dirent *de;
    while ((de = readdir(d))) {
        if (strncmp(de->d_name, "event", 5))
            continue;
        char path[400];
        snprintf(path, sizeof path, "%s/%s", a->dir, de->d_name);
        fx_evdev_open(a, path, 0);
    }
    closedir(d);
    a->inotify_fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (a->inotify_fd >= 0 && inotify_add_watch(a->inotify_fd, a->dir, IN_CREATE | IN_ATTRIB) < 0) {
        close(a->inotify_fd);
        a->inotify_fd = -1;
    }
}

void fx_evdev_hotplug(fx_evdev_set *a)
{
    char buf[4096] __attribute__((aligned(__alignof__(struct inotify_event))));
    for (;;) {
        ssize_t n = read(a->inotify_fd, buf, sizeof buf);
        if (n <= 0)
            return;
        for (char *p = buf; p < buf + n;) {
            struct inotify_event *ev = (struct inotify_event *)(void *)p;
            if (ev->len && !strncmp(ev->name, "event", 5)) {
                char path[400];
                snprintf(path, sizeof path, "%s/%s", a->dir, ev->name);
                /* quiet: a node may be created before its permissions are set */
                fx_evdev_open(a, path, 1);
            }
            p += sizeof *ev + ev->len;
        }
    }
}

void fx_evdev_close_all(fx_evdev_set *a)
{
    while (a->ndevs) {
        fx_evdev *e = a->devs[--a->ndevs];
        libevdev_free(e->dev);
        close(e->fd);
        free(e);
    }
    if (a->inotify_fd >= 0)
        close(a->inotify_fd);
    a->inotify_fd = -1;
}
