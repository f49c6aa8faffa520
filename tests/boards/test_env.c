/* SPDX-License-Identifier: MIT */
/* The table of FIXEL_* variables (boards/env/env_table.c) and the corner
 * values generated from it (issue #26): for every INT entry the range's
 * ends, one past them, 0, +-1, and values near 2^15, 2^16, 2^24, 2^31 and
 * 2^63 are parsed and must be taken exactly when inside [min, max]; every
 * WORD entry takes each of its words in any case and nothing else; and the
 * options fx_*_options_from_env fill never hold a value outside the table. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/env.h"
#include "fixel/error.h"
#include "fx_test.h"

static char last_log[512];
static int log_count;

static void capture(fx_log_priority p, void *user, const char *fmt, va_list ap)
{
    (void)user;
    (void)p;
    vsnprintf(last_log, sizeof last_log, fmt, ap);
    log_count++;
}

FX_TEST(env_table_entries_well_formed)
{
    int n = 0;
    const fx_env_var *v = fx_env_table(&n);
    FX_CHECK(v && n >= 20);
    for (int i = 0; i < n; i++) {
        FX_CHECK(!strncmp(v[i].name, "FIXEL_", 6));
        FX_CHECK(fx_env_lookup(v[i].name) == &v[i]); /* names are unique */
        FX_CHECK(v[i].who && v[i].meaning && *v[i].meaning);
        if (v[i].kind == FX_ENV_WORD) {
            int words = 0;
            while (v[i].words[words])
                words++;
            FX_CHECK(v[i].listed >= 1 && v[i].listed <= words);
        }
        if (v[i].kind == FX_ENV_INT)
            FX_CHECK(v[i].min <= v[i].max);
        char want[200];
        FX_CHECK(fx_env_expect(&v[i], want, sizeof want) == 0 && want[0]);
    }
    FX_CHECK(fx_env_lookup("FIXEL_NO_SUCH") == NULL && fx_env_lookup(NULL) == NULL);
}

FX_TEST(env_int_corners_from_table)
{
    int n = 0;
    const fx_env_var *v = fx_env_table(&n);
    static const long long pivots[] = {0, 1 << 15, 1 << 16, 1 << 24, 2147483648LL, LLONG_MAX};
    int ints = 0;
    for (int i = 0; i < n; i++) {
        if (v[i].kind != FX_ENV_INT)
            continue;
        ints++;
        long long cand[64];
        int k = 0;
        cand[k++] = v[i].min;
        cand[k++] = v[i].max;
        cand[k++] = (long long)v[i].min - 1;
        cand[k++] = (long long)v[i].max + 1;
        for (size_t p = 0; p < sizeof pivots / sizeof pivots[0]; p++)
            for (int d = -1; d <= 1; d++) {
                if (pivots[p] == LLONG_MAX && d == 1)
                    continue;
                cand[k++] = pivots[p] + d;
                cand[k++] = -(pivots[p] + d);
            }
        for (int c = 0; c < k; c++) {
            char text[32];
            snprintf(text, sizeof text, "%lld", cand[c]);
            long got = -12345;
            int r = fx_env_parse(&v[i], text, &got);
            int inside = cand[c] >= v[i].min && cand[c] <= v[i].max;
            if (inside)
                FX_CHECK(r == 0 && got == cand[c]);
            else
                FX_CHECK(r == -FX_ERANGE && got == -12345);
        }
        /* one past 2^63 and text that strtol would half-take */
        static const char *const junk[] = {"9223372036854775808", "-9223372036854775809", "", " 5", "+5",
                                           "5 ", "5x", "0x10", "-", "1e3", "\x1b[31m"};
        for (size_t j = 0; j < sizeof junk / sizeof junk[0]; j++) {
            long got = -12345;
            int r = fx_env_parse(&v[i], junk[j], &got);
            FX_CHECK(r < 0 && got == -12345);
        }
    }
    FX_CHECK(ints >= 2);
}

