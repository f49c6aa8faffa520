/* SPDX-License-Identifier: MIT */
/* fixel — GPIO push buttons: the description fx_app_options.buttons takes,
 * and the FIXEL_BUTTONS / board profile map syntax. Included by
 * fixel/app.h; usable alone (the input layer sees only this). */
#ifndef FIXEL_BUTTONS_H
#define FIXEL_BUTTONS_H

#ifdef __cplusplus
extern "C" {
#endif

/* A GPIO push button. */
typedef struct fx_gpio_button {
    const char *chip;     /* "gpiochip0", "0" or a path; NULL: search every chip for name */
    int offset;           /* line offset, or -1 to look the line up by name */
    const char *name;     /* line name (used when offset < 0) */
    int active_low;       /* 1: pressed pulls the line low */
    unsigned debounce_ms; /* 0: 20 ms */
    int key;              /* character (keyboard callback) or, with special = 1, FX_KEY_* */
    int special;
} fx_gpio_button;

/* Parse "CHIP:LINE=KEY[/low][@MS],..." (LINE: offset or line name; an empty
 * CHIP searches every chip for the line name; /low: active low with the
 * pull-up enabled; @MS: debounce time; KEY: a
 * single character, or up, down, left, right, pageup, pagedown, home, end,
 * insert, f1..f12, enter, esc, space, tab, menu). Names point into buf, which is
 * modified. Returns the number of buttons, or -FX_EINVAL. */
int fx_gpio_parse_buttons(char *buf, fx_gpio_button *out, int max);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
