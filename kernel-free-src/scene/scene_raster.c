/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the raster module: DDA and antialiased lines,
 * line attributes, polylines and curves. */
#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "fixel/scene.h"
#include "fixel/xform.h"
#include "../base/fx_internal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define MAX_POINTS 256

typedef struct raster_state {
    fx_line_style st;
    uint32_t tol; /* curve tolerance, 1/256 px; 0: the default */
} raster_state;

static raster_state *state(fx_scene *sc)
{
    raster_state *r = sc->mod[FX_SCENE_MOD_RASTER];
    if (!r) {
        r = fx_scene_alloc(sc, sizeof *r);
        if (!r)
            return 0;
        fx_line_style_init(&r->st);
        sc->mod[FX_SCENE_MOD_RASTER] = r;
    }
    sc->ctx.line_style = &r->st;
    return r;
}

#define STATE(r)                                                  \
    raster_state *r = state(sc);                                  \
    if (!r)                                                       \
        return fx_scene_error(sc, "scene arena full (line style)")

/* n points, mapped through the current transform (affine maps commute
 * with Bézier and B-spline evaluation, so control points map exactly). */
static void map_points(fx_scene *sc, int32_t *xy, int n)
{
    for (int i = 0; i < n; i++)
        fx_ctx_map(&sc->ctx, xy[2 * i], xy[2 * i + 1], &xy[2 * i], &xy[2 * i + 1]);
}

static int ints(fx_scene *sc, int32_t *v, int n)
{
    for (int i = 0; i < n; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    TRY(fx_scene_end(sc));
    map_points(sc, v, n / 2);
    return 0;
}

static int cmd_dda(fx_scene *sc)
{
    int32_t v[4];
    TRY(ints(sc, v, 4));
    fx_dda(&sc->ctx, v[0], v[1], v[2], v[3]);
    return 0;
}

static int cmd_aaline(fx_scene *sc)
{
    int32_t v[4];
    TRY(ints(sc, v, 4));
    fx_aaline(&sc->ctx, v[0], v[1], v[2], v[3]);
    return 0;
}

/* "X Y X Y ..." up to the end of the line: at least min points. */
static int points(fx_scene *sc, int32_t *xy, int min, int max, int *n)
{
    int k = 0;
    while (fx_scene_more(sc)) {
        if (k == max)
            return fx_scene_error(sc, "too many points (at most %d)", max);
        TRY(fx_scene_arg_int(sc, &xy[2 * k]));
        TRY(fx_scene_arg_int(sc, &xy[2 * k + 1]));
        k++;
    }
    TRY(fx_scene_end(sc));
    if (k < min)
        return fx_scene_error(sc, "needs at least %d points, got %d", min, k);
    map_points(sc, xy, k);
    *n = k;
    return 0;
}

static int cmd_polyline(fx_scene *sc)
{
    int32_t xy[2 * MAX_POINTS];
    int n;
    TRY(points(sc, xy, 1, MAX_POINTS, &n));
    fx_polyline(&sc->ctx, xy, n);
    return 0;
}

static int cmd_bezier(fx_scene *sc)
{
    int32_t xy[2 * FX_BEZIER_MAX_POINTS];
    int n;
    TRY(points(sc, xy, 3, FX_BEZIER_MAX_POINTS, &n));
    STATE(r);
    return fx_bezier(&sc->ctx, xy, n, r->tol);
}

static int cmd_bspline(fx_scene *sc)
{
    int32_t xy[2 * MAX_POINTS];
    int n;
    TRY(points(sc, xy, 4, MAX_POINTS, &n));
    STATE(r);
    return fx_bspline(&sc->ctx, xy, n, r->tol);
}

static int cmd_spline(fx_scene *sc)
{
    int32_t xy[2 * MAX_POINTS];
    int n;
    TRY(points(sc, xy, 2, MAX_POINTS, &n));
    STATE(r);
    return fx_spline(&sc->ctx, xy, n, r->tol);
}

/* linestyle solid|dashed|dotted|dashdot|BITS [UNIT [PHASE]]; BITS is a
 * string of 1s and 0s, first character = first unit. */
static int cmd_linestyle(fx_scene *sc)
{
    static const char *const names[] = {"solid", "dashed", "dotted", "dashdot", 0};
    static const uint32_t pat[] = {0, 0x3F, 0x1, 0x13F};
    static const uint8_t len[] = {0, 9, 2, 11};
    char w[40];
    TRY(fx_scene_arg_word(sc, w, sizeof w));
    uint32_t p = 0;
    int n = 0, which = -1;
    for (int i = 0; names[i]; i++) {
        const char *a = names[i], *b = w;
        while (*a && *a == *b)
            a++, b++;
        if (!*a && !*b)
            which = i;
    }
    if (which >= 0) {
        p = pat[which];
        n = len[which];
    } else {
        for (; w[n]; n++) {
            if (w[n] != '0' && w[n] != '1')
                return fx_scene_error(sc, "expected solid|dashed|dotted|dashdot or a bit string like 1110, got '%s'", w);
            if (n == 32)
                return fx_scene_error(sc, "bit pattern longer than 32");
            p |= (uint32_t)(w[n] - '0') << n;
        }
    }
    int32_t unit = 0, phase = 0;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &unit));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &phase));
    TRY(fx_scene_end(sc));
    if (unit < 0 || unit > 65535 || phase < 0)
        return fx_scene_error(sc, "unit must be 0..65535 and phase >= 0");
    STATE(r);
    r->st.pattern = p;
    r->st.pattern_len = (uint8_t)n;
    r->st.unit = (uint16_t)unit;
    r->st.phase = (uint32_t)phase;
    return 0;
}

