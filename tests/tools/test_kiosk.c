/* SPDX-License-Identifier: MIT */
/* fixel-kiosk parsers (tools/fixel-kiosk/kiosk_parse.c): config directives
 * and their errors, data lines good and bad, the ring buffer's bound. */
#include "fx_test.h"

#include <stdio.h>
#include <string.h>

#include "../../tools/fixel-kiosk/kiosk_parse.c"

static kiosk_config K;

static int cfg(const char *s, char *err)
{
    return kiosk_config_parse(&K, s, strlen(s), err, 128);
}

static int line(const char *s, int64_t t) { return kiosk_data_line(&K, s, strlen(s), t, NULL); }

FX_TEST(kiosk_milli_parse_and_round)
{
    int64_t v = 0;
    FX_CHECK_EQ(kiosk_parse_milli("21.5", 4, &v), 0);
    FX_CHECK_EQ(v, 21500);
    FX_CHECK_EQ(kiosk_parse_milli("-0.0005", 7, &v), 0);
    FX_CHECK_EQ(v, -1); /* half away from zero */
    FX_CHECK_EQ(kiosk_parse_milli("+.25", 4, &v), 0);
    FX_CHECK_EQ(v, 250);
    FX_CHECK_EQ(kiosk_parse_milli("1e5", 3, &v), -1);
    FX_CHECK_EQ(kiosk_parse_milli("-", 1, &v), -1);
    FX_CHECK_EQ(kiosk_parse_milli(".", 1, &v), -1);
    FX_CHECK_EQ(kiosk_parse_milli("99999999999999999999", 20, &v), -1);
    char b[32];
    kiosk_format_milli(b, sizeof b, 21549, 1);
    FX_CHECK(strcmp(b, "21.5") == 0);
    kiosk_format_milli(b, sizeof b, -1950, 0);
    FX_CHECK(strcmp(b, "-2") == 0);
    kiosk_format_milli(b, sizeof b, -4, 2);
    FX_CHECK(strcmp(b, "0.00") == 0); /* no "-0.00" */
    kiosk_format_milli(b, sizeof b, 7, 3);
    FX_CHECK(strcmp(b, "0.007") == 0);
}

FX_TEST(kiosk_config_parses_widgets)
{
    char err[128];
    FX_CHECK_EQ(cfg("# c\ntitle My panel  \ngrid 3x2\nstale 2.5\nhistory 30\nbg #102030\n"
                    "widget gauge rpm col=1 row=0 h=2 min=0 max=6000 unit=\"r/min\" label=\"Motor speed\"\n"
                    "widget spark rpm col=0 row=1\nwidget clock col=2\nwidget text msg col=0 row=0\n",
                    err), 0);
    FX_CHECK(strcmp(K.title, "My panel") == 0);
    FX_CHECK_EQ(K.cols, 3);
    FX_CHECK_EQ(K.rows, 2);
    FX_CHECK_EQ(K.stale_ms, 2500);
    FX_CHECK_EQ(K.history, 30);
    FX_CHECK_EQ_HEX(K.bg, 0xFF102030u);
    FX_CHECK_EQ(K.nwidgets, 4);
    FX_CHECK_EQ(K.nsources, 2); /* rpm shared by two widgets */
    FX_CHECK_EQ(K.widgets[0].max, 6000000);
    FX_CHECK(strcmp(K.widgets[0].label, "Motor speed") == 0);
    FX_CHECK(strcmp(K.widgets[0].unit, "r/min") == 0);
    FX_CHECK_EQ(K.widgets[1].source, K.widgets[0].source);
    FX_CHECK_EQ(K.widgets[2].source, -1);
    FX_CHECK_EQ((int)K.widgets[2].type, (int)KIOSK_CLOCK);
}

FX_TEST(kiosk_config_errors_name_the_line)
{
    char err[128];
    FX_CHECK_EQ(cfg("grid 2x2\n\nwidget dial x\n", err), -1);
    FX_CHECK(strncmp(err, "line 3: unknown widget type", 27) == 0);
    FX_CHECK_EQ(cfg("widget number x label=\"open\n", err), -1);
    FX_CHECK(strstr(err, "line 1") != NULL);
    FX_CHECK_EQ(cfg("grid 2x2\nwidget bar x col=1 w=2\n", err), -1);
    FX_CHECK(strstr(err, "outside the grid") != NULL);
    FX_CHECK_EQ(cfg("widget gauge x min=5 max=5\n", err), -1);
    FX_CHECK_EQ(cfg("grid 2x2 extra\n", err), -1);
    FX_CHECK_EQ(cfg("history 1000\n", err), -1);
    FX_CHECK_EQ(cfg("widget number x colour=#ffffff\n", err), -1);
    char many[64 * 40] = "grid 16x16\n";
    for (int i = 0; i <= KIOSK_MAX_WIDGETS; i++) strcat(many, "widget clock\n");
    FX_CHECK_EQ(cfg(many, err), -1);
    FX_CHECK(strstr(err, "too many widgets") != NULL);
}

