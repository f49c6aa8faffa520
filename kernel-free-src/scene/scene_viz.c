/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of the viz module: built-in integer fields (the
 * scripts have no data files of their own) and the plots drawn from them. */
#include "fixel/colour.h"
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
    int32_t *ta, *tb, *tc; /* tensor field */
    int32_t tw, th;
    fx_tensor_style tstyle;
    int have_tstyle;
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
    /* one-pixel steps: twice round the part on the surface is plenty (and
     * bounds the work). The surface, not the clip: a band of a frame must
     * trace the same streamlines as the whole frame, and a streamline draws
     * a step past its rectangle, so one whose rectangle misses a band can
     * still light the band's edge row. */
    fx_rect on = fx_rect_intersect(r, (fx_rect){0, 0, sc->ctx.surf.w, sc->ctx.surf.h});
    int32_t steps = 2 * ((on.x1 - on.x0) + (on.y1 - on.y0));
    if (fx_rect_empty(on))
        return 0;
    for (int32_t j = 0; j < n; j++)
        for (int32_t i = 0; i < n; i++) {
            int32_t x = r.x0 + (int32_t)(((int64_t)(2 * i + 1) * w) / (2 * n));
            int32_t y = r.y0 + (int32_t)(((int64_t)(2 * j + 1) * h) / (2 * n));
            fx_streamline(&sc->ctx, r, &g, x, y, FX16_ONE, steps);
        }
    return 0;
}


/* ---- tensor fields ---- */

static int32_t clamp_t(int64_t v)
{
    return (int32_t)(v > FX_TENSOR_MAX ? FX_TENSOR_MAX : v < -FX_TENSOR_MAX ? -FX_TENSOR_MAX : v);
}

static int cmd_tfield(fx_scene *sc)
{
    static const char *const names[] = {"hessian", "rotating", 0};
    int k = fx_scene_arg_choice(sc, names);
    TRY(k);
    int32_t w = 0, h = 0;
    if (k == 1)
        TRY(size_args(sc, &w, &h));
    TRY(fx_scene_end(sc));
    viz_state *st = vstate(sc);
    if (k == 0) {
        if (!st || !st->s)
            return fx_scene_error(sc, "no scalar field: use 'field' first");
        w = st->sw;
        h = st->sh;
    }
    size_t n = (size_t)w * h;
    int32_t *a = st ? fx_scene_alloc(sc, n * sizeof *a) : 0;
    int32_t *b = a ? fx_scene_alloc(sc, n * sizeof *b) : 0;
    int32_t *c = b ? fx_scene_alloc(sc, n * sizeof *c) : 0;
    if (!c)
        return fx_scene_error(sc, "out of scene memory for a %dx%d tensor field", w, h);
    for (int32_t j = 0; j < h; j++)
        for (int32_t i = 0; i < w; i++) {
            size_t o = (size_t)j * w + i;
            if (k == 0) {
                /* the Hessian by central differences (one-sided at the
                 * border), y up: d/dy = -d/drow */
                const int32_t *f = st->s;
                int32_t S = st->sstride;
                int32_t i0 = i > 0 ? i - 1 : i, i1 = i < w - 1 ? i + 1 : i;
                int32_t j0 = j > 0 ? j - 1 : j, j1 = j < h - 1 ? j + 1 : j;
                int64_t fc = f[(ptrdiff_t)j * S + i];
                int64_t fxx = (int64_t)f[(ptrdiff_t)j * S + i1] - 2 * fc + f[(ptrdiff_t)j * S + i0];
                int64_t fyy = (int64_t)f[(ptrdiff_t)j1 * S + i] - 2 * fc + f[(ptrdiff_t)j0 * S + i];
                int64_t fxy = -((int64_t)f[(ptrdiff_t)j1 * S + i1] - f[(ptrdiff_t)j0 * S + i1] -
                                f[(ptrdiff_t)j1 * S + i0] + f[(ptrdiff_t)j0 * S + i0]) /
                              4;
                a[o] = clamp_t(fxx);
                b[o] = clamp_t(fxy);
                c[o] = clamp_t(fyy);
            } else {
                /* eigenvalues 1000 (x + 0.3) and 1000 (y + 0.3) with x, y in
                 * [-1, 1] (y up): all four sign cases; the first eigenvector
                 * radial, A = R diag(p, q) R^T */
                int64_t x = ((int64_t)i * 2000) / (w - 1) - 1000, y = 1000 - ((int64_t)j * 2000) / (h - 1);
                int64_t p = x + 300, q = y + 300;
                fx_angle t = fx_atan2((int32_t)y, (int32_t)x);
                int64_t co = fx_cos(t), si = fx_sin(t); /* Q16 */
                a[o] = (int32_t)((p * co * co + q * si * si) >> 32);
                b[o] = (int32_t)(((p - q) * co * si) >> 32);
                c[o] = (int32_t)((p * si * si + q * co * co) >> 32);
            }
        }
    st->ta = a;
    st->tb = b;
    st->tc = c;
    st->tw = w;
    st->th = h;
    return 0;
}

