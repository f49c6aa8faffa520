/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the viz module: built-in integer fields (the
 * scripts have no data files of their own) and the plots drawn from them. */
#include "fixel/error.h"
#include "fixel/koch.h"
#include "fixel/scene.h"
#include "fixel/viz.h"
#include "scene_fractal.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

typedef struct viz_state {
    int32_t *s; /* scalar field */
    int32_t sw, sh, sstride;
    int32_t *u, *v; /* vector field */
    int32_t vw, vh;
} viz_state;

static viz_state *vstate(fx_scene *sc)
{
    if (!sc->mod[FX_SCENE_MOD_VIZ])
        sc->mod[FX_SCENE_MOD_VIZ] = fx_scene_alloc(sc, sizeof(viz_state));
    return sc->mod[FX_SCENE_MOD_VIZ];
}

static int size_args(fx_scene *sc, int32_t *w, int32_t *h)
{
    TRY(fx_scene_arg_int(sc, w));
    TRY(fx_scene_arg_int(sc, h));
    if (*w < 2 || *h < 2 || *w > 1025 || *h > 1025)
        return fx_scene_error(sc, "grid size %dx%d out of range (2..1025)", *w, *h);
    return 0;
}

/* exp(-r^2) * amp for r^2 in Q16.16 (e^-x = 2^(-x log2 e)) */
static int32_t bump(int64_t r2, int32_t amp)
{
    if (r2 > 40 * 65536)
        return 0;
    fx16 e = fx16_exp2(-(fx16)((r2 * 94548) >> 16)); /* log2(e) = 1.4427 in Q16 */
    return (int32_t)(((int64_t)e * amp) >> 16);
}

