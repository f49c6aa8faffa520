/* SPDX-License-Identifier: MIT */
/* fixel — driving an app headless: replay files (fx_app_options.replay,
 * FIXEL_REPLAY), injected events, the frame limit and saved frames.
 *
 * A replay file is the tests/input stream format, fed into the main loop:
 * raw evdev-style events go through virtual devices and the same
 * translation as real devices (fx_input_feed, then fx_app_emit), logical
 * events ("event mouse left down 10 20") straight to the callbacks.
 * fixel/app.h documents the statements. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <fcntl.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app_int.h"
#include "../display/display_int.h"
#include "fixel/error.h"
#include "fixel/files.h"
#include "fixel/memfb.h"

struct fx_replay {
    FILE *f;
    char path[256];
    int lineno;
    fx_input_dev dev[FX_REPLAY_DEVICES];
    /* what binds them to displays: "replay-N" unless the device statement
     * gives a name (and bus) */
    char name[FX_REPLAY_DEVICES][80];
    unsigned bus[FX_REPLAY_DEVICES];
    int display[FX_REPLAY_DEVICES];
    unsigned gen[FX_REPLAY_DEVICES];
    uint64_t resume_us; /* "wait": statements resume at this time */
};

/* ---- names of event types and codes (linux/input-event-codes.h) ---- */

static const struct {
    const char *name;
    int value;
} names[] = {
    {"SYN", 0}, {"KEY", 1}, {"REL", 2}, {"ABS", 3}, {"SYN_REPORT", 0}, {"SYN_DROPPED", 3},
    {"REL_X", 0}, {"REL_Y", 1}, {"REL_HWHEEL", 6}, {"REL_WHEEL", 8}, {"ABS_X", 0}, {"ABS_Y", 1},
    {"ABS_MT_SLOT", 0x2f}, {"ABS_MT_POSITION_X", 0x35}, {"ABS_MT_POSITION_Y", 0x36},
    {"ABS_MT_TRACKING_ID", 0x39}, {"BTN_LEFT", 0x110}, {"BTN_RIGHT", 0x111}, {"BTN_MIDDLE", 0x112},
    {"BTN_TOOL_PEN", 0x140}, {"BTN_TOUCH", 0x14a}, {"BTN_STYLUS", 0x14b}, {"KEY_ESC", 1},
    {"KEY_MINUS", 12}, {"KEY_EQUAL", 13}, {"KEY_BACKSPACE", 14}, {"KEY_TAB", 15}, {"KEY_ENTER", 28},
    {"KEY_LEFTCTRL", 29}, {"KEY_SEMICOLON", 39}, {"KEY_APOSTROPHE", 40}, {"KEY_GRAVE", 41},
    {"KEY_LEFTSHIFT", 42}, {"KEY_BACKSLASH", 43}, {"KEY_COMMA", 51}, {"KEY_DOT", 52},
    {"KEY_SLASH", 53}, {"KEY_RIGHTSHIFT", 54}, {"KEY_LEFTALT", 56}, {"KEY_SPACE", 57},
    {"KEY_CAPSLOCK", 58}, {"KEY_F10", 68}, {"KEY_KP5", 76}, {"KEY_F11", 87}, {"KEY_F12", 88},
    {"KEY_RIGHTCTRL", 97}, {"KEY_RIGHTALT", 100}, {"KEY_HOME", 102}, {"KEY_UP", 103},
    {"KEY_PAGEUP", 104}, {"KEY_LEFT", 105}, {"KEY_RIGHT", 106}, {"KEY_END", 107}, {"KEY_DOWN", 108},
    {"KEY_PAGEDOWN", 109}, {"KEY_INSERT", 110}, {"KEY_DELETE", 111},
};

/* KEY_A..KEY_Z, KEY_0..KEY_9, KEY_F1..KEY_F9 by rule; the rest by table;
 * else a number (decimal, 0x hex). Returns 0 or -1. */
