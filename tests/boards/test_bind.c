/* SPDX-License-Identifier: MIT */
/* Input devices bound to displays (docs/displays.md): the choice on fake
 * devices and displays (configuration, the USB and built-in-panel
 * guesses), the binding syntax, and an app with two memory displays whose
 * replayed touchscreens and mice are delivered to the display they are
 * bound to, in that display's rotated coordinates and to its callbacks. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../boards/app/app_int.h"
#include "../../boards/display/display_int.h"
#include "fixel/app.h"
#include "fixel/env.h"
#include "fixel/error.h"
#include "fx_test.h"

/* ---- the choice ---- */

static const fx_bind_disp pi5[] = {
    /* HDMI on vc4, the DSI panel on RP1: the app's own first */
    {"HDMI-A-1", "/sys/devices/platform/axi/107c580000.hdmi", 1},
    {"DSI-1", "/sys/devices/platform/axi/1000120000.pcie/1f00130000.dsi", 1},
};

FX_TEST(bind_builtin_touch_goes_to_the_builtin_panel)
{
    const char *why = NULL;
    fx_bind_dev goodix = {"/dev/input/event4", "Goodix Capacitive TouchScreen",
                          "/sys/devices/platform/axi/1000120000.pcie/1f00088000.i2c/i2c-6/6-0014", 0x18,
                          FX_DEV_TOUCH | FX_DEV_MT};
    FX_CHECK_EQ(fx_bind_choose(&goodix, pi5, 2, NULL, 0, &why), 1);
    FX_CHECK(why && strstr(why, "built-in"));
    /* the same controller on SPI (an SPI panel's ads7846) */
    fx_bind_dev ads = goodix;
    ads.bus = 0x1C;
    ads.cls = FX_DEV_TOUCH;
    FX_CHECK_EQ(fx_bind_choose(&ads, pi5, 2, NULL, 0, &why), 1);
    /* on USB it is not the panel's */
    fx_bind_dev usb = goodix;
    usb.bus = 0x03;
    FX_CHECK_EQ(fx_bind_choose(&usb, pi5, 2, NULL, 0, &why), 0);
    /* a keyboard or a mouse on I2C is never guessed */
    fx_bind_dev kbd = goodix;
    kbd.cls = FX_DEV_KEYBOARD;
    FX_CHECK_EQ(fx_bind_choose(&kbd, pi5, 2, NULL, 0, &why), 0);
    kbd.cls = FX_DEV_MOUSE;
    FX_CHECK_EQ(fx_bind_choose(&kbd, pi5, 2, NULL, 0, &why), 0);
    /* two built-in panels: no guess */
    fx_bind_disp two[] = {pi5[0], pi5[1], {"DPI-1", "/sys/devices/platform/axi/dpi", 1}};
    FX_CHECK_EQ(fx_bind_choose(&goodix, two, 3, NULL, 0, &why), 0);
    FX_CHECK(why && !strcmp(why, "the app's own display"));
    /* ...unless one of them takes no input (no callbacks) */
    two[2].wants_input = 0;
    FX_CHECK_EQ(fx_bind_choose(&goodix, two, 3, NULL, 0, &why), 1);
    /* a panel display without input callbacks is not guessed either */
    fx_bind_disp quiet[] = {pi5[0], {"DSI-1", "", 0}};
    FX_CHECK_EQ(fx_bind_choose(&goodix, quiet, 2, NULL, 0, &why), 0);
    /* eDP and LVDS are built in; HDMI, Virtual and Composite are not */
    fx_bind_disp edp[] = {{"Virtual-1", "", 1}, {"eDP-1", "", 1}, {"Composite-1", "", 1}};
    FX_CHECK_EQ(fx_bind_choose(&goodix, edp, 3, NULL, 0, &why), 1);
    edp[1].connector = "HDMI-A-2";
    FX_CHECK_EQ(fx_bind_choose(&goodix, edp, 3, NULL, 0, &why), 0);
}

