/* SPDX-License-Identifier: MIT */
/* fixel — scene-script tokenizer, argument parsing and dispatch. */
#include "fixel/scene.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"
#include "scene_shared.h"

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
extern const fx_scene_cmd fx_scene_cmds_rt[];
extern const fx_scene_cmd fx_scene_cmds_vsd[];
extern const fx_scene_cmd fx_scene_cmds_objects[];
extern const fx_scene_cmd fx_scene_cmds_anim[];

/* One table per module, each in its own scene_<module>.c. */
const fx_scene_cmd *const fx_scene_tables[] = {
    fx_scene_cmds_core,    fx_scene_cmds_raster, fx_scene_cmds_conic, fx_scene_cmds_text,
    fx_scene_cmds_clip,    fx_scene_cmds_fill,   fx_scene_cmds_3d,    fx_scene_cmds_fractal,
    fx_scene_cmds_viz,     fx_scene_cmds_input,  fx_scene_cmds_rt,     fx_scene_cmds_vsd,
    fx_scene_cmds_objects, fx_scene_cmds_anim,
    0,
};

void fx_scene_init(fx_scene *sc, const fx_scene_host *host, void *arena, size_t arena_size)
{
    fx_memset(sc, 0, sizeof *sc);
    sc->host = *host;
    sc->w = 320;
    sc->h = 240;
    sc->format = FX_FMT_XRGB8888;
    /* Module state in the arena holds 64-bit fields: start at the first
     * 8-byte boundary and keep whole 8-byte units, so any arena the caller
     * has works (fx_scene_run_mt lays band arenas of this size end to end,
     * each then aligned too). */
    size_t skip = arena ? (size_t)(-(uintptr_t)arena & 7u) : 0;
    sc->arena = arena && arena_size > skip ? (uint8_t *)arena + skip : NULL;
    sc->arena_size = sc->arena ? (arena_size - skip) & ~(size_t)7 : 0;
    if (!sc->arena_size)
        sc->arena = NULL;
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

void *fx_scene_alloc_raw(fx_scene *sc, size_t size)
{
    size_t at = (sc->arena_used + 7) & ~(size_t)7;
    if (at > sc->arena_size || size > sc->arena_size - at)
        return 0;
    sc->arena_used = at + size;
    return sc->arena + at;
}

void *fx_scene_alloc(fx_scene *sc, size_t size)
{
    void *p = fx_scene_alloc_raw(sc, size);
    if (p)
        fx_memset(p, 0, size);
    return p;
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
    fx_scene_band_clip(sc, &sc->ctx.clip);
    return 0;
}

void fx_scene_set_band(fx_scene *sc, fx_rect band)
{
    sc->banded = 1;
    sc->band = band;
    if (sc->have_surface)
        fx_scene_band_clip(sc, &sc->ctx.clip);
}

void fx_scene_band_clip(const fx_scene *sc, fx_rect *clip)
{
    if (!sc->banded)
        return;
    *clip = fx_rect_intersect(*clip, sc->band);
    if (fx_rect_empty(*clip)) /* empty, but still a valid rectangle */
        clip->x1 = clip->x0, clip->y1 = clip->y0;
}

int fx_scene_error(fx_scene *sc, const char *fmt, ...)
{
    if (!sc->err[0]) {
        char raw[sizeof sc->err];
        va_list ap;
        va_start(ap, fmt);
        fx_vfmt(raw, sizeof raw, fmt, ap);
        va_end(ap);
        /* Script text quoted in a message must not split or colour the
         * SCRIPT:LINE:COL line: control bytes are shown as \xNN. */
        size_t o = 0;
        for (size_t i = 0; raw[i] && o + 1 < sizeof sc->err; i++) {
            unsigned char ch = (unsigned char)raw[i];
            if (ch >= 0x20 && ch != 0x7F) {
                sc->err[o++] = (char)ch;
            } else if (o + 5 < sizeof sc->err) {
                static const char hex[] = "0123456789abcdef";
                sc->err[o++] = '\\';
                sc->err[o++] = 'x';
                sc->err[o++] = hex[ch >> 4];
                sc->err[o++] = hex[ch & 15];
            } else {
                break;
            }
        }
        sc->err[o] = 0;
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

/* ---- the argument table check (entries in scene_args.c) ---- */

static int tok_is(const char *t, int l, const char *w)
{
    int i = 0;
    while (i < l && w[i] && w[i] == t[i])
        i++;
    return i == l && !w[i];
}

/* A decimal integer token: 1 and *v (saturated to +-2^62 beyond it), or 0
 * when the token is not an integer. */
static int tok_int(const char *t, int l, int64_t *v)
{
    int i = 0, neg = 0;
    if (l > 1 && (t[0] == '-' || t[0] == '+'))
        neg = t[i++] == '-';
    if (i >= l)
        return 0;
    int64_t acc = 0;
    for (; i < l; i++) {
        if (t[i] < '0' || t[i] > '9')
            return 0;
        if (acc <= (((int64_t)1 << 62) - 9) / 10)
            acc = acc * 10 + (t[i] - '0');
        else
            acc = (int64_t)1 << 62; /* saturated: out of any range */
    }
    if (acc > ((int64_t)1 << 62))
        acc = (int64_t)1 << 62;
    *v = neg ? -acc : acc;
    return 1;
}

static int range_error(fx_scene *sc, const fx_scene_arg *a, const char *t, int l)
{
    char range[64];
    fx_scene_arg_range(a, range, sizeof range);
    return fx_scene_error(sc, "%s %.*s out of range, expected %s", a->name, l > 40 ? 40 : l, t, range);
}

/* 1 when the form starting at f (an FX_ARG_FORM) or a later one of the same
 * group has keyword t; *out = its first argument. Else the default form. */
static const fx_scene_arg *pick_form(const fx_scene_arg *f, const char *t, int l, int have, int *consumed)
{
    const fx_scene_arg *dflt = 0;
    *consumed = 0;
    for (; f->type != FX_ARG_END; f++) {
        if (f->type != FX_ARG_FORM)
            continue;
        if (!f->name)
            dflt = f + 1;
        else if (have && tok_is(t, l, f->name)) {
            *consumed = 1;
            return f + 1;
        }
    }
    return dflt;
}

int fx_scene_check_args(fx_scene *sc, const fx_scene_argspec *spec)
{
    const fx_scene_arg *a = spec->args, *rep = 0, *group = 0;
    int64_t reps = 0;
    int in_form = 0, s, l, r = 0;
    int save_pos = sc->pos, save_col = sc->tok_col;
    for (;;) {
        if (a->type == FX_ARG_END || (a->type == FX_ARG_FORM && in_form)) {
            if (!group || !fx_scene_more(sc))
                break;
            reps++;
            if (reps >= rep->max) {
                next_token(sc, &s, &l);
                char range[48];
                fx_scene_arg_range(rep, range, sizeof range);
                r = fx_scene_error(sc, "%s %lld out of range, expected %s", rep->name, (long long)reps + 1, range);
                break;
            }
            a = group;
            continue;
        }
        if (a->type == FX_ARG_OPT) {
            a++;
            continue;
        }
        if (a->type == FX_ARG_REPEAT) {
            rep = a;
            group = ++a;
            reps = 0;
            continue;
        }
        int save = sc->pos;
        int have = next_token(sc, &s, &l);
        const char *t = sc->text + s;
        if (a->type == FX_ARG_FORM) {
            int used;
            a = pick_form(a, t, l, have, &used);
            if (!a)
                break;
            in_form = 1;
            if (!used)
                sc->pos = save;
            continue;
        }
        if (!have)
            break; /* missing: the command says what it needed */
        if (a->type == FX_ARG_INT) {
            int64_t v;
            if (!tok_int(t, l, &v))
                break; /* not an integer: the command's message */
            if (v < a->min || v > a->max) {
                r = range_error(sc, a, t, l);
                break;
            }
        } else if (a->type == FX_ARG_FX16 || a->type == FX_ARG_FX56) {
            int n;
            int64_t v;
            if (a->type == FX_ARG_FX16) {
                fx16 x = 0;
                n = fx16_parse(t, l, &x);
                v = x;
            } else {
                fx56 x = 0;
                n = fx56_parse(t, l, &x);
                v = x;
            }
            int low = (a->flags & FX_ARG_OPEN_MIN) ? v <= a->min : v < a->min;
            if (n == -FX_ERANGE || (n == l && (low || v > a->max))) {
                r = range_error(sc, a, t, l);
                break;
            }
            if (n != l)
                break;
        }
        a++;
    }
    if (r >= 0) {
        sc->pos = save_pos;
        sc->tok_col = save_col;
    }
    return r;
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
    if (fx_scene_anim_recording(sc) && !tok_is(line + s, l, "endblur"))
        return fx_scene_anim_record(sc, line, len, lineno);
    const fx_scene_cmd *cmd = fx_scene_find(line + s, (size_t)l);
    if (!cmd)
        return fx_scene_error(sc, "unknown command '%.*s'", l > 40 ? 40 : l, line + s);
    const fx_scene_argspec *spec = fx_scene_args_find(cmd->name);
    if (!spec)
        return fx_scene_error(sc, "'%s' has no entry in the argument table", cmd->name);
    int rc = fx_scene_check_args(sc, spec);
    if (rc < 0)
        return rc;
    if (cmd->flags & FX_SCENE_DRAWS) {
        int r = fx_scene_surface(sc);
        if (r < 0)
            return r;
    }
    int r = cmd->run(sc);
    /* clip, clip pop, viewport and the rest set the clip the script asked
     * for; a band narrows it again before the next command draws */
    if (sc->have_surface)
        fx_scene_band_clip(sc, &sc->ctx.clip);
    if (r < 0 && !sc->err[0])
        fx_scene_error(sc, "%s failed: %s (usage: %s)", cmd->name, fx_strerror(r), cmd->usage);
    return r < 0 ? r : 0;
}

int fx_scene_script_serial(const char *text, size_t len)
{
    size_t i = 0;
    int lineno = 1;
    while (i < len) {
        size_t e = i;
        while (e < len && text[e] != '\n')
            e++;
        size_t s = i;
        while (s < e && is_space(text[s]))
            s++;
        size_t w = s;
        while (w < e && !is_space(text[w]))
            w++;
        if (w > s && text[s] != '#') {
            const fx_scene_cmd *c = fx_scene_find(text + s, w - s);
            if (c && (c->flags & FX_SCENE_SERIAL))
                return lineno;
        }
        i = e + 1;
        lineno++;
    }
    return 0;
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
    int r = fx_scene_end_script(sc);
    return r < 0 ? r : fx_scene_surface(sc);
}