static int value_of(const char *w, long *v)
{
    static const char *const rows[] = {"qwertyuiop", "asdfghjkl", "zxcvbnm"};
    static const int row_code[] = {16, 30, 44};
    if (!strncmp(w, "KEY_", 4) && w[4] && !w[5]) {
        char c = w[4];
        if (c >= '1' && c <= '9') {
            *v = 2 + (c - '1');
            return 0;
        }
        if (c == '0') {
            *v = 11;
            return 0;
        }
        for (int r = 0; r < 3; r++) {
            const char *p = strchr(rows[r], c - 'A' + 'a');
            if (c >= 'A' && c <= 'Z' && p) {
                *v = row_code[r] + (p - rows[r]);
                return 0;
            }
        }
    }
    if (!strncmp(w, "KEY_F", 5) && w[5] >= '1' && w[5] <= '9' && !w[6]) {
        *v = 59 + (w[5] - '1');
        return 0;
    }
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(names[i].name, w)) {
            *v = names[i].value;
            return 0;
        }
    char *end;
    errno = 0;
    *v = strtol(w, &end, 0);
    return end != w && !*end && !errno && *v >= -2147483647L - 1 && *v <= 2147483647L ? 0 : -1;
}

static int int_of(const char *w, int32_t *out)
{
    char *end;
    errno = 0;
    long v = strtol(w, &end, 10);
    if (end == w || *end || errno || v < -2147483647L - 1 || v > 2147483647L)
        return -1;
    *out = (int32_t)v;
    return 0;
}

static int word_index(const char *w, const char *const *list, int n)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(w, list[i]))
            return i;
    return -1;
}

/* "event TEXT": the event fx_event_describe prints as TEXT. Key and
 * special events may leave out the position (the pointer's is used), and
 * a key may be a quoted character ('c'). Returns 0 or -1. */
static int parse_event(fx_app *a, char **w, int n, fx_event *e)
{
    static const char *const types[] = {"key", "keyup", "special", "specialup", "mouse", "motion",
                                        "passive", "wheel", "touch", "reshape", "close"};
    static const uint8_t type_of[] = {FX_EVENT_KEY, FX_EVENT_KEY_UP, FX_EVENT_SPECIAL,
                                      FX_EVENT_SPECIAL_UP, FX_EVENT_MOUSE, FX_EVENT_MOTION,
                                      FX_EVENT_PASSIVE, FX_EVENT_WHEEL, FX_EVENT_TOUCH,
                                      FX_EVENT_RESHAPE, FX_EVENT_CLOSE};
    static const char *const buttons[] = {"left", "middle", "right"};
    static const char *const states[] = {"down", "up"};
    static const char *const phases[] = {"down", "move", "up"};
    memset(e, 0, sizeof *e);
    if (n < 1)
        return -1;
    int t = word_index(w[0], types, (int)(sizeof types / sizeof types[0]));
    if (t < 0)
        return -1;
    e->type = type_of[t];
    int32_t *xy = NULL;
    int at = 1;
    switch (e->type) {
    case FX_EVENT_KEY:
    case FX_EVENT_KEY_UP:
    case FX_EVENT_SPECIAL:
    case FX_EVENT_SPECIAL_UP:
        if (n != 2 && n != 4)
            return -1;
        if (w[1][0] == '\'' && w[1][1] && w[1][2] == '\'' && !w[1][3])
            e->key = (unsigned char)w[1][1];
        else if (int_of(w[1], &e->key) < 0)
            return -1;
        if (n == 2) {
            fx_input_to_logical(&a->in, a->in.px, a->in.py, &e->x, &e->y);
            return 0;
        }
        at = 2;
        break;
    case FX_EVENT_MOUSE: {
        int b = n == 5 ? word_index(w[1], buttons, 3) : -1;
        int s = n == 5 ? word_index(w[2], states, 2) : -1;
        if (b < 0 || s < 0)
            return -1;
        e->button = (uint8_t)b;
        e->state = (uint8_t)s;
        at = 3;
        break;
    }
    case FX_EVENT_WHEEL:
        if (n != 4 || int_of(w[1], &e->value) < 0)
            return -1;
        at = 2;
        break;
    case FX_EVENT_TOUCH: {
        int p = n == 5 ? word_index(w[2], phases, 3) : -1;
        if (p < 0 || int_of(w[1], &e->id) < 0)
            return -1;
        e->phase = (uint8_t)p;
        at = 3;
        break;
    }
    case FX_EVENT_CLOSE: return n == 1 ? 0 : -1;
    default: /* motion, passive, reshape */
        if (n != 3)
            return -1;
        break;
    }
    xy = &e->x;
    if (at + 2 != n || int_of(w[at], &xy[0]) < 0 || int_of(w[at + 1], &xy[1]) < 0)
        return -1;
    return 0;
}

