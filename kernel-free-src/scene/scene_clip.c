/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the clip module: clip windows and their stack,
 * the line clipper, exterior clipping, polygon clipping, and the current
 * transform (a stack of 3x3 matrices, window-to-viewport as its base).
 *
 * Transform commands post-multiply the current transform (CTM = CTM . T), so
 * the command written last acts on the points first, as in OpenGL:
 * "translate 100 50" then "rotate 30" turns a shape about the origin and then
 * moves it. Drawing commands of every module map their coordinates through
 * it (fx_ctx_map / fx_xform2_apply on sc->ctx.xform).
 *
 * Script windows are given by two corner pixels, both inclusive, in either
 * order (the course's xwmin..xwmax): "clip 10 10 50 40" keeps pixels 10..50
 * and 10..40. The context stores the half-open fx_rect {10, 10, 51, 41}. */
#include "fixel/clip.h"
#include "fixel/line.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/xform.h"
#include "../base/fx_internal.h"
#include "scene_frame.h"
#include "scene_shared.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define CLIP_DEPTH 32
#define XFORM_DEPTH 32
#define POLY_MAX 64

typedef struct clip_state {
    fx_rect saved[CLIP_DEPTH];
    fx_clip_stack stack;
    fx_rect ext;
    int have_ext;
    fx_xform2 cur, base;          /* the CTM; base = window-to-viewport or I */
    fx_xform2 xstack[XFORM_DEPTH];
    int xn;
    fx16 win[4];
    int have_win;
    int32_t par_num, par_den; /* pixel aspect ratio, 'pixelaspect' */
} clip_state;

static clip_state *state(fx_scene *sc)
{
    clip_state *st = sc->mod[FX_SCENE_MOD_CLIP];
    if (!st) {
        st = fx_scene_alloc(sc, sizeof *st);
        if (!st)
            return 0;
        fx_clip_stack_init(&st->stack, st->saved, CLIP_DEPTH);
        fx_xform2_identity(&st->cur);
        fx_xform2_identity(&st->base);
        st->par_num = st->par_den = 1;
        sc->mod[FX_SCENE_MOD_CLIP] = st;
    }
    sc->ctx.xform = &st->cur;
    return st;
}

#define STATE(st)                                                      \
    clip_state *st = state(sc);                                        \
    if (!st)                                                           \
        return fx_scene_error(sc, "scene arena full (clip state)")

fx_xform2 *fx_scene_ctm(fx_scene *sc)
{
    clip_state *st = state(sc);
    if (!st) {
        fx_scene_error(sc, "scene arena full (clip state)");
        return 0;
    }
    return &st->cur;
}

/* Four integers: two inclusive corner pixels -> half-open rectangle. */
static int arg_window(fx_scene *sc, fx_rect *r)
{
    int32_t v[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    int64_t x0 = FX_MIN(v[0], v[2]), x1 = (int64_t)FX_MAX(v[0], v[2]) + 1;
    int64_t y0 = FX_MIN(v[1], v[3]), y1 = (int64_t)FX_MAX(v[1], v[3]) + 1;
    r->x0 = (int32_t)x0;
    r->y0 = (int32_t)y0;
    r->x1 = fx_sat32(x1);
    r->y1 = fx_sat32(y1);
    return 0;
}

/* A leading keyword, or -1 (and nothing consumed) when the next token is not
 * one of them. */
static int keyword(fx_scene *sc, const char *const *words)
{
    int save = sc->pos;
    char w[16];
    if (!fx_scene_more(sc) || fx_scene_arg_word(sc, w, sizeof w) < 0) {
        sc->pos = save;
        return -1;
    }
    for (int i = 0; words[i]; i++) {
        const char *a = words[i], *b = w;
        while (*a && *a == *b)
            a++, b++;
        if (!*a && !*b)
            return i;
    }
    sc->pos = save;
    return -1;
}

static int cmd_clip(fx_scene *sc)
{
    static const char *const words[] = {"off", "push", "pop", 0};
    STATE(st);
    fx_rect r;
    int k = keyword(sc, words);
    if (k == 0 || k == 2) {
        TRY(fx_scene_end(sc));
        if (k == 0) {
            fx_ctx_reset_clip(&sc->ctx);
            st->stack.n = 0;
            return 0;
        }
        if (fx_clip_pop(&st->stack, &sc->ctx) < 0)
            return fx_scene_error(sc, "'clip pop' without a matching 'clip push'");
        return 0;
    }
    TRY(arg_window(sc, &r));
    TRY(fx_scene_end(sc));
    if (k == 1) {
        if (fx_clip_push(&st->stack, &sc->ctx, r) < 0)
            return fx_scene_error(sc, "clip stack full (%d windows)", CLIP_DEPTH);
        return 0;
    }
    fx_ctx_set_clip(&sc->ctx, r);
    if (fx_rect_empty(sc->ctx.clip))
        sc->ctx.clip.x1 = sc->ctx.clip.x0, sc->ctx.clip.y1 = sc->ctx.clip.y0;
    return 0;
}

static int cmd_cliplines(fx_scene *sc)
{
    static const char *const names[] = {"direct", "cohen", "liang", "nln", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    TRY(fx_scene_end(sc));
    sc->ctx.line_clipper = (uint8_t)k;
    return 0;
}

static int cmd_exterior(fx_scene *sc)
{
    static const char *const words[] = {"on", "off", 0};
    STATE(st);
    int k = keyword(sc, words);
    if (k >= 0) {
        TRY(fx_scene_end(sc));
        if (k == 1) {
            fx_ctx_exterior_off(&sc->ctx);
            return 0;
        }
        if (!st->have_ext)
            return fx_scene_error(sc, "'exterior on' needs a window first: exterior X0 Y0 X1 Y1");
        fx_ctx_exterior(&sc->ctx, st->ext);
        return 0;
    }
    TRY(arg_window(sc, &st->ext));
    TRY(fx_scene_end(sc));
    st->have_ext = 1;
    fx_ctx_exterior(&sc->ctx, st->ext);
    return 0;
}

/* ---- polygons ---- */

/* Q16.16 vertex pairs to the end of the line, through the CTM. */
static int arg_poly(fx_scene *sc, clip_state *st, fx_pt16 *p, int *n)
{
    int k = 0;
    while (fx_scene_more(sc)) {
        if (k == POLY_MAX)
            return fx_scene_error(sc, "too many vertices (at most %d)", POLY_MAX);
        TRY(fx_scene_arg_fx16(sc, &p[k].x));
        TRY(fx_scene_arg_fx16(sc, &p[k].y));
        k++;
    }
    if (k < 3)
        return fx_scene_error(sc, "a polygon needs at least 3 vertices");
    TRY(fx_scene_end(sc));
    fx_xform2_apply_pts(&st->cur, p, p, k);
    *n = k;
    return 0;
}

static int32_t clamp32(int32_t v, int32_t lo, int32_t hi) { return v < lo ? lo : v > hi ? hi : v; }

/* Vertices round to pixel centres. A clipped polygon (in, non-NULL) lies in
 * the pixel squares of the window, [x0 - 1/2, x1 - 1/2]: its left and top
 * borders round half a pixel in to the first column and row, and the right
 * and bottom ones must come half a pixel in too, to the last column and
 * row, or their lines fall just outside the clip and vanish (issue #44:
 * 40 pixels in the left column, 1 in the right one). */
static void outline(const fx_ctx *c, const fx_pt16 *p, const int *starts, int npieces, int closed, const fx_rect *in)
{
    for (int pc = 0; pc < npieces; pc++) {
        int a = starts[pc], n = starts[pc + 1] - a;
        for (int i = 0; i + (closed ? 0 : 1) < n; i++) {
            fx_pt16 u = p[a + i], v = p[a + (i + 1) % n];
            int32_t x0 = fx16_round(u.x), y0 = fx16_round(u.y), x1 = fx16_round(v.x), y1 = fx16_round(v.y);
            if (in) {
                x0 = clamp32(x0, in->x0, in->x1 - 1), x1 = clamp32(x1, in->x0, in->x1 - 1);
                y0 = clamp32(y0, in->y0, in->y1 - 1), y1 = clamp32(y1, in->y0, in->y1 - 1);
            }
            fx_line(c, x0, y0, x1, y1);
        }
    }
}

static int cmd_clippoly(fx_scene *sc)
{
    static const char *const algos[] = {"sh", "wa", 0};
    static const char *const modes[] = {"fill", "outline", 0};
    STATE(st);
    int algo = fx_scene_arg_choice(sc, algos);
    TRY(algo);
    int mode = fx_scene_arg_choice(sc, modes);
    TRY(mode);
    fx_pt16 p[POLY_MAX], out[12 * POLY_MAX];
    int n, starts[POLY_MAX + 2], np;
    TRY(arg_poly(sc, st, p, &n));
    if (algo == 0) {
        int m = fx_clip_poly_sh(sc->ctx.clip, p, n, out, 12 * POLY_MAX);
        if (m < 0)
            return fx_scene_error(sc, "clipped polygon too large");
        np = m > 0;
        starts[0] = 0;
        starts[1] = m;
    } else {
        uint64_t work[(12 * POLY_MAX * 8 + 7) / 8 + 64];
        np = fx_clip_poly_pieces(sc->ctx.clip, p, n, out, 12 * POLY_MAX, starts, POLY_MAX + 1, work,
                                 sizeof work);
        if (np < 0)
            return fx_scene_error(sc, "clipped polygon too large");
    }
    fx_trace(&sc->ctx, "clippoly %s: %d vertices -> %d piece%s, %d vertices", algos[algo], n, np,
             np == 1 ? "" : "s", np ? starts[np] : 0);
    if (mode == 0)
        return fx_poly_fill16(&sc->ctx, out, starts, np);
    outline(&sc->ctx, out, starts, np, 1, &sc->ctx.clip);
    return 0;
}

static int cmd_xpoly(fx_scene *sc)
{
    static const char *const modes[] = {"fill", "outline", "open", 0};
    STATE(st);
    int mode = fx_scene_arg_choice(sc, modes);
    TRY(mode);
    fx_pt16 p[POLY_MAX];
    int n;
    TRY(arg_poly(sc, st, p, &n));
    int starts[2] = {0, n};
    if (mode == 0)
        return fx_poly_fill16(&sc->ctx, p, starts, 1);
    outline(&sc->ctx, p, starts, 1, mode == 1, NULL);
    return 0;
}

/* ---- the current transform ---- */

static int cmd_push(fx_scene *sc)
{
    STATE(st);
    TRY(fx_scene_end(sc));
    if (st->xn == XFORM_DEPTH)
        return fx_scene_error(sc, "transform stack full (%d)", XFORM_DEPTH);
    st->xstack[st->xn++] = st->cur;
    return 0;
}

static int cmd_pop(fx_scene *sc)
{
    STATE(st);
    TRY(fx_scene_end(sc));
    if (!st->xn)
        return fx_scene_error(sc, "'pop' without a matching 'push'");
    st->cur = st->xstack[--st->xn];
    return 0;
}

static int cmd_identity(fx_scene *sc)
{
    STATE(st);
    TRY(fx_scene_end(sc));
    st->cur = st->base;
    return 0;
}

static int cmd_translate(fx_scene *sc)
{
    STATE(st);
    fx16 tx, ty;
    TRY(fx_scene_arg_fx16(sc, &tx));
    TRY(fx_scene_arg_fx16(sc, &ty));
    TRY(fx_scene_end(sc));
    fx_xform2 t;
    fx_xform2_translation(&t, tx, ty);
    fx_xform2_pre(&st->cur, &t);
    return 0;
}

static int cmd_scale(fx_scene *sc)
{
    STATE(st);
    fx16 sx, sy, px = 0, py = 0;
    TRY(fx_scene_arg_fx16(sc, &sx));
    sy = sx;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &sy));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx16(sc, &px));
        TRY(fx_scene_arg_fx16(sc, &py));
    }
    TRY(fx_scene_end(sc));
    fx_xform2 t;
    fx_xform2_scaling(&t, sx, sy, px, py);
    fx_xform2_pre(&st->cur, &t);
    return 0;
}

