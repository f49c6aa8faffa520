/* SPDX-License-Identifier: MIT */
/* fixel-kiosk parsers: config text and data lines, from memory buffers.
 * Every input is bounded by a length (no NUL needed) and every copy by the
 * fixed sizes in kiosk.h: a hostile line can be rejected but never make the
 * model grow. */
#include "kiosk.h"

#include <string.h>
#include <strings.h>

#include "fixel/colormap.h"

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }
static int is_name_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '.' || c == '-' || c == '/';
}

static void copy_str(char *dst, size_t size, const char *s, size_t n)
{
    if (n >= size) n = size - 1;
    memcpy(dst, s, n);
    dst[n] = 0;
}

int kiosk_parse_milli(const char *s, size_t len, int64_t *out)
{
    size_t i = 0;
    int neg = 0, digits = 0, frac = 0;
    int64_t v = 0;
    if (i < len && (s[i] == '-' || s[i] == '+')) neg = s[i++] == '-';
    for (; i < len && s[i] >= '0' && s[i] <= '9'; i++, digits++) {
        v = v * 10 + (s[i] - '0');
        if (v > KIOSK_VALUE_MAX) return -1; /* the declared range: v * 1000 + 999 stays far from INT64_MAX */
    }
    v *= 1000;
    if (i < len && s[i] == '.') {
        int64_t scale = 100;
        for (i++; i < len && s[i] >= '0' && s[i] <= '9'; i++, frac++) {
            if (scale > 0) v += (s[i] - '0') * scale;
            else if (scale == 0 && s[i] >= '5') v += 1; /* round half away from zero */
            scale = scale > 0 ? scale / 10 : -1;
        }
    }
    if (i != len || digits + frac == 0) return -1;
    *out = neg ? -v : v;
    return 0;
}

int kiosk_parse_onoff(const char *s, size_t len)
{
    while (len && (s[len - 1] == ' ' || s[len - 1] == '\n' || s[len - 1] == '\r')) len--;
    /* every byte counts: a C-string compare would read "on\0garbage" as "on" */
    if ((len == 2 && !strncasecmp(s, "on", 2)) || (len == 1 && s[0] == '1')) return 1;
    if ((len == 3 && !strncasecmp(s, "off", 3)) || (len == 1 && s[0] == '0')) return 0;
    return -1;
}

void kiosk_format_milli(char *buf, size_t size, int64_t v, int d)
{
    static const int64_t div[4] = {1000, 100, 10, 1};
    char tmp[32];
    int n = 0, neg = v < 0;
    uint64_t u = neg ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    uint64_t q, f;
    if (d < 0) d = 0;
    if (d > 3) d = 3;
    u = (u + (uint64_t)div[d] / 2) / (uint64_t)div[d]; /* rounded to d decimals */
    q = u;
    for (int k = 0; k < d; k++) q /= 10;
    f = u - q * (d == 0 ? 1 : d == 1 ? 10 : d == 2 ? 100 : 1000);
    for (int k = 0; k < d; k++) { tmp[n++] = (char)('0' + f % 10); f /= 10; }
    if (d) tmp[n++] = '.';
    do { tmp[n++] = (char)('0' + q % 10); q /= 10; } while (q);
    if (neg && u) tmp[n++] = '-';
    size_t o = 0;
    while (n > 0 && o + 1 < size) buf[o++] = tmp[--n];
    if (size) buf[o] = 0;
}

int64_t kiosk_hist_at(const kiosk_source *s, uint32_t n, uint32_t i)
{
    if (n > s->count) n = s->count;
    if (n == 0) return 0;
    return s->hist[(s->head + KIOSK_HIST_MAX - n + i % n) % KIOSK_HIST_MAX];
}

/* ---- config ---- */

typedef struct tok { const char *s; size_t n; } tok;

/* Next whitespace-separated token of [*p, end); double quotes group. */
static int next_tok(const char **p, const char *end, tok *t)
{
    const char *q = *p;
    while (q < end && is_space(*q)) q++;
    /* "# text" is a comment; "#rrggbb" is a colour */
    if (q >= end || (*q == '#' && (q + 1 >= end || is_space(q[1]) || q[1] == '#'))) { *p = end; return 0; }
    t->s = q;
    int quoted = 0;
    while (q < end && (quoted || !is_space(*q))) {
        if (*q == '"') quoted = !quoted;
        q++;
    }
    if (quoted) return -1;
    t->n = (size_t)(q - t->s);
    *p = q;
    return 1;
}

static int tok_is(tok t, const char *w) { return strlen(w) == t.n && memcmp(t.s, w, t.n) == 0; }

static int parse_int(tok t, int lo, int hi, int *out)
{
    int64_t v = 0;
    if (t.n == 0 || t.n > 9) return -1;
    for (size_t i = 0; i < t.n; i++) {
        if (t.s[i] < '0' || t.s[i] > '9') return -1;
        v = v * 10 + (t.s[i] - '0');
    }
    if (v < lo || v > hi) return -1;
    *out = (int)v;
    return 0;
}

static int parse_pair(tok t, int lo, int hi, int *a, int *b)
{
    for (size_t i = 0; i < t.n; i++)
        if (t.s[i] == 'x')
            return parse_int((tok){t.s, i}, lo, hi, a) || parse_int((tok){t.s + i + 1, t.n - i - 1}, lo, hi, b)
                       ? -1 : 0;
    return -1;
}

static int parse_color(tok t, uint32_t *out)
{
    uint32_t v = 0;
    if (t.n != 7 || t.s[0] != '#') return -1;
    for (size_t i = 1; i < 7; i++) {
        char c = t.s[i];
        int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10
              : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (d < 0) return -1;
        v = v << 4 | (uint32_t)d;
    }
    *out = 0xFF000000u | v;
    return 0;
}

/* "value" or value: strip one pair of quotes; labels must be printable. */
static int parse_text(tok t, char *dst)
{
    if (t.n >= 2 && t.s[0] == '"' && t.s[t.n - 1] == '"') { t.s++; t.n -= 2; }
    if (t.n >= KIOSK_TEXT_MAX) return -1;
    for (size_t i = 0; i < t.n; i++)
        if ((unsigned char)t.s[i] < 0x20 || t.s[i] == 0x7f || t.s[i] == '"') return -1;
    copy_str(dst, KIOSK_TEXT_MAX, t.s, t.n);
    return 0;
}

static int find_source(const kiosk_config *k, const char *s, size_t n)
{
    for (int i = 0; i < k->nsources; i++)
        if (strlen(k->sources[i].name) == n && memcmp(k->sources[i].name, s, n) == 0) return i;
    return -1;
}

/* tests/corners/kiosk-corners.sh checks this list against kiosk_keys */
#define UNKNOWN_DIRECTIVE \
    "unknown directive (title grid size stale history bg panel fg columns widget mqtt mqtt_tls subscribe screen schedule " \
    "page carousel touch output)"
