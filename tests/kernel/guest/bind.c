/* SPDX-License-Identifier: MIT */
/* Guest program: input devices bound to displays, and one connector per
 * display (issue #25), on two DRM cards (card0 and the second device,
 * loaded here from /modules.cards and removed at the end, as multi.c
 * does). run.py turns card1's connector (Virtual-2) with
 * video=Virtual-2:panel_orientation=right_side_up, so the second display
 * is 640x400 shown as 400x640 without any setting.
 *
 * Checked: a second display naming the connector the first drives is
 * refused with the connector in the message; one opened without a name
 * takes the other card's output. An app on card0 with card1's output
 * added, two uinput touchscreens: the one FIXEL_INPUT_BIND binds to
 * Virtual-2 arrives on the added display's callbacks in its turned
 * coordinates (the panel orientation's rotation), the unbound one on the
 * app's own display in its coordinates, and fx_app_input_display says
 * which is which. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fixel/app.h"
#include "fixel/display.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "guest.h"
#include "guest_drm.h"
#include "uinput.h"

static char conn0[32], conn1[32];

static void options(fx_display_options *o, const char *connector)
{
    fx_display_options_init(o);
    o->backend = FX_BACKEND_DRM;
    o->console = 0;
    o->connector = connector;
    o->log = capture_log;
    o->log_priority = FX_LOG_DEBUG;
}

/* ---- one connector, one display --------------------------------------------- */

static void claim_child(void *arg)
{
    (void)arg;
    char c0[48];
    snprintf(c0, sizeof c0, "card0:%s", conn0);
    fx_display_options o;
    options(&o, c0);
    fx_display *a = NULL, *b = NULL, *c = NULL;
    if (guest_open("bind-claim-first", &a, &o) < 0)
        return;
    logbuf[0] = 0;
    options(&o, conn0); /* the same output by its bare name */
    int r = fx_display_open(&b, &o);
    char want[96];
    snprintf(want, sizeof want, "connector %s (/dev/dri/card0) is already driven", conn0);
    guest_check("bind-claim-same-connector", r == -FX_EBUSY && !b && strstr(logbuf, want),
                "second open of %s: %d (%s); log: %s", conn0, r, fx_strerror(r), logbuf);
    fx_display_close(b);
    options(&o, NULL); /* no name: the next free output */
    r = fx_display_open(&c, &o);
    fx_display_info ic;
    if (c)
        fx_display_get_info(c, &ic);
    guest_check("bind-claim-next-free", r == 0 && c && !strcmp(ic.connector, conn1) &&
                                            !strcmp(ic.device, "/dev/dri/card1"),
                "open without a connector: %d, got %s %s (want /dev/dri/card1 %s)", r, c ? ic.device : "-",
                c ? ic.connector : "-", conn1);
    fx_display_close(c);
    fx_display_close(a);
}

/* ---- a touchscreen bound to the second display ------------------------------- */

struct rec {
    char ev[8][40];
    int n;
};
struct bind_run {
    fx_app *app;
    fx_display *second;
    struct libevdev_uinput *bound, *unbound;
    struct rec main, other;
    fx_display *bound_on, *unbound_on;
};
static struct bind_run run;

static void rec_touch(void *u, int id, int x, int y, int ph)
{
    struct rec *r = u;
    (void)id;
    if (r->n < 8)
        snprintf(r->ev[r->n++], 40, "%s %d %d", ph == 0 ? "down" : ph == 1 ? "move" : "up", x, y);
    printf("  %s event: %s %d %d\n", r == &run.main ? "main" : "second", ph == 0 ? "down" : "up", x, y);
}

static void step(void *u, int k)
{
    (void)u;
    /* raw 0..4095 spans each device's display */
    if (k == 0)
        uinput_tap(run.bound, 4095, 0);   /* the panel's top-right corner: the viewer's top-left */
    else if (k == 1)
        uinput_tap(run.unbound, 0, 0);    /* the app's own display, not turned: its top-left */
    else if (k == 2)
        uinput_tap(run.bound, 0, 4095);   /* the panel's bottom-left: the viewer's bottom-right */
    else if (k == 3)
        uinput_tap(run.unbound, 4095, 4095);
    else {
        run.bound_on = fx_app_input_display(run.app, "fixel bound touchscreen");
        run.unbound_on = fx_app_input_display(run.app, "fixel unbound touchscreen");
        fx_app_quit(run.app);
    }
}

static struct libevdev_uinput *touchscreen(const char *name)
{
    struct libevdev *dev = libevdev_new();
    libevdev_set_name(dev, name);
    uinput_enable_multitouch(dev, 1);
    return uinput_create(dev);
}

