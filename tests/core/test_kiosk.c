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
