/* fixel — scene commands of the fractal module: escape-time sets and the
 * colour-map setting they share with the viz commands, Koch curves, random
 * fractals, IFS and space-filling curves. */
#include "fixel/colormap.h"
#include "fixel/error.h"
#include "fixel/fractal.h"
#include "fixel/scene.h"
#include "scene_fractal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

static fx_scene_fractal defaults = {FX_CMAP_COUNT, 0, 0xFF000000u};

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
    return fx_fractal_render(s, sc->ctx.clip, &v, &pal);
}

static int cmd_mandelbrot(fx_scene *sc) { return escape_time(sc, 0); }
static int cmd_julia(fx_scene *sc) { return escape_time(sc, 1); }

const fx_scene_cmd fx_scene_cmds_fractal[] = {
    {"colormap", cmd_colormap, "colormap grey|hot|viridis|hsv|w9 [PERIOD]", 0},
    {"insidecolor", cmd_insidecolor, "insidecolor #RRGGBB", 0},
    {"mandelbrot", cmd_mandelbrot, "mandelbrot CRE CIM WIDTH MAXITER", FX_SCENE_DRAWS},
    {"julia", cmd_julia, "julia CRE CIM CX CY WIDTH MAXITER", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