int fx_app_inject(fx_app *a, const fx_event *e)
{
    if (!a || !e || e->type == FX_EVENT_NONE || e->type > FX_EVENT_CLOSE)
        return -FX_EINVAL;
    fx_event k = *e;
    if (!k.time_us)
        k.time_us = fx_app_now_us();
    fx_app_emit(a, &k);
    return 0;
}

int fx_replay_open(fx_app *a, const char *path)
{
    fx_replay *r = calloc(1, sizeof *r);
    if (!r)
        return -FX_ENOMEM;
    /* fixel/files.h: a regular file only. A FIFO did not block the open
     * (O_NONBLOCK) but one whose writer never wrote blocked the main
     * loop's read (issue #40); a directory is refused here, not by a
     * failing read later. */
    char why[160];
    r->f = fx_fopen_regular(path, NULL, why, sizeof why);
    if (!r->f) {
        int e = errno ? -errno : -FX_EIO;
        fx_display_log(a->disp, FX_LOG_ERROR, "replay: cannot open %s: %s", path, why);
        free(r);
        return e;
    }
    snprintf(r->path, sizeof r->path, "%s", path);
    for (int i = 0; i < FX_REPLAY_DEVICES; i++) {
        fx_input_dev_init(&r->dev[i], 0);
        snprintf(r->name[i], sizeof r->name[i], "replay-%d", i);
    }
    a->replay = r;
    return 0;
}

void fx_replay_close(fx_app *a)
{
    if (!a->replay)
        return;
    if (a->replay->f)
        fclose(a->replay->f);
    free(a->replay);
    a->replay = NULL;
}

static unsigned class_of(const char *s)
{
    static const struct {
        const char *name;
        unsigned cls;
    } cls[] = {{"keyboard", FX_DEV_KEYBOARD}, {"mouse", FX_DEV_MOUSE}, {"touch", FX_DEV_TOUCH},
               {"mt", FX_DEV_MT}, {"tablet", FX_DEV_TABLET}};
    unsigned c = 0;
    char buf[64];
    snprintf(buf, sizeof buf, "%s", s);
    for (char *save = NULL, *t = strtok_r(buf, "+", &save); t; t = strtok_r(NULL, "+", &save)) {
        unsigned k = 0;
        for (size_t i = 0; i < sizeof cls / sizeof cls[0]; i++)
            if (!strcmp(t, cls[i].name))
                k = cls[i].cls;
        if (!k)
            return 0;
        c |= k;
    }
    return c;
}

