/* SPDX-License-Identifier: MIT */
/* SDL2 2.26 and SDL2_gfx 1.0 (Debian), both through SDL's software renderer
 * on an SDL_Surface that wraps the harness buffer. Blending is off (every
 * colour is opaque and replaces the pixel); each call ends with
 * SDL_RenderFlush so that batched commands are drawn inside the timing. */
/* Without the peer libraries (`make all` on a machine without them) this file
 * compiles to nothing and fixel-bench measures fixel and the ceilings only. */
#ifdef BENCH_PEERS
#include "bench.h"

#include <SDL.h>
#include <SDL2_gfxPrimitives.h>
#include <stdlib.h>

struct sdl_ctx {
    SDL_Surface *s, *src;
    SDL_Renderer *r;
};

#define RGB(c) (Uint8)((c) >> 16 & 0xFF), (Uint8)((c) >> 8 & 0xFF), (Uint8)((c) & 0xFF)

static void *sdl_open(const struct target *t)
{
    struct sdl_ctx *c = calloc(1, sizeof *c);
    Uint32 f = t->fmt == FMT_XRGB8888 ? SDL_PIXELFORMAT_RGB888 : SDL_PIXELFORMAT_RGB565;
    int depth = t->fmt == FMT_XRGB8888 ? 32 : 16;
    c->s = SDL_CreateRGBSurfaceWithFormatFrom(t->pixels, BW, BH, depth, t->stride, f);
    c->src = SDL_CreateRGBSurfaceWithFormatFrom(WL->blit_src[t->fmt], BW, BH, depth, t->stride, f);
    if (!c->s || !c->src) {
        free(c);
        return NULL;
    }
    SDL_SetSurfaceBlendMode(c->src, SDL_BLENDMODE_NONE);
    c->r = SDL_CreateSoftwareRenderer(c->s);
    if (!c->r) {
        SDL_FreeSurface(c->s);
        SDL_FreeSurface(c->src);
        free(c);
        return NULL;
    }
    SDL_SetRenderDrawBlendMode(c->r, SDL_BLENDMODE_NONE);
    return c;
}

static void sdl_close(void *ctx)
{
    struct sdl_ctx *c = ctx;
    SDL_DestroyRenderer(c->r);
    SDL_FreeSurface(c->s);
    SDL_FreeSurface(c->src);
    free(c);
}

static void sdl_w1(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    (void)n;
    SDL_SetRenderDrawColor(c->r, RGB(W1_COLOUR), 255);
    SDL_RenderClear(c->r);
    SDL_RenderFlush(c->r);
}

static void sdl_w2(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *q = &WL->rects[i];
        SDL_Rect r = {q->x, q->y, q->w, q->h};
        SDL_SetRenderDrawColor(c->r, RGB(q->c), 255);
        SDL_RenderFillRect(c->r, &r);
    }
    SDL_RenderFlush(c->r);
}

static void sdl_w3(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &WL->lines[i];
        SDL_SetRenderDrawColor(c->r, RGB(l->c), 255);
        SDL_RenderDrawLine(c->r, l->x0, l->y0, l->x1, l->y1);
    }
    SDL_RenderFlush(c->r);
}

static void tri(struct sdl_ctx *c, const struct wl_tri *t, int gouraud)
{
    SDL_Vertex v[3];
    for (int k = 0; k < 3; k++) {
        uint32_t q = t->c[gouraud ? k : 0];
        v[k].position.x = (float)t->x[k] + 0.5f;
        v[k].position.y = (float)t->y[k] + 0.5f;
        v[k].color.r = (Uint8)(q >> 16);
        v[k].color.g = (Uint8)(q >> 8);
        v[k].color.b = (Uint8)q;
        v[k].color.a = 255;
        v[k].tex_coord.x = v[k].tex_coord.y = 0;
    }
    SDL_RenderGeometry(c->r, NULL, v, 3, NULL, 0);
}

static void sdl_w8(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++)
        tri(c, &WL->tris[i], 0);
    SDL_RenderFlush(c->r);
}

static void sdl_w8g(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++)
        tri(c, &WL->tris[i], 1);
    SDL_RenderFlush(c->r);
}

static void sdl_w10(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    (void)n;
    SDL_BlitSurface(c->src, NULL, c->s, NULL);
}