#define ALLW 0x1FFu /* the widgets that show a source */
#define BTNW (1u << KIOSK_BUTTON)
#define LAYW (ALLW | BTNW)
#define HEATW (1u << KIOSK_HEAT)
#define IMGW (1u << KIOSK_IMAGE)
#define QRW (1u << KIOSK_QR)
#define VMAX (KIOSK_VALUE_MAX * 1000)
const kiosk_key kiosk_keys[] = {
    {"directive", "title", 't', 0, KIOSK_TEXT_MAX - 1, 0, "the rest of the line"},
    {"directive", "grid", 'p', 1, 16, 0, "CxR cells"},
    {"directive", "size", 'p', 16, 8192, 0, "WxH pixels"},
    {"directive", "stale", 'm', 1, 86400000000LL, 0, "seconds a source may be silent"},
    {"directive", "history", 'i', 2, KIOSK_HIST_MAX, 0, "samples per spark"},
    {"directive", "bg", 'c', 0, 0, 0, "#rrggbb"},
    {"directive", "panel", 'c', 0, 0, 0, "#rrggbb"},
    {"directive", "fg", 'c', 0, 0, 0, "#rrggbb"},
    {"directive", "columns", 't', 0, 0, 0, "name,name,... (up to 32)"},
    {"directive", "widget", 't', 0, 0, 0, "TYPE SOURCE key=value..."},
    {"directive", "mqtt", 't', 0, 0, 0, "key=value...: the broker (keys: scope mqtt)"},
    {"directive", "mqtt_tls", 't', 0, 0, 0, "key=value...: TLS to the broker (keys: scope mqtt_tls)"},
    {"directive", "subscribe", 't', 0, 0, 0, "TOPIC key=value...: a topic feeding sources (keys: scope subscribe)"},
    {"directive", "screen", 't', 0, 0, 0, "key=value...: screen power and backlight (keys: scope screen)"},
    {"widget", "col", 'i', 0, 63, LAYW, "first cell column"},
    {"widget", "row", 'i', 0, 63, LAYW, "first cell row"},
    {"widget", "w", 'i', 1, 64, LAYW, "cells wide"},
    {"widget", "h", 'i', 1, 64, LAYW, "cells high"},
    {"widget", "decimals", 'i', 0, 3, ALLW, "digits after the point"},
    {"widget", "min", 'm', -VMAX, VMAX, ALLW, "low end of the scale (max - min <= 2251799813685; heat: within +-2000000)"},
    {"widget", "max", 'm', -VMAX, VMAX, ALLW, "high end of the scale (heat: within +-2000000)"},
    {"widget", "color", 'c', 0, 0, LAYW, "#rrggbb"},
    {"widget", "label", 't', 0, KIOSK_TEXT_MAX - 1, LAYW, "caption"},
    {"widget", "unit", 't', 0, KIOSK_TEXT_MAX - 1, ALLW, "unit after the value"},
    {"widget", "cells", 'p', 1, KIOSK_HEAT_DIM, HEATW, "CxR grid of the heat map"},
    {"widget", "cmap", 'w', 0, 0, HEATW, "a colour map name (viridis, hot, ...)"},
    {"widget", "smooth", 'i', 0, 1, HEATW, "bilinear heat map"},
    {"widget", "filter", 'w', 0, 0, IMGW, "nearest|bilinear"},
    {"widget", "path", 'f', 1, KIOSK_PATH_MAX - 1, IMGW, "image file (PNG, JPEG, GIF, WebP or PPM)"},
    {"widget", "text", 't', 0, KIOSK_TEXT_MAX - 1, QRW, "the string encoded until the source sends one"},
    {"widget", "ecc", 'w', 0, 0, QRW, "L|M|Q|H: error correction (7, 15, 25, 30 % of the code; default M)"},
    {"widget", "quiet", 'i', 0, 16, QRW, "modules of white around the code (default 4, the standard's)"},
    {"widget", "topic", 't', 1, KIOSK_TOPIC_MAX - 1, BTNW, "a tap publishes to this topic (needs mqtt)"},
    {"widget", "payload", 't', 0, KIOSK_PAYLOAD_MAX - 1, BTNW, "the message published (default: empty)"},
    {"widget", "qos", 'i', 0, 2, BTNW, "quality of service of the message"},
    {"widget", "retain", 'i', 0, 1, BTNW, "the broker keeps the message for later subscribers"},
    {"widget", "page", 't', 1, KIOSK_NAME_MAX - 1, BTNW, "a tap goes to this page (a name, next or prev)"},
    {"directive", "page", 't', 0, 0, 0, "NAME key=value...: the widgets after it are on this page (keys: scope page; up to 16)"},
    {"page", "dwell", 'i', 0, 86400, 0, "seconds the carousel shows this page (0: the carousel's dwell)"},
    {"page", "grid", 'p', 1, 16, 0, "CxR cells of this page (default: the grid directive's)"},
    {"directive", "carousel", 't', 0, 0, 0, "key=value...: the pages turn by themselves (keys: scope carousel)"},
    {"carousel", "dwell", 'i', 0, 86400, 0, "seconds each page shows (0: no carousel)"},
    {"directive", "touch", 't', 0, 0, 0, "key=value...: swipes and edge taps turn pages (keys: scope touch)"},
    {"touch", "swipe", 'i', 0, 8192, 0, "pixels a finger must travel sideways for a swipe (0: no swipes; default 40)"},
    {"touch", "edge", 'i', 0, 50, 0, "percent of the width at each side where a tap turns the page (0: none; default 10)"},
    {"mqtt", "host", 't', 1, KIOSK_HOST_MAX - 1, 0, "broker name or address"},
    {"mqtt", "port", 'i', 1, 65535, 0, "broker port (1883; 8883 with TLS)"},
    {"mqtt", "client", 't', 1, 63, 0, "client id (default fixel-kiosk-HOST-PID)"},
    {"mqtt", "keepalive", 'i', 5, 3600, 0, "seconds between pings"},
    {"mqtt", "session", 'w', 0, 0, 0, "clean|persistent (persistent: the broker keeps QoS 1/2 messages)"},
    {"mqtt", "prefix", 't', 1, KIOSK_TOPIC_MAX - 1, 0, "control and status topics live below it"},
    {"mqtt", "backoff", 'i', 1, 300, 0, "first reconnect delay, seconds"},
    {"mqtt", "backoff_max", 'i', 1, 3600, 0, "longest reconnect delay, seconds"},
    {"mqtt", "auth", 'f', 1, KIOSK_PATH_MAX - 1, 0, "file: user line, password line"},
    {"mqtt", "status", 'i', 1, 3600, 0, "seconds between status publications"},
    {"mqtt_tls", "ca", 'f', 1, KIOSK_PATH_MAX - 1, 0, "CA certificate file (PEM)"},
    {"mqtt_tls", "cert", 'f', 1, KIOSK_PATH_MAX - 1, 0, "client certificate (PEM)"},
    {"mqtt_tls", "key", 'f', 1, KIOSK_PATH_MAX - 1, 0, "client key (PEM)"},
    {"mqtt_tls", "verify", 'i', 0, 1, 0, "check the broker's name against its certificate"},
    {"subscribe", "TOPIC", 't', 1, KIOSK_TOPIC_MAX - 1, 0, "topic filter (+ and # wildcards)"},
    {"subscribe", "qos", 'i', 0, 2, 0, "quality of service"},
    {"subscribe", "source", 't', 1, KIOSK_NAME_MAX - 1, 0, "the payload feeds this source (else: data lines)"},
    {"subscribe", "json", 't', 1, KIOSK_JPATH_MAX - 1, 0, "take this field of a JSON payload (a.b[2].c)"},
    {"screen", "backlight", 't', 1, 63, 0, "auto (the first found, none is fine: HDMI), none, or a device name"},
    {"screen", "sysfs", 'f', 1, KIOSK_PATH_MAX - 1, 0, "backlight class directory (/sys/class/backlight)"},
    {"screen", "brightness", 'i', 0, 100, 0, "percent set at start (default: leave it)"},
    {"screen", "idle", 'i', 0, 1440, 0, "minutes without input before the screen goes dark (0: never)"},
    {"directive", "schedule", 't', 0, 0, 0, "key=value...: when the screen is on (keys: scope schedule; up to 8 lines)"},
    {"directive", "output", 't', 1, KIOSK_OUTPUT_MAX - 1, 0,
     "NAME key=value...: one screen's section, up to 4 (keys: scope output); grid, title, widgets below are its"},
    {"output", "NAME", 't', 1, KIOSK_OUTPUT_MAX - 1, 0, "the connector (HDMI-A-1, DSI-1...), on any card"},
    {"output", "rotation", 'w', 0, 0, 0, "0|90|180|270 (default: FIXEL_ROTATION, else the panel's orientation)"},
    {"output", "size", 'p', 16, 8192, 0, "WxH pixels of a memory display (headless, FIXEL_BACKEND=memory)"},
    {"schedule", "on", 't', 1, 5, 0, "HH:MM the screen comes on"},
    {"schedule", "off", 't', 1, 5, 0, "HH:MM it goes off (before on: the next day)"},
    {"schedule", "days", 't', 3, 27, 0, "mon..sun, lists and ranges: mon-fri, sat,sun (default: every day)"},
    {"data", "VALUE", 'm', -VMAX, VMAX, 0, "name=value, name,value or CSV: every number"},
    {0, 0, 0, 0, 0, 0, 0},
};

const kiosk_key *kiosk_key_find(const char *scope, const char *name, size_t n)
{
    for (const kiosk_key *q = kiosk_keys; q->name; q++)
        if (!strcmp(q->scope, scope) && strlen(q->name) == n && !memcmp(q->name, name, n)) return q;
    return NULL;
}

/* "KEY=VALUE: expected MIN..MAX" into k->msg (no stdio in this file). */
static const char *range_msg(kiosk_config *k, const kiosk_key *q, tok val)
{
    char *o = k->msg, *e = k->msg + sizeof k->msg - 1;
    const char *parts[3] = {q->name, "=", NULL};
    for (int i = 0; parts[i] && i < 2; i++)
        for (const char *c = parts[i]; *c && o < e; c++) *o++ = *c;
    for (size_t i = 0; i < val.n && i < 24 && o < e; i++)
        *o++ = (unsigned char)val.s[i] < 0x20 || val.s[i] == 0x7f ? '?' : val.s[i];
    for (const char *c = ": expected "; *c && o < e; c++) *o++ = *c;
    char num[64];
    for (int b = 0; b < 2; b++) {
        int64_t v = b ? q->max : q->min;
        int d = q->type == 'm' ? 3 : 0;
        if (q->type == 'm') kiosk_format_milli(num, sizeof num, v, 3);
        else {
            uint64_t u = v < 0 ? 0 - (uint64_t)v : (uint64_t)v;
            int n = 0;
            char rev[24];
            do { rev[n++] = (char)('0' + u % 10); u /= 10; } while (u);
            int k2 = 0;
            if (v < 0) num[k2++] = '-';
            while (n) num[k2++] = rev[--n];
            num[k2] = 0;
        }
        /* drop a fraction of zeros */
        size_t L = strlen(num);
        if (d && L > 4 && !strcmp(num + L - 4, ".000")) num[L - 4] = 0;
        if (b) for (const char *c = ".."; *c && o < e; c++) *o++ = *c;
        for (const char *c = num; *c && o < e; c++) *o++ = *c;
    }
    if (q->type == 'p') for (const char *c = " each"; *c && o < e; c++) *o++ = *c;
    *o = 0;
    return k->msg;
}

