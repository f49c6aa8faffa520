/* SPDX-License-Identifier: MIT */
/* Recorded input streams (tests/input/NAME.txt) replayed through the pure
 * translation layer; each emitted event must match the next "expect" line.
 *
 * Stream format, one statement per line ('#' comments):
 *   screen W H [ROT]                  physical size and display rotation
 *   device N CLASS[+CLASS] [abs X0 X1 Y0 Y1] [mt X0 X1 Y0 Y1]
 *                                     CLASS: keyboard mouse touch mt tablet
 *   calib N A0 A1 A2 A3 A4 A5 A6      tslib pointercal for device N
 *   calibflag N swap|invertx|inverty
 *   ev N TYPE CODE VALUE              TYPE/CODE by name (see below) or number
 *   syn N                             SYN_REPORT on device N
 *   dropped N                         SYN_DROPPED on device N
 *   gpio N MS LEVEL                   a debounced GPIO line, initial level
 *   edge N T_MS LEVEL                 a raw edge on line N at time T
 *   poll N T_MS                       poll line N at time T ("gpio N press|release")
 *   expect TEXT                       the next event, as fx_event_describe prints it
 * At the end every emitted event must have been expected. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/input.h"
#include "fx_test.h"

static const struct {
    const char *name;
    int value;
} names[] = {
    {"SYN", 0}, {"KEY", 1}, {"REL", 2}, {"ABS", 3}, {"SYN_REPORT", 0}, {"REL_X", 0},
    {"REL_Y", 1}, {"REL_WHEEL", 8}, {"ABS_X", 0}, {"ABS_Y", 1}, {"ABS_MT_SLOT", 0x2f},
    {"ABS_MT_POSITION_X", 0x35}, {"ABS_MT_POSITION_Y", 0x36}, {"ABS_MT_TRACKING_ID", 0x39},
    {"BTN_LEFT", 0x110}, {"BTN_RIGHT", 0x111}, {"BTN_MIDDLE", 0x112}, {"BTN_TOUCH", 0x14a},
    {"BTN_STYLUS", 0x14b}, {"KEY_ESC", 1}, {"KEY_1", 2}, {"KEY_A", 30}, {"KEY_B", 48},
    {"KEY_C", 46}, {"KEY_Q", 16}, {"KEY_Z", 44}, {"KEY_ENTER", 28}, {"KEY_SPACE", 57},
    {"KEY_LEFTSHIFT", 42}, {"KEY_RIGHTSHIFT", 54}, {"KEY_LEFTCTRL", 29}, {"KEY_LEFTALT", 56},
    {"KEY_CAPSLOCK", 58}, {"KEY_F1", 59}, {"KEY_F10", 68}, {"KEY_F11", 87}, {"KEY_F12", 88},
    {"KEY_UP", 103}, {"KEY_DOWN", 108}, {"KEY_LEFT", 105}, {"KEY_RIGHT", 106},
    {"KEY_PAGEUP", 104}, {"KEY_PAGEDOWN", 109}, {"KEY_HOME", 102}, {"KEY_END", 107},
    {"KEY_INSERT", 110}, {"KEY_DELETE", 111}, {"KEY_SLASH", 53}, {"KEY_KP5", 76},
};

static int value_of(const char *w, int *ok)
{
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(names[i].name, w))
            return names[i].value;
    char *end;
    long v = strtol(w, &end, 0);
    *ok = *end == 0 && end != w;
    return (int)v;
}

typedef struct {
    char got[64][80];
    int n;
} sink;

static void collect(void *u, const fx_event *e)
{
    sink *s = u;
    if (s->n < 64)
        fx_event_describe(e, s->got[s->n++], 80);
}

static void replay(const char *path)
{
    FILE *f = fopen(path, "r");
    FX_CHECK_MSG(f != NULL, "cannot open %s", path);
    if (!f)
        return;
    fx_input in;
    fx_input_init(&in, 320, 240, 0);
    fx_input_dev dev[4];
    for (int i = 0; i < 4; i++)
        fx_input_dev_init(&dev[i], 0);
    fx_debounce gp[4];
    sink s = {.n = 0};
    int next = 0, lineno = 0;
    char line[256];
    uint64_t t = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *hash = strchr(line, '#');
        if (hash)
            *hash = 0;
        line[strcspn(line, "\r\n")] = 0;
        char w[8][48];
        int n = sscanf(line, "%47s %47s %47s %47s %47s %47s %47s %47s", w[0], w[1], w[2], w[3], w[4],
                       w[5], w[6], w[7]);
        if (n <= 0)
            continue;
        int ok = 1, N = n > 1 ? atoi(w[1]) & 3 : 0;
        if (!strcmp(w[0], "screen")) {
            fx_input_init(&in, atoi(w[1]), atoi(w[2]), n > 3 ? atoi(w[3]) : 0);
        } else if (!strcmp(w[0], "device")) {
            unsigned cls = 0;
            cls |= strstr(w[2], "keyboard") ? FX_DEV_KEYBOARD : 0u;
            cls |= strstr(w[2], "mouse") ? FX_DEV_MOUSE : 0u;
            cls |= strstr(w[2], "touch") ? FX_DEV_TOUCH : 0u;
            cls |= strstr(w[2], "mt") ? FX_DEV_MT : 0u;
            cls |= strstr(w[2], "tablet") ? FX_DEV_TABLET : 0u;
            fx_calib keep = dev[N].calib;
            fx_input_dev_init(&dev[N], cls);
            dev[N].calib = keep;
            for (int k = 3; k + 4 < n + 1 && k < n; k += 5) {
                int32_t *mn = !strcmp(w[k], "mt") ? dev[N].mt_min : dev[N].abs_min;
                int32_t *mx = !strcmp(w[k], "mt") ? dev[N].mt_max : dev[N].abs_max;
                if (k + 4 >= n) {
                    ok = 0;
                    break;
                }
                mn[0] = atoi(w[k + 1]);
                mx[0] = atoi(w[k + 2]);
                mn[1] = atoi(w[k + 3]);
                mx[1] = atoi(w[k + 4]);
            }
        } else if (!strcmp(w[0], "calib")) {
            char *p = line + strlen("calib");
            while (*p == ' ')
                p++;
            p = strchr(p, ' ');
            ok = p && fx_calib_parse(&dev[N].calib, p, (unsigned)strlen(p)) == 0;
        } else if (!strcmp(w[0], "calibflag")) {
            dev[N].calib.swap_xy |= !strcmp(w[2], "swap");
            dev[N].calib.invert_x |= !strcmp(w[2], "invertx");
            dev[N].calib.invert_y |= !strcmp(w[2], "inverty");
        } else if (!strcmp(w[0], "ev") && n == 5) {
            fx_raw_event e = {t, (uint16_t)value_of(w[2], &ok), (uint16_t)value_of(w[3], &ok),
                              value_of(w[4], &ok)};
            fx_input_feed(&in, &dev[N], &e, collect, &s);
        } else if (!strcmp(w[0], "syn") || !strcmp(w[0], "dropped")) {
            fx_raw_event e = {t, 0, (uint16_t)(w[0][0] == 's' ? 0 : 3), 0};
            fx_input_feed(&in, &dev[N], &e, collect, &s);
        } else if (!strcmp(w[0], "at")) {
            t = (uint64_t)atoll(w[1]) * 1000;
        } else if (!strcmp(w[0], "gpio")) {
            fx_debounce_init(&gp[N], (uint32_t)atoi(w[2]), atoi(w[3]));
        } else if (!strcmp(w[0], "edge")) {
            fx_debounce_edge(&gp[N], atoi(w[3]), (uint64_t)atoll(w[2]) * 1000);
        } else if (!strcmp(w[0], "poll")) {
            int r = fx_debounce_poll(&gp[N], (uint64_t)atoll(w[2]) * 1000);
            if (r >= 0 && s.n < 64)
                snprintf(s.got[s.n++], 80, "gpio %d %s", N, r ? "press" : "release");
        } else if (!strcmp(w[0], "expect")) {
            const char *want = line + 6;
            while (*want == ' ')
                want++;
            if (next >= s.n)
                FX_CHECK_MSG(0, "%s:%d: expected '%s', got nothing", path, lineno, want);
            else if (strcmp(s.got[next], want))
                FX_CHECK_MSG(0, "%s:%d: expected '%s', got '%s'", path, lineno, want, s.got[next]);
            next++;
        } else {
            ok = 0;
        }
        FX_CHECK_MSG(ok, "%s:%d: bad line '%s'", path, lineno, line);
    }
    for (; next < s.n; next++)
        FX_CHECK_MSG(0, "%s: unexpected event '%s'", path, s.got[next]);
    fclose(f);
}

FX_TEST(input_recorded_streams)
{
    DIR *d = opendir("tests/input");
    FX_CHECK(d != NULL);
    if (!d)
        return;
    int count = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        size_t l = strlen(e->d_name);
        if (l < 5 || strcmp(e->d_name + l - 4, ".txt"))
            continue;
        char path[512];
        snprintf(path, sizeof path, "tests/input/%s", e->d_name);
        replay(path);
        count++;
    }
    closedir(d);
    FX_CHECK(count >= 6);
}

FX_TEST(keymap_us_layout)
{
    FX_CHECK_EQ(fx_keymap_us(30, 0, 0), 'a');
    FX_CHECK_EQ(fx_keymap_us(30, FX_MOD_SHIFT, 0), 'A');
    FX_CHECK_EQ(fx_keymap_us(30, 0, 1), 'A');
    FX_CHECK_EQ(fx_keymap_us(30, FX_MOD_SHIFT, 1), 'a');
    FX_CHECK_EQ(fx_keymap_us(2, FX_MOD_SHIFT, 1), '!'); /* caps does not shift digits */
    FX_CHECK_EQ(fx_keymap_us(46, FX_MOD_CTRL, 0), 3);   /* Ctrl-C */
    FX_CHECK_EQ(fx_keymap_us(28, 0, 0), 13);
    FX_CHECK_EQ(fx_keymap_us(127, 0, 0), -FX_KEY_MENU); /* KEY_COMPOSE, the Menu key */
    FX_CHECK_EQ(fx_keymap_us(139, 0, 0), -FX_KEY_MENU); /* KEY_MENU */
    FX_CHECK_EQ(fx_keymap_us(1, 0, 0), 27);
    FX_CHECK_EQ(fx_keymap_us(111, 0, 0), 127);
    FX_CHECK_EQ(fx_keymap_us(59, 0, 0), -FX_KEY_F1);
    FX_CHECK_EQ(fx_keymap_us(88, 0, 0), -FX_KEY_F12);
    FX_CHECK_EQ(fx_keymap_us(104, 0, 0), -FX_KEY_PAGE_UP);
    FX_CHECK_EQ(fx_keymap_us(42, 0, 0), 0);
    FX_CHECK_EQ(fx_keymap_us(500, 0, 0), 0);
}

