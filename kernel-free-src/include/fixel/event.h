/* SPDX-License-Identifier: MIT */
/* fixel — the event model: platform-neutral input events and GLUT-style
 * callback dispatch.
 *
 * A program registers callbacks in the spirit of GLUT (display, reshape,
 * keyboard, special, mouse, motion, passive motion, wheel, touch, idle,
 * close); the boards side turns kernel input into fx_event values (through
 * input.h) and fx_dispatch calls the matching callback. Coordinates are
 * logical screen pixels: after display rotation and touch calibration.
 */
#ifndef FIXEL_EVENT_H
#define FIXEL_EVENT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fx_event_type {
    FX_EVENT_NONE,
    FX_EVENT_KEY,          /* key: a character (ASCII, control chars for Ctrl) */
    FX_EVENT_KEY_UP,
    FX_EVENT_SPECIAL,      /* key: FX_KEY_F1.. FX_KEY_INSERT, FX_KEY_MENU */
    FX_EVENT_SPECIAL_UP,
    FX_EVENT_MOUSE,        /* button, state, x, y */
    FX_EVENT_MOTION,       /* x, y with a button held */
    FX_EVENT_PASSIVE,      /* x, y with no button held */
    FX_EVENT_WHEEL,        /* value: +1 away from the user, -1 towards; x, y */
    FX_EVENT_TOUCH,        /* id (slot), x, y, phase */
    FX_EVENT_RESHAPE,      /* x, y: the new logical width and height */
    FX_EVENT_CLOSE,
} fx_event_type;

/* GLUT's numbering, so course code ports unchanged. */
enum { FX_BUTTON_LEFT = 0, FX_BUTTON_MIDDLE = 1, FX_BUTTON_RIGHT = 2 };
enum { FX_DOWN = 0, FX_UP = 1 };
enum { FX_TOUCH_DOWN = 0, FX_TOUCH_MOVE = 1, FX_TOUCH_UP = 2 };
enum {
    FX_KEY_F1 = 1, FX_KEY_F2, FX_KEY_F3, FX_KEY_F4, FX_KEY_F5, FX_KEY_F6,
    FX_KEY_F7, FX_KEY_F8, FX_KEY_F9, FX_KEY_F10, FX_KEY_F11, FX_KEY_F12,
    FX_KEY_LEFT = 100, FX_KEY_UP = 101, FX_KEY_RIGHT = 102, FX_KEY_DOWN = 103,
    FX_KEY_PAGE_UP = 104, FX_KEY_PAGE_DOWN = 105, FX_KEY_HOME = 106, FX_KEY_END = 107,
    FX_KEY_INSERT = 108,
    /* The PC keyboard's Menu key (or a GPIO button named "menu"): no GLUT
     * key has this code; the GLUT layer opens the program's pop-up menu
     * with it, so a menu works without a pointer. */
    FX_KEY_MENU = 0x100,
};
/* Modifier bits in fx_event.mods (GLUT's values). */
enum { FX_MOD_SHIFT = 1, FX_MOD_CTRL = 2, FX_MOD_ALT = 4 };

typedef struct fx_event {
    uint8_t type;   /* fx_event_type */
    uint8_t button; /* FX_BUTTON_* */
    uint8_t state;  /* FX_DOWN / FX_UP */
    uint8_t phase;  /* FX_TOUCH_* */
    int32_t key;    /* character or FX_KEY_* */
    int32_t x, y;
    int32_t id;     /* touch slot */
    int32_t value;  /* wheel direction */
    uint32_t mods;  /* FX_MOD_* held when the event happened */
    uint64_t time_us;
} fx_event;

typedef struct fx_callbacks {
    void (*display)(void *user);
    void (*reshape)(void *user, int w, int h);
    void (*keyboard)(void *user, unsigned char key, int x, int y);
    void (*keyboard_up)(void *user, unsigned char key, int x, int y);
    void (*special)(void *user, int key, int x, int y);
    void (*special_up)(void *user, int key, int x, int y);
    void (*mouse)(void *user, int button, int state, int x, int y);
    void (*motion)(void *user, int x, int y);
    void (*passive_motion)(void *user, int x, int y);
    void (*wheel)(void *user, int direction, int x, int y);
    void (*touch)(void *user, int id, int x, int y, int phase);
    void (*idle)(void *user);
    void (*close)(void *user);
} fx_callbacks;

/* Call the callback that matches e (nothing when it is NULL). */
void fx_dispatch(const fx_callbacks *cb, void *user, const fx_event *e);

/* One line describing e ("mouse left down 12 34"), for logs and tests;
 * returns the length (as fx_fmt). */
int fx_event_describe(const fx_event *e, char *buf, unsigned size);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