static int cmd_rotate(fx_scene *sc)
{
    STATE(st);
    fx16 deg, px = 0, py = 0;
    TRY(fx_scene_arg_fx16(sc, &deg));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx16(sc, &px));
        TRY(fx_scene_arg_fx16(sc, &py));
    }
    TRY(fx_scene_end(sc));
    fx_xform2 t;
    fx_xform2_rotation(&t, fx_angle_from_deg16(deg), px, py);
    fx_xform2_pre(&st->cur, &t);
    return 0;
}

static int cmd_shear(fx_scene *sc)
{
    static const char *const axes[] = {"x", "y", 0};
    STATE(st);
    int ax = fx_scene_arg_choice(sc, axes);
    TRY(ax);
    fx16 sh, ref = 0;
    TRY(fx_scene_arg_fx16(sc, &sh));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &ref));
    TRY(fx_scene_end(sc));
    fx_xform2 t;
    if (ax == 0)
        fx_xform2_shear_x(&t, sh, ref);
    else
        fx_xform2_shear_y(&t, sh, ref);
    fx_xform2_pre(&st->cur, &t);
    return 0;
}

static int cmd_reflect(fx_scene *sc)
{
    static const char *const kinds[] = {"x", "y", "origin", "diagonal", "line", 0};
    STATE(st);
    int k = fx_scene_arg_choice(sc, kinds);
    TRY(k);
    fx_xform2 t;
    if (k == 4) {
        fx16 v[4];
        for (int i = 0; i < 4; i++)
            TRY(fx_scene_arg_fx16(sc, &v[i]));
        TRY(fx_scene_end(sc));
        int64_t dx = (int64_t)v[2] - v[0], dy = (int64_t)v[3] - v[1];
        if (!dx && !dy)
            return fx_scene_error(sc, "the line needs two different points");
        while (dx > INT32_MAX || dx < -INT32_MAX || dy > INT32_MAX || dy < -INT32_MAX)
            dx /= 2, dy /= 2; /* the direction is all that matters */
        fx_xform2_reflection_line(&t, v[0], v[1], fx_atan2((int32_t)dy, (int32_t)dx));
    } else {
        TRY(fx_scene_end(sc));
        fx_xform2_reflection(&t, (fx_reflect)k);
    }
    fx_xform2_pre(&st->cur, &t);
    return 0;
}