FX_TEST(bind_usb_touch_goes_to_the_usb_display_it_sits_with)
{
    const char *why = NULL;
    /* a DisplayLink monitor (hub 3-1 inside: display on 3-1.2, touch on 3-1.3) */
    fx_bind_disp disp[] = {
        {"HDMI-A-1", "/sys/devices/platform/gpu", 1},
        {"DVI-I-1", "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-1/3-1.2/3-1.2:1.0", 1},
    };
    fx_bind_dev touch = {"/dev/input/event7", "ILITEK Multi-Touch",
                         "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-1/3-1.3/3-1.3:1.0/0003:222A:0001.0003",
                         0x03, FX_DEV_TOUCH | FX_DEV_MT};
    FX_CHECK_EQ(fx_bind_choose(&touch, disp, 2, NULL, 0, &why), 1);
    FX_CHECK(why && strstr(why, "USB"));
    /* another port of the root hub is not the monitor's */
    touch.sysfs = "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-2/3-2:1.0/0003:222A:0001.0004";
    FX_CHECK_EQ(fx_bind_choose(&touch, disp, 2, NULL, 0, &why), 0);
    /* a display straight on a root port: only its own USB device counts */
    disp[1].card_sysfs = "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-2/3-2:1.0";
    FX_CHECK_EQ(fx_bind_choose(&touch, disp, 2, NULL, 0, &why), 1);
    touch.sysfs = "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-4/3-4:1.0/x";
    FX_CHECK_EQ(fx_bind_choose(&touch, disp, 2, NULL, 0, &why), 0);
    /* "3-2" must be a whole component: 3-21 is another device */
    touch.sysfs = "/sys/devices/pci0000:00/0000:00:14.0/usb3/3-21/3-21:1.0/x";
    FX_CHECK_EQ(fx_bind_choose(&touch, disp, 2, NULL, 0, &why), 0);
}

FX_TEST(bind_configuration_wins)
{
    const char *why = NULL;
    fx_bind_dev goodix = {"/dev/input/event4", "Goodix Capacitive TouchScreen", "", 0x18, FX_DEV_TOUCH};
    fx_bind_rule r[3];
    int n = 0;
    char err[160];
    FX_CHECK_EQ(fx_bind_parse(" Goodix Capacitive TouchScreen = HDMI-A-1 ; /dev/input/event9=1;", r, 3,
                              &n, err, sizeof err), 0);
    FX_CHECK_EQ(n, 2);
    FX_CHECK(!strcmp(r[0].device, "Goodix Capacitive TouchScreen") && !strcmp(r[0].display, "HDMI-A-1"));
    FX_CHECK(!strcmp(r[1].device, "/dev/input/event9") && !strcmp(r[1].display, "1"));
    /* the guess would say DSI-1; the rule says HDMI */
    FX_CHECK_EQ(fx_bind_choose(&goodix, pi5, 2, r, n, &why), 0);
    FX_CHECK(why && !strcmp(why, "configured"));
    /* by node, and by number */
    fx_bind_dev other = {"/dev/input/event9", "USB Mouse", "", 0x03, FX_DEV_MOUSE};
    FX_CHECK_EQ(fx_bind_choose(&other, pi5, 2, r, n, &why), 1);
    /* by connector, case and card prefix aside */
    snprintf(r[1].display, sizeof r[1].display, "drm-rp1-dsi:dsi-1");
    FX_CHECK_EQ(fx_bind_choose(&other, pi5, 2, r, n, &why), 1);
    /* a display not open: the app's own, and said so */
    snprintf(r[1].display, sizeof r[1].display, "HDMI-A-2");
    FX_CHECK_EQ(fx_bind_choose(&other, pi5, 2, r, n, &why), 0);
    FX_CHECK(why && strstr(why, "not open"));
    snprintf(r[1].display, sizeof r[1].display, "3");
    FX_CHECK_EQ(fx_bind_choose(&other, pi5, 2, r, n, &why), 0);
    /* the name must be the whole name */
    fx_bind_dev near = goodix;
    near.name = "Goodix Capacitive TouchScreen 2";
    FX_CHECK_EQ(fx_bind_choose(&near, pi5, 2, r, n, &why), 1); /* guessed, not configured */
    FX_CHECK(why && strstr(why, "built-in"));
}

