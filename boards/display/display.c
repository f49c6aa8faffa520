/* SPDX-License-Identifier: MIT */
/* The display object: backend choice (DRM -> fbdev -> memory), presentation
 * mode (direct or shadow), damage bookkeeping and rotation. The backends in
 * drm.c and fbdev.c only know how to show one of their buffers. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <poll.h>
#include <sys/epoll.h>
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>

#include "../linux/console/console_int.h"
#include "display_int.h"
#include "fixel/error.h"

/* Backends pass the kernel's -errno through (ENAMETOOLONG, ENOTTY, ...):
 * fx_strerror knows only the FX_E* codes, libc knows the rest. */
static const char *err_text(int r)
{
    const char *s = fx_strerror(r);
    return strcmp(s, "unknown error") ? s : strerror(r < 0 ? -r : r);
}

/* Compiled-in defaults of the board profile (boards/<name>.mk). */
#ifndef FX_BOARD_ROTATION
#define FX_BOARD_ROTATION 0
#endif
#ifndef FX_BOARD_BACKEND
#define FX_BOARD_BACKEND "auto"
#endif

/* ---- logging ----------------------------------------------------------- */

void fx_display_log(const fx_display *d, fx_log_priority p, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fx_logv(&d->log, p, fmt, ap);
    va_end(ap);
}

/* ---- options ----------------------------------------------------------- */

void fx_display_options_init(fx_display_options *o)
{
    memset(o, 0, sizeof *o);
    o->backend = FX_BACKEND_AUTO;
    o->present = FX_PRESENT_AUTO;
    o->format = FX_FMT_COUNT;
    o->drm_format = FX_FMT_COUNT;
    o->rotation = -1;
    o->console = 1;
    o->signals = 1;
    o->memory_w = 640;
    o->memory_h = 480;
}

const char *fx_backend_name(fx_backend b)
{
    switch (b) {
    case FX_BACKEND_DRM: return "drm";
    case FX_BACKEND_FBDEV: return "fbdev";
    case FX_BACKEND_MEMORY: return "memory";
    default: return "auto";
    }
}

static int parse_backend(const char *s, fx_backend *b)
{
    if (!strcasecmp(s, "drm") || !strcasecmp(s, "kms"))
        *b = FX_BACKEND_DRM;
    else if (!strcasecmp(s, "fbdev") || !strcasecmp(s, "fb"))
        *b = FX_BACKEND_FBDEV;
    else if (!strcasecmp(s, "memory") || !strcasecmp(s, "headless"))
        *b = FX_BACKEND_MEMORY;
    else if (!strcasecmp(s, "auto") || !*s)
        *b = FX_BACKEND_AUTO;
    else
        return -FX_EINVAL;
    return 0;
}

/* ---- open / close ------------------------------------------------------ */

static int vt_release(void *user);
static void vt_acquire(void *user);
static void pace_done(fx_display *d);

/* Several displays open at once share one console: the VT is put in
 * graphics mode by the first and given back by the last to close (a second
 * fx_vt_enter would save KD_GRAPHICS as the mode to restore and could not
 * take the switch signals). A VT switch releases and retakes all of them. */
#define MAX_DISPLAYS 8
static struct {
    fx_vt *vt;
    fx_display *member[MAX_DISPLAYS];
    int n;
} console;

static int console_release(void *user)
{
    (void)user;
    /* One display that denies (kiosk) keeps them all: a switch that would
     * release some and not others would show the console on half of them. */
    for (int i = 0; i < console.n; i++)
        if (console.member[i]->opt.vt_switch == FX_VT_SWITCH_DENY) {
            for (int k = 0; k < console.n; k++)
                console.member[k]->info.vt_refused++;
            fx_display_log(console.member[i], FX_LOG_DEBUG, "VT switch refused (kiosk policy)");
            return 0;
        }
    for (int i = 0; i < console.n; i++)
        vt_release(console.member[i]);
    return 1;
}

static void console_acquire(void *user)
{
    (void)user;
    for (int i = 0; i < console.n; i++)
        vt_acquire(console.member[i]);
}

