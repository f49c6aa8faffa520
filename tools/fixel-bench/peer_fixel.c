/* SPDX-License-Identifier: MIT */
/* fixel through its public API only: one context, one call per primitive,
 * the colour set per primitive (fx_ctx_set_color packs it) as an application
 * would.
 * Every workload's API is on main: the entries of the table at the end are
 * all wired (a NULL entry would show as "-"). */
#include "bench.h"

#include <fixel/circle.h>
#include <fixel/draw.h>
#include <fixel/fill.h>
#include <fixel/fractal.h>
#include <fixel/line.h>
#include <fixel/surface.h>

#include "workloads.h"

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

/* W3 and W4 differ only in the line call, W5 and W6 in the circle call. */
typedef void (*line_fn)(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1);
typedef void (*circle_fn)(const fx_ctx *c, int32_t cx, int32_t cy, int32_t r);

static inline void lines(struct fxb *b, int n, line_fn draw)
{
    const struct wl_line *l = WL->lines;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(l[i].c));
        draw(&b->c, l[i].x0, l[i].y0, l[i].x1, l[i].y1);
    }
}

static inline void circles(struct fxb *b, int n, circle_fn draw)
{
    const struct wl_circle *q = WL->circles;
    for (int i = 0; i < n; i++) {
        fx_ctx_set_color(&b->c, OPAQUE(q[i].c));
        draw(&b->c, q[i].cx, q[i].cy, q[i].r);
    }
}

static void fx_w3(void *ctx, int n) { lines(ctx, n, fx_line); }
static void fx_w4(void *ctx, int n) { lines(ctx, n, fx_aaline); }
static void fx_w5(void *ctx, int n) { circles(ctx, n, fx_circle); }
static void fx_w6(void *ctx, int n) { circles(ctx, n, fx_disc); }

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

static void fx_w9(void *ctx, int n)
{
    struct fxb *b = ctx;
    (void)n;
    bench_mandel_w9(&b->s);
}

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
            [W4_AALINES] = fx_w4,
            [W5_CIRCLES] = fx_w5,
            [W6_DISCS] = fx_w6,
            [W7_POLYS] = fx_w7,
            [W8_TRIS] = fx_w8,
            [W8G_TRIS_GOURAUD] = fx_w8g,
            [W9_MANDEL] = fx_w9,
            [W10_BLIT] = fx_w10,
        },
};
