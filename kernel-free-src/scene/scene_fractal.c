/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the fractal module: escape-time sets and the
 * colour-map setting they share with the viz commands, Koch curves, random
 * fractals, IFS and space-filling curves. */
#include "fixel/colormap.h"
#include "fixel/error.h"
#include "fixel/fractal.h"
#include "fixel/ifs.h"
#include "fixel/koch.h"
#include "fixel/scene.h"
#include "fixel/boxdim.h"
#include "fixel/circle.h"
#include "fixel/collage.h"
#include "fixel/julia.h"
#include "fixel/line.h"
#include "fixel/randfract.h"
#include "fixel/turtle.h"
#include "scene_mesh.h"
#include "scene_fractal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

static const fx_scene_fractal defaults = {FX_CMAP_COUNT, 0, 0xFF000000u, 0, {{0}}, {0, 0, 65536, 65536}, {0, 0, 0, 0, 0}, 0, 0};

const fx_scene_fractal *fx_scene_fractal_state(fx_scene *sc)
{
    return sc->mod[FX_SCENE_MOD_FRACTAL] ? sc->mod[FX_SCENE_MOD_FRACTAL] : &defaults;
}

static fx_scene_fractal *state(fx_scene *sc)
{
    if (!sc->mod[FX_SCENE_MOD_FRACTAL]) {
        fx_scene_fractal *st = fx_scene_alloc(sc, sizeof *st);
        if (!st)
            return 0;
        *st = defaults;
        sc->mod[FX_SCENE_MOD_FRACTAL] = st;
    }
    return sc->mod[FX_SCENE_MOD_FRACTAL];
}

static int cmd_colormap(fx_scene *sc)
{
    char name[32];
    int32_t period = 0;
    TRY(fx_scene_arg_word(sc, name, sizeof name));
    fx_cmap m = fx_cmap_from_name(name);
    int w9 = name[0] == 'w' && name[1] == '9' && !name[2];
    if (m == FX_CMAP_COUNT && !w9)
        return fx_scene_error(sc, "unknown colour map '%s' (grey|hot|viridis|hsv|w9)", name);
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_int(sc, &period));
        if (period < 1 || period > 1 << 20)
            return fx_scene_error(sc, "colour-map period %d out of range (1..1048576)", period);
    }
    TRY(fx_scene_end(sc));
    fx_scene_fractal *st = state(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    st->cmap = m;
    st->period = (uint32_t)period;
    return 0;
}

