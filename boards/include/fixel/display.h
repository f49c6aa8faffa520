/* SPDX-License-Identifier: MIT */
/* fixel — real displays: DRM/KMS, fbdev and a headless memory display.
 *
 * A display hands the program an fx_surface to draw into and presents damage
 * rectangles. Two presentation modes exist:
 *
 *  direct  the surface IS the off-screen scanout buffer (a DRM dumb buffer or
 *          the hidden page of a panned fbdev); present flips, no copy. Before
 *          each frame the library copies the previous frame's damage from the
 *          front buffer so the surface always holds the last presented picture
 *          (that copy reads scanout memory, which is uncached on some SoCs).
 *  shadow  the surface is a back buffer in normal memory; present copies only
 *          the damaged rows into scanout memory (rotating if asked) and then
 *          flips or, single-buffered, just stores. Never reads scanout memory.
 *
 * AUTO picks direct when the device can double-buffer and no software rotation
 * is needed, shadow otherwise; the choice and its reason are logged once.
 * Rotation is done by the DRM primary plane when it has a "rotation"
 * property offering the angle (the program then draws straight into the
 * scanout buffer), by copying otherwise.
 *
 * The program sees the rotated logical size: with rotation 90 or 270 a
 * 800x480 panel is drawn as 480x800. Rotation is clockwise: the logical
 * picture appears turned 90 degrees clockwise on the physical screen.
 *
 * Event loops: fx_display_fd() is the DRM fd (page-flip completion events)
 * or -1; when it is readable call fx_display_dispatch(). fx_display_surface()
 * waits for a pending flip itself (bounded), so a loop without poll works too.
 *
 * Several displays: open one fx_display per output (its own options:
 * connector, mode, rotation...); each keeps its own surface, size,
 * rotation, presentation, damage, flip pacing and hotplug. Displays on one
 * DRM card share its open file (one DRM master) and never get the same
 * CRTC; the console is taken by the first opened and given back by the
 * last closed; a signal restores all of them. docs/displays.md.
 *
 * Errors are negative fixel error codes (errno values, see fixel/error.h).
 * Diagnostics go through the log function in the options; the default writes
 * lines prefixed "fixel: " to stderr at FX_LOG_INFO and above; log_priority
 * (or FIXEL_LOG=debug|info|error|none, through fixel/env.h) changes that level.
 */
#ifndef FIXEL_DISPLAY_H
#define FIXEL_DISPLAY_H

#include <stdarg.h>
#include <stdint.h>

#include "fixel/log.h"
#include "fixel/sprite.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_display fx_display;

typedef enum fx_backend {
    FX_BACKEND_AUTO,   /* the board profile's, else DRM, then fbdev, then memory */
    FX_BACKEND_DRM,
    FX_BACKEND_FBDEV,
    FX_BACKEND_MEMORY,
} fx_backend;

typedef enum fx_present_mode {
    FX_PRESENT_AUTO,   /* the rule above (FIXEL_PRESENT=direct|shadow through fixel/env.h) */
    FX_PRESENT_DIRECT,
    FX_PRESENT_SHADOW,
} fx_present_mode;

/* What happens when another VT is asked for (chvt, logind, a Ctrl-Alt-Fn
 * the program forwards with fx_display_switch_vt). */
typedef enum fx_vt_switch {
    FX_VT_SWITCH_ALLOW, /* (FIXEL_VT_SWITCH=deny|allow through fixel/env.h) drop the display
                           while away (DRM master released), redraw on return */
    FX_VT_SWITCH_DENY,  /* kiosk: refuse every switch away from the program's VT */
} fx_vt_switch;

