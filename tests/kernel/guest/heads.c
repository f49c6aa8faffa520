/* SPDX-License-Identifier: MIT */
/* Guest program: two heads of one card driven by one fx_app (issue #25).
 * x86_64 only: there the second display device is a virtio-gpu with two
 * outputs (run.py: gpu1, max_outputs=2), so card1 has Virtual-2 (head 0,
 * 640x400) and Virtual-3 (head 1). qemu enables head 0 only (a head is
 * enabled when a display window asks for it, and the rig has none), so
 * Virtual-3 is forced on through sysfs here, as a monitor being plugged in.
 * The aarch64 guest's second device is a bochs-display (one head; its
 * virtio-gpu is card0, which every other program uses alone), so the
 * program has nothing to do there.
 *
 * run.py gives both heads a panel orientation on the kernel command line:
 * Virtual-2 right side up (outputs.c's panel), Virtual-3 left side up.
 * The app's own display is head 1 (so the touchscreen maps to it), head 0
 * is added with fx_app_add_display and drawn by its own callback.
 * Checked: both open on the one card with a CRTC each and the rotation of
 * their own panel (90 and 270); each head's picture on its own qemu head
 * (screendump of gpu1 head 0 / head 1, every pixel); a uinput touchscreen's
 * corners land on the logical corners of head 1's turned picture; head 1
 * forced off through sysfs while head 0 keeps its picture and draws a new
 * one, forced on again: it comes back (modeset) and draws, head 0 unchanged
 * and never reshaped. The driver is unloaded at the end. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <libevdev/libevdev-uinput.h>
#include <libevdev/libevdev.h>

#include "fixel/app.h"
#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "guest.h"

#if defined(__x86_64__)
#include "guest_drm.h"
#include "scenes.h"
#include "uinput.h"

#define HEAD0 "Virtual-2"
#define HEAD1 "Virtual-3"
#define STATUS1 "/sys/class/drm/card1-" HEAD1 "/status"

static struct heads {
    fx_app *app;
    fx_display *own;   /* head 1: the app's display */
    fx_display *other; /* head 0: added */
    const char *own_scene, *other_scene;
    int own_draws, other_draws;
    int tries;         /* polls of the step waiting for something */
    int other_mark;    /* other_draws when a redraw was asked for */
    int own_mark;
    int forced;        /* the last force(): 0 or -errno */
    char ev[8][48];
    int nev;
    struct libevdev_uinput *ts;
} H;

static void draw_own(void *user)
{
    (void)user;
    fx_surface s = fx_app_surface(H.app);
    scene_draw(H.own_scene, &s);
    fx_app_present(H.app, NULL, 0);
    H.own_draws++;
}

static void draw_other(fx_app *a, fx_display *d, void *user)
{
    (void)a;
    (void)user;
    fx_surface s = fx_display_surface(d);
    scene_draw(H.other_scene, &s);
    fx_display_present(d, NULL, 0);
    H.other_draws++;
}

static void on_touch(void *u, int id, int x, int y, int ph)
{
    (void)u;
    (void)id;
    if (H.nev < 8)
        snprintf(H.ev[H.nev++], 48, "%s %d %d", ph == 0 ? "down" : ph == 1 ? "move" : "up", x, y);
    printf("  event: touch %d %d %d\n", ph, x, y);
}

static void tw(unsigned t, unsigned c, int v) { libevdev_uinput_write_event(H.ts, t, c, v); }
static void tap(int x, int y)
{
    tw(EV_ABS, ABS_MT_SLOT, 0);
    tw(EV_ABS, ABS_MT_TRACKING_ID, 21);
    tw(EV_ABS, ABS_MT_POSITION_X, x);
    tw(EV_ABS, ABS_MT_POSITION_Y, y);
    tw(EV_ABS, ABS_X, x);
    tw(EV_ABS, ABS_Y, y);
    tw(EV_KEY, BTN_TOUCH, 1);
    tw(EV_SYN, SYN_REPORT, 0);
    tw(EV_ABS, ABS_MT_TRACKING_ID, -1);
    tw(EV_KEY, BTN_TOUCH, 0);
    tw(EV_SYN, SYN_REPORT, 0);
}

/* SCREEN request for display d on gpu1's head. */
static void screen(fx_display *d, const char *name, const char *spec, int head)
{
    fx_display_info in;
    fx_display_get_info(d, &in);
    guest_request("SCREEN %s %d %d %d %s gpu1@%d", name, in.width, in.height, in.rotation, spec, head);
}

static int force(const char *how)
{
    int w = write_file(STATUS1, how);
    return w ? w : write_file("/sys/class/drm/card1/uevent", "change");
}

static void step(void *user, int k);

/* The step waits for cond: polled every 50 ms for up to 3 s, then goes on
 * (its checks then fail and say what was missing). */
