/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the fill module: polygons, triangles, Gouraud
 * shading, blending and fill styles. The module's state (the pattern, the
 * style the context points at, a large edge table) lives in the arena. */
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/scene.h"
#include "scene_mesh.h"
#include "fixel/texture.h"
#include "../base/fx_internal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define MAX_VERTS 1024
#define PAT_MAX 32
#define TEX_MAX 256

typedef struct fill_state {
    fx_fill_style style;
    void *seed_work;
    size_t seed_size;
    fx_gradient grad;
    fx_proc_map proc;
    fx_texture tex;
    fx_tex_map texmap;
    int have_tex;
    uint32_t texpx[TEX_MAX * TEX_MAX];
    uint8_t bits[PAT_MAX * PAT_MAX / 8];
    int32_t xy[2 * MAX_VERTS];
    fx_color col[MAX_VERTS];
    fx_fill_edge edges[MAX_VERTS];
} fill_state;

static fill_state *state(fx_scene *sc)
{
    if (!sc->mod[FX_SCENE_MOD_FILL])
        sc->mod[FX_SCENE_MOD_FILL] = fx_scene_alloc(sc, sizeof(fill_state));
    if (!sc->mod[FX_SCENE_MOD_FILL])
        fx_scene_error(sc, "scene arena too small for the fill module");
    return sc->mod[FX_SCENE_MOD_FILL];
}

/* X Y pairs (with a colour after each when col is set) to the end of line. */
static int read_verts(fx_scene *sc, fill_state *st, int with_color, int frac, int32_t *n)
{
    int32_t k = 0;
    while (fx_scene_more(sc)) {
        if (k == MAX_VERTS)
            return fx_scene_error(sc, "more than %d vertices", MAX_VERTS);
        if (frac) {
            fx16 x, y;
            TRY(fx_scene_arg_fx16(sc, &x));
            TRY(fx_scene_arg_fx16(sc, &y));
            st->xy[2 * k] = (int32_t)(((int64_t)x + 128) >> 8); /* Q16.16 -> 24.8, nearest; */
            st->xy[2 * k + 1] = (int32_t)(((int64_t)y + 128) >> 8); /* x + 128 overflowed at 32767.99999 */
        } else {
            TRY(fx_scene_arg_int(sc, &st->xy[2 * k]));
            TRY(fx_scene_arg_int(sc, &st->xy[2 * k + 1]));
        }
        if (with_color)
            TRY(fx_scene_arg_color(sc, &st->col[k]));
        k++;
    }
    *n = k;
    return 0;
}

static const char *const rules[] = {"evenodd", "nonzero", 0};

static int fillpoly(fx_scene *sc, int frac)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int rule = fx_scene_arg_choice(sc, rules);
    TRY(rule);
    int32_t n;
    TRY(read_verts(sc, st, 0, frac, &n));
    if (n < 3)
        return fx_scene_error(sc, "a polygon needs at least 3 vertices");
    int r = fx_fill_path(&sc->ctx, st->xy, &n, 1, frac ? 8 : 0, (fx_fill_rule)rule, st->edges, MAX_VERTS);
    return r < 0 ? fx_scene_error(sc, "fill failed: %s", fx_strerror(r)) : 0;
}

static int cmd_fillpoly(fx_scene *sc) { return fillpoly(sc, 0); }
static int cmd_fillpolyf(fx_scene *sc) { return fillpoly(sc, 1); }

static int cmd_polygon(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int32_t n;
    TRY(read_verts(sc, st, 0, 0, &n));
    if (n < 2)
        return fx_scene_error(sc, "a polygon needs at least 2 vertices");
    fx_polygon(&sc->ctx, st->xy, n);
    return 0;
}

