/* SPDX-License-Identifier: MIT */
/* fixel — the app: display + input + GPIO behind GLUT-style callbacks, and
 * the main loop (poll over every fd; timerfd for timers and debouncing;
 * signalfd for SIGINT/SIGTERM/SIGHUP). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <fcntl.h>
#include <limits.h>
#include <sys/signalfd.h>
#include <sys/stat.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "app_int.h"
#include "../display/display_int.h"
#include "fixel/error.h"
#include "fixel/files.h"

#ifndef FX_BOARD_GPIO_BUTTONS
#define FX_BOARD_GPIO_BUTTONS ""
#endif

static fx_app *current;

static uint64_t now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000;
}

uint64_t fx_app_now_us(void) { return now_us(); }

static uint64_t clock_now(void *user)
{
    (void)user;
    return now_us();
}

/* Display i of the app: 0 its own, 1.. the added ones. */
static fx_display *disp_of(const fx_app *a, int i) { return i == 0 ? a->disp : a->extra[i - 1].disp; }
static fx_input *input_of(fx_app *a, int i) { return i == 0 ? &a->in : &a->extra[i - 1].in; }
static int *touch_hidden_of(fx_app *a, int i)
{
    return i == 0 ? &a->pointer_touch_hidden : &a->extra[i - 1].touch_hidden;
}

/* The pointer state follows its display's size and rotation (a monitor
 * replaced by a bigger one keeps its input in range). */
static void input_geometry(fx_app *a, int i)
{
    fx_display_info info;
    fx_display_get_info(disp_of(a, i), &info);
    fx_input *in = input_of(a, i);
    if (in->phys_w == info.width && in->phys_h == info.height && in->rotation == info.rotation)
        return;
    in->phys_w = info.width;
    in->phys_h = info.height;
    in->rotation = info.rotation;
    if (in->px >= info.width)
        in->px = info.width - 1;
    if (in->py >= info.height)
        in->py = info.height - 1;
}

void fx_app_emit(void *u, const fx_event *e)
{
    fx_app *a = u;
    int i = a->emitting;
    int *hidden = touch_hidden_of(a, i);
    /* A touchscreen's pointing (BTN_TOUCH comes as mouse events too) hides
     * the pointer; a mouse or tablet brings it back. */
    if (e->type == FX_EVENT_TOUCH || (a->feeding_cls & FX_DEV_TOUCH))
        *hidden = 1;
    else if ((a->feeding_cls & (FX_DEV_MOUSE | FX_DEV_TABLET)) &&
             (e->type == FX_EVENT_MOUSE || e->type == FX_EVENT_MOTION ||
              e->type == FX_EVENT_PASSIVE || e->type == FX_EVENT_WHEEL))
        *hidden = 0;
    if (i == 0)
        fx_dispatch(&a->cb, a->user, e);
    else
        fx_dispatch(&a->extra[i - 1].cb, a->extra[i - 1].cb_user, e);
}

void fx_app_feed(fx_app *a, fx_input_dev *d, const fx_raw_event *ev)
{
    int i = fx_app_device_display(a, d);
    input_geometry(a, i);
    a->feeding_cls = d->cls;
    a->emitting = i;
    fx_input_feed(input_of(a, i), d, ev, fx_app_emit, a);
    a->feeding_cls = 0;
    a->emitting = 0;
}

/* ---- input devices bound to displays ------------------------------------- */