FX_TEST(kiosk_data_lines)
{
    char err[128];
    FX_CHECK_EQ(cfg("widget number t\nwidget text s col=1\n", err), 0);
    FX_CHECK_EQ(line("t=21.5", 10), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].value, 21500);
    FX_CHECK_EQ(K.sources[0].last_ms, 10);
    FX_CHECK_EQ(line("  t , -3 \r", 20), KIOSK_LINE_OK); /* CSV form, spaces, CRLF */
    FX_CHECK_EQ(K.sources[0].value, -3000);
    FX_CHECK_EQ(line("s=pump on", 30), KIOSK_LINE_OK);
    FX_CHECK(strcmp(K.sources[1].text, "pump on") == 0);
    FX_CHECK_EQ(line("t=warm", 40), KIOSK_LINE_BAD);    /* numeric source */
    FX_CHECK_EQ(line("garbage", 40), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("=5", 40), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("t=", 40), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("t\x01=5", 40), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("s=a\x1b[2Jb", 40), KIOSK_LINE_BAD); /* no control characters on screen */
    FX_CHECK_EQ(line("other=5", 40), KIOSK_LINE_IGNORED);
    FX_CHECK_EQ(line("# note", 40), KIOSK_LINE_IGNORED);
    FX_CHECK_EQ(line("", 40), KIOSK_LINE_IGNORED);
    FX_CHECK_EQ(K.sources[0].value, -3000); /* bad lines left it alone */
    FX_CHECK_EQ(K.sources[0].last_ms, 20);
    FX_CHECK_EQ(K.sources[0].updates, 2u);
}

FX_TEST(kiosk_ring_buffer_is_bounded)
{
    char err[128], l[32];
    FX_CHECK_EQ(cfg("widget spark v\n", err), 0);
    for (int i = 0; i < 3 * KIOSK_HIST_MAX + 7; i++) {
        snprintf(l, sizeof l, "v=%d", i);
        FX_CHECK_EQ(line(l, i), KIOSK_LINE_OK);
    }
    const kiosk_source *s = &K.sources[0];
    FX_CHECK_EQ(s->count, (uint32_t)KIOSK_HIST_MAX);
    int last = 3 * KIOSK_HIST_MAX + 6;
    FX_CHECK_EQ(kiosk_hist_at(s, 10, 9), (int64_t)last * 1000);
    FX_CHECK_EQ(kiosk_hist_at(s, 10, 0), (int64_t)(last - 9) * 1000);
    FX_CHECK_EQ(kiosk_hist_at(s, KIOSK_HIST_MAX, 0), (int64_t)(last - KIOSK_HIST_MAX + 1) * 1000);
}

FX_TEST(kiosk_heat_config)
{
    char err[128];
    FX_CHECK_EQ(cfg("grid 2x1\nwidget heat m cells=4x3 min=-5 max=5 cmap=hot smooth=1\n", err), 0);
    FX_CHECK_EQ(K.sources[0].kind, KIOSK_KIND_HEAT);
    FX_CHECK_EQ(K.sources[0].gw, 4);
    FX_CHECK_EQ(K.sources[0].gh, 3);
    FX_CHECK_EQ(K.widgets[0].cmap, (int)FX_CMAP_HOT);
    FX_CHECK_EQ(K.widgets[0].smooth, 1);
    FX_CHECK_EQ(K.sources[0].cells[11], KIOSK_CELL_NONE);
    FX_CHECK_EQ(cfg("widget heat m\n", err), -1);
    FX_CHECK(strstr(err, "cells=CxR") != NULL);
    FX_CHECK_EQ(cfg("widget heat m cells=17x1\n", err), -1);
    FX_CHECK_EQ(cfg("widget heat m cells=4x4 cmap=plasma\n", err), -1);
    FX_CHECK_EQ(cfg("widget heat m cells=4x4 max=3000000\n", err), -1);
    FX_CHECK_EQ(cfg("widget number m cells=4x4\n", err), -1); /* heat keys on other widgets */
    FX_CHECK_EQ(cfg("grid 2x1\nwidget heat m cells=4x4\nwidget heat m col=1 cells=4x3\n", err), -1);
    FX_CHECK(strstr(err, "same cells") != NULL);
    FX_CHECK_EQ(cfg("grid 2x1\nwidget heat m cells=4x4\nwidget number m col=1\n", err), -1);
    FX_CHECK_EQ(cfg("grid 2x1\nwidget image m\nwidget gauge m col=1\n", err), -1);
    FX_CHECK_EQ(cfg("grid 2x1\nwidget text m\nwidget gauge m col=1\n", err), 0);
    FX_CHECK_EQ(K.sources[0].kind, KIOSK_KIND_NUMBER);
}