static int cmd_filltri(fx_scene *sc)
{
    int32_t v[6];
    for (int i = 0; i < 6; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    TRY(fx_scene_end(sc));
    fx_fill_tri(&sc->ctx, v[0], v[1], v[2], v[3], v[4], v[5]);
    return 0;
}

static int cmd_gouraudtri(fx_scene *sc)
{
    int32_t v[6];
    fx_color c[3];
    for (int i = 0; i < 3; i++) {
        TRY(fx_scene_arg_int(sc, &v[2 * i]));
        TRY(fx_scene_arg_int(sc, &v[2 * i + 1]));
        TRY(fx_scene_arg_color(sc, &c[i]));
    }
    TRY(fx_scene_end(sc));
    fx_fill_tri_gouraud(&sc->ctx, v, c);
    return 0;
}

static int cmd_gouraudpoly(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int32_t n;
    TRY(read_verts(sc, st, 1, 0, &n));
    if (n < 3)
        return fx_scene_error(sc, "a polygon needs at least 3 vertices");
    fx_fill_poly_gouraud(&sc->ctx, st->xy, st->col, n);
    return 0;
}

/* issue #44: the notes' scan-line Gouraud (fx_fill_poly_gouraud_scan) */
static int cmd_gouraudscan(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int32_t n;
    TRY(read_verts(sc, st, 1, 0, &n));
    if (n < 3)
        return fx_scene_error(sc, "a polygon needs at least 3 vertices");
    if (fx_fill_poly_gouraud_scan(&sc->ctx, st->xy, st->col, n) < 0)
        return fx_scene_error(sc, "vertex out of range (|X|, |Y| <= %d)", FX_GOURAUD_SCAN_COORD);
    return 0;
}

static int cmd_blend(fx_scene *sc)
{
    static const char *const modes[] = {"src", "over", 0};
    int m = fx_scene_arg_choice(sc, modes);
    TRY(m);
    TRY(fx_scene_end(sc));
    sc->ctx.blend = (uint8_t)(m == 1 ? FX_BLEND_OVER : FX_BLEND_SRC);
    return 0;
}

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b)
        a++, b++;
    return *a == *b;
}

/* The next argument starts with ch (after blanks). */
static int next_is(const fx_scene *sc, char ch)
{
    int p = sc->pos;
    while (p < sc->len && (sc->text[p] == ' ' || sc->text[p] == '\t'))
        p++;
    return p < sc->len && sc->text[p] == ch;
}

static int hexval(char ch)
{
    if (ch >= '0' && ch <= '9')
        return ch - '0';
    if (ch >= 'a' && ch <= 'f')
        return ch - 'a' + 10;
    if (ch >= 'A' && ch <= 'F')
        return ch - 'A' + 10;
    return -1;
}

/* pattern off | pattern bg #C|none | pattern anchor X Y | pattern W H ROW... */
/* hatch INTENSITY | hatch off: the pattern style of the cross-hatching
 * for that intensity (fill.h fx_hatch_style), in the pattern's storage */
static int cmd_hatch(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int p = sc->pos;
    while (p < sc->len && (sc->text[p] == ' ' || sc->text[p] == '\t'))
        p++;
    /* a number (the intensity) or a word ("off") */
    if (p < sc->len && sc->text[p] != '-' && sc->text[p] != '+' && (sc->text[p] < '0' || sc->text[p] > '9')) {
        char w[8];
        TRY(fx_scene_arg_word(sc, w, sizeof w));
        if (!streq(w, "off"))
            return fx_scene_error(sc, "expected off or an intensity 0..255");
        TRY(fx_scene_end(sc));
        sc->ctx.fill_style = 0;
        return 0;
    }
    int32_t v;
    TRY(fx_scene_arg_int(sc, &v));
    TRY(fx_scene_end(sc));
    if (v < 0 || v > 255)
        return fx_scene_error(sc, "intensity %d out of range (0..255)", v);
    fx_hatch_style(&st->style, st->bits, (uint8_t)v);
    sc->ctx.fill_style = &st->style;
    return 0;
}

