/* fixel — scene commands of the fill module: polygons, triangles, Gouraud
 * shading, blending and fill styles. The module's state (the pattern, the
 * style the context points at, a large edge table) lives in the arena. */
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/scene.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define MAX_VERTS 1024
#define PAT_MAX 32

typedef struct fill_state {
    fx_fill_style style;
    void *seed_work;
    size_t seed_size;
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
            st->xy[2 * k] = (x + 128) >> 8; /* Q16.16 -> 24.8, nearest */
            st->xy[2 * k + 1] = (y + 128) >> 8;
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

const fx_scene_cmd fx_scene_cmds_fill[] = {
    {"flood", cmd_flood, "flood X Y 4|8", FX_SCENE_DRAWS},
    {"boundaryfill", cmd_boundaryfill, "boundaryfill X Y #BOUNDARY 4|8", FX_SCENE_DRAWS},
    {"fillpoly", cmd_fillpoly, "fillpoly evenodd|nonzero X0 Y0 X1 Y1 X2 Y2 ...", FX_SCENE_DRAWS},
    {"fillpolyf", cmd_fillpolyf, "fillpolyf evenodd|nonzero X0 Y0 ... (fractional pixel-centre coordinates)",
     FX_SCENE_DRAWS},
    {"polygon", cmd_polygon, "polygon X0 Y0 X1 Y1 ...", FX_SCENE_DRAWS},
    {"filltri", cmd_filltri, "filltri X0 Y0 X1 Y1 X2 Y2", FX_SCENE_DRAWS},
    {"gouraudtri", cmd_gouraudtri, "gouraudtri X0 Y0 #C0 X1 Y1 #C1 X2 Y2 #C2", FX_SCENE_DRAWS},
    {"gouraudpoly", cmd_gouraudpoly, "gouraudpoly X0 Y0 #C0 X1 Y1 #C1 ... (convex)", FX_SCENE_DRAWS},
    {"blend", cmd_blend, "blend src|over", FX_SCENE_DRAWS},
    {"pattern", cmd_pattern, "pattern off | W H HEXROW... | bg #C|none | anchor X Y", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
