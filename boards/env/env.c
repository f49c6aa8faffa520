/* SPDX-License-Identifier: MIT */
/* The one place the boards side reads the environment: the FIXEL_*
 * variables of README.md, turned into option fields for programs to pass
 * to fx_display_open / fx_app_open (fixel/env.h). Each fills a field only
 * while it holds the unset value fx_*_options_init gave it. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "../posix/posix_int.h"
#include "fixel/env.h"
#include "fixel/error.h"

static const char *var(const char *name)
{
    const char *e = getenv(name);
    return e && *e ? e : NULL;
}

/* Messages go where the display's will: o's log function and level. */
static fx_logger logger_of(const fx_display_options *o)
{
    fx_logger l = {o->log ? o->log : fx_log_stderr, o->log_user,
                   o->log_priority ? o->log_priority : FX_LOG_INFO};
    return l;
}

static int parse_backend(const char *s, fx_backend *b)
{
    if (!strcasecmp(s, "drm") || !strcasecmp(s, "kms"))
        *b = FX_BACKEND_DRM;
    else if (!strcasecmp(s, "fbdev") || !strcasecmp(s, "fb"))
        *b = FX_BACKEND_FBDEV;
    else if (!strcasecmp(s, "memory") || !strcasecmp(s, "headless"))
        *b = FX_BACKEND_MEMORY;
    else if (!strcasecmp(s, "auto"))
        *b = FX_BACKEND_AUTO;
    else
        return -FX_EINVAL;
    return 0;
}

int fx_display_options_from_env(fx_display_options *o)
{
    const char *e, *bad_log = NULL;
    /* First: it decides which of the messages below are shown. */
    if (o->log_priority == 0 && (e = var("FIXEL_LOG"))) {
        if (!strcasecmp(e, "debug"))
            o->log_priority = FX_LOG_DEBUG;
        else if (!strcasecmp(e, "error"))
            o->log_priority = FX_LOG_ERROR;
        else if (!strcasecmp(e, "none"))
            o->log_priority = -1;
        else if (!strcasecmp(e, "info"))
            o->log_priority = FX_LOG_INFO;
        else
            bad_log = e; /* said below, once the logger exists */
    }
    fx_logger l = logger_of(o);
    if (bad_log)
        fx_log(&l, FX_LOG_ERROR, "FIXEL_LOG=%s ignored (debug, info, error or none)", bad_log);

    if (o->present == FX_PRESENT_AUTO && (e = var("FIXEL_PRESENT"))) {
        if (!strcasecmp(e, "direct"))
            o->present = FX_PRESENT_DIRECT;
        else if (!strcasecmp(e, "shadow"))
            o->present = FX_PRESENT_SHADOW;
        else
            fx_log(&l, FX_LOG_ERROR, "FIXEL_PRESENT=%s ignored (direct or shadow)", e);
    }
    if (o->rotation < 0 && (e = var("FIXEL_ROTATION"))) {
        /* whole words only: atoi took "xyz" as 0 and "2147483648" as a
         * negative angle (issue #26) */
        static const char *const angles[] = {"0", "90", "180", "270"};
        int i = 0;
        while (i < 4 && strcmp(e, angles[i]))
            i++;
        if (i < 4)
            o->rotation = 90 * i;
        else
            fx_log(&l, FX_LOG_ERROR, "FIXEL_ROTATION=%s ignored (0, 90, 180 or 270)", e);
    }
    if (!o->drm_device)
        o->drm_device = getenv("FIXEL_DRM_DEVICE");
    if (!o->fb_device)
        o->fb_device = getenv("FIXEL_FB_DEVICE");
    if (!o->connector)
        o->connector = getenv("FIXEL_CONNECTOR");
    if (!o->mode)
        o->mode = getenv("FIXEL_MODE");
    if (o->format == FX_FMT_COUNT && o->drm_format == FX_FMT_COUNT && (e = var("FIXEL_DRM_FORMAT")) &&
        strcasecmp(e, "auto")) {
        if (!strcasecmp(e, "XRGB8888"))
            o->drm_format = FX_FMT_XRGB8888;
        else if (!strcasecmp(e, "RGB565"))
            o->drm_format = FX_FMT_RGB565;
        else
            fx_log(&l, FX_LOG_ERROR, "FIXEL_DRM_FORMAT=%s ignored (XRGB8888 or RGB565)", e);
    }
    if (!o->sw_rotation && (e = var("FIXEL_SW_ROTATION")) && strcmp(e, "0"))
        o->sw_rotation = 1;
    if (o->vt_switch == FX_VT_SWITCH_ALLOW && (e = getenv("FIXEL_VT_SWITCH")) && !strcasecmp(e, "deny"))
        o->vt_switch = FX_VT_SWITCH_DENY;
    /* Last: the one value that makes opening impossible. */
    if (o->backend == FX_BACKEND_AUTO && (e = var("FIXEL_BACKEND"))) {
        fx_backend b;
        if (parse_backend(e, &b) < 0) {
            fx_log(&l, FX_LOG_ERROR, "FIXEL_BACKEND=%s: use drm, fbdev or memory", e);
            return -FX_EINVAL;
        }
        o->backend = b;
        o->backend_from_env = 1;
    }
    return 0;
}

int fx_app_options_from_env(fx_app_options *o)
{
    int r = fx_display_options_from_env(&o->display);
    fx_logger l = logger_of(&o->display);
    const char *e;
    if (o->pointer == FX_POINTER_AUTO && (e = var("FIXEL_POINTER")) && strcasecmp(e, "auto")) {
        if (!strcasecmp(e, "on") || !strcmp(e, "1"))
            o->pointer = FX_POINTER_ON;
        else if (!strcasecmp(e, "off") || !strcmp(e, "0"))
            o->pointer = FX_POINTER_OFF;
        else
            fx_log(&l, FX_LOG_ERROR, "FIXEL_POINTER=%s ignored (on, off or auto)", e);
    }
    if (!o->pointercal)
        o->pointercal = getenv("FIXEL_POINTERCAL");
    if (!o->touch)
        o->touch = getenv("FIXEL_TOUCH");
    if (!o->button_map)
        o->button_map = getenv("FIXEL_BUTTONS");
    if (!o->replay)
        o->replay = var("FIXEL_REPLAY");
    if (!o->frame_out)
        o->frame_out = var("FIXEL_OUT");
    if (o->frames == 0 && (e = var("FIXEL_FRAMES"))) {
        char *end;
        errno = 0;
        long n = strtol(e, &end, 10);
        if (end == e || *end || errno || n < 1 || n > 1000000000L) {
            fx_log(&l, FX_LOG_ERROR, "FIXEL_FRAMES=%s: use a number of frames from 1", e);
            if (r == 0)
                r = -FX_EINVAL;
        } else {
            o->frames = (int)n;
        }
    }
    return r;
}

int fx_app_bind_inputs_from_env(fx_app *a)
{
    const char *e = var("FIXEL_INPUT_BIND");
    return e ? fx_app_bind_inputs(a, e) : 0;
}
