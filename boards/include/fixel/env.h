/* SPDX-License-Identifier: MIT */
/* fixel — the environment, read once, by the program.
 *
 * The library never calls getenv. A program that honours the FIXEL_*
 * variables (README.md has the table; every fixel tool does) calls one of
 * these after fx_*_options_init:
 *
 *     fx_app_options o;
 *     fx_app_options_init(&o);
 *     o.display.rotation = 90;                  // the program's choice wins
 *     if (fx_app_options_from_env(&o) < 0) return 1;   // reason logged
 *     fx_app_open(&app, &o);
 *
 * Each function fills only the fields marked [env] in fixel/display.h and
 * fixel/app.h that still hold their unset value, so the order is: a value
 * the program sets > the environment > the board profile's default (applied
 * at open) > the built-in default; calling it before or after setting
 * fields gives the same result. Strings point into the environment: do not
 * change those variables before the open.
 *
 * A value that cannot be parsed is logged (through o's log function and
 * level, FIXEL_LOG applied) and ignored, except FIXEL_BACKEND: an unknown
 * backend returns -FX_EINVAL, as opening with it used to, and FIXEL_FRAMES
 * (below). Otherwise 0.
 */
#ifndef FIXEL_ENV_H
#define FIXEL_ENV_H

#include "fixel/app.h"
#include "fixel/display.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* FIXEL_BACKEND, FIXEL_PRESENT, FIXEL_DRM_DEVICE, FIXEL_FB_DEVICE,
 * FIXEL_CONNECTOR, FIXEL_MODE, FIXEL_DRM_FORMAT, FIXEL_ROTATION,
 * FIXEL_SW_ROTATION, FIXEL_VT_SWITCH, FIXEL_LOG. */
int fx_display_options_from_env(fx_display_options *o);
/* The display's (o->display), then FIXEL_POINTER, FIXEL_POINTERCAL,
 * FIXEL_TOUCH, FIXEL_BUTTONS, FIXEL_REPLAY, FIXEL_FRAMES, FIXEL_OUT.
 * FIXEL_FRAMES that is not a positive integer returns -FX_EINVAL (a
 * scripted run must not run forever instead). */
int fx_app_options_from_env(fx_app_options *o);
/* After fx_app_open: FIXEL_INPUT_BIND ("DEVICE=DISPLAY;...", see
 * fx_app_bind_inputs) as input bindings of the open app. Returns 0 (also
 * when unset) or the error of fx_app_bind_inputs (logged). */
int fx_app_bind_inputs_from_env(fx_app *a);

/* The table of every FIXEL_* variable fixel reads (the library's, the
 * GLUT layer's and fixel-kiosk's), with its type and range; `fixel-info
 * --env` prints it and README.md's table follows it. */
typedef enum {
    FX_ENV_WORD, /* one of words[] (case-blind); values[] gives its value */
    FX_ENV_INT,  /* a decimal integer in [min, max] */
    FX_ENV_TEXT, /* free text, parsed where it is used (FIXEL_MODE, ...) */
    FX_ENV_PATH  /* a file or device path, checked when it is opened */
} fx_env_kind;

typedef struct fx_env_var {
    const char *name;
    fx_env_kind kind;
    const char *const *words; /* WORD: NULL-terminated; synonyms after the first `listed` */
    const int *values;
    int listed;
    long min, max; /* INT */
    const char *who;     /* "library", "GLUT layer", "fixel-kiosk" */
    const char *meaning; /* one line for listings */
} fx_env_var;

/* The table and its length (count may be NULL). Never NULL. */
const fx_env_var *fx_env_table(int *count);
/* The entry named name, or NULL. */
const fx_env_var *fx_env_lookup(const char *name);
/* text parsed as v declares: 0 with *value set; -FX_EINVAL when it is not
 * a word of v or not a number, -FX_ERANGE when outside [min, max]. TEXT
 * and PATH variables have no value: -FX_EINVAL. */
int fx_env_parse(const fx_env_var *v, const char *text, long *value);
/* What v accepts, for messages: "0, 90, 180 or 270", "a whole number
 * from 1 to 1000000000". 0, or -FX_ERANGE when buf is too small. */
int fx_env_expect(const fx_env_var *v, char *buf, size_t n);
/* The variable name as the table declares it, read now: 1 when unset or
 * empty, 0 with *value set, or a negative error with msg (when given) set
 * to a one-line "NAME=VALUE ignored (what it accepts)"; -FX_EINVAL also
 * for a name not in the table. */
int fx_env_get(const char *name, long *value, char *msg, size_t n);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
