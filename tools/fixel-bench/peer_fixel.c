/* fixel through its public API only, one call per primitive, colours
 * converted per call as an application would.
 *
 * A workload whose API has not landed yet stays NULL in the table below and
 * is shown as "-"; wiring one in is a two-line change here. */
#include "bench.h"

#include <fixel/surface.h>

struct fx_ctx {
    fx_surface s, src;
};
static struct fx_ctx C[FMT_COUNT];

static void *fx_open(const struct target *t)
{
    struct fx_ctx *c = &C[t->fmt];
    fx_format f = t->fmt == FMT_XRGB8888 ? FX_FMT_XRGB8888 : FX_FMT_RGB565;
    if (fx_surface_init(&c->s, t->pixels, BW, BH, t->stride, f) != 0)
        return NULL;
    if (fx_surface_init(&c->src, WL->blit_src[t->fmt], BW, BH, t->stride, f) != 0)
        return NULL;
    return c;
}
static void fx_close(void *ctx) { (void)ctx; }

#define OPAQUE(c) (0xFF000000u | (c))

static void fx_w1(void *ctx, int n)
{
    struct fx_ctx *c = ctx;
    (void)n;
    fx_surface_clear(&c->s, OPAQUE(W1_COLOUR));
}

static void fx_w2(void *ctx, int n)
{
    struct fx_ctx *c = ctx;
    const struct wl_rect *r = WL->rects;
    for (int i = 0; i < n; i++) {
        fx_rect q = {r[i].x, r[i].y, r[i].x + r[i].w, r[i].y + r[i].h};
        fx_surface_fill(&c->s, q, OPAQUE(r[i].c));
    }
}

static void fx_w10(void *ctx, int n)
{
    struct fx_ctx *c = ctx;
    (void)n;
    fx_blit(&c->s, 0, 0, &c->src);
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
            [W10_BLIT] = fx_w10,
        },
};