FX_TEST(bind_syntax_errors_add_nothing)
{
    fx_bind_rule r[2];
    int n = 0;
    char err[160] = "";
    FX_CHECK_EQ(fx_bind_parse("a=1;no-equals", r, 2, &n, err, sizeof err), -FX_EINVAL);
    FX_CHECK_EQ(n, 0);
    FX_CHECK(strstr(err, "item 2") && strstr(err, "DEVICE=DISPLAY"));
    FX_CHECK_EQ(fx_bind_parse("=1", r, 2, &n, err, sizeof err), -FX_EINVAL);
    FX_CHECK_EQ(fx_bind_parse("a= ", r, 2, &n, err, sizeof err), -FX_EINVAL);
    FX_CHECK_EQ(fx_bind_parse("a=1;b=2;c=3", r, 2, &n, err, sizeof err), -FX_ENOSPC);
    FX_CHECK_EQ(n, 0);
    FX_CHECK(strstr(err, "at most 2"));
    FX_CHECK_EQ(fx_bind_parse("", r, 2, &n, err, sizeof err), 0);
    FX_CHECK_EQ(n, 0);
}

/* ---- delivery: an app with two memory displays, replayed input ---- */

typedef struct rec {
    fx_app *app;
    char log[8][64];
    int n;
    fx_display *panel, *other, *nosuch; /* where the devices were bound at the last frame */
} rec;

static void rec_mouse(void *u, int button, int state, int x, int y)
{
    rec *r = u;
    if (r->n < 8)
        snprintf(r->log[r->n++], sizeof r->log[0], "mouse %d %d %d %d", button, state, x, y);
    fx_app_post_redisplay(r->app); /* the next frame records the bindings */
}

static void rec_touch(void *u, int id, int x, int y, int phase)
{
    rec *r = u;
    if (r->n < 8)
        snprintf(r->log[r->n++], sizeof r->log[0], "touch %d %d %d %d", id, phase, x, y);
}

static void rec_reshape(void *u, int w, int h)
{
    rec *r = u;
    if (r->n < 8)
        snprintf(r->log[r->n++], sizeof r->log[0], "reshape %d %d", w, h);
}

typedef struct bound {
    fx_app *app;
    rec main, second;
} bound;

static void draw_main(void *u)
{
    rec *r = u;
    r->panel = fx_app_input_display(r->app, "Panel Touch");
    r->other = fx_app_input_display(r->app, "replay-1");
    r->nosuch = fx_app_input_display(r->app, "no such device");
    fx_surface s = fx_app_surface(r->app);
    fx_surface_clear(&s, 0xFF000000u);
    fx_app_present(r->app, NULL, 0);
}

static void draw_second(fx_app *a, fx_display *d, void *u)
{
    (void)a, (void)u;
    fx_surface s = fx_display_surface(d);
    fx_surface_clear(&s, 0xFF000000u);
    fx_display_present(d, NULL, 0);
}

static int has(const rec *r, const char *line)
{
    for (int i = 0; i < r->n; i++)
        if (!strcmp(r->log[i], line))
            return 1;
    return 0;
}

static const char *write_replay(const char *text)
{
    static char path[64];
    snprintf(path, sizeof path, "/tmp/fixel-bind-%d.txt", (int)getpid());
    FILE *f = fopen(path, "w");
    if (!f)
        return NULL;
    fputs(text, f);
    fclose(f);
    return path;
}

/* Device 0 ("Panel Touch") is bound to the second display, 40x30 turned
 * 90 degrees, device 1 is not: the same raw corner lands on each display's
 * own pixels. Rotation 90 shows logical (x, y) at physical (W-1-y, x), so
 * physical (px, py) is logical (py, W-1-px). */