static const char *const type_names[KIOSK_NTYPES] = {"number", "gauge", "bar", "spark", "text",
                                                      "clock",  "heat",  "image", "qr", "button"};

/* A path: printable, no quotes (one pair around it is stripped). */
static int parse_path(tok t, char *dst)
{
    if (t.n >= 2 && t.s[0] == '"' && t.s[t.n - 1] == '"') { t.s++; t.n -= 2; }
    if (t.n == 0 || t.n >= KIOSK_PATH_MAX) return -1;
    for (size_t i = 0; i < t.n; i++)
        if ((unsigned char)t.s[i] < 0x20 || t.s[i] == 0x7f || t.s[i] == '"') return -1;
    copy_str(dst, KIOSK_PATH_MAX, t.s, t.n);
    return 0;
}

static int parse_cmap(tok t, int *out)
{
    char name[16];
    if (t.n == 0 || t.n >= sizeof name) return -1;
    copy_str(name, sizeof name, t.s, t.n);
    fx_cmap m = fx_cmap_from_name(name);
    if (m == FX_CMAP_COUNT) return -1;
    *out = (int)m;
    return 0;
}

static int parse_header(kiosk_config *k, const char *l, size_t a, size_t b, int min_fields);
static int header_has_heat(const kiosk_config *k);

static int topic_ok(const char *s, size_t n, int filter);
static kiosk_page *cur_page(kiosk_config *k, const char *line, const char *at, int lineno);
static const char *parse_button_key(kiosk_config *k, kiosk_button *b, const kiosk_key *q, tok val, int iv,
                                    const char *line, int lineno);

static const char *parse_widget(kiosk_config *k, const char *line, const char *p, const char *end, int lineno)
{
    tok t;
    if (k->nwidgets >= KIOSK_MAX_WIDGETS) return "too many widgets";
    kiosk_widget *w = &k->widgets[k->nwidgets];
    memset(w, 0, sizeof *w);
    if (next_tok(&p, end, &t) != 1) return "widget needs a type";
    k->errat = t.s;
    int ty = -1;
    for (int i = 0; i < KIOSK_NTYPES; i++)
        if (tok_is(t, type_names[i])) ty = i;
    if (ty < 0) return "unknown widget type (number gauge bar spark text clock heat image qr button)";
    if (!cur_page(k, line, t.s, lineno)) return "too many pages (16)";
    w->type = (kiosk_type)ty;
    w->page = k->pg.npages - 1;
    w->button = -1;
    w->source = -1;
    w->w = w->h = 1;
    w->max = 100000;
    w->color = 0xFF4FC3F7u;
    if (w->type == KIOSK_SPARK) w->max = 0; /* automatic range */
    if (w->type == KIOSK_IMAGE) w->smooth = 1;
    if (w->type == KIOSK_HEAT) w->cmap = FX_CMAP_VIRIDIS;
    if (w->type == KIOSK_QR) w->qr_ecc = 1, w->qr_quiet = 4;
    int cw = 0, ch = 0;
    kiosk_button *btn = NULL;
    if (w->type == KIOSK_BUTTON) {
        /* a name, no source: it is the label unless label= says otherwise */
        if (next_tok(&p, end, &t) != 1) return "button needs a name";
        k->errat = t.s;
        for (size_t i = 0; i < t.n; i++)
            if (!is_name_char(t.s[i])) return "bad button name";
        if (t.n >= KIOSK_NAME_MAX) return "button name too long";
        if (k->pg.nbuttons >= KIOSK_MAX_BUTTONS) return "too many buttons (16)";
        w->button = k->pg.nbuttons;
        btn = &k->pg.buttons[w->button];
        memset(btn, 0, sizeof *btn);
        btn->page = KIOSK_PAGE_NONE;
        copy_str(w->label, KIOSK_TEXT_MAX, t.s, t.n);
        w->color = 0xFF26A69Au;
    } else if (w->type != KIOSK_CLOCK) {
        if (next_tok(&p, end, &t) != 1) return "widget needs a source name";
        k->errat = t.s;
        for (size_t i = 0; i < t.n; i++)
            if (!is_name_char(t.s[i])) return "bad source name";
        if (t.n >= KIOSK_NAME_MAX) return "source name too long";
        int s = find_source(k, t.s, t.n);
        if (s < 0) {
            if (k->nsources >= KIOSK_MAX_SOURCES) return "too many sources";
            s = k->nsources++;
            memset(&k->sources[s], 0, sizeof k->sources[s]);
            copy_str(k->sources[s].name, KIOSK_NAME_MAX, t.s, t.n);
        }
        w->source = s;
        copy_str(w->label, KIOSK_TEXT_MAX, t.s, t.n);
    }
    int r;
    while ((r = next_tok(&p, end, &t)) == 1) {
        size_t eq = 0;
        k->errat = t.s;
        while (eq < t.n && t.s[eq] != '=') eq++;
        if (eq == t.n) return "expected key=value";
        tok key = {t.s, eq}, val = {t.s + eq + 1, t.n - eq - 1};
        int bad;
        const kiosk_key *q = kiosk_key_find("widget", key.s, key.n);
        if (!q || !(q->widgets & (1u << w->type)))
            return "unknown widget key (col row w h decimals min max color label unit; heat: cells cmap smooth; "
                   "image: path filter; qr: text ecc quiet; button: topic payload qos retain page)";
        int64_t m = 0;
        int iv = 0;
        /* numbers: the type from the table, then the table's range */
        if (q->type == 'i' || q->type == 'm') {
            if (q->type == 'i') {
                if (parse_int(val, 0, 999999999, &iv)) return range_msg(k, q, val);
                m = iv;
            } else if (kiosk_parse_milli(val.s, val.n, &m)) {
                return range_msg(k, q, val);
            }
            if (m < q->min || m > q->max) return range_msg(k, q, val);
        }
        if (btn && (q->widgets & ALLW) == 0) {
            const char *e = parse_button_key(k, btn, q, val, iv, line, lineno);
            if (e) return e;
            bad = 0;
        } else if (tok_is(key, "col")) bad = (w->col = iv, 0);
        else if (tok_is(key, "row")) bad = (w->row = iv, 0);
        else if (tok_is(key, "w")) bad = (w->w = iv, 0);
        else if (tok_is(key, "h")) bad = (w->h = iv, 0);
        else if (tok_is(key, "decimals")) bad = (w->decimals = iv, 0);
        else if (tok_is(key, "min")) bad = (w->min = m, 0);
        else if (tok_is(key, "max")) bad = (w->max = m, 0);
        else if (tok_is(key, "color")) bad = parse_color(val, &w->color);
        else if (tok_is(key, "label")) bad = parse_text(val, w->label);
        else if (tok_is(key, "unit")) bad = parse_text(val, w->unit);
        else if (tok_is(key, "cells")) {
            if (parse_pair(val, (int)q->min, (int)q->max, &cw, &ch)) return range_msg(k, q, val);
            bad = 0;
        } else if (tok_is(key, "cmap")) bad = parse_cmap(val, &w->cmap);
        else if (tok_is(key, "smooth")) bad = (w->smooth = iv, 0);
        else if (tok_is(key, "text")) bad = parse_text(val, w->qrtext);
        else if (tok_is(key, "quiet")) bad = (w->qr_quiet = iv, 0);
        else if (tok_is(key, "ecc"))
            bad = tok_is(val, "L") ? (w->qr_ecc = 0, 0) : tok_is(val, "M") ? (w->qr_ecc = 1, 0)
                : tok_is(val, "Q") ? (w->qr_ecc = 2, 0) : tok_is(val, "H") ? (w->qr_ecc = 3, 0) : -1;
        else if (tok_is(key, "filter"))
            bad = tok_is(val, "nearest") ? (w->smooth = 0, 0) : tok_is(val, "bilinear") ? (w->smooth = 1, 0) : -1;
        else bad = parse_path(val, k->sources[w->source].path);
        if (bad) return "bad widget value";
    }
    if (r < 0) return "unterminated quote";
    if (btn && !btn->topic[0] && btn->page == KIOSK_PAGE_NONE && !btn->pagename[0]) {
        k->errat = NULL;
        return "button needs topic= (a message to publish) or page= (a page to show)";
    }
    if (w->min > w->max || (w->min == w->max && w->type != KIOSK_SPARK && w->type != KIOSK_NUMBER &&
                            w->type != KIOSK_TEXT && w->type != KIOSK_CLOCK && w->type != KIOSK_IMAGE &&
                            w->type != KIOSK_QR))
        return "min must be below max";
    if (w->max - w->min > INT64_MAX / 4096) return "range too large";
    if (w->type == KIOSK_HEAT && (w->min < -2000000000 || w->max > 2000000000))
        return "heat min/max must lie within +-2000000";
    if (w->source >= 0) {
        kiosk_source *so = &k->sources[w->source];
        kiosk_kind want = w->type == KIOSK_HEAT ? KIOSK_KIND_HEAT : w->type == KIOSK_IMAGE ? KIOSK_KIND_IMAGE
                        : w->type == KIOSK_TEXT || w->type == KIOSK_QR ? KIOSK_KIND_TEXT : KIOSK_KIND_NUMBER;
        int shown = 0;
        for (int i = 0; i < k->nwidgets; i++) shown |= k->widgets[i].source == w->source;
        kiosk_kind have = shown ? so->kind : want;
        /* text widgets may show a number's text; any other mix has no common value */
        if (have != want && !((have == KIOSK_KIND_TEXT && want == KIOSK_KIND_NUMBER) ||
                              (have == KIOSK_KIND_NUMBER && want == KIOSK_KIND_TEXT)))
            return "source shown by widgets wanting different values (heat, image, other)";
        if (have == KIOSK_KIND_TEXT && want == KIOSK_KIND_NUMBER) have = want;
        so->kind = have;
        if (w->type == KIOSK_HEAT) {
            if (!cw) return "heat needs cells=CxR";
            if (cw * ch > KIOSK_HEAT_MAX) return "heat has too many cells";
            if (shown && (so->gw != cw || so->gh != ch)) return "heat widgets of one source need the same cells";
            so->gw = cw;
            so->gh = ch;
            for (int i = 0; i < KIOSK_HEAT_MAX; i++) so->cells[i] = KIOSK_CELL_NONE;
        }
    }
    if (btn) k->pg.nbuttons++;
    k->nwidgets++;
    return NULL;
}