FX_TEST(env_words_from_table)
{
    int n = 0;
    const fx_env_var *v = fx_env_table(&n);
    for (int i = 0; i < n; i++) {
        if (v[i].kind != FX_ENV_WORD)
            continue;
        for (int w = 0; v[i].words[w]; w++) {
            long got;
            FX_CHECK(fx_env_parse(&v[i], v[i].words[w], &got) == 0 && got == v[i].values[w]);
            char up[64];
            size_t len = strlen(v[i].words[w]);
            FX_CHECK(len < sizeof up - 2);
            for (size_t c = 0; c <= len; c++)
                up[c] = (char)((v[i].words[w][c] >= 'a' && v[i].words[w][c] <= 'z') ? v[i].words[w][c] - 32
                                                                                     : v[i].words[w][c]);
            FX_CHECK(fx_env_parse(&v[i], up, &got) == 0 && got == v[i].values[w]);
            /* a word with anything around it is not the word */
            char pad[70];
            snprintf(pad, sizeof pad, "%s ", v[i].words[w]);
            FX_CHECK(fx_env_parse(&v[i], pad, &got) == -FX_EINVAL);
            snprintf(pad, sizeof pad, "0%s", v[i].words[w]);
            FX_CHECK(fx_env_parse(&v[i], pad, &got) == -FX_EINVAL);
        }
        long got;
        FX_CHECK(fx_env_parse(&v[i], "no-such-value", &got) == -FX_EINVAL);
        FX_CHECK(fx_env_parse(&v[i], "", &got) == -FX_EINVAL);
    }
}

/* Every variable at every corner through the real readers: whatever the
 * value, the option fields hold one the table allows, and a value that is
 * not taken is said in one line naming the variable. */
FX_TEST(env_options_never_out_of_range)
{
    static const char *const values[] = {"", "0", "1", "-1", "90", "2147483648", "9223372036854775808",
                                         "memory", "deny", "RGB565", "debug", "off", "no-such-value",
                                         "a\x1b[31mb\rc"};
    int n = 0;
    const fx_env_var *v = fx_env_table(&n);
    for (int i = 0; i < n; i++) {
        if (strcmp(v[i].who, "library"))
            continue;
        for (size_t j = 0; j < sizeof values / sizeof values[0]; j++) {
            setenv(v[i].name, values[j], 1);
            fx_app_options o;
            fx_app_options_init(&o);
            o.display.log = capture;
            log_count = 0;
            last_log[0] = 0;
            int r = fx_app_options_from_env(&o);
            long want;
            int pr = fx_env_parse(&v[i], values[j], &want);
            if (v[i].kind <= FX_ENV_INT && values[j][0] && pr < 0) {
                /* not taken: said, naming the variable, in one line */
                FX_CHECK(log_count >= 1 && strstr(last_log, v[i].name) && !strchr(last_log, '\n') &&
                         !strchr(last_log, '\x1b') && !strchr(last_log, '\r'));
            }
            FX_CHECK(o.display.rotation == -1 || o.display.rotation == 0 || o.display.rotation == 90 ||
                     o.display.rotation == 180 || o.display.rotation == 270);
            FX_CHECK(o.frames >= 0 && o.frames <= 1000000000);
            FX_CHECK(o.display.sw_rotation == 0 || o.display.sw_rotation == 1);
            if (!strcmp(v[i].name, "FIXEL_FRAMES") || !strcmp(v[i].name, "FIXEL_BACKEND"))
                FX_CHECK((r < 0) == (values[j][0] && (pr < 0)));
            else
                FX_CHECK(r == 0);
            unsetenv(v[i].name);
        }
    }
}

FX_TEST(env_get_message_and_unset)
{
    long v = 7;
    char msg[256];
    unsetenv("FIXEL_ROTATION");
    FX_CHECK(fx_env_get("FIXEL_ROTATION", &v, msg, sizeof msg) == 1 && v == 7);
    setenv("FIXEL_ROTATION", "", 1);
    FX_CHECK(fx_env_get("FIXEL_ROTATION", &v, msg, sizeof msg) == 1 && v == 7);
    setenv("FIXEL_ROTATION", "45", 1);
    FX_CHECK(fx_env_get("FIXEL_ROTATION", &v, msg, sizeof msg) == -FX_EINVAL && v == 7);
    FX_CHECK(!strcmp(msg, "FIXEL_ROTATION=45 ignored (0, 90, 180 or 270)"));
    setenv("FIXEL_FRAMES", "0", 1);
    FX_CHECK(fx_env_get("FIXEL_FRAMES", &v, msg, sizeof msg) == -FX_ERANGE);
    FX_CHECK(!strcmp(msg, "FIXEL_FRAMES=0 ignored (a whole number from 1 to 1000000000)"));
    /* a long value is cut, not echoed whole */
    char big[2000];
    memset(big, 'x', sizeof big - 1);
    big[sizeof big - 1] = 0;
    setenv("FIXEL_FRAMES", big, 1);
    FX_CHECK(fx_env_get("FIXEL_FRAMES", &v, msg, sizeof msg) == -FX_EINVAL && strlen(msg) < 160);
    unsetenv("FIXEL_FRAMES");
    unsetenv("FIXEL_ROTATION");
    FX_CHECK(fx_env_get("FIXEL_NOT_IN_TABLE", &v, msg, sizeof msg) == -FX_EINVAL);
}
