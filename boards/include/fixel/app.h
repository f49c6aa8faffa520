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
 * comes from a tslib pointercal file (pointercal, else /etc/pointercal when
 * present), and touch = "swap,invertx,inverty" adjusts the axes (the
 * FIXEL_POINTERCAL and FIXEL_TOUCH variables, through fixel/env.h).
 * Coordinates follow the display rotation.
 *
 * Software pointer: an arrow (or a sprite set with fx_app_set_pointer_sprite)
 * drawn over the picture at the mouse position, following the display
 * rotation. It is never part of the program's surface (see
 * fx_display_set_pointer), and a move without a new frame repaints only the
 * old and new sprite rectangles. FX_POINTER_AUTO (the default) shows it
 * while a relative mouse or a tablet is connected, so touch-only systems
 * have none; FX_POINTER_ON/OFF (or FIXEL_POINTER=on|off|auto, through
 * fixel/env.h) override AUTO. It hides on touch
 * input and comes back on the next mouse motion.
 *
 * Driving an app headless (tests of your own program, as fixel tests
 * itself): with the memory backend (FIXEL_BACKEND=memory) nothing needs a
 * device, and three options (or their FIXEL_* variables, through
 * fixel/env.h) make a run scripted and checkable:
 *
 *     FIXEL_BACKEND=memory FIXEL_REPLAY=clicks.txt FIXEL_OUT=frame-%03d.png ./myprog
 *
 *   replay     a file of input statements fed into the main loop instead of
 *              the devices under /dev/input (which are then not opened);
 *              when it ends, and the frame it led to is drawn, the main loop
 *              returns 0.
 *   frames     the main loop returns 0 after this many display callbacks.
 *   frame_out  after each display callback the screen (what
 *              fx_display_screen holds: the presented picture with the
 *              software pointer, physical size) is written to this file,
 *              PNG, or PPM for a .ppm name; one %d (%03d...) is the frame
 *              number, from 1; without one each frame replaces the last.
 *              A file that cannot be written ends the loop with its error.
 *              Displays added with fx_app_add_display write theirs after
 *              each of their draw callbacks, to the name with ".dN" before
 *              the extension (N its display number: f-%03d.d1.png),
 *              numbered by that display's own count.
 *
 * Replay files are the tests/input stream format; '#' starts a comment
 * (except in the character '#'), one statement a line:
 *
 *   device N CLASS[+CLASS] [abs X0 X1 Y0 Y1] [mt X0 X1 Y0 Y1] [bus BUS]
 *          [name NAME...]
 *                     declare virtual device N (0..7); CLASS: keyboard
 *                     mouse touch mt tablet; abs/mt: its axis ranges
 *                     (default: the screen size); BUS (usb i2c spi host
 *                     virtual) and NAME (the rest of the line; default
 *                     replay-N) are what binds it to a display
 *                     (fx_app_bind_input)
 *   ev N TYPE CODE VALUE   a raw evdev event of device N, translated as a
 *                     real device's (rotation, calibration, keymap); TYPE
 *                     and CODE are numbers or names (KEY, REL, ABS,
 *                     REL_X, BTN_LEFT, BTN_TOUCH, ABS_MT_SLOT, KEY_A..KEY_Z,
 *                     KEY_0..KEY_9, KEY_F1..KEY_F12, KEY_ENTER, KEY_ESC,
 *                     KEY_LEFTSHIFT, KEY_UP...)
 *   syn N / dropped N SYN_REPORT / SYN_DROPPED of device N
 *   calib N A0..A6    a tslib pointercal for device N; calibflag N swap|
 *                     invertx|inverty
 *   event TEXT        a logical event, written as fx_event_describe prints
 *                     it: "mouse left down 10 20", "motion 30 40",
 *                     "passive 5 5", "key 99 0 0" (or "key 'c'": the
 *                     pointer's position), "special 100", "wheel 1 10 10",
 *                     "touch 0 down 10 20", "close"; goes to the callbacks
 *                     as fx_app_inject
 *   frame             let the program draw the frame it asked for (if it
 *                     did) before the next statement
 *   wait MS           run the loop (timers, animation) for MS milliseconds
 *   screen W H [ROT]  check the display's physical size and rotation
 * A statement that cannot be used ends the loop with -FX_EINVAL and the
 * file and line logged.
 */
#ifndef FIXEL_APP_H
#define FIXEL_APP_H

#include "fixel/buttons.h"
#include "fixel/display.h"
#include "fixel/event.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_app fx_app;

typedef enum fx_pointer_mode {
    FX_POINTER_AUTO, /* on while a mouse or tablet is present */
    FX_POINTER_ON,   /* shown (still hidden by touch input until the mouse moves) */
    FX_POINTER_OFF,
} fx_pointer_mode;

typedef struct fx_app_options {
    /* [env] as in fx_display_options: fx_app_options_from_env (fixel/env.h)
     * fills these from FIXEL_* variables while they hold their unset value. */
    fx_display_options display;
    int input;              /* 1: use evdev devices (default) */
    const char *input_dir;  /* default "/dev/input" */
    int grab;               /* 1: EVIOCGRAB keyboards so keys never reach the console */
    const char *pointercal; /* [env FIXEL_POINTERCAL] NULL: /etc/pointercal if readable */
    const char *touch;      /* [env FIXEL_TOUCH] "swap,invertx,inverty" (any of them) replaces the
                               calibration's axis flags; NULL: the calibration's */
    const fx_gpio_button *buttons; /* NULL: button_map */
    int nbuttons;
    const char *button_map; /* [env FIXEL_BUTTONS] used when buttons is NULL, in the syntax of
                               fx_gpio_parse_buttons; NULL: the board profile's map */
    fx_pointer_mode pointer; /* [env FIXEL_POINTER] software pointer policy (default AUTO) */
    /* Headless driving (above); unset: NULL / 0. */
    const char *replay;     /* [env FIXEL_REPLAY] replay file: the input instead of /dev/input */
    int frames;             /* [env FIXEL_FRAMES] stop after this many frames; 0: no limit */
    const char *frame_out;  /* [env FIXEL_OUT] write each frame to this file ("f-%03d.png") */
} fx_app_options;

/* Options with every default (then set fields, or fx_app_options_from_env),
 * opening the app (display, input, buttons: 0 or a negative error, the reason
 * logged) and closing it (console and CRTC restored). */
void fx_app_options_init(fx_app_options *o);
int fx_app_open(fx_app **out, const fx_app_options *o);
void fx_app_close(fx_app *a);

/* The GLUT-style callbacks of the app's own display and input (fixel/event.h),
 * each called with user. */
void fx_app_set_callbacks(fx_app *a, const fx_callbacks *cb, void *user);
/* Ask for a display callback (several calls before it runs count once). */
void fx_app_post_redisplay(fx_app *a);
/* The surface to draw the frame into, and showing it (damage as fx_display_present). */
fx_surface fx_app_surface(fx_app *a);
int fx_app_present(fx_app *a, const fx_rect *damage, int n);
/* One-shot timer: fn(user, value) after ms milliseconds. Returns 0 or -FX_ENOSPC. */
int fx_app_timer(fx_app *a, unsigned ms, void (*fn)(void *user, int value), int value);
/* The program's own file descriptor in the loop: fn(user, fd) runs from
 * the loop as soon as fd is readable (or hung up), so data arriving on a
 * pipe, socket or eventfd (another thread's wake-up) is handled at once
 * instead of at the next timer. fn must read what is there (the call
 * repeats while fd stays readable). At most FX_APP_MAX_WATCH fds; watching
 * a watched fd again replaces its function; fn NULL stops watching fd (do
 * it before closing fd). Returns 0, -FX_EINVAL (fd < 0 or a removal of an
 * fd not watched) or -FX_ENOSPC. */
#define FX_APP_MAX_WATCH 8
int fx_app_watch_fd(fx_app *a, int fd, void (*fn)(void *user, int fd), void *user);
/* Run until fx_app_quit, the close callback's signal (SIGINT/SIGTERM/SIGHUP)
 * or a fatal error. Returns 0, or a negative error. */
int fx_app_main_loop(fx_app *a);
void fx_app_quit(fx_app *a);

/* The app's own display (for fx_display_* calls such as power or info). */
fx_display *fx_app_display(fx_app *a);

/* Several displays (docs/displays.md): the app's own display (opened from
 * fx_app_options.display, the one input, the pointer and the callbacks of
 * fx_app_set_callbacks belong to) is unchanged; each further output is
 * opened here with its own options (connector, mode, rotation...) and drawn
 * by its own callback, called from fx_app_main_loop once a frame was asked
 * for with fx_app_post_redisplay_on and no flip of that display is pending
 * (each display is paced by its own vblank). Inside it draw into
 * fx_display_surface(d) and call fx_display_present(d, ...). The displays
 * are closed by fx_app_close (before the app's own, which keeps the console
 * until last). At most FX_APP_MAX_DISPLAYS in all. Returns 0 (with *out set
 * when out is not NULL) or an error (logged); -FX_ENOSPC when full. */
#define FX_APP_MAX_DISPLAYS 4
int fx_app_add_display(fx_app *a, const fx_display_options *o,
                       void (*draw)(fx_app *a, fx_display *d, void *user), void *user, fx_display **out);
/* Ask for a draw callback of display d (added above, or the app's own:
 * then the same as fx_app_post_redisplay). */
void fx_app_post_redisplay_on(fx_app *a, fx_display *d);
/* Input devices bound to displays (docs/displays.md). Every input device
 * belongs to one display of the app: its events arrive in that display's
 * logical coordinates (its size and rotation, the panel's orientation
 * included, so a touchscreen follows its panel) and go to that display's
 * callbacks; its software pointer is that display's. Unbound devices,
 * GPIO buttons and fx_app_inject belong to the app's own display, as with
 * one display.
 *
 * Input callbacks of an added display d (keyboard, special, mouse, motion,
 * passive_motion, wheel, touch, their _up forms, and reshape with d's
 * logical size when the main loop starts); display, idle and close are
 * the app's (set with fx_app_set_callbacks), d's frames are drawn by its
 * draw callback. d may be the app's own display: then the same as
 * fx_app_set_callbacks. Returns 0 or -FX_EINVAL (d is not the app's). */
int fx_app_set_display_callbacks(fx_app *a, fx_display *d, const fx_callbacks *cb, void *user);
/* Bind input device `device` to display d (the app's own or an added
 * one; NULL removes the device's binding): a device node
 * ("/dev/input/event5", or a /dev/input/by-path or by-id link) or the
 * device's name as the kernel gives it (the input log lines print it:
 * "Goodix Capacitive TouchScreen"). It applies to the device now and
 * whenever it is plugged in again, and wins over the automatic choice and
 * over the bindings given before. Returns 0, -FX_EINVAL or -FX_ENOSPC
 * (FX_APP_MAX_BINDS). */
#define FX_APP_MAX_BINDS 8
int fx_app_bind_input(fx_app *a, const char *device, fx_display *d);
/* Bindings as text, "DEVICE=DISPLAY[;DEVICE=DISPLAY...]" (FIXEL_INPUT_BIND,
 * through fixel/env.h): DEVICE as above, DISPLAY a connector name
 * ("DSI-1", "vc4:HDMI-A-2") or a display number (0 the app's own, 1.. the
 * added ones in the order they were added). A display not open (yet)
 * leaves the device on the app's own display until it is added. Returns 0,
 * or -FX_EINVAL / -FX_ENOSPC (logged, nothing added). */
int fx_app_bind_inputs(fx_app *a, const char *spec);
/* The display input device `device` (node or name, as above) is bound to
 * now, or NULL when no such device is open. */
fx_display *fx_app_input_display(fx_app *a, const char *device);
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

/* Dispatch e to the callbacks now, as if an input device had produced it
 * (coordinates are logical pixels; time_us 0: now). For tests and for
 * programs with input of their own. Returns 0 or -FX_EINVAL. */
int fx_app_inject(fx_app *a, const fx_event *e);
/* Display callbacks run so far. */
int fx_app_frame_count(const fx_app *a);

/* GLUT-style calls on the most recently opened app. */
void fx_post_redisplay(void);
int fx_main_loop(void);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
