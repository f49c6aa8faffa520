/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — the parsed FIXEL_GLUT_REPLAY file (replay.c). Not installed. */
#ifndef FIXEL_GLUT_REPLAY_H
#define FIXEL_GLUT_REPLAY_H

#include <GL/freeglut.h>
#include <stdint.h>

enum {
    FXG_EV_MOUSE, FXG_EV_MOTION, FXG_EV_PASSIVE, FXG_EV_KEY, FXG_EV_KEYUP, FXG_EV_SPECIAL,
    FXG_EV_SPECIALUP, FXG_EV_MENU, FXG_EV_WHEEL, FXG_EV_EVDEV
};

typedef struct fx_glut_replay_event {
    long frame;
    int kind;
    int a, b;          /* button / key / wheel direction / evdev device; state / evdev value */
    int x, y, has_xy;
    int mods;          /* GLUT_ACTIVE_* during the callback */
    uint16_t type, code; /* evdev */
    char path[192];    /* menu labels, '/'-separated */
    int line;
} fx_glut_replay_event;

typedef struct fx_glut_replay {
    const char *path;
    fx_glut_replay_event *ev;
    int n, next;
} fx_glut_replay;

/* Parses the whole file; a line that does not parse exits with status 5. */
void fx_glut_replay_load(fx_glut_replay *r, const char *path);
/* Exits with status 5, naming e's line. */
void fx_glut_replay_fail(const fx_glut_replay *r, const fx_glut_replay_event *e, const char *why)
    __attribute__((noreturn));

#endif
