/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the text module: fonts, text, and the text
 * style (clipping mode, scale, background). Font files come through the
 * host's load_file (fixel-draw inflates .psf.gz there); the core only parses
 * the bytes. */
#include "fixel/error.h"
#include "fixel/font.h"
#include "fixel/scene.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

typedef struct text_state {
    fx_text_style st;
    fx_font font;
    void *face; /* the host's smooth font (fx_scene_text_host); NULL: PSF/built-in */
} text_state;

static text_state *state(fx_scene *sc)
{
    text_state *t = sc->mod[FX_SCENE_MOD_TEXT];
    if (!t) {
        t = fx_scene_alloc(sc, sizeof *t);
        if (!t)
            return 0;
        t->st.scale = 1;
        t->st.clip = FX_TEXT_CLIP_PIXEL;
        sc->mod[FX_SCENE_MOD_TEXT] = t;
    }
    return t;
}

static int need_state(fx_scene *sc, text_state **t)
{
    *t = state(sc);
    return *t ? 0 : fx_scene_error(sc, "no scene memory left for the text style");
}

/* The next argument starts with a double quote. */
static int quoted_next(const fx_scene *sc)
{
    int i = sc->pos;
    while (i < sc->len && (sc->text[i] == ' ' || sc->text[i] == '\t'))
        i++;
    return i < sc->len && sc->text[i] == '"';
}

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b)
        a++, b++;
    return *a == *b;
}

/* 'font FAMILY|FILE SIZE [WEIGHT] [FEATURE...]': a smooth font from the host. */
static int smooth_font(fx_scene *sc, const char *name)
{
    static const struct {
        const char *w;
        int32_t v;
    } weights[] = {{"thin", 100}, {"extralight", 200}, {"light", 300}, {"regular", 400}, {"normal", 400},
                   {"medium", 500}, {"semibold", 600}, {"bold", 700}, {"extrabold", 800}, {"black", 900}};
    int32_t px, weight = 0;
    TRY(fx_scene_arg_int(sc, &px));
    if (px < 1 || px > 1024)
        return fx_scene_error(sc, "font size %d px out of range (1..1024)", px);
    char feats[512], word[64];
    int nf = 0, first = 1;
    feats[0] = 0;
    while (fx_scene_more(sc)) {
        TRY(fx_scene_arg_word(sc, word, sizeof word));
        int known = 0;
        if (first) {
            for (unsigned k = 0; k < sizeof weights / sizeof weights[0]; k++)
                if (streq(word, weights[k].w))
                    weight = weights[k].v, known = 1;
            if (!known && word[0] >= '0' && word[0] <= '9') {
                int32_t v = 0;
                int i = 0;
                while (word[i] >= '0' && word[i] <= '9' && v <= 1000)
                    v = v * 10 + (word[i++] - '0');
                if (word[i] || v < 1 || v > 1000)
                    return fx_scene_error(sc, "font weight '%s': expected 1..1000 or thin..black", word);
                weight = v, known = 1;
            }
        }
        first = 0;
        if (known)
            continue;
        int l = 0;
        while (word[l])
            l++;
        if (nf + l + 2 > (int)sizeof feats)
            return fx_scene_error(sc, "font features: too many");
        if (nf)
            feats[nf++] = ',';
        for (int i = 0; i <= l; i++)
            feats[nf + i] = word[i];
        nf += l;
    }
    text_state *t;
    TRY(need_state(sc, &t));
    if (!sc->text_host || !sc->text_host->open)
        return fx_scene_error(sc, "smooth fonts are not available here: 'font %s %d' needs a host with FreeType "
                                  "(fixel-draw built with libfreetype-dev and friends)", name, px);
    char err[160];
    void *face = 0;
    err[0] = 0;
    int r = sc->text_host->open(sc->text_host->user, name, px, weight, feats, &face, err, sizeof err);
    if (r < 0)
        return fx_scene_error(sc, "font: %s", err[0] ? err : fx_strerror(r));
    t->face = face;
    return 0;
}

static int cmd_font(fx_scene *sc)
{
    char path[512];
    text_state *t;
    if (quoted_next(sc))
        TRY(fx_scene_arg_string(sc, path, sizeof path));
    else
        TRY(fx_scene_arg_word(sc, path, sizeof path));
    if (fx_scene_more(sc))
        return smooth_font(sc, path);
    TRY(fx_scene_end(sc));
    TRY(need_state(sc, &t));
    t->face = 0;
    const char *b = "builtin";
    int i = 0;
    while (b[i] && path[i] == b[i])
        i++;
    if (!b[i] && !path[i]) {
        t->st.font = 0;
        return 0;
    }
    if (!sc->host.load_file)
        return fx_scene_error(sc, "files not available: cannot load font '%s'", path);
    const uint8_t *data;
    size_t len;
    int r = sc->host.load_file(sc->host.user, path, &data, &len);
    if (r < 0)
        return fx_scene_error(sc, "cannot read font '%s': %s", path, fx_strerror(r));
    fx_font f;
    r = fx_font_load(&f, data, len);
    if (r < 0)
        return fx_scene_error(sc, "'%s' is not a usable PSF font: %s", path, fx_strerror(r));
    /* the unicode table indexed once: lookups stop walking it (issue #26) */
    size_t ix = fx_font_index_bytes(&f);
    if (ix) {
        void *mem = fx_scene_alloc(sc, ix);
        if (!mem || fx_font_index(&f, mem, ix) < 0)
            return fx_scene_error(sc, "out of scene memory for the unicode index of '%s'", path);
    }
    t->font = f;
    t->st.font = &t->font;
    return 0;
}

