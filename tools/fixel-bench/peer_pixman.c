/* SPDX-License-Identifier: MIT */
/* pixman 0.42 (Debian). Fills use pixman_image_fill_rectangles (SRC); the
 * non-AA triangles and polygons go through pixman's own rasterizer with an
 * a1 mask, polygons after an even-odd tessellation into trapezoids that is
 * timed with them (pixman has no polygon call; this is what a user of
 * pixman has to write). */
/* Without the peer libraries (`make all` on a machine without them) this file
 * compiles to nothing and fixel-bench measures fixel and the ceilings only. */
#ifdef BENCH_PEERS
#include "bench.h"

#include <pixman.h>
#include <stdlib.h>

struct px_ctx {
    pixman_image_t *dst, *src;
};

static pixman_color_t px_colour(uint32_t c)
{
    pixman_color_t p = {(uint16_t)((c >> 16 & 0xFF) * 0x101), (uint16_t)((c >> 8 & 0xFF) * 0x101),
                        (uint16_t)((c & 0xFF) * 0x101), 0xFFFF};
    return p;
}

static void *px_open(const struct target *t)
{
    struct px_ctx *c = calloc(1, sizeof *c);
    pixman_format_code_t f = t->fmt == FMT_XRGB8888 ? PIXMAN_x8r8g8b8 : PIXMAN_r5g6b5;
    c->dst = pixman_image_create_bits(f, BW, BH, (uint32_t *)t->pixels, t->stride);
    c->src = pixman_image_create_bits(f, BW, BH, (uint32_t *)WL->blit_src[t->fmt], t->stride);
    if (!c->dst || !c->src) {
        free(c);
        return NULL;
    }
    /* Without a clip region pixman's solid fill does not clip at all (it
     * writes past the row end); a user has to set one. */
    pixman_region32_t clip;
    pixman_region32_init_rect(&clip, 0, 0, BW, BH);
    pixman_image_set_clip_region32(c->dst, &clip);
    pixman_region32_fini(&clip);
    return c;
}

static void px_close(void *ctx)
{
    struct px_ctx *c = ctx;
    pixman_image_unref(c->dst);
    pixman_image_unref(c->src);
    free(c);
}

static void px_w1(void *ctx, int n)
{
    struct px_ctx *c = ctx;
    (void)n;
    pixman_color_t col = px_colour(W1_COLOUR);
    pixman_rectangle16_t r = {0, 0, BW, BH};
    pixman_image_fill_rectangles(PIXMAN_OP_SRC, c->dst, &col, 1, &r);
}

static void px_w2(void *ctx, int n)
{
    struct px_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *q = &WL->rects[i];
        pixman_color_t col = px_colour(q->c);
        pixman_rectangle16_t r = {(int16_t)q->x, (int16_t)q->y, (uint16_t)q->w, (uint16_t)q->h};
        pixman_image_fill_rectangles(PIXMAN_OP_SRC, c->dst, &col, 1, &r);
    }
}

#define FX(v) ((pixman_fixed_t)((v) * 65536.0 + ((v) < 0 ? -0.5 : 0.5)))
#define CENTRE(i) (pixman_int_to_fixed(i) + pixman_fixed_1 / 2)

static void px_w8(void *ctx, int n)
{
    struct px_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        pixman_color_t col = px_colour(t->c[0]);
        pixman_image_t *s = pixman_image_create_solid_fill(&col);
        pixman_triangle_t tri = {{CENTRE(t->x[0]), CENTRE(t->y[0])},
                                 {CENTRE(t->x[1]), CENTRE(t->y[1])},
                                 {CENTRE(t->x[2]), CENTRE(t->y[2])}};
        pixman_composite_triangles(PIXMAN_OP_OVER, s, c->dst, PIXMAN_a1, 0, 0, 0, 0, 1, &tri);
        pixman_image_unref(s);
    }
}

/* Even-odd polygon -> trapezoids: cut at every vertex y and at every edge
 * crossing, so that inside each band the edges keep their order; then pair
 * the edges sorted by x in the middle of the band. */
