/* SPDX-License-Identifier: MIT */
/* Guest program: the software pointer on real scanout (bochs-drm on x86_64,
 * virtio-gpu with DIRTYFB on aarch64). A uinput relative mouse moves it;
 * the host's screendump must show the bars picture with the arrow at the
 * position the program was told, drawn without a new frame, the program's
 * own surface free of it, and no arrow at all with FIXEL_POINTER=off.
 * Also reports the CPU time of an idle loop with the pointer on. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fixel/app.h"
#include "guest.h"
#include "scenes.h"
#include "uinput.h"

static void quiet(fx_log_priority p, void *u, const char *fmt, va_list ap)
{
    (void)p, (void)u;
    if (p <= FX_LOG_ERROR) {
        vprintf(fmt, ap);
        printf("\n");
    }
}

static struct libevdev_uinput *mouse;

static struct libevdev_uinput *make_mouse(void)
{
    struct libevdev *d = libevdev_new();
    libevdev_set_name(d, "fixel pointer mouse");
    libevdev_enable_event_code(d, EV_REL, REL_X, NULL);
    libevdev_enable_event_code(d, EV_REL, REL_Y, NULL);
    libevdev_enable_event_code(d, EV_KEY, BTN_LEFT, NULL);
    libevdev_enable_event_code(d, EV_KEY, BTN_RIGHT, NULL);
    return uinput_create(d);
}

static void move(int dx, int dy)
{
    libevdev_uinput_write_event(mouse, EV_REL, REL_X, dx);
    libevdev_uinput_write_event(mouse, EV_REL, REL_Y, dy);
    libevdev_uinput_write_event(mouse, EV_SYN, SYN_REPORT, 0);
}

typedef struct run {
    fx_app *app;
    const char *tag;
    int rotation, expect_pointer;
    int frames, px, py, moved;
    int32_t w, h;
    long idle_us;
} run;

static void on_display(void *u)
{
    run *r = u;
    fx_surface s = fx_app_surface(r->app);
    scene_draw("bars", &s);
    fx_app_present(r->app, NULL, 0);
    r->frames++;
}

static void on_passive(void *u, int x, int y)
{
    run *r = u;
    r->px = x;
    r->py = y;
    r->moved++;
}

static long cpu_us(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (long)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1000000L + ru.ru_utime.tv_usec +
           ru.ru_stime.tv_usec;
}

static const char *spec(char *buf, size_t n, const run *r, int x, int y)
{
    if (r->expect_pointer)
        snprintf(buf, n, "bars@%d.%d", x, y);
    else
        snprintf(buf, n, "bars");
    return buf;
}

static void on_step(void *u, int k)
{
    run *r = u;
    char name[64], sp[64];
    int W = r->w, H = r->h; /* the physical screen, as SCREEN wants it */
    switch (k) {
    case 0: /* first frame shown; the pointer starts at the centre */
        snprintf(name, sizeof name, "pointer-%s-first", r->tag);
        if (r->rotation == 0)
            guest_request("SCREEN %s %d %d %d %s", name, W, H, r->rotation,
                          spec(sp, sizeof sp, r, r->w / 2, r->h / 2));
        move(-37, -21);
        fx_app_timer(r->app, 300, on_step, 1);
        break;
    case 1: { /* moved without a frame */
        snprintf(name, sizeof name, "pointer-%s-moved", r->tag);
        guest_request("SCREEN %s %d %d %d %s", name, W, H, r->rotation,
                      spec(sp, sizeof sp, r, r->px, r->py));
        snprintf(name, sizeof name, "pointer-%s-no-frame", r->tag);
        guest_check(name, r->frames == 1 && r->moved > 0, "frames %d, motion callbacks %d at (%d,%d)",
                    r->frames, r->moved, r->px, r->py);
        /* The program's surface: its own bars, no arrow. */
        fx_surface s = fx_app_surface(r->app);
        fx_surface ref;
        int32_t stride = fx_format_min_stride(s.format, s.w);
        void *mem = calloc((size_t)s.h, (size_t)stride);
        int diff = -1;
        if (mem && fx_surface_init(&ref, mem, s.w, s.h, stride, s.format) == 0) {
            scene_draw("bars", &ref);
            diff = 0;
            for (int32_t y = 0; y < s.h; y++)
                for (int32_t x = 0; x < s.w; x++)
                    diff += fx_surface_get_native(&s, x, y) != fx_surface_get_native(&ref, x, y);
        }
        free(mem);
        snprintf(name, sizeof name, "pointer-%s-surface-clean", r->tag);
        guest_check(name, diff == 0, "%d of %dx%d pixels differ from the program's drawing", diff,
                    s.w, s.h);
        /* A move to the edge: clipped there. */
        move(5000, 5000);
        fx_app_timer(r->app, 300, on_step, 2);
        break;
    }
    case 2:
        snprintf(name, sizeof name, "pointer-%s-corner", r->tag);
        guest_request("SCREEN %s %d %d %d %s", name, W, H, r->rotation,
                      spec(sp, sizeof sp, r, r->px, r->py));
        r->idle_us = cpu_us();
        fx_app_timer(r->app, 1000, on_step, 3);
        break;
    case 3:
        r->idle_us = cpu_us() - r->idle_us;
        fx_app_quit(r->app);
        break;
    }
}