FX_TEST(kiosk_heat_lines)
{
    char err[128];
    FX_CHECK_EQ(cfg("grid 2x1\nwidget heat m cells=3x2\nwidget number t col=1\n", err), 0);
    FX_CHECK_EQ(line("m[1]=7,8,9.5", 5), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.changed, 1u);
    FX_CHECK_EQ(K.sources[0].cells[0], KIOSK_CELL_NONE); /* row 0 not sent yet */
    FX_CHECK_EQ(K.sources[0].cells[3], 7000);
    FX_CHECK_EQ(K.sources[0].cells[5], 9500);
    FX_CHECK_EQ(line(" m = 1, 2,3 ,4,-5,6 ", 6), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].cells[0], 1000);
    FX_CHECK_EQ(K.sources[0].cells[4], -5000);
    FX_CHECK_EQ(K.sources[0].last_ms, 6);
    FX_CHECK_EQ(line("m=1,2,3,4,5", 7), KIOSK_LINE_BAD);      /* one short */
    FX_CHECK_EQ(line("m=1,2,3,4,5,6,7", 7), KIOSK_LINE_BAD);  /* one over */
    FX_CHECK_EQ(line("m[2]=1,2,3", 7), KIOSK_LINE_BAD);       /* no row 2 */
    FX_CHECK_EQ(line("m[0]=1,x,3", 7), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("m[0=1,2,3", 7), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("m[]=1,2,3", 7), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("t[0]=1", 7), KIOSK_LINE_BAD);          /* rows belong to heat maps */
    FX_CHECK_EQ(line("m[0]=1,,3", 7), KIOSK_LINE_BAD);
    FX_CHECK_EQ(K.sources[0].cells[1], 2000);                /* bad lines changed nothing */
    FX_CHECK_EQ(K.sources[0].last_ms, 6);
    /* out-of-range values saturate and never become the "unset" marker */
    FX_CHECK_EQ(line("m[0]=-9999999,9999999,0", 8), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].cells[0], INT32_MIN + 1);
    FX_CHECK_EQ(K.sources[0].cells[1], INT32_MAX);
}

FX_TEST(kiosk_image_paths)
{
    char err[128], l[400];
    FX_CHECK_EQ(cfg("widget image cam path=\"/srv/cam now.png\" filter=nearest\n", err), 0);
    FX_CHECK(strcmp(K.sources[0].path, "/srv/cam now.png") == 0);
    FX_CHECK_EQ(K.sources[0].kind, KIOSK_KIND_IMAGE);
    FX_CHECK_EQ(K.widgets[0].smooth, 0);
    uint32_t g = K.sources[0].path_gen;
    FX_CHECK_EQ(line("cam=/tmp/a.ppm", 1), KIOSK_LINE_OK);
    FX_CHECK(strcmp(K.sources[0].path, "/tmp/a.ppm") == 0);
    FX_CHECK_EQ(line("cam=/tmp/a.ppm", 2), KIOSK_LINE_OK); /* the same path again: a reload */
    FX_CHECK_EQ(K.sources[0].path_gen, g + 2);
    memset(l, 0, sizeof l);
    memcpy(l, "cam=/", 5);
    memset(l + 5, 'a', KIOSK_PATH_MAX - 2); /* 4 + 1 + 254 = a 255-byte path fits */
    FX_CHECK_EQ(line(l, 3), KIOSK_LINE_OK);
    FX_CHECK_EQ(strlen(K.sources[0].path), (size_t)KIOSK_PATH_MAX - 1);
    l[5 + KIOSK_PATH_MAX - 2] = 'a'; /* one more does not */
    FX_CHECK_EQ(line(l, 4), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("cam=a\"b", 4), KIOSK_LINE_BAD);
    FX_CHECK_EQ(K.sources[0].path_gen, g + 3);
    FX_CHECK_EQ(cfg("widget image cam filter=cubic\n", err), -1);
}

