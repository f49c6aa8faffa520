/* SPDX-License-Identifier: MIT */
/* fixel-kiosk pages (tools/fixel-kiosk/kiosk_pages.c and the page, carousel,
 * touch and button directives of kiosk_parse.c): the config errors and their
 * places, gestures on made-up positions, the carousel on made-up times. */
#include "fx_test.h"

#include <stdio.h>
#include <string.h>

#include "../../tools/fixel-kiosk/kiosk_pages.c"

static kiosk_config P;

/* kiosk_config_parse comes from test_kiosk.c (it includes kiosk_parse.c) */
static int pcfg(const char *s, char *err) { return kiosk_config_parse(&P, s, strlen(s), err, 160); }

FX_TEST(kiosk_pages_parse)
{
    char err[160];
    /* no page lines: one page "main", as before pages existed */
    FX_CHECK_EQ(pcfg("grid 2x1\nwidget number a\n", err), 0);
    FX_CHECK_EQ(P.pg.npages, 1);
    FX_CHECK(!strcmp(P.pg.pages[0].name, "main"));
    FX_CHECK_EQ(P.pg.pages[0].cols, 2);
    /* widgets before the first page line are on "main"; grids per page */
    FX_CHECK_EQ(pcfg("grid 2x2\nwidget number a\npage b grid=3x1 dwell=7\nwidget text t col=2\n"
                     "carousel dwell=5\ntouch swipe=60 edge=20\n", err), 0);
    FX_CHECK_EQ(P.pg.npages, 2);
    FX_CHECK_EQ(P.widgets[0].page, 0);
    FX_CHECK_EQ(P.widgets[1].page, 1);
    FX_CHECK_EQ(P.pg.pages[1].cols, 3);
    FX_CHECK_EQ(P.pg.pages[1].rows, 1);
    FX_CHECK_EQ(P.pg.pages[0].cols, 2);
    FX_CHECK_EQ(P.pg.pages[1].dwell_s, 7);
    FX_CHECK_EQ(P.pg.dwell_s, 5);
    FX_CHECK_EQ(P.pg.swipe_px, 60);
    FX_CHECK_EQ(P.pg.edge_pct, 20);
    /* a page's grid is its own: col=2 fits 3x1, not the 2x2 grid */
    FX_CHECK_EQ(pcfg("grid 2x2\npage b\nwidget text t col=2\n", err), -1);
    FX_CHECK(strstr(err, "outside the grid") != NULL);
    /* buttons: a page action needs no broker, resolved after the whole file */
    FX_CHECK_EQ(pcfg("page a\nwidget button Go page=b\npage b\nwidget button Back page=prev label=\"Go back\"\n", err), 0);
    FX_CHECK_EQ(P.pg.nbuttons, 2);
    FX_CHECK_EQ(P.pg.buttons[0].page, 1);
    FX_CHECK_EQ(P.pg.buttons[1].page, KIOSK_PAGE_PREV);
    FX_CHECK(!strcmp(P.widgets[1].label, "Go back"));
    FX_CHECK_EQ(P.widgets[0].button, 0);
    FX_CHECK_EQ(P.widgets[0].source, -1);
    FX_CHECK_EQ(P.nsources, 0);
    FX_CHECK_EQ(pcfg("widget button L topic=home/light/set payload={\"state\":\"ON\"} qos=2 retain=1\n"
                     "mqtt host=127.0.0.1\n", err), 0);
    FX_CHECK(!strcmp(P.pg.buttons[0].topic, "home/light/set"));
    FX_CHECK(!strcmp(P.pg.buttons[0].payload, "{\"state\":\"ON\"}"));
    FX_CHECK_EQ(P.pg.buttons[0].qos, 2);
    FX_CHECK_EQ(P.pg.buttons[0].retain, 1);
    FX_CHECK_EQ(pcfg("widget button L topic=t payload=\"on now\"\nmqtt host=h\n", err), 0);
    FX_CHECK(!strcmp(P.pg.buttons[0].payload, "on now"));
}

/* config text, the error's line and column, a piece of its message */
static void bad(const char *text, int line, int col, const char *what)
{
    char err[160];
    FX_CHECK_MSG(pcfg(text, err) == -1, "accepted: %s", text);
    FX_CHECK_MSG(P.errline == line && P.errcol == col, "%s: at %d:%d, wanted %d:%d (%s)", text, P.errline,
                 P.errcol, line, col, err);
    FX_CHECK_MSG(strstr(err, what) != NULL, "%s: '%s' lacks '%s'", text, err, what);
}

