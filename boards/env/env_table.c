/* SPDX-License-Identifier: MIT */
/* Every FIXEL_* variable any part of fixel reads, with its type and range:
 * the one table the parsers (env.c, the GLUT layer, fixel-kiosk), the
 * listing of fixel-info --env, README.md's table and the corner tests
 * (tests/boards/test_env.c, tests/tools/env-table.sh) all work from, so a
 * variable cannot be read without a declared range (issue #26). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "fixel/env.h"
#include "fixel/error.h"

#define W(...) (const char *const[]){__VA_ARGS__, NULL}
#define V(...) (const int[]){__VA_ARGS__}

/* Word lists name the canonical word first; synonyms follow with the same
 * value and are accepted but not listed in messages. */
static const fx_env_var table[] = {
    {"FIXEL_BACKEND", FX_ENV_WORD, W("drm", "fbdev", "memory", "auto", "kms", "fb", "headless"),
     V(FX_BACKEND_DRM, FX_BACKEND_FBDEV, FX_BACKEND_MEMORY, FX_BACKEND_AUTO, FX_BACKEND_DRM, FX_BACKEND_FBDEV,
       FX_BACKEND_MEMORY),
     4, 0, 0, "library", "display backend (default: the first that works of drm, fbdev, memory)"},
    {"FIXEL_DRM_DEVICE", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "library",
     "DRM card: a path, card name (card1), driver (vc4) or by-path name (platform-gpu)"},
    {"FIXEL_FB_DEVICE", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "library", "fbdev device path"},
    {"FIXEL_CONNECTOR", FX_ENV_TEXT, NULL, NULL, 0, 0, 0, "library",
     "DRM output by name (HDMI-A-1, or CARD:CONNECTOR), searched on every card"},
    {"FIXEL_MODE", FX_ENV_TEXT, NULL, NULL, 0, 0, 0, "library", "display mode WxH[@Hz]"},
    {"FIXEL_DRM_FORMAT", FX_ENV_WORD, W("XRGB8888", "RGB565", "auto"),
     V(FX_FMT_XRGB8888, FX_FMT_RGB565, FX_FMT_COUNT), 3, 0, 0, "library", "scanout format"},
    {"FIXEL_PRESENT", FX_ENV_WORD, W("direct", "shadow"), V(FX_PRESENT_DIRECT, FX_PRESENT_SHADOW), 2, 0, 0,
     "library", "draw into scanout memory or into a back buffer"},
    {"FIXEL_ROTATION", FX_ENV_WORD, W("0", "90", "180", "270"), V(0, 90, 180, 270), 4, 0, 0, "library",
     "picture rotation in degrees, clockwise (default: the panel's orientation)"},
    {"FIXEL_SW_ROTATION", FX_ENV_WORD, W("0", "1"), V(0, 1), 2, 0, 0, "library",
     "1: rotate in software even when the display can rotate"},
    {"FIXEL_VT_SWITCH", FX_ENV_WORD, W("allow", "deny"), V(FX_VT_SWITCH_ALLOW, FX_VT_SWITCH_DENY), 2, 0, 0,
     "library", "Ctrl-Alt-Fn while running"},
    {"FIXEL_LOG", FX_ENV_WORD, W("debug", "info", "error", "none"), V(FX_LOG_DEBUG, FX_LOG_INFO, FX_LOG_ERROR, -1), 4,
     0, 0, "library", "log level (stderr, 'fixel: ' prefix)"},
    {"FIXEL_POINTER", FX_ENV_WORD, W("on", "off", "auto", "1", "0"),
     V(FX_POINTER_ON, FX_POINTER_OFF, FX_POINTER_AUTO, FX_POINTER_ON, FX_POINTER_OFF), 3, 0, 0, "library",
     "software mouse pointer"},
    {"FIXEL_POINTERCAL", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "library", "tslib pointercal file (touch calibration)"},
    {"FIXEL_TOUCH", FX_ENV_TEXT, NULL, NULL, 0, 0, 0, "library", "touch axes: swap,invertx,inverty"},
    {"FIXEL_INPUT_BIND", FX_ENV_TEXT, NULL, NULL, 0, 0, 0, "library",
     "input devices bound to displays: DEVICE=DISPLAY;..."},
    {"FIXEL_BUTTONS", FX_ENV_TEXT, NULL, NULL, 0, 0, 0, "library", "GPIO button map chip:line=key[/low][@ms],..."},
    {"FIXEL_REPLAY", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "library", "input from a replay file instead of /dev/input"},
    {"FIXEL_FRAMES", FX_ENV_INT, NULL, NULL, 0, 1, 1000000000L, "library", "stop after N frames"},
    {"FIXEL_OUT", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "library", "write every frame to this file (frame-%03d.png)"},
    {"FIXEL_WAIT_DISPLAY", FX_ENV_WORD, W("1", "0"), V(1, 0), 2, 0, 0, "fixel-kiosk",
     "0: do not wait for a display to be connected"},
    {"FIXEL_GLUT_FRAMES", FX_ENV_INT, NULL, NULL, 0, 0, 1000000000L, "GLUT layer",
     "exit 0 when the N-th frame ends (0: run on)"},
    {"FIXEL_GLUT_OUT", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "GLUT layer", "write that frame (PNG, or PPM for .ppm)"},
    {"FIXEL_GLUT_REPLAY", FX_ENV_PATH, NULL, NULL, 0, 0, 0, "GLUT layer", "headless input from a replay file"},
    {"FIXEL_GLUT_FULLSCREEN", FX_ENV_WORD, W("0", "1"), V(0, 1), 2, 0, 0, "GLUT layer",
     "1: the window is the whole screen"},
    {"FIXEL_GLUT_BENCH", FX_ENV_WORD, W("0", "1"), V(0, 1), 2, 0, 0, "GLUT layer",
     "1: print frames per second at exit"},
};