FX_TEST(kiosk_csv_header)
{
    char err[128];
    FX_CHECK_EQ(cfg("grid 2x2\nwidget number temp\nwidget number hum col=1\nwidget text state row=1\n"
                    "widget image cam col=1 row=1\n", err), 0);
    FX_CHECK_EQ(line("time,temp,hum", 1), KIOSK_LINE_HEADER);
    FX_CHECK_EQ(K.ncols, 3);
    FX_CHECK_EQ(line("12:00,21.5,40", 2), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].value, 21500);
    FX_CHECK_EQ(K.sources[1].value, 40000);
    FX_CHECK_EQ(K.changed, 3u);
    FX_CHECK_EQ(line("12:01,,41", 3), KIOSK_LINE_OK); /* an empty field leaves its source alone */
    FX_CHECK_EQ(K.sources[0].last_ms, 2);
    FX_CHECK_EQ(K.sources[1].value, 41000);
    FX_CHECK_EQ(K.changed, 2u);
    FX_CHECK_EQ(line("12:02,22,wet", 4), KIOSK_LINE_BAD); /* all or nothing */
    FX_CHECK_EQ(K.sources[0].value, 21500);
    FX_CHECK_EQ(line("12:02,,", 4), KIOSK_LINE_IGNORED);
    FX_CHECK_EQ(line("temp,19", 5), KIOSK_LINE_OK); /* other field counts: name,value as before */
    FX_CHECK_EQ(K.sources[0].value, 19000);
    FX_CHECK_EQ(line("temp=18", 5), KIOSK_LINE_OK);
    FX_CHECK_EQ(line("a,b,c,d", 6), KIOSK_LINE_HEADER); /* a new header replaces the old one */
    FX_CHECK_EQ(line("12:00,21.5,40", 7), KIOSK_LINE_BAD);
    FX_CHECK_EQ(line("state,cam,temp,x", 8), KIOSK_LINE_HEADER);
    FX_CHECK_EQ(line("pump on,/img/1.png,20,?", 9), KIOSK_LINE_OK);
    FX_CHECK(strcmp(K.sources[2].text, "pump on") == 0);
    FX_CHECK(strcmp(K.sources[3].path, "/img/1.png") == 0);
    FX_CHECK_EQ(K.changed, 0xDu);
    /* not all names, so no header: "1a" is read as an unknown name,value */
    FX_CHECK_EQ(line("1a,b,c", 9), KIOSK_LINE_IGNORED);
    FX_CHECK_EQ(K.ncols, 4);
    /* a two-column CSV needs its header in the config */
    FX_CHECK_EQ(cfg("grid 2x1\ncolumns when,temp\nwidget number temp\n", err), 0);
    FX_CHECK_EQ(K.ncols, 2);
    FX_CHECK_EQ(line("08:15,3.25", 1), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].value, 3250);
    FX_CHECK_EQ(cfg("columns a,1b\n", err), -1);
    FX_CHECK_EQ(cfg("columns t,m\nwidget heat m cells=2x2\n", err), -1);
    FX_CHECK(strstr(err, "heat") != NULL);
    FX_CHECK_EQ(cfg("widget heat m cells=2x2\n", err), 0);
    FX_CHECK_EQ(line("t,m,x", 1), KIOSK_LINE_BAD); /* heat maps take no CSV column */
    FX_CHECK_EQ(K.ncols, 0);
}

