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

    /* Displays added with fx_app_add_display: each drawn by its own
     * callback when it asked for a frame and has no flip pending. */
    struct {
        fx_display *disp;
        void (*draw)(fx_app *a, fx_display *d, void *user);
        void *user;
        int redisplay;
    } extra[FX_APP_MAX_DISPLAYS - 1];
    int nextra;

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

#endif