static int cmd_tensorstyle(fx_scene *sc)
{
    fx_tensor_style t;
    TRY(fx_scene_arg_color(sc, &t.pos));
    TRY(fx_scene_arg_color(sc, &t.neg));
    TRY(fx_scene_arg_color(sc, &t.mixed));
    TRY(fx_scene_end(sc));
    viz_state *st = vstate(sc);
    if (!st)
        return fx_scene_error(sc, "out of scene memory");
    st->tstyle = t;
    st->have_tstyle = 1;
    return 0;
}

static int cmd_tensor(fx_scene *sc)
{
    fx_rect r;
    int32_t step = 1;
    TRY(rect_args(sc, &r));
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &step));
    TRY(fx_scene_end(sc));
    if (step < 1)
        return fx_scene_error(sc, "step must be at least 1");
    viz_state *st = sc->mod[FX_SCENE_MOD_VIZ];
    if (!st || !st->ta)
        return fx_scene_error(sc, "no tensor field: use 'tfield' first");
    fx_tgrid g = {st->ta, st->tb, st->tc, st->tw, st->th, st->tw};
    /* blue for positive definite, red negative, pale green for saddles */
    static const fx_tensor_style def = {0xFF3070D0u, 0xFFD04040u, 0xFF90C070u};
    fx_tensor_glyphs(&sc->ctx, r, &g, step, st->have_tstyle ? &st->tstyle : &def);
    return 0;
}

/* ---- multi-part glyphs ---- */

static int cmd_starglyph(fx_scene *sc)
{
    int32_t cx, cy, rad;
    fx_color outline;
    fx16 vals[32];
    int32_t n = 0;
    TRY(fx_scene_arg_int(sc, &cx));
    TRY(fx_scene_arg_int(sc, &cy));
    TRY(fx_scene_arg_int(sc, &rad));
    TRY(fx_scene_arg_color(sc, &outline));
    while (fx_scene_more(sc)) {
        if (n == 32)
            return fx_scene_error(sc, "more than 32 values");
        TRY(fx_scene_arg_fx16(sc, &vals[n]));
        n++;
    }
    if (n < 3)
        return fx_scene_error(sc, "a star glyph needs 3..32 values");
    if (rad < 0 || rad > 1048576)
        return fx_scene_error(sc, "radius %d out of range (0..1048576)", rad);
    fx_star_glyph(&sc->ctx, cx, cy, rad, vals, n, outline);
    return 0;
}

/* Arrow from the vector field; disc colour and bar from the scalar field
 * at the nearest of its nodes: its value, and its gradient's magnitude. */
static int64_t grad_mag(const fx_grid *s, int32_t i, int32_t j)
{
    int32_t i0 = i > 0 ? i - 1 : i, i1 = i < s->w - 1 ? i + 1 : i;
    int32_t j0 = j > 0 ? j - 1 : j, j1 = j < s->h - 1 ? j + 1 : j;
    /* central differences per node spacing, doubled to stay in integers */
    int64_t gx = ((int64_t)s->v[(ptrdiff_t)j * s->stride + i1] - s->v[(ptrdiff_t)j * s->stride + i0]) * 2 / (i1 - i0);
    int64_t gy = ((int64_t)s->v[(ptrdiff_t)j1 * s->stride + i] - s->v[(ptrdiff_t)j0 * s->stride + i]) * 2 / (j1 - j0);
    /* |values| < 2^31: each difference < 2^33, brought under 2^31 for fx_hypot */
    return (int64_t)fx_hypot((int32_t)(gx / 8), (int32_t)(gy / 8));
}