int fx_app_resolve_binding(fx_app *a, const fx_bind_dev *dev, int *display, unsigned *gen)
{
    if (*gen == a->bind_gen && *display <= a->nextra)
        return *display;
    fx_bind_disp disp[FX_APP_MAX_DISPLAYS];
    char sysfs[FX_APP_MAX_DISPLAYS][256];
    int n = 1 + a->nextra;
    for (int i = 0; i < n; i++) {
        fx_display_info info;
        fx_display_get_info(disp_of(a, i), &info);
        sysfs[i][0] = 0;
        const char *card = info.backend == FX_BACKEND_DRM ? strrchr(info.device, '/') : NULL;
        if (card) {
            char link[96], real[PATH_MAX];
            snprintf(link, sizeof link, "/sys/class/drm/%s/device", card + 1);
            if (realpath(link, real) && strlen(real) < sizeof sysfs[i])
                memcpy(sysfs[i], real, strlen(real) + 1);
        }
        disp[i].connector = info.connector ? info.connector : "";
        disp[i].card_sysfs = sysfs[i];
        disp[i].wants_input = i == 0 || a->extra[i - 1].has_cb;
    }
    const char *why;
    int was = *gen ? *display : 0;
    int i = fx_bind_choose(dev, disp, n, a->binds, a->nbinds, &why);
    if (i != was || (!*gen && i != 0)) {
        fx_display_info info;
        fx_display_get_info(disp_of(a, i), &info);
        fx_display_log(a->disp, FX_LOG_INFO, "input: %s \"%s\" to display %d%s%s (%s)",
                       dev->path[0] ? dev->path : "replay device", dev->name, i,
                       info.connector && info.connector[0] ? " " : "",
                       info.connector ? info.connector : "", why);
    }
    *display = i;
    *gen = a->bind_gen;
    return i;
}

static int evdev_display(fx_app *a, fx_evdev *e)
{
    fx_bind_dev bd = {e->path, e->name, e->sysfs, e->bus, e->st.cls};
    return fx_app_resolve_binding(a, &bd, &e->display, &e->bind_gen);
}

int fx_app_device_display(fx_app *a, const fx_input_dev *d)
{
    if (a->nextra == 0)
        return 0;
    for (int k = 0; k < a->ev.ndevs; k++)
        if (&a->ev.devs[k]->st == d)
            return evdev_display(a, a->ev.devs[k]);
    return fx_replay_device_display(a, d);
}

/* The index of display d in the app, or -1. */
static int display_index(const fx_app *a, const fx_display *d)
{
    for (int i = 0; i <= a->nextra; i++)
        if (disp_of(a, i) == d)
            return i;
    return -1;
}

static void bindings_changed(fx_app *a)
{
    if (++a->bind_gen == 0)
        a->bind_gen = 1; /* 0 means never resolved */
}

int fx_app_bind_input(fx_app *a, const char *device, fx_display *d)
{
    if (!a || !device || !*device || strlen(device) >= sizeof a->binds[0].device)
        return -FX_EINVAL;
    int i = d ? display_index(a, d) : 0;
    if (i < 0)
        return -FX_EINVAL;
    /* A new binding of the same device replaces the old one. */
    for (int k = 0; k < a->nbinds; k++)
        if (!strcmp(a->binds[k].device, device)) {
            a->binds[k] = a->binds[--a->nbinds];
            k--;
        }
    if (d) {
        if (a->nbinds >= FX_APP_MAX_BINDS)
            return -FX_ENOSPC;
        /* first: it wins over the rules given before */
        memmove(&a->binds[1], &a->binds[0], (size_t)a->nbinds * sizeof a->binds[0]);
        snprintf(a->binds[0].device, sizeof a->binds[0].device, "%s", device);
        snprintf(a->binds[0].display, sizeof a->binds[0].display, "%d", i);
        a->nbinds++;
    }
    bindings_changed(a);
    return 0;
}

int fx_app_bind_inputs(fx_app *a, const char *spec)
{
    if (!a || !spec)
        return -FX_EINVAL;
    char err[160];
    int r = fx_bind_parse(spec, a->binds, FX_APP_MAX_BINDS, &a->nbinds, err, sizeof err);
    if (r < 0) {
        fx_display_log(a->disp, FX_LOG_ERROR, "input bindings '%s': %s", spec, err);
        return r;
    }
    bindings_changed(a);
    return 0;
}

fx_display *fx_app_input_display(fx_app *a, const char *device)
{
    if (!a || !device)
        return NULL;
    char real[PATH_MAX];
    const char *path = device[0] == '/' && realpath(device, real) ? real : device;
    for (int k = 0; k < a->ev.ndevs; k++) {
        fx_evdev *e = a->ev.devs[k];
        if (!strcmp(e->path, path) || !strcmp(e->name, device))
            return disp_of(a, evdev_display(a, e));
    }
    int i = fx_replay_named_display(a, device);
    return i >= 0 ? disp_of(a, i) : NULL;
}

