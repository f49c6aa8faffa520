/* SPDX-License-Identifier: MIT */
/* fx_app_watch_fd: a program's own fd in the main loop's poll (the kiosk's
 * MQTT thread wakes the loop through an eventfd with it). Data written to a
 * pipe from a timer reaches the watch callback in the same loop, before a
 * 2 s safety timer; callbacks may remove watches; the limits hold. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <string.h>
#include <unistd.h>

#include "fixel/app.h"
#include "fixel/error.h"
#include "fx_test.h"

typedef struct watch_state {
    fx_app *app;
    int pipe[2];
    int calls;
    char got[8];
    int quit_by_safety;
} watch_state;

static void on_readable(void *user, int fd)
{
    watch_state *w = user;
    w->calls++;
    ssize_t n = read(fd, w->got, sizeof w->got - 1);
    w->got[n > 0 ? n : 0] = 0;
    /* a callback may stop watching its own fd */
    fx_app_watch_fd(w->app, fd, NULL, NULL);
    fx_app_quit(w->app);
}

static void write_later(void *user, int v)
{
    (void)v;
    watch_state *w = user;
    if (write(w->pipe[1], "ok", 2) != 2)
        w->calls = -100;
}

static void safety(void *user, int v)
{
    (void)v;
    watch_state *w = user;
    w->quit_by_safety = 1;
    fx_app_quit(w->app);
}

static void never(void *user, int fd)
{
    (void)user;
    (void)fd;
}

static fx_app *open_app(void)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 8;
    o.display.memory_h = 8;
    o.display.console = 0;
    o.display.signals = 0;
    o.display.log_priority = -1;
    o.input = 0;
    fx_app *a = NULL;
    return fx_app_open(&a, &o) == 0 ? a : NULL;
}

FX_TEST(app_watch_fd_wakes_the_loop)
{
    static watch_state w;
    memset(&w, 0, sizeof w);
    FX_CHECK(pipe(w.pipe) == 0);
    w.app = open_app();
    FX_CHECK(w.app != NULL);
    if (!w.app)
        return;
    FX_CHECK_EQ(fx_app_watch_fd(w.app, w.pipe[0], on_readable, &w), 0);
    fx_app_timer(w.app, 30, write_later, 0);
    fx_app_timer(w.app, 2000, safety, 0);
    /* timers pass the app's user pointer: the callbacks' state */
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    fx_app_set_callbacks(w.app, &cb, &w);
    FX_CHECK_EQ(fx_app_main_loop(w.app), 0);
    FX_CHECK_EQ(w.calls, 1);
    FX_CHECK(!strcmp(w.got, "ok"));
    FX_CHECK_EQ(w.quit_by_safety, 0);
    /* removed by the callback: removing again is an error */
    FX_CHECK_EQ(fx_app_watch_fd(w.app, w.pipe[0], NULL, NULL), -FX_EINVAL);
    fx_app_close(w.app);
    close(w.pipe[0]);
    close(w.pipe[1]);
}

FX_TEST(app_watch_fd_limits)
{
    fx_app *a = open_app();
    FX_CHECK(a != NULL);
    if (!a)
        return;
    FX_CHECK_EQ(fx_app_watch_fd(a, -1, never, NULL), -FX_EINVAL);
    FX_CHECK_EQ(fx_app_watch_fd(NULL, 0, never, NULL), -FX_EINVAL);
    for (int k = 0; k < FX_APP_MAX_WATCH; k++)
        FX_CHECK_EQ(fx_app_watch_fd(a, 100 + k, never, NULL), 0);
    FX_CHECK_EQ(fx_app_watch_fd(a, 200, never, NULL), -FX_ENOSPC);
    /* watching a watched fd again replaces it and takes no new slot */
    FX_CHECK_EQ(fx_app_watch_fd(a, 100, never, a), 0);
    FX_CHECK_EQ(fx_app_watch_fd(a, 103, NULL, NULL), 0);
    FX_CHECK_EQ(fx_app_watch_fd(a, 200, never, NULL), 0);
    FX_CHECK_EQ(fx_app_watch_fd(a, 201, never, NULL), -FX_ENOSPC);
    fx_app_close(a);
}
