/* SPDX-License-Identifier: MIT */
/* fixel — the GPIO button map syntax (pure: no OS calls, so the board-less
 * test builds have it too). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdlib.h>
#include <string.h>

#include "fixel/buttons.h"
#include "fixel/event.h"
#include "fixel/error.h"

static const struct {
    const char *name;
    int key, special;
} key_names[] = {
    {"up", FX_KEY_UP, 1},         {"down", FX_KEY_DOWN, 1},   {"left", FX_KEY_LEFT, 1},
    {"right", FX_KEY_RIGHT, 1},   {"pageup", FX_KEY_PAGE_UP, 1}, {"pagedown", FX_KEY_PAGE_DOWN, 1},
    {"home", FX_KEY_HOME, 1},     {"end", FX_KEY_END, 1},     {"insert", FX_KEY_INSERT, 1},
    {"enter", 13, 0},             {"esc", 27, 0},             {"space", ' ', 0},
    {"tab", 9, 0},                {"menu", FX_KEY_MENU, 1},
};

int fx_gpio_parse_buttons(char *buf, fx_gpio_button *out, int max)
{
    int n = 0;
    char *save = NULL;
    for (char *item = strtok_r(buf, ",", &save); item; item = strtok_r(NULL, ",", &save)) {
        if (n == max)
            return -FX_E2BIG;
        fx_gpio_button *b = &out[n];
        memset(b, 0, sizeof *b);
        char *eq = strchr(item, '='), *colon = strchr(item, ':');
        if (!eq || !colon || colon > eq)
            return -FX_EINVAL;
        *colon = *eq = 0;
        b->chip = *item ? item : NULL; /* ":NAME=KEY" searches every chip */
        char *line = colon + 1, *key = eq + 1, *end;
        long off = strtol(line, &end, 10);
        if (*line && !*end) {
            b->offset = (int)off;
        } else {
            b->offset = -1;
            b->name = line;
        }
        char *at = strchr(key, '@');
        if (at) {
            *at = 0;
            b->debounce_ms = (unsigned)strtoul(at + 1, &end, 10);
            if (*end)
                return -FX_EINVAL;
        }
        char *low = strstr(key, "/low");
        if (low) {
            *low = 0;
            b->active_low = 1;
        }
        int found = 0;
        for (size_t k = 0; k < sizeof key_names / sizeof key_names[0]; k++)
            if (!strcmp(key, key_names[k].name)) {
                b->key = key_names[k].key;
                b->special = key_names[k].special;
                found = 1;
            }
        if (!found && (key[0] == 'f' || key[0] == 'F') && key[1] >= '1' && key[1] <= '9') {
            long f = strtol(key + 1, &end, 10);
            if (*end || f < 1 || f > 12)
                return -FX_EINVAL;
            b->key = (int)f;
            b->special = 1;
            found = 1;
        }
        if (!found && key[0] && !key[1]) {
            b->key = (unsigned char)key[0];
            found = 1;
        }
        if (!found)
            return -FX_EINVAL;
        n++;
    }
    return n;
}
