/* SPDX-License-Identifier: MIT */
/* The one place the boards side reads the environment: the FIXEL_*
 * variables of README.md, turned into option fields for programs to pass
 * to fx_display_open / fx_app_open (fixel/env.h). Each fills a field only
 * while it holds the unset value fx_*_options_init gave it. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <stdio.h>
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

/* getenv lives here, the one file of the library that reads the
 * environment (tests/check-layers.sh); the table and its parse are in
 * env_table.c. */
/* At most 40 bytes of a value and only printable ones: a message must stay
 * one line whatever the environment holds. buf has 48 bytes. */
static const char *quote(const char *e, char *buf)
{
    size_t k = 0;
    for (const char *p = e; *p && k < 40; p++)
        buf[k++] = (*p >= 0x20 && *p < 0x7f) ? *p : '?';
    if (strlen(e) > 40) {
        memcpy(buf + k, "...", 3);
        k += 3;
    }
    buf[k] = 0;
    return buf;
}

int fx_env_get(const char *name, long *value, char *msg, size_t n)
{
    const fx_env_var *v = fx_env_lookup(name);
    if (msg && n)
        msg[0] = 0;
    if (!v || !value)
        return -FX_EINVAL;
    const char *e = getenv(name);
    if (!e || !*e)
        return 1;
    int r = fx_env_parse(v, e, value);
    if (r < 0 && msg && n) {
        char want[160];
        fx_env_expect(v, want, sizeof want);
        char shown[48];
        snprintf(msg, n, "%s=%s ignored (%s)", name, quote(e, shown), want);
    }
    return r;
}

/* A WORD or INT variable through the table: 1 unset, 0 set (*value),
 * -1 bad (logged when l is given, with the table's range). */
static int word(const char *name, long *value, const fx_logger *l)
{
    char msg[256];
    int r = fx_env_get(name, value, msg, sizeof msg);
    if (r < 0 && l)
        fx_log(l, FX_LOG_ERROR, "%s", msg);
    return r < 0 ? -1 : r;
}

int fx_display_options_from_env(fx_display_options *o)
{
    long v;
    char bad_log[256] = "";
    /* First: it decides which of the messages below are shown. */
    if (o->log_priority == 0) {
        int r = fx_env_get("FIXEL_LOG", &v, bad_log, sizeof bad_log);
        if (r == 0)
            o->log_priority = (int)v;
    }
    fx_logger l = logger_of(o);
    if (bad_log[0])
        fx_log(&l, FX_LOG_ERROR, "%s", bad_log); /* said now the logger exists */

    if (o->present == FX_PRESENT_AUTO && word("FIXEL_PRESENT", &v, &l) == 0)
        o->present = (fx_present_mode)v;
    /* whole words only: atoi took "xyz" as 0 and "2147483648" as a
     * negative angle (issue #26) */
    if (o->rotation < 0 && word("FIXEL_ROTATION", &v, &l) == 0)
        o->rotation = (int)v;
    if (!o->drm_device)
        o->drm_device = getenv("FIXEL_DRM_DEVICE");
    if (!o->fb_device)
        o->fb_device = getenv("FIXEL_FB_DEVICE");
    if (!o->connector)
        o->connector = getenv("FIXEL_CONNECTOR");
    if (!o->mode)
        o->mode = getenv("FIXEL_MODE");
    if (o->format == FX_FMT_COUNT && o->drm_format == FX_FMT_COUNT && word("FIXEL_DRM_FORMAT", &v, &l) == 0)
        o->drm_format = (fx_format)v; /* auto is FX_FMT_COUNT: unchanged */
    if (!o->sw_rotation && word("FIXEL_SW_ROTATION", &v, &l) == 0)
        o->sw_rotation = (int)v;
    if (o->vt_switch == FX_VT_SWITCH_ALLOW && word("FIXEL_VT_SWITCH", &v, &l) == 0)
        o->vt_switch = (fx_vt_switch)v;
    /* Last: the one value that makes opening impossible. */
    if (o->backend == FX_BACKEND_AUTO) {
        int r = word("FIXEL_BACKEND", &v, NULL);
        if (r < 0) {
            char want[128];
            fx_env_expect(fx_env_lookup("FIXEL_BACKEND"), want, sizeof want);
            char shown[48];
            fx_log(&l, FX_LOG_ERROR, "FIXEL_BACKEND=%s: use %s", quote(getenv("FIXEL_BACKEND"), shown), want);
            return -FX_EINVAL;
        }
        if (r == 0 && v != FX_BACKEND_AUTO) {
            o->backend = (fx_backend)v;
            o->backend_from_env = 1;
        }
    }
    return 0;
}

int fx_app_options_from_env(fx_app_options *o)
{
    int r = fx_display_options_from_env(&o->display);
    fx_logger l = logger_of(&o->display);
    long v;
    if (o->pointer == FX_POINTER_AUTO && word("FIXEL_POINTER", &v, &l) == 0)
        o->pointer = (fx_pointer_mode)v;
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
    /* a scripted run must not run forever instead: an error, not ignored */
    if (o->frames == 0) {
        int k = word("FIXEL_FRAMES", &v, &l);
        if (k == 0)
            o->frames = (int)v;
        else if (k < 0 && r == 0)
            r = -FX_EINVAL;
    }
    return r;
}

int fx_app_bind_inputs_from_env(fx_app *a)
{
    const char *e = var("FIXEL_INPUT_BIND");
    return e ? fx_app_bind_inputs(a, e) : 0;
}