FX_TEST(rotation_maps_every_corner)
{
    fx_input in;
    int32_t x, y, w, h;
    int rots[] = {0, 90, 180, 270};
    for (int r = 0; r < 4; r++) {
        fx_input_init(&in, 800, 480, rots[r]);
        fx_input_logical_size(&in, &w, &h);
        FX_CHECK_EQ(w, r & 1 ? 480 : 800);
        /* every physical pixel maps inside the logical screen, one-to-one at corners */
        int32_t px[] = {0, 799, 0, 799}, py[] = {0, 0, 479, 479};
        for (int c = 0; c < 4; c++) {
            fx_input_to_logical(&in, px[c], py[c], &x, &y);
            FX_CHECK(x >= 0 && x < w && y >= 0 && y < h);
        }
    }
    fx_input_init(&in, 800, 480, 90);
    fx_input_to_logical(&in, 799, 0, &x, &y); /* physical top-right shows logical top-left */
    FX_CHECK(x == 0 && y == 0);
    fx_input_init(&in, 800, 480, 270);
    fx_input_to_logical(&in, 0, 479, &x, &y); /* bottom-left shows logical top-left */
    FX_CHECK(x == 0 && y == 0);
}

FX_TEST(calibration_file_parsing)
{
    fx_calib c;
    memset(&c, 0, sizeof c);
    const char good[] = "-67 13652 -2524268 -9181 -3 34996208 65536 800 480 0\n";
    FX_CHECK_EQ(fx_calib_parse(&c, good, sizeof good - 1), 0);
    FX_CHECK_EQ(c.a[0], -67);
    FX_CHECK_EQ(c.a[6], 65536);
    FX_CHECK_EQ(fx_calib_parse(&c, "1 2 3", 5), -22);
    FX_CHECK_EQ(fx_calib_parse(&c, "1 0 0 0 1 0 0", 13), -22); /* a6 = 0 */
    FX_CHECK_EQ(fx_calib_parse(&c, "1 x 0 0 1 0 1", 13), -22);
    FX_CHECK_EQ(fx_calib_parse(&c, "99999999999 0 0 0 1 0 1", 23), -22);
}