static void run_bound(const char *replay, const char *bind_env, int by_call, bound *b)
{
    memset(b, 0, sizeof *b);
    fx_app_options o;
    fx_app_options_init(&o);
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 64;
    o.display.memory_h = 48;
    o.display.log_priority = -1;
    o.replay = write_replay(replay);
    FX_CHECK(o.replay != NULL);
    FX_CHECK_EQ(fx_app_open(&b->app, &o), 0);
    if (!b->app)
        return;
    b->main.app = b->second.app = b->app;
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.display = draw_main;
    cb.mouse = rec_mouse;
    cb.touch = rec_touch;
    cb.reshape = rec_reshape;
    fx_app_set_callbacks(b->app, &cb, &b->main);
    fx_display_options d2 = o.display;
    d2.memory_w = 40;
    d2.memory_h = 30;
    d2.rotation = 90;
    fx_display *second = NULL;
    FX_CHECK_EQ(fx_app_add_display(b->app, &d2, draw_second, b, &second), 0);
    fx_callbacks cb2 = cb;
    cb2.display = NULL;
    FX_CHECK_EQ(fx_app_set_display_callbacks(b->app, second, &cb2, &b->second), 0);
    /* the app's own display through the same call: its callbacks */
    FX_CHECK_EQ(fx_app_set_display_callbacks(b->app, fx_app_display(b->app), &cb, &b->main), 0);
    if (bind_env) {
        setenv("FIXEL_INPUT_BIND", bind_env, 1);
        FX_CHECK_EQ(fx_app_bind_inputs_from_env(b->app), 0);
        unsetenv("FIXEL_INPUT_BIND");
    }
    if (by_call)
        FX_CHECK_EQ(fx_app_bind_input(b->app, "Panel Touch", second), 0);
    FX_CHECK_EQ(fx_app_main_loop(b->app), 0);
    FX_CHECK(b->main.panel == (!bind_env && !by_call ? fx_app_display(b->app) : second));
    FX_CHECK(b->main.other == fx_app_display(b->app));
    FX_CHECK(b->main.nosuch == NULL);
    fx_app_close(b->app);
    unlink(o.replay);
}

static const char *const corner_replay =
    "device 0 touch abs 0 39 0 29 bus i2c name Panel Touch\n"
    "device 1 touch abs 0 39 0 29\n"
    "ev 0 ABS ABS_X 30\nev 0 ABS ABS_Y 5\nev 0 KEY BTN_TOUCH 1\nsyn 0\n"
    "ev 0 KEY BTN_TOUCH 0\nsyn 0\n" /* lifted: one pointer per display */
    "ev 1 ABS ABS_X 39\nev 1 ABS ABS_Y 29\nev 1 KEY BTN_TOUCH 1\nsyn 1\n"
    "frame\n";

FX_TEST(app_bound_touch_arrives_on_its_display)
{
    static const char *const how[] = {"FIXEL_INPUT_BIND", "fx_app_bind_input"};
    for (int k = 0; k < 2; k++) {
        bound b;
        run_bound(corner_replay, k == 0 ? "Panel Touch=1" : NULL, k == 1, &b);
        /* device 0 on the second display: physical (30, 5) -> logical (5, 39 - 30) */
        FX_CHECK_MSG(has(&b.second, "mouse 0 0 5 9"), "%s: second display got %s", how[k],
                     b.second.n > 1 ? b.second.log[1] : "nothing");
        FX_CHECK_MSG(!has(&b.main, "mouse 0 0 5 9"), "%s", how[k]);
        /* device 1 on the app's own 64x48 display: the range's corner is its corner */
        FX_CHECK_MSG(has(&b.main, "mouse 0 0 63 47"), "%s", how[k]);
        FX_CHECK(!has(&b.second, "mouse 0 0 63 47"));
        /* each display's callbacks got its own logical size */
        FX_CHECK(has(&b.main, "reshape 64 48"));
        FX_CHECK(has(&b.second, "reshape 30 40"));
    }
}

FX_TEST(app_unbound_touch_keeps_the_apps_display)
{
    bound b;
    run_bound(corner_replay, NULL, 0, &b);
    /* no binding and no built-in panel among memory displays: both on the
     * app's own display, scaled to 64x48 */
    FX_CHECK(has(&b.main, "mouse 0 0 48 8")); /* (30*63*2+39)/78 = 48, (5*47*2+29)/58 = 8 */
    FX_CHECK(has(&b.main, "mouse 0 0 63 47"));
    FX_CHECK_EQ(b.second.n, 1); /* its reshape only */
    FX_CHECK(has(&b.main, "mouse 0 1 48 8"));

}

