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
#include "scene_fractal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

static const fx_scene_fractal defaults = {FX_CMAP_COUNT, 0, 0xFF000000u, 0, {{0}}, {0, 0, 65536, 65536}};

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

static int escape_time(fx_scene *sc, int julia)
{
    fx56 cre, cim, jre = 0, jim = 0, width;
    int32_t maxiter;
    TRY(fx_scene_arg_fx56(sc, &cre));
    TRY(fx_scene_arg_fx56(sc, &cim));
    if (julia) {
        TRY(fx_scene_arg_fx56(sc, &jre));
        TRY(fx_scene_arg_fx56(sc, &jim));
    }
    TRY(fx_scene_arg_fx56(sc, &width));
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

    const fx_scene_fractal *st = fx_scene_fractal_state(sc);
    uint32_t lut[256];
    fx_dwell_pal pal;
    if (st->cmap == FX_CMAP_COUNT) {
        /* the W9 grey ramp, whatever maxiter is */
        fx_dwell_pal_w9(&pal, lut, s->format);
    } else {
        fx_color tab[256];
        fx_cmap_table(st->cmap, tab, 256);
        for (int i = 0; i < 256; i++)
            lut[i] = fx_pack(s->format, tab[i]);
        pal.lut = lut;
        pal.len = 256;
        /* a period cycles through the map every `period` iterations;
         * without one the map spans the dwells 0..maxiter-1 once */
        uint32_t span = st->period ? st->period : (uint32_t)maxiter;
        pal.mul = (uint32_t)(((uint64_t)256 << 16) / span);
        if (pal.mul == 0)
            pal.mul = 1;
        pal.wrap = st->period != 0;
    }
    pal.inside = fx_pack(s->format, st->inside);
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

static int cmd_fern(fx_scene *sc) { return run_ifs(sc, &fx_ifs_fern, 1); }
static int cmd_julia(fx_scene *sc) { return escape_time(sc, 1); }

const fx_scene_cmd fx_scene_cmds_fractal[] = {
    {"colormap", cmd_colormap, "colormap grey|hot|viridis|hsv|w9 [PERIOD]", 0},
    {"insidecolor", cmd_insidecolor, "insidecolor #RRGGBB", 0},
    {"mandelbrot", cmd_mandelbrot, "mandelbrot CRE CIM WIDTH MAXITER", FX_SCENE_DRAWS},
    {"julia", cmd_julia, "julia CRE CIM CX CY WIDTH MAXITER", FX_SCENE_DRAWS},
    {"koch", cmd_koch, "koch X0 Y0 X1 Y1 ORDER", FX_SCENE_DRAWS},
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
    {0, 0, 0, 0},
};