static int cmd_pattern(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    char w[40];
    TRY(fx_scene_arg_word(sc, w, sizeof w));
    fx_fill_style *s = &st->style;
    if (streq(w, "off")) {
        TRY(fx_scene_end(sc));
        sc->ctx.fill_style = 0;
        return 0;
    }
    if (streq(w, "anchor")) {
        TRY(fx_scene_arg_int(sc, &s->ax));
        TRY(fx_scene_arg_int(sc, &s->ay));
        return fx_scene_end(sc);
    }
    if (streq(w, "bg")) {
        if (fx_scene_more(sc) && !next_is(sc, '#')) {
            char none[8];
            TRY(fx_scene_arg_word(sc, none, sizeof none));
            if (!streq(none, "none"))
                return fx_scene_error(sc, "expected a colour or 'none'");
            s->bg_transparent = 1;
        } else {
            TRY(fx_scene_arg_color(sc, &s->bg));
            s->bg_transparent = 0;
        }
        return fx_scene_end(sc);
    }
    int32_t pw = 0, ph;
    for (const char *p = w; *p; p++) {
        if (*p < '0' || *p > '9' || pw > PAT_MAX)
            return fx_scene_error(sc, "expected off, bg, anchor or a width 1..%d", PAT_MAX);
        pw = pw * 10 + (*p - '0');
    }
    TRY(fx_scene_arg_int(sc, &ph));
    if (pw < 1 || pw > PAT_MAX || ph < 1 || ph > PAT_MAX)
        return fx_scene_error(sc, "pattern size %dx%d out of range (1..%d)", pw, ph, PAT_MAX);
    int32_t stride = (pw + 7) / 8;
    for (int32_t j = 0; j < ph; j++) {
        char row[2 * PAT_MAX / 8 + 2];
        TRY(fx_scene_arg_word(sc, row, sizeof row));
        int32_t len = 0;
        while (row[len])
            len++;
        if (len != 2 * stride)
            return fx_scene_error(sc, "pattern row needs %d hex digits", 2 * stride);
        for (int32_t b = 0; b < stride; b++) {
            int hi = hexval(row[2 * b]), lo = hexval(row[2 * b + 1]);
            if (hi < 0 || lo < 0)
                return fx_scene_error(sc, "bad hex digit in pattern row '%s'", row);
            st->bits[j * stride + b] = (uint8_t)(hi << 4 | lo);
        }
    }
    TRY(fx_scene_end(sc));
    s->kind = FX_FILL_PATTERN;
    s->bits = st->bits;
    s->w = pw;
    s->h = ph;
    s->stride = stride;
    sc->ctx.fill_style = s;
    return 0;
}

static int seed(fx_scene *sc, int boundary)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    int32_t x, y, conn;
    fx_color b = 0;
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    if (boundary)
        TRY(fx_scene_arg_color(sc, &b));
    TRY(fx_scene_arg_int(sc, &conn));
    if (conn != 4 && conn != 8)
        return fx_scene_error(sc, "connectivity must be 4 or 8");
    TRY(fx_scene_end(sc));
    if (!st->seed_work) {
        /* sized for the whole surface once; the clip only ever shrinks it */
        fx_ctx whole = sc->ctx;
        fx_ctx_reset_clip(&whole);
        st->seed_size = fx_seed_work_size(&whole);
        st->seed_work = fx_scene_alloc(sc, st->seed_size);
        if (!st->seed_work)
            return fx_scene_error(sc, "scene arena too small for a seed fill (%lu bytes)",
                                  (unsigned long)st->seed_size);
    }
    int r = boundary ? fx_boundary_fill(&sc->ctx, x, y, b, conn, st->seed_work, st->seed_size)
                     : fx_flood_fill(&sc->ctx, x, y, conn, st->seed_work, st->seed_size);
    return r < 0 ? fx_scene_error(sc, "seed fill failed: %s", fx_strerror(r)) : 0;
}

static int cmd_flood(fx_scene *sc) { return seed(sc, 0); }
static int cmd_boundaryfill(fx_scene *sc) { return seed(sc, 1); }

static int style_off(fx_scene *sc)
{
    TRY(fx_scene_end(sc));
    sc->ctx.fill_style = 0;
    return 0;
}