/* ---- MQTT directives ---- */

/* A topic: printable, no spaces or quotes; with wildcards (a filter) '+'
 * fills a whole level and '#' is the whole last one. */
static int topic_ok(const char *s, size_t n, int filter)
{
    if (n == 0 || n >= KIOSK_TOPIC_MAX) return 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c <= 0x20 || c == 0x7f || c == '"') return 0;
        if (c == '+' || c == '#') {
            if (!filter) return 0;
            if (i > 0 && s[i - 1] != '/') return 0;
            if (c == '+' && i + 1 < n && s[i + 1] != '/') return 0;
            if (c == '#' && i + 1 != n) return 0;
        }
    }
    return 1;
}

int kiosk_jpath_steps(const char *path, kiosk_jstep *st, int max)
{
    int n = 0;
    const char *p = path;
    while (*p) {
        if (n == max) return -1;
        if (*p == '[') {
            int v = 0, d = 0;
            for (p++; *p >= '0' && *p <= '9' && d < 6; p++, d++) v = v * 10 + (*p - '0');
            if (!d || *p != ']') return -1;
            p++;
            st[n].name = NULL;
            st[n].len = 0;
            st[n++].index = v;
        } else {
            if (n && *p != '.') return -1;
            if (*p == '.') p++;
            const char *a = p;
            while ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
                   *p == '_' || *p == '-')
                p++;
            if (p == a) return -1;
            st[n].name = a;
            st[n].len = (size_t)(p - a);
            st[n++].index = -1;
        }
    }
    return n;
}

/* "key=value" of scope; fills *q, *val and, for integers, *iv. NULL or the
 * error (with k->errat on the token). */
static const char *kv_parse(kiosk_config *k, const char *scope, tok t, const kiosk_key **qq, tok *val, int *iv)
{
    size_t eq = 0;
    k->errat = t.s;
    while (eq < t.n && t.s[eq] != '=') eq++;
    if (eq == t.n) return "expected key=value";
    const kiosk_key *q = kiosk_key_find(scope, t.s, eq);
    *val = (tok){t.s + eq + 1, t.n - eq - 1};
    *qq = q;
    if (!q || q->name[0] < 'a') return NULL; /* the caller names the keys */
    if (q->type == 'i') {
        if (parse_int(*val, (int)q->min, (int)q->max, iv)) return range_msg(k, q, *val);
    } else if (q->type == 't' || q->type == 'f') {
        tok v = *val;
        if (v.n >= 2 && v.s[0] == '"' && v.s[v.n - 1] == '"') { v.s++; v.n -= 2; }
        if (v.n < (size_t)q->min || v.n > (size_t)q->max) return range_msg(k, q, *val);
        for (size_t i = 0; i < v.n; i++)
            if ((unsigned char)v.s[i] < 0x20 || v.s[i] == 0x7f || v.s[i] == '"') return "control character or quote in value";
        *val = v;
    }
    return NULL;
}

static void kv_copy(char *dst, size_t size, tok v) { copy_str(dst, size, v.s, v.n); }

static const char *parse_mqtt(kiosk_config *k, const char *p, const char *end)
{
    kiosk_mqtt_cfg *m = &k->mqtt;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    if (m->enabled) { k->errat = NULL; return "a second mqtt directive (one broker per kiosk)"; }
    m->enabled = 1;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "mqtt", t, &q, &v, &iv);
        if (e) return e;
        if (!q) return "unknown mqtt key (host port client keepalive session prefix backoff backoff_max auth status)";
        if (!strcmp(q->name, "host")) {
            for (size_t i = 0; i < v.n; i++)
                if (!is_name_char(v.s[i]) && v.s[i] != ':') return "host: letters, digits, . - : only";
            kv_copy(m->host, sizeof m->host, v);
        } else if (!strcmp(q->name, "port")) m->port = iv;
        else if (!strcmp(q->name, "client")) kv_copy(m->client, sizeof m->client, v);
        else if (!strcmp(q->name, "keepalive")) m->keepalive = iv;
        else if (!strcmp(q->name, "session")) {
            if (tok_is(v, "clean")) m->persistent = 0;
            else if (tok_is(v, "persistent")) m->persistent = 1;
            else return "session=: expected clean or persistent";
        } else if (!strcmp(q->name, "prefix")) {
            if (!topic_ok(v.s, v.n, 0) || v.s[v.n - 1] == '/') return "prefix: a topic without wildcards, spaces or a final /";
            kv_copy(m->prefix, sizeof m->prefix, v);
        } else if (!strcmp(q->name, "backoff")) m->backoff_min = iv;
        else if (!strcmp(q->name, "backoff_max")) m->backoff_max = iv;
        else if (!strcmp(q->name, "auth")) kv_copy(m->auth, sizeof m->auth, v);
        else m->status_s = iv;
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    if (!m->host[0]) return "mqtt needs host=";
    if (m->backoff_max < m->backoff_min) return "backoff_max must not be below backoff";
    return NULL;
}

static const char *parse_screen(kiosk_config *k, const char *p, const char *end)
{
    kiosk_screen_cfg *c = &k->screen;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "screen", t, &q, &v, &iv);
        if (e) return e;
        if (!q) return "unknown screen key (backlight sysfs brightness idle)";
        if (!strcmp(q->name, "backlight")) {
            for (size_t i = 0; i < v.n; i++)
                if ((!is_name_char(v.s[i]) && v.s[i] != ':') || v.s[i] == '/') return "backlight: a device name (letters, digits, . - _ :)";
            kv_copy(c->backlight, sizeof c->backlight, v);
        } else if (!strcmp(q->name, "sysfs")) kv_copy(c->sysfs, sizeof c->sysfs, v);
        else if (!strcmp(q->name, "idle")) c->idle_min = iv;
        else c->brightness = iv;
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    return NULL;
}

/* "output NAME key=value...": a new screen section; grid, size and title
 * set before the first one are its defaults. */
