/* Internal to boards/: the app object (boards/app/app.c), above the display
 * and input layers; tests/core reaches in to replay input. Not installed. */
#ifndef FIXEL_APP_INT_H
#define FIXEL_APP_INT_H

#include "../linux/input/input_int.h"
#include "fixel/app.h"
#include "fixel/input.h"

#define FX_APP_MAX_TIMERS 32

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

    /* software pointer policy (app.c) */
    fx_pointer_mode pointer_mode; /* resolved: never AUTO from the environment */
    int pointer_touch_hidden;     /* the last pointing was a touch */
    unsigned feeding_cls;         /* class of the device whose events are being fed */
};

void fx_app_emit(void *app, const fx_event *e);
/* Feed one raw event of device d (its class decides pointer hiding). */
void fx_app_feed(fx_app *a, fx_input_dev *d, const fx_raw_event *ev);
/* Show, hide or move the software pointer to match the policy and the
 * input state; cheap when nothing changed (the loop calls it every pass). */
void fx_app_pointer_sync(fx_app *a);

#endif