static void console_join(fx_display *d)
{
    if (console.n >= MAX_DISPLAYS) {
        fx_display_log(d, FX_LOG_ERROR, "more than %d displays: this one leaves the console alone",
                       MAX_DISPLAYS);
        return;
    }
    if (!console.n) {
        fx_vt_hooks hooks = {console_release, console_acquire, NULL};
        if (fx_vt_enter(&console.vt, &d->log, d->opt.vt_switch == FX_VT_SWITCH_DENY, &hooks) < 0)
            console.vt = NULL; /* logged; a display without a VT (ssh, serial) still works */
    }
    console.member[console.n++] = d;
    d->vt = console.vt;
}

static void console_leave(fx_display *d)
{
    int i = 0;
    while (i < console.n && console.member[i] != d)
        i++;
    if (i == console.n)
        return;
    console.member[i] = console.member[--console.n];
    if (!console.n && console.vt) {
        fx_vt_leave(console.vt);
        console.vt = NULL;
    }
    d->vt = NULL;
}

/* The signal path (async-signal-safe): the backend's restore, then the
 * console's. */
static void emergency_restore(void *user)
{
    fx_display *d = user;
    if (d->ops && d->ops->emergency_restore)
        d->ops->emergency_restore(d);
    fx_vt_emergency_restore(d->vt);
}

static int open_backend(fx_display *d, fx_backend b)
{
    switch (b) {
    case FX_BACKEND_DRM: return fx_drm_open(d);
    case FX_BACKEND_FBDEV: return fx_fbdev_open(d);
    default: return fx_memory_open(d);
    }
}

static void reset_backend(fx_display *d)
{
    if (d->ops)
        d->ops->close(d);
    d->ops = NULL;
    d->priv = NULL;
    memset(d->scan, 0, sizeof d->scan);
    memset(&d->info, 0, sizeof d->info);
    d->nbuf = 0;
    d->opt.rotation = d->rotation_default; /* the failed backend may have taken a panel's */
    d->sw_rotation = d->opt.rotation;
    d->rotation_why = NULL;
    /* else the next backend's log line names the device that failed */
    d->device[0] = 0;
    d->connector[0] = 0;
}

static int alloc_shadow(fx_display *d)
{
    int32_t lw, lh;
    fx_rotated_size(d->sw_rotation, d->info.width, d->info.height, &lw, &lh);
    int32_t stride = (fx_format_min_stride(d->info.format, lw) + 15) & ~15;
    free(d->shadow_mem);
    d->shadow_mem = calloc((size_t)lh, (size_t)stride);
    if (!d->shadow_mem)
        return -FX_ENOMEM;
    return fx_surface_init(&d->shadow, d->shadow_mem, lw, lh, stride, d->info.format);
}

static int display_resized(fx_display *d)
{
    int r = 0;
    if (d->info.present == FX_PRESENT_SHADOW)
        r = alloc_shadow(d);
    fx_damage_reset(&d->prev);
    d->repair = 0;
    /* New buffers: nothing of ours is drawn in them. */
    for (int i = 0; i < 2; i++)
        d->ptr.save[i].r = (fx_rect){0, 0, 0, 0};
    d->ptr.undrawn = (fx_rect){0, 0, 0, 0};
    d->ptr.drawing = 0;
    d->info.reshapes++;
    int32_t lw, lh;
    fx_rotated_size(d->sw_rotation, d->info.width, d->info.height, &lw, &lh);
    fx_display_log(d, FX_LOG_INFO, "display is now %dx%d", d->info.width, d->info.height);
    if (d->reshape_cb)
        d->reshape_cb(d, lw, lh, d->reshape_user);
    return r;
}

static int choose_present(fx_display *d)
{
    fx_present_mode m = d->opt.present;
    const char *why;
    if (m == FX_PRESENT_DIRECT && d->sw_rotation != 0) {
        fx_display_log(d, FX_LOG_INFO, "rotation %d needs a back buffer: shadow presentation",
                       d->sw_rotation);
        m = FX_PRESENT_SHADOW;
    }
    if (m == FX_PRESENT_AUTO) {
        if (d->sw_rotation != 0) {
            m = FX_PRESENT_SHADOW;
            why = "software rotation";
        } else if (d->nbuf < 2 && d->info.backend != FX_BACKEND_MEMORY) {
            m = FX_PRESENT_SHADOW;
            why = "single-buffered scanout (no tearing-free direct drawing)";
        } else {
            m = FX_PRESENT_DIRECT;
            why = d->nbuf < 2 ? "memory surface" : "two scanout buffers, flip without copy";
        }
        fx_display_log(d, FX_LOG_DEBUG, "%s presentation: %s",
                       m == FX_PRESENT_DIRECT ? "direct" : "shadow", why);
    }
    d->info.present = m;
    if (m == FX_PRESENT_SHADOW)
        return alloc_shadow(d);
    return 0;
}

