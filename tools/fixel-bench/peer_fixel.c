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
            [W10_BLIT] = fx_w10,
        },
};