static int cmd_window(fx_scene *sc)
{
    STATE(st);
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_fx16(sc, &st->win[i]));
    TRY(fx_scene_end(sc));
    if (st->win[0] == st->win[2] || st->win[1] == st->win[3])
        return fx_scene_error(sc, "the world window has no area");
    st->have_win = 1;
    return 0;
}

static int cmd_viewport(fx_scene *sc)
{
    static const char *const words[] = {"off", 0};
    static const char *const opts[] = {"aspect", 0};
    STATE(st);
    if (keyword(sc, words) == 0) {
        TRY(fx_scene_end(sc));
        fx_xform2_identity(&st->base);
        st->cur = st->base;
        fx_ctx_reset_clip(&sc->ctx);
        return 0;
    }
    fx_rect r;
    TRY(arg_window(sc, &r));
    int aspect = 0;
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_choice(sc, opts));
        aspect = 1;
    }
    TRY(fx_scene_end(sc));
    if (!st->have_win)
        return fx_scene_error(sc, "'viewport' needs a world 'window' first");
    if (r.x0 < -32767 || r.x1 > 32767 || r.y0 < -32767 || r.y1 > 32767)
        return fx_scene_error(sc, "viewport outside the Q16.16 range");
    if (fx_xform2_window_viewport_par(&st->base, st->win[0], st->win[1], st->win[2], st->win[3],
                                      fx16_from_int(r.x0), fx16_from_int(r.y0), fx16_from_int(r.x1 - 1),
                                      fx16_from_int(r.y1 - 1), aspect, st->par_num, st->par_den) < 0)
        return fx_scene_error(sc, "the world window has no area");
    st->cur = st->base;
    /* The course clips against the window before mapping; clipping against
     * the viewport after mapping removes the same points. */
    fx_ctx_set_clip(&sc->ctx, r);
    return 0;
}