typedef struct {
    int32_t x, y;
    int n;
} last_pos;

static void keep_last(void *u, const fx_event *e)
{
    last_pos *p = u;
    p->x = e->x;
    p->y = e->y;
    p->n++;
}

static void feed_xy(fx_input *in, fx_input_dev *d, int32_t x, int32_t y, last_pos *p)
{
    fx_raw_event ev[] = {{0, 3, 0, x}, {0, 3, 1, y}, {0, 1, 0x14a, 1}, {0, 0, 0, 0}};
    for (size_t i = 0; i < sizeof ev / sizeof ev[0]; i++)
        fx_input_feed(in, d, &ev[i], keep_last, p);
}

/* The scaling's definition in exact arithmetic: nearest pixel, the range
 * ends on the edge pixels, clamped to the screen. */
static int32_t ref_scale(int64_t r, int64_t lo, int64_t hi, int64_t n)
{
    __extension__ __int128 a = (__int128)(r - lo) * (n - 1) * 2 + (hi - lo);
    __extension__ __int128 q = a / (2 * (__int128)(hi - lo));
    if (a < 0 && q * 2 * (hi - lo) != a)
        q--; /* floor */
    return q < 0 ? 0 : q > n - 1 ? (int32_t)(n - 1) : (int32_t)q;
}