int fx_display_open(fx_display **out, const fx_display_options *opt)
{
    fx_display_options defaults;
    *out = NULL;
    if (!opt) {
        fx_display_options_init(&defaults);
        opt = &defaults;
    }
    fx_display *d = calloc(1, sizeof *d);
    if (!d)
        return -FX_ENOMEM;
    d->opt = *opt;
    d->log.fn = opt->log ? opt->log : fx_log_stderr;
    d->log.user = opt->log_user;
    d->log.priority = opt->log_priority ? opt->log_priority : FX_LOG_INFO;
    d->resized = display_resized;
    d->shown = -1;
    d->epoll_fd = -1;
    d->pace_fd = -1;
    d->ptr.sprite = *fx_sprite_arrow();
    for (int i = 0; i < 2; i++) {
        d->ptr.save[i].mem = d->ptr.mem[i];
        d->ptr.save[i].cap = FX_SPRITE_MAX * FX_SPRITE_MAX;
    }

    d->rotation_asked = d->opt.rotation >= 0;
    if (d->opt.rotation < 0)
        d->opt.rotation = FX_BOARD_ROTATION;
    d->rotation_default = d->opt.rotation;
    if (d->opt.rotation != 0 && d->opt.rotation != 90 && d->opt.rotation != 180 &&
        d->opt.rotation != 270) {
        fx_display_log(d, FX_LOG_ERROR, "rotation %d is not 0, 90, 180 or 270", d->opt.rotation);
        free(d);
        return -FX_EINVAL;
    }
    /* Backends that rotate in hardware set it to 0. */
    d->sw_rotation = d->opt.rotation;

    fx_backend b = d->opt.backend;
    char reasons[256] = "";
    const char *why = "requested by the program";
    if (d->opt.backend_from_env) {
        why = "FIXEL_BACKEND"; /* and FIXEL_BACKEND=auto skips the board default */
    } else if (b == FX_BACKEND_AUTO) {
        if (parse_backend(FX_BOARD_BACKEND, &b) == 0 && b != FX_BACKEND_AUTO)
            why = "board profile default";
    }

    int r;
    if (b != FX_BACKEND_AUTO) {
        d->info.backend = b;
        r = open_backend(d, b);
        if (r < 0) {
            /* Backends say nothing at error level about a device that is
             * not there (auto probing expects that): say it here. */
            if (r == -FX_ENOENT || r == -FX_ENODEV)
                fx_display_log(d, FX_LOG_ERROR,
                               "no %s display found (%s%s%s): is its driver loaded? "
                               "FIXEL_BACKEND=memory runs headless",
                               fx_backend_name(b), d->device[0] ? d->device : "",
                               d->device[0] ? ": " : "", err_text(r));
            reset_backend(d);
            free(d);
            return r;
        }
    } else {
        /* Automatic order; remember each failure for the one log line. */
        static const fx_backend order[] = {FX_BACKEND_DRM, FX_BACKEND_FBDEV, FX_BACKEND_MEMORY};
        r = -FX_ENODEV;
        for (unsigned i = 0; i < sizeof order / sizeof order[0]; i++) {
            d->info.backend = order[i];
            r = open_backend(d, order[i]);
            if (r >= 0)
                break;
            reset_backend(d);
            size_t l = strlen(reasons);
            snprintf(reasons + l, sizeof reasons - l, "%s%s: %s", l ? "; " : "",
                     fx_backend_name(order[i]), err_text(r));
        }
        if (r < 0) {
            free(d);
            return r;
        }
        why = reasons[0] ? reasons : "first in the automatic order";
    }
    d->info.backend = b == FX_BACKEND_AUTO ? d->info.backend : b;
    d->info.rotation = d->opt.rotation;
    d->info.rotation_hw = d->opt.rotation != d->sw_rotation;
    if (!d->rotation_why)
        d->rotation_why = "in software";
    if (d->info.backend != FX_BACKEND_DRM)
        d->info.connected = 1;
    d->info.buffers = d->nbuf;
    d->info.device = d->device;
    d->info.connector = d->connector;

    r = choose_present(d);
    if (r < 0) {
        fx_display_close(d);
        return r;
    }
    fx_display_info pi;
    fx_display_get_info(d, &pi);
    fx_display_log(d, FX_LOG_INFO, "%s%s%s%s%s %dx%d %s, %s, %d buffer%s, rotation %d%s%s (%s)",
                   fx_backend_name(d->info.backend), d->device[0] ? " " : "", d->device,
                   d->connector[0] ? " " : "",
                   d->connector, pi.width, pi.height,
                   fx_format_get(d->info.format)->name,
                   d->info.present == FX_PRESENT_DIRECT ? "direct" : "shadow", d->nbuf,
                   d->nbuf == 1 ? "" : "s", d->opt.rotation,
                   d->opt.rotation ? " " : "", d->opt.rotation ? d->rotation_why : "", why);

    if (d->info.backend != FX_BACKEND_MEMORY && d->opt.console)
        console_join(d);
    if (d->opt.signals && d->info.backend != FX_BACKEND_MEMORY)
        fx_signals_register(emergency_restore, d);
    d->info.vt = fx_vt_number(d->vt);

    /* One fd for event loops: flip events, hotplug and VT switch requests. */
    int fds[3] = {d->ops->fd(d), fx_vt_event_fd(d->vt), d->ops->hotplug_fd ? d->ops->hotplug_fd(d) : -1};
    d->epoll_fd = -1;
    if (fds[0] >= 0 || fds[1] >= 0 || fds[2] >= 0) {
        d->epoll_fd = epoll_create1(EPOLL_CLOEXEC);
        for (int i = 0; i < 3 && d->epoll_fd >= 0; i++) {
            struct epoll_event ev = {.events = EPOLLIN, .data.fd = fds[i]};
            if (fds[i] >= 0 && epoll_ctl(d->epoll_fd, EPOLL_CTL_ADD, fds[i], &ev) < 0)
                fx_display_log(d, FX_LOG_ERROR, "epoll_ctl: %s", strerror(errno));
        }
    }
    *out = d;
    return 0;
}

