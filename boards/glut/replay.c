/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — FIXEL_GLUT_REPLAY: the scripted input of headless runs.
 *
 * The format and its timing are tests/glut/README.md's (the Mesa shim,
 * tests/glut/mesa/shim.c, implements the same), summarised in
 * boards/glut/README.md:
 *
 *     frame N: EVENT ARGS... [mods=shift,ctrl,alt]     # comment
 *
 * An event tagged N is delivered at the first point between main-loop
 * iterations at which at least N frames have ended (after the display work,
 * before the idle callback), in file order. The whole file is parsed when the
 * window is created; a line that does not parse ends the program with exit
 * status 5 and a message naming the line, as does a menu path that does not
 * exist when it is delivered.
 *
 * Two events go beyond the shim's set: `wheel up|down [X Y]` (freeglut's
 * wheel: glutMouseWheelFunc, else buttons 3/4 on the mouse callback) and, for
 * testing fixel's own input path, `evdev keyboard|mouse TYPE CODE VALUE`,
 * a raw evdev event (numbers of linux/input-event-codes.h) fed through
 * fixel's input layer (US keymap, shift/ctrl/caps state). */
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/files.h"
#include "glut_replay.h"

__attribute__((noreturn)) static void die(const char *path, int line, const char *why)
{
    fprintf(stderr, "fixel-glut: FIXEL_GLUT_REPLAY=%s line %d: %s\n", path, line, why);
    exit(5);
}

static int parse_key(const char *t, int *ok)
{
    static const struct { const char *n; int c; } names[] = {
        {"space", ' '}, {"enter", 13}, {"escape", 27}, {"esc", 27}, {"tab", 9},
        {"backspace", 8}, {"delete", 127}};
    *ok = 1;
    if (t[0] && !t[1])
        return (unsigned char)t[0];
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(t, names[i].n))
            return names[i].c;
    if (t[0] == '0' && (t[1] == 'x' || t[1] == 'X') && t[2]) {
        char *end;
        long v = strtol(t + 2, &end, 16);
        if (!*end && v >= 0 && v <= 255)
            return (int)v;
    }
    *ok = 0;
    return 0;
}

static int parse_special(const char *t, int *ok)
{
    static const struct { const char *n; int c; } names[] = {
        {"left", GLUT_KEY_LEFT}, {"right", GLUT_KEY_RIGHT}, {"up", GLUT_KEY_UP},
        {"down", GLUT_KEY_DOWN}, {"page_up", GLUT_KEY_PAGE_UP}, {"page_down", GLUT_KEY_PAGE_DOWN},
        {"home", GLUT_KEY_HOME}, {"end", GLUT_KEY_END}, {"insert", GLUT_KEY_INSERT}};
    *ok = 1;
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(t, names[i].n))
            return names[i].c;
    if (t[0] == 'f' && t[1]) {
        char *end;
        long n = strtol(t + 1, &end, 10);
        if (!*end && n >= 1 && n <= 12)
            return GLUT_KEY_F1 + (int)n - 1;
    }
    *ok = 0;
    return 0;
}

static int parse_button(const char *t, int *ok)
{
    *ok = 1;
    if (!strcmp(t, "left"))
        return GLUT_LEFT_BUTTON;
    if (!strcmp(t, "middle"))
        return GLUT_MIDDLE_BUTTON;
    if (!strcmp(t, "right"))
        return GLUT_RIGHT_BUTTON;
    *ok = 0;
    return 0;
}

static int parse_int(const char *t, long lo, long hi, int *ok)
{
    char *end;
    errno = 0;
    long v = strtol(t, &end, 0);
    if (!*t || *end || errno || v < lo || v > hi) {
        *ok = 0;
        return 0;
    }
    return (int)v;
}

/* Parses one line (comment and newline already cut, not blank) into *e;
 * returns NULL or what is wrong with it. */