static int cmd_insidecolor(fx_scene *sc)
{
    fx_color c;
    TRY(fx_scene_arg_color(sc, &c));
    TRY(fx_scene_end(sc));
    fx_scene_fractal *st = state(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    st->inside = c;
    return 0;
}

/* The dwell colours of the scene's colour map (W9 grey by default): a
 * period cycles through the map every `period` iterations; without one the
 * map spans the dwells 0..maxiter-1 once. */
static void dwell_pal(fx_scene *sc, fx_dwell_pal *pal, uint32_t lut[256], uint32_t maxiter)
{
    const fx_scene_fractal *st = fx_scene_fractal_state(sc);
    const fx_surface *s = &sc->ctx.surf;
    if (st->cmap == FX_CMAP_COUNT) {
        fx_dwell_pal_w9(pal, lut, s->format);
    } else {
        fx_color tab[256];
        fx_cmap_table(st->cmap, tab, 256);
        for (int i = 0; i < 256; i++)
            lut[i] = fx_pack(s->format, tab[i]);
        pal->lut = lut;
        pal->len = 256;
        uint32_t span = st->period ? st->period : maxiter;
        pal->mul = (uint32_t)(((uint64_t)256 << 16) / span);
        if (pal->mul == 0)
            pal->mul = 1;
        pal->wrap = st->period != 0;
    }
    pal->inside = fx_pack(s->format, st->inside);
}

/* One part of c=RE,IM within +-lim. */
static int c_part(fx_scene *sc, const char *t, int l, const char *name, int lim, fx56 *v)
{
    int n = fx56_parse(t, l, v);
    if (n == -FX_ERANGE || (n == l && (*v < -(fx56)lim * FX56_ONE || *v > (fx56)lim * FX56_ONE)))
        return fx_scene_error(sc, "c=RE,IM: %s %.*s out of range, expected -%d..%d", name, l > 40 ? 40 : l, t, lim,
                              lim);
    if (n != l || l == 0)
        return fx_scene_error(sc, "c=RE,IM: %s: expected a decimal number, got '%.*s'", name, l > 40 ? 40 : l, t);
    return 0;
}

/* The Julia commands' arguments (issue #44): CENTRE_RE CENTRE_IM C_RE C_IM
 * WIDTH, the view centre first as in 'mandelbrot'; or c first, in the form
 * c=C_RE,C_IM CENTRE_RE CENTRE_IM WIDTH, which cannot be taken for a centre
 * (typing c in the centre's place used to draw c = 0's set without a word).
 * a[] = the centre, c, the width; lim bounds the parts of c. */
static int julia_args(fx_scene *sc, fx56 a[5], int lim)
{
    char w[96];
    int save = sc->pos, have_c = 0;
    if (fx_scene_more(sc) && fx_scene_arg_word(sc, w, sizeof w) == 0 && w[0] == 'c' && w[1] == '=') {
        int n = 0, comma = -1;
        while (w[n]) {
            if (w[n] == ',' && comma < 0)
                comma = n;
            n++;
        }
        if (comma < 0)
            return fx_scene_error(sc, "expected c=RE,IM (c's real and imaginary parts), got '%s'", w);
        TRY(c_part(sc, w + 2, comma - 2, "RE", lim, &a[2]));
        TRY(c_part(sc, w + comma + 1, n - comma - 1, "IM", lim, &a[3]));
        have_c = 1;
        TRY(fx_scene_arg_fx56(sc, &a[0]));
    } else {
        sc->err[0] = 0; /* a bare word read as one is not an error here */
        sc->pos = save;
        TRY(fx_scene_arg_fx56(sc, &a[0]));
    }
    TRY(fx_scene_arg_fx56(sc, &a[1]));
    if (!have_c) {
        TRY(fx_scene_arg_fx56(sc, &a[2]));
        TRY(fx_scene_arg_fx56(sc, &a[3]));
    }
    return fx_scene_arg_fx56(sc, &a[4]);
}

static int escape_time(fx_scene *sc, int julia)
{
    fx56 cre, cim, jre = 0, jim = 0, width;
    int32_t maxiter;
    if (julia) {
        fx56 a[5];
        TRY(julia_args(sc, a, 16));
        cre = a[0], cim = a[1], jre = a[2], jim = a[3], width = a[4];
    } else {
        TRY(fx_scene_arg_fx56(sc, &cre));
        TRY(fx_scene_arg_fx56(sc, &cim));
        TRY(fx_scene_arg_fx56(sc, &width));
    }
    TRY(fx_scene_arg_int(sc, &maxiter));
    TRY(fx_scene_end(sc));
    if (maxiter < 1 || (uint32_t)maxiter > FX_FRACTAL_MAX_ITER)
        return fx_scene_error(sc, "iteration count %d out of range (1..%u)", maxiter,
                              FX_FRACTAL_MAX_ITER);
    const fx_surface *s = &sc->ctx.surf;
    fx_fractal_view v = julia ? fx_julia_view(cre, cim, jre, jim, width, s->w, s->h, (uint32_t)maxiter)
                              : fx_mandel_view(cre, cim, width, s->w, s->h, (uint32_t)maxiter);
    if (fx_fractal_check(&v) < 0)
        return fx_scene_error(sc, "view out of range (|centre|, |c| <= 16, 0 < width <= 16)");

    uint32_t lut[256];
    fx_dwell_pal pal;
    dwell_pal(sc, &pal, lut, (uint32_t)maxiter);
    fx_trace(&sc->ctx, "%s: %s path, pixel step %lld/2^56, %d iterations",
             julia ? "julia" : "mandelbrot",
             fx_fractal_precision(&v) == 32 ? "Q4.28 (32-bit)" : "Q8.56 (64-bit)",
             (long long)(v.width / v.fw), maxiter);
    return fx_fractal_render(s, sc->ctx.clip, &v, &pal);
}

static int cmd_mandelbrot(fx_scene *sc) { return escape_time(sc, 0); }

static int ints(fx_scene *sc, int32_t *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    return 0;
}

static int order_arg(fx_scene *sc, int32_t *n)
{
    TRY(fx_scene_arg_int(sc, n));
    if (*n < 0 || *n > 1000)
        return fx_scene_error(sc, "order %d out of range (0..1000)", *n);
    return 0;
}

static int cmd_koch(fx_scene *sc)
{
    int32_t v[4], n;
    TRY(ints(sc, v, 4));
    TRY(order_arg(sc, &n));
    TRY(fx_scene_end(sc));
    fx_koch(&sc->ctx, v[0], v[1], v[2], v[3], (uint32_t)n);
    return 0;
}

static int cmd_snowflake(fx_scene *sc)
{
    int32_t v[3], n;
    TRY(ints(sc, v, 3));
    TRY(order_arg(sc, &n));
    TRY(fx_scene_end(sc));
    if (v[2] < 0 || v[2] > (1 << 28))
        return fx_scene_error(sc, "radius %d out of range (0..2^28)", v[2]);
    fx_koch_snowflake(&sc->ctx, v[0], v[1], v[2], (uint32_t)n);
    return 0;
}

static int fract_params(fx_scene *sc, fx_fract_params *p)
{
    int32_t seed;
    TRY(fx_scene_arg_fx16(sc, &p->beta));
    TRY(fx_scene_arg_fx16(sc, &p->sd));
    TRY(fx_scene_arg_int(sc, &seed));
    p->seed = (uint32_t)seed;
    p->min_len = 2;
    if (p->beta < 0 || p->beta > 3 * FX16_ONE)
        return fx_scene_error(sc, "beta out of range (0..3)");
    if (p->sd < 0 || p->sd > FX16_ONE)
        return fx_scene_error(sc, "standard deviation out of range (0..1)");
    return 0;
}

static int cmd_fractline(fx_scene *sc)
{
    int32_t v[4];
    fx_fract_params p;
    TRY(ints(sc, v, 4));
    TRY(fract_params(sc, &p));
    TRY(fx_scene_end(sc));
    uint32_t st = p.seed;
    fx_fractline(&sc->ctx, v[0], v[1], v[2], v[3], &p, &st);
    return 0;
}

static int cmd_coastline(fx_scene *sc)
{
    fx_fract_params p;
    int32_t xy[64];
    int n = 0;
    TRY(fract_params(sc, &p));
    while (fx_scene_more(sc)) {
        if (n == 64)
            return fx_scene_error(sc, "at most 32 vertices");
        TRY(fx_scene_arg_int(sc, &xy[n++]));
    }
    if (n < 6 || n % 2)
        return fx_scene_error(sc, "need at least 3 vertices as X Y pairs");
    TRY(fx_scene_end(sc));
    fx_coastline(&sc->ctx, xy, n / 2, &p);
    return 0;
}

static int cmd_spacefill(fx_scene *sc, int peano)
{
    int32_t v[3], n;
    TRY(ints(sc, v, 3));
    TRY(order_arg(sc, &n));
    TRY(fx_scene_end(sc));
    if (v[2] < 1)
        return fx_scene_error(sc, "size must be at least 1");
    if (peano)
        fx_peano(&sc->ctx, v[0], v[1], v[2], (uint32_t)n);
    else
        fx_hilbert(&sc->ctx, v[0], v[1], v[2], (uint32_t)n);
    return 0;
}
static int cmd_hilbert(fx_scene *sc) { return cmd_spacefill(sc, 0); }
static int cmd_peano(fx_scene *sc) { return cmd_spacefill(sc, 1); }

/* user IFS maps, collected by 'ifsmap' in the module state */
static int cmd_ifsmap(fx_scene *sc)
{
    fx16 v[7];
    for (int i = 0; i < 7; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    TRY(fx_scene_end(sc));
    fx_scene_fractal *st = state(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    if (st->nmaps == FX_IFS_MAX_MAPS)
        return fx_scene_error(sc, "at most %d maps", FX_IFS_MAX_MAPS);
    fx_ifs_map m = {v[0], v[1], v[2], v[3], v[4], v[5], v[6]};
    st->maps[st->nmaps++] = m;
    return 0;
}

static int cmd_ifswindow(fx_scene *sc)
{
    fx16 v[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_fx16(sc, &v[i]));
    TRY(fx_scene_end(sc));
    fx_scene_fractal *st = state(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    st->win[0] = v[0];
    st->win[1] = v[1];
    st->win[2] = v[2];
    st->win[3] = v[3];
    return 0;
}

static int run_ifs(fx_scene *sc, const fx_ifs *s, int chaos)
{
    int32_t v[4], n, seed = 1;
    TRY(ints(sc, v, 4));
    TRY(fx_scene_arg_int(sc, &n));
    if (chaos)
        TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    if (fx_ifs_check(s) < 0)
        return fx_scene_error(sc, "bad IFS: 1..16 maps with probabilities summing to 1, and a window");
    if (v[2] < 1 || v[3] < 1)
        return fx_scene_error(sc, "empty destination rectangle");
    int64_t x1 = (int64_t)v[0] + v[2], y1 = (int64_t)v[1] + v[3];
    fx_rect d = {v[0], v[1], x1 > INT32_MAX ? INT32_MAX : (int32_t)x1,
                 y1 > INT32_MAX ? INT32_MAX : (int32_t)y1};
    if (chaos) {
        if (n < 0 || n > 4000000)
            return fx_scene_error(sc, "point count %d out of range (0..4000000)", n);
        fx_ifs_chaos(&sc->ctx, d, s, (uint32_t)n, (uint32_t)seed);
    } else {
        if (n < 0 || fx_ifs_copier(&sc->ctx, d, s, (uint32_t)n) < 0)
            return fx_scene_error(sc, "copier depth %d too deep (at most 2^20 copies)", n);
    }
    return 0;
}

static int cmd_ifs(fx_scene *sc)
{
    static const char *const systems[] = {"sierpinski", "fern", "user", 0};
    static const char *const modes[] = {"chaos", "copier", 0};
    int k = fx_scene_arg_choice(sc, systems);
    TRY(k);
    int mode = fx_scene_arg_choice(sc, modes);
    TRY(mode);
    fx_ifs user;
    const fx_ifs *s = k == 0 ? &fx_ifs_sierpinski : &fx_ifs_fern;
    if (k == 2) {
        const fx_scene_fractal *st = fx_scene_fractal_state(sc);
        user.maps = st->maps;
        user.n = st->nmaps;
        user.wx0 = st->win[0];
        user.wy0 = st->win[1];
        user.wx1 = st->win[2];
        user.wy1 = st->win[3];
        s = &user;
    }
    return run_ifs(sc, s, mode == 0);
}

/* issue #44: ifscopy sierpinski|fern|user X Y W H DEPTH BG: the copier
 * from whatever the script drew in the rectangle (fx_ifs_copier_picture) */
static int cmd_ifscopy(fx_scene *sc)
{
    static const char *const systems[] = {"sierpinski", "fern", "user", 0};
    int k = fx_scene_arg_choice(sc, systems);
    TRY(k);
    int32_t v[4], depth;
    fx_color bg;
    TRY(ints(sc, v, 4));
    TRY(fx_scene_arg_int(sc, &depth));
    TRY(fx_scene_arg_color(sc, &bg));
    TRY(fx_scene_end(sc));
    fx_ifs user;
    const fx_ifs *s = k == 0 ? &fx_ifs_sierpinski : &fx_ifs_fern;
    if (k == 2) {
        const fx_scene_fractal *st = fx_scene_fractal_state(sc);
        user.maps = st->maps;
        user.n = st->nmaps;
        user.wx0 = st->win[0];
        user.wy0 = st->win[1];
        user.wx1 = st->win[2];
        user.wy1 = st->win[3];
        s = &user;
    }
    if (fx_ifs_check(s) < 0)
        return fx_scene_error(sc, "bad IFS: 1..16 maps with probabilities summing to 1, and a window");
    if (v[2] < 1 || v[3] < 1 || depth < 0)
        return fx_scene_error(sc, "empty destination rectangle or negative depth");
    int64_t x1 = (int64_t)v[0] + v[2], y1 = (int64_t)v[1] + v[3];
    fx_rect d = {v[0], v[1], x1 > INT32_MAX ? INT32_MAX : (int32_t)x1, y1 > INT32_MAX ? INT32_MAX : (int32_t)y1};
    fx_rect in = fx_rect_intersect(d, sc->ctx.clip);
    uint32_t cap = fx_rect_empty(in) ? 0 : (uint32_t)((int64_t)(in.x1 - in.x0) * (in.y1 - in.y0));
    fx_ifs_pixel *work = cap ? fx_scene_alloc(sc, (size_t)cap * sizeof *work) : 0;
    if (cap && !work)
        return fx_scene_error(sc, "out of scene memory for the picture (%u pixels)", cap);
    int32_t n = fx_ifs_copier_picture(&sc->ctx, d, s, (uint32_t)depth, bg, work, cap);
    if (n == -FX_E2BIG)
        return fx_scene_error(sc, "picture pixels x maps^DEPTH over %u: a smaller picture or DEPTH",
                              FX_IFS_PICTURE_WORK);
    if (n < 0)
        return fx_scene_error(sc, "bad copier picture");
    fx_trace(&sc->ctx, "ifscopy: a picture of %d pixels through %d maps, depth %d", n, s->n, depth);
    return 0;
}

static int cmd_fern(fx_scene *sc) { return run_ifs(sc, &fx_ifs_fern, 1); }
static int cmd_julia(fx_scene *sc) { return escape_time(sc, 1); }

/* ---- issue #23: J_c, fixed points and basins, box counting, the turtle,
 * grass, fire and the 3D mountain ---- */

/* v in Q16.16 as a signed decimal with four places, for trace lines */
static const char *dec4(char *buf, size_t n, int64_t v16)
{
    int64_t a = v16 < 0 ? -v16 : v16;
    int64_t ip = a >> 16, fr = ((a & 0xFFFF) * 10000 + 32768) >> 16;
    if (fr == 10000) {
        ip++;
        fr = 0;
    }
    fx_fmt(buf, n, "%s%lld.%04lld", v16 < 0 ? "-" : "", (long long)ip, (long long)fr);
    return buf;
}

/* CENTRE_RE CENTRE_IM C_RE C_IM WIDTH or c=C_RE,C_IM CENTRE_RE CENTRE_IM
 * WIDTH: a Julia view of the whole surface (|c| parts <= 2) */
static int julia_view_args(fx_scene *sc, fx_fractal_view *v, uint32_t maxiter)
{
    fx56 a[5];
    TRY(julia_args(sc, a, 2));
    const fx_surface *s = &sc->ctx.surf;
    *v = fx_julia_view(a[0], a[1], a[2], a[3], a[4], s->w, s->h, maxiter);
    return 0;
}

static int julia_view_ok(fx_scene *sc, const fx_fractal_view *v)
{
    if (fx_julia_check(v) < 0)
        return fx_scene_error(sc, "view out of range (|centre| <= 16, |CX|, |CY| <= 2, 2^-28 <= width <= 16)");
    return 0;
}

static int cmd_juliaset(fx_scene *sc)
{
    static const char *const modes[] = {"random", "tree", 0};
    int mode = fx_scene_arg_choice(sc, modes);
    TRY(mode);
    fx_fractal_view v;
    int32_t n, seed = 1;
    TRY(julia_view_args(sc, &v, 1));
    TRY(fx_scene_arg_int(sc, &n));
    if (mode == 0)
        TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    TRY(julia_view_ok(sc, &v));
    int32_t hits;
    if (mode == 0) {
        if (n < 0 || n > FX_JULIA_SCENE_POINTS)
            return fx_scene_error(sc, "point count %d out of range (0..%d)", n, FX_JULIA_SCENE_POINTS);
        hits = fx_julia_inverse_random(&sc->ctx, &v, (uint32_t)n, (uint32_t)seed);
    } else {
        if (n < 0 || n > FX_JULIA_SCENE_DEPTH)
            return fx_scene_error(sc, "depth %d out of range (0..%d)", n, FX_JULIA_SCENE_DEPTH);
        hits = fx_julia_inverse_tree(&sc->ctx, &v, (uint32_t)n);
    }
    if (hits < 0)
        return fx_scene_error(sc, "bad Julia view");
    fx_trace(&sc->ctx, "juliaset: %d points of J_c inside the clip", hits);
    return 0;
}

static const char *const fixed_kind[] = {"attracting", "neutral", "repelling"};

static int cmd_juliafixed(fx_scene *sc)
{
    fx_fractal_view v;
    TRY(julia_view_args(sc, &v, 1));
    TRY(fx_scene_end(sc));
    TRY(julia_view_ok(sc, &v));
    fx_julia_fixed fp[2];
    fx_julia_fixed_points(v.jre, v.jim, fp);
    for (int k = 0; k < 2; k++) {
        int32_t x, y;
        fx_julia_to_pixel(&v, fp[k].re, fp[k].im, &x, &y);
        /* attracting: a disc; repelling: a ring; neutral: a square */
        if (fp[k].kind == FX_FIXED_ATTRACTING)
            fx_disc(&sc->ctx, x, y, 3);
        else if (fp[k].kind == FX_FIXED_REPELLING)
            fx_circle(&sc->ctx, x, y, 4);
        else
            fx_rect_outline(&sc->ctx, x - 3, y - 3, 7, 7);
        char a[24], b[24], m[24];
        fx_trace(&sc->ctx, "juliafixed: z%d = %s %s i, |2z| = %s, %s, pixel (%d, %d)", k + 1,
                 dec4(a, sizeof a, fp[k].re >> 40), dec4(b, sizeof b, fp[k].im >> 40), dec4(m, sizeof m, fp[k].mult),
                 fixed_kind[fp[k].kind], x, y);
    }
    return 0;
}

static int cmd_juliabasins(fx_scene *sc)
{
    static const fx_color basin[6] = {0xFFFFC040u, 0xFF40B0FFu, 0xFFFF5A5Au, 0xFF60E060u, 0xFFC080FFu, 0xFFF0F0F0u};
    fx_fractal_view v;
    int32_t maxiter;
    TRY(julia_view_args(sc, &v, 1));
    TRY(fx_scene_arg_int(sc, &maxiter));
    TRY(fx_scene_end(sc));
    if (maxiter < 1 || maxiter > FX_JULIA_SCENE_ITER)
        return fx_scene_error(sc, "iteration count %d out of range (1..%d)", maxiter, FX_JULIA_SCENE_ITER);
    v.maxiter = (uint32_t)maxiter;
    TRY(julia_view_ok(sc, &v));
    uint32_t lut[256];
    fx_dwell_pal pal;
    dwell_pal(sc, &pal, lut, (uint32_t)maxiter);
    int p = fx_julia_basins(&sc->ctx.surf, sc->ctx.clip, &v, &pal, basin, 6);
    if (p < 0)
        return fx_scene_error(sc, "bad Julia view");
    fx_trace(&sc->ctx, "juliabasins: attracting cycle of period %d%s", p, p ? "" : " (none: no interior basin)");
    return 0;
}

static int cmd_boxdim(fx_scene *sc)
{
    int32_t v[4], smin, smax;
    fx_color bg;
    fx16 expect = 0;
    int have_expect = 0;
    TRY(ints(sc, v, 4));
    TRY(fx_scene_arg_color(sc, &bg));
    TRY(fx_scene_arg_int(sc, &smin));
    TRY(fx_scene_arg_int(sc, &smax));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx16(sc, &expect));
        have_expect = 1;
    }
    TRY(fx_scene_end(sc));
    if (v[2] < 1 || v[3] < 1)
        return fx_scene_error(sc, "empty rectangle");
    if (smin < 1 || smax < 2 * smin)
        return fx_scene_error(sc, "need SMAX >= 2 x SMIN (at least two box sizes)");
    int64_t x1 = (int64_t)v[0] + v[2], y1 = (int64_t)v[1] + v[3];
    fx_rect r = {v[0], v[1], x1 > INT32_MAX ? INT32_MAX : (int32_t)x1, y1 > INT32_MAX ? INT32_MAX : (int32_t)y1};
    r = fx_rect_intersect(r, sc->ctx.clip);
    const fx_surface *s = &sc->ctx.surf;
    fx16 dim;
    int32_t counts[FX_BOXDIM_MAX_SIZES];
    int n;
    if (fx_rect_empty(r) || fx_boxdim_surface(s, r, fx_pack(s->format, bg), smin, smax, &dim, counts, &n) < 0)
        return fx_scene_error(sc, "nothing but the background colour in the rectangle");
    char a[24], b[24], c[24];
    for (int i = 0; i < n; i++)
        fx_trace(&sc->ctx, "boxdim: box %d px: %d boxes", smin << i, counts[i]);
    if (have_expect)
        fx_trace(&sc->ctx, "boxdim: D = %s from %d sizes; known %s, off by %s", dec4(a, sizeof a, dim), n,
                 dec4(b, sizeof b, expect), dec4(c, sizeof c, (int64_t)dim - expect));
    else
        fx_trace(&sc->ctx, "boxdim: D = %s from %d sizes", dec4(a, sizeof a, dim), n);
    return 0;
}

static int cmd_turtle(fx_scene *sc)
{
    static const char *const ops[] = {"home", "moveto", "lineto", "moverel", "linerel", "turn", "turnto",
                                      "forward", "jump", "koch", "hilbert", "where", 0};
    int op = fx_scene_arg_choice(sc, ops);
    TRY(op);
    fx16 a[3] = {0, 0, 0};
    int32_t order = 0, parity = 1;
    static const int nfx[] = {3, 2, 2, 2, 2, 1, 1, 1, 1, 1, 1, 0};
    for (int i = 0; i < nfx[op]; i++)
        TRY(fx_scene_arg_fx16(sc, &a[i]));
    if (op == 9 || op == 10) {
        TRY(fx_scene_arg_int(sc, &order));
        if (op == 10 && fx_scene_more(sc))
            TRY(fx_scene_arg_int(sc, &parity));
    }
    TRY(fx_scene_end(sc));
    if (order < 0 || order > FX_TURTLE_MAX_ORDER)
        return fx_scene_error(sc, "order %d out of range (0..%d)", order, FX_TURTLE_MAX_ORDER);
    if (parity != 1 && parity != -1)
        return fx_scene_error(sc, "parity must be 1 or -1");
    fx_scene_fractal *st = state(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    fx_turtle *t = &st->turtle;
    if (op != 11 && op != 0)
        TRY(fx_scene_surface(sc));
    t->ctx = &sc->ctx;
    switch (op) {
    case 0: fx_turtle_init(t, &sc->ctx, a[0], a[1], a[2]); break;
    case 1: fx_turtle_move_to(t, a[0], a[1]); break;
    case 2: fx_turtle_line_to(t, a[0], a[1]); break;
    case 3: fx_turtle_move_rel(t, a[0], a[1]); break;
    case 4: fx_turtle_line_rel(t, a[0], a[1]); break;
    case 5: fx_turtle_turn(t, a[0]); break;
    case 6: fx_turtle_turn_to(t, a[0]); break;
    case 7: fx_turtle_forward(t, a[0], 1); break;
    case 8: fx_turtle_forward(t, a[0], 0); break;
    case 9: fx_turtle_koch(t, a[0], (uint32_t)order); break;
    case 10: fx_turtle_hilbert(t, a[0], (uint32_t)order, parity); break;
    default: break;
    }
    char x[24], y[24], h[24];
    fx_trace(&sc->ctx, "turtle: CP (%s, %s) heading %s, %lld segments", dec4(x, sizeof x, t->x),
             dec4(y, sizeof y, t->y), dec4(h, sizeof h, fx_turtle_heading(t)), (long long)t->segs);
    return 0;
}

static int rect_args(fx_scene *sc, fx_rect *r)
{
    int32_t v[4];
    TRY(ints(sc, v, 4));
    if (v[2] < 1 || v[3] < 1)
        return fx_scene_error(sc, "empty rectangle");
    *r = (fx_rect){v[0], v[1], (int32_t)((int64_t)v[0] + v[2]), (int32_t)((int64_t)v[1] + v[3])};
    return 0;
}

static int cmd_grass(fx_scene *sc)
{
    fx_rect r;
    int32_t n, seed;
    TRY(rect_args(sc, &r));
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    if (n < 0 || n > FX_GRASS_SCENE_BLADES)
        return fx_scene_error(sc, "blade count %d out of range (0..%d)", n, FX_GRASS_SCENE_BLADES);
    int32_t segs = fx_grass(&sc->ctx, r, (uint32_t)n, (uint32_t)seed);
    if (segs < 0)
        return fx_scene_error(sc, "grass rectangle out of range (within +-32767)");
    fx_trace(&sc->ctx, "grass: %d blades, %d segments", n, segs);
    return 0;
}

static int cmd_fire(fx_scene *sc)
{
    fx_rect r;
    fx16 rough;
    int32_t seed;
    TRY(rect_args(sc, &r));
    TRY(fx_scene_arg_fx16(sc, &rough));
    TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    if (fx_fire(&sc->ctx, r, rough, (uint32_t)seed) < 0)
        return fx_scene_error(sc, "fire rectangle out of range (0..16384) or roughness outside 0..1");
    return 0;
}

/* The module's scratch block (mountain, collage, fractcompress): kept and
 * reused, replaced by a bigger one only when a command needs more. */
static void *scratch(fx_scene *sc, size_t need)
{
    fx_scene_fractal *st = state(sc);
    if (!st)
        return 0;
    if (need > st->buf_bytes) {
        void *mem = fx_scene_alloc(sc, need);
        if (!mem)
            return 0;
        st->buf = mem;
        st->buf_bytes = need;
    }
    return st->buf;
}

/* ---- issue #44: the orbit of 0 ---- */

#define ORBIT_CMD_MAX 1024

static const char *const orbit_kind[] = {"explodes", "fixed point", "spiral into a fixed point", "cycle",
                                         "bounded, no cycle found"};

/* orbit C_RE C_IM N [CENTRE_RE CENTRE_IM WIDTH]: prints the first values
 * and the classification, and draws the orbit in the current colour over a
 * Mandelbrot view of the surface (centre -0.5 0, width 4 by default). */
static int cmd_orbit(fx_scene *sc)
{
    fx56 cre, cim, vre = -FX56_ONE / 2, vim = 0, width = 4 * FX56_ONE;
    int32_t n;
    TRY(fx_scene_arg_fx56(sc, &cre));
    TRY(fx_scene_arg_fx56(sc, &cim));
    TRY(fx_scene_arg_int(sc, &n));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx56(sc, &vre));
        TRY(fx_scene_arg_fx56(sc, &vim));
        TRY(fx_scene_arg_fx56(sc, &width));
    }
    TRY(fx_scene_end(sc));
    if (n < 1 || n > ORBIT_CMD_MAX)
        return fx_scene_error(sc, "N %d out of range (1..%d)", n, ORBIT_CMD_MAX);
    fx56 *z = scratch(sc, 2 * ORBIT_CMD_MAX * sizeof(fx56));
    if (!z)
        return fx_scene_error(sc, "out of scene memory for the orbit");
    fx_orbit0_info info;
    if (fx_orbit0(cre, cim, (uint32_t)n, z, z + ORBIT_CMD_MAX, &info) < 0)
        return fx_scene_error(sc, "c out of range (|C_RE|, |C_IM| <= 16)");
    const fx_surface *s = &sc->ctx.surf;
    fx_fractal_view v = fx_mandel_view(vre, vim, width, s->w, s->h, 1);
    if (fx_fractal_check(&v) < 0)
        return fx_scene_error(sc, "view out of range (|centre| <= 16, 0 < width <= 16)");
    char a[24], b[24];
    uint32_t last = info.steps;
    for (uint32_t k = 0; k <= last && k < 12; k++)
        fx_trace(&sc->ctx, "orbit: z%u = %s %s i", k, dec4(a, sizeof a, z[k] >> 40),
                 dec4(b, sizeof b, z[ORBIT_CMD_MAX + k] >> 40));
    if (info.kind == FX_ORBIT0_CYCLE)
        fx_trace(&sc->ctx, "orbit: c = %s %s i: cycle of period %d (checked at step %u)", dec4(a, sizeof a, cre >> 40),
                 dec4(b, sizeof b, cim >> 40), info.period, info.steps);
    else if (info.kind == FX_ORBIT0_ESCAPES)
        fx_trace(&sc->ctx, "orbit: c = %s %s i: explodes, |z%u| > 2", dec4(a, sizeof a, cre >> 40),
                 dec4(b, sizeof b, cim >> 40), info.steps);
    else {
        char p[24], q[24];
        fx_trace(&sc->ctx, "orbit: c = %s %s i: %s, z%u = %s %s i", dec4(a, sizeof a, cre >> 40),
                 dec4(b, sizeof b, cim >> 40), orbit_kind[info.kind], info.steps, dec4(p, sizeof p, info.re >> 40),
                 dec4(q, sizeof q, info.im >> 40));
    }
    int32_t px = 0, py = 0;
    for (uint32_t k = 0; k <= last; k++) {
        int32_t x, y;
        fx_julia_to_pixel(&v, z[k], z[ORBIT_CMD_MAX + k], &x, &y);
        if (k)
            fx_line(&sc->ctx, px, py, x, y);
        fx_circle(&sc->ctx, x, y, 2);
        px = x, py = y;
    }
    return 0;
}

/* ---- issue #44: fractional Brownian curves by spectral synthesis ---- */

/* Four samples per pixel of the chord keep the curve rough down to the
 * pixel (a sum stopping at half the sampling rate is smooth for a few
 * samples below it); a chord beyond 16384 px (the largest surface) still
 * gets 65537, so the work stays within FBM_CMD_SAMPLES x TERMS sines. */
#define FBM_CMD_SAMPLES 65537
#define FBM_CMD_TERMS 2048

/* fbmcurve X0 Y0 X1 Y1 BETA SD SEED [TERMS]: fractline's arguments, so a
 * script can swap one for the other and compare; TERMS defaults to the
 * most the samples carry (capped at 1024). */
static int cmd_fbmcurve(fx_scene *sc)
{
    int32_t v[4], seed, terms = 0;
    fx16 beta, sd;
    TRY(ints(sc, v, 4));
    TRY(fx_scene_arg_fx16(sc, &beta));
    TRY(fx_scene_arg_fx16(sc, &sd));
    TRY(fx_scene_arg_int(sc, &seed));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_int(sc, &terms));
        if (terms < 1 || terms > FBM_CMD_TERMS)
            return fx_scene_error(sc, "TERMS %d out of range (1..%d)", terms, FBM_CMD_TERMS);
    }
    TRY(fx_scene_end(sc));
    if (beta < 0 || beta > 4 * FX16_ONE)
        return fx_scene_error(sc, "BETA out of range (0..4)");
    if (sd < 0 || sd > FX16_ONE)
        return fx_scene_error(sc, "SD out of range (0..1 chord lengths)");
    int64_t dx = (int64_t)v[2] - v[0], dy = (int64_t)v[3] - v[1];
    if (dx < 0)
        dx = -dx;
    if (dy < 0)
        dy = -dy;
    int64_t n = 4 * (dx > dy ? dx : dy) + 1;
    if (n > FBM_CMD_SAMPLES)
        n = FBM_CMD_SAMPLES;
    if (terms == 0)
        terms = n < 3 ? 1 : n > 2049 ? 1024 : (int32_t)(n - 1) / 2;
    if (n < 2 * (int64_t)terms + 1)
        n = 2 * (int64_t)terms + 1; /* no frequency above half the sampling rate */
    fx16 *h = scratch(sc, (size_t)n * sizeof(fx16));
    if (!h)
        return fx_scene_error(sc, "out of scene memory for the curve's heights");
    fx_fbm_params p = {beta, sd, (uint32_t)terms, (uint32_t)seed};
    if (fx_fbm_spectral(&sc->ctx, v[0], v[1], v[2], v[3], &p, h, (int32_t)n) < 0)
        return fx_scene_error(sc, "fbmcurve arguments out of range");
    char b[24];
    fx_trace(&sc->ctx, "fbmcurve: %d samples, %d terms, D = (5 - beta) / 2 = %s", (int)n, terms,
             dec4(b, sizeof b, (5 * (int64_t)FX16_ONE - beta) / 2));
    return 0;
}

