/* SPDX-License-Identifier: MIT */
/* fixel-kiosk pages: gestures, page names and the carousel (kiosk_pages.h).
 * Pure: no I/O, no clock of its own. */
#include "kiosk.h"

#include <string.h>

int kiosk_gesture(const kiosk_pages_cfg *c, int w, int x0, int y0, int x1, int y1)
{
    if (c->npages < 2) return KIOSK_GESTURE_NONE;
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    int64_t ax = dx < 0 ? -dx : dx, ay = dy < 0 ? -dy : dy;
    /* mostly sideways, far enough: a finger dragged left brings the next page */
    if (c->swipe_px && ax >= c->swipe_px && ax > 2 * ay) return dx < 0 ? KIOSK_GESTURE_NEXT : KIOSK_GESTURE_PREV;
    /* a tap (it moved less than a swipe, and less than 16 pixels): an edge zone turns the page */
    int64_t slop = c->swipe_px && c->swipe_px < 16 ? c->swipe_px : 16;
    if (c->edge_pct && w > 0 && ax < slop && ay < slop) {
        int64_t zone = (int64_t)w * c->edge_pct / 100;
        if (x0 < zone) return KIOSK_GESTURE_PREV;
        if (x0 >= w - zone) return KIOSK_GESTURE_NEXT;
    }
    return KIOSK_GESTURE_NONE;
}

int kiosk_page_lookup(const kiosk_pages_cfg *c, int cur, const char *s, unsigned n)
{
    if (c->npages < 1) return -1;
    if (n == 4 && !memcmp(s, "next", 4)) return (cur + 1) % c->npages;
    if (n == 4 && !memcmp(s, "prev", 4)) return (cur + c->npages - 1) % c->npages;
    int64_t v = 0;
    unsigned i = 0;
    for (; i < n && i < 6 && s[i] >= '0' && s[i] <= '9'; i++) v = v * 10 + (s[i] - '0');
    if (n && i == n) return v < c->npages ? (int)v : -1;
    for (int p = 0; p < c->npages; p++)
        if (strlen(c->pages[p].name) == n && !memcmp(c->pages[p].name, s, n)) return p;
    return -1;
}

int kiosk_carousel(const kiosk_pages_cfg *c, int cur, int64_t *since_ms, int64_t now_ms)
{
    if (!c->dwell_s || c->npages < 2 || cur < 0 || cur >= c->npages) return cur;
    /* bounded: a clock that jumped ahead by years turns at most one round */
    for (int i = 0; i < c->npages; i++) {
        int d = c->pages[cur].dwell_s ? c->pages[cur].dwell_s : c->dwell_s;
        int64_t due = *since_ms + (int64_t)d * 1000;
        if (now_ms < due) return cur;
        *since_ms = due;
        cur = (cur + 1) % c->npages;
    }
    *since_ms = now_ms;
    return cur;
}