static const char *parse_output(kiosk_config *k, const char *p, const char *end, int line)
{
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    if (next_tok(&p, end, &t) != 1) { k->errat = NULL; return "output needs a connector name (HDMI-A-1, DSI-1...)"; }
    k->errat = t.s;
    q = kiosk_key_find("output", "NAME", 4);
    if (t.n > (size_t)q->max) return range_msg(k, q, t);
    for (size_t i = 0; i < t.n; i++)
        if (!is_name_char(t.s[i]) || t.s[i] == '/') return "output: a connector name (letters, digits, - _ .)";
    for (int i = 0; i < k->noutputs; i++)
        if (strlen(k->outputs[i].name) == t.n && !memcmp(k->outputs[i].name, t.s, t.n)) {
            /* the line of the first, in the message (no stdio here) */
            static const char pre[] = "output named twice (first on line ";
            char *o = k->msg, *e = k->msg + sizeof k->msg - 2;
            for (const char *c = pre; *c && o < e; c++) *o++ = *c;
            char num[12];
            int n = 0, l = k->outputs[i].line;
            do { num[n++] = (char)('0' + l % 10); l /= 10; } while (l && n < 11);
            while (n && o < e) *o++ = num[--n];
            *o++ = ')';
            *o = 0;
            return k->msg;
        }
    if (k->noutputs >= KIOSK_MAX_OUTPUTS) return "more than 4 outputs";
    kiosk_output *s = &k->outputs[k->noutputs];
    memset(s, 0, sizeof *s);
    copy_str(s->name, sizeof s->name, t.s, t.n);
    s->rotation = -1;
    s->cols = k->cols;
    s->rows = k->rows;
    s->width = k->width;
    s->height = k->height;
    memcpy(s->title, k->title, sizeof s->title);
    s->line = line;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "output", t, &q, &v, &iv);
        if (e) return e;
        if (!q || q->name[0] < 'a') return "unknown output key (rotation size)";
        if (!strcmp(q->name, "rotation")) {
            static const char *const deg[] = {"0", "90", "180", "270"};
            s->rotation = -1;
            for (int i = 0; i < 4; i++)
                if (tok_is(v, deg[i])) s->rotation = 90 * i;
            if (s->rotation < 0) return "rotation: 0, 90, 180 or 270";
        } else if (parse_pair(v, (int)q->min, (int)q->max, &s->width, &s->height))
            return range_msg(k, q, v);
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    k->noutputs++;
    return NULL;
}

/* Directives for the whole kiosk: before the first output section, so
 * that nobody reads one inside a section as that screen's. */
static int kiosk_wide(tok t)
{
    static const char *const w[] = {"mqtt", "mqtt_tls", "subscribe", "screen", "schedule", "stale",
                                    "history", "columns", "bg", "panel", "fg"};
    for (size_t i = 0; i < sizeof w / sizeof w[0]; i++)
        if (tok_is(t, w[i])) return 1;
    return 0;
}

/* "7:05" or "07:05" into minutes after midnight; -1 when not a time. */
static int parse_hhmm(tok v)
{
    size_t c = 0;
    while (c < v.n && v.s[c] != ':') c++;
    if (c < 1 || c > 2 || v.n - c != 3) return -1;
    int h = 0, m = 0;
    for (size_t i = 0; i < v.n; i++) {
        if (i == c) continue;
        if (v.s[i] < '0' || v.s[i] > '9') return -1;
        if (i < c) h = h * 10 + (v.s[i] - '0');
        else m = m * 10 + (v.s[i] - '0');
    }
    return h > 23 || m > 59 ? -1 : h * 60 + m;
}

static int day_index(const char *s)
{
    static const char days[7][4] = {"mon", "tue", "wed", "thu", "fri", "sat", "sun"};
    for (int i = 0; i < 7; i++)
        if (!memcmp(s, days[i], 3)) return i;
    return -1;
}

/* "mon-fri", "sat,sun", "mon,wed-fri", "fri-mon" (wraps) into a mask. */
static int parse_days(tok v, unsigned *mask)
{
    *mask = 0;
    size_t i = 0;
    while (i < v.n) {
        if (v.n - i < 3) return -1;
        int a = day_index(v.s + i), b = a;
        i += 3;
        if (i < v.n && v.s[i] == '-') {
            if (v.n - i < 4) return -1;
            b = day_index(v.s + i + 1);
            i += 4;
        }
        if (a < 0 || b < 0) return -1;
        for (int d = a;; d = (d + 1) % 7) {
            *mask |= 1u << d;
            if (d == b) break;
        }
        if (i < v.n && v.s[i++] != ',') return -1;
        if (i == v.n && v.s[i - 1] == ',') return -1;
    }
    return 0;
}

static const char *parse_schedule(kiosk_config *k, const char *p, const char *end)
{
    kiosk_screen_cfg *c = &k->screen;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    if (c->nsched >= KIOSK_SCHED_MAX) { k->errat = NULL; return "more than 8 schedule lines"; }
    kiosk_sched *s = &c->sched[c->nsched];
    s->on_min = s->off_min = -1;
    s->days = 0x7f;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "schedule", t, &q, &v, &iv);
        if (e) return e;
        if (!q) return "unknown schedule key (on off days)";
        if (!strcmp(q->name, "days")) {
            if (parse_days(v, &s->days)) return "days: mon tue wed thu fri sat sun, lists and ranges (mon-fri,sun)";
        } else {
            int m = parse_hhmm(v);
            if (m < 0) return !strcmp(q->name, "on") ? "on: expected HH:MM, 00:00..23:59" : "off: expected HH:MM, 00:00..23:59";
            if (!strcmp(q->name, "on")) s->on_min = m;
            else s->off_min = m;
        }
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    if (s->on_min < 0 || s->off_min < 0) return "schedule needs on= and off=";
    if (s->on_min == s->off_min) return "schedule: on= and off= are the same time";
    c->nsched++;
    return NULL;
}

static const char *parse_mqtt_tls(kiosk_config *k, const char *p, const char *end)
{
    kiosk_mqtt_cfg *m = &k->mqtt;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    m->tls = 1;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "mqtt_tls", t, &q, &v, &iv);
        if (e) return e;
        if (!q) return "unknown mqtt_tls key (ca cert key verify)";
        if (!strcmp(q->name, "ca")) kv_copy(m->ca, sizeof m->ca, v);
        else if (!strcmp(q->name, "cert")) kv_copy(m->cert, sizeof m->cert, v);
        else if (!strcmp(q->name, "key")) kv_copy(m->key, sizeof m->key, v);
        else m->verify = iv;
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    if (!m->ca[0]) return "mqtt_tls needs ca=";
    if (!m->cert[0] != !m->key[0]) return "mqtt_tls: cert= and key= go together";
    return NULL;
}

static const char *parse_subscribe(kiosk_config *k, const char *line, const char *p, const char *end, int lineno)
{
    kiosk_mqtt_cfg *m = &k->mqtt;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    if (next_tok(&p, end, &t) != 1) { k->errat = NULL; return "subscribe needs a topic"; }
    k->errat = t.s;
    if (m->nsubs >= KIOSK_MQTT_SUBS) return "too many subscriptions (16)";
    if (t.n >= KIOSK_TOPIC_MAX) return range_msg(k, kiosk_key_find("subscribe", "TOPIC", 5), t);
    if (!topic_ok(t.s, t.n, 1)) return "bad topic filter (no spaces; + a whole level, # the whole last one)";
    kiosk_sub *s = &m->subs[m->nsubs];
    memset(s, 0, sizeof *s);
    s->source = -1;
    s->line = lineno;
    s->col = (int)(t.s - line) + 1;
    copy_str(s->topic, sizeof s->topic, t.s, t.n);
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "subscribe", t, &q, &v, &iv);
        if (e) return e;
        if (!q || q->name[0] < 'a') return "unknown subscribe key (qos source json)";
        if (!strcmp(q->name, "qos")) s->qos = iv;
        else if (!strcmp(q->name, "source")) {
            for (size_t i = 0; i < v.n; i++)
                if (!is_name_char(v.s[i])) return "bad source name";
            kv_copy(s->srcname, sizeof s->srcname, v);
            s->col = (int)(t.s - line) + 1;
        } else {
            kiosk_jstep st[KIOSK_JPATH_DEPTH];
            kv_copy(s->json, sizeof s->json, v);
            if (kiosk_jpath_steps(s->json, st, KIOSK_JPATH_DEPTH) <= 0)
                return "json=: a path like a.b[2].c (names of letters, digits, _ -; up to 16 steps)";
        }
    }
    if (r < 0) return "unterminated quote";
    if (s->json[0] && !s->srcname[0]) { k->errat = NULL; return "json= needs source="; }
    m->nsubs++;
    return NULL;
}

/* ---- pages, carousel, touch, buttons (kiosk_pages.h) ---- */

static int page_name_ok(tok t)
{
    if (t.n == 0 || t.n >= KIOSK_NAME_MAX || !((t.s[0] >= 'a' && t.s[0] <= 'z') || (t.s[0] >= 'A' && t.s[0] <= 'Z') ||
                                               t.s[0] == '_'))
        return 0;
    for (size_t i = 0; i < t.n; i++)
        if (!is_name_char(t.s[i]) || t.s[i] == '/') return 0;
    /* next and prev are the words that turn pages */
    return !tok_is(t, "next") && !tok_is(t, "prev");
}

/* The page a widget goes on: the last "page" line's, else an implicit
 * first page "main" (a config without page lines is one page, as before). */
