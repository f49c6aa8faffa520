/* fixel-kiosk parsers: config text and data lines, from memory buffers.
 * Every input is bounded by a length (no NUL needed) and every copy by the
 * fixed sizes in kiosk.h: a hostile line can be rejected but never make the
 * model grow. */
#include "kiosk.h"

#include <string.h>

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
        if (v > (INT64_MAX / 10 - 9) / 1000) return -1; /* keeps v * 1000 in range */
        v = v * 10 + (s[i] - '0');
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

static const char *const type_names[] = {"number", "gauge", "bar", "spark", "text", "clock"};

static const char *parse_widget(kiosk_config *k, const char *p, const char *end)
{
    tok t;
    if (k->nwidgets >= KIOSK_MAX_WIDGETS) return "too many widgets";
    kiosk_widget *w = &k->widgets[k->nwidgets];
    memset(w, 0, sizeof *w);
    if (next_tok(&p, end, &t) != 1) return "widget needs a type";
    int ty = -1;
    for (int i = 0; i < 6; i++)
        if (tok_is(t, type_names[i])) ty = i;
    if (ty < 0) return "unknown widget type (number gauge bar spark text clock)";
    w->type = (kiosk_type)ty;
    w->source = -1;
    w->w = w->h = 1;
    w->max = 100000;
    w->color = 0xFF4FC3F7u;
    if (w->type == KIOSK_SPARK) w->max = 0; /* automatic range */
    if (w->type != KIOSK_CLOCK) {
        if (next_tok(&p, end, &t) != 1) return "widget needs a source name";
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
        while (eq < t.n && t.s[eq] != '=') eq++;
        if (eq == t.n) return "expected key=value";
        tok key = {t.s, eq}, val = {t.s + eq + 1, t.n - eq - 1};
        int bad;
        if (tok_is(key, "col")) bad = parse_int(val, 0, 63, &w->col);
        else if (tok_is(key, "row")) bad = parse_int(val, 0, 63, &w->row);
        else if (tok_is(key, "w")) bad = parse_int(val, 1, 64, &w->w);
        else if (tok_is(key, "h")) bad = parse_int(val, 1, 64, &w->h);
        else if (tok_is(key, "decimals")) bad = parse_int(val, 0, 3, &w->decimals);
        else if (tok_is(key, "min")) bad = kiosk_parse_milli(val.s, val.n, &w->min);
        else if (tok_is(key, "max")) bad = kiosk_parse_milli(val.s, val.n, &w->max);
        else if (tok_is(key, "color")) bad = parse_color(val, &w->color);
        else if (tok_is(key, "label")) bad = parse_text(val, w->label);
        else if (tok_is(key, "unit")) bad = parse_text(val, w->unit);
        else return "unknown widget key (col row w h decimals min max color label unit)";
        if (bad) return "bad widget value";
    }
    if (r < 0) return "unterminated quote";
    if (w->min > w->max || (w->min == w->max && w->type != KIOSK_SPARK && w->type != KIOSK_NUMBER &&
                            w->type != KIOSK_TEXT && w->type != KIOSK_CLOCK))
        return "min must be below max";
    if (w->max - w->min > INT64_MAX / 4096) return "range too large";
    k->nwidgets++;
    return NULL;
}

