/* SPDX-License-Identifier: MIT */
/* Internal to boards/linux: the app object shared by app.c, evdev.c and
 * gpio.c. Not installed. */
#ifndef FIXEL_APP_INT_H
#define FIXEL_APP_INT_H

#include "fixel/app.h"
#include "fixel/input.h"

#define FX_APP_MAX_DEVS 32
#define FX_APP_MAX_GPIO 16
#define FX_APP_MAX_OUT 8
#define FX_APP_MAX_TIMERS 32

struct libevdev;
struct gpiod_chip;
struct gpiod_line;

typedef struct fx_evdev {
    int fd;
    struct libevdev *dev;
    fx_input_dev st;
    char path[96];
} fx_evdev;

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

struct fx_app {
    fx_display *disp;
    fx_input in;
    fx_callbacks cb;
    void *user;

    fx_evdev *devs[FX_APP_MAX_DEVS];
    int ndevs;
    int inotify_fd;
    char input_dir[128];
    int grab;
    fx_calib calib;
    int access_logged;

    fx_gpio_in gpio[FX_APP_MAX_GPIO];
    int ngpio;
    fx_gpio_out out[FX_APP_MAX_OUT];
    int nout;

    int tfd, sfd;
    struct {
        uint64_t at_us;
        void (*fn)(void *user, int value);
        int value, used;
    } timers[FX_APP_MAX_TIMERS];

    int redisplay, quit, started;

    /* software pointer policy (app.c) */
    fx_pointer_mode pointer_mode; /* resolved: never AUTO from the environment */
    int pointer_touch_hidden;     /* the last pointing was a touch */
    unsigned feeding_cls;         /* class of the device whose events are being fed */
};

uint64_t fx_app_now_us(void);
void fx_app_emit(void *app, const fx_event *e);
/* Feed one raw event of device d (its class decides pointer hiding). */
void fx_app_feed(fx_app *a, fx_input_dev *d, const fx_raw_event *ev);
/* Show, hide or move the software pointer to match the policy and the
 * input state; cheap when nothing changed (the loop calls it every pass). */
void fx_app_pointer_sync(fx_app *a);

/* evdev.c */
void fx_evdev_scan(fx_app *a);
int fx_evdev_open(fx_app *a, const char *path, int quiet);
void fx_evdev_read(fx_app *a, int index);
void fx_evdev_hotplug(fx_app *a);
void fx_evdev_close_all(fx_app *a);

/* gpio.c */
int fx_gpio_open_buttons(fx_app *a, const fx_gpio_button *b, int n);
void fx_gpio_read(fx_app *a, int index);
/* Poll debouncers at now; returns the earliest pending deadline (or UINT64_MAX). */
uint64_t fx_gpio_poll(fx_app *a, uint64_t now);
void fx_gpio_close_all(fx_app *a);

#endif