typedef struct fx_display_options {
    /* Fields marked [env] are the ones fx_display_options_from_env (fixel/env.h)
     * fills from a FIXEL_* variable when they still hold their unset value,
     * the one given here and set by fx_display_options_init. The library
     * itself never reads the environment. */
    fx_backend backend;    /* [env FIXEL_BACKEND] AUTO: the board profile's BOARD_BACKEND, else
                              DRM, then fbdev, then memory */
    int backend_from_env;  /* set by from_env when backend came from FIXEL_BACKEND (the log line
                              names it, and the board default is skipped) */
    fx_present_mode present; /* [env FIXEL_PRESENT] */
    /* /dev/dri/cardN or /dev/fbN (each backend takes only its kind); NULL:
     * drm_device / fb_device, else the first card with a connected
     * connector / /dev/fb0. */
    const char *device;
    const char *drm_device; /* [env FIXEL_DRM_DEVICE] NULL; a path or a card name (driver,
                               by-path name, cardN: fixel/cards.h, docs/displays.md) */
    const char *fb_device;  /* [env FIXEL_FB_DEVICE] NULL */
    const char *connector; /* [env FIXEL_CONNECTOR] DRM connector name ("HDMI-A-1", searched on
                              every card) or "CARD:NAME" ("vc4:HDMI-A-2"); NULL: first connected */
    const char *mode;      /* [env FIXEL_MODE] "WxH" or "WxH@Hz"; NULL: the preferred mode */
    fx_format format;      /* FX_FMT_XRGB8888 or FX_FMT_RGB565 for DRM (a plane lacking it gets the
                              other), the memory backend's format; FX_FMT_COUNT: drm_format */
    fx_format drm_format;  /* [env FIXEL_DRM_FORMAT=XRGB8888|RGB565] FX_FMT_COUNT: the board
                              profile's BOARD_DRM_FORMAT, else XRGB8888 unless the plane has only RGB565 */
    int rotation;          /* [env FIXEL_ROTATION] 0, 90, 180, 270; -1: the DRM panel's "panel
                              orientation", else the board profile's, else 0 */
    int sw_rotation;       /* [env FIXEL_SW_ROTATION=1] 1: rotate in software even where the DRM
                              plane has a rotation property; 0: the plane rotates when it can */
    int console;           /* 1: KD_GRAPHICS + keyboard off while open (default); 0: leave the VT alone */
    int signals;           /* 1: restore the console/CRTC on fatal and terminating signals (default) */
    fx_vt_switch vt_switch; /* [env FIXEL_VT_SWITCH] VT switching policy (needs console = 1; uses
                               SIGUSR1/SIGUSR2 when the program leaves them at their default).
                               ALLOW is also the unset value: FIXEL_VT_SWITCH=deny turns it to DENY */
    int fb_force_refresh;  /* fbdev: FB_ACTIVATE_FORCE after each present, for drivers that need it */
    int32_t memory_w, memory_h; /* memory backend size (default 640x480) */
    fx_log_func log;       /* NULL: the default stderr logger */
    void *log_user;
    int log_priority;      /* [env FIXEL_LOG] messages above this priority are dropped; 0: FX_LOG_INFO;
                              negative: none */
} fx_display_options;

/* Fill o with the defaults described above. */
void fx_display_options_init(fx_display_options *o);

/* Open a display. On failure *out is NULL and the reason has been logged. */
int fx_display_open(fx_display **out, const fx_display_options *o);
/* Headless boot: block until the output o asks for (o->drm_device / device,
 * o->connector, else any) has a connected connector with modes, logging one
 * line when it has to wait; it wakes on DRM hotplug uevents and re-checks
 * every 5 s for drivers that send none. timeout_ms < 0 waits for ever.
 * Returns 0 when the output is there (or o asks for fbdev or memory), -FX_ENODEV
 * at once when there is nothing to wait for (no KMS card and no output
 * named), -FX_EACCES when the cards may not be opened, 1 on timeout. Call it
 * before fx_display_open / fx_app_open (fixel-kiosk does by default). */
int fx_display_wait_connected(const fx_display_options *o, int timeout_ms);

/* Restore the console and CRTC, free everything. NULL is accepted. */
void fx_display_close(fx_display *d);

/* The surface to draw the next frame into (logical, rotated size). Call it
 * once per frame: in direct mode its pixels alternate between two buffers. */
fx_surface fx_display_surface(fx_display *d);

/* Show the frame. damage lists the changed logical rectangles (clipped here);
 * n == 0 or damage == NULL means the whole surface. Returns 0 or an error. */
int fx_display_present(fx_display *d, const fx_rect *damage, int n);

/* Wait (at most timeout_ms) until the last presented frame is on screen,
 * i.e. no flip is pending. Returns 0, or an error when the flip timed out
 * (the display then falls back to SetCrtc presentation). */
int fx_display_wait(fx_display *d, int timeout_ms);

/* The fd to poll (readable) for the display's events: page-flip completion
 * and hotplug uevents (DRM), VT switch requests. -1 when there is none (memory backend). */
int fx_display_fd(const fx_display *d);
/* Handle pending events of fx_display_fd(); never blocks. fx_display_surface
 * and fx_display_present also handle pending VT switches themselves. */
int fx_display_dispatch(fx_display *d);
/* 1 while a page flip has been queued and has not completed. */
int fx_display_flip_pending(const fx_display *d);
/* Called from fx_display_dispatch (or the wait in fx_display_surface) each
 * time a flip completes. */
void fx_display_set_flip_callback(fx_display *d, void (*cb)(fx_display *d, void *user), void *user);

/* Called when the program's VT is left (active = 0: the display is not
 * shown and presents are dropped) and when it comes back (active = 1: the
 * library has put the last presented frame back on screen, except with
 * direct presentation on fbdev, whose pages the console overwrote: redraw
 * everything and present it). */
