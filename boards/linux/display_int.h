/* SPDX-License-Identifier: MIT */
/* Internal to boards/linux: the display object shared by display.c, drm.c,
 * fbdev.c and vt.c, and the pure helpers of present.c (which tests/core
 * exercises through this header, libevdev style). Not installed. */
#ifndef FIXEL_DISPLAY_INT_H
#define FIXEL_DISPLAY_INT_H

#include <stdint.h>

#include "fixel/display.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"

/* ---- pure helpers (present.c: no OS headers, no allocation) ---- */

/* fbdev pixel layout as FBIOGET_VSCREENINFO reports it, reduced to the
 * fields that decide the format. */
typedef struct fx_fb_bitfields {
    uint32_t bits_per_pixel;
    uint32_t grayscale;        /* 1 = gray, 0 = colour (fourcc values are not handled) */
    uint32_t red_offset, red_length;
    uint32_t green_offset, green_length;
    uint32_t blue_offset, blue_length;
    uint32_t transp_offset, transp_length;
    int mono_inverted;         /* FB_VISUAL_MONO01: a set bit is black */
} fx_fb_bitfields;

/* The fixel format matching the layout, or FX_FMT_COUNT when none does. */
fx_format fx_fb_format_from_bitfields(const fx_fb_bitfields *b);

/* "WxH" or "WxH@Hz" (decimal, no spaces). hz is 0 when absent. Returns 0 or
 * -FX_EINVAL. */
int fx_mode_parse(const char *s, int32_t *w, int32_t *h, int32_t *hz);

/* A damage list: at most FX_DAMAGE_MAX pairwise non-intersecting rectangles
 * whose union covers every rectangle added since the last reset. Rectangles
 * that overlap are merged, and so are neighbours whose union costs no more
 * pixels than the two apart; when the list is full the pair whose merge adds
 * the fewest pixels is merged. */
#define FX_DAMAGE_MAX 8
typedef struct fx_damage {
    fx_rect r[FX_DAMAGE_MAX];
    int n;
} fx_damage;

void fx_damage_reset(fx_damage *d);
/* Adds r clipped to bounds (empty results are ignored). */
void fx_damage_add(fx_damage *d, fx_rect r, fx_rect bounds);
int64_t fx_damage_area(const fx_damage *d);

/* Physical size of a logical w x h surface under rotation, and back: 90 and
 * 270 swap the sides. */
void fx_rotated_size(int rotation, int32_t w, int32_t h, int32_t *rw, int32_t *rh);


/* Copy logical rectangle r of src into dst under rotation. src and dst have
 * the same format; dst is the physical surface (sides swapped for 90/270);
 * r must lie inside src. Every format is supported, MONO1 included. */
void fx_copy_rotated(const fx_surface *dst, const fx_surface *src, fx_rect r, int rotation);

/* A DRM plane's "rotation" property: its enum entries as the kernel lists
 * them (struct drm_mode_property_enum). Values of a bitmask property are
 * ORs of 1 << entry value. */
typedef struct fx_prop_enum {
    uint64_t value;
    char name[32];
} fx_prop_enum;
#define FX_PLANE_ROTATE_0 (1u << 0) /* DRM_MODE_ROTATE_*: counter-clockwise */
#define FX_PLANE_ROTATE_90 (1u << 1)
#define FX_PLANE_ROTATE_180 (1u << 2)
#define FX_PLANE_ROTATE_270 (1u << 3)

/* The DRM rotation bits the entries offer (names and bit numbers must both
 * match the kernel's, or the entry is ignored). */
uint32_t fx_plane_rotation_mask(const fx_prop_enum *e, int n);
/* The DRM bit that shows fixel's clockwise rotation (0/90/180/270), 0 for
 * other angles. */
uint32_t fx_plane_rotation_bit(int rotation);
/* 1 when the plane should rotate: rotation != 0, not forced to software,
 * the property exists and offers the angle. *why explains the choice. */
int fx_plane_rotation_choose(int rotation, int has_property, uint32_t mask, int force_software,
                             const char **why);
/* The scanout format for a DRM plane: want is FX_FMT_XRGB8888, FX_FMT_RGB565
 * or FX_FMT_COUNT (automatic: XRGB8888 unless only RGB565 is offered); a
 * requested format the plane lacks falls back to the other. FX_FMT_COUNT
 * when nothing usable is offered or want is another format. */
fx_format fx_drm_format_choose(fx_format want, int has_xrgb, int has_565, const char **why);

/* ---- blocking calls with a timeout (waiter.c) ---- */

typedef struct fx_waiter fx_waiter;
/* A helper thread (all signals blocked) that runs fn(arg) on request. */
int fx_waiter_create(fx_waiter **w, int (*fn)(void *arg), void *arg);
/* Run fn and wait at most timeout_ms: 0 when it returned (its value in
 * *result), 1 when it is still running (a later run waits for, or collects,
 * that same call instead of starting another). */