static int cmd_field(fx_scene *sc)
{
    static const char *const names[] = {"waves", "peaks", "terrain", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    int32_t w, h, seed = 1;
    fx16 rough = 39322; /* 0.6 */
    TRY(size_args(sc, &w, &h));
    if (k == 2) {
        TRY(fx_scene_arg_int(sc, &seed));
        if (fx_scene_more(sc))
            TRY(fx_scene_arg_fx16(sc, &rough));
    }
    TRY(fx_scene_end(sc));
    viz_state *st = vstate(sc);
    int32_t side = 2, kk = 1;
    while (side + 1 < (w > h ? w : h))
        side *= 2, kk++;
    size_t cells = k == 2 ? (size_t)(side + 1) * (side + 1) : (size_t)w * h;
    int32_t *g = st ? fx_scene_alloc(sc, cells * sizeof *g) : 0;
    if (!g)
        return fx_scene_error(sc, "out of scene memory for a %dx%d field", w, h);
    st->s = g;
    st->sw = w;
    st->sh = h;
    st->sstride = w;
    if (k == 2) {
        /* diamond-square on the enclosing 2^k + 1 grid; the field is its
         * top-left w x h corner */
        st->sstride = side + 1;
        return fx_terrain(g, side + 1, kk, 10000, rough, (uint32_t)seed) < 0
                   ? fx_scene_error(sc, "bad terrain parameters")
                   : 0;
    }
    for (int32_t j = 0; j < h; j++)
        for (int32_t i = 0; i < w; i++) {
            /* x, y in [0, 1] as Q16.16 */
            int64_t x = ((int64_t)i << 16) / (w - 1), y = ((int64_t)j << 16) / (h - 1);
            int32_t v;
            if (k == 0) {
                /* sin(3 turns x/2) cos(2 turns y/2) * 10000 */
                fx_angle a = (fx_angle)((uint64_t)x * 3 * 32768), b = (fx_angle)((uint64_t)y * 2 * 32768);
                v = (int32_t)(((int64_t)fx_sin(a) * fx_cos(b) * 10000) >> 32);
            } else {
                const int32_t bx[3] = {19661, 45875, 32768}, by[3] = {22938, 39322, 52429};
                const int32_t amp[3] = {10000, -8000, 5000};
                v = 0;
                for (int b = 0; b < 3; b++) {
                    int64_t dx = x - bx[b], dy = y - by[b];
                    /* width 0.18: r^2 / 0.0324 */
                    int64_t r2 = ((dx * dx + dy * dy) >> 16) * 65536 / 2123;
                    v += bump(r2, amp[b]);
                }
            }
            g[j * w + i] = v;
        }
    return 0;
}

static int cmd_vfield(fx_scene *sc)
{
    static const char *const names[] = {"vortex", "saddle", "swirl", "dipole", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    int32_t w, h;
    TRY(size_args(sc, &w, &h));
    TRY(fx_scene_end(sc));
    viz_state *st = vstate(sc);
    int32_t *u = st ? fx_scene_alloc(sc, (size_t)w * h * sizeof *u) : 0;
    int32_t *v = u ? fx_scene_alloc(sc, (size_t)w * h * sizeof *v) : 0;
    if (!v)
        return fx_scene_error(sc, "out of scene memory for a %dx%d field", w, h);
    for (int32_t j = 0; j < h; j++)
        for (int32_t i = 0; i < w; i++) {
            /* x, y in [-1, 1] (y up) in units of 1/1000 */
            int32_t x = (int32_t)(((int64_t)i * 2000) / (w - 1)) - 1000;
            int32_t y = 1000 - (int32_t)(((int64_t)j * 2000) / (h - 1));
            int32_t a, b;
            switch (k) {
            case 0: a = -y; b = x; break;
            case 1: a = x; b = -y; break;
            case 2: a = -y - x / 3; b = x - y / 3; break;
            default: {
                /* two opposite charges at (-0.5, 0) and (0.5, 0) */
                int64_t dx1 = x + 500, dx2 = x - 500, yy = (int64_t)y * y;
                int64_t r1 = dx1 * dx1 + yy + 2500, r2 = dx2 * dx2 + yy + 2500;
                a = (int32_t)((dx1 * 300000) / r1 - (dx2 * 300000) / r2);
                b = (int32_t)(((int64_t)y * 300000) / r1 - ((int64_t)y * 300000) / r2);
            }
            }
            u[j * w + i] = a;
            v[j * w + i] = b;
        }
    st->u = u;
    st->v = v;
    st->vw = w;
    st->vh = h;
    return 0;
}

static int rect_args(fx_scene *sc, fx_rect *r)
{
    int32_t v[4];
    for (int i = 0; i < 4; i++)
        TRY(fx_scene_arg_int(sc, &v[i]));
    if (v[2] < 1 || v[3] < 1)
        return fx_scene_error(sc, "empty rectangle %dx%d", v[2], v[3]);
    r->x0 = v[0];
    r->y0 = v[1];
    /* the far edge saturates: a rectangle reaching past int32 is clipped anyway */
    int64_t x1 = (int64_t)v[0] + v[2], y1 = (int64_t)v[1] + v[3];
    r->x1 = x1 > INT32_MAX ? INT32_MAX : (int32_t)x1;
    r->y1 = y1 > INT32_MAX ? INT32_MAX : (int32_t)y1;
    return 0;
}

static int scalar(fx_scene *sc, fx_grid *g)
{
    viz_state *st = sc->mod[FX_SCENE_MOD_VIZ];
    if (!st || !st->s)
        return fx_scene_error(sc, "no scalar field: use 'field' first");
    g->v = st->s;
    g->w = st->sw;
    g->h = st->sh;
    g->stride = st->sstride;
    return 0;
}

static int vector(fx_scene *sc, fx_vgrid *g)
{
    viz_state *st = sc->mod[FX_SCENE_MOD_VIZ];
    if (!st || !st->u)
        return fx_scene_error(sc, "no vector field: use 'vfield' first");
    g->u = st->u;
    g->v = st->v;
    g->w = st->vw;
    g->h = st->vh;
    g->stride = st->vw;
    return 0;
}

static fx_cmap plot_map(fx_scene *sc)
{
    fx_cmap m = fx_scene_fractal_state(sc)->cmap;
    return m == FX_CMAP_COUNT ? FX_CMAP_VIRIDIS : m;
}

static int cmd_heatmap(fx_scene *sc)
{
    fx_rect r;
    fx_grid g;
    int32_t lo = 0, hi = 0;
    TRY(rect_args(sc, &r));
    int given = fx_scene_more(sc);
    if (given) {
        TRY(fx_scene_arg_int(sc, &lo));
        TRY(fx_scene_arg_int(sc, &hi));
    }
    TRY(fx_scene_end(sc));
    TRY(scalar(sc, &g));
    if (!given)
        fx_grid_range(&g, &lo, &hi);
    fx_heatmap(&sc->ctx, r, &g, lo, hi, plot_map(sc));
    return 0;
}

static int cmd_colorbar(fx_scene *sc)
{
    fx_rect r;
    int32_t ticks = 5;
    TRY(rect_args(sc, &r));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &ticks));
    TRY(fx_scene_end(sc));
    if (ticks < 0 || ticks > 100)
        return fx_scene_error(sc, "tick count %d out of range (0..100)", ticks);
    fx_colorbar(&sc->ctx, r, plot_map(sc), ticks);
    return 0;
}