static kiosk_page *cur_page(kiosk_config *k, const char *line, const char *at, int lineno)
{
    kiosk_pages_cfg *c = &k->pg;
    if (c->npages == 0) {
        kiosk_page *pg = &c->pages[c->npages++];
        memset(pg, 0, sizeof *pg);
        strcpy(pg->name, "main");
        pg->line = lineno;
        pg->col = (int)(at - line) + 1;
    }
    return &c->pages[c->npages - 1];
}

static const char *parse_page(kiosk_config *k, const char *line, const char *p, const char *end, int lineno)
{
    kiosk_pages_cfg *c = &k->pg;
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    if (next_tok(&p, end, &t) != 1) { k->errat = NULL; return "page needs a name"; }
    k->errat = t.s;
    if (!page_name_ok(t)) return "page name: a letter or _, then letters, digits, _ . - (not next or prev; up to 31)";
    for (int i = 0; i < c->npages; i++)
        if (tok_is(t, c->pages[i].name)) return "a second page of that name";
    if (c->npages >= KIOSK_MAX_PAGES) return "too many pages (16)";
    kiosk_page *pg = &c->pages[c->npages];
    memset(pg, 0, sizeof *pg);
    copy_str(pg->name, sizeof pg->name, t.s, t.n);
    pg->line = lineno;
    pg->col = (int)(t.s - line) + 1;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, "page", t, &q, &v, &iv);
        if (e) return e;
        if (!q) return "unknown page key (dwell grid)";
        if (!strcmp(q->name, "dwell")) pg->dwell_s = iv;
        else if (parse_pair(v, (int)q->min, (int)q->max, &pg->cols, &pg->rows)) return range_msg(k, q, v);
    }
    if (r < 0) return "unterminated quote";
    c->npages++;
    k->errat = NULL;
    return NULL;
}

/* "carousel key=value..." and "touch key=value...": integers only. */
static const char *parse_turning(kiosk_config *k, const char *scope, const char *p, const char *end)
{
    tok t, v;
    const kiosk_key *q;
    int iv = 0, r;
    while ((r = next_tok(&p, end, &t)) == 1) {
        const char *e = kv_parse(k, scope, t, &q, &v, &iv);
        if (e) return e;
        if (!q) return scope[0] == 'c' ? "unknown carousel key (dwell)" : "unknown touch key (swipe edge)";
        if (!strcmp(q->name, "dwell")) k->pg.dwell_s = iv;
        else if (!strcmp(q->name, "swipe")) k->pg.swipe_px = iv;
        else k->pg.edge_pct = iv;
    }
    if (r < 0) return "unterminated quote";
    k->errat = NULL;
    return NULL;
}

/* A payload: printable bytes; one pair of quotes around it is stripped
 * when there are none inside, so payload={"state":"ON"} is JSON as written. */
static int parse_payload(tok t, char *dst)
{
    if (t.n >= 2 && t.s[0] == '"' && t.s[t.n - 1] == '"' && !memchr(t.s + 1, '"', t.n - 2)) { t.s++; t.n -= 2; }
    if (t.n >= KIOSK_PAYLOAD_MAX) return -1;
    for (size_t i = 0; i < t.n; i++)
        if ((unsigned char)t.s[i] < 0x20 || t.s[i] == 0x7f) return -1;
    copy_str(dst, KIOSK_PAYLOAD_MAX, t.s, t.n);
    return 0;
}

static const char *parse_button_key(kiosk_config *k, kiosk_button *b, const kiosk_key *q, tok val, int iv,
                                    const char *line, int lineno)
{
    if (!strcmp(q->name, "qos")) b->qos = iv;
    else if (!strcmp(q->name, "retain")) b->retain = iv;
    else if (!strcmp(q->name, "payload")) {
        if (parse_payload(val, b->payload)) return range_msg(k, q, val);
    } else {
        tok v = val;
        if (v.n >= 2 && v.s[0] == '"' && v.s[v.n - 1] == '"') { v.s++; v.n -= 2; }
        if (!strcmp(q->name, "topic")) {
            if (v.n < 1 || v.n >= KIOSK_TOPIC_MAX) return range_msg(k, q, val);
            if (!topic_ok(v.s, v.n, 0)) return "topic=: a topic without wildcards, spaces or quotes";
            copy_str(b->topic, sizeof b->topic, v.s, v.n);
        } else {
            if (v.n < 1 || v.n >= KIOSK_NAME_MAX) return range_msg(k, q, val);
            if (!page_name_ok(v) && !tok_is(v, "next") && !tok_is(v, "prev")) return "page=: a page name, next or prev";
            copy_str(b->pagename, sizeof b->pagename, v.s, v.n);
        }
        /* checked after the whole file (the mqtt line or the page may come later) */
        b->line = lineno;
        b->col = (int)(k->errat - line) + 1;
    }
    return NULL;
}

/* After the whole file: every page has widgets and a grid, button pages
 * exist, a button that publishes has a broker. NULL or the error, its
 * place in k->errline/errcol. */
static const char *check_pages(kiosk_config *k)
{
    kiosk_pages_cfg *c = &k->pg;
    if (c->npages == 0) {
        c->npages = 1;
        memset(&c->pages[0], 0, sizeof c->pages[0]);
        strcpy(c->pages[0].name, "main");
    }
    for (int i = 0; i < c->npages; i++) {
        kiosk_page *pg = &c->pages[i];
        int n = 0;
        if (!pg->cols) { pg->cols = k->cols; pg->rows = k->rows; }
        for (int j = 0; j < k->nwidgets; j++) n += k->widgets[j].page == i;
        if (!n && (c->npages > 1 || pg->line)) {
            k->errline = pg->line;
            k->errcol = pg->col;
            return "a page without widgets";
        }
    }
    for (int i = 0; i < c->nbuttons; i++) {
        kiosk_button *b = &c->buttons[i];
        k->errline = b->line;
        k->errcol = b->col;
        if (b->topic[0] && !k->mqtt.enabled)
            return "topic= needs an mqtt directive (the broker to publish to)";
        if (b->pagename[0]) {
            b->page = !strcmp(b->pagename, "next") ? KIOSK_PAGE_NEXT : !strcmp(b->pagename, "prev") ? KIOSK_PAGE_PREV
                    : KIOSK_PAGE_NONE;
            for (int j = 0; j < c->npages && b->page == KIOSK_PAGE_NONE; j++)
                if (!strcmp(c->pages[j].name, b->pagename)) b->page = j;
            if (b->page == KIOSK_PAGE_NONE) return "page=: no page of that name";
        }
    }
    k->errline = k->errcol = 0;
    return NULL;
}