FX_TEST(kiosk_pages_hostile_configs)
{
    bad("widget button L topic=home/x\n", 1, 17, "needs an mqtt directive");
    bad("page a\nwidget button L page=nowhere\n", 2, 17, "no page of that name");
    bad("widget button L\n", 1, 1, "needs topic= (a message to publish) or page=");
    bad("widget button L qos=3 page=next\n", 1, 17, "qos=3: expected 0..2");
    bad("widget button L retain=2 page=next\n", 1, 17, "retain=2: expected 0..1");
    bad("widget button L topic=a/+/b\nmqtt host=h\n", 1, 17, "without wildcards");
    bad("widget button L decimals=1 page=next\n", 1, 17, "unknown widget key");
    bad("widget number a topic=x\n", 1, 17, "unknown widget key");
    bad("page a\npage b\nwidget number x\n", 1, 6, "a page without widgets");
    bad("page a\nwidget number x\npage a\n", 3, 6, "a second page of that name");
    bad("page next\n", 1, 6, "page name");
    bad("page 1st\n", 1, 6, "page name");
    bad("page a/b\n", 1, 6, "page name");
    bad("page\n", 1, 1, "page needs a name");
    bad("page a dwell=86401\nwidget number x\n", 1, 8, "dwell=86401: expected 0..86400");
    bad("page a grid=17x1\nwidget number x\n", 1, 8, "grid=17x1: expected 1..16");
    bad("page a frob=1\n", 1, 8, "unknown page key");
    bad("carousel dwell=-1\n", 1, 10, "dwell=-1: expected 0..86400");
    bad("touch edge=51\n", 1, 7, "edge=51: expected 0..50");
    bad("touch swipe=x\n", 1, 7, "swipe=x: expected 0..8192");
    bad("widget number x\npage main\n", 2, 6, "a second page of that name");
    char many[600] = "";
    for (int i = 0; i < 17; i++) {
        char l[32];
        snprintf(l, sizeof l, "page p%d\nwidget clock\n", i);
        strcat(many, l);
    }
    bad(many, 33, 6, "too many pages (16)");
    char buttons[800] = "";
    for (int i = 0; i < 17; i++) strcat(buttons, "widget button B page=next\n");
    bad(buttons, 17, 15, "too many buttons (16)");
    /* a payload longer than the buffer is refused, not cut */
    char big[300];
    snprintf(big, sizeof big, "widget button L page=next payload=%0200d\n", 0);
    bad(big, 1, 27, "payload=");
}

FX_TEST(kiosk_pages_gestures)
{
    kiosk_pages_cfg c;
    memset(&c, 0, sizeof c);
    c.npages = 3;
    c.swipe_px = 40;
    c.edge_pct = 10;
    /* 480 wide: edge zones are x < 48 and x >= 432 */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 400, 100, 300, 110), KIOSK_GESTURE_NEXT);  /* dragged left */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 100, 100, 300, 90), KIOSK_GESTURE_PREV);   /* dragged right */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 300, 100, 261, 100), KIOSK_GESTURE_NONE);  /* 39 px: too short */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 300, 100, 260, 100), KIOSK_GESTURE_NEXT);  /* 40 px */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 300, 10, 200, 200), KIOSK_GESTURE_NONE);   /* mostly down: a scroll */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 470, 100, 471, 101), KIOSK_GESTURE_NEXT);  /* tap at the right edge */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 432, 100, 432, 100), KIOSK_GESTURE_NEXT);
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 431, 100, 431, 100), KIOSK_GESTURE_NONE);  /* the middle */
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 47, 100, 47, 100), KIOSK_GESTURE_PREV);
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 48, 100, 48, 100), KIOSK_GESTURE_NONE);
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 10, 100, 30, 100), KIOSK_GESTURE_NONE);    /* moved 20: neither */
    c.edge_pct = 0;
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 470, 100, 470, 100), KIOSK_GESTURE_NONE);
    c.swipe_px = 0;
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 400, 100, 0, 100), KIOSK_GESTURE_NONE);
    /* one page: nothing to turn; absurd coordinates do not overflow */
    c.swipe_px = 40;
    FX_CHECK_EQ(kiosk_gesture(&c, 480, -2147483647 - 1, 0, 2147483647, 0), KIOSK_GESTURE_PREV);
    c.npages = 1;
    FX_CHECK_EQ(kiosk_gesture(&c, 480, 400, 100, 100, 100), KIOSK_GESTURE_NONE);
}

FX_TEST(kiosk_pages_lookup_and_carousel)
{
    char err[160];
    FX_CHECK_EQ(pcfg("carousel dwell=10\npage a dwell=2\nwidget clock\npage b\nwidget clock\npage c dwell=1\n"
                     "widget clock\n", err), 0);
    kiosk_pages_cfg *c = &P.pg;
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "b", 1), 1);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "2", 1), 2);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "3", 1), -1);
    FX_CHECK_EQ(kiosk_page_lookup(c, 2, "next", 4), 0);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "prev", 4), 2);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "d", 1), -1);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "", 0), -1);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "99999999999", 11), -1);
    FX_CHECK_EQ(kiosk_page_lookup(c, 0, "-1", 2), -1);
    /* a 2 s, b the carousel's 10 s, c 1 s */
    int64_t since = 0;
    FX_CHECK_EQ(kiosk_carousel(c, 0, &since, 1999), 0);
    FX_CHECK_EQ(kiosk_carousel(c, 0, &since, 2000), 1);
    FX_CHECK_EQ(since, 2000);
    FX_CHECK_EQ(kiosk_carousel(c, 1, &since, 11999), 1);
    FX_CHECK_EQ(kiosk_carousel(c, 1, &since, 12000), 2);
    FX_CHECK_EQ(kiosk_carousel(c, 2, &since, 13000), 0);
    FX_CHECK_EQ(since, 13000);
    /* a stalled kiosk catches up by the dwell times: 13 + 2 + 10 = 25 s: c */
    FX_CHECK_EQ(kiosk_carousel(c, 0, &since, 25500), 2);
    FX_CHECK_EQ(since, 25000);
    /* a clock years ahead turns at most one round and starts over */
    FX_CHECK_EQ(kiosk_carousel(c, 2, &since, (int64_t)1 << 50), 2);
    FX_CHECK_EQ(since, (int64_t)1 << 50);
    c->dwell_s = 0; /* no carousel: per-page dwell alone does nothing */
    since = 0;
    FX_CHECK_EQ(kiosk_carousel(c, 0, &since, 100000), 0);
}