static int cmd_glyphs(fx_scene *sc)
{
    fx_rect r;
    fx_vgrid g = {0, 0, 0, 0, 0};
    fx_grid s = {0, 0, 0, 0};
    int32_t step;
    TRY(rect_args(sc, &r));
    TRY(fx_scene_arg_int(sc, &step));
    TRY(fx_scene_end(sc));
    if (step < 1)
        return fx_scene_error(sc, "step must be at least 1");
    TRY(vector(sc, &g));
    TRY(scalar(sc, &s));
    int32_t lo, hi;
    fx_grid_range(&s, &lo, &hi);
    int64_t W = (int64_t)r.x1 - r.x0, H = (int64_t)r.y1 - r.y0;
    int64_t sx = (W - 1) * step / (g.w - 1), sy = (H - 1) * step / (g.h - 1);
    int64_t size = (sx < sy ? sx : sy) * 9 / 10;
    if (size < 4)
        return 0;
    if (size > 4096)
        size = 4096;
    /* the largest speed and gradient over the drawn nodes scale arrow and bar */
    uint32_t vmax = 1;
    int64_t gmax = 1;
    for (int pass = 0; pass < 2; pass++)
        for (int32_t j = 0; j < g.h; j += step)
            for (int32_t i = 0; i < g.w; i += step) {
                ptrdiff_t o = (ptrdiff_t)j * g.w + i;
                int32_t si = (int32_t)((int64_t)i * (s.w - 1) / (g.w - 1));
                int32_t sj = (int32_t)((int64_t)j * (s.h - 1) / (g.h - 1));
                int64_t gm = grad_mag(&s, si, sj);
                uint32_t m = fx_hypot(g.u[o], g.v[o]);
                if (pass == 0) {
                    vmax = m > vmax ? m : vmax;
                    gmax = gm > gmax ? gm : gmax;
                    continue;
                }
                int64_t px = r.x0 + (int64_t)i * (W - 1) / (g.w - 1), py = r.y0 + (int64_t)j * (H - 1) / (g.h - 1);
                if (px + size < sc->ctx.clip.x0 || px - size > sc->ctx.clip.x1 || py + size < sc->ctx.clip.y0 ||
                    py - size > sc->ctx.clip.y1)
                    continue;
                int64_t sv = s.v[(ptrdiff_t)sj * s.stride + si];
                fx16 t = hi > lo ? (fx16)((sv - lo) * 65536 / ((int64_t)hi - lo)) : 0;
                fx16 du = (fx16)((int64_t)g.u[o] * 65536 / vmax), dv = (fx16)((int64_t)g.v[o] * 65536 / vmax);
                fx16 bar = (fx16)(gm * 65536 / gmax);
                fx_multi_glyph(&sc->ctx, (int32_t)px, (int32_t)py, (int32_t)size, du, dv, t, bar, plot_map(sc));
            }
    return 0;
}

/* ---- colour from wavelength ---- */

static int cmd_chromaticity(fx_scene *sc)
{
    static const char *const modes[] = {"all", "fill", "lines", 0};
    fx_rect r;
    int mode = 0;
    TRY(rect_args(sc, &r));
    if (fx_scene_more(sc))
        TRY(mode = fx_scene_arg_choice(sc, modes));
    TRY(fx_scene_end(sc));
    int lines = FX_CHROMA_LOCUS | FX_CHROMA_GAMUT | FX_CHROMA_TICKS;
    int flags = mode == 0 ? FX_CHROMA_FILL | lines : mode == 1 ? FX_CHROMA_FILL : lines;
    if (fx_chromaticity_diagram(&sc->ctx, r, flags) == -FX_E2BIG)
        return fx_scene_error(sc, "diagram %dx%d too large (at most 1048576 pixels a side)", r.x1 - r.x0,
                              r.y1 - r.y0);
    return 0;
}

static int cmd_spectrum(fx_scene *sc)
{
    fx_rect r;
    int32_t nm0 = FX_CIE_FIRST, nm1 = FX_CIE_FIRST + (FX_CIE_N - 1) * FX_CIE_STEP;
    TRY(rect_args(sc, &r));
    if (fx_scene_more(sc)) {
        TRY(fx_scene_arg_int(sc, &nm0));
        TRY(fx_scene_arg_int(sc, &nm1));
    }
    TRY(fx_scene_end(sc));
    if (nm0 < 380 || nm1 > 780 || nm0 >= nm1)
        return fx_scene_error(sc, "wavelengths %d..%d: need 380 <= NM0 < NM1 <= 780", nm0, nm1);
    /* one column per visible pixel, its wavelength at the column's centre */
    fx_rect v = fx_rect_intersect(r, sc->ctx.clip);
    if (fx_rect_empty(v))
        return 0;
    int64_t w = (int64_t)r.x1 - r.x0;
    fx_ctx c = sc->ctx;
    for (int32_t x = v.x0; x < v.x1; x++) {
        int64_t k = (int64_t)x - r.x0;
        int64_t nm16 = (int64_t)nm0 * 65536 + ((int64_t)(nm1 - nm0) * 65536 * (2 * k + 1)) / (2 * w);
        fx_ctx_set_color(&c, fx_wavelength_to_rgb((fx16)nm16));
        fx_fill_rect(&c, x, v.y0, 1, v.y1 - v.y0);
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
    {"tfield", cmd_tfield, "tfield hessian | tfield rotating GW GH", 0},
    {"tensorstyle", cmd_tensorstyle, "tensorstyle POSITIVE NEGATIVE MIXED", 0},
    {"tensor", cmd_tensor, "tensor X Y W H [STEP]", FX_SCENE_DRAWS},
    {"starglyph", cmd_starglyph, "starglyph CX CY R OUTLINE V1 V2 V3 ... (3..32 values in 0..1)", FX_SCENE_DRAWS},
    {"glyphs", cmd_glyphs, "glyphs X Y W H STEP", FX_SCENE_DRAWS},
    {"chromaticity", cmd_chromaticity, "chromaticity X Y W H [all|fill|lines]", FX_SCENE_DRAWS},
    {"spectrum", cmd_spectrum, "spectrum X Y W H [NM0 NM1]", FX_SCENE_DRAWS},
    {0, 0, 0, 0},
};
