/* SPDX-License-Identifier: MIT */
/* cairo 1.16 (Debian) drawing into the harness buffer through an image
 * surface. Integer coordinates denote pixel centres, so every vertex gets
 * +0.5; non-AA workloads use CAIRO_ANTIALIAS_NONE, all drawing uses
 * CAIRO_OPERATOR_SOURCE with opaque colours. */
/* Without the peer libraries (`make all` on a machine without them) this file
 * compiles to nothing and fixel-bench measures fixel and the ceilings only. */
#ifdef BENCH_PEERS
#include "bench.h"

#include <cairo.h>
#include <math.h>
#include <stdlib.h>

struct cr_ctx {
    cairo_surface_t *s, *src;
    cairo_t *cr;
};

static void set_rgb(cairo_t *cr, uint32_t c)
{
    cairo_set_source_rgb(cr, (c >> 16 & 0xFF) / 255.0, (c >> 8 & 0xFF) / 255.0, (c & 0xFF) / 255.0);
}

static void *cr_open(const struct target *t)
{
    struct cr_ctx *c = calloc(1, sizeof *c);
    cairo_format_t f = t->fmt == FMT_XRGB8888 ? CAIRO_FORMAT_RGB24 : CAIRO_FORMAT_RGB16_565;
    c->s = cairo_image_surface_create_for_data(t->pixels, f, BW, BH, t->stride);
    c->src = cairo_image_surface_create_for_data(WL->blit_src[t->fmt], f, BW, BH, t->stride);
    c->cr = cairo_create(c->s);
    if (cairo_status(c->cr) != CAIRO_STATUS_SUCCESS) {
        free(c);
        return NULL;
    }
    cairo_set_operator(c->cr, CAIRO_OPERATOR_SOURCE);
    cairo_set_line_width(c->cr, 1.0);
    return c;
}

static void cr_close(void *ctx)
{
    struct cr_ctx *c = ctx;
    cairo_destroy(c->cr);
    cairo_surface_finish(c->s);
    cairo_surface_destroy(c->s);
    cairo_surface_destroy(c->src);
    free(c);
}

static void cr_done(struct cr_ctx *c) { cairo_surface_flush(c->s); }

static void cr_w1(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    (void)n;
    set_rgb(c->cr, W1_COLOUR);
    cairo_paint(c->cr);
    cr_done(c);
}

static void cr_w2(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (int i = 0; i < n; i++) {
        const struct wl_rect *r = &WL->rects[i];
        set_rgb(cr, r->c);
        cairo_rectangle(cr, r->x, r->y, r->w, r->h);
        cairo_fill(cr);
    }
    cr_done(c);
}

static void lines(struct cr_ctx *c, int n, cairo_antialias_t aa)
{
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, aa);
    /* square caps reach the centre of both end pixels, as "both endpoints
     * drawn" asks */
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_SQUARE);
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &WL->lines[i];
        set_rgb(cr, l->c);
        cairo_move_to(cr, l->x0 + 0.5, l->y0 + 0.5);
        cairo_line_to(cr, l->x1 + 0.5, l->y1 + 0.5);
        cairo_stroke(cr);
    }
    cr_done(c);
}
static void cr_w3(void *ctx, int n) { lines(ctx, n, CAIRO_ANTIALIAS_NONE); }
static void cr_w4(void *ctx, int n) { lines(ctx, n, CAIRO_ANTIALIAS_DEFAULT); }

/* W5 strokes the circles that W6 fills */
static inline void circles(struct cr_ctx *c, int n, void (*paint)(cairo_t *))
{
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (int i = 0; i < n; i++) {
        const struct wl_circle *q = &WL->circles[i];
        set_rgb(cr, q->c);
        cairo_arc(cr, q->cx + 0.5, q->cy + 0.5, q->r, 0, 2 * M_PI);
        paint(cr);
    }
    cr_done(c);
}
static void cr_w5(void *ctx, int n) { circles(ctx, n, cairo_stroke); }
static void cr_w6(void *ctx, int n) { circles(ctx, n, cairo_fill); }

static void cr_w7(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
    for (int i = 0; i < n; i++) {
        const struct wl_poly *p = &WL->polys[i];
        set_rgb(cr, p->c);
        cairo_move_to(cr, p->x[0] + 0.5, p->y[0] + 0.5);
        for (int k = 1; k < POLY_N; k++)
            cairo_line_to(cr, p->x[k] + 0.5, p->y[k] + 0.5);
        cairo_close_path(cr);
        cairo_fill(cr);
    }
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cr_done(c);
}

static void tri_path(cairo_t *cr, const struct wl_tri *t)
{
    cairo_move_to(cr, t->x[0] + 0.5, t->y[0] + 0.5);
    cairo_line_to(cr, t->x[1] + 0.5, t->y[1] + 0.5);
    cairo_line_to(cr, t->x[2] + 0.5, t->y[2] + 0.5);
    cairo_close_path(cr);
}

static void cr_w8(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        set_rgb(cr, t->c[0]);
        tri_path(cr, t);
        cairo_fill(cr);
    }
    cr_done(c);
}

static void cr_w8g(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    cairo_t *cr = c->cr;
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        cairo_pattern_t *p = cairo_pattern_create_mesh();
        cairo_mesh_pattern_begin_patch(p);
        cairo_mesh_pattern_move_to(p, t->x[0] + 0.5, t->y[0] + 0.5);
        cairo_mesh_pattern_line_to(p, t->x[1] + 0.5, t->y[1] + 0.5);
        cairo_mesh_pattern_line_to(p, t->x[2] + 0.5, t->y[2] + 0.5);
        for (int k = 0; k < 3; k++) {
            uint32_t q = t->c[k];
            cairo_mesh_pattern_set_corner_color_rgb(p, (unsigned)k, (q >> 16 & 0xFF) / 255.0,
                                                    (q >> 8 & 0xFF) / 255.0, (q & 0xFF) / 255.0);
        }
        cairo_mesh_pattern_end_patch(p);
        cairo_set_source(cr, p);
        tri_path(cr, t);
        cairo_fill(cr);
        cairo_pattern_destroy(p);
    }
    cr_done(c);
}

static void cr_w10(void *ctx, int n)
{
    struct cr_ctx *c = ctx;
    (void)n;
    cairo_set_source_surface(c->cr, c->src, 0, 0);
    cairo_paint(c->cr);
    cr_done(c);
}

const struct peer peer_cairo = {
    .name = "cairo",
    .fmt_mask = 3,
    .open = cr_open,
    .close = cr_close,
    .fn =
        {
            [W1_CLEAR] = cr_w1,
            [W2_RECTS] = cr_w2,
            [W3_LINES] = cr_w3,
            [W4_AALINES] = cr_w4,
            [W5_CIRCLES] = cr_w5,
            [W6_DISCS] = cr_w6,
            [W7_POLYS] = cr_w7,
            [W8_TRIS] = cr_w8,
            [W8G_TRIS_GOURAUD] = cr_w8g,
            [W10_BLIT] = cr_w10,
        },
};

#endif /* BENCH_PEERS */