static int waiting(int cond, int k)
{
    if (!cond && ++H.tries < 60) {
        fx_app_timer(H.app, 50, step, k);
        return 1;
    }
    H.tries = 0;
    return 0;
}

/* A new frame of scene on d (drawn by the loop), then step next. */
static void redraw(fx_display *d, const char *scene, int next)
{
    if (d == H.own) {
        H.own_scene = scene;
        H.own_mark = H.own_draws;
    } else {
        H.other_scene = scene;
        H.other_mark = H.other_draws;
    }
    fx_app_post_redisplay_on(H.app, d);
    fx_app_timer(H.app, 50, step, next);
}

static int idle(void) { return !fx_display_flip_pending(H.own) && !fx_display_flip_pending(H.other); }

static void step(void *user, int k)
{
    (void)user;
    fx_display_info io, ia;
    fx_display_get_info(H.own, &io);
    fx_display_get_info(H.other, &ia);
    switch (k) {
    case 0: /* both drawn once */
        if (waiting(H.own_draws >= 1 && H.other_draws >= 1 && idle(), k))
            return;
        guest_check("heads-two-on-one-card",
                    !strcmp(io.device, "/dev/dri/card1") && !strcmp(ia.device, "/dev/dri/card1") &&
                        !strcmp(io.connector, HEAD1) && !strcmp(ia.connector, HEAD0) && io.width == 640 &&
                        io.height == 480 && ia.width == 640 && ia.height == 400,
                    "own %s %s %dx%d, added %s %s %dx%d", io.device, io.connector, io.width, io.height, ia.device,
                    ia.connector, ia.width, ia.height);
        guest_check("heads-panel-orientation",
                    io.rotation == 270 && ia.rotation == 90 &&
                        strstr(logbuf, HEAD1 ": panel orientation \"Left Side Up\": rotation 270") &&
                        strstr(logbuf, HEAD0 ": panel orientation \"Right Side Up\": rotation 90"),
                    "head 1 rotation %d (want 270, Left Side Up), head 0 %d (want 90, Right Side Up)", io.rotation,
                    ia.rotation);
        screen(H.other, "heads-head0-picture", "bars", 0);
        screen(H.own, "heads-head1-picture", "checker", 1);
        /* head 1's panel corners, raw 0..4095 over its physical 640x480 */
        tap(0, 4095); /* bottom-left: the viewer's top-left (turned 270) */
        tap(4095, 0); /* top-right: the viewer's bottom-right */
        tap(0, 0);    /* top-left: the viewer's top-right */
        fx_app_timer(H.app, 50, step, 1);
        return;
    case 1: {
        if (waiting(H.nev >= 6, k))
            return;
        static const char *const want[] = {"down 0 0", "up 0 0", "down 479 639", "up 479 639", "down 479 0",
                                           "up 479 0"};
        int32_t w, h;
        fx_app_size(H.app, &w, &h);
        int ok = H.nev == 6 && w == 480 && h == 640;
        char got[400] = "";
        for (int i = 0; i < H.nev; i++) {
            ok = ok && !strcmp(H.ev[i], want[i]);
            snprintf(got + strlen(got), sizeof got - strlen(got), "%s%s", i ? "; " : "", H.ev[i]);
        }
        guest_check("heads-touch-second-head", ok,
                    "logical %dx%d; touches [%s], want [down 0 0; up 0 0; down 479 639; up 479 639; "
                    "down 479 0; up 479 0]", w, h, got);
        H.forced = force("off");
        fx_app_timer(H.app, 50, step, 2);
        return;
    }
    case 2: /* head 1 gone: head 0 keeps its picture, then draws another */
        if (waiting(!io.connected, k))
            return;
        guest_check("heads-hotplug-off",
                    H.forced == 0 && !io.connected && io.hotplugs >= 1 && ia.connected && ia.reshapes == 0,
                    "forced off (%d); head 1 %s after %u hotplugs; head 0 %s, %u reshapes, %u hotplugs seen",
                    H.forced, io.connected ? "still connected" : "gone", io.hotplugs,
                    ia.connected ? "connected" : "gone", ia.reshapes, ia.hotplugs);
        screen(H.other, "heads-hotplug-other-unchanged", "bars", 0);
        redraw(H.other, "checker", 3);
        return;
    case 3:
        if (waiting(H.other_draws > H.other_mark && idle(), k))
            return;
        screen(H.other, "heads-hotplug-other-draws", "checker", 0);
        H.forced = force("on");
        fx_app_timer(H.app, 50, step, 4);
        return;
    case 4: /* head 1 back: modeset again, then a new frame */
        if (waiting(io.connected, k))
            return;
        guest_check("heads-hotplug-on",
                    H.forced == 0 && io.connected && io.hotplugs >= 2 && io.width == 640 && io.height == 480 &&
                        io.rotation == 270 && strstr(logbuf, HEAD1 " connected: 640x480"),
                    "forced on (%d); head 1 connected %d after %u hotplugs, %dx%d rotation %d, modeset %s", H.forced,
                    io.connected, io.hotplugs, io.width, io.height, io.rotation,
                    strstr(logbuf, HEAD1 " connected: 640x480") ? "logged" : "not logged");
        redraw(H.own, "bars", 5);
        return;
    case 5:
        if (waiting(H.own_draws > H.own_mark && idle(), k))
            return;
        screen(H.own, "heads-hotplug-back-picture", "bars", 1);
        screen(H.other, "heads-hotplug-other-after", "checker", 0);
        guest_check("heads-hotplug-other-kept", ia.connected && ia.reshapes == 0 && ia.rotation == 90 &&
                                                    ia.width == 640 && ia.height == 400,
                    "head 0 connected %d, %u reshapes, %dx%d rotation %d through head 1's unplug and replug",
                    ia.connected, ia.reshapes, ia.width, ia.height, ia.rotation);
        fx_app_quit(H.app);
        return;
    }
}