void fx_display_close(fx_display *d)
{
    if (!d)
        return;
    if (d->ops && d->flip_pending && !d->paced)
        d->ops->wait(d, 200);
    if (d->opt.signals && d->info.backend != FX_BACKEND_MEMORY)
        fx_signals_unregister(emergency_restore, d);
    /* A kiosk stopped at night must not leave the console dark. */
    if (d->ops && d->power_off && d->ops->set_power)
        d->ops->set_power(d, 1);
    if (d->ops)
        d->ops->close(d);
    console_leave(d);
    if (d->epoll_fd >= 0)
        close(d->epoll_fd);
    if (d->pace_fd >= 0)
        close(d->pace_fd);
    free(d->shadow_mem);
    free(d);
}

/* ---- software pointer ---------------------------------------------------- */

static const fx_rect no_rect = {0, 0, 0, 0};

/* Take buffer buf's sprite out; returns the physical rectangle touched. */
static fx_rect ptr_undraw(fx_display *d, int buf)
{
    return fx_sprite_restore(&d->scan[buf], &d->ptr.save[buf]);
}

/* Draw the sprite into buffer buf (which must hold none); returns the
 * physical rectangle touched. Shadow buffers are physical and rotated;
 * direct buffers are the program's unrotated surface. */
static fx_rect ptr_draw(fx_display *d, int buf)
{
    if (!d->ptr.visible)
        return no_rect;
    int rot = d->info.present == FX_PRESENT_SHADOW ? d->sw_rotation : 0;
    if (fx_sprite_draw(&d->scan[buf], rot, &d->ptr.sprite, d->ptr.x, d->ptr.y, &d->ptr.save[buf]) < 0)
        return no_rect;
    return d->ptr.save[buf].r;
}

/* Bring the buffer on screen up to the pointer state: old and new sprite
 * rectangles only, no frame. */
static void ptr_refresh(fx_display *d)
{
    int b = d->shown;
    /* Before the first frame, while away, or while the program is drawing
     * into the only buffer, the next present draws the pointer. */
    if (b < 0 || d->away || d->ptr.drawing)
        return;
    fx_rect phys[2];
    int n = 0;
    phys[0] = ptr_undraw(d, b);
    phys[1] = ptr_draw(d, b);
    if (!fx_rect_empty(phys[0]))
        n++;
    if (!fx_rect_empty(phys[1]))
        phys[n++] = phys[1];
    if (n == 0)
        return;
    d->info.pointer_updates++;
    d->ops->show(d, b, phys, n); /* the buffer on screen: DIRTYFB at most, never a flip */
}

