/* SPDX-License-Identifier: MIT */
/* fixel — scene-script tokenizer, argument parsing and dispatch. */
#include "fixel/scene.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

extern const fx_scene_cmd fx_scene_cmds_core[];
extern const fx_scene_cmd fx_scene_cmds_raster[];
extern const fx_scene_cmd fx_scene_cmds_clip[];
extern const fx_scene_cmd fx_scene_cmds_fill[];
extern const fx_scene_cmd fx_scene_cmds_3d[];
extern const fx_scene_cmd fx_scene_cmds_fractal[];
extern const fx_scene_cmd fx_scene_cmds_conic[];
extern const fx_scene_cmd fx_scene_cmds_text[];
extern const fx_scene_cmd fx_scene_cmds_viz[];
extern const fx_scene_cmd fx_scene_cmds_input[];

/* One table per module, each in its own scene_<module>.c. */
const fx_scene_cmd *const fx_scene_tables[] = {
    fx_scene_cmds_core,    fx_scene_cmds_raster, fx_scene_cmds_conic, fx_scene_cmds_text,
    fx_scene_cmds_clip,    fx_scene_cmds_fill,   fx_scene_cmds_3d,    fx_scene_cmds_fractal,
    fx_scene_cmds_viz,     fx_scene_cmds_input,  0,
};

void fx_scene_init(fx_scene *sc, const fx_scene_host *host, void *arena, size_t arena_size)
{
    fx_memset(sc, 0, sizeof *sc);
    sc->host = *host;
    sc->w = 320;
    sc->h = 240;
    sc->format = FX_FMT_XRGB8888;
    sc->arena = arena;
    sc->arena_size = arena ? arena_size : 0;
    sc->ctx.color = 0xFFFFFFFFu; /* kept until the surface exists, then packed */
}

void fx_scene_fix_size(fx_scene *sc, int32_t w, int32_t h)
{
    sc->w = w;
    sc->h = h;
    sc->size_fixed = 1;
}

void fx_scene_fix_format(fx_scene *sc, fx_format f)
{
    sc->format = f;
    sc->format_fixed = 1;
}

void *fx_scene_alloc(fx_scene *sc, size_t size)
{
    size_t at = (sc->arena_used + 7) & ~(size_t)7;
    if (at > sc->arena_size || size > sc->arena_size - at)
        return 0;
    sc->arena_used = at + size;
    fx_memset(sc->arena + at, 0, size);
    return sc->arena + at;
}

int fx_scene_surface(fx_scene *sc)
{
    if (sc->have_surface)
        return 0;
    fx_surface s;
    if (!sc->host.make_surface)
        return fx_scene_error(sc, "no surface available");
    int r = sc->host.make_surface(sc->host.user, sc->w, sc->h, sc->format, &s);
    if (r < 0)
        return fx_scene_error(sc, "cannot create a %dx%d %s surface: %s", sc->w, sc->h,
                              fx_format_get(sc->format)->name, fx_strerror(r));
    fx_ctx keep = sc->ctx; /* colour and styles set before the surface existed */
    fx_ctx_init(&sc->ctx, &s);
    fx_ctx_set_color(&sc->ctx, keep.color);
    sc->ctx.line_style = keep.line_style;
    sc->ctx.trace = sc->host.trace;
    sc->ctx.trace_user = sc->host.user;
    sc->have_surface = 1;
    return 0;
}