static int cmd_mountain(fx_scene *sc)
{
    fx16 size, height, rough = 45875 /* 0.7 */, sea = 13107 /* 0.2 */;
    int32_t k, seed;
    TRY(fx_scene_arg_fx16(sc, &size));
    TRY(fx_scene_arg_fx16(sc, &height));
    TRY(fx_scene_arg_int(sc, &k));
    TRY(fx_scene_arg_int(sc, &seed));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &rough));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_fx16(sc, &sea));
    TRY(fx_scene_end(sc));
    int32_t nv, nt;
    if (fx_terrain_mesh_size(k, &nv, &nt) < 0)
        return fx_scene_error(sc, "grid order %d out of range (1..%d)", k, FX_TERRAIN_MESH_MAX_K);
    if (size <= 0 || height < 0 || rough < 0 || rough > FX16_ONE || sea < 0 || sea > FX16_ONE)
        return fx_scene_error(sc, "SIZE > 0, HEIGHT >= 0, ROUGH and SEA in 0..1");
    int32_t side = (1 << k) + 1;
    int32_t *h = scratch(sc, (size_t)side * side * sizeof(int32_t) + (size_t)nv * sizeof(uint32_t));
    if (!h)
        return fx_scene_error(sc, "out of scene memory for a %dx%d terrain", side, side);
    fx_mesh m;
    TRY(fx_scene_mesh_alloc(sc, nv, nt, 0, &m));
    m.col = (uint32_t *)(h + (size_t)side * side);
    /* a central peak under the random relief: a mountain, not a plain */
    fx_terrain(h, side, k, 1 << 20, rough, (uint32_t)seed);
    fx_terrain_peak(h, side, k, 3 << 19);
    if (fx_terrain_mesh(&m, h, side, k, size, height, sea) < 0)
        return fx_scene_error(sc, "bad terrain parameters");
    fx_trace(&sc->ctx, "mountain: %dx%d grid, %d triangles", side, side, nt);
    return fx_scene_mesh_draw(sc, &m);
}