const fx_env_var *fx_env_table(int *count)
{
    if (count)
        *count = (int)(sizeof table / sizeof table[0]);
    return table;
}

const fx_env_var *fx_env_lookup(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (!strcmp(table[i].name, name))
            return &table[i];
    return NULL;
}

int fx_env_expect(const fx_env_var *v, char *buf, size_t n)
{
    if (!v || !buf || n == 0)
        return -FX_EINVAL;
    buf[0] = 0;
    if (v->kind == FX_ENV_INT)
        return snprintf(buf, n, "a whole number from %ld to %ld", v->min, v->max) < (int)n ? 0 : -FX_ERANGE;
    if (v->kind != FX_ENV_WORD)
        return snprintf(buf, n, "%s", v->kind == FX_ENV_PATH ? "a path" : "text") < (int)n ? 0 : -FX_ERANGE;
    size_t len = 0;
    for (int i = 0; i < v->listed; i++) {
        const char *sep = i == 0 ? "" : i == v->listed - 1 ? " or " : ", ";
        int k = snprintf(buf + len, n - len, "%s%s", sep, v->words[i]);
        if (k < 0 || (size_t)k >= n - len)
            return -FX_ERANGE;
        len += (size_t)k;
    }
    return 0;
}

int fx_env_parse(const fx_env_var *v, const char *text, long *value)
{
    if (!v || !text || !value)
        return -FX_EINVAL;
    if (v->kind == FX_ENV_WORD) {
        /* Words are case-blind (RGB565, Memory); digits compare exactly, so
         * "090" and "90 " are not 90. */
        for (int i = 0; v->words[i]; i++)
            if (!strcasecmp(text, v->words[i])) {
                *value = v->values[i];
                return 0;
            }
        return -FX_EINVAL;
    }
    if (v->kind != FX_ENV_INT)
        return -FX_EINVAL;
    /* strtol alone takes " 5", "+5" and saturates 2^63 silently. */
    if (!(text[0] >= '0' && text[0] <= '9') && !(text[0] == '-' && text[1] >= '0' && text[1] <= '9'))
        return -FX_EINVAL;
    char *end;
    errno = 0;
    long n = strtol(text, &end, 10);
    if (*end)
        return -FX_EINVAL;
    if (errno == ERANGE || n < v->min || n > v->max)
        return -FX_ERANGE;
    *value = n;
    return 0;
}