int kiosk_config_parse(kiosk_config *k, const char *buf, size_t len, char *err, size_t errsize)
{
    const char *p = buf, *end = buf + len;
    int line = 0;
    memset(k, 0, sizeof *k);
    k->cols = k->rows = 2;
    k->stale_ms = 10000;
    k->history = 120;
    k->bg = 0xFF0E1116u;
    k->panel = 0xFF1B222Bu;
    k->fg = 0xFFE8EAEDu;
    if (err && errsize) err[0] = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        line++;
        const char *q = p, *msg = NULL;
        tok t;
        while (q < eol && is_space(*q)) q++;
        int r = q < eol && *q == '#' ? 0 : next_tok(&q, eol, &t);
        for (const char *c = p; c < eol; c++)
            if (*c == 0) { r = -1; break; }
        if (r < 0) msg = "unreadable line";
        else if (r == 0) msg = NULL;
        else if (tok_is(t, "widget")) msg = parse_widget(k, q, eol);
        else {
            tok v;
            int rv = next_tok(&q, eol, &v);
            tok extra;
            if (rv != 1) msg = "missing value";
            else if (tok_is(t, "title")) {
                /* the rest of the line, so titles need no quotes */
                const char *e = eol;
                while (e > v.s && is_space(e[-1])) e--;
                if (parse_text((tok){v.s, (size_t)(e - v.s)}, k->title)) msg = "bad title";
                q = eol;
            } else if (tok_is(t, "grid")) msg = parse_pair(v, 1, 16, &k->cols, &k->rows) ? "grid wants CxR, 1..16" : NULL;
            else if (tok_is(t, "size")) msg = parse_pair(v, 16, 8192, &k->width, &k->height) ? "size wants WxH" : NULL;
            else if (tok_is(t, "stale")) {
                int64_t ms;
                if (kiosk_parse_milli(v.s, v.n, &ms) || ms < 1 || ms > 86400000000) msg = "stale wants seconds";
                else k->stale_ms = (int)(ms > 2000000000 ? 2000000000 : ms);
            } else if (tok_is(t, "history"))
                msg = parse_int(v, 2, KIOSK_HIST_MAX, &k->history) ? "history wants 2..256" : NULL;
            else if (tok_is(t, "bg")) msg = parse_color(v, &k->bg) ? "bad colour (#rrggbb)" : NULL;
            else if (tok_is(t, "panel")) msg = parse_color(v, &k->panel) ? "bad colour (#rrggbb)" : NULL;
            else if (tok_is(t, "fg")) msg = parse_color(v, &k->fg) ? "bad colour (#rrggbb)" : NULL;
            else msg = "unknown directive (title grid size stale history bg panel fg widget)";
            if (!msg && next_tok(&q, eol, &extra) != 0) msg = "extra text after value";
        }
        if (msg) {
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
    for (int i = 0; i < k->nwidgets; i++) {
        const kiosk_widget *w = &k->widgets[i];
        if (w->col + w->w > k->cols || w->row + w->h > k->rows) {
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

static int source_numeric(const kiosk_config *k, int s)
{
    for (int i = 0; i < k->nwidgets; i++)
        if (k->widgets[i].source == s && k->widgets[i].type != KIOSK_TEXT) return 1;
    return 0;
}

int kiosk_data_line(kiosk_config *k, const char *line, size_t len, int64_t now_ms, int *src)
{
    size_t a = 0, b = len, sep;
    while (a < b && is_space(line[a])) a++;
    while (b > a && (is_space(line[b - 1]) || line[b - 1] == '\n')) b--;
    if (a == b || line[a] == '#') return KIOSK_LINE_IGNORED;
    if (len > KIOSK_LINE_MAX) return KIOSK_LINE_BAD;
    for (sep = a; sep < b && line[sep] != '=' && line[sep] != ','; sep++)
        if (!is_name_char(line[sep]) && !is_space(line[sep])) return KIOSK_LINE_BAD;
    if (sep == b) return KIOSK_LINE_BAD;
    size_t ne = sep, vs = sep + 1;
    while (ne > a && is_space(line[ne - 1])) ne--;
    while (vs < b && is_space(line[vs])) vs++;
    if (ne == a || ne - a >= KIOSK_NAME_MAX) return KIOSK_LINE_BAD;
    for (size_t i = a; i < ne; i++)
        if (!is_name_char(line[i])) return KIOSK_LINE_BAD;
    if (vs == b || b - vs >= KIOSK_TEXT_MAX) return KIOSK_LINE_BAD;
    for (size_t i = vs; i < b; i++)
        if ((unsigned char)line[i] < 0x20 || line[i] == 0x7f) return KIOSK_LINE_BAD;
    int s = find_source(k, line + a, ne - a);
    int64_t v = 0;
    int numeric = s >= 0 ? source_numeric(k, s) : 0;
    int parsed = kiosk_parse_milli(line + vs, b - vs, &v) == 0;
    if (s < 0) return parsed || !numeric ? KIOSK_LINE_IGNORED : KIOSK_LINE_BAD;
    if (numeric && !parsed) return KIOSK_LINE_BAD;
    kiosk_source *so = &k->sources[s];
    copy_str(so->text, KIOSK_TEXT_MAX, line + vs, b - vs);
    so->last_ms = now_ms;
    so->updates++;
    if (parsed) {
        so->value = v;
        so->has_value = 1;
        so->hist[so->head] = v;
        so->head = (so->head + 1) % KIOSK_HIST_MAX;
        if (so->count < KIOSK_HIST_MAX) so->count++;
    }
    if (src) *src = s;
    return KIOSK_LINE_OK;
}
