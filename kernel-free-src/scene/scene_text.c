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

static int cmd_font(fx_scene *sc)
{
    char path[512];
    text_state *t;
    if (quoted_next(sc))
        TRY(fx_scene_arg_string(sc, path, sizeof path));
    else
        TRY(fx_scene_arg_word(sc, path, sizeof path));
    TRY(fx_scene_end(sc));
    TRY(need_state(sc, &t));
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

static int cmd_text(fx_scene *sc)
{
    int32_t x, y;
    char s[2048];
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_arg_string(sc, s, sizeof s));
    TRY(fx_scene_end(sc));
    text_state *t = sc->mod[FX_SCENE_MOD_TEXT];
    sc->ctx.text_style = t ? &t->st : 0;
    fx_text(&sc->ctx, x, y, s);
    return 0;
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
    {"font", cmd_font, "font builtin|PATH|\"PATH\"   (PSF1/PSF2, .psf.gz in fixel-draw)", 0},
    {"text", cmd_text, "text X Y \"STRING\"   (top-left corner; \\n starts a new line)", FX_SCENE_DRAWS},
    {"textclip", cmd_textclip, "textclip pixel|char|string", FX_SCENE_SERIAL},
    {"textscale", cmd_textscale, "textscale N", 0},
    {"textbg", cmd_textbg, "textbg #RRGGBB|#AARRGGBB|none", 0},
    {0, 0, 0, 0},
};
