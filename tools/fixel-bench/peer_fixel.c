/* SPDX-License-Identifier: MIT */
/* fixel through its public API only: one context, one call per primitive,
 * the colour set per primitive (fx_ctx_set_color packs it) as an application
 * would.
 *
 * A workload whose API has not landed on main yet stays NULL in the table at
 * the end and is shown as "-"; wiring one in is a few lines here. */
#include "bench.h"

#include <fixel/draw.h>
#include <fixel/line.h>
#include <fixel/surface.h>

/* Modules still being written land one by one; each is wired in as soon as
 * its header is on main, and its workloads show "-" until then. */
#if __has_include(<fixel/circle.h>)
#include <fixel/circle.h>
#define HAVE_CIRCLE 1
#endif
#if __has_include(<fixel/fill.h>)
#include <fixel/fill.h>
#define HAVE_FILL 1
#endif
#if __has_include(<fixel/fractal.h>)
#include <fixel/fractal.h>
#define HAVE_FRACTAL 1
#endif

struct fxb {
    fx_surface s, src;
    fx_ctx c;
};
static struct fxb C[FMT_COUNT];

static void *fx_open(const struct target *t)
{
    struct fxb *b = &C[t->fmt];
    fx_format f = t->fmt == FMT_XRGB8888 ? FX_FMT_XRGB8888 : FX_FMT_RGB565;
    if (fx_surface_init(&b->s, t->pixels, BW, BH, t->stride, f) != 0)
        return NULL;
    if (fx_surface_init(&b->src, WL->blit_src[t->fmt], BW, BH, t->stride, f) != 0)
        return NULL;
    fx_ctx_init(&b->c, &b->s);
    return b;
}
static void fx_close(void *ctx) { (void)ctx; }

#define OPAQUE(c) (0xFF000000u | (c))

static void fx_w1(void *ctx, int n)
{
    struct fxb *b = ctx;
    (void)n;
    fx_ctx_set_color(&b->c, OPAQUE(W1_COLOUR));
    fx_clear(&b->c);
}

static void fx_w2(void *ctx, int n)
{
    struct fxb *b = ctx;
    const struct wl_rect *r = WL->rects;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(r[i].c));
        fx_fill_rect(&b->c, r[i].x, r[i].y, r[i].w, r[i].h);
    }
}

static void fx_w3(void *ctx, int n)
{
    struct fxb *b = ctx;
    const struct wl_line *l = WL->lines;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(l[i].c));
        fx_line(&b->c, l[i].x0, l[i].y0, l[i].x1, l[i].y1);
    }
}

/* fx_aaline joins line.h, which exists already: bench.mk defines
 * BENCH_HAVE_AALINE when the header declares it. */
#ifdef BENCH_HAVE_AALINE
static void fx_w4(void *ctx, int n)
{
    struct fxb *b = ctx;
    const struct wl_line *l = WL->lines;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(l[i].c));
        fx_aaline(&b->c, l[i].x0, l[i].y0, l[i].x1, l[i].y1);
    }
}
#endif

#ifdef HAVE_CIRCLE
static void fx_w5(void *ctx, int n)
{
    struct fxb *b = ctx;
    const struct wl_circle *q = WL->circles;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(q[i].c));
        fx_circle(&b->c, q[i].cx, q[i].cy, q[i].r);
    }
}

static void fx_w6(void *ctx, int n)
{
    struct fxb *b = ctx;
    const struct wl_circle *q = WL->circles;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(q[i].c));
        fx_disc(&b->c, q[i].cx, q[i].cy, q[i].r);
    }
}
#endif

#ifdef HAVE_FILL
static void fx_w7(void *ctx, int n)
{
    struct fxb *b = ctx;
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

static void fx_w8(void *ctx, int n)
{
    struct fxb *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        fx_ctx_set_color(&b->c, OPAQUE(t->c[0]));
        fx_fill_tri(&b->c, t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]);
    }
}

static void fx_w8g(void *ctx, int n)
{
    struct fxb *b = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        int32_t xy[6] = {t->x[0], t->y[0], t->x[1], t->y[1], t->x[2], t->y[2]};
        fx_color col[3] = {OPAQUE(t->c[0]), OPAQUE(t->c[1]), OPAQUE(t->c[2])};
        fx_fill_tri_gouraud(&b->c, xy, col);
    }
}
#endif

#ifdef HAVE_FRACTAL
static void fx_w9(void *ctx, int n)
{
    struct fxb *b = ctx;
    (void)n;
    fx_mandel_w9(&b->s);
}
#endif

static void fx_w10(void *ctx, int n)
{
    struct fxb *b = ctx;
    (void)n;
    fx_blit(&b->s, 0, 0, &b->src);
}

const struct peer peer_fixel = {
    .name = "fixel",
    .fmt_mask = 3,
    .open = fx_open,
    .close = fx_close,
    .fn =
        {
            [W1_CLEAR] = fx_w1,
            [W2_RECTS] = fx_w2,
            [W3_LINES] = fx_w3,
#ifdef BENCH_HAVE_AALINE
            [W4_AALINES] = fx_w4,
#endif
#ifdef HAVE_CIRCLE
            [W5_CIRCLES] = fx_w5,
            [W6_DISCS] = fx_w6,
#endif
#ifdef HAVE_FILL
            [W7_POLYS] = fx_w7,
            [W8_TRIS] = fx_w8,
            [W8G_TRIS_GOURAUD] = fx_w8g,
#endif
#ifdef HAVE_FRACTAL
            [W9_MANDEL] = fx_w9,
#endif
            [W10_BLIT] = fx_w10,
        },
};
