/* SPDX-License-Identifier: MIT */
/* fixel as a user's program calls it: this file is compiled apart from the
 * project (bench.mk: -std=c11 -O2, no -march, no -fPIC, no project flags)
 * against the headers as `make install` lays them out (build/api-include/
 * fixel/*.h, nothing else of the source tree) and linked to libfixel.a like
 * any program. One fx_surface_init on the harness's buffer, one call per
 * primitive, fx_ctx_set_color before each. It is the "fixel-api" column;
 * the "fixel" column (peer_fixel.c) is built with the project's flags.
 * The harness side (struct peer, the workload arrays) is plain C in bench.h. */
#include "../bench.h"

#include <fixel/circle.h>
#include <fixel/draw.h>
#include <fixel/fill.h>
#include <fixel/fractal.h>
#include <fixel/line.h>
#include <fixel/surface.h>

struct api {
    fx_surface s, src;
    fx_ctx c;
};
static struct api A[FMT_COUNT];

static void *api_open(const struct target *t)
{
    struct api *b = &A[t->fmt];
    fx_format f = t->fmt == FMT_XRGB8888 ? FX_FMT_XRGB8888 : FX_FMT_RGB565;
    if (fx_surface_init(&b->s, t->pixels, BW, BH, t->stride, f) != 0 ||
        fx_surface_init(&b->src, WL->blit_src[t->fmt], BW, BH, t->stride, f) != 0)
        return NULL;
    fx_ctx_init(&b->c, &b->s);
    return b;
}
static void api_close(void *ctx) { (void)ctx; }

#define OPAQUE(c) (0xFF000000u | (c))

static void api_w1(void *ctx, int n)
{
    struct api *b = ctx;
    (void)n;
    fx_ctx_set_color(&b->c, OPAQUE(W1_COLOUR));
    fx_clear(&b->c);
}

static void api_w2(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *r = &WL->rects[i];
        fx_ctx_set_color(&b->c, OPAQUE(r->c));
        fx_fill_rect(&b->c, r->x, r->y, r->w, r->h);
    }
}

static void api_w3(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &WL->lines[i];
        fx_ctx_set_color(&b->c, OPAQUE(l->c));
        fx_line(&b->c, l->x0, l->y0, l->x1, l->y1);
    }
}

static void api_w4(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &WL->lines[i];
        fx_ctx_set_color(&b->c, OPAQUE(l->c));
        fx_aaline(&b->c, l->x0, l->y0, l->x1, l->y1);
    }
}

static void api_w5(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_circle *q = &WL->circles[i];
        fx_ctx_set_color(&b->c, OPAQUE(q->c));
        fx_circle(&b->c, q->cx, q->cy, q->r);
    }
}

static void api_w6(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_circle *q = &WL->circles[i];
        fx_ctx_set_color(&b->c, OPAQUE(q->c));
        fx_disc(&b->c, q->cx, q->cy, q->r);
    }
}

static void api_w7(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_poly *p = &WL->polys[i];
        int32_t xy[2 * POLY_N];
        for (int k = 0; k < POLY_N; k++) {
            xy[2 * k] = p->x[k];
            xy[2 * k + 1] = p->y[k];
        }
        fx_ctx_set_color(&b->c, OPAQUE(p->c));
        fx_fill_poly(&b->c, xy, POLY_N, FX_FILL_EVENODD);
    }
}

static void api_w8(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        fx_ctx_set_color(&b->c, OPAQUE(t->c[0]));
        fx_fill_tri(&b->c, t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]);
    }
}

static void api_w8g(void *ctx, int n)
{
    struct api *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        int32_t xy[6] = {t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]};
        fx_color col[3] = {OPAQUE(t->c[0]), OPAQUE(t->c[1]), OPAQUE(t->c[2])};
        fx_fill_tri_gouraud(&b->c, xy, col);
    }
}

/* docs/BENCHMARK.md W9: centre -0.5+0i, width 3, 256 iterations, its palette. */
static void api_w9(void *ctx, int n)
{
    struct api *b = ctx;
    (void)n;
    uint32_t lut[65];
    fx_dwell_pal pal;
    fx_dwell_pal_w9(&pal, lut, b->s.format);
    fx_fractal_view v = fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, BW, BH, 256);
    fx_fractal_render(&b->s, fx_surface_rect(&b->s), &v, &pal);
}

static void api_w10(void *ctx, int n)
{
    struct api *b = ctx;
    (void)n;
    fx_blit(&b->s, 0, 0, &b->src);
}

const struct peer peer_fixel_api = {
    .name = "fixel-api",
    .fmt_mask = 3,
    .open = api_open,
    .close = api_close,
    .fn =
        {
            [W1_CLEAR] = api_w1,
            [W2_RECTS] = api_w2,
            [W3_LINES] = api_w3,
            [W4_AALINES] = api_w4,
            [W5_CIRCLES] = api_w5,
            [W6_DISCS] = api_w6,
            [W7_POLYS] = api_w7,
            [W8_TRIS] = api_w8,
            [W8G_TRIS_GOURAUD] = api_w8g,
            [W9_MANDEL] = api_w9,
            [W10_BLIT] = api_w10,
        },
};