int fx_scene_error(fx_scene *sc, const char *fmt, ...)
{
    if (!sc->err[0]) {
        va_list ap;
        va_start(ap, fmt);
        fx_vfmt(sc->err, sizeof sc->err, fmt, ap);
        va_end(ap);
        sc->err_line = sc->lineno;
        sc->err_col = sc->tok_col + 1;
    }
    return -FX_EINVAL;
}

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }
static int is_hex(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

/* A '#' begins a comment unless it begins a token of exactly 6 or 8 hex
 * digits (a colour). */
static int comment_at(const fx_scene *sc, int i)
{
    if (sc->text[i] != '#')
        return 0;
    int n = 0;
    while (i + 1 + n < sc->len && is_hex(sc->text[i + 1 + n]))
        n++;
    int end = i + 1 + n;
    int token_ends = end >= sc->len || is_space(sc->text[end]);
    return !((n == 6 || n == 8) && token_ends);
}

/* The next token as [*start, *start + *len); 0 when the line has no more. */
static int next_token(fx_scene *sc, int *start, int *len)
{
    int i = sc->pos;
    while (i < sc->len && is_space(sc->text[i]))
        i++;
    sc->tok_col = i;
    if (i >= sc->len || comment_at(sc, i)) {
        sc->pos = i;
        return 0;
    }
    int s = i;
    if (sc->text[i] == '"') {
        i++;
        while (i < sc->len && sc->text[i] != '"')
            i += sc->text[i] == '\\' && i + 1 < sc->len ? 2 : 1;
        if (i < sc->len)
            i++;
    } else {
        while (i < sc->len && !is_space(sc->text[i]))
            i++;
    }
    *start = s;
    *len = i - s;
    sc->pos = i;
    return 1;
}

int fx_scene_more(fx_scene *sc)
{
    int save = sc->pos, s, l;
    int more = next_token(sc, &s, &l);
    sc->pos = save;
    return more;
}

int fx_scene_end(fx_scene *sc)
{
    int s, l;
    if (next_token(sc, &s, &l))
        return fx_scene_error(sc, "unexpected argument '%.*s'", l, sc->text + s);
    sc->tok_col = sc->cmd_col;
    return 0;
}

#define NEED_TOKEN(what)                                  \
    int s, l;                                             \
    if (!next_token(sc, &s, &l))                          \
        return fx_scene_error(sc, "missing %s", what);    \
    const char *t = sc->text + s

int fx_scene_arg_int(fx_scene *sc, int32_t *v)
{
    NEED_TOKEN("integer argument");
    int i = 0, neg = 0;
    if (l > 1 && (t[0] == '-' || t[0] == '+'))
        neg = t[i++] == '-';
    if (i >= l)
        return fx_scene_error(sc, "expected an integer, got '%.*s'", l, t);
    int64_t acc = 0;
    for (; i < l; i++) {
        if (t[i] < '0' || t[i] > '9')
            return fx_scene_error(sc, "expected an integer, got '%.*s'", l, t);
        acc = acc * 10 + (t[i] - '0');
        if (acc > (int64_t)INT32_MAX + 1)
            return fx_scene_error(sc, "integer '%.*s' out of range", l, t);
    }
    if (neg)
        acc = -acc;
    if (acc > INT32_MAX)
        return fx_scene_error(sc, "integer '%.*s' out of range", l, t);
    *v = (int32_t)acc;
    return 0;
}

int fx_scene_arg_color(fx_scene *sc, fx_color *v)
{
    /* "#12345G" reads as a comment to the tokenizer; where a colour is
     * expected, a '#' glued to a word is a malformed colour instead. */
    int i = sc->pos;
    while (i < sc->len && is_space(sc->text[i]))
        i++;
    if (i + 1 < sc->len && sc->text[i] == '#' && !is_space(sc->text[i + 1]) &&
        comment_at(sc, i)) {
        int e = i;
        while (e < sc->len && !is_space(sc->text[e]))
            e++;
        sc->tok_col = i;
        return fx_scene_error(sc, "expected a colour #RRGGBB or #AARRGGBB, got '%.*s'", e - i,
                              sc->text + i);
    }
    NEED_TOKEN("colour (#RRGGBB or #AARRGGBB)");
    if (t[0] != '#' || (l != 7 && l != 9))
        return fx_scene_error(sc, "expected a colour #RRGGBB or #AARRGGBB, got '%.*s'", l, t);
    uint32_t c = 0;
    for (int k = 1; k < l; k++) {
        char ch = t[k];
        if (!is_hex(ch))
            return fx_scene_error(sc, "bad hex digit in colour '%.*s'", l, t);
        c = c * 16 + (uint32_t)(ch <= '9' ? ch - '0' : (ch | 32) - 'a' + 10);
    }
    *v = l == 7 ? 0xFF000000u | c : c;
    return 0;
}

int fx_scene_arg_fx16(fx_scene *sc, fx16 *v)
{
    NEED_TOKEN("number");
    int n = fx16_parse(t, l, v);
    if (n == -FX_ERANGE)
        return fx_scene_error(sc, "number '%.*s' out of range for Q16.16", l, t);
    if (n != l)
        return fx_scene_error(sc, "expected a decimal number, got '%.*s'", l, t);
    return 0;
}

int fx_scene_arg_fx56(fx_scene *sc, fx56 *v)
{
    NEED_TOKEN("number");
    int n = fx56_parse(t, l, v);
    if (n == -FX_ERANGE)
        return fx_scene_error(sc, "number '%.*s' out of range (|x| < 128)", l, t);
    if (n != l)
        return fx_scene_error(sc, "expected a decimal number, got '%.*s'", l, t);
    return 0;
}

int fx_scene_arg_word(fx_scene *sc, char *buf, size_t size)
{
    NEED_TOKEN("word");
    if (t[0] == '"')
        return fx_scene_error(sc, "expected a word, got a string");
    if ((size_t)l >= size)
        return fx_scene_error(sc, "word '%.*s' too long", l, t);
    fx_memcpy(buf, t, (size_t)l);
    buf[l] = 0;
    return 0;
}

int fx_scene_arg_string(fx_scene *sc, char *buf, size_t size)
{
    NEED_TOKEN("string");
    if (t[0] != '"' || l < 2 || t[l - 1] != '"')
        return fx_scene_error(sc, "expected a double-quoted string, got '%.*s'", l, t);
    size_t n = 0;
    for (int i = 1; i < l - 1; i++) {
        char ch = t[i];
        if (ch == '\\' && i + 1 < l - 1) {
            ch = t[++i];
            if (ch == 'n')
                ch = '\n';
        }
        if (n + 1 >= size)
            return fx_scene_error(sc, "string too long (at most %u bytes)", (unsigned)size - 1);
        buf[n++] = ch;
    }
    buf[n] = 0;
    return 0;
}

int fx_scene_arg_choice(fx_scene *sc, const char *const *choices)
{
    char w[32];
    int r = fx_scene_arg_word(sc, w, sizeof w);
    if (r < 0)
        return r;
    for (int i = 0; choices[i]; i++) {
        const char *a = choices[i], *b = w;
        while (*a && *a == *b)
            a++, b++;
        if (!*a && !*b)
            return i;
    }
    char list[160];
    size_t n = 0;
    for (int i = 0; choices[i] && n + 1 < sizeof list; i++)
        n += (size_t)fx_fmt(list + n, sizeof list - n, "%s%s", i ? "|" : "", choices[i]);
    return fx_scene_error(sc, "expected one of %s, got '%s'", list, w);
}

const fx_scene_cmd *fx_scene_find(const char *name, size_t len)
{
    for (int t = 0; fx_scene_tables[t]; t++)
        for (const fx_scene_cmd *c = fx_scene_tables[t]; c->name; c++) {
            size_t i = 0;
            while (i < len && c->name[i] && c->name[i] == name[i]) /* a NUL in the script must not run past the name */
                i++;
            if (i == len && !c->name[i])
                return c;
        }
    return 0;
}

int fx_scene_exec_line(fx_scene *sc, const char *line, size_t len, int lineno)
{
    sc->text = line;
    sc->len = (int)len;
    sc->pos = 0;
    sc->lineno = lineno;
    int s, l;
    if (!next_token(sc, &s, &l))
        return 0;
    sc->cmd_col = s;
    const fx_scene_cmd *cmd = fx_scene_find(line + s, (size_t)l);
    if (!cmd)
        return fx_scene_error(sc, "unknown command '%.*s'", l, line + s);
    if (cmd->flags & FX_SCENE_DRAWS) {
        int r = fx_scene_surface(sc);
        if (r < 0)
            return r;
    }
    int r = cmd->run(sc);
    if (r < 0 && !sc->err[0])
        fx_scene_error(sc, "%s failed: %s (usage: %s)", cmd->name, fx_strerror(r), cmd->usage);
    return r < 0 ? r : 0;
}

int fx_scene_run(fx_scene *sc, const char *text, size_t len)
{
    size_t i = 0;
    int lineno = 1;
    while (i < len) {
        size_t e = i;
        while (e < len && text[e] != '\n')
            e++;
        if (e - i > (size_t)INT32_MAX)
            return fx_scene_error(sc, "line too long");
        int r = fx_scene_exec_line(sc, text + i, e - i, lineno);
        if (r < 0)
            return r;
        i = e + 1;
        lineno++;
    }
    return fx_scene_surface(sc);
}
