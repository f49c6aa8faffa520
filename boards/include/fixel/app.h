/* SPDX-License-Identifier: MIT */
/* fixel — the program's view: a display, input devices and GPIO buttons
 * behind GLUT-style callbacks and one main loop.
 *
 *     fx_app *app;
 *     fx_app_options o;
 *     fx_app_options_init(&o);
 *     if (fx_app_open(&app, &o) < 0) return 1;   // reason already logged
 *     fx_callbacks cb = {.display = draw, .keyboard = key, .mouse = click};
 *     fx_app_set_callbacks(app, &cb, &state);
 *     fx_app_main_loop(app);                     // until quit, close or a signal
 *     fx_app_close(app);                         // console and CRTC restored
 *
 * The loop sleeps in poll() over the DRM fd, every input and GPIO fd, an
 * inotify fd on /dev/input (hotplug), a timerfd and a signalfd: an idle
 * program uses no CPU. The display callback runs when a frame was asked for
 * with fx_app_post_redisplay and no page flip is pending, so frames are paced
 * by vblank. Inside it, draw into fx_app_surface() and call fx_app_present().
 *
 * Input devices are found under /dev/input and classified (keyboard,
 * relative mouse, touchscreen, multitouch, tablet); devices plugged in later
 * are picked up, unplugged ones dropped with one log line. Touch calibration
 * comes from a tslib pointercal file (FIXEL_POINTERCAL, else /etc/pointercal
 * when present), and FIXEL_TOUCH=swap,invertx,inverty adjusts the axes.
 * Coordinates follow the display rotation.
 *
 * Software pointer: an arrow (or a sprite set with fx_app_set_pointer_sprite)
 * drawn over the picture at the mouse position, following the display
 * rotation. It is never part of the program's surface (see
 * fx_display_set_pointer), and a move without a new frame repaints only the
 * old and new sprite rectangles. FX_POINTER_AUTO (the default) shows it
 * while a relative mouse or a tablet is connected, so touch-only systems
 * have none; FIXEL_POINTER=on|off|auto overrides AUTO. It hides on touch
 * input and comes back on the next mouse motion.
 */
#ifndef FIXEL_APP_H
#define FIXEL_APP_H

#include "fixel/display.h"
#include "fixel/event.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_app fx_app;

typedef enum fx_pointer_mode {
    FX_POINTER_AUTO, /* FIXEL_POINTER=on|off|auto, else on while a mouse or tablet is present */
    FX_POINTER_ON,   /* shown (still hidden by touch input until the mouse moves) */
    FX_POINTER_OFF,
} fx_pointer_mode;

/* A GPIO push button. */
typedef struct fx_gpio_button {
    const char *chip;     /* "gpiochip0", "0" or a path; NULL: search every chip for name */
    int offset;           /* line offset, or -1 to look the line up by name */
    const char *name;     /* line name (used when offset < 0) */
    int active_low;       /* 1: pressed pulls the line low */
    unsigned debounce_ms; /* 0: 20 ms */
    int key;              /* character (keyboard callback) or, with special = 1, FX_KEY_* */
    int special;
} fx_gpio_button;

typedef struct fx_app_options {
    fx_display_options display;
    int input;              /* 1: use evdev devices (default) */
    const char *input_dir;  /* default "/dev/input" */
    int grab;               /* 1: EVIOCGRAB keyboards so keys never reach the console */
    const char *pointercal; /* NULL: FIXEL_POINTERCAL, else /etc/pointercal if readable */
    const fx_gpio_button *buttons; /* NULL: FIXEL_BUTTONS, else the board's default map
                                    * (see fx_gpio_parse_buttons) */
    int nbuttons;
    fx_pointer_mode pointer; /* software pointer policy (default AUTO) */
} fx_app_options;

void fx_app_options_init(fx_app_options *o);
int fx_app_open(fx_app **out, const fx_app_options *o);
void fx_app_close(fx_app *a);

void fx_app_set_callbacks(fx_app *a, const fx_callbacks *cb, void *user);
/* Ask for a display callback (several calls before it runs count once). */
void fx_app_post_redisplay(fx_app *a);
/* The surface to draw the frame into, and showing it (damage as fx_display_present). */
fx_surface fx_app_surface(fx_app *a);
int fx_app_present(fx_app *a, const fx_rect *damage, int n);
/* One-shot timer: fn(user, value) after ms milliseconds. Returns 0 or -FX_ENOSPC. */
int fx_app_timer(fx_app *a, unsigned ms, void (*fn)(void *user, int value), int value);
/* Run until fx_app_quit, the close callback's signal (SIGINT/SIGTERM/SIGHUP)
 * or a fatal error. Returns 0, or a negative error. */
int fx_app_main_loop(fx_app *a);
void fx_app_quit(fx_app *a);

fx_display *fx_app_display(fx_app *a);
/* The logical screen size (after rotation). */
void fx_app_size(const fx_app *a, int32_t *w, int32_t *h);
/* Drive a GPIO output line (LED, backlight): requested on first use. */
int fx_app_gpio_output(fx_app *a, const char *chip, int offset, int value);
/* Software pointer policy (FX_POINTER_AUTO here means the automatic rule,
 * not the environment), and its image (copied; NULL: the built-in arrow).
 * set_pointer_sprite returns 0 or -FX_EINVAL (see fx_sprite_check). */
void fx_app_set_pointer(fx_app *a, fx_pointer_mode mode);
int fx_app_set_pointer_sprite(fx_app *a, const fx_sprite *s);
/* 1 while the pointer is meant to be on screen. */
int fx_app_pointer_visible(const fx_app *a);
/* Number of input devices and GPIO buttons open now. */
int fx_app_input_count(const fx_app *a);

/* GLUT-style calls on the most recently opened app. */
void fx_post_redisplay(void);
int fx_main_loop(void);

/* Parse "CHIP:LINE=KEY[/low][@MS],..." (LINE: offset or line name; an empty
 * CHIP searches every chip for the line name; /low: active low with the
 * pull-up enabled; @MS: debounce time; KEY: a
 * single character, or up, down, left, right, pageup, pagedown, home, end,
 * insert, f1..f12, enter, esc, space, tab). Names point into buf, which is
 * modified. Returns the number of buttons, or -FX_EINVAL. */
int fx_gpio_parse_buttons(char *buf, fx_gpio_button *out, int max);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