int fx_app_set_display_callbacks(fx_app *a, fx_display *d, const fx_callbacks *cb, void *user)
{
    int i = a && d ? display_index(a, d) : -1;
    if (i < 0 || !cb)
        return -FX_EINVAL;
    if (i == 0) {
        fx_app_set_callbacks(a, cb, user);
        return 0;
    }
    a->extra[i - 1].cb = *cb;
    a->extra[i - 1].cb_user = user;
    a->extra[i - 1].has_cb = 1;
    bindings_changed(a); /* the guesses may bind to it now */
    return 0;
}

/* The evdev devices' sink. */
static void feed_raw(void *u, fx_input_dev *d, const fx_raw_event *ev)
{
    fx_app_feed(u, d, ev);
}

/* The buttons' sink: their key events carry the pointer position. */
static void emit_button(void *u, const fx_event *e)
{
    fx_app *a = u;
    fx_event k = *e;
    fx_input_to_logical(&a->in, a->in.px, a->in.py, &k.x, &k.y);
    fx_app_emit(a, &k);
}

/* The pointer of display i: AUTO shows it while a mouse or tablet bound
 * to that display is connected. */
static int pointer_visible_on(fx_app *a, int i)
{
    if (a->pointer_mode == FX_POINTER_OFF || *touch_hidden_of(a, i))
        return 0;
    if (a->pointer_mode == FX_POINTER_ON)
        return 1;
    for (int k = 0; k < a->ev.ndevs; k++)
        if ((a->ev.devs[k]->st.cls & (FX_DEV_MOUSE | FX_DEV_TABLET)) &&
            (a->nextra == 0 ? 0 : evdev_display(a, a->ev.devs[k])) == i)
            return 1;
    return 0;
}

int fx_app_pointer_visible(const fx_app *a)
{
    /* resolving a binding caches it; the answer is the same */
    return pointer_visible_on((fx_app *)a, 0);
}

void fx_app_pointer_sync(fx_app *a)
{
    for (int i = 0; i <= a->nextra; i++) {
        int32_t x, y;
        fx_input *in = input_of(a, i);
        input_geometry(a, i);
        fx_input_to_logical(in, in->px, in->py, &x, &y);
        fx_display_set_pointer(disp_of(a, i), pointer_visible_on(a, i), x, y);
    }
}

void fx_app_set_pointer(fx_app *a, fx_pointer_mode mode)
{
    a->pointer_mode = mode;
    fx_app_pointer_sync(a);
}

int fx_app_set_pointer_sprite(fx_app *a, const fx_sprite *s)
{
    return fx_display_set_pointer_sprite(a->disp, s);
}

void fx_app_options_init(fx_app_options *o)
{
    memset(o, 0, sizeof *o);
    fx_display_options_init(&o->display);
    o->input = 1;
}

static void load_pointercal(fx_app *a, const char *path)
{
    int explicit = path != NULL;
    if (!path)
        path = "/etc/pointercal";
    /* fixel/files.h: a FIFO with no writer must not block the open; only
     * a regular file is read. */
    FILE *f = fx_fopen_regular(path, NULL, NULL, 0);
    if (!f && (errno == EISDIR || errno == EOPNOTSUPP)) {
        fx_display_log(a->disp, FX_LOG_ERROR, "input: calibration %s is not a regular file; ignored", path);
        return;
    }
    if (!f) {
        if (explicit)
            fx_display_log(a->disp, FX_LOG_ERROR, "input: cannot read calibration %s: %s", path,
                           strerror(errno));
        return;
    }
    char buf[256];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    if (fx_calib_parse(&a->ev.calib, buf, (unsigned)n) < 0)
        fx_display_log(a->disp, FX_LOG_ERROR, "input: %s is not a tslib pointercal file "
                       "(7 integers, the last non-zero); ignored", path);
    else
        fx_display_log(a->disp, FX_LOG_INFO, "input: touch calibration from %s", path);
}

