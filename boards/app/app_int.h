/* SPDX-License-Identifier: MIT */
/* Internal to boards/: the app object (boards/app/app.c), above the display
 * and input layers; tests/core reaches in to replay input. Not installed. */
#ifndef FIXEL_APP_INT_H
#define FIXEL_APP_INT_H

#include "../linux/input/input_int.h"
#include "fixel/app.h"
#include "fixel/input.h"

#define FX_APP_MAX_TIMERS 32
#define FX_REPLAY_DEVICES 8

typedef struct fx_replay fx_replay; /* replay.c */

/* ---- input devices bound to displays (bind.c) ---- */

typedef struct fx_bind_dev {
    const char *path;   /* the device node ("/dev/input/event3"), "" for a replay device */
    const char *name;   /* the kernel's device name */
    const char *sysfs;  /* the real sysfs path of the device the input node belongs to, "" unknown */
    unsigned bus;       /* BUS_* of linux/input.h (0x03 USB, 0x18 I2C, 0x1C SPI...), 0 unknown */
    unsigned cls;       /* FX_DEV_* */
} fx_bind_dev;

typedef struct fx_bind_disp {
    const char *connector;  /* "DSI-1", "" for fbdev and memory */
    const char *card_sysfs; /* the real sysfs path of the card's device, "" unknown */
    int wants_input;        /* the app's own display, or one with input callbacks: the
                               guesses bind only to these */
} fx_bind_disp;

typedef struct fx_bind_rule {
    char device[128];  /* a device path (links resolved) or a device name */
    char display[48];  /* a display number or a connector name */
} fx_bind_rule;

/* The index in disp[] (0: the app's own display) for dev: the first rule
 * naming dev, else a USB display and the device under one USB hub, else a
 * touch controller on I2C/SPI and the one built-in panel (DSI, DPI, eDP,
 * LVDS, SPI connectors), else 0. *why says which (static text). */
int fx_bind_choose(const fx_bind_dev *dev, const fx_bind_disp *disp, int n, const fx_bind_rule *rules,
                   int nrules, const char **why);
/* Appends "DEVICE=DISPLAY[;DEVICE=DISPLAY...]" to rules[*n..max): 0, or
 * -FX_EINVAL / -FX_ENOSPC with the reason in err (nothing appended). */
int fx_bind_parse(const char *spec, fx_bind_rule *rules, int max, int *n, char *err, size_t errlen);
/* The display index device d is bound to (resolved again when bindings or
 * displays changed): 0 for devices the app does not know. */
int fx_app_device_display(fx_app *a, const fx_input_dev *d);
/* Resolve one device's binding, caching it in *display / *gen; logs a
 * binding to another display than the app's own when it changes. */
int fx_app_resolve_binding(fx_app *a, const fx_bind_dev *dev, int *display, unsigned *gen);

struct fx_app {
    fx_display *disp;
    fx_input in;
    fx_callbacks cb;
    void *user;

    fx_evdev_set ev;        /* raw events to fx_app_feed */
    fx_gpio_set gpio;       /* key events to fx_app_emit */

    int tfd, sfd;
    struct {
        uint64_t at_us;
        void (*fn)(void *user, int value);
        int value, used;
    } timers[FX_APP_MAX_TIMERS];

    int redisplay, quit, started;
    /* a frame was drawn since the replay's last turn (see the main loop) */
    int replay_owed;

    /* Displays added with fx_app_add_display: each drawn by its own
     * callback when it asked for a frame and has no flip pending. */
    struct {
        fx_display *disp;
        void (*draw)(fx_app *a, fx_display *d, void *user);
        void *user;
        int redisplay;
        /* input bound to it: pointer state in its coordinates, callbacks */
        fx_input in;
        fx_callbacks cb;
        void *cb_user;
        int has_cb;
        int touch_hidden;
        int frames;       /* draw callbacks run (frame files) */
    } extra[FX_APP_MAX_DISPLAYS - 1];
    int nextra;
    /* fx_app_watch_fd: the program's own fds in the loop's poll */
    struct {
        int fd;
        void (*fn)(void *user, int fd);
        void *user;
    } watch[FX_APP_MAX_WATCH];
    int nwatch;

    /* Input bindings (fx_app_bind_input*): a device's display is resolved
     * again whenever bind_gen moved on (new rules, added displays). */
    fx_bind_rule binds[FX_APP_MAX_BINDS];
    int nbinds;
    unsigned bind_gen;
    int emitting;       /* the display index of the events being emitted */

    /* software pointer policy (app.c) */
    fx_pointer_mode pointer_mode; /* resolved: never AUTO from the environment */
    int pointer_touch_hidden;     /* the last pointing was a touch */
    unsigned feeding_cls;         /* class of the device whose events are being fed */

    /* headless driving (replay.c) */
    fx_replay *replay;      /* the replay file being played, or NULL */
    int frames, max_frames; /* display callbacks run; stop after max_frames (0: never) */
    const char *frame_out;  /* file name pattern for each frame, or NULL */
};

void fx_app_emit(void *app, const fx_event *e);
/* Feed one raw event of device d (its class decides pointer hiding). */
void fx_app_feed(fx_app *a, fx_input_dev *d, const fx_raw_event *ev);
/* Show, hide or move the software pointer to match the policy and the
 * input state; cheap when nothing changed (the loop calls it every pass). */
void fx_app_pointer_sync(fx_app *a);
uint64_t fx_app_now_us(void);

/* replay.c: open the file (reason logged); run statements until "frame",
 * "wait" or the end: 1 more to come (*resume_us: when, 0 now), 0 the end,
 * negative: a bad line or a read error (logged). */
int fx_replay_open(fx_app *a, const char *path);
int fx_replay_step(fx_app *a, uint64_t now, uint64_t *resume_us);
void fx_replay_close(fx_app *a);
/* 1 when p is a valid frame file pattern (at most one %d). */
int fx_frame_pattern_ok(const char *p);
/* After a display callback: count it, save it, stop at the limit. 0 or
 * the write error (logged). */
int fx_app_frame_done(fx_app *a);
/* The same after added display i (0-based in extra[]): its frames are
 * written to the frame_out name with ".dN" before the extension (N = i + 1,
 * the display's number), numbered by that display's own count. */
int fx_app_extra_frame_done(fx_app *a, int i);
/* Replay devices: the display device d (one of the replay's) is bound to,
 * 0 when d is not a replay device; the display of the replay device
 * named name, or -1. */
int fx_replay_device_display(fx_app *a, const fx_input_dev *d);
int fx_replay_named_display(fx_app *a, const char *name);

#endif