/* Issue #40: a device reporting -1..2^31-1 overflowed the 32-bit range
 * difference and the 64-bit numerator. Every corner of the int32 ranges and
 * values, on tiny and huge screens, lands on the exact pixel. */
FX_TEST(input_scaling_extreme_ranges)
{
    const int32_t v[] = {INT32_MIN, INT32_MIN + 1, -2, -1, 0, 1, 4095, INT32_MAX - 1, INT32_MAX};
    const int32_t sizes[][2] = {{800, 480}, {1, 1}, {2, 3}, {INT32_MAX, INT32_MAX}};
    const size_t nv = sizeof v / sizeof v[0];
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (size_t a = 0; a < nv; a++)
            for (size_t b = a + 1; b < nv; b++)
                for (size_t r = 0; r < nv; r++) {
                    fx_input in;
                    fx_input_dev d;
                    fx_input_init(&in, sizes[s][0], sizes[s][1], 0);
                    fx_input_dev_init(&d, FX_DEV_TOUCH);
                    d.abs_min[0] = d.abs_min[1] = v[a];
                    d.abs_max[0] = d.abs_max[1] = v[b];
                    last_pos p = {-7, -7, 0};
                    feed_xy(&in, &d, v[r], v[nv - 1 - r], &p);
                    FX_CHECK(p.n > 0);
                    int32_t ex = ref_scale(v[r], v[a], v[b], sizes[s][0]);
                    int32_t ey = ref_scale(v[nv - 1 - r], v[a], v[b], sizes[s][1]);
                    FX_CHECK_MSG(p.x == ex && p.y == ey,
                                 "screen %d range %d..%d raw %d,%d: got %d,%d want %d,%d",
                                 (int)sizes[s][0], (int)v[a], (int)v[b], (int)v[r],
                                 (int)v[nv - 1 - r], (int)p.x, (int)p.y, (int)ex, (int)ey);
                }
}

/* The pointercal path with every coefficient and value at an int32 corner:
 * the three terms do not fit 64 bits together; the pixel is the exact
 * quotient clamped to the screen, also after inversion. */
FX_TEST(input_calibration_extreme_coefficients)
{
    const int32_t v[] = {INT32_MIN, -1, 1, INT32_MAX};
    for (int i = 0; i < 4 * 4 * 4 * 4 * 2; i++) {
        int32_t a0 = v[i & 3], a2 = v[(i >> 2) & 3], a6 = v[(i >> 4) & 3], r = v[(i >> 6) & 3];
        int inv = (i >> 8) & 1;
        fx_input in;
        fx_input_dev d;
        fx_input_init(&in, 800, 480, 0);
        fx_input_dev_init(&d, FX_DEV_TOUCH);
        d.calib = (fx_calib){.a = {a0, a0, a2, a0, a0, a2, a6}, .valid = 1, .invert_x = (uint8_t)inv};
        last_pos p = {-7, -7, 0};
        feed_xy(&in, &d, r, r, &p);
        __extension__ __int128 q = ((__int128)a2 + (__int128)a0 * r + (__int128)a0 * r) / a6;
        int32_t e = q < 0 ? 0 : q > 799 ? 799 : (int32_t)q;
        int32_t ey = q < 0 ? 0 : q > 479 ? 479 : (int32_t)q;
        FX_CHECK_MSG(p.n > 0 && p.x == (inv ? 799 - e : e) && p.y == ey,
                     "a0 %d a2 %d a6 %d raw %d: got %d,%d", (int)a0, (int)a2, (int)a6, (int)r,
                     (int)p.x, (int)p.y);
    }
}