/* gradient linear X0 Y0 X1 Y1 #C... | radial CX CY R #C... | off */
static int cmd_gradient(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    static const char *const kinds[] = {"linear", "radial", "off", 0};
    int k = fx_scene_arg_choice(sc, kinds);
    TRY(k);
    if (k == 2)
        return style_off(sc);
    fx_gradient *g = &st->grad;
    fx_memset(g, 0, sizeof *g);
    g->radial = (uint8_t)(k == 1);
    TRY(fx_scene_arg_int(sc, &g->x0));
    TRY(fx_scene_arg_int(sc, &g->y0));
    if (k == 1) {
        TRY(fx_scene_arg_int(sc, &g->r));
        if (g->r < 1)
            return fx_scene_error(sc, "radius must be >= 1");
    } else {
        TRY(fx_scene_arg_int(sc, &g->x1));
        TRY(fx_scene_arg_int(sc, &g->y1));
    }
    while (fx_scene_more(sc)) {
        if (g->nstops == FX_GRADIENT_MAX_STOPS)
            return fx_scene_error(sc, "more than %d colour stops", FX_GRADIENT_MAX_STOPS);
        TRY(fx_scene_arg_color(sc, &g->stops[g->nstops++]));
    }
    if (g->nstops < 2)
        return fx_scene_error(sc, "a gradient needs at least 2 colours");
    fx_fill_style *s = &st->style;
    s->kind = FX_FILL_SHADER;
    s->shade = fx_gradient_shade;
    s->user = g;
    sc->ctx.fill_style = s;
    return 0;
}

/* proctex KIND X0 Y0 SIZE #C0 #C1 [SEED] | off */
static int cmd_proctex(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    static const char *const kinds[] = {"fakesphere", "noise", "turbulence", "wood", "marble", "off", 0};
    int k = fx_scene_arg_choice(sc, kinds);
    TRY(k);
    if (k == FX_PROC_COUNT)
        return style_off(sc);
    fx_proc_map *m = &st->proc;
    m->kind = k;
    TRY(fx_scene_arg_int(sc, &m->x0));
    TRY(fx_scene_arg_int(sc, &m->y0));
    TRY(fx_scene_arg_int(sc, &m->size));
    if (m->size < 1)
        return fx_scene_error(sc, "size must be >= 1");
    TRY(fx_scene_arg_color(sc, &m->c0));
    TRY(fx_scene_arg_color(sc, &m->c1));
    int32_t seed = 1;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    m->seed = (uint32_t)seed;
    fx_fill_style *s = &st->style;
    s->kind = FX_FILL_SHADER;
    s->shade = fx_proc_shade;
    s->user = m;
    sc->ctx.fill_style = s;
    return 0;
}

/* texture checker W H CELL #C0 #C1 | texture KIND W H #C0 #C1 [SEED]
 * | texture filter nearest|bilinear | texture wrap repeat|clamp */