static int cmd_linewidth(fx_scene *sc)
{
    int32_t w;
    TRY(fx_scene_arg_int(sc, &w));
    if (w < 1 || w > FX_LINE_MAX_WIDTH)
        return fx_scene_error(sc, "line width %d out of range (1..%d)", w, FX_LINE_MAX_WIDTH);
    TRY(fx_scene_end(sc));
    STATE(r);
    r->st.width = w;
    return 0;
}

static int cmd_linecap(fx_scene *sc)
{
    static const char *const names[] = {"butt", "square", "round", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    TRY(fx_scene_end(sc));
    STATE(r);
    r->st.cap = (uint8_t)k;
    return 0;
}

static int cmd_linejoin(fx_scene *sc)
{
    static const char *const names[] = {"miter", "round", "bevel", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    fx16 limit = 0;
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_fx16(sc, &limit));
        if (limit < FX16_ONE)
            return fx_scene_error(sc, "mitre limit must be >= 1");
    }
    TRY(fx_scene_end(sc));
    STATE(r);
    r->st.join = (uint8_t)k;
    r->st.miter_limit = limit;
    return 0;
}

static int cmd_curvetol(fx_scene *sc)
{
    int32_t t;
    TRY(fx_scene_arg_int(sc, &t));
    if (t < 1 || t > 65536)
        return fx_scene_error(sc, "tolerance %d out of range (1..65536, in 1/256 pixel)", t);
    TRY(fx_scene_end(sc));
    STATE(r);
    r->tol = (uint32_t)t;
    return 0;
}

const fx_scene_cmd fx_scene_cmds_raster[] = {
    {"dda", cmd_dda, "dda X0 Y0 X1 Y1", FX_SCENE_DRAWS},
    {"aaline", cmd_aaline, "aaline X0 Y0 X1 Y1", FX_SCENE_DRAWS},
    {"polyline", cmd_polyline, "polyline X0 Y0 X1 Y1 ...", FX_SCENE_DRAWS},
    {"bezier", cmd_bezier, "bezier X0 Y0 ... (3..9 control points)", FX_SCENE_DRAWS},
    {"bspline", cmd_bspline, "bspline X0 Y0 ... (>= 4 control points)", FX_SCENE_DRAWS},
    {"spline", cmd_spline, "spline X0 Y0 ... (>= 2 points, Catmull-Rom)", FX_SCENE_DRAWS},
    {"linestyle", cmd_linestyle, "linestyle solid|dashed|dotted|dashdot|BITS [UNIT [PHASE]]", 0},
    {"linewidth", cmd_linewidth, "linewidth W", 0},
    {"linecap", cmd_linecap, "linecap butt|square|round", 0},
    {"linejoin", cmd_linejoin, "linejoin miter|round|bevel [LIMIT]", 0},
    {"curvetol", cmd_curvetol, "curvetol T (1/256 pixel)", 0},
    {0, 0, 0, 0},
};