/* Non-square pixels: later 'viewport ... aspect' mappings and 3D
 * projections draw x at NUM/DEN of the y scale. */
static int cmd_pixelaspect(fx_scene *sc)
{
    STATE(st);
    int32_t n, d;
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_arg_int(sc, &d));
    TRY(fx_scene_end(sc));
    if (n < 1 || d < 1 || n > FX_PAR_MAX || d > FX_PAR_MAX)
        return fx_scene_error(sc, "pixelaspect %d %d out of range (1..%d each)", n, d, FX_PAR_MAX);
    st->par_num = n;
    st->par_den = d;
    return 0;
}

void fx_scene_pixel_aspect(fx_scene *sc, int32_t *num, int32_t *den)
{
    const clip_state *st = sc->mod[FX_SCENE_MOD_CLIP];
    *num = st ? st->par_num : 1;
    *den = st ? st->par_den : 1;
}

const fx_scene_cmd fx_scene_cmds_clip[] = {
    {"clip", cmd_clip, "clip X0 Y0 X1 Y1 (inclusive corners) | clip off | clip push X0 Y0 X1 Y1 | clip pop",
     FX_SCENE_DRAWS},
    {"cliplines", cmd_cliplines, "cliplines direct|cohen|liang|nln", FX_SCENE_DRAWS},
    {"exterior", cmd_exterior, "exterior X0 Y0 X1 Y1 (draw only outside; inclusive corners) | exterior on|off",
     FX_SCENE_DRAWS},
    {"clippoly", cmd_clippoly,
     "clippoly sh|wa fill|outline X0 Y0 X1 Y1 X2 Y2 ... (clip to the clip window; sh = Sutherland-Hodgman, wa = "
     "Weiler-Atherton pieces)", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"xpoly", cmd_xpoly, "xpoly fill|outline|open X0 Y0 X1 Y1 ... (Q16.16 vertices through the transform)",
     FX_SCENE_DRAWS},
    {"push", cmd_push, "push (save the current transform)", FX_SCENE_DRAWS},
    {"pop", cmd_pop, "pop (restore the saved transform)", FX_SCENE_DRAWS},
    {"identity", cmd_identity, "identity (back to the window-to-viewport mapping, or none)", FX_SCENE_DRAWS},
    {"translate", cmd_translate, "translate TX TY", FX_SCENE_DRAWS},
    {"scale", cmd_scale, "scale SX [SY [PX PY]] (about the fixed point PX PY)", FX_SCENE_DRAWS},
    {"rotate", cmd_rotate,
     "rotate DEGREES [PX PY] (from +x towards +y: clockwise on screen; counter-clockwise after 'coords course')",
     FX_SCENE_DRAWS},
    {"shear", cmd_shear, "shear x|y SH [REF] (relative to the line y = REF or x = REF)", FX_SCENE_DRAWS},
    {"reflect", cmd_reflect, "reflect x|y|origin|diagonal | reflect line X0 Y0 X1 Y1", FX_SCENE_DRAWS},
    {"window", cmd_window, "window WX0 WY0 WX1 WY1 (world coordinates for 'viewport')", FX_SCENE_DRAWS},
    {"viewport", cmd_viewport, "viewport X0 Y0 X1 Y1 [aspect] | viewport off", FX_SCENE_DRAWS},
    {"pixelaspect", cmd_pixelaspect,
     "pixelaspect NUM DEN (non-square pixels: x drawn NUM/DEN of y by 'viewport ... aspect' and 3D projections)",
     FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