int fx_app_open(fx_app **out, const fx_app_options *o)
{
    *out = NULL;
    fx_app *a = calloc(1, sizeof *a);
    if (!a)
        return -FX_ENOMEM;
    a->ev.inotify_fd = a->tfd = a->sfd = -1;
    a->bind_gen = 1;
    int r = fx_display_open(&a->disp, &o->display);
    if (r < 0) {
        free(a);
        return r;
    }
    fx_display_info info;
    fx_display_get_info(a->disp, &info);
    fx_input_init(&a->in, info.width, info.height, info.rotation);
    snprintf(a->ev.dir, sizeof a->ev.dir, "%s", o->input_dir ? o->input_dir : "/dev/input");
    a->ev.grab = o->grab;
    a->ev.sink = (fx_raw_sink){feed_raw, a};
    a->ev.log = a->disp->log;
    a->gpio.sink = (fx_event_sink){emit_button, a};
    a->gpio.clock = (fx_clock){clock_now, NULL};
    a->gpio.log = a->disp->log;
    load_pointercal(a, o->pointercal);
    const char *touch = o->touch;
    if (touch) {
        a->ev.calib.swap_xy = strstr(touch, "swap") != NULL;
        a->ev.calib.invert_x = strstr(touch, "invertx") != NULL;
        a->ev.calib.invert_y = strstr(touch, "inverty") != NULL;
    }
    /* A replay file is the input: real devices would make it non-deterministic. */
    if (o->input && !o->replay)
        fx_evdev_scan(&a->ev);
    if (o->buttons && o->nbuttons > 0) {
        fx_gpio_open_buttons(&a->gpio, o->buttons, o->nbuttons);
    } else if (o->button_map || FX_BOARD_GPIO_BUTTONS[0]) {
        /* the map (FIXEL_BUTTONS), else the board profile's default map */
        const char *src = o->button_map ? o->button_map : FX_BOARD_GPIO_BUTTONS;
        char *spec = strdup(src);
        fx_gpio_button b[FX_GPIO_MAX_IN];
        int n = spec ? fx_gpio_parse_buttons(spec, b, FX_GPIO_MAX_IN) : -FX_ENOMEM;
        if (n < 0)
            fx_display_log(a->disp, FX_LOG_ERROR, "gpio: cannot parse the button map '%s'", src);
        else
            fx_gpio_open_buttons(&a->gpio, b, n);
        free(spec);
    }
    a->tfd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    /* Blocked in this thread and read through signalfd: the loop ends
     * normally and fx_app_close restores the console. */
    sigprocmask(SIG_BLOCK, &set, NULL);
    a->sfd = signalfd(-1, &set, SFD_NONBLOCK | SFD_CLOEXEC);
    a->pointer_mode = o->pointer;
    a->max_frames = o->frames > 0 ? o->frames : 0;
    if (o->frame_out) {
        if (!fx_frame_pattern_ok(o->frame_out)) {
            fx_display_log(a->disp, FX_LOG_ERROR,
                           "frame files '%s': at most one %%d (as in frame-%%03d.png), %%%% for %%",
                           o->frame_out);
            fx_app_close(a);
            return -FX_EINVAL;
        }
        a->frame_out = o->frame_out;
    }
    if (o->replay && (r = fx_replay_open(a, o->replay)) < 0) {
        fx_app_close(a);
        return r;
    }
    fx_app_pointer_sync(a); /* drawn with the first frame */
    current = a;
    *out = a;
    return 0;
}

void fx_app_close(fx_app *a)
{
    if (!a)
        return;
    fx_replay_close(a);
    fx_evdev_close_all(&a->ev);
    fx_gpio_close_all(&a->gpio);
    if (a->tfd >= 0)
        close(a->tfd);
    if (a->sfd >= 0)
        close(a->sfd);
    for (int i = 0; i < a->nextra; i++)
        fx_display_close(a->extra[i].disp);
    fx_display_close(a->disp);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    if (current == a)
        current = NULL;
    free(a);
}

void fx_app_set_callbacks(fx_app *a, const fx_callbacks *cb, void *user)
{
    a->cb = *cb;
    a->user = user;
}

void fx_app_post_redisplay(fx_app *a) { a->redisplay = 1; }