static int tessellate(const struct wl_poly *p, pixman_trapezoid_t *out)
{
    double ex0[POLY_N], ey0[POLY_N], ex1[POLY_N], ey1[POLY_N];
    double cuts[POLY_N + POLY_N * POLY_N / 2];
    int nc = 0, ntr = 0;
    for (int i = 0; i < POLY_N; i++) {
        int j = (i + 1) % POLY_N;
        ex0[i] = p->x[i] + 0.5;
        ey0[i] = p->y[i] + 0.5;
        ex1[i] = p->x[j] + 0.5;
        ey1[i] = p->y[j] + 0.5;
        cuts[nc++] = ey0[i];
    }
    for (int i = 0; i < POLY_N; i++)
        for (int j = i + 1; j < POLY_N; j++) {
            double ax = ex1[i] - ex0[i], ay = ey1[i] - ey0[i];
            double bx = ex1[j] - ex0[j], by = ey1[j] - ey0[j];
            double den = ax * by - ay * bx;
            if (den == 0)
                continue;
            double cx = ex0[j] - ex0[i], cy = ey0[j] - ey0[i];
            double u = (cx * by - cy * bx) / den, v = (cx * ay - cy * ax) / den;
            if (u > 0 && u < 1 && v > 0 && v < 1)
                cuts[nc++] = ey0[i] + u * ay;
        }
    qsort(cuts, (size_t)nc, sizeof cuts[0], bench_cmp_double);
    for (int b = 0; b + 1 < nc; b++) {
        double top = cuts[b], bot = cuts[b + 1];
        if (bot - top < 1e-9)
            continue;
        double mid = 0.5 * (top + bot), xs[POLY_N];
        int es[POLY_N], k = 0;
        for (int i = 0; i < POLY_N; i++) {
            double lo = ey0[i] < ey1[i] ? ey0[i] : ey1[i], hi = ey0[i] < ey1[i] ? ey1[i] : ey0[i];
            if (lo <= top && bot <= hi && lo != hi) {
                double x = ex0[i] + (mid - ey0[i]) * (ex1[i] - ex0[i]) / (ey1[i] - ey0[i]);
                int m = k++;
                while (m > 0 && xs[m - 1] > x) {
                    xs[m] = xs[m - 1];
                    es[m] = es[m - 1];
                    m--;
                }
                xs[m] = x;
                es[m] = i;
            }
        }
        for (int m = 0; m + 1 < k; m += 2) {
            pixman_trapezoid_t *t = &out[ntr++];
            int l = es[m], r = es[m + 1];
            t->top = FX(top);
            t->bottom = FX(bot);
            t->left.p1.x = FX(ex0[l]);
            t->left.p1.y = FX(ey0[l]);
            t->left.p2.x = FX(ex1[l]);
            t->left.p2.y = FX(ey1[l]);
            t->right.p1.x = FX(ex0[r]);
            t->right.p1.y = FX(ey0[r]);
            t->right.p2.x = FX(ex1[r]);
            t->right.p2.y = FX(ey1[r]);
        }
    }
    return ntr;
}

static void px_w7(void *ctx, int n)
{
    struct px_ctx *c = ctx;
    pixman_trapezoid_t traps[(POLY_N + POLY_N * POLY_N / 2) * POLY_N / 2];
    for (int i = 0; i < n; i++) {
        const struct wl_poly *p = &WL->polys[i];
        int nt = tessellate(p, traps);
        pixman_color_t col = px_colour(p->c);
        pixman_image_t *s = pixman_image_create_solid_fill(&col);
        pixman_composite_trapezoids(PIXMAN_OP_OVER, s, c->dst, PIXMAN_a1, 0, 0, 0, 0, nt, traps);
        pixman_image_unref(s);
    }
}

static void px_w10(void *ctx, int n)
{
    struct px_ctx *c = ctx;
    (void)n;
    pixman_image_composite32(PIXMAN_OP_SRC, c->src, NULL, c->dst, 0, 0, 0, 0, 0, 0, BW, BH);
}

const struct peer peer_pixman = {
    .name = "pixman",
    .fmt_mask = 3,
    .open = px_open,
    .close = px_close,
    .fn =
        {
            [W1_CLEAR] = px_w1,
            [W2_RECTS] = px_w2,
            [W7_POLYS] = px_w7,
            [W8_TRIS] = px_w8,
            [W10_BLIT] = px_w10,
        },
};

#endif /* BENCH_PEERS */