static const char *joined(const struct rec *r, char *buf, size_t n)
{
    buf[0] = 0;
    for (int i = 0; i < r->n; i++)
        snprintf(buf + strlen(buf), n - strlen(buf), "%s%s", i ? "; " : "", r->ev[i]);
    return buf;
}

static void bound_child(void *arg)
{
    (void)arg;
    run.bound = touchscreen("fixel bound touchscreen");
    run.unbound = touchscreen("fixel unbound touchscreen");
    if (!run.bound || !run.unbound) {
        guest_check("bind-touch-second", 0, "no uinput touchscreens");
        return;
    }
    char c0[48], bind[96];
    snprintf(c0, sizeof c0, "card0:%s", conn0);
    fx_app_options o;
    fx_app_options_init(&o);
    options(&o.display, c0);
    o.pointercal = NULL; /* the guest has no /etc/pointercal: range scaling */
    if (fx_app_open(&run.app, &o) < 0) {
        guest_check("bind-touch-second", 0, "fx_app_open failed: %s", logbuf);
        return;
    }
    fx_display_options o2;
    options(&o2, conn1);
    if (fx_app_add_display(run.app, &o2, NULL, NULL, &run.second) < 0) {
        guest_check("bind-touch-second", 0, "fx_app_add_display %s failed: %s", conn1, logbuf);
        fx_app_close(run.app);
        return;
    }
    fx_callbacks cb = {.touch = rec_touch};
    fx_app_set_callbacks(run.app, &cb, &run.main);
    fx_app_set_display_callbacks(run.app, run.second, &cb, &run.other);
    /* the configuration a user writes: by device name and connector name */
    snprintf(bind, sizeof bind, "fixel bound touchscreen=%s", conn1);
    setenv("FIXEL_INPUT_BIND", bind, 1);
    int br = fx_app_bind_inputs_from_env(run.app);
    for (int k = 0; k < 5; k++)
        fx_app_timer(run.app, (unsigned)(150 + 150 * k), step, k);
    fx_app_main_loop(run.app);
    fx_display_info i1, i2;
    fx_display_get_info(fx_app_display(run.app), &i1);
    fx_display_get_info(run.second, &i2);
    char got[300], want[160];
    /* the added display: 640x400 physical, rotation 90 from the panel */
    static const char *const want2[] = {"down 0 0", "up 0 0", "down 399 639", "up 399 639"};
    int ok = br == 0 && i2.rotation == 90 && i2.width == 640 && i2.height == 400 && run.other.n == 4;
    for (int i = 0; ok && i < 4; i++)
        ok = !strcmp(run.other.ev[i], want2[i]);
    guest_check("bind-touch-second", ok,
                "bind %d; %s %dx%d rotation %d; touches [%s], want [down 0 0; up 0 0; down 399 639; up 399 639]",
                br, i2.connector, i2.width, i2.height, i2.rotation, joined(&run.other, got, sizeof got));
    /* the app's own display, not turned: the unbound device's corners */
    snprintf(want, sizeof want, "down 0 0; up 0 0; down %d %d; up %d %d", i1.width - 1, i1.height - 1,
             i1.width - 1, i1.height - 1);
    joined(&run.main, got, sizeof got);
    guest_check("bind-touch-unbound-main", i1.rotation == 0 && !strcmp(got, want),
                "%s %dx%d; touches [%s], want [%s]", i1.connector, i1.width, i1.height, got, want);
    guest_check("bind-input-display", run.bound_on == run.second && run.unbound_on == fx_app_display(run.app),
                "bound device on %s, unbound on %s", run.bound_on == run.second ? "the added display" : "another",
                run.unbound_on == fx_app_display(run.app) ? "the app's own" : "another");
    fx_app_close(run.app);
    libevdev_uinput_destroy(run.bound);
    libevdev_uinput_destroy(run.unbound);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char detail[300];
    int lr = 0;
    int ok = guest_second_card(conn0, conn1, detail, sizeof detail, &lr);
    guest_check("bind-second-card", lr == 0 && ok, "loaded %s; card1 %s", detail, ok ? "present" : "missing");
    if (!ok)
        return 1;
    msleep(300); /* the new card's fbdev emulation and fbcon settle */
    int st = guest_in_child(claim_child, NULL);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;
    st = guest_in_child(bound_child, NULL);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;
    guest_remove_second_card("bind-second-card-removed", CARD1_MODULE);
    return guest_failed;
}
