/* SPDX-License-Identifier: MIT */
/* Guest program: input and the main loop on real kernel devices — uinput
 * mice, multitouch screens and keyboards, qemu's virtio tablet driven from
 * the host, gpio-sim lines as bouncing buttons and an LED, hotplug and
 * unplug, and the permission message for a user outside the input group.
 * Every case records the callbacks the app delivers and compares them with
 * what the injected events must produce (CHECK lines for the host). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "fixel/app.h"
#include "fixel/error.h"
#include "guest.h"
#include "uinput.h"

/* ---- recording callbacks ---- */
typedef struct rec {
    char ev[64][64];
    int n;
    fx_app *app;
    void (*step)(struct rec *r, int k);
} rec;

static void add(rec *r, const char *fmt, ...)
{
    if (r->n >= 64)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->ev[r->n++], 64, fmt, ap);
    va_end(ap);
    printf("  event: %s\n", r->ev[r->n - 1]);
}
static void cb_key(void *u, unsigned char k, int x, int y) { add(u, "key %d %d %d", k, x, y); }
static void cb_keyup(void *u, unsigned char k, int x, int y) { add(u, "keyup %d %d %d", k, x, y); }
static void cb_special(void *u, int k, int x, int y) { add(u, "special %d %d %d", k, x, y); }
static void cb_mouse(void *u, int b, int s, int x, int y)
{
    add(u, "mouse %s %s %d %d", b == 0 ? "left" : b == 1 ? "middle" : "right", s == FX_DOWN ? "down" : "up", x, y);
}
static void cb_motion(void *u, int x, int y) { add(u, "motion %d %d", x, y); }
static void cb_passive(void *u, int x, int y) { add(u, "passive %d %d", x, y); }
static void cb_wheel(void *u, int d, int x, int y) { add(u, "wheel %d %d %d", d, x, y); }
static void cb_touch(void *u, int id, int x, int y, int ph)
{
    add(u, "touch %d %s %d %d", id, ph == 0 ? "down" : ph == 1 ? "move" : "up", x, y);
}
static void on_step(void *u, int k)
{
    rec *r = u;
    if (k < 0) {
        fx_app_quit(r->app);
        return;
    }
    r->step(r, k);
}

static int open_app(fx_app **a, int rotation, const char *pointercal, const fx_gpio_button *b, int nb)
{
    fx_app_options o;
    fx_app_options_init(&o);
    fx_app_options_from_env(&o); /* FIXEL_POINTER=off from init.sh, as the tools do */
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 800;
    o.display.memory_h = 480;
    o.display.rotation = rotation;
    o.display.console = 0;
    o.display.log = capture_log;
    o.display.log_priority = FX_LOG_DEBUG;
    o.pointercal = pointercal;
    o.buttons = b;
    o.nbuttons = nb;
    logbuf[0] = 0;
    return fx_app_open(a, &o);
}

static void run(rec *r, int steps, int step_ms)
{
    fx_callbacks cb = {.keyboard = cb_key, .keyboard_up = cb_keyup, .special = cb_special,
                       .mouse = cb_mouse, .motion = cb_motion, .passive_motion = cb_passive,
                       .wheel = cb_wheel, .touch = cb_touch};
    fx_app_set_callbacks(r->app, &cb, r);
    for (int k = 0; k < steps; k++)
        fx_app_timer(r->app, (unsigned)(50 + k * step_ms), on_step, k);
    fx_app_timer(r->app, (unsigned)(50 + steps * step_ms + 300), on_step, -1);
    fx_app_main_loop(r->app);
}

static int expect_seq(const char *name, rec *r, const char *const *want, int n)
{
    int ok = r->n == n;
    for (int i = 0; ok && i < n; i++)
        ok = !strcmp(r->ev[i], want[i]);
    char got[600] = "";
    for (int i = 0; i < r->n && strlen(got) < 500; i++)
        snprintf(got + strlen(got), sizeof got - strlen(got), "%s%s", i ? "; " : "", r->ev[i]);
    guest_check(name, ok, "got [%s]", got);
    return ok;
}

static int has(rec *r, const char *s)
{
    for (int i = 0; i < r->n; i++)
        if (!strcmp(r->ev[i], s))
            return 1;
    return 0;
}