static int smooth_draw(fx_scene *sc, text_state *t, int32_t x, int32_t y, int32_t w, int32_t h, int align, int ell,
                       const char *s)
{
    size_t len = 0;
    while (s[len])
        len++;
    char err[160];
    err[0] = 0;
    int r = sc->text_host->draw(sc->text_host->user, t->face, &sc->ctx, x, y, w, h, align, ell, s, len, err,
                                sizeof err);
    return r < 0 ? fx_scene_error(sc, "text: %s", err[0] ? err : fx_strerror(r)) : 0;
}

static int cmd_text(fx_scene *sc)
{
    int32_t x, y;
    char s[2048];
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_arg_string(sc, s, sizeof s));
    TRY(fx_scene_end(sc));
    text_state *t = sc->mod[FX_SCENE_MOD_TEXT];
    if (t && t->face)
        return smooth_draw(sc, t, x, y, 0, 0, 0, 0, s);
    sc->ctx.text_style = t ? &t->st : 0;
    fx_text(&sc->ctx, x, y, s);
    return 0;
}

/* 'textbox X Y W H [left|centre|right] [ellipsis] "STRING"' (smooth fonts). */
static int cmd_textbox(fx_scene *sc)
{
    static const char *const aligns[] = {"left", "centre", "right", "ellipsis", 0};
    int32_t x, y, w, h;
    char s[2048];
    int align = 0, ell = 0;
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_arg_int(sc, &w));
    TRY(fx_scene_arg_int(sc, &h));
    if (w < 1 || h < 1)
        return fx_scene_error(sc, "textbox size %dx%d: both must be at least 1", w, h);
    for (int k = 0; k < 2 && !quoted_next(sc) && fx_scene_more(sc); k++) {
        int m = fx_scene_arg_choice(sc, aligns);
        TRY(m);
        if (m == 3)
            ell = 1;
        else
            align = m;
    }
    TRY(fx_scene_arg_string(sc, s, sizeof s));
    TRY(fx_scene_end(sc));
    text_state *t = sc->mod[FX_SCENE_MOD_TEXT];
    if (!t || !t->face)
        return fx_scene_error(sc, "textbox needs a smooth font first: font FAMILY|FILE SIZE");
    return smooth_draw(sc, t, x, y, w, h, align, ell, s);
}

static int cmd_textclip(fx_scene *sc)
{
    static const char *const modes[] = {"pixel", "char", "string", 0};
    text_state *t;
    int m = fx_scene_arg_choice(sc, modes);
    TRY(m);
    TRY(fx_scene_end(sc));
    TRY(need_state(sc, &t));
    t->st.clip = (uint8_t)m; /* the list follows enum fx_text_clip */
    return 0;
}

static int cmd_textscale(fx_scene *sc)
{
    int32_t n;
    text_state *t;
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_end(sc));
    if (n < 1 || n > 256)
        return fx_scene_error(sc, "text scale %d out of range (1..256)", n);
    TRY(need_state(sc, &t));
    t->st.scale = n;
    return 0;
}

static int cmd_textbg(fx_scene *sc)
{
    text_state *t;
    fx_color c = 0;
    int none = 0;
    if (!quoted_next(sc) && fx_scene_more(sc)) {
        int i = sc->pos;
        while (i < sc->len && (sc->text[i] == ' ' || sc->text[i] == '\t'))
            i++;
        none = sc->text[i] == 'n';
    }
    if (none) {
        static const char *const w[] = {"none", 0};
        TRY(fx_scene_arg_choice(sc, w));
    } else {
        TRY(fx_scene_arg_color(sc, &c));
    }
    TRY(fx_scene_end(sc));
    TRY(need_state(sc, &t));
    t->st.has_bg = !none;
    t->st.bg = c;
    return 0;
}

const fx_scene_cmd fx_scene_cmds_text[] = {
    {"font", cmd_font,
     "font builtin|PATH|\"PATH\"   (PSF1/PSF2, .psf.gz in fixel-draw)\n"
     "font FAMILY|FILE SIZE [WEIGHT] [FEATURE...]   (smooth: TrueType/OpenType by file or fontconfig family, "
     "SIZE px, WEIGHT thin..black or 1..1000, OpenType features such as tnum -liga)",
     0},
    {"text", cmd_text, "text X Y \"STRING\"   (top-left corner; \\n starts a new line)", FX_SCENE_DRAWS},
    {"textbox", cmd_textbox,
     "textbox X Y W H [left|centre|right] [ellipsis] \"STRING\"   (smooth font: wrapped at UAX #14 breaks)",
     FX_SCENE_DRAWS},
    {"textclip", cmd_textclip, "textclip pixel|char|string", FX_SCENE_SERIAL},
    {"textscale", cmd_textscale, "textscale N", 0},
    {"textbg", cmd_textbg, "textbg #RRGGBB|#AARRGGBB|none", 0},
    {0, 0, 0, 0},
};