int fx_app_add_display(fx_app *a, const fx_display_options *o,
                       void (*draw)(fx_app *a, fx_display *d, void *user), void *user, fx_display **out)
{
    if (out)
        *out = NULL;
    if (a->nextra >= FX_APP_MAX_DISPLAYS - 1) {
        fx_display_log(a->disp, FX_LOG_ERROR, "at most %d displays in one app", FX_APP_MAX_DISPLAYS);
        return -FX_ENOSPC;
    }
    fx_display *d;
    int r = fx_display_open(&d, o);
    if (r < 0)
        return r;
    a->extra[a->nextra].disp = d;
    a->extra[a->nextra].draw = draw;
    a->extra[a->nextra].user = user;
    a->extra[a->nextra].redisplay = 1; /* its first frame */
    fx_display_info info;
    fx_display_get_info(d, &info);
    fx_input_init(&a->extra[a->nextra].in, info.width, info.height, info.rotation);
    a->nextra++;
    bindings_changed(a); /* a binding may name its connector */
    if (out)
        *out = d;
    return 0;
}

void fx_app_post_redisplay_on(fx_app *a, fx_display *d)
{
    if (d == a->disp)
        a->redisplay = 1;
    for (int i = 0; i < a->nextra; i++)
        if (a->extra[i].disp == d)
            a->extra[i].redisplay = 1;
}

/* Draw one added display whose frame is due: 1 when one was drawn. */
static int draw_extra(fx_app *a)
{
    for (int i = 0; i < a->nextra; i++)
        if (a->extra[i].redisplay && a->extra[i].draw && !fx_display_flip_pending(a->extra[i].disp)) {
            a->extra[i].redisplay = 0;
            a->extra[i].draw(a, a->extra[i].disp, a->extra[i].user);
            return fx_app_extra_frame_done(a, i) < 0 ? -1 : 1;
        }
    return 0;
}

/* 1 when an added display wants a frame but has no fd to wake the loop. */
static int extra_due_without_fd(const fx_app *a)
{
    for (int i = 0; i < a->nextra; i++)
        if (a->extra[i].redisplay && a->extra[i].draw && fx_display_fd(a->extra[i].disp) < 0)
            return 1;
    return 0;
}
fx_surface fx_app_surface(fx_app *a) { return fx_display_surface(a->disp); }
int fx_app_present(fx_app *a, const fx_rect *damage, int n) { return fx_display_present(a->disp, damage, n); }
fx_display *fx_app_display(fx_app *a) { return a->disp; }
void fx_app_quit(fx_app *a) { a->quit = 1; }
void fx_app_size(const fx_app *a, int32_t *w, int32_t *h) { fx_input_logical_size(&a->in, w, h); }
int fx_app_input_count(const fx_app *a) { return a->ev.ndevs + a->gpio.nin; }
int fx_app_gpio_output(fx_app *a, const char *chip, int offset, int value)
{
    return fx_gpio_output(&a->gpio, chip, offset, value);
}

int fx_app_timer(fx_app *a, unsigned ms, void (*fn)(void *user, int value), int value)
{
    for (int i = 0; i < FX_APP_MAX_TIMERS; i++)
        if (!a->timers[i].used) {
            a->timers[i].used = 1;
            a->timers[i].at_us = now_us() + (uint64_t)ms * 1000;
            a->timers[i].fn = fn;
            a->timers[i].value = value;
            return 0;
        }
    return -FX_ENOSPC;
}

/* Run due timers and debouncers; returns the next deadline. */
static uint64_t run_timers(fx_app *a)
{
    uint64_t now = now_us(), next = fx_gpio_poll(&a->gpio, now);
    for (int i = 0; i < FX_APP_MAX_TIMERS; i++) {
        if (!a->timers[i].used)
            continue;
        if (a->timers[i].at_us <= now) {
            a->timers[i].used = 0; /* one-shot; the callback may re-arm */
            a->timers[i].fn(a->user, a->timers[i].value);
        }
    }
    for (int i = 0; i < FX_APP_MAX_TIMERS; i++)
        if (a->timers[i].used && a->timers[i].at_us < next)
            next = a->timers[i].at_us;
    return next;
}