void fx_display_set_pointer(fx_display *d, int visible, int32_t x, int32_t y)
{
    visible = visible != 0;
    if (visible == d->ptr.visible && (!visible || (x == d->ptr.x && y == d->ptr.y)))
        return;
    d->ptr.visible = visible;
    d->ptr.x = x;
    d->ptr.y = y;
    ptr_refresh(d);
}

int fx_display_set_pointer_sprite(fx_display *d, const fx_sprite *s)
{
    if (!s)
        s = fx_sprite_arrow();
    if (fx_sprite_check(s) < 0)
        return -FX_EINVAL;
    d->ptr.sprite = *s;
    if (s != fx_sprite_arrow()) {
        memcpy(d->ptr.image, s->pixels, (size_t)s->w * (size_t)s->h * sizeof *s->pixels);
        d->ptr.sprite.pixels = d->ptr.image;
    }
    if (d->ptr.visible)
        ptr_refresh(d);
    return 0;
}

int fx_display_set_power(fx_display *d, int on)
{
    on = on != 0;
    if (!d->ops)
        return -FX_EINVAL;
    if (on == !d->power_off)
        return 0;
    if (d->ops->set_power) {
        int r = d->ops->set_power(d, on);
        if (r < 0) {
            fx_log(&d->log, FX_LOG_ERROR, "screen %s (%s) failed: %s", on ? "on" : "off",
                   fx_display_power_method(d), strerror(-r));
            return r;
        }
    }
    d->power_off = !on;
    if (on && d->paced && !d->away)
        pace_done(d); /* the screen paces the next frame again */
    fx_log(&d->log, FX_LOG_INFO, "screen %s (%s)", on ? "on" : "off", fx_display_power_method(d));
    return 0;
}

int fx_display_power(const fx_display *d)
{
    return !d->power_off;
}

const char *fx_display_power_method(const fx_display *d)
{
    return d->power_method ? d->power_method : "none";
}

fx_surface fx_display_screen(const fx_display *d)
{
    return d->scan[d->shown >= 0 ? d->shown : 0];
}

/* ---- frames ------------------------------------------------------------ */

/* While the screen is off (or our VT is not shown) a present shows nothing
 * and no flip completes, so a program that draws again as soon as no flip
 * is pending would draw as fast as the CPU allows. A timer at the mode's
 * refresh stands in for vblank: the present counts as a pending flip until
 * it fires, on the display's fd like a flip event. */
static int64_t pace_period_ns(const fx_display *d)
{
    int32_t mhz = d->info.refresh_mhz;
    if (mhz < 1000 || mhz > 1000000)
        mhz = 60000; /* unknown (memory, some fbdev): 60 Hz */
    return 1000000000000 / mhz;
}

static void pace_start(fx_display *d)
{
    if (d->pace_fd < 0) {
        d->pace_fd = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
        if (d->pace_fd < 0)
            return;
        if (d->epoll_fd < 0)
            d->epoll_fd = epoll_create1(EPOLL_CLOEXEC);
        struct epoll_event ev = {.events = EPOLLIN, .data.fd = d->pace_fd};
        if (d->epoll_fd < 0 || epoll_ctl(d->epoll_fd, EPOLL_CTL_ADD, d->pace_fd, &ev) < 0) {
            close(d->pace_fd);
            d->pace_fd = -1;
            return;
        }
    }
    int64_t ns = pace_period_ns(d);
    struct itimerspec its;
    memset(&its, 0, sizeof its);
    its.it_value.tv_sec = (time_t)(ns / 1000000000);
    its.it_value.tv_nsec = (long)(ns % 1000000000);
    if (timerfd_settime(d->pace_fd, 0, &its, NULL) < 0)
        return;
    d->paced = 1;
    d->flip_pending = 1;
}

static void pace_done(fx_display *d)
{
    struct itimerspec off;
    memset(&off, 0, sizeof off);
    timerfd_settime(d->pace_fd, 0, &off, NULL); /* also clears a pending expiry */
    d->paced = 0;
    d->flip_pending = 0;
    if (d->flip_cb)
        d->flip_cb(d, d->flip_user);
}

/* The paced present completes when its timer fires: 0, or 1 when
 * timeout_ms passed first. */