static void child(const char *tag, int rotation, const char *env, int expect_pointer)
{
    if (env)
        setenv("FIXEL_POINTER", env, 1);
    else
        unsetenv("FIXEL_POINTER");
    fx_app_options o;
    fx_app_options_init(&o);
    fx_app_options_from_env(&o); /* FIXEL_POINTER=off from init.sh, as the tools do */
    o.display.backend = FX_BACKEND_DRM;
    o.display.rotation = rotation;
    o.display.log = quiet;
    run r;
    memset(&r, 0, sizeof r);
    r.tag = tag;
    r.rotation = rotation;
    r.expect_pointer = expect_pointer;
    char name[64];
    snprintf(name, sizeof name, "pointer-%s-open", tag);
    int e = fx_app_open(&r.app, &o);
    guest_check(name, e == 0, "fx_app_open: %d", e);
    if (e < 0)
        _exit(1);
    fx_display_info info;
    fx_display_get_info(fx_app_display(r.app), &info);
    r.w = info.width;
    r.h = info.height;
    snprintf(name, sizeof name, "pointer-%s-policy", tag);
    guest_check(name, fx_app_pointer_visible(r.app) == expect_pointer,
                "visible %d with FIXEL_POINTER=%s and %d input devices",
                fx_app_pointer_visible(r.app), env ? env : "(unset)", fx_app_input_count(r.app));
    fx_callbacks cb = {.display = on_display, .passive_motion = on_passive};
    fx_app_set_callbacks(r.app, &cb, &r);
    fx_app_timer(r.app, 300, on_step, 0);
    fx_app_main_loop(r.app);
    snprintf(name, sizeof name, "pointer-%s-idle-cpu", tag);
    guest_check(name, r.idle_us < 100000, "%ld us of CPU in 1 s idle (%s presentation, dirtyfb %d)",
                r.idle_us, info.present == FX_PRESENT_DIRECT ? "direct" : "shadow", info.dirtyfb);
    fx_app_close(r.app);
    _exit(guest_failed);
}

static void fork_child(const char *tag, int rotation, const char *env, int expect_pointer)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0)
        child(tag, rotation, env, expect_pointer);
    int st = 0;
    waitpid(pid, &st, 0);
    char name[64];
    snprintf(name, sizeof name, "pointer-%s-exit", tag);
    guest_check(name, WIFEXITED(st) && WEXITSTATUS(st) == 0, "status 0x%x", st);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    mouse = make_mouse();
    guest_check("pointer-uinput-mouse", mouse != NULL, "uinput mouse created");
    if (!mouse)
        return 1;
    fork_child("auto", 0, NULL, 1);
    fork_child("rot90", 90, "auto", 1);
    fork_child("off", 0, "off", 0);
    libevdev_uinput_destroy(mouse);
    return guest_failed;
}