static void arm(fx_app *a, uint64_t at_us)
{
    struct itimerspec its;
    memset(&its, 0, sizeof its);
    if (at_us != UINT64_MAX) {
        if (at_us == 0)
            at_us = 1;
        its.it_value.tv_sec = (time_t)(at_us / 1000000u);
        its.it_value.tv_nsec = (long)(at_us % 1000000u) * 1000;
    }
    timerfd_settime(a->tfd, TFD_TIMER_ABSTIME, &its, NULL);
}

int fx_app_main_loop(fx_app *a)
{
    enum { MAXFD = 4 + FX_APP_MAX_DISPLAYS + FX_EVDEV_MAX + FX_GPIO_MAX_IN + FX_APP_MAX_WATCH };
    a->quit = 0;
    if (!a->started) {
        a->started = 1;
        fx_event e;
        memset(&e, 0, sizeof e);
        e.type = FX_EVENT_RESHAPE;
        fx_input_logical_size(&a->in, &e.x, &e.y);
        fx_dispatch(&a->cb, a->user, &e);
        for (int k = 0; k < a->nextra; k++)
            if (a->extra[k].has_cb) {
                fx_input_logical_size(&a->extra[k].in, &e.x, &e.y);
                fx_dispatch(&a->extra[k].cb, a->extra[k].cb_user, &e);
            }
        a->redisplay = 1;
    }
    while (!a->quit) {
        uint64_t next = run_timers(a);
        if (a->quit)
            break;
        /* An animated page whose frame outlasts its tick always has a frame
         * due; the replay, which runs when none is, would never run again.
         * So once a frame has been drawn the replay gets its turn before
         * the next one, and frames and replay statements alternate. */
        if (a->redisplay && !fx_display_flip_pending(a->disp) && a->cb.display && !a->replay_owed) {
            a->redisplay = 0;
            a->cb.display(a->user);
            int f = fx_app_frame_done(a);
            if (f < 0)
                return f;
            a->replay_owed = a->replay != NULL;
            continue; /* timers or input may have become due meanwhile */
        }
        int x = draw_extra(a);
        if (x < 0)
            return -FX_EIO; /* a frame file that cannot be written (logged) */
        if (x)
            continue;
        if (a->replay) {
            /* The replay runs when no frame is due: "frame" lets the
             * program draw what the statements before it asked for. */
            uint64_t resume;
            a->replay_owed = 0;
            int s = fx_replay_step(a, now_us(), &resume);
            if (s < 0)
                return s;
            if (s == 0) {
                fx_replay_close(a); /* the end of the file ends the run */
                break;
            }
            fx_app_pointer_sync(a);
            if (!resume)
                continue;
            if (resume < next)
                next = resume;
        }
        arm(a, next);
        struct pollfd p[MAXFD];
        int n = 0, dfd = fx_display_fd(a->disp);
        int i_sig = -1, i_tim = -1, i_disp = -1, i_ino = -1, i_dev = 0, i_gpio = 0;
        if (a->sfd >= 0)
            i_sig = n, p[n++] = (struct pollfd){a->sfd, POLLIN, 0};
        if (a->tfd >= 0)
            i_tim = n, p[n++] = (struct pollfd){a->tfd, POLLIN, 0};
        if (dfd >= 0)
            i_disp = n, p[n++] = (struct pollfd){dfd, POLLIN, 0};
        if (a->ev.inotify_fd >= 0)
            i_ino = n, p[n++] = (struct pollfd){a->ev.inotify_fd, POLLIN, 0};
        int i_extra = n;
        for (int k = 0; k < a->nextra; k++)
            p[n++] = (struct pollfd){fx_display_fd(a->extra[k].disp), POLLIN, 0}; /* -1 is skipped */
        i_dev = n;
        for (int k = 0; k < a->ev.ndevs; k++)
            p[n++] = (struct pollfd){a->ev.devs[k]->fd, POLLIN, 0};
        i_gpio = n;
        for (int k = 0; k < a->gpio.nin; k++)
            p[n++] = (struct pollfd){a->gpio.in[k].fd, POLLIN, 0};
        int i_watch = n, nwatch = a->nwatch, wfd[FX_APP_MAX_WATCH];
        for (int k = 0; k < nwatch; k++)
            wfd[k] = a->watch[k].fd, p[n++] = (struct pollfd){a->watch[k].fd, POLLIN, 0};
        int ndev = a->ev.ndevs, ngpio = a->gpio.nin;
        /* Sleep unless the program wants idle calls, or a frame is due and no
         * flip event will wake us (no DRM fd). */
        int timeout = a->cb.idle ? 0
                      : ((a->redisplay && a->cb.display && dfd < 0) || extra_due_without_fd(a)) ? 1 : -1;
        int r = poll(p, (nfds_t)n, timeout);
        if (r < 0) {
            if (errno == EINTR)
                continue;
            return -errno;
        }
        if (r == 0) {
            if (a->cb.idle)
                a->cb.idle(a->user);
            continue;
        }
        if (i_sig >= 0 && (p[i_sig].revents & POLLIN)) {
            struct signalfd_siginfo si;
            if (read(a->sfd, &si, sizeof si) == (ssize_t)sizeof si) {
                fx_display_log(a->disp, FX_LOG_INFO, "signal %u: closing", si.ssi_signo);
                if (a->cb.close)
                    a->cb.close(a->user);
                a->quit = 1;
                break;
            }
        }
        if (i_tim >= 0 && (p[i_tim].revents & POLLIN)) {
            uint64_t ticks;
            if (read(a->tfd, &ticks, sizeof ticks) < 0) {
                /* EAGAIN: the timer was re-armed meanwhile */
            }
        }
        if (i_disp >= 0 && (p[i_disp].revents & POLLIN))
            fx_display_dispatch(a->disp);
        for (int k = 0; k < a->nextra; k++)
            if (p[i_extra + k].revents & POLLIN)
                fx_display_dispatch(a->extra[k].disp);
        if (i_ino >= 0 && (p[i_ino].revents & POLLIN))
            fx_evdev_hotplug(&a->ev);
        /* Devices may be dropped while reading: walk from the end so the
         * swap-with-last removal never skips one. */
        for (int k = ndev - 1; k >= 0; k--)
            if (p[i_dev + k].revents & (POLLIN | POLLHUP | POLLERR))
                if (k < a->ev.ndevs && a->ev.devs[k]->fd == p[i_dev + k].fd)
                    fx_evdev_read(&a->ev, k);
        for (int k = ngpio - 1; k >= 0; k--)
            if (p[i_gpio + k].revents & (POLLIN | POLLHUP | POLLERR))
                if (k < a->gpio.nin && a->gpio.in[k].fd == p[i_gpio + k].fd)
                    fx_gpio_read(&a->gpio, k);
        /* A callback may add or remove watches: each fd is looked up again. */
        for (int k = 0; k < nwatch; k++)
            if (p[i_watch + k].revents & (POLLIN | POLLHUP | POLLERR))
                for (int j = 0; j < a->nwatch; j++)
                    if (a->watch[j].fd == wfd[k]) {
                        a->watch[j].fn(a->watch[j].user, wfd[k]);
                        break;
                    }
        /* Once per pass, not per event: a burst of mouse reports costs one
         * repaint of the sprite. */
        fx_app_pointer_sync(a);
    }
    return 0;
}

int fx_app_watch_fd(fx_app *a, int fd, void (*fn)(void *user, int fd), void *user)
{
    if (!a || fd < 0)
        return -FX_EINVAL;
    for (int k = 0; k < a->nwatch; k++)
        if (a->watch[k].fd == fd) {
            if (!fn) {
                a->watch[k] = a->watch[--a->nwatch];
                return 0;
            }
            a->watch[k].fn = fn;
            a->watch[k].user = user;
            return 0;
        }
    if (!fn)
        return -FX_EINVAL;
    if (a->nwatch == FX_APP_MAX_WATCH)
        return -FX_ENOSPC;
    a->watch[a->nwatch].fd = fd;
    a->watch[a->nwatch].fn = fn;
    a->watch[a->nwatch].user = user;
    a->nwatch++;
    return 0;
}

void fx_post_redisplay(void)
{
    if (current)
        fx_app_post_redisplay(current);
}

int fx_main_loop(void) { return current ? fx_app_main_loop(current) : -FX_EINVAL; }