FX_TEST(app_bindings_refuse_bad_input)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.input = 0;
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.log_priority = -1;
    fx_app *a = NULL;
    FX_CHECK_EQ(fx_app_open(&a, &o), 0);
    if (!a)
        return;
    fx_display *other = NULL;
    FX_CHECK_EQ(fx_display_open(&other, &o.display), 0);
    FX_CHECK_EQ(fx_app_bind_input(a, "x", other), -FX_EINVAL); /* not the app's display */
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    FX_CHECK_EQ(fx_app_set_display_callbacks(a, other, &cb, NULL), -FX_EINVAL);
    FX_CHECK_EQ(fx_app_bind_input(a, "", fx_app_display(a)), -FX_EINVAL);
    FX_CHECK_EQ(fx_app_bind_inputs(a, "nothing to bind"), -FX_EINVAL);
    setenv("FIXEL_INPUT_BIND", "a=1;b", 1);
    FX_CHECK_EQ(fx_app_bind_inputs_from_env(a), -FX_EINVAL);
    unsetenv("FIXEL_INPUT_BIND");
    int r = 0;
    char name[16];
    for (int i = 0; i <= FX_APP_MAX_BINDS && r == 0; i++) {
        snprintf(name, sizeof name, "dev%d", i);
        r = fx_app_bind_input(a, name, fx_app_display(a));
    }
    FX_CHECK_EQ(r, -FX_ENOSPC);
    /* rebinding a device replaces its rule; NULL removes it */
    FX_CHECK_EQ(fx_app_bind_input(a, "dev0", fx_app_display(a)), 0);
    FX_CHECK_EQ(fx_app_bind_input(a, "dev0", NULL), 0);
    FX_CHECK_EQ(fx_app_bind_input(a, "dev9", fx_app_display(a)), 0);
    fx_display_close(other);
    fx_app_close(a);
}

/* A mouse bound to the added display moves that display's software
 * pointer, in its coordinates, and shows it there (FX_POINTER_AUTO: while
 * a mouse is bound to it); the app's own display shows none. */
FX_TEST(app_bound_mouse_moves_its_displays_pointer)
{
    fx_app_options o;
    fx_app_options_init(&o);
    o.input = 0;
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.memory_w = 64;
    o.display.memory_h = 48;
    o.display.log_priority = -1;
    fx_app *a = NULL;
    FX_CHECK_EQ(fx_app_open(&a, &o), 0);
    if (!a)
        return;
    fx_display_options d2 = o.display;
    d2.memory_w = 40;
    d2.memory_h = 30;
    fx_display *second = NULL;
    FX_CHECK_EQ(fx_app_add_display(a, &d2, NULL, NULL, &second), 0);
    fx_callbacks none;
    memset(&none, 0, sizeof none);
    FX_CHECK_EQ(fx_app_set_display_callbacks(a, second, &none, NULL), 0);
    /* a mouse as the evdev reader would have it, without a device behind it */
    fx_evdev *e = calloc(1, sizeof *e);
    if (!e || !second) {
        free(e);
        fx_app_close(a);
        return;
    }
    e->fd = -1;
    snprintf(e->path, sizeof e->path, "/dev/input/event9");
    snprintf(e->name, sizeof e->name, "USB Mouse");
    e->bus = 0x03;
    fx_input_dev_init(&e->st, FX_DEV_MOUSE);
    a->ev.devs[a->ev.ndevs++] = e;
    fx_app_pointer_sync(a);
    FX_CHECK_EQ(a->disp->ptr.visible, 1); /* unbound: the app's own display's */
    FX_CHECK_EQ(second->ptr.visible, 0);
    FX_CHECK_EQ(fx_app_bind_input(a, "/dev/input/event9", second), 0);
    fx_raw_event mv[] = {{0, FX_IN_REL, FX_IN_REL_X, 7}, {0, FX_IN_REL, FX_IN_REL_Y, -4},
                         {0, FX_IN_SYN, FX_IN_SYN_REPORT, 0}};
    for (int i = 0; i < 3; i++)
        fx_app_feed(a, &e->st, &mv[i]);
    fx_app_pointer_sync(a);
    FX_CHECK_EQ(a->disp->ptr.visible, 0);
    FX_CHECK_EQ(second->ptr.visible, 1);
    /* from the centre of the 40x30 display, not of the 64x48 one */
    FX_CHECK(second->ptr.x == 20 + 7 && second->ptr.y == 15 - 4);
    FX_CHECK(fx_app_input_display(a, "USB Mouse") == second);
    FX_CHECK(fx_app_input_display(a, "/dev/input/event9") == second);
    free(a->ev.devs[--a->ev.ndevs]); /* ours, without an fd */
    fx_app_close(a);
}