FX_TEST(kiosk_mqtt_directives)
{
    char err[128];
    FX_CHECK_EQ(cfg("mqtt host=broker.lan port=8883 client=hall keepalive=60 session=persistent prefix=fleet/hall "
                    "backoff=2 backoff_max=30 auth=/etc/fixel/mqtt.auth status=5\n"
                    "mqtt_tls ca=/etc/ca.crt cert=/etc/c.crt key=/etc/c.key verify=1\n"
                    "subscribe home/+/temp source=temp json=sensors.values[2].t qos=1\n"
                    "subscribe fleet/lines/#\n"
                    "widget number temp\n",
                    err), 0);
    FX_CHECK_EQ(K.mqtt.enabled, 1);
    FX_CHECK(strcmp(K.mqtt.host, "broker.lan") == 0);
    FX_CHECK_EQ(K.mqtt.port, 8883);
    FX_CHECK_EQ(K.mqtt.persistent, 1);
    FX_CHECK_EQ(K.mqtt.tls, 1);
    FX_CHECK_EQ(K.mqtt.nsubs, 2);
    FX_CHECK_EQ(K.mqtt.subs[0].source, 0);
    FX_CHECK_EQ(K.mqtt.subs[0].qos, 1);
    FX_CHECK_EQ(K.mqtt.subs[1].source, -1);
    kiosk_jstep st[KIOSK_JPATH_DEPTH];
    FX_CHECK_EQ(kiosk_jpath_steps(K.mqtt.subs[0].json, st, KIOSK_JPATH_DEPTH), 4);
    FX_CHECK_EQ(st[2].index, 2);
    FX_CHECK(st[3].name && st[3].len == 1 && st[3].name[0] == 't');
    FX_CHECK_EQ(kiosk_jpath_steps("a..b", st, KIOSK_JPATH_DEPTH), -1);
    FX_CHECK_EQ(kiosk_jpath_steps("a[x]", st, KIOSK_JPATH_DEPTH), -1);
    /* errors: FILE:LINE:COL comes from errline/errcol, the range from the table */
    FX_CHECK_EQ(cfg("grid 2x2\nmqtt host=h port=0\n", err), -1);
    FX_CHECK(strstr(err, "port=0: expected 1..65535") != NULL);
    FX_CHECK_EQ(K.errline, 2);
    FX_CHECK_EQ(K.errcol, 13);
    FX_CHECK_EQ(cfg("mqtt host=h\nsubscribe a/b+ qos=1\n", err), -1);
    FX_CHECK_EQ(K.errcol, 11);
    FX_CHECK_EQ(cfg("mqtt host=h\nsubscribe # qos=1 json=a\n", err), -1); /* json without source */
    FX_CHECK_EQ(cfg("subscribe a\n", err), -1);                           /* no broker */
    FX_CHECK_EQ(cfg("mqtt port=1\n", err), -1);                            /* no host */
    FX_CHECK_EQ(cfg("mqtt host=h session=sometimes\n", err), -1);
    FX_CHECK_EQ(cfg("mqtt host=h\nmqtt_tls cert=a\n", err), -1);
    FX_CHECK_EQ(cfg("mqtt host=h prefix=a/#\n", err), -1);
    FX_CHECK_EQ(cfg("mqtt host=h backoff=10 backoff_max=5\n", err), -1);
}

FX_TEST(kiosk_topic_match_and_set_value)
{
    FX_CHECK(kiosk_topic_match("a/+/c", "a/b/c", 5));
    FX_CHECK(!kiosk_topic_match("a/+/c", "a/b/d", 5));
    FX_CHECK(!kiosk_topic_match("a/+", "a/b/c", 5));
    FX_CHECK(kiosk_topic_match("a/#", "a/b/c", 5));
    FX_CHECK(kiosk_topic_match("a/#", "a", 1));
    FX_CHECK(kiosk_topic_match("#", "x/y", 3));
    FX_CHECK(!kiosk_topic_match("#", "$SYS/x", 6));
    FX_CHECK(!kiosk_topic_match("a/b", "a/bc", 4));
    FX_CHECK(!kiosk_topic_match("a/bc", "a/b", 3));
    FX_CHECK(kiosk_topic_match("a/+", "a/", 2));
    char err[128];
    FX_CHECK_EQ(cfg("widget number t\nwidget heat h col=1 cells=2x1 min=0 max=1\nwidget text s row=1\n", err), 0);
    FX_CHECK_EQ(kiosk_set_value(&K, 0, " 21.5\n", 6, 10), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[0].value, 21500);
    FX_CHECK_EQ(kiosk_set_value(&K, 0, "warm", 4, 10), KIOSK_LINE_BAD);
    FX_CHECK_EQ(kiosk_set_value(&K, 0, "1\0002", 3, 10), KIOSK_LINE_BAD);
    FX_CHECK_EQ(kiosk_set_value(&K, 1, "0.5,1", 5, 10), KIOSK_LINE_OK);
    FX_CHECK_EQ(K.sources[1].cells[1], 1000);
    FX_CHECK_EQ(kiosk_set_value(&K, 1, "0.5", 3, 10), KIOSK_LINE_BAD);
    FX_CHECK_EQ(kiosk_set_value(&K, 2, "running", 7, 10), KIOSK_LINE_OK);
    FX_CHECK_EQ(kiosk_set_value(&K, 5, "1", 1, 10), KIOSK_LINE_BAD);
}