const struct peer peer_sdl2 = {
    .name = "sdl2",
    .fmt_mask = 3,
    .open = sdl_open,
    .close = sdl_close,
    .fn =
        {
            [W1_CLEAR] = sdl_w1,
            [W2_RECTS] = sdl_w2,
            [W3_LINES] = sdl_w3,
            [W8_TRIS] = sdl_w8,
            [W8G_TRIS_GOURAUD] = sdl_w8g,
            [W10_BLIT] = sdl_w10,
        },
};

/* ---- SDL2_gfx: inclusive corner coordinates, Sint16 vertex arrays ---- */

static void gfx_w1(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    (void)n;
    boxRGBA(c->r, 0, 0, BW - 1, BH - 1, RGB(W1_COLOUR), 255);
    SDL_RenderFlush(c->r);
}

static void gfx_w2(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_rect *q = &WL->rects[i];
        boxRGBA(c->r, (Sint16)q->x, (Sint16)q->y, (Sint16)(q->x + q->w - 1), (Sint16)(q->y + q->h - 1),
                RGB(q->c), 255);
    }
    SDL_RenderFlush(c->r);
}

/* W3 and W4 differ only in the line call, W5 and W6 in the circle call. */
typedef int (*gfx_line_fn)(SDL_Renderer *r, Sint16 x1, Sint16 y1, Sint16 x2, Sint16 y2, Uint8 cr, Uint8 cg,
                           Uint8 cb, Uint8 ca);
typedef int (*gfx_circle_fn)(SDL_Renderer *r, Sint16 x, Sint16 y, Sint16 rad, Uint8 cr, Uint8 cg, Uint8 cb,
                             Uint8 ca);

static inline void gfx_lines(struct sdl_ctx *c, int n, gfx_line_fn draw)
{
    for (int i = 0; i < n; i++) {
        const struct wl_line *l = &WL->lines[i];
        draw(c->r, (Sint16)l->x0, (Sint16)l->y0, (Sint16)l->x1, (Sint16)l->y1, RGB(l->c), 255);
    }
    SDL_RenderFlush(c->r);
}

static inline void gfx_circles(struct sdl_ctx *c, int n, gfx_circle_fn draw)
{
    for (int i = 0; i < n; i++) {
        const struct wl_circle *q = &WL->circles[i];
        draw(c->r, (Sint16)q->cx, (Sint16)q->cy, (Sint16)q->r, RGB(q->c), 255);
    }
    SDL_RenderFlush(c->r);
}

static void gfx_w3(void *ctx, int n) { gfx_lines(ctx, n, lineRGBA); }
static void gfx_w4(void *ctx, int n) { gfx_lines(ctx, n, aalineRGBA); }
static void gfx_w5(void *ctx, int n) { gfx_circles(ctx, n, circleRGBA); }
static void gfx_w6(void *ctx, int n) { gfx_circles(ctx, n, filledCircleRGBA); }

static void gfx_w7(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_poly *p = &WL->polys[i];
        Sint16 vx[POLY_N], vy[POLY_N];
        for (int k = 0; k < POLY_N; k++) {
            vx[k] = (Sint16)p->x[k];
            vy[k] = (Sint16)p->y[k];
        }
        filledPolygonRGBA(c->r, vx, vy, POLY_N, RGB(p->c), 255);
    }
    SDL_RenderFlush(c->r);
}

static void gfx_w8(void *ctx, int n)
{
    struct sdl_ctx *c = ctx;
    for (int i = 0; i < n; i++) {
        const struct wl_tri *t = &WL->tris[i];
        filledTrigonRGBA(c->r, (Sint16)t->x[0], (Sint16)t->y[0], (Sint16)t->x[1], (Sint16)t->y[1],
                         (Sint16)t->x[2], (Sint16)t->y[2], RGB(t->c[0]), 255);
    }
    SDL_RenderFlush(c->r);
}

const struct peer peer_sdlgfx = {
    .name = "sdlgfx",
    .fmt_mask = 3,
    .open = sdl_open,
    .close = sdl_close,
    .fn =
        {
            [W1_CLEAR] = gfx_w1,
            [W2_RECTS] = gfx_w2,
            [W3_LINES] = gfx_w3,
            [W4_AALINES] = gfx_w4,
            [W5_CIRCLES] = gfx_w5,
            [W6_DISCS] = gfx_w6,
            [W7_POLYS] = gfx_w7,
            [W8_TRIS] = gfx_w8,
        },
};

#endif /* BENCH_PEERS */