static int cmd_texture(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    static const char *const kinds[] = {"fakesphere", "noise", "turbulence", "wood", "marble", "checker",
                                        "filter", "wrap", "image", 0};
    int k = fx_scene_arg_choice(sc, kinds);
    TRY(k);
    if (k == 8) {
        char path[256];
        fx_surface img;
        TRY(fx_scene_arg_string(sc, path, sizeof path));
        TRY(fx_scene_end(sc));
        if (!sc->host.load_image)
            return fx_scene_error(sc, "images not available");
        int e = sc->host.load_image(sc->host.user, path, &img);
        if (e < 0)
            return fx_scene_error(sc, "cannot read image '%s': %s", path, fx_strerror(e));
        if (img.w < 1 || img.h < 1 || !img.pixels)
            return fx_scene_error(sc, "image '%s' is empty", path);
        st->tex.img = img;
        st->have_tex = 1;
        return 0;
    }
    if (k == 6 || k == 7) {
        static const char *const filters[] = {"nearest", "bilinear", 0}, *const wraps[] = {"repeat", "clamp", 0};
        int v = fx_scene_arg_choice(sc, k == 6 ? filters : wraps);
        TRY(v);
        TRY(fx_scene_end(sc));
        if (k == 6)
            st->tex.filter = (uint8_t)v;
        else
            st->tex.wrap = (uint8_t)v;
        return 0;
    }
    int32_t w, h, cell = 1, seed = 1;
    fx_color c0, c1;
    TRY(fx_scene_arg_int(sc, &w));
    TRY(fx_scene_arg_int(sc, &h));
    if (w < 1 || h < 1 || w > TEX_MAX || h > TEX_MAX)
        return fx_scene_error(sc, "texture size %dx%d out of range (1..%d)", w, h, TEX_MAX);
    if (k == 5) {
        TRY(fx_scene_arg_int(sc, &cell));
        if (cell < 1)
            return fx_scene_error(sc, "cell must be >= 1");
    }
    TRY(fx_scene_arg_color(sc, &c0));
    TRY(fx_scene_arg_color(sc, &c1));
    if (k != 5 && fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    uint8_t filter = st->tex.filter, wrap = st->tex.wrap;
    fx_surface_init(&st->tex.img, st->texpx, w, h, w * 4, FX_FMT_ARGB8888);
    if (k == 5)
        fx_tex_checker(&st->tex.img, cell, c0, c1);
    else
        for (int32_t y = 0; y < h; y++)
            for (int32_t x = 0; x < w; x++) { /* texel centres sample the unit square */
                fx16 s = (fx16)(((int64_t)x * 2 + 1) * FX16_ONE / (2 * w));
                fx16 t = (fx16)(((int64_t)y * 2 + 1) * FX16_ONE / (2 * h));
                st->texpx[y * w + x] = fx_color_lerp(c0, c1, fx_proc_eval(k, s, t, (uint32_t)seed));
            }
    st->tex.filter = filter;
    st->tex.wrap = wrap;
    st->have_tex = 1;
    return 0;
}

const fx_texture *fx_scene_texture(fx_scene *sc)
{
    const fill_state *st = sc->mod[FX_SCENE_MOD_FILL];
    return st && st->have_tex ? &st->tex : NULL;
}

static int need_tex(fx_scene *sc, fill_state *st)
{
    return st->have_tex ? 0 : fx_scene_error(sc, "no texture yet (use 'texture' first)");
}

/* textri X0 Y0 S0 T0 X1 Y1 S1 T1 X2 Y2 S2 T2 | texpoly X Y S T ... */
static int textured(fx_scene *sc, int poly)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    TRY(need_tex(sc, st));
    fx16 stv[2 * 64];
    int32_t xy[2 * 64], n = 0;
    while (fx_scene_more(sc) && n < 64) {
        TRY(fx_scene_arg_int(sc, &xy[2 * n]));
        TRY(fx_scene_arg_int(sc, &xy[2 * n + 1]));
        TRY(fx_scene_arg_fx16(sc, &stv[2 * n]));
        TRY(fx_scene_arg_fx16(sc, &stv[2 * n + 1]));
        n++;
    }
    TRY(fx_scene_end(sc));
    if (poly ? n < 3 : n != 3)
        return fx_scene_error(sc, poly ? "texpoly needs at least 3 vertices" : "textri needs 3 vertices");
    fx_fill_poly_tex(&sc->ctx, xy, stv, n, &st->tex);
    return 0;
}

static int cmd_textri(fx_scene *sc) { return textured(sc, 0); }
static int cmd_texpoly(fx_scene *sc) { return textured(sc, 1); }

/* texstyle X0 Y0 SIZE | off: the texture tiled in surface space, one copy
 * per SIZE pixels from (X0, Y0), as the fill style */