/* ---- uinput devices ---- */
static struct libevdev_uinput *make_dev(const char *name, int kind)
{
    struct libevdev *d = libevdev_new();
    libevdev_set_name(d, name);
    if (kind == 0) { /* relative mouse */
        libevdev_enable_event_code(d, EV_REL, REL_X, NULL);
        libevdev_enable_event_code(d, EV_REL, REL_Y, NULL);
        libevdev_enable_event_code(d, EV_REL, REL_WHEEL, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_LEFT, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_RIGHT, NULL);
        libevdev_enable_event_code(d, EV_KEY, BTN_MIDDLE, NULL);
    } else if (kind == 1) { /* multitouch screen */
        uinput_enable_multitouch(d, 4);
    } else { /* keyboard */
        for (int k = KEY_ESC; k <= KEY_F10; k++)
            libevdev_enable_event_code(d, EV_KEY, (unsigned)k, NULL);
        libevdev_enable_event_code(d, EV_KEY, KEY_UP, NULL);
    }
    return uinput_create(d);
}

static struct libevdev_uinput *mouse, *touch, *kbd;
static void w(struct libevdev_uinput *u, unsigned t, unsigned c, int v)
{
    libevdev_uinput_write_event(u, t, c, v);
}
static void syn(struct libevdev_uinput *u) { w(u, EV_SYN, SYN_REPORT, 0); }

static void mouse_steps(rec *r, int k)
{
    (void)r;
    switch (k) {
    case 0: w(mouse, EV_REL, REL_X, 10); w(mouse, EV_REL, REL_Y, 5); syn(mouse); break;
    case 1: w(mouse, EV_KEY, BTN_LEFT, 1); syn(mouse); break;
    case 2: w(mouse, EV_REL, REL_X, 3); syn(mouse); break;
    case 3: w(mouse, EV_KEY, BTN_LEFT, 0); syn(mouse); break;
    case 4: w(mouse, EV_REL, REL_WHEEL, 1); syn(mouse); break;
    case 5: w(mouse, EV_REL, REL_X, -5000); syn(mouse); break;
    }
}

static void touch_steps(rec *r, int k)
{
    (void)r;
    switch (k) {
    case 0:
        w(touch, EV_ABS, ABS_MT_SLOT, 0);
        w(touch, EV_ABS, ABS_MT_TRACKING_ID, 7);
        w(touch, EV_ABS, ABS_MT_POSITION_X, 400);
        w(touch, EV_ABS, ABS_MT_POSITION_Y, 2000);
        w(touch, EV_ABS, ABS_X, 400);
        w(touch, EV_ABS, ABS_Y, 2000);
        w(touch, EV_KEY, BTN_TOUCH, 1);
        syn(touch);
        break;
    case 1:
        w(touch, EV_ABS, ABS_MT_SLOT, 1);
        w(touch, EV_ABS, ABS_MT_TRACKING_ID, 8);
        w(touch, EV_ABS, ABS_MT_POSITION_X, 1000);
        w(touch, EV_ABS, ABS_MT_POSITION_Y, 1000);
        syn(touch);
        break;
    case 2:
        w(touch, EV_ABS, ABS_MT_TRACKING_ID, -1);
        w(touch, EV_ABS, ABS_MT_SLOT, 0);
        w(touch, EV_ABS, ABS_MT_TRACKING_ID, -1);
        w(touch, EV_KEY, BTN_TOUCH, 0);
        syn(touch);
        break;
    }
}

static void key_steps(rec *r, int k)
{
    (void)r;
    switch (k) {
    case 0: w(kbd, EV_KEY, KEY_LEFTSHIFT, 1); w(kbd, EV_KEY, KEY_A, 1); syn(kbd); break;
    case 1: w(kbd, EV_KEY, KEY_A, 0); w(kbd, EV_KEY, KEY_LEFTSHIFT, 0); syn(kbd); break;
    case 2: w(kbd, EV_KEY, KEY_F1, 1); w(kbd, EV_KEY, KEY_F1, 0); syn(kbd); break;
    case 3: w(kbd, EV_KEY, KEY_UP, 1); syn(kbd); break;
    }
}

static int unplug_count_before, unplug_count_after;
static void unplug_steps(rec *r, int k)
{
    switch (k) {
    case 0:
        unplug_count_before = fx_app_input_count(r->app);
        libevdev_uinput_destroy(mouse);
        mouse = NULL;
        break;
    case 1: /* the loop has noticed by now; others still work */
        unplug_count_after = fx_app_input_count(r->app);
        w(kbd, EV_KEY, KEY_B, 1);
        w(kbd, EV_KEY, KEY_B, 0);
        syn(kbd);
        break;
    case 2: mouse = make_dev("fixel hotplug mouse", 0); break;
    case 3: w(mouse, EV_KEY, BTN_RIGHT, 1); syn(mouse); break;
    }
}

