/* SPDX-License-Identifier: MIT */
/* fixel-kiosk pages (docs/kiosk.md, "Pages and touch"): several pages of
 * widgets, a carousel that turns them, swipes and edge taps that turn them
 * by hand, and button widgets whose tap publishes an MQTT message or goes
 * to a page. The config parser (kiosk_parse.c) fills kiosk_pages_cfg; the
 * decisions below are pure (positions and times are passed in) so the unit
 * tests drive them without a display; main.c feeds them the input events
 * and its clock. Included by kiosk.h (after KIOSK_NAME_MAX, KIOSK_TOPIC_MAX). */
#ifndef FIXEL_KIOSK_PAGES_H
#define FIXEL_KIOSK_PAGES_H

#include <stdint.h>

#define KIOSK_MAX_PAGES 16
#define KIOSK_MAX_BUTTONS 16
#define KIOSK_PAYLOAD_MAX 128 /* a button's payload, including the NUL */
#define KIOSK_PRESS_MS 250    /* a button stays drawn pressed this long after its release */
#define KIOSK_PAGE_NEXT (-2)  /* a button's page=next */
#define KIOSK_PAGE_PREV (-3)  /* a button's page=prev */
#define KIOSK_PAGE_NONE (-1)

typedef struct kiosk_page {
    char name[KIOSK_NAME_MAX];
    int cols, rows;     /* its grid; 0: the config's "grid" */
    int dwell_s;        /* seconds the carousel shows it; 0: the carousel's dwell= */
    int line, col;      /* where it was declared (an empty page is reported there) */
} kiosk_page;

typedef struct kiosk_button {
    char topic[KIOSK_TOPIC_MAX]; /* "" : no message */
    char payload[KIOSK_PAYLOAD_MAX];
    int qos, retain;
    int page;           /* a page index, KIOSK_PAGE_NEXT/PREV, or KIOSK_PAGE_NONE */
    char pagename[KIOSK_NAME_MAX]; /* page= as written, resolved after the whole file */
    int line, col;      /* of the button's topic= or page= (errors found after the whole file) */
} kiosk_button;

typedef struct kiosk_pages_cfg {
    int npages;         /* at least 1 after a successful parse */
    kiosk_page pages[KIOSK_MAX_PAGES];
    int dwell_s;        /* "carousel dwell=": 0, no carousel */
    int swipe_px;       /* "touch swipe=": shortest swipe; 0, swipes off */
    int edge_pct;       /* "touch edge=": tap zones at the left and right edges, percent of the width; 0 off */
    int nbuttons;
    kiosk_button buttons[KIOSK_MAX_BUTTONS];
} kiosk_pages_cfg;

/* What a press (down at x0,y0) and its release (at x1,y1) on a screen w
 * pixels wide mean, when the press did not start on a button. */
enum { KIOSK_GESTURE_NONE = 0, KIOSK_GESTURE_NEXT = 1, KIOSK_GESTURE_PREV = -1 };
int kiosk_gesture(const kiosk_pages_cfg *c, int w, int x0, int y0, int x1, int y1);

/* The page a "set/page" payload or a button's page= names, from page cur:
 * a number (0-based index), a page's name, "next" or "prev" (wrapping).
 * -1 when it names none. */
int kiosk_page_lookup(const kiosk_pages_cfg *c, int cur, const char *s, unsigned n);

/* The carousel: the page to show at now_ms when page cur has been shown
 * since since_ms (turning as many pages as the dwell times say, so a kiosk
 * that stalled catches up); *since_ms moves to when the returned page came
 * up. Returns cur when there is no carousel. */
int kiosk_carousel(const kiosk_pages_cfg *c, int cur, int64_t *since_ms, int64_t now_ms);

#endif
