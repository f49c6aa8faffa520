/* SPDX-License-Identifier: MIT */
/* Internal to boards/: the input layer (evdev.c, gpio.c, or the stand-ins
 * of boards/linux/absent). Above the posix layer and the core only: it
 * knows no app and no display. Devices hand their raw events to a sink
 * {fn, user}; buttons emit finished events to a sink and read time from a
 * clock callback, as the core's fx_input_feed does. Not installed. */
#ifndef FIXEL_INPUT_INT_H
#define FIXEL_INPUT_INT_H

#include <stdint.h>

#include "../../posix/posix_int.h"
#include "fixel/buttons.h"
#include "fixel/input.h"

#define FX_EVDEV_MAX 32
#define FX_GPIO_MAX_IN 16
#define FX_GPIO_MAX_OUT 8

struct libevdev;
struct gpiod_chip;
struct gpiod_line;

/* Where the raw events of device dev go (fx_app_feed, a test, a recorder). */
typedef struct fx_raw_sink {
    void (*fn)(void *user, fx_input_dev *dev, const fx_raw_event *ev);
    void *user;
} fx_raw_sink;

/* Where finished events go. */
typedef struct fx_event_sink {
    fx_emit_fn fn;
    void *user;
} fx_event_sink;

/* A monotonic clock in microseconds. */
typedef struct fx_clock {
    uint64_t (*now_us)(void *user);
    void *user;
} fx_clock;

typedef struct fx_evdev {
    int fd;
    struct libevdev *dev;
    fx_input_dev st;
    char path[96];
    /* what binds it to a display (boards/app/bind.c) */
    char name[80];
    char sysfs[256];    /* real path of /sys/class/input/eventN/device/device, "" unknown */
    unsigned bus;
    int display;        /* the owner's: the display it is bound to */
    unsigned bind_gen;  /* the owner's: 0 unresolved */
} fx_evdev;

/* The evdev devices of one directory. The owner fills dir, grab, calib,
 * sink and log, sets inotify_fd to -1, and may read devs[i]->st.cls. */
typedef struct fx_evdev_set {
    fx_evdev *devs[FX_EVDEV_MAX];
    int ndevs;
    int inotify_fd;
    char dir[128];
    int grab;              /* EVIOCGRAB keyboards */
    fx_calib calib;        /* given to touchscreens as they appear */
    int access_logged;
    fx_raw_sink sink;
    fx_logger log;
} fx_evdev_set;

void fx_evdev_scan(fx_evdev_set *s);
int fx_evdev_open(fx_evdev_set *s, const char *path, int quiet);
void fx_evdev_read(fx_evdev_set *s, int index);
void fx_evdev_hotplug(fx_evdev_set *s);
void fx_evdev_close_all(fx_evdev_set *s);

typedef struct fx_gpio_in {
    struct gpiod_chip *chip;
    struct gpiod_line *line;
    int fd, close_chip;
    fx_debounce db;
    fx_gpio_button b;
} fx_gpio_in;

typedef struct fx_gpio_out {
    struct gpiod_chip *chip;
    struct gpiod_line *line;
    char chipname[32];
    int offset;
} fx_gpio_out;

/* GPIO buttons and output lines. The owner fills sink, clock and log.
 * Emitted key events carry type, key and time_us; the sink adds the rest
 * (the pointer position). */
typedef struct fx_gpio_set {
    fx_gpio_in in[FX_GPIO_MAX_IN];
    int nin;
    fx_gpio_out out[FX_GPIO_MAX_OUT];
    int nout;
    fx_event_sink sink;
    fx_clock clock;
    fx_logger log;
} fx_gpio_set;

int fx_gpio_open_buttons(fx_gpio_set *s, const fx_gpio_button *b, int n);
void fx_gpio_read(fx_gpio_set *s, int index);
/* Poll debouncers at now; returns the earliest pending deadline (or UINT64_MAX). */
uint64_t fx_gpio_poll(fx_gpio_set *s, uint64_t now);
void fx_gpio_close_all(fx_gpio_set *s);
/* Drive an output line, requested on first use. */
int fx_gpio_output(fx_gpio_set *s, const char *chip, int offset, int value);

#endif
