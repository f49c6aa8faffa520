/* SPDX-License-Identifier: MIT */
/* libFuzzer target: fixel-kiosk's config and data-line parsers, every
 * widget type and data form (name=value, name,value, heat maps whole and by
 * row, image paths, CSV headers and rows). The input is split at the first
 * NUL: config before it, data lines after. Seeds: tests/fuzz/corpus/kiosk. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "../../tools/fixel-kiosk/kiosk.h"

/* fuzz_gkiosk.c includes this file with its own clock and entry name. */
#ifndef KIOSK_TIME
#define KIOSK_TIME(line) (line)
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static kiosk_config k;
    char err[128];
    const char *p = (const char *)data;
    const char *nul = memchr(p, 0, size);
    size_t clen = nul ? (size_t)(nul - p) : size;
    if (kiosk_config_parse(&k, p, clen, err, sizeof err) < 0) return 0;
    /* pages (kiosk_pages.h): every widget on a page, every button's page real */
    if (k.pg.npages < 1 || k.pg.npages > KIOSK_MAX_PAGES || k.pg.nbuttons > KIOSK_MAX_BUTTONS) __builtin_trap();
    for (int i = 0; i < k.nwidgets; i++) {
        const kiosk_widget *w = &k.widgets[i];
        const kiosk_page *pg = &k.pg.pages[w->page < 0 || w->page >= k.pg.npages ? (__builtin_trap(), 0) : w->page];
        if (w->col + w->w > pg->cols || w->row + w->h > pg->rows) __builtin_trap();
        if ((w->type == KIOSK_BUTTON) != (w->button >= 0) || w->button >= k.pg.nbuttons) __builtin_trap();
    }
    for (int i = 0; i < k.pg.nbuttons; i++) {
        const kiosk_button *b = &k.pg.buttons[i];
        if (b->page >= k.pg.npages || b->page < KIOSK_PAGE_PREV || (b->topic[0] && !k.mqtt.enabled)) __builtin_trap();
    }
    if (!nul) return 0;
    const char *q = nul + 1, *end = p + size;
    int64_t line = 0;
    while (q < end) {
        const char *eol = memchr(q, '\n', (size_t)(end - q));
        if (!eol) eol = end;
        int s = -1;
        if (kiosk_data_line(&k, q, (size_t)(eol - q), KIOSK_TIME(line), &s) == KIOSK_LINE_OK &&
            (s < 0 || s >= k.nsources))
            __builtin_trap();
        if (k.nsources < 32 && (k.changed >> k.nsources)) __builtin_trap(); /* only real sources change */
        if (k.ncols < 0 || k.ncols > KIOSK_CSV_MAX) __builtin_trap();
        for (int i = 0; i < k.ncols; i++)
            if (!memchr(k.colname[i], 0, KIOSK_NAME_MAX)) __builtin_trap();
        for (int i = 0; i < k.nsources; i++) {
            const kiosk_source *so = &k.sources[i];
            if (so->count > KIOSK_HIST_MAX) __builtin_trap();
            if (!memchr(so->path, 0, KIOSK_PATH_MAX) || !memchr(so->text, 0, KIOSK_TEXT_MAX)) __builtin_trap();
            if (so->kind == KIOSK_KIND_HEAT) {
                if (so->gw < 1 || so->gh < 1 || so->gw * so->gh > KIOSK_HEAT_MAX) __builtin_trap();
                for (int c = so->gw * so->gh; c < KIOSK_HEAT_MAX; c++)
                    if (so->cells[c] != KIOSK_CELL_NONE) __builtin_trap(); /* no write past the map */
            }
        }
        line++;
        q = eol + 1;
    }
    return 0;
}
