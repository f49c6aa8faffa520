/* SPDX-License-Identifier: MIT */
/* Naming DRM cards and choosing an output on described cards (fixel/cards.h).
 * Pure: no OS headers, no allocation; fx_drm_cards (boards/linux/drm/) fills
 * the descriptions. */
#include <stddef.h>
#include <string.h>

#include "fixel/cards.h"

static int is_digits(const char *s)
{
    if (!*s)
        return 0;
    for (; *s; s++)
        if (*s < '0' || *s > '9')
            return 0;
    return 1;
}

/* '-' and '_' alike: module names use '_', several DRM drivers '-'. */
static int same_driver(const char *a, const char *b)
{
    for (;; a++, b++) {
        char x = *a == '-' ? '_' : *a, y = *b == '-' ? '_' : *b;
        if (x != y)
            return 0;
        if (!x)
            return 1;
    }
}

/* spec[0..len) equals the whole of s, or a tail of s after a '-' that
 * starts a component ("pci-...", "platform-...", "amba-..."). */
static int path_name_is(const char *s, const char *spec, size_t len)
{
    size_t n = strlen(s);
    if (len == 0 || len > n)
        return 0;
    if (strncmp(spec, "pci-", 4) && strncmp(spec, "platform-", 9) && strncmp(spec, "amba-", 5))
        return 0;
    if (strncmp(s + n - len, spec, len))
        return 0;
    return n == len || s[n - len - 1] == '-';
}

int fx_card_matches(const fx_card_desc *c, const char *spec)
{
    if (!spec || !*spec)
        return 0;
    if (!strncmp(spec, "/dev/dri/", 9))
        spec += 9;
    if (!strncmp(spec, "card", 4) && is_digits(spec + 4)) {
        int v = 0;
        for (const char *p = spec + 4; *p && v < 100000; p++)
            v = v * 10 + (*p - '0');
        return v == c->minor;
    }
    if (c->driver[0] && same_driver(c->driver, spec))
        return 1;
    if (c->path_name[0]) {
        size_t len = strlen(spec);
        if (len > 5 && !strcmp(spec + len - 5, "-card"))
            len -= 5; /* the udev link's own name */
        return path_name_is(c->path_name, spec, len);
    }
    return 0;
}

/* Cards allowed by both specs (NULL: no condition). */
static int allowed(const fx_card_desc *c, const char *device, const char *card_spec)
{
    if (c->error)
        return 0;
    if (device && *device && !fx_card_matches(c, device))
        return 0;
    return !card_spec || fx_card_matches(c, card_spec);
}

fx_card_pick fx_card_pick_output(const fx_card_desc *cards, int n, const char *device,
                                 const char *connector, int *card, int *conn)
{
    char card_spec[192];
    const char *name = connector && *connector ? connector : NULL;
    const char *cs = NULL;
    if (name) {
        const char *colon = strrchr(name, ':');
        if (colon) {
            size_t len = (size_t)(colon - name);
            if (len >= sizeof card_spec)
                return FX_PICK_NO_CARD;
            memcpy(card_spec, name, len);
            card_spec[len] = 0;
            cs = card_spec;
            name = colon + 1;
            if (!*name)
                name = NULL; /* "vc4:": any connected output of that card */
        }
    }
    int any = 0;
    for (int i = 0; i < n; i++)
        any |= allowed(&cards[i], device, cs);
    if (!any && ((device && *device) || cs))
        return FX_PICK_NO_CARD;
    /* Pass 0: connected with modes. Pass 1 (named only): any status with
     * modes, as a connector forced on reports "unknown". */
    for (int pass = 0; pass < (name ? 2 : 1); pass++)
        for (int i = 0; i < n; i++) {
            if (!allowed(&cards[i], device, cs))
                continue;
            for (int k = 0; k < cards[i].nconn && k < FX_CARD_CONNECTORS_MAX; k++) {
                const fx_connector_desc *c = &cards[i].conn[k];
                if (name && strcmp(c->name, name))
                    continue;
                if (c->modes > 0 && (pass == 1 || c->connected == 1)) {
                    *card = i;
                    *conn = k;
                    return FX_PICK_OK;
                }
            }
        }
    if (!name)
        return FX_PICK_NONE_CONNECTED;
    for (int i = 0; i < n; i++)
        for (int k = 0; allowed(&cards[i], device, cs) && k < cards[i].nconn && k < FX_CARD_CONNECTORS_MAX; k++)
            if (!strcmp(cards[i].conn[k].name, name)) {
                *card = i;
                *conn = k;
                return FX_PICK_DISCONNECTED;
            }
    return FX_PICK_NO_CONNECTOR;
}