static void tap_steps(rec *r, int k)
{
    (void)r;
    if (k == 0)
        guest_request("TAP 16384 8192");
}

/* ---- gpio-sim ---- */
static char sim_dev[64], sim_chip[64];
static int gpio_sim_setup(void)
{
    const char *b = "/sys/kernel/config/gpio-sim/fx";
    char p[256];
    mkdir(b, 0755);
    snprintf(p, sizeof p, "%s/bank0", b);
    mkdir(p, 0755);
    snprintf(p, sizeof p, "%s/bank0/num_lines", b);
    write_file(p, "4");
    const char *names[] = {"BUTTON_A", "LED_1", "BUTTON_B"};
    for (int i = 0; i < 3; i++) {
        snprintf(p, sizeof p, "%s/bank0/line%d", b, i);
        mkdir(p, 0755);
        snprintf(p, sizeof p, "%s/bank0/line%d/name", b, i);
        write_file(p, names[i]);
    }
    snprintf(p, sizeof p, "%s/live", b);
    if (write_file(p, "1") < 0)
        return -1;
    snprintf(p, sizeof p, "%s/dev_name", b);
    read_line(p, sim_dev, sizeof sim_dev);
    snprintf(p, sizeof p, "%s/bank0/chip_name", b);
    read_line(p, sim_chip, sizeof sim_chip);
    printf("  gpio-sim: %s %s\n", sim_dev, sim_chip);
    return sim_chip[0] ? 0 : -1;
}
static void pull(int line, int up)
{
    char p[256];
    snprintf(p, sizeof p, "/sys/devices/platform/%s/%s/sim_gpio%d/pull", sim_dev, sim_chip, line);
    write_file(p, up ? "pull-up" : "pull-down");
}
static void *bouncer(void *arg)
{
    (void)arg;
    msleep(80);
    /* a bouncing press: 5 edges within 6 ms, then held */
    for (int i = 0; i < 5; i++) {
        pull(0, i % 2 == 0);
        msleep(1);
    }
    pull(0, 1);
    msleep(150);
    /* a bouncing release */
    for (int i = 0; i < 4; i++) {
        pull(0, i % 2);
        msleep(1);
    }
    pull(0, 0);
    msleep(100);
    /* a glitch shorter than the debounce time: nothing */
    pull(0, 1);
    msleep(2);
    pull(0, 0);
    msleep(100);
    /* the button found by line name */
    pull(2, 1);
    msleep(100);
    pull(2, 0);
    return NULL;
}
static void gpio_steps(rec *r, int k) { (void)r; (void)k; }

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    rec r;

    /* 1. a user outside the input group is told which group it needs */
    pid_t pid = fork();
    if (pid == 0) {
        if (setgid(1000) || setgroups(0, NULL) || setuid(1000))
            _exit(2);
        fx_app *a;
        int rc = open_app(&a, 0, NULL, NULL, 0);
        int ok = rc == 0 && fx_app_input_count(a) == 0 && strstr(logbuf, "'input'") != NULL;
        guest_check("input-permission-hint", ok, "open %d, devices %d, log: %.200s", rc,
                    rc == 0 ? fx_app_input_count(a) : -1, logbuf);
        if (rc == 0)
            fx_app_close(a);
        fflush(stdout);
        _exit(0);
    }
    int st;
    waitpid(pid, &st, 0);

    mouse = make_dev("fixel test mouse", 0);
    touch = make_dev("fixel test touchscreen", 1);
    kbd = make_dev("fixel test keyboard", 2);
    guest_check("uinput-devices", mouse && touch && kbd, "mouse %p touch %p keyboard %p",
                (void *)mouse, (void *)touch, (void *)kbd);
    if (!mouse || !touch || !kbd)
        return 1;

    /* 2. relative mouse: passive, button, drag, wheel, clamping */
    memset(&r, 0, sizeof r);
    if (open_app(&r.app, 0, NULL, NULL, 0) == 0) {
        r.step = mouse_steps;
        run(&r, 6, 40);
        const char *want[] = {"passive 410 245", "mouse left down 410 245", "motion 413 245",
                              "mouse left up 413 245", "wheel 1 413 245", "passive 0 245"};
        expect_seq("input-mouse", &r, want, 6);
        fx_app_close(r.app);
    }

    /* 3. multitouch + calibration + 90 degree rotation */
    FILE *f = fopen("/tmp/pointercal", "w");
    if (f) {
        fputs("0 16384 -655360 16384 0 327680 65536\n", f);
        fclose(f);
    }
    memset(&r, 0, sizeof r);
    if (open_app(&r.app, 90, "/tmp/pointercal", NULL, 0) == 0) {
        r.step = touch_steps;
        run(&r, 3, 40);
        /* raw (400, 2000) -> physical (490, 105) -> logical (105, 309);
         * raw (1000, 1000) -> physical (240, 255) -> logical (255, 559) */
        const char *want[] = {"passive 105 309",     "mouse left down 105 309", "touch 0 down 105 309",
                              "touch 1 down 255 559", "mouse left up 105 309",   "touch 0 up 105 309",
                              "touch 1 up 255 559"};
        expect_seq("input-touch-rot90-calibrated", &r, want, 7);
        fx_app_close(r.app);
    }

    /* 4. keyboard with modifiers and special keys */
    memset(&r, 0, sizeof r);
    if (open_app(&r.app, 0, NULL, NULL, 0) == 0) {
        r.step = key_steps;
        run(&r, 4, 40);
        const char *want[] = {"key 65 400 240", "keyup 65 400 240", "special 1 400 240",
                              "special 101 400 240"};
        expect_seq("input-keyboard", &r, want, 4);
        fx_app_close(r.app);
    }

    /* 5. unplug mid-run, then plug a new device in */
    memset(&r, 0, sizeof r);
    if (open_app(&r.app, 0, NULL, NULL, 0) == 0) {
        r.step = unplug_steps;
        run(&r, 4, 80);
        int ok = unplug_count_after == unplug_count_before - 1 && has(&r, "key 98 400 240") &&
                 has(&r, "mouse right down 400 240") && strstr(logbuf, "was unplugged") != NULL;
        guest_check("input-unplug-hotplug", ok, "devices %d -> %d, %d events", unplug_count_before,
                    unplug_count_after, r.n);
        fx_app_close(r.app);
    }

    /* 6. qemu's virtio tablet, tapped from the host (0..32767 on each axis) */
    memset(&r, 0, sizeof r);
    if (open_app(&r.app, 0, NULL, NULL, 0) == 0) {
        r.step = tap_steps;
        run(&r, 1, 40);
        int ok = has(&r, "mouse left down 400 120") && has(&r, "mouse left up 400 120");
        guest_check("input-virtio-tablet-tap", ok, "%d events, first '%s'", r.n, r.n ? r.ev[0] : "");
        fx_app_close(r.app);
    }

    /* 7. gpio-sim: bouncing buttons give one press, an output drives an LED */
    if (gpio_sim_setup() == 0) {
        fx_gpio_button b[2] = {{sim_chip, 0, NULL, 0, 20, 'a', 0}, {NULL, -1, "BUTTON_B", 0, 20, FX_KEY_F2, 1}};
        memset(&r, 0, sizeof r);
        if (open_app(&r.app, 0, NULL, b, 2) == 0) {
            r.step = gpio_steps;
            pthread_t t;
            pthread_create(&t, NULL, bouncer, NULL);
            run(&r, 1, 700); /* the bouncer's script takes ~550 ms */
            pthread_join(t, NULL);
            const char *want[] = {"key 97 400 240", "keyup 97 400 240", "special 2 400 240"};
            expect_seq("gpio-button-debounce", &r, want, 3);
            char p[256], v[16] = "";
            snprintf(p, sizeof p, "/sys/devices/platform/%s/%s/sim_gpio1/value", sim_dev, sim_chip);
            int r1 = fx_app_gpio_output(r.app, sim_chip, 1, 1);
            read_line(p, v, sizeof v);
            int on = r1 == 0 && !strcmp(v, "1");
            fx_app_gpio_output(r.app, sim_chip, 1, 0);
            read_line(p, v, sizeof v);
            guest_check("gpio-led-output", on && !strcmp(v, "0"), "set %d, value now %s", r1, v);
            fx_app_close(r.app);
        }
    } else {
        guest_check("gpio-sim-setup", 0, "could not create a gpio-sim chip");
    }
    if (mouse)
        libevdev_uinput_destroy(mouse);
    libevdev_uinput_destroy(touch);
    libevdev_uinput_destroy(kbd);
    return guest_failed;
}
