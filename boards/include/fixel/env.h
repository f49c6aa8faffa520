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

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