static int pace_wait(fx_display *d, int timeout_ms)
{
    struct pollfd p = {d->pace_fd, POLLIN, 0};
    int r;
    do
        r = poll(&p, 1, timeout_ms);
    while (r < 0 && errno == EINTR);
    if (r <= 0)
        return 1;
    pace_done(d);
    return 0;
}

static void wait_flip(fx_display *d)
{
    if (d->paced)
        pace_wait(d, 1000);
    else if (d->flip_pending)
        d->ops->wait(d, 1000);
}

fx_surface fx_display_surface(fx_display *d)
{
    fx_vt_handle_events(d->vt);
    if (d->info.present == FX_PRESENT_SHADOW)
        return d->shadow;
    wait_flip(d);
    int b = d->nbuf == 2 ? d->back : 0;
    /* No longer on screen (or about to be drawn over): the program gets its
     * own pixels back. */
    fx_rect gone = ptr_undraw(d, b);
    if (d->nbuf == 1 && !fx_rect_empty(gone))
        d->ptr.undrawn = gone;
    if (d->repair && d->nbuf == 2) {
        /* The back buffer holds the frame before last: bring it up to the
         * picture on screen by copying what the last frame changed. */
        for (int i = 0; i < d->prev.n; i++)
            fx_copy_rotated(&d->scan[d->back], &d->scan[d->back ^ 1], d->prev.r[i], 0);
        /* The copy may have carried the front's sprite along; the front's
         * save holds the picture under it, which is the back's picture now. */
        fx_sprite_save_apply(&d->scan[b], &d->ptr.save[b ^ 1]);
    }
    d->repair = 0;
    if (d->nbuf == 1)
        d->ptr.drawing = 1;
    return d->scan[b];
}

int fx_display_present(fx_display *d, const fx_rect *damage, int n)
{
    fx_damage cur;
    fx_rect bounds = {0, 0, 0, 0};
    fx_rect phys[FX_DAMAGE_MAX];
    int r;

    if (d->info.present == FX_PRESENT_SHADOW) {
        bounds.x1 = d->shadow.w;
        bounds.y1 = d->shadow.h;
    } else {
        bounds.x1 = d->info.width;
        bounds.y1 = d->info.height;
    }
    fx_damage_reset(&cur);
    if (!damage || n <= 0)
        fx_damage_add(&cur, bounds, bounds);
    else
        for (int i = 0; i < n; i++)
            fx_damage_add(&cur, damage[i], bounds);
    if (cur.n == 0)
        return 0;

    fx_vt_handle_events(d->vt);
    /* Switched away, fbdev memory shows another VT's console: leave it
     * alone; the return to our VT redraws from the shadow. */
    if (d->away && d->info.backend == FX_BACKEND_FBDEV) {
        if (!d->flip_pending)
            pace_start(d); /* not drawn, but paced like the others */
        return 0;
    }
    wait_flip(d);
    int target = d->nbuf == 2 ? d->back : 0;
    fx_rect ptr_old = d->shown >= 0 ? d->ptr.save[d->shown].r : no_rect;
    /* Shadow: the target's pixels under its old sprite are stale picture the
     * copy below brings up to date. Direct: normally already out (taken at
     * fx_display_surface). */
    ptr_undraw(d, target);
    if (d->info.present == FX_PRESENT_SHADOW) {
        /* A flipped-to buffer last received the frame before the previous
         * one: it needs this frame's damage and the previous frame's. */
        fx_damage todo = cur;
        if (d->nbuf == 2) {
            if (d->shown < 0)
                fx_damage_add(&todo, bounds, bounds);
            for (int i = 0; i < d->prev.n; i++)
                fx_damage_add(&todo, d->prev.r[i], bounds);
        }
        for (int i = 0; i < todo.n; i++)
            fx_copy_rotated(&d->scan[target], &d->shadow, todo.r[i], d->sw_rotation);
    }
    d->ptr.drawing = 0;
    fx_rect ptr_new = ptr_draw(d, target);
    /* Physical damage: the frame's, and both sprite rectangles (for DIRTYFB
     * drivers). Rotation keeps the logical list's non-overlap and merge
     * costs, so without a pointer this is the rotated list itself. */
    fx_damage pd;
    fx_rect pbounds = {0, 0, d->info.width, d->info.height};
    fx_damage_reset(&pd);
    for (int i = 0; i < cur.n; i++)
        fx_damage_add(&pd, fx_rect_rotate(cur.r[i], d->sw_rotation, d->info.width, d->info.height),
                      pbounds);
    fx_damage_add(&pd, ptr_old, pbounds);
    fx_damage_add(&pd, d->ptr.undrawn, pbounds);
    fx_damage_add(&pd, ptr_new, pbounds);
    d->ptr.undrawn = no_rect;
    for (int i = 0; i < pd.n; i++)
        phys[i] = pd.r[i];
    /* DRM buffers are ours even while away: keep the bookkeeping as if
     * shown, so the return puts the latest frame up. */
    r = d->away ? 0 : d->ops->show(d, target, phys, pd.n);
    if (r < 0)
        return r;
    if ((d->power_off || d->away) && !d->flip_pending)
        pace_start(d);
    d->shown = target;
    if (d->nbuf == 2) {
        d->back ^= 1;
        d->repair = d->info.present == FX_PRESENT_DIRECT;
    }
    d->prev = cur;
    return 0;
}