/* Output sections (issue #25): each screen's grid, title and widgets; the
 * sources shared; the errors with their place. */
FX_TEST(kiosk_output_sections)
{
    char err[128];
    FX_CHECK_EQ(cfg("grid 3x3\ntitle All\noutput HDMI-A-1\nwidget number t col=2 row=2\n"
                    "output DSI-1 rotation=270 size=480x800\ngrid 1x2\ntitle Panel\nwidget bar t row=1\n"
                    "widget text s\n", err), 0);
    FX_CHECK_EQ(K.noutputs, 2);
    FX_CHECK(!strcmp(K.outputs[0].name, "HDMI-A-1") && !strcmp(K.outputs[1].name, "DSI-1"));
    /* the section inherits what came before it, then has its own */
    FX_CHECK(K.outputs[0].cols == 3 && K.outputs[0].rows == 3 && !strcmp(K.outputs[0].title, "All"));
    FX_CHECK(K.outputs[0].rotation == -1 && K.outputs[0].width == 0);
    FX_CHECK(K.outputs[1].cols == 1 && K.outputs[1].rows == 2 && !strcmp(K.outputs[1].title, "Panel"));
    FX_CHECK(K.outputs[1].rotation == 270 && K.outputs[1].width == 480 && K.outputs[1].height == 800);
    FX_CHECK(K.nwidgets == 3 && K.widgets[0].screen == 0 && K.widgets[1].screen == 1 && K.widgets[2].screen == 1);
    /* one source t for both screens: a line updates the widgets of each */
    FX_CHECK_EQ(K.nsources, 2);
    FX_CHECK(K.widgets[0].source == K.widgets[1].source);
    FX_CHECK_EQ(line("t=5", 0), KIOSK_LINE_OK);
    /* without sections: screen 0, no outputs */
    FX_CHECK_EQ(cfg("widget number t\n", err), 0);
    FX_CHECK(K.noutputs == 0 && K.widgets[0].screen == 0);
    FX_CHECK_EQ(cfg("output A\noutput B\noutput A\n", err), -1);
    FX_CHECK(K.errline == 3 && K.errcol == 8 && strstr(err, "output named twice (first on line 1)"));
    FX_CHECK_EQ(cfg("output A speed=2\n", err), -1);
    FX_CHECK(K.errline == 1 && K.errcol == 10 && strstr(err, "unknown output key"));
    FX_CHECK_EQ(cfg("output A rotation=45\n", err), -1);
    FX_CHECK_EQ(cfg("output A size=20000x10\n", err), -1);
    FX_CHECK(strstr(err, "size=20000x10: expected 16..8192 each"));
    FX_CHECK_EQ(cfg("output A\nscreen idle=5\n", err), -1);
    FX_CHECK(K.errline == 2 && K.errcol == 1);
    FX_CHECK_EQ(cfg("output A\ngrid 1x1\nwidget clock col=1\n", err), -1);
    FX_CHECK(K.errline == 3 && strstr(err, "outside the grid"));
    FX_CHECK_EQ(cfg("output A\noutput B\noutput C\noutput D\noutput E\n", err), -1);
    FX_CHECK(K.errline == 5 && strstr(err, "more than 4 outputs"));
}

/* Issue #40: set/screen read its payload as a C string, so "on\0garbage"
 * switched the screen on. Every byte of the payload counts. */
FX_TEST(kiosk_screen_payload_uses_its_whole_length)
{
    FX_CHECK_EQ(kiosk_parse_onoff("on", 2), 1);
    FX_CHECK_EQ(kiosk_parse_onoff("ON\r\n", 4), 1);
    FX_CHECK_EQ(kiosk_parse_onoff("1", 1), 1);
    FX_CHECK_EQ(kiosk_parse_onoff("Off ", 4), 0);
    FX_CHECK_EQ(kiosk_parse_onoff("0\n", 2), 0);
    FX_CHECK_EQ(kiosk_parse_onoff("on\0garbage", 10), -1);
    FX_CHECK_EQ(kiosk_parse_onoff("off\0", 4), -1);
    FX_CHECK_EQ(kiosk_parse_onoff("1\0", 2), -1);
    FX_CHECK_EQ(kiosk_parse_onoff("o", 1), -1);
    FX_CHECK_EQ(kiosk_parse_onoff("onn", 3), -1);
    FX_CHECK_EQ(kiosk_parse_onoff("", 0), -1);
    FX_CHECK_EQ(kiosk_parse_onoff(" on", 3), -1);
}