static int32_t clamp32(int64_t v) { return v > INT32_MAX ? INT32_MAX : (int32_t)v; }

/* The square [x, x + n)^2 lies on the surface (commands that read pixels). */
static int on_surface(fx_scene *sc, int32_t x, int32_t y, int32_t n, const char *what)
{
    const fx_surface *s = &sc->ctx.surf;
    if (x < 0 || y < 0 || (int64_t)x + n > s->w || (int64_t)y + n > s->h)
        return fx_scene_error(sc, "%s square %d,%d size %d is not inside the %dx%d surface", what, x, y, n, s->w, s->h);
    return 0;
}

static int cmd_collage(fx_scene *sc)
{
    int32_t x, y, n, maxmaps, dx, dy, npoints, seed;
    fx_color bg;
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_arg_color(sc, &bg));
    TRY(fx_scene_arg_int(sc, &maxmaps));
    TRY(fx_scene_arg_int(sc, &dx));
    TRY(fx_scene_arg_int(sc, &dy));
    TRY(fx_scene_arg_int(sc, &npoints));
    TRY(fx_scene_arg_int(sc, &seed));
    TRY(fx_scene_end(sc));
    if (n < 12 || n > FX_COLLAGE_MAX_SIDE || n % 12)
        return fx_scene_error(sc, "size %d: a multiple of 12 in 12..%d", n, FX_COLLAGE_MAX_SIDE);
    if (maxmaps < 1 || maxmaps > FX_IFS_MAX_MAPS)
        return fx_scene_error(sc, "map count %d out of range (1..%d)", maxmaps, FX_IFS_MAX_MAPS);
    if (npoints < 0 || npoints > 4000000)
        return fx_scene_error(sc, "point count %d out of range (0..4000000)", npoints);
    TRY(on_surface(sc, x, y, n, "target"));
    uint8_t *t = scratch(sc, 2 * (size_t)n * n);
    if (!t)
        return fx_scene_error(sc, "out of scene memory");
    const fx_surface *s = &sc->ctx.surf;
    uint32_t bgn = fx_pack(s->format, bg);
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++)
            t[j * n + i] = fx_surface_get_native(s, x + i, y + j) != bgn;
    fx_collage_result res;
    fx_collage_search(t, n, n, maxmaps, t + (size_t)n * n, &res);
    for (int i = 0; i < res.n; i++)
        fx_trace(&sc->ctx, "collage: map %d: scale 1/%d x 1/%d, offset %d/12, %d/12", i + 1, res.maps[i].ax_den,
                 res.maps[i].ay_den, res.maps[i].ex, res.maps[i].ey);
    fx_trace(&sc->ctx, "collage: %d maps; distance %d px (%d of %d target pixels missed, %d extra)", res.n,
             res.missed + res.extra, res.missed, res.target, res.extra);
    if (res.n == 0)
        return 0;
    /* the attractor, and the maps kept as the user IFS ('ifs user ...') */
    fx_scene_fractal *st = state(sc);
    fx_ifs ifs;
    fx_collage_to_ifs(res.maps, res.n, st->maps, &ifs);
    st->nmaps = res.n;
    st->win[0] = st->win[1] = 0;
    st->win[2] = st->win[3] = FX16_ONE;
    fx_rect d = {dx, dy, clamp32((int64_t)dx + n), clamp32((int64_t)dy + n)};
    fx_ifs_chaos(&sc->ctx, d, &ifs, (uint32_t)npoints, (uint32_t)seed);
    return 0;
}