static int cmd_contour(fx_scene *sc)
{
    fx_rect r;
    fx_grid g;
    int32_t n, levels[64];
    TRY(rect_args(sc, &r));
    TRY(fx_scene_arg_int(sc, &n));
    if (n < 1 || n > 64)
        return fx_scene_error(sc, "level count %d out of range (1..64)", n);
    int given = fx_scene_more(sc);
    if (given)
        for (int i = 0; i < n; i++)
            TRY(fx_scene_arg_int(sc, &levels[i]));
    TRY(fx_scene_end(sc));
    TRY(scalar(sc, &g));
    if (!given) {
        /* n levels evenly inside (lo, hi) */
        int32_t lo, hi;
        fx_grid_range(&g, &lo, &hi);
        for (int i = 0; i < n; i++)
            levels[i] = (int32_t)(lo + ((int64_t)hi - lo) * (i + 1) / (n + 1));
    }
    for (int i = 0; i < n; i++)
        fx_contour(&sc->ctx, r, &g, levels[i]);
    return 0;
}

static int cmd_quiver(fx_scene *sc)
{
    fx_rect r;
    fx_vgrid g;
    int32_t step = 1;
    TRY(rect_args(sc, &r));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &step));
    TRY(fx_scene_end(sc));
    if (step < 1)
        return fx_scene_error(sc, "step must be at least 1");
    TRY(vector(sc, &g));
    fx_quiver(&sc->ctx, r, &g, step);
    return 0;
}

static int cmd_stream(fx_scene *sc)
{
    fx_rect r;
    fx_vgrid g;
    int32_t n;
    TRY(rect_args(sc, &r));
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_end(sc));
    if (n < 1 || n > 64)
        return fx_scene_error(sc, "seed count %d out of range (1..64)", n);
    TRY(vector(sc, &g));
    int64_t w = (int64_t)r.x1 - r.x0, h = (int64_t)r.y1 - r.y0;
    /* one-pixel steps: twice round the visible part is plenty */
    fx_rect vis = fx_rect_intersect(r, sc->ctx.clip);
    int32_t steps = 2 * ((vis.x1 - vis.x0) + (vis.y1 - vis.y0));
    if (fx_rect_empty(vis))
        return 0;
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++) {
            int32_t x = r.x0 + (int32_t)(((int64_t)(2 * i + 1) * w) / (2 * n));
            int32_t y = r.y0 + (int32_t)(((int64_t)(2 * j + 1) * h) / (2 * n));
            fx_streamline(&sc->ctx, r, &g, x, y, FX16_ONE, steps);
        }
    return 0;
}

const fx_scene_cmd fx_scene_cmds_viz[] = {
    {"field", cmd_field, "field waves|peaks GW GH | field terrain GW GH SEED [ROUGH]", 0},
    {"vfield", cmd_vfield, "vfield vortex|saddle|swirl|dipole GW GH", 0},
    {"heatmap", cmd_heatmap, "heatmap X Y W H [LO HI]", FX_SCENE_DRAWS},
    {"colorbar", cmd_colorbar, "colorbar X Y W H [TICKS]", FX_SCENE_DRAWS},
    {"contour", cmd_contour, "contour X Y W H N [LEVEL1 ... LEVELN]", FX_SCENE_DRAWS},
    {"quiver", cmd_quiver, "quiver X Y W H [STEP]", FX_SCENE_DRAWS},
    {"stream", cmd_stream, "stream X Y W H N", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
