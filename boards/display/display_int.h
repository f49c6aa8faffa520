/* SPDX-License-Identifier: MIT */
/* Internal to boards/: the display object and the backend ops table, shared
 * by the front end (boards/display/display.c, which also sees the console)
 * and the backends (boards/memory, boards/linux/display, boards/linux/drm),
 * which see only this header and the posix layer; and the pure helpers of
 * present.c and formats.c (which tests/boards exercises through this header,
 * libevdev style). Not installed. */
#ifndef FIXEL_DISPLAY_INT_H
#define FIXEL_DISPLAY_INT_H

#include <stdint.h>

#include "../posix/posix_int.h"
#include "fixel/display.h"
#include "fixel/scanout.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"

/* ---- pure helpers (present.c, formats.c: no OS headers, no allocation;
 * the public ones are in fixel/scanout.h) ---- */

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
/* The clockwise rotation that shows a picture upright on a panel whose
 * connector property "panel orientation" has this enum name ("Normal",
 * "Upside Down", "Left Side Up", "Right Side Up"), as the kernel's own
 * console turns it; -1 for any other name. */
int fx_panel_orientation_rotation(const char *name);
/* The values of a connector's "DPMS" enum property for on and off (the
 * kernel's entries are "On", "Standby", "Suspend", "Off"). Returns 0, or -1
 * when either entry is missing (the property is not usable). */
int fx_dpms_values(const fx_prop_enum *e, int n, uint64_t *on, uint64_t *off);

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
    /* From a fatal or terminating signal: put back what the backend changed
     * (CRTC, plane rotation) with async-signal-safe calls only; NULL when
     * there is nothing to restore. */
    void (*emergency_restore)(fx_display *d);
    /* Screen power (fx_display_set_power); NULL: only remembered. */
    int (*set_power)(fx_display *d, int on);
};

struct fx_display {
    fx_display_options opt;
    fx_logger log;          /* the program's log function and level */

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
    int rotation_asked;     /* the program or FIXEL_ROTATION gave opt.rotation: a panel's
                               orientation property must not change it */
    int rotation_default;   /* opt.rotation as resolved before any backend (each retry starts
                               from it; the DRM backend may take the panel's instead) */
    const char *rotation_why; /* how the rotation is done, for the log line */

    fx_surface shadow;      /* shadow mode: logical back buffer */
    void *shadow_mem;
    void *memory_mem;       /* memory backend's buffer */

    void (*flip_cb)(fx_display *d, void *user);
    void *flip_user;

    struct fx_vt *vt;       /* the console (boards/linux/console), NULL when none */
    int epoll_fd;           /* DRM fd + VT signal pipe, for event loops */
    int away;               /* our VT is not on screen */
    int power_off;          /* fx_display_set_power(d, 0): presents are not shown */
    int pace_fd;            /* timerfd standing in for vblank while the screen is off, or -1 */
    int paced;              /* flip_pending is a paced present (pace_fd), not a real flip */
    const char *power_method; /* set by the backend: "dpms", "crtc", "fbblank"; NULL: "none" */
    void (*vt_cb)(fx_display *d, int active, void *user);
    void *vt_user;
    void (*reshape_cb)(fx_display *d, int32_t w, int32_t h, void *user);
    void *reshape_user;
    /* Set by the front end: backends call it after replacing scan[] with
     * buffers of a new size (d->info.width/height updated); the shadow
     * follows, the program is told. */
    int (*resized)(fx_display *d);

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

/* Backends call this when a flip completes. */
static inline void fx_display_flip_done(fx_display *d)
{
    d->flip_pending = 0;
    d->info.flips++;
    if (d->flip_cb)
        d->flip_cb(d, d->flip_user);
}

/* Backends: fill d->scan[], d->nbuf, d->info and d->ops, or fail with a
 * logged reason. The front end calls them (boards/memory,
 * boards/linux/display, boards/linux/drm or boards/linux/absent). */
int fx_drm_open(fx_display *d);
int fx_fbdev_open(fx_display *d);
int fx_memory_open(fx_display *d);

#endif