int kiosk_config_parse(kiosk_config *k, const char *buf, size_t len, char *err, size_t errsize)
{
    const char *p = buf, *end = buf + len;
    int line = 0, saw_pages = 0; /* page, carousel or touch lines (not with output sections yet) */
    memset(k, 0, sizeof *k);
    k->cols = k->rows = 2;
    k->stale_ms = 10000;
    k->history = 120;
    k->bg = 0xFF0E1116u;
    k->panel = 0xFF1B222Bu;
    k->fg = 0xFFE8EAEDu;
    k->mqtt.port = 1883;
    k->mqtt.keepalive = 30;
    k->mqtt.backoff_min = 1;
    k->mqtt.backoff_max = 60;
    k->mqtt.status_s = 30;
    k->mqtt.verify = 1;
    strcpy(k->screen.backlight, "auto");
    k->screen.brightness = -1;
    k->pg.swipe_px = 40;
    k->pg.edge_pct = 10;
    if (err && errsize) err[0] = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        line++;
        const char *q = p, *msg = NULL;
        k->errat = NULL;
        tok t;
        while (q < eol && is_space(*q)) q++;
        int r = q < eol && *q == '#' ? 0 : next_tok(&q, eol, &t);
        for (const char *c = p; c < eol; c++)
            if (*c == 0) { r = -1; break; }
        if (r < 0) msg = "unreadable line";
        else if (r == 0) msg = NULL;
        else if (tok_is(t, "output")) {
            if (k->nwidgets && !k->noutputs) { k->errat = t.s; msg = "output after widgets: with output sections every widget goes in one"; }
            else if (saw_pages) {
                k->errat = t.s;
                msg = "output sections and pages (page, carousel, touch) do not go together yet";
            } else msg = parse_output(k, q, eol, line);
        } else if (k->noutputs && kiosk_wide(t)) {
            k->errat = t.s;
            msg = "this directive is for the whole kiosk: put it before the first output";
        } else if (k->noutputs && (tok_is(t, "page") || tok_is(t, "carousel") || tok_is(t, "touch"))) {
            k->errat = t.s;
            msg = "output sections and pages (page, carousel, touch) do not go together yet";
        } else if (tok_is(t, "widget")) {
            msg = parse_widget(k, p, q, eol, line);
            if (!msg) {
                /* the grid check below needs the section's grid, and says where */
                kiosk_widget *w = &k->widgets[k->nwidgets - 1];
                w->screen = k->noutputs ? k->noutputs - 1 : 0;
                w->line = line;
                if (w->screen > 0 && w->type == KIOSK_BUTTON) {
                    k->errat = t.s;
                    msg = "button widgets go on the first output (the one touch belongs to)";
                }
            }
        }
        else if (tok_is(t, "page")) msg = parse_page(k, p, q, eol, line), saw_pages = 1;
        else if (tok_is(t, "carousel") || tok_is(t, "touch"))
            msg = parse_turning(k, t.s[0] == 'c' ? "carousel" : "touch", q, eol), saw_pages = 1;
        else if (tok_is(t, "mqtt")) msg = parse_mqtt(k, q, eol);
        else if (tok_is(t, "mqtt_tls")) msg = parse_mqtt_tls(k, q, eol);
        else if (tok_is(t, "screen")) msg = parse_screen(k, q, eol);
        else if (tok_is(t, "schedule")) msg = parse_schedule(k, q, eol);
        else if (tok_is(t, "subscribe")) msg = parse_subscribe(k, p, q, eol, line);
        else if (!kiosk_key_find("directive", t.s, t.n)) msg = UNKNOWN_DIRECTIVE; /* the table decides */
        else {
            tok v;
            int rv = next_tok(&q, eol, &v);
            tok extra;
            k->errat = rv == 1 ? v.s : NULL;
            if (rv != 1) msg = "missing value";
            else if (tok_is(t, "title")) {
                /* the rest of the line, so titles need no quotes */
                const char *e = eol;
                while (e > v.s && is_space(e[-1])) e--;
                if (parse_text((tok){v.s, (size_t)(e - v.s)}, k->noutputs ? k->outputs[k->noutputs - 1].title : k->title))
                    msg = "bad title";
                q = eol;
            } else if (tok_is(t, "grid") || tok_is(t, "size")) {
                const kiosk_key *kq = kiosk_key_find("directive", t.s, t.n);
                int *a = tok_is(t, "grid") ? &k->cols : &k->width, *b = tok_is(t, "grid") ? &k->rows : &k->height;
                if (k->noutputs) { /* a section's own */
                    kiosk_output *o = &k->outputs[k->noutputs - 1];
                    a = tok_is(t, "grid") ? &o->cols : &o->width;
                    b = tok_is(t, "grid") ? &o->rows : &o->height;
                }
                msg = parse_pair(v, (int)kq->min, (int)kq->max, a, b) ? range_msg(k, kq, v) : NULL;
            } else if (tok_is(t, "stale")) {
                const kiosk_key *kq = kiosk_key_find("directive", "stale", 5);
                int64_t ms;
                if (kiosk_parse_milli(v.s, v.n, &ms) || ms < kq->min || ms > kq->max) msg = range_msg(k, kq, v);
                else k->stale_ms = (int)(ms > 2000000000 ? 2000000000 : ms);
            } else if (tok_is(t, "history")) {
                const kiosk_key *kq = kiosk_key_find("directive", "history", 7);
                msg = parse_int(v, (int)kq->min, (int)kq->max, &k->history) ? range_msg(k, kq, v) : NULL;
            }
            else if (tok_is(t, "bg")) msg = parse_color(v, &k->bg) ? "bad colour (#rrggbb)" : NULL;
            else if (tok_is(t, "panel")) msg = parse_color(v, &k->panel) ? "bad colour (#rrggbb)" : NULL;
            else if (tok_is(t, "fg")) msg = parse_color(v, &k->fg) ? "bad colour (#rrggbb)" : NULL;
            else if (tok_is(t, "columns"))
                msg = parse_header(k, v.s, 0, v.n, 2) ? "columns wants name,name,... (up to 32, no heat sources)" : NULL;
            else { k->errat = t.s; msg = UNKNOWN_DIRECTIVE; }
            if (!msg && next_tok(&q, eol, &extra) != 0) { k->errat = extra.s; msg = "extra text after value"; }
        }
        if (msg) {
            k->errline = line;
            k->errcol = k->errat && k->errat >= p && k->errat <= eol ? (int)(k->errat - p) + 1 : 1;
            if (err && errsize) {
                /* no snprintf: this file stays free of stdio for the fuzzer */
                char num[16];
                int n = 0, v = line;
                do { num[n++] = (char)('0' + v % 10); v /= 10; } while (v && n < 15);
                size_t o = 0;
                const char *pre = "line ";
                for (const char *c = pre; *c && o + 1 < errsize; c++) err[o++] = *c;
                while (n > 0 && o + 1 < errsize) err[o++] = num[--n];
                for (const char *c = ": "; *c && o + 1 < errsize; c++) err[o++] = *c;
                for (const char *c = msg; *c && o + 1 < errsize; c++) err[o++] = *c;
                err[o] = 0;
            }
            return -1;
        }
        p = eol < end ? eol + 1 : end;
    }
    if (k->ncols && header_has_heat(k)) {
        const char *m = "columns names a heat source (heat maps take name=v1,v2,... lines)";
        size_t o = 0;
        for (; err && m[o] && o + 1 < errsize; o++) err[o] = m[o];
        if (err && errsize) err[o] = 0;
        return -1;
    }
    for (int i = 0; i < k->mqtt.nsubs; i++) {
        kiosk_sub *sb = &k->mqtt.subs[i];
        const char *m = NULL;
        if (!k->mqtt.enabled) m = "subscribe without an mqtt directive (host=...)";
        else if (sb->srcname[0] && (sb->source = find_source(k, sb->srcname, strlen(sb->srcname))) < 0)
            m = "source= names no widget's source";
        else if (sb->source >= 0 && k->sources[sb->source].kind == KIOSK_KIND_IMAGE && sb->json[0])
            m = "json= on an image source (paths come as plain payloads)";
        if (m) {
            size_t o = 0;
            k->errline = sb->line;
            k->errcol = sb->col;
            for (; err && m[o] && o + 1 < errsize; o++) err[o] = m[o];
            if (err && errsize) err[o] = 0;
            return -1;
        }
    }
    {
        const char *m = check_pages(k);
        if (m) {
            size_t o = 0;
            for (; err && m[o] && o + 1 < errsize; o++) err[o] = m[o];
            if (err && errsize) err[o] = 0;
            return -1;
        }
    }
    for (int i = 0; i < k->nwidgets; i++) {
        const kiosk_widget *w = &k->widgets[i];
        const kiosk_page *pg = &k->pg.pages[w->page];
        /* with output sections (no pages) the section's grid */
        int gc = k->noutputs ? k->outputs[w->screen].cols : pg->cols;
        int gr = k->noutputs ? k->outputs[w->screen].rows : pg->rows;
        if (w->col + w->w > gc || w->row + w->h > gr) {
            k->errline = w->line;
            k->errcol = 1;
            if (err && errsize) {
                const char *m = "a widget lies outside the grid";
                size_t o = 0;
                for (; m[o] && o + 1 < errsize; o++) err[o] = m[o];
                err[o] = 0;
            }
            return -1;
        }
    }
    return 0;
}

/* ---- data ---- */

static int is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

/* Split [a, b) at commas into at most max fields, spaces trimmed. Returns
 * the number of fields, or -1 when there are more than max. */
static int split_fields(const char *l, size_t a, size_t b, size_t *fs, size_t *fe, int max)
{
    int n = 0;
    for (size_t p = a;;) {
        size_t q = p;
        while (q < b && l[q] != ',') q++;
        if (n == max) return -1;
        size_t x = p, y = q;
        while (x < y && is_space(l[x])) x++;
        while (y > x && is_space(l[y - 1])) y--;
        fs[n] = x;
        fe[n] = y;
        n++;
        if (q == b) return n;
        p = q + 1;
    }
}

static int header_has_heat(const kiosk_config *k)
{
    for (int i = 0; i < k->ncols; i++) {
        int s = find_source(k, k->colname[i], strlen(k->colname[i]));
        if (s >= 0 && k->sources[s].kind == KIOSK_KIND_HEAT) return 1;
    }
    return 0;
}

/* A CSV header: min_fields or more names, each starting with a letter or
 * '_'. Installs it and returns 0; -1 (nothing changed) when l is not one. */
static int parse_header(kiosk_config *k, const char *l, size_t a, size_t b, int min_fields)
{
    size_t fs[KIOSK_CSV_MAX], fe[KIOSK_CSV_MAX];
    int n = split_fields(l, a, b, fs, fe, KIOSK_CSV_MAX);
    if (n < min_fields) return -1;
    for (int i = 0; i < n; i++) {
        if (fe[i] == fs[i] || fe[i] - fs[i] >= KIOSK_NAME_MAX || !is_name_start(l[fs[i]])) return -1;
        for (size_t c = fs[i]; c < fe[i]; c++)
            if (!is_name_char(l[c])) return -1;
    }
    for (int i = 0; i < n; i++) copy_str(k->colname[i], KIOSK_NAME_MAX, l + fs[i], fe[i] - fs[i]);
    k->ncols = n;
    return 0;
}

