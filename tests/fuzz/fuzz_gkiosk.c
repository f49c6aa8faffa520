/* SPDX-License-Identifier: MIT */
/* libFuzzer target (issue #26): fixel-kiosk configs and data generated from
 * its key table (kiosk_keys in tools/fixel-kiosk/kiosk_parse.c). Every
 * directive, widget option and data value takes a corner of its declared
 * range (choice.h) or a value inside it; each data line comes with a clock
 * reading of its own (0, 8*10^13, near INT64_MAX / 1000, INT64_MIN, ...).
 * The generated text then runs through fuzz_kiosk.c's checks.
 * FUZZ_GRAMMAR_PRINT=1 prints the generated config and data. */
#include <stdlib.h>

#include "choice.h"

static int64_t clock_of[64];
#define KIOSK_TIME(line) ((line) < 64 ? clock_of[line] : (line))
#define LLVMFuzzerTestOneInput kiosk_checks
#include "fuzz_kiosk.c"
#undef LLVMFuzzerTestOneInput

static const char *const types[] = {"number", "gauge", "bar", "spark", "text", "clock", "heat", "image", "qr"};
static const char *const names[] = {"a", "b", "c", "h"};

static void put_value(in *s, out *o, const kiosk_key *q)
{
    char t[64];
    switch (q->type) {
    case 'i': put_dec(o, corner(s, q->min, q->max), 0); return;
    case 'm': put_dec(o, corner(s, q->min, q->max), 3); return;
    case 'p':
        put_dec(o, corner(s, q->min, q->max), 0);
        putc1(o, 'x');
        put_dec(o, corner(s, q->min, q->max), 0);
        return;
    case 'c': snprintf(t, sizeof t, "#%06X", take(s, 3)); put(o, t); return;
    case 'w': put(o, take(s, 1) & 1 ? "bilinear" : "viridis"); return;
    case 'f': put(o, take(s, 1) & 1 ? "/dev/null" : "\"missing.png\""); return;
    default: {
        uint32_t n = take(s, 1) % 70;
        putc1(o, '"');
        for (uint32_t i = 0; i < n; i++)
            putc1(o, (char)(' ' + take(s, 1) % 95));
        putc1(o, '"');
    }
    }
}

static const kiosk_key *pick(in *s, const char *scope)
{
    int n = 0;
    for (const kiosk_key *q = kiosk_keys; q->name; q++)
        n += !strcmp(q->scope, scope);
    int k = (int)(take(s, 1) % (uint32_t)n);
    for (const kiosk_key *q = kiosk_keys; q->name; q++)
        if (!strcmp(q->scope, scope) && k-- == 0)
            return q;
    return NULL;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char text[8192];
    in s = {data, size};
    out o = {text, 0, sizeof text};
    text[0] = 0;
    const kiosk_key *vk = kiosk_key_find("data", "VALUE", 5);
    uint32_t nd = take(&s, 1) % 5;
    for (uint32_t i = 0; i < nd; i++) {
        const kiosk_key *q = pick(&s, "directive");
        if (!strcmp(q->name, "widget"))
            continue;
        put(&o, q->name);
        putc1(&o, ' ');
        if (!strcmp(q->name, "columns"))
            put(&o, "a,b,c");
        else
            put_value(&s, &o, q);
        putc1(&o, '\n');
    }
    uint32_t nw = 1 + take(&s, 1) % 4;
    for (uint32_t i = 0; i < nw; i++) {
        uint32_t ty = take(&s, 1) % 8;
        put(&o, "widget ");
        put(&o, types[ty]);
        putc1(&o, ' ');
        put(&o, names[take(&s, 1) % 4]);
        uint32_t no = take(&s, 1) % 5;
        for (uint32_t j = 0; j < no; j++) {
            const kiosk_key *q = pick(&s, "widget");
            putc1(&o, ' ');
            put(&o, q->name);
            putc1(&o, '=');
            put_value(&s, &o, q);
        }
        putc1(&o, '\n');
    }
    size_t nul = o.n;
    putc1(&o, 'X'); /* becomes the NUL between config and data */
    uint32_t nl = take(&s, 1) % 12;
    for (uint32_t i = 0; i < nl && i < 64; i++) {
        clock_of[i] = take(&s, 1) & 1 ? corner(&s, INT64_MIN, INT64_MAX)
                                       : (take(&s, 1) & 1 ? INT64_MAX / 1000 - (int64_t)take(&s, 1) : 80000000000000LL);
        uint32_t form = take(&s, 1) % 6;
        const char *nm = names[take(&s, 1) % 4];
        if (form == 0) { /* CSV header then a row */
            put(&o, "a,b,c\n");
            put_dec(&o, corner(&s, vk->min, vk->max), 3);
            put(&o, ",x,");
            put_dec(&o, corner(&s, vk->min, vk->max), 3);
        } else if (form == 1) { /* a heat map row */
            put(&o, nm);
            putc1(&o, '[');
            put_dec(&o, corner(&s, -1, 16), 0);
            put(&o, "]=");
            uint32_t nc = take(&s, 1) % 18;
            for (uint32_t c = 0; c < nc; c++) {
                put_dec(&o, corner(&s, vk->min, vk->max), 3);
                putc1(&o, ',');
            }
        } else if (form == 2) { /* the raw digits of the issue */
            put(&o, nm);
            put(&o, take(&s, 1) & 1 ? "=9223372036854776" : "=-9223372036854775.999");
        } else {
            put(&o, nm);
            putc1(&o, form == 3 ? ',' : '=');
            put_dec(&o, corner(&s, vk->min, vk->max), (int)(take(&s, 1) % 4));
        }
        putc1(&o, '\n');
    }
    static int print = -1;
    if (print < 0)
        print = getenv("FUZZ_GRAMMAR_PRINT") != NULL;
    if (print)
        fprintf(stderr, "%.*s\n--\n%s\n", (int)nul, text, text + nul + 1);
    /* an exact-size heap copy, so ASan catches a read one past the end */
    uint8_t *copy = malloc(o.n ? o.n : 1);
    memcpy(copy, text, o.n);
    if (nul < o.n)
        copy[nul] = 0;
    kiosk_checks(copy, o.n);
    free(copy);
    return 0;
}