static int cmd_fractcompress(fx_scene *sc)
{
    int32_t x, y, n, dx, dy, iters;
    TRY(fx_scene_arg_int(sc, &x));
    TRY(fx_scene_arg_int(sc, &y));
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_arg_int(sc, &dx));
    TRY(fx_scene_arg_int(sc, &dy));
    TRY(fx_scene_arg_int(sc, &iters));
    TRY(fx_scene_end(sc));
    if (n < 8 || n > FX_FIC_SCENE_SIDE || n % 8)
        return fx_scene_error(sc, "size %d: a multiple of 8 in 8..%d", n, FX_FIC_SCENE_SIDE);
    if (iters < 0 || iters > 100)
        return fx_scene_error(sc, "iteration count %d out of range (0..100)", iters);
    TRY(on_surface(sc, x, y, n, "source"));
    size_t px = (size_t)n * n, nc = px / 16;
    uint8_t *img = scratch(sc, 3 * px + nc * sizeof(fx_fic_code) + 8);
    if (!img)
        return fx_scene_error(sc, "out of scene memory");
    uint8_t *out = img + px, *tmp = out + px;
    fx_fic_code *codes = (fx_fic_code *)(((uintptr_t)(tmp + px) + 7) & ~(uintptr_t)7);
    const fx_surface *s = &sc->ctx.surf;
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++) {
            fx_color c = fx_unpack(s->format, fx_surface_get_native(s, x + i, y + j));
            /* Rec. 601 luma in integers */
            img[j * n + i] = (uint8_t)((77 * (c >> 16 & 255) + 150 * (c >> 8 & 255) + 29 * (c & 255) + 128) >> 8);
        }
    fx_fic_encode(img, n, codes);
    fx_fic_decode(codes, n, (uint32_t)iters, out, tmp);
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++) {
            uint32_t g = out[j * n + i];
            fx_surface_put(s, clamp32((int64_t)dx + i), clamp32((int64_t)dy + j),
                           0xFF000000u | g << 16 | g << 8 | g);
        }
    /* the code: per 4 x 4 block a domain index, 3 bits of symmetry, 5 of
     * scale, 11 of offset */
    int32_t nd = (n / 4 - 1) * (n / 4 - 1), bits = 0;
    while ((1 << bits) < nd)
        bits++;
    char p[24];
    fx16 q = fx_psnr(img, out, (int32_t)px);
    fx_trace(&sc->ctx, "fractcompress: %dx%d grey, %d range blocks, %d bytes of code (%d%% of the pixels), %d rounds, "
             "PSNR %s dB", n, n, (int)nc, (int)((nc * (uint32_t)(bits + 19) + 7) / 8),
             (int)((nc * (uint32_t)(bits + 19) + 7) / 8 * 100 / px), iters,
             q == INT32_MAX ? "inf" : dec4(p, sizeof p, q));
    return 0;
}