static const char *parse_line(char *s, long last_frame, fx_glut_replay_event *e)
{
    memset(e, 0, sizeof *e);
    int n = 0, ok = 1;
    if (sscanf(s, "frame %ld: %n", &e->frame, &n) != 1 || n == 0)
        return "expected 'frame N: EVENT ARGS'";
    if (e->frame < 1)
        return "frame numbers start at 1";
    if (e->frame < last_frame)
        return "frame numbers must not decrease";
    s += n;
    if (!strncmp(s, "menu ", 5)) { /* menu BUTTON LABEL[/LABEL...] (labels may hold spaces) */
        char btn[16];
        int m = 0;
        if (sscanf(s + 5, "%15s %n", btn, &m) != 1 || m == 0 || !s[5 + m])
            return "menu BUTTON LABEL[/LABEL...]";
        e->kind = FXG_EV_MENU;
        e->a = parse_button(btn, &ok);
        if (!ok)
            return "button must be left, middle or right";
        if (strlen(s + 5 + m) >= sizeof e->path)
            return "menu path too long";
        snprintf(e->path, sizeof e->path, "%s", s + 5 + m);
        return NULL;
    }
    char *tok[8];
    int nt = 0;
    for (char *t = strtok(s, " \t"); t; t = strtok(NULL, " \t")) {
        if (nt == 8)
            return "too many words";
        tok[nt++] = t;
    }
    if (nt == 0)
        return "no event after 'frame N:'";
    if (nt > 1 && !strncmp(tok[nt - 1], "mods=", 5)) {
        char *save = NULL;
        for (char *m = strtok_r(tok[--nt] + 5, ",", &save); m; m = strtok_r(NULL, ",", &save)) {
            if (!strcmp(m, "shift"))
                e->mods |= GLUT_ACTIVE_SHIFT;
            else if (!strcmp(m, "ctrl"))
                e->mods |= GLUT_ACTIVE_CTRL;
            else if (!strcmp(m, "alt"))
                e->mods |= GLUT_ACTIVE_ALT;
            else
                return "mods= takes shift, ctrl, alt";
        }
    }
    const char *k = tok[0];
    int args, need_xy = 0;
    if (!strcmp(k, "mouse")) {
        if (nt != 5)
            return "mouse BUTTON down|up X Y";
        e->kind = FXG_EV_MOUSE;
        e->a = parse_button(tok[1], &ok);
        if (!ok)
            return "button must be left, middle or right";
        if (!strcmp(tok[2], "down"))
            e->b = GLUT_DOWN;
        else if (!strcmp(tok[2], "up"))
            e->b = GLUT_UP;
        else
            return "mouse BUTTON down|up X Y";
        args = 3, need_xy = 1;
    } else if (!strcmp(k, "motion") || !strcmp(k, "passive")) {
        if (nt != 3)
            return "motion|passive X Y";
        e->kind = k[0] == 'm' ? FXG_EV_MOTION : FXG_EV_PASSIVE;
        args = 1, need_xy = 1;
    } else if (!strcmp(k, "key") || !strcmp(k, "keyup")) {
        if (nt != 2 && nt != 4)
            return "key|keyup KEY [X Y]";
        e->kind = k[3] ? FXG_EV_KEYUP : FXG_EV_KEY;
        e->a = parse_key(tok[1], &ok);
        if (!ok)
            return "unknown key name";
        args = 2;
    } else if (!strcmp(k, "special") || !strcmp(k, "specialup")) {
        if (nt != 2 && nt != 4)
            return "special|specialup NAME [X Y]";
        e->kind = k[7] ? FXG_EV_SPECIALUP : FXG_EV_SPECIAL;
        e->a = parse_special(tok[1], &ok);
        if (!ok)
            return "unknown special key";
        args = 2;
    } else if (!strcmp(k, "wheel")) {
        if (nt != 2 && nt != 4)
            return "wheel up|down [X Y]";
        e->kind = FXG_EV_WHEEL;
        if (!strcmp(tok[1], "up"))
            e->a = 1;
        else if (!strcmp(tok[1], "down"))
            e->a = -1;
        else
            return "wheel up|down [X Y]";
        args = 2;
    } else if (!strcmp(k, "evdev")) {
        if (nt != 5 || e->mods)
            return "evdev keyboard|mouse TYPE CODE VALUE";
        e->kind = FXG_EV_EVDEV;
        if (!strcmp(tok[1], "keyboard"))
            e->a = 0;
        else if (!strcmp(tok[1], "mouse"))
            e->a = 1;
        else
            return "evdev keyboard|mouse TYPE CODE VALUE";
        e->type = parse_int(tok[2], 0, 0xFFFF, &ok);
        e->code = parse_int(tok[3], 0, 0xFFFF, &ok);
        e->b = parse_int(tok[4], -2147483647L, 2147483647L, &ok);
        if (!ok)
            return "evdev TYPE CODE VALUE are numbers";
        return NULL;
    } else {
        return "unknown event (mouse, motion, passive, key, keyup, special, specialup, menu, "
               "wheel, evdev)";
    }
    if (nt == args + 2) {
        e->x = parse_int(tok[args], -1000000, 1000000, &ok);
        e->y = parse_int(tok[args + 1], -1000000, 1000000, &ok);
        if (!ok)
            return "X Y must be integers";
        e->has_xy = 1;
    } else if (need_xy) {
        return "missing X Y";
    }
    return NULL;
}

void fx_glut_replay_load(fx_glut_replay *r, const char *path)
{
    memset(r, 0, sizeof *r);
    r->path = path;
    /* the one rule for user-named files (fixel/files.h): a FIFO with no
     * writer would block open() for ever, a directory or a device is no
     * replay file */
    char not_file[128];
    FILE *f = fx_fopen_regular(path, NULL, not_file, sizeof not_file);
    if (!f) {
        fprintf(stderr, "fixel-glut: FIXEL_GLUT_REPLAY=%s: %s\n", path, not_file);
        exit(5);
    }
    char buf[512];
    int line = 0, cap = 0;
    long last = 0;
    while (fgets(buf, sizeof buf, f)) {
        line++;
        size_t len = strlen(buf);
        if (len == sizeof buf - 1 && buf[len - 1] != '\n')
            die(path, line, "line too long");
        char *hash = strchr(buf, '#');
        if (hash)
            *hash = 0;
        char *s = buf;
        while (*s == ' ' || *s == '\t')
            s++;
        len = strlen(s);
        while (len && (s[len - 1] == '\n' || s[len - 1] == '\r' || s[len - 1] == ' ' ||
                       s[len - 1] == '\t'))
            s[--len] = 0;
        if (!*s)
            continue;
        fx_glut_replay_event e;
        const char *why = parse_line(s, last, &e);
        if (why)
            die(path, line, why);
        e.line = line;
        last = e.frame;
        if (r->n == cap) {
            cap = cap ? cap * 2 : 64;
            fx_glut_replay_event *ne = realloc(r->ev, (size_t)cap * sizeof *ne);
            if (!ne)
                die(path, line, "out of memory");
            r->ev = ne;
        }
        r->ev[r->n++] = e;
    }
    fclose(f);
}

void fx_glut_replay_fail(const fx_glut_replay *r, const fx_glut_replay_event *e, const char *why)
{
    die(r->path, e->line, why);
}