static void heads_child(void *arg)
{
    (void)arg;
    struct libevdev *dev = libevdev_new();
    libevdev_set_name(dev, "fixel heads touchscreen");
    uinput_enable_multitouch(dev, 1);
    H.ts = uinput_create(dev);
    if (!H.ts) {
        guest_check("heads-open", 0, "no uinput touchscreen");
        return;
    }
    fx_app_options o;
    fx_app_options_init(&o);
    fx_app_options_from_env(&o);
    o.display.backend = FX_BACKEND_DRM;
    o.display.connector = "card1:" HEAD1;
    o.display.mode = "640x480"; /* qemu's EDID prefers 1024x768 for a head it has not sized */
    o.display.log = capture_log;
    o.display.log_priority = FX_LOG_DEBUG;
    o.pointer = FX_POINTER_OFF; /* the virtio tablet would show it over the picture */
    o.pointercal = NULL;        /* no /etc/pointercal: range scaling */
    logbuf[0] = 0;
    if (fx_app_open(&H.app, &o) < 0) {
        guest_check("heads-open", 0, "fx_app_open on card1:%s failed", HEAD1);
        return;
    }
    H.own = fx_app_display(H.app);
    fx_display_options d;
    fx_display_options_init(&d);
    d.backend = FX_BACKEND_DRM;
    d.connector = "card1:" HEAD0;
    d.log = capture_log;
    d.log_priority = FX_LOG_DEBUG;
    int r = fx_app_add_display(H.app, &d, draw_other, NULL, &H.other);
    guest_check("heads-open", r == 0, "card1:%s as the app's display, card1:%s added: %s", HEAD1, HEAD0,
                r ? fx_strerror(r) : "ok");
    if (r == 0) {
        H.own_scene = "checker";
        H.other_scene = "bars";
        fx_callbacks cb = {.display = draw_own, .touch = on_touch};
        fx_app_set_callbacks(H.app, &cb, NULL);
        fx_app_timer(H.app, 50, step, 0);
        fx_app_main_loop(H.app);
    }
    fx_app_close(H.app);
    libevdev_uinput_destroy(H.ts);
}

/* The connectors card1 has (sysfs), lowest number first, into out. */
static void card1_connectors(char *out, size_t n)
{
    out[0] = 0;
    for (int num = 1; num < 16; num++) {
        char p[64];
        snprintf(p, sizeof p, "/sys/class/drm/card1-Virtual-%d", num);
        if (access(p, F_OK) == 0)
            snprintf(out + strlen(out), n - strlen(out), "%sVirtual-%d", out[0] ? " " : "", num);
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char conn0[32] = "", conn1[32] = "", detail[300], conns[96], st[32];
    int lr = 0;
    int ok = guest_second_card(conn0, conn1, detail, sizeof detail, &lr);
    card1_connectors(conns, sizeof conns);
    read_line(STATUS1, st, sizeof st);
    guest_check("heads-second-card", lr == 0 && ok && !strcmp(conns, HEAD0 " " HEAD1),
                "loaded %s; card1 connectors \"%s\" (want \"" HEAD0 " " HEAD1 "\"), %s %s before forcing", detail,
                conns, HEAD1, st);
    if (!ok)
        return 1;
    msleep(300); /* the new card's fbdev emulation settles */
    int f = force("on");
    read_line(STATUS1, st, sizeof st);
    guest_check("heads-second-head-plugged", f == 0 && !strcmp(st, "connected"), "forced on: %d, status %s", f,
                st);

    int s = guest_in_child(heads_child, NULL);
    if (!WIFEXITED(s) || WEXITSTATUS(s))
        guest_failed = 1;

    force("detect"); /* as the other programs find it */
    guest_remove_second_card("heads-second-card-removed", "virtio_gpu");
    return guest_failed;
}

#else

int main(void)
{
    /* No two-head card in this guest (see the top of the file). */
    printf("heads: x86_64 guest only\n");
    return 0;
}

#endif