const fx_scene_cmd fx_scene_cmds_fractal[] = {
    {"colormap", cmd_colormap, "colormap grey|hot|viridis|hsv|w9 [PERIOD]", 0},
    {"insidecolor", cmd_insidecolor, "insidecolor #RRGGBB", 0},
    {"mandelbrot", cmd_mandelbrot, "mandelbrot CRE CIM WIDTH MAXITER", FX_SCENE_DRAWS},
    {"julia", cmd_julia, "julia CENTRE_RE CENTRE_IM C_RE C_IM WIDTH MAXITER | julia c=C_RE,C_IM CENTRE_RE CENTRE_IM WIDTH MAXITER   "
     "(the view's centre, then c; or c first, named)", FX_SCENE_DRAWS},
    {"koch", cmd_koch, "koch X0 Y0 X1 Y1 ORDER   (bumps towards +y, turning as 'rotate' does: above the base line after 'coords course')", FX_SCENE_DRAWS},
    {"snowflake", cmd_snowflake, "snowflake CX CY R ORDER", FX_SCENE_DRAWS},
    {"fractline", cmd_fractline, "fractline X0 Y0 X1 Y1 BETA SD SEED", FX_SCENE_DRAWS},
    {"coastline", cmd_coastline, "coastline BETA SD SEED X0 Y0 X1 Y1 X2 Y2 ...", FX_SCENE_DRAWS},
    {"hilbert", cmd_hilbert, "hilbert X Y SIZE ORDER", FX_SCENE_DRAWS},
    {"peano", cmd_peano, "peano X Y SIZE ORDER", FX_SCENE_DRAWS},
    {"ifsmap", cmd_ifsmap, "ifsmap A B C D E F P", 0},
    {"ifswindow", cmd_ifswindow, "ifswindow X0 Y0 X1 Y1", 0},
    {"ifs", cmd_ifs, "ifs sierpinski|fern|user chaos X Y W H NPOINTS SEED | ... copier X Y W H DEPTH",
     FX_SCENE_DRAWS},
    {"fern", cmd_fern, "fern X Y W H NPOINTS SEED", FX_SCENE_DRAWS},
    {"juliaset", cmd_juliaset, "juliaset random CENTRE_RE CENTRE_IM C_RE C_IM WIDTH NPOINTS SEED | juliaset tree CENTRE_RE CENTRE_IM C_RE C_IM WIDTH DEPTH   "
     "(or c=C_RE,C_IM CENTRE_RE CENTRE_IM WIDTH in place of the five)",
     FX_SCENE_DRAWS},
    {"juliafixed", cmd_juliafixed, "juliafixed CENTRE_RE CENTRE_IM C_RE C_IM WIDTH | juliafixed c=C_RE,C_IM CENTRE_RE CENTRE_IM WIDTH", FX_SCENE_DRAWS},
    {"juliabasins", cmd_juliabasins, "juliabasins CENTRE_RE CENTRE_IM C_RE C_IM WIDTH MAXITER | juliabasins c=C_RE,C_IM CENTRE_RE CENTRE_IM WIDTH MAXITER", FX_SCENE_DRAWS},
    /* these read the picture drawn so far, which a band has only part of */
    {"boxdim", cmd_boxdim, "boxdim X Y W H BG SMIN SMAX [KNOWN]", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"turtle", cmd_turtle,
     "turtle home X Y DEG | moveto X Y | lineto X Y | moverel DX DY | linerel DX DY | turn DEG | turnto DEG | "
     "forward D | jump D | koch LEN ORDER | hilbert STEP ORDER [PARITY] | where   "
     "(DEG from +x towards +y, as 'rotate': counter-clockwise after 'coords course')",
     0},
    {"grass", cmd_grass, "grass X Y W H NBLADES SEED", FX_SCENE_DRAWS},
    {"fire", cmd_fire, "fire X Y W H ROUGH SEED", FX_SCENE_DRAWS},
    {"collage", cmd_collage, "collage X Y SIZE BG MAXMAPS DX DY NPOINTS SEED", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"fractcompress", cmd_fractcompress, "fractcompress X Y SIZE DX DY ROUNDS", FX_SCENE_DRAWS | FX_SCENE_SERIAL},
    {"mountain", cmd_mountain, "mountain SIZE HEIGHT K SEED [ROUGH [SEA]]", FX_SCENE_DRAWS},
    /* issue #44 */
    {"ifscopy", cmd_ifscopy,
     "ifscopy sierpinski|fern|user X Y W H DEPTH BG   (the copier from any picture: what is drawn in the "
     "rectangle, every pixel not BG, goes through DEPTH rounds of the machine)",
     FX_SCENE_DRAWS | FX_SCENE_SERIAL}, /* it reads the picture, which a band has only part of */
    {"orbit", cmd_orbit,
     "orbit C_RE C_IM N [CENTRE_RE CENTRE_IM WIDTH]   (the orbit of 0 under z^2 + c: its first values, "
     "explodes / fixed point / spiral / cycle of period p, drawn over the Mandelbrot view)",
     FX_SCENE_DRAWS},
    {"fbmcurve", cmd_fbmcurve,
     "fbmcurve X0 Y0 X1 Y1 BETA SD SEED [TERMS]   (fractional Brownian curve by spectral synthesis: sinusoids "
     "with amplitudes k^(-BETA/2), D = (5 - BETA)/2; SD in chord lengths)",
     FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