int fx_waiter_run(fx_waiter *w, int timeout_ms, int *result);
/* Stop the thread; one stuck in fn is left to free everything itself. */
void fx_waiter_destroy(fx_waiter *w);

/* ---- the display object ---- */

struct fx_backend_ops {
    /* Make buffer buf visible; phys lists its changed physical rectangles. */
    int (*show)(fx_display *d, int buf, const fx_rect *phys, int n);
    /* Wait up to timeout_ms for a queued flip; 0 when none is pending. */
    int (*wait)(fx_display *d, int timeout_ms);
    int (*dispatch)(fx_display *d);
    int (*fd)(const fx_display *d);
    void (*close)(fx_display *d);
    /* VT switched away: give the device up (DRM master). */
    int (*suspend)(fx_display *d);
    /* VT back: take it again and show buffer d->shown as it is. */
    int (*resume)(fx_display *d);
    /* A second fd for the event loop (DRM: kernel uevents), or -1. */
    int (*hotplug_fd)(const fx_display *d);
};

typedef struct fx_vt fx_vt;

struct fx_display {
    fx_display_options opt;
    fx_log_func log;
    void *log_user;
    int log_priority;

    const struct fx_backend_ops *ops;
    void *priv;
    fx_display_info info;
    char device[64];
    char connector[32];

    fx_surface scan[2];     /* scanout buffers (physical size, logical when the plane rotates);
                               info.width/height hold their size until get_info */
    int nbuf;
    int back;               /* index of the off-screen buffer */
    int shown;              /* index on screen, -1 before the first present */
    int flip_pending;
    int repair;             /* direct mode: copy prev damage front->back before drawing */
    fx_damage prev;         /* logical damage of the last presented frame */

    int sw_rotation;        /* rotation done by copying (0 when the plane rotates) */
    const char *rotation_why; /* how the rotation is done, for the log line */

    fx_surface shadow;      /* shadow mode: logical back buffer */
    void *shadow_mem;
    void *memory_mem;       /* memory backend's buffer */

    void (*flip_cb)(fx_display *d, void *user);
    void *flip_user;

    fx_vt *vt;
    int epoll_fd;           /* DRM fd + VT signal pipe, for event loops */
    int away;               /* our VT is not on screen */
    void (*vt_cb)(fx_display *d, int active, void *user);
    void *vt_user;
    void (*reshape_cb)(fx_display *d, int32_t w, int32_t h, void *user);
    void *reshape_user;

    /* Software pointer: drawn only into scanout buffers, never into the
     * program's surface (direct mode takes it out again before handing the
     * buffer over). save[i] holds what buffer i has under its sprite. */
    struct {
        int visible;
        int32_t x, y;           /* logical hotspot position */
        int drawing;            /* direct, one buffer: the program holds the surface */
        fx_rect undrawn;        /* direct, one buffer: where it was taken out, still to be
                                 * reported with the frame (DIRTYFB) */
        fx_sprite sprite;
        uint32_t image[FX_SPRITE_MAX * FX_SPRITE_MAX];
        fx_sprite_save save[2];
        uint32_t mem[2][FX_SPRITE_MAX * FX_SPRITE_MAX];
    } ptr;
};

/* Backends call this after replacing scan[] with buffers of a new size
 * (d->info.width/height updated): the shadow follows, the program is told. */
int fx_display_resized(fx_display *d);

void fx_display_logv(const fx_display *d, fx_log_priority p, const char *fmt, va_list ap);
/* Called by backends when a flip completes. */
void fx_display_flip_done(fx_display *d);

/* Backends: fill d->scan[], d->nbuf, d->info and d->ops, or fail with a
 * logged reason. */
int fx_drm_open(fx_display *d);
int fx_fbdev_open(fx_display *d);

/* For the emergency (signal) path: restore what the backend changed using
 * only async-signal-safe calls. */
void fx_drm_emergency_restore(void *priv);

/* Console: switch to graphics and mute the keyboard; restore. */
int fx_vt_enter(fx_display *d, fx_vt **out);
void fx_vt_leave(fx_vt *vt);
/* VT_PROCESS switching: the fd that becomes readable when a switch is
 * requested (-1 when switching is not handled), and the handler that reads
 * it and calls back into display.c (fx_display_vt_release/acquire). */
int fx_vt_event_fd(const fx_vt *vt);
void fx_vt_handle_events(fx_display *d);
int fx_vt_number(const fx_vt *vt);
int fx_vt_activate(fx_vt *vt, int n);
/* display.c: leave or retake the screen; release returns 1 to allow. */
int fx_display_vt_release(fx_display *d);
void fx_display_vt_acquire(fx_display *d);

/* Fatal/terminating-signal restoration: each open display registers its
 * backend restore and console. */
void fx_signals_register(fx_display *d);
void fx_signals_unregister(fx_display *d);
/* The emergency path for one display (async-signal-safe). */
void fx_vt_emergency_restore(fx_vt *vt);

/* When open() on path fails with EACCES, name the group that owns the node. */
void fx_log_access_hint(const fx_display *d, const char *path);

#endif