static int cmd_texstyle(fx_scene *sc)
{
    fill_state *st = state(sc);
    if (!st)
        return -FX_ENOMEM;
    char w[16];
    int32_t x0, y0, size;
    int num = next_is(sc, '-');
    for (char d = '0'; d <= '9'; d++)
        num |= next_is(sc, d);
    if (!num) {
        TRY(fx_scene_arg_word(sc, w, sizeof w));
        if (!streq(w, "off"))
            return fx_scene_error(sc, "expected X0 Y0 SIZE or off");
        return style_off(sc);
    }
    TRY(need_tex(sc, st));
    TRY(fx_scene_arg_int(sc, &x0));
    TRY(fx_scene_arg_int(sc, &y0));
    TRY(fx_scene_arg_int(sc, &size));
    TRY(fx_scene_end(sc));
    if (size < 1)
        return fx_scene_error(sc, "size must be >= 1");
    fx_tex_map *m = &st->texmap;
    fx_memset(m, 0, sizeof *m);
    m->tex = &st->tex;
    m->dsdx = m->dtdy = FX16_ONE / size;
    m->s0 = fx_sat32(-(int64_t)x0 * m->dsdx); /* 40000 * 65536 overflowed int32 */
    m->t0 = fx_sat32(-(int64_t)y0 * m->dtdy);
    fx_fill_style *s = &st->style;
    s->kind = FX_FILL_SHADER;
    s->shade = fx_tex_shade;
    s->user = m;
    sc->ctx.fill_style = s;
    return 0;
}

const fx_scene_cmd fx_scene_cmds_fill[] = {
    {"gradient", cmd_gradient, "gradient linear X0 Y0 X1 Y1 #C0 #C1 ... | radial CX CY R #C0 #C1 ... | off",
     FX_SCENE_DRAWS},
    {"proctex", cmd_proctex, "proctex fakesphere|noise|turbulence|wood|marble X0 Y0 SIZE #C0 #C1 [SEED] | off",
     FX_SCENE_DRAWS},
    {"texture", cmd_texture,
     "texture checker W H CELL #C0 #C1 | texture fakesphere|noise|turbulence|wood|marble W H #C0 #C1 [SEED] | "
     "texture filter nearest|bilinear | texture wrap repeat|clamp | texture image PATH",
     0},
    {"textri", cmd_textri, "textri X0 Y0 S0 T0 X1 Y1 S1 T1 X2 Y2 S2 T2", FX_SCENE_DRAWS},
    {"texpoly", cmd_texpoly, "texpoly X0 Y0 S0 T0 X1 Y1 S1 T1 ... (convex)", FX_SCENE_DRAWS},
    {"texstyle", cmd_texstyle, "texstyle X0 Y0 SIZE | off", FX_SCENE_DRAWS},
    {"flood", cmd_flood, "flood X Y 4|8", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"boundaryfill", cmd_boundaryfill, "boundaryfill X Y #BOUNDARY 4|8", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"fillpoly", cmd_fillpoly, "fillpoly evenodd|nonzero X0 Y0 X1 Y1 X2 Y2 ...", FX_SCENE_DRAWS},
    {"fillpolyf", cmd_fillpolyf, "fillpolyf evenodd|nonzero X0 Y0 ... (fractional pixel-centre coordinates)",
     FX_SCENE_DRAWS},
    {"polygon", cmd_polygon, "polygon X0 Y0 X1 Y1 ...", FX_SCENE_DRAWS},
    {"filltri", cmd_filltri, "filltri X0 Y0 X1 Y1 X2 Y2", FX_SCENE_DRAWS},
    {"gouraudtri", cmd_gouraudtri, "gouraudtri X0 Y0 #C0 X1 Y1 #C1 X2 Y2 #C2", FX_SCENE_DRAWS},
    {"gouraudpoly", cmd_gouraudpoly, "gouraudpoly X0 Y0 #C0 X1 Y1 #C1 ... (convex)", FX_SCENE_DRAWS},
    /* issue #44 */
    {"gouraudscan", cmd_gouraudscan,
     "gouraudscan X0 Y0 #C0 X1 Y1 #C1 ... (convex; the notes' scan-line Gouraud: along the edges, then across "
     "each span, where gouraudpoly splits into a fan of triangles)",
     FX_SCENE_DRAWS},
    {"blend", cmd_blend, "blend src|over", FX_SCENE_DRAWS},
    {"pattern", cmd_pattern, "pattern off | W H HEXROW... | bg #C|none | anchor X Y", FX_SCENE_DRAWS},
    /* DRAWS: a style set before the surface exists would be lost when it is made */
    {"hatch", cmd_hatch, "hatch INTENSITY | hatch off", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