static void touch(kiosk_config *k, int s, const char *v, size_t n, int64_t now_ms)
{
    kiosk_source *so = &k->sources[s];
    copy_str(so->text, KIOSK_TEXT_MAX, v, n);
    so->last_ms = now_ms;
    so->updates++;
    k->changed |= 1u << s;
}

/* Is value v[0..n) acceptable for source s (row: a heat row index or -1)? */
static int value_ok(const kiosk_config *k, int s, const char *v, size_t n)
{
    int64_t x;
    switch (k->sources[s].kind) {
    case KIOSK_KIND_NUMBER: return kiosk_parse_milli(v, n, &x) == 0;
    case KIOSK_KIND_TEXT: return n > 0 && n < KIOSK_TEXT_MAX;
    case KIOSK_KIND_IMAGE: return n > 0 && n < KIOSK_PATH_MAX && memchr(v, '"', n) == NULL;
    default: return 0;
    }
}

/* Store a value value_ok accepted. */
static void store(kiosk_config *k, int s, const char *v, size_t n, int64_t now_ms)
{
    kiosk_source *so = &k->sources[s];
    int64_t x;
    touch(k, s, v, n, now_ms);
    if (so->kind == KIOSK_KIND_IMAGE) {
        copy_str(so->path, KIOSK_PATH_MAX, v, n);
        so->path_gen++;
        return;
    }
    if (kiosk_parse_milli(v, n, &x) == 0) {
        so->value = x;
        so->has_value = 1;
        so->hist[so->head] = x;
        so->head = (so->head + 1) % KIOSK_HIST_MAX;
        if (so->count < KIOSK_HIST_MAX) so->count++;
    }
}

/* "v1,v2,..." into heat source s: all cells (row < 0) or one row. */
static int store_heat(kiosk_config *k, int s, int row, const char *l, size_t a, size_t b, int64_t now_ms)
{
    kiosk_source *so = &k->sources[s];
    size_t fs[KIOSK_HEAT_MAX], fe[KIOSK_HEAT_MAX];
    int32_t v[KIOSK_HEAT_MAX];
    int want = row < 0 ? so->gw * so->gh : so->gw;
    if (row >= so->gh) return KIOSK_LINE_BAD;
    if (split_fields(l, a, b, fs, fe, KIOSK_HEAT_MAX) != want) return KIOSK_LINE_BAD;
    for (int i = 0; i < want; i++) {
        int64_t x;
        if (kiosk_parse_milli(l + fs[i], fe[i] - fs[i], &x)) return KIOSK_LINE_BAD;
        /* KIOSK_CELL_NONE stays reserved for "unset" */
        v[i] = x > INT32_MAX ? INT32_MAX : x <= INT32_MIN ? INT32_MIN + 1 : (int32_t)x;
    }
    memcpy(so->cells + (row < 0 ? 0 : row * so->gw), v, (size_t)want * sizeof v[0]);
    so->has_value = 1;
    touch(k, s, l + a, b - a, now_ms);
    return KIOSK_LINE_OK;
}

static int csv_row(kiosk_config *k, const char *l, size_t a, size_t b, int64_t now_ms, int *src)
{
    size_t fs[KIOSK_CSV_MAX], fe[KIOSK_CSV_MAX];
    int idx[KIOSK_CSV_MAX];
    int n = split_fields(l, a, b, fs, fe, KIOSK_CSV_MAX), used = 0;
    /* all or nothing: a row with one bad field changes no source */
    for (int i = 0; i < n; i++) {
        idx[i] = fe[i] > fs[i] ? find_source(k, k->colname[i], strlen(k->colname[i])) : -1;
        if (idx[i] >= 0 && !value_ok(k, idx[i], l + fs[i], fe[i] - fs[i])) return KIOSK_LINE_BAD;
    }
    for (int i = 0; i < n; i++)
        if (idx[i] >= 0) {
            store(k, idx[i], l + fs[i], fe[i] - fs[i], now_ms);
            if (src) *src = idx[i];
            used++;
        }
    return used ? KIOSK_LINE_OK : KIOSK_LINE_IGNORED;
}

int kiosk_data_line(kiosk_config *k, const char *line, size_t len, int64_t now_ms, int *src)
{
    size_t a = 0, b = len, sep;
    k->changed = 0;
    while (a < b && is_space(line[a])) a++;
    while (b > a && (is_space(line[b - 1]) || line[b - 1] == '\n')) b--;
    if (a == b || line[a] == '#') return KIOSK_LINE_IGNORED;
    if (len > KIOSK_LINE_MAX) return KIOSK_LINE_BAD;
    for (size_t i = a; i < b; i++)
        if ((unsigned char)line[i] < 0x20 || line[i] == 0x7f) return KIOSK_LINE_BAD;
    if (!memchr(line + a, '=', b - a)) {
        int commas = 0;
        for (size_t i = a; i < b; i++) commas += line[i] == ',';
        if (commas >= 2 && parse_header(k, line, a, b, 3) == 0)
            return header_has_heat(k) ? (k->ncols = 0, KIOSK_LINE_BAD) : KIOSK_LINE_HEADER;
        if (k->ncols >= 2 && commas + 1 == k->ncols) return csv_row(k, line, a, b, now_ms, src);
    }
    for (sep = a; sep < b && line[sep] != '=' && line[sep] != ','; sep++)
        if (!is_name_char(line[sep]) && !is_space(line[sep]) && line[sep] != '[' && line[sep] != ']')
            return KIOSK_LINE_BAD;
    if (sep == b) return KIOSK_LINE_BAD;
    size_t ne = sep, vs = sep + 1;
    int row = -1;
    while (ne > a && is_space(line[ne - 1])) ne--;
    while (vs < b && is_space(line[vs])) vs++;
    if (ne > a && line[ne - 1] == ']') { /* name[R]: one row of a heat map */
        size_t lb = ne - 1;
        while (lb > a && line[lb] != '[') lb--;
        if (line[lb] != '[' || parse_int((tok){line + lb + 1, ne - 2 - lb}, 0, KIOSK_HEAT_DIM - 1, &row))
            return KIOSK_LINE_BAD;
        ne = lb;
    }
    if (ne == a || ne - a >= KIOSK_NAME_MAX) return KIOSK_LINE_BAD;
    for (size_t i = a; i < ne; i++)
        if (!is_name_char(line[i])) return KIOSK_LINE_BAD;
    if (vs == b) return KIOSK_LINE_BAD;
    int s = find_source(k, line + a, ne - a);
    if (s < 0) return KIOSK_LINE_IGNORED;
    if (k->sources[s].kind == KIOSK_KIND_HEAT) {
        int r = store_heat(k, s, row, line, vs, b, now_ms);
        if (r == KIOSK_LINE_OK && src) *src = s;
        return r;
    }
    if (row >= 0 || !value_ok(k, s, line + vs, b - vs)) return KIOSK_LINE_BAD;
    store(k, s, line + vs, b - vs, now_ms);
    if (src) *src = s;
    return KIOSK_LINE_OK;
}

int kiosk_set_value(kiosk_config *k, int s, const char *v, size_t n, int64_t now_ms)
{
    size_t a = 0, b = n;
    k->changed = 0;
    if (s < 0 || s >= k->nsources) return KIOSK_LINE_BAD;
    while (a < b && (is_space(v[a]) || v[a] == '\n')) a++;
    while (b > a && (is_space(v[b - 1]) || v[b - 1] == '\n')) b--;
    if (a == b || b - a > KIOSK_LINE_MAX) return KIOSK_LINE_BAD;
    for (size_t i = a; i < b; i++)
        if ((unsigned char)v[i] < 0x20 || v[i] == 0x7f) return KIOSK_LINE_BAD;
    if (k->sources[s].kind == KIOSK_KIND_HEAT) return store_heat(k, s, -1, v, a, b, now_ms);
    if (!value_ok(k, s, v + a, b - a)) return KIOSK_LINE_BAD;
    store(k, s, v + a, b - a, now_ms);
    return KIOSK_LINE_OK;
}

int kiosk_topic_match(const char *f, const char *t, size_t n)
{
    size_t i = 0;
    if (n && t[0] == '$' && f[0] != '$') return 0;
    for (;;) {
        if (f[0] == '#') return 1; /* the rest, including the parent level itself */
        if (f[0] == '+') {
            while (i < n && t[i] != '/') i++;
            f++;
        } else {
            while (*f && *f != '/' && i < n && t[i] != '/' && *f == t[i]) { f++; i++; }
            if (*f && *f != '/') return 0;
            if (i < n && t[i] != '/') return 0;
        }
        /* both at the end of a level */
        if (!*f) return i == n;
        if (i == n) return f[1] == '#' && !f[2]; /* "a/#" accepts "a" */
        f++;
        i++;
    }
}