/* One statement; 1: go on, 0: stop here (frame or wait), -1: bad line. */
static int statement(fx_app *a, char *line, uint64_t now)
{
    fx_replay *r = a->replay;
    char *w[24];
    int n = 0;
    for (char *save = NULL, *t = strtok_r(line, " \t", &save); t && n < 24; t = strtok_r(NULL, " \t", &save))
        w[n++] = t;
    if (n == 0)
        return 1;
    int32_t N = -1;
    if (n > 1 && strcmp(w[0], "event") && strcmp(w[0], "screen") && strcmp(w[0], "wait") &&
        (int_of(w[1], &N) < 0 || N < 0 || N >= FX_REPLAY_DEVICES))
        return -1;
    fx_input_dev *d = N >= 0 ? &r->dev[N] : NULL;
    if (!strcmp(w[0], "frame") && n == 1)
        return 0;
    if (!strcmp(w[0], "wait") && n == 2) {
        int32_t ms;
        if (int_of(w[1], &ms) < 0 || ms < 0)
            return -1;
        r->resume_us = now + (uint64_t)ms * 1000;
        return 0;
    }
    if (!strcmp(w[0], "event")) {
        fx_event e;
        if (parse_event(a, w + 1, n - 1, &e) < 0)
            return -1;
        fx_app_inject(a, &e);
        return 1;
    }
    if (!strcmp(w[0], "screen") && (n == 3 || n == 4)) {
        fx_display_info info;
        fx_display_get_info(a->disp, &info);
        int32_t W, H, rot = 0;
        if (int_of(w[1], &W) < 0 || int_of(w[2], &H) < 0 || (n == 4 && int_of(w[3], &rot) < 0))
            return -1;
        if (W != info.width || H != info.height || rot != info.rotation) {
            fx_display_log(a->disp, FX_LOG_ERROR, "replay: %s:%d: the display is %dx%d rotation %d",
                           r->path, r->lineno, info.width, info.height, info.rotation);
            return -1;
        }
        return 1;
    }
    if (!strcmp(w[0], "device") && n >= 3) {
        unsigned cls = class_of(w[2]);
        if (!cls)
            return -1;
        fx_calib keep = d->calib;
        fx_input_dev_init(d, cls);
        d->calib = keep;
        r->gen[N] = 0; /* a new device: bound again */
        int k = 3;
        for (; k < n && (!strcmp(w[k], "abs") || !strcmp(w[k], "mt")); k += 5) {
            int mt = !strcmp(w[k], "mt");
            if ((!mt && strcmp(w[k], "abs")) || k + 4 >= n)
                return -1;
            int32_t v[4];
            for (int j = 0; j < 4; j++)
                if (int_of(w[k + 1 + j], &v[j]) < 0)
                    return -1;
            int32_t *mn = mt ? d->mt_min : d->abs_min, *mx = mt ? d->mt_max : d->abs_max;
            mn[0] = v[0], mx[0] = v[1], mn[1] = v[2], mx[1] = v[3];
        }
        if (k + 1 < n && !strcmp(w[k], "bus")) {
            static const char *const buses[] = {"usb", "i2c", "spi", "host", "virtual"};
            static const unsigned bus_no[] = {0x03, 0x18, 0x1C, 0x19, 0x06};
            int b = word_index(w[k + 1], buses, 5);
            if (b < 0)
                return -1;
            r->bus[N] = bus_no[b];
            k += 2;
        }
        if (k < n) {
            /* name TEXT: the rest of the statement */
            if (strcmp(w[k], "name") || k + 1 >= n)
                return -1;
            r->name[N][0] = 0;
            for (int j = k + 1; j < n; j++) {
                size_t l = strlen(r->name[N]);
                snprintf(r->name[N] + l, sizeof r->name[N] - l, "%s%s", j > k + 1 ? " " : "", w[j]);
            }
        }
        return 1;
    }
    if (!strcmp(w[0], "calib") && n == 9) {
        char text[160] = "";
        for (int k = 2; k < 9; k++) {
            size_t l = strlen(text);
            snprintf(text + l, sizeof text - l, "%s ", w[k]);
        }
        return fx_calib_parse(&d->calib, text, (unsigned)strlen(text)) == 0 ? 1 : -1;
    }
    if (!strcmp(w[0], "calibflag") && n == 3) {
        if (!strcmp(w[2], "swap"))
            d->calib.swap_xy = 1;
        else if (!strcmp(w[2], "invertx"))
            d->calib.invert_x = 1;
        else if (!strcmp(w[2], "inverty"))
            d->calib.invert_y = 1;
        else
            return -1;
        return 1;
    }
    if (!d || !d->cls)
        return -1; /* ev/syn/dropped need a declared device */
    fx_raw_event ev = {now, FX_IN_SYN, FX_IN_SYN_REPORT, 0};
    if (!strcmp(w[0], "ev") && n == 5) {
        long t, c, v;
        if (value_of(w[2], &t) < 0 || value_of(w[3], &c) < 0 || value_of(w[4], &v) < 0 || t < 0 ||
            t > 0xFFFF || c < 0 || c > 0xFFFF)
            return -1;
        ev.type = (uint16_t)t, ev.code = (uint16_t)c, ev.value = (int32_t)v;
    } else if (!strcmp(w[0], "dropped") && n == 2) {
        ev.code = FX_IN_SYN_DROPPED;
    } else if (strcmp(w[0], "syn") || n != 2) {
        return -1;
    }
    fx_app_feed(a, d, &ev);
    return 1;
}