/* ---- event-loop plumbing ------------------------------------------------ */

int fx_display_fd(const fx_display *d)
{
    return d->epoll_fd;
}

int fx_display_dispatch(fx_display *d)
{
    fx_vt_handle_events(d->vt);
    if (d->paced)
        pace_wait(d, 0);
    return d->ops->dispatch(d);
}

/* ---- VT switching ------------------------------------------------------- */

static int vt_release(void *user)
{
    fx_display *d = user;
    if (d->opt.vt_switch == FX_VT_SWITCH_DENY) {
        d->info.vt_refused++;
        fx_display_log(d, FX_LOG_DEBUG, "VT switch refused (kiosk policy)");
        return 0;
    }
    wait_flip(d);
    if (d->ops->suspend)
        d->ops->suspend(d);
    d->away = 1;
    d->info.vt_away++;
    fx_display_log(d, FX_LOG_DEBUG, "VT switched away: display released");
    if (d->vt_cb)
        d->vt_cb(d, 0, d->vt_user);
    return 1;
}

static void vt_acquire(void *user)
{
    fx_display *d = user;
    if (d->ops->resume && d->ops->resume(d) < 0)
        fx_display_log(d, FX_LOG_ERROR, "back on our VT but the display could not be retaken");
    if (d->info.backend == FX_BACKEND_FBDEV && d->info.present == FX_PRESENT_SHADOW && d->shown >= 0)
        fx_copy_rotated(&d->scan[d->shown], &d->shadow, fx_surface_rect(&d->shadow), d->sw_rotation);
    d->away = 0;
    ptr_refresh(d); /* moves while away, or a console that painted over it */
    d->info.vt_back++;
    fx_display_log(d, FX_LOG_DEBUG, "back on our VT: display retaken");
    if (d->vt_cb)
        d->vt_cb(d, 1, d->vt_user);
}

void fx_display_set_reshape_callback(fx_display *d, void (*cb)(fx_display *, int32_t, int32_t, void *),
                                     void *user)
{
    d->reshape_cb = cb;
    d->reshape_user = user;
}

void fx_display_set_vt_callback(fx_display *d, void (*cb)(fx_display *, int, void *), void *user)
{
    d->vt_cb = cb;
    d->vt_user = user;
}

int fx_display_active(const fx_display *d)
{
    return !d->away;
}

int fx_display_switch_vt(fx_display *d, int n)
{
    return d->vt ? fx_vt_activate(d->vt, n) : -FX_ENOTSUP;
}

int fx_display_wait(fx_display *d, int timeout_ms)
{
    if (d->paced)
        return pace_wait(d, timeout_ms < 0 ? 0 : timeout_ms) ? -FX_EBUSY : 0;
    return d->flip_pending ? d->ops->wait(d, timeout_ms) : 0;
}

int fx_display_flip_pending(const fx_display *d)
{
    return d->flip_pending;
}

void fx_display_set_flip_callback(fx_display *d, void (*cb)(fx_display *, void *), void *user)
{
    d->flip_cb = cb;
    d->flip_user = user;
}

void fx_display_get_info(const fx_display *d, fx_display_info *info)
{
    *info = d->info;
    if (d->info.rotation_hw && (d->info.rotation == 90 || d->info.rotation == 270)) {
        /* The plane turns the logical-size buffer: report the screen. */
        info->width = d->info.height;
        info->height = d->info.width;
    }
}
