/* SPDX-License-Identifier: MIT */
/* fixel — raw input to events: pure translation from evdev-style events
 * (type, code, value, as the kernel reports them) to fx_event, with device
 * classes, pointer state, multitouch slots, touch calibration, display
 * rotation, a US keyboard layout and GPIO button debouncing.
 *
 * The boards side reads the kernel (libevdev, libgpiod) and feeds this;
 * tests feed recorded streams. Nothing here touches a device.
 */
#ifndef FIXEL_INPUT_H
#define FIXEL_INPUT_H

#include <stdint.h>
#include "fixel/event.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Event types and codes: the values of <linux/input-event-codes.h>, named
 * here because the core may not include kernel headers. */
enum {
    FX_IN_SYN = 0x00, FX_IN_KEY = 0x01, FX_IN_REL = 0x02, FX_IN_ABS = 0x03,
    FX_IN_SYN_REPORT = 0, FX_IN_SYN_DROPPED = 3,
    FX_IN_REL_X = 0x00, FX_IN_REL_Y = 0x01, FX_IN_REL_HWHEEL = 0x06, FX_IN_REL_WHEEL = 0x08,
    FX_IN_ABS_X = 0x00, FX_IN_ABS_Y = 0x01,
    FX_IN_ABS_MT_SLOT = 0x2f, FX_IN_ABS_MT_POSITION_X = 0x35, FX_IN_ABS_MT_POSITION_Y = 0x36,
    FX_IN_ABS_MT_TRACKING_ID = 0x39,
    FX_IN_BTN_LEFT = 0x110, FX_IN_BTN_RIGHT = 0x111, FX_IN_BTN_MIDDLE = 0x112,
    FX_IN_BTN_TOOL_PEN = 0x140, FX_IN_BTN_TOUCH = 0x14a, FX_IN_BTN_STYLUS = 0x14b,
};

/* Device classes (a bit set: a touchscreen with slots is TOUCH | MT). */
enum {
    FX_DEV_KEYBOARD = 1,
    FX_DEV_MOUSE = 2,  /* relative pointer */
    FX_DEV_TOUCH = 4,  /* absolute, direct (touchscreen) */
    FX_DEV_MT = 8,     /* multitouch slots (protocol B) */
    FX_DEV_TABLET = 16 /* absolute, pen */
};

#define FX_INPUT_MAX_SLOTS 10

typedef struct fx_raw_event {
    uint64_t time_us;
    uint16_t type, code;
    int32_t value;
} fx_raw_event;

/* Touch calibration: tslib's pointercal model, x' = (a2 + a0*x + a1*y) / a6,
 * y' = (a5 + a3*x + a4*y) / a6 from raw device units to physical screen
 * pixels; when not valid, the device's absolute range is scaled to the
 * screen. Then swap_xy / invert_x / invert_y, then display rotation. */
typedef struct fx_calib {
    int32_t a[7];
    uint8_t valid;
    uint8_t swap_xy, invert_x, invert_y;
    /* optional range override for scaling (used when min < max) */
    int32_t xmin, xmax, ymin, ymax;
} fx_calib;

typedef struct fx_input_dev {
    unsigned cls;
    int32_t abs_min[2], abs_max[2];    /* ABS_X, ABS_Y ranges */
    int32_t mt_min[2], mt_max[2];      /* ABS_MT_POSITION_X/Y ranges */
    fx_calib calib;
    /* state collected until SYN_REPORT */
    int32_t abs[2], rel[2], wheel;
    uint8_t abs_dirty, dropped;
    uint16_t btn_changed, btn_state; /* bit 0 left, 1 right, 2 middle, 3 touch */
    int slot;
    struct {
        int32_t id, x, y;
        uint8_t active, was_active, dirty;
    } slots[FX_INPUT_MAX_SLOTS];
} fx_input_dev;

/* The shared pointer and keyboard state of one screen. */
typedef struct fx_input {
    int32_t phys_w, phys_h; /* physical (unrotated) screen size */
    int rotation;           /* 0, 90, 180, 270 clockwise, as the display */
    int32_t px, py;         /* pointer, physical pixels */
    unsigned buttons;       /* FX_BUTTON_* bits held (1 << button) */
    unsigned mods;          /* FX_MOD_* */
    uint8_t shift_l, shift_r, ctrl_l, ctrl_r, alt_l, alt_r, caps;
} fx_input;

typedef void (*fx_emit_fn)(void *user, const fx_event *e);

/* phys_w x phys_h is the physical screen; rotation as fx_display. The
 * pointer starts at the centre. */
void fx_input_init(fx_input *in, int32_t phys_w, int32_t phys_h, int rotation);
/* cls from FX_DEV_*; absolute ranges default to the screen size. */
void fx_input_dev_init(fx_input_dev *d, unsigned cls);
/* Feed one raw event; complete events are emitted (possibly several). */
void fx_input_feed(fx_input *in, fx_input_dev *d, const fx_raw_event *ev, fx_emit_fn emit,
                   void *user);
/* Physical pixel -> logical pixel under the rotation. */
void fx_input_to_logical(const fx_input *in, int32_t px, int32_t py, int32_t *lx, int32_t *ly);
/* The logical screen size. */
void fx_input_logical_size(const fx_input *in, int32_t *w, int32_t *h);

/* Parse tslib's pointercal text ("a0 a1 a2 a3 a4 a5 a6 [xres yres [rot]]").
 * Returns 0 or -FX_EINVAL (a6 == 0 or fewer than 7 integers). */
int fx_calib_parse(fx_calib *c, const char *text, unsigned len);

/* Key code (evdev KEY_*) to character with the US layout and modifiers:
 * returns the character (> 0), or -FX_KEY_* for a special key, or 0 for a
 * key that produces nothing (modifiers, unknown codes). */
int fx_keymap_us(unsigned code, unsigned mods, int caps);

/* GPIO button debouncing: a change counts once the line has stayed at its
 * new level for ms milliseconds; bounces in between are ignored. */
typedef struct fx_debounce {
    uint32_t ms;
    uint8_t stable, raw;
    uint64_t last_us;
} fx_debounce;
void fx_debounce_init(fx_debounce *d, uint32_t ms, int level);
/* Record an edge (the new raw level at time t). */
void fx_debounce_edge(fx_debounce *d, int level, uint64_t t_us);
/* At time now: 1 when the stable level changed to 1, 0 when it changed to
 * 0, -1 when nothing changed. */
int fx_debounce_poll(fx_debounce *d, uint64_t now_us);
/* When to poll next: the time the pending change settles, or UINT64_MAX. */
uint64_t fx_debounce_deadline(const fx_debounce *d);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