int fx_replay_step(fx_app *a, uint64_t now, uint64_t *resume_us)
{
    fx_replay *r = a->replay;
    *resume_us = 0;
    if (r->resume_us > now) {
        *resume_us = r->resume_us;
        return 1;
    }
    r->resume_us = 0;
    char line[512];
    while (fgets(line, sizeof line, r->f)) {
        r->lineno++;
        char *hash = strchr(line, '#');
        /* '#' starts a comment; "'#'" is the character */
        if (hash && !(hash > line && hash[-1] == '\'' && hash[1] == '\''))
            *hash = 0;
        line[strcspn(line, "\r\n")] = 0;
        char copy[512];
        snprintf(copy, sizeof copy, "%s", line);
        int s = statement(a, line, now);
        if (s < 0) {
            fx_display_log(a->disp, FX_LOG_ERROR, "replay: %s:%d: cannot use '%s' (see fixel/app.h)",
                           r->path, r->lineno, copy);
            return -FX_EINVAL;
        }
        if (s == 0) {
            if (r->resume_us > now)
                *resume_us = r->resume_us;
            return 1;
        }
    }
    if (ferror(r->f)) {
        fx_display_log(a->disp, FX_LOG_ERROR, "replay: %s: read error", r->path);
        return -FX_EIO;
    }
    return 0;
}

/* ---- frames ---- */

/* The file name pattern: at most one %d conversion (flags 0 and a width
 * allowed), %% for a percent sign. */
int fx_frame_pattern_ok(const char *p)
{
    int conv = 0;
    for (; *p; p++) {
        if (*p != '%')
            continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        p++;
        while (*p >= '0' && *p <= '9')
            p++;
        if (*p != 'd' || ++conv > 1)
            return 0;
    }
    return 1;
}

int fx_app_frame_done(fx_app *a)
{
    a->frames++;
    if (a->frame_out) {
        char path[4096];
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
        snprintf(path, sizeof path, a->frame_out, a->frames);
#pragma GCC diagnostic pop
        fx_surface s = fx_display_screen(a->disp);
        int r = fx_write_image(path, &s);
        if (r < 0) {
            fx_display_log(a->disp, FX_LOG_ERROR, "frame %d: cannot write %s: %s", a->frames, path,
                           fx_strerror(r));
            return r;
        }
        fx_display_log(a->disp, FX_LOG_DEBUG, "frame %d: wrote %s", a->frames, path);
    }
    if (a->max_frames > 0 && a->frames >= a->max_frames)
        a->quit = 1;
    return 0;
}

int fx_app_frame_count(const fx_app *a) { return a->frames; }

/* "f-%03d.png" -> "f-%03d.d1.png" */
static void extra_name(char *out, size_t n, const char *pattern, int display)
{
    const char *slash = strrchr(pattern, '/');
    const char *dot = strrchr(pattern, '.');
    if (!dot || (slash && dot < slash))
        dot = pattern + strlen(pattern);
    snprintf(out, n, "%.*s.d%d%s", (int)(dot - pattern), pattern, display, dot);
}

int fx_app_extra_frame_done(fx_app *a, int i)
{
    int f = ++a->extra[i].frames;
    if (!a->frame_out)
        return 0;
    char pattern[4096], path[4096];
    extra_name(pattern, sizeof pattern, a->frame_out, i + 1);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
    snprintf(path, sizeof path, pattern, f);
#pragma GCC diagnostic pop
    fx_surface s = fx_display_screen(a->extra[i].disp);
    int r = fx_write_image(path, &s);
    if (r < 0) {
        fx_display_log(a->disp, FX_LOG_ERROR, "display %d frame %d: cannot write %s: %s", i + 1, f, path,
                       fx_strerror(r));
        return r;
    }
    fx_display_log(a->disp, FX_LOG_DEBUG, "display %d frame %d: wrote %s", i + 1, f, path);
    return 0;
}

int fx_replay_device_display(fx_app *a, const fx_input_dev *d)
{
    fx_replay *r = a->replay;
    if (!r || d < r->dev || d >= r->dev + FX_REPLAY_DEVICES)
        return 0;
    int i = (int)(d - r->dev);
    fx_bind_dev bd = {"", r->name[i], "", r->bus[i], d->cls};
    return fx_app_resolve_binding(a, &bd, &r->display[i], &r->gen[i]);
}

int fx_replay_named_display(fx_app *a, const char *name)
{
    fx_replay *r = a->replay;
    for (int i = 0; r && i < FX_REPLAY_DEVICES; i++)
        if (r->dev[i].cls && !strcmp(r->name[i], name))
            return fx_replay_device_display(a, &r->dev[i]);
    return -1;
}