void fx_display_set_vt_callback(fx_display *d, void (*cb)(fx_display *d, int active, void *user),
                                void *user);
/* 1 while the program's VT is on screen (always 1 without a console). */
int fx_display_active(const fx_display *d);
/* Ask for VT n (1..63): for programs that forward Ctrl-Alt-Fn from evdev
 * while the console keyboard is muted. Returns 0 or an error. */
int fx_display_switch_vt(fx_display *d, int n);

/* Called after the display changed size: the monitor was replaced or its
 * preferred mode changed (DRM hotplug, seen through kernel uevents). w and h
 * are the new logical size; the next fx_display_surface has it, cleared to
 * black: redraw everything and present it. */
void fx_display_set_reshape_callback(fx_display *d,
                                     void (*cb)(fx_display *d, int32_t w, int32_t h, void *user),
                                     void *user);

typedef struct fx_display_info {
    fx_backend backend;
    fx_present_mode present;  /* the mode in use (never AUTO) */
    const char *device;       /* path opened, "" for memory */
    const char *connector;    /* DRM connector name, "" otherwise */
    int32_t width, height;    /* physical (unrotated) size */
    int32_t refresh_mhz;      /* mode refresh in millihertz, 0 when unknown */
    fx_format format;         /* format of scanout memory */
    int rotation;
    int rotation_hw;          /* 1: the DRM plane rotates (no software copy), 0: software or none */
    int buffers;              /* scanout buffers: 2 when flipping/panning, else 1 */
    int dirtyfb;              /* DRM: 1 when the driver accepted DIRTYFB, 0 refused, -1 not tried */
    uint32_t flips, fallbacks; /* page flips completed, SetCrtc used instead */
    int vt;                   /* the VT held in graphics mode, 0 when none */
    uint32_t vt_away, vt_back, vt_refused; /* VT switch events handled */
    uint32_t hotplugs;        /* DRM hotplug uevents for our card handled */
    int connected;            /* DRM: our connector is connected (1 elsewhere) */
    uint32_t reshapes;        /* size changes after hotplug */
    uint32_t pointer_updates; /* pointer moves shown without a frame (old + new rectangles only) */
} fx_display_info;

/* Fill info with the display's backend, mode and counters (above). */
void fx_display_get_info(const fx_display *d, fx_display_info *info);

/* A software pointer drawn over the picture (fx_app drives it from the mouse;
 * see fixel/app.h). It lives only in scanout memory: the program's surface
 * never contains it, so reading pixels back gives the program's own drawing.
 * Shadow presentation draws it after the damaged-row copy; direct
 * presentation saves the pixels under it and puts them back before handing
 * the buffer to the program. A move between frames repaints only the old and
 * new sprite rectangles of the buffer on screen (plus DIRTYFB for them).
 * (x, y) is the hotspot in logical pixels; hidden by default. With one
 * direct buffer the pointer is off screen from fx_display_surface until the
 * frame is presented. */
void fx_display_set_pointer(fx_display *d, int visible, int32_t x, int32_t y);
/* Replace the sprite (copied; NULL: the built-in arrow). Returns 0 or
 * -FX_EINVAL (see fx_sprite_check). */
int fx_display_set_pointer_sprite(fx_display *d, const fx_sprite *s);
/* What the scanout buffer on screen holds now (physical size, the pointer
 * included): for tests and screenshots of the memory backend. */
fx_surface fx_display_screen(const fx_display *d);
const char *fx_backend_name(fx_backend b);
/* Screen power for kiosks (a dark screen at night, idle blanking). DRM: the
 * connector's "DPMS" property, or the CRTC switched off when the connector
 * has none; fbdev: FBIOBLANK; memory: only remembered. While off, presents
 * still draw into the buffers but are not shown; on shows the newest frame.
 * No flip completes while off (nor while the program's VT is away), so each
 * such present counts as a pending flip for one refresh period (the mode's,
 * else 60 Hz), ended by a timer on fx_display_fd: a program that draws
 * whenever no flip is pending is paced as by vblank instead of spinning.
 * fx_display_close (and so fx_app_close) turns the screen back on. Returns 0
 * or -errno (the state is unchanged then). A panel's backlight is separate:
 * fixel/backlight.h. */
int fx_display_set_power(fx_display *d, int on);
/* 1 when on (the default), 0 after fx_display_set_power(d, 0). */
int fx_display_power(const fx_display *d);
/* How the backend switches power: "dpms", "crtc", "fbblank", "none". */
const char *fx_display_power_method(const fx_display *d);

/* Log through the display's log function and level (fx_app uses it). */
void fx_display_log(const fx_display *d, fx_log_priority p, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
