/* SPDX-License-Identifier: MIT */
/* Seed fills against a breadth-first reference flood written here, with tiny
 * stacks (overflow rescans), clipping, same-colour fills, and a 4096x4096
 * perfect maze (one long winding region). */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/fill.h"
#include "fx_test.h"

/* 1 for every pixel of the region the reference reaches. */
static void ref_region(const uint8_t *img, int w, int h, fx_rect clip, int sx, int sy, int boundary, uint8_t key,
                       int conn, uint8_t *out)
{
    memset(out, 0, (size_t)w * h);
    int *q = malloc(sizeof(int) * (size_t)w * h);
    int qh = 0, qt = 0;
#define IN(x, y)                                                                                          \
    ((x) >= clip.x0 && (x) < clip.x1 && (y) >= clip.y0 && (y) < clip.y1 && !out[(y) * w + (x)] &&         \
     (boundary ? img[(y) * w + (x)] != key : img[(y) * w + (x)] == key))
    if (IN(sx, sy)) {
        out[sy * w + sx] = 1;
        q[qt++] = sy * w + sx;
    }
    while (qh < qt) {
        int p = q[qh++], x = p % w, y = p / w;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                if ((dx == 0 && dy == 0) || (conn == 4 && dx != 0 && dy != 0))
                    continue;
                int nx = x + dx, ny = y + dy;
                if (IN(nx, ny)) {
                    out[ny * w + nx] = 1;
                    q[qt++] = ny * w + nx;
                }
            }
    }
#undef IN
    free(q);
}

FX_TEST(seedfill_random_images_match_bfs_reference)
{
    enum { W = 53, H = 41 };
    static uint8_t img[W * H], orig[W * H], reg[W * H];
    static uint64_t work[1 << 15];
    uint32_t seed = 2024;
    for (int iter = 0; iter < 400; iter++) {
        /* blobs of 3 grey levels: random seeds smoothed by a majority pass */
        for (int i = 0; i < W * H; i++)
            orig[i] = (uint8_t)(fx_test_rand(&seed) % 3 * 100);
        for (int k = 0; k < 2; k++)
            for (int i = W; i < W * H - W; i++)
                if (orig[i - 1] == orig[i + 1] || orig[i - W] == orig[i + 1])
                    orig[i] = orig[i + 1];
        memcpy(img, orig, sizeof img);
        fx_surface s;
        fx_surface_init(&s, img, W, H, W, FX_FMT_GRAY8);
        fx_ctx c;
        fx_ctx_init(&c, &s);
        fx_rect clip = {0, 0, W, H};
        if (iter % 3 == 1) {
            clip = (fx_rect){5, 3, 47, 37};
            fx_ctx_set_clip(&c, clip);
        }
        fx_ctx_set_color(&c, iter % 4 == 0 ? 0xFF000000u : 0xFFFFFFFFu); /* sometimes the seed's own colour */
        int conn = iter % 2 ? 8 : 4, boundary = (iter >> 1) % 2;
        int sx = 5 + (int)(fx_test_rand(&seed) % (W - 10)), sy = 3 + (int)(fx_test_rand(&seed) % (H - 6));
        uint8_t key = boundary ? 200 : orig[sy * W + sx];
        /* small stacks force overflow rescans on some iterations */
        size_t size = iter % 5 == 0 ? fx_seed_work_size(&c) - (FX_SEED_STACK_DEFAULT - FX_SEED_STACK_MIN) * 12
                                    : fx_seed_work_size(&c);
        FX_CHECK(size <= sizeof work);
        int r = boundary ? fx_boundary_fill(&c, sx, sy, 0xFFC8C8C8u, conn, work, size)
                         : fx_flood_fill(&c, sx, sy, conn, work, size);
        FX_CHECK_EQ(r, 0);
        ref_region(orig, W, H, clip, sx, sy, boundary, key, conn, reg);
        uint8_t fillv = (uint8_t)fx_pack(FX_FMT_GRAY8, c.color);
        int bad = 0;
        for (int i = 0; i < W * H; i++)
            bad += img[i] != (reg[i] ? fillv : orig[i]);
        FX_CHECK_MSG(bad == 0, "iter %d (conn %d, boundary %d): %d pixels differ", iter, conn, boundary, bad);
        if (bad)
            return;
    }
}

FX_TEST(seedfill_rejects_bad_arguments_and_small_work)
{
    uint32_t px[16 * 16] = {0};
    fx_surface s;
    fx_surface_init(&s, px, 16, 16, 64, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    uint8_t work[512];
    FX_CHECK_EQ(fx_flood_fill(&c, 1, 1, 6, work, sizeof work), -FX_EINVAL);
    FX_CHECK_EQ(fx_flood_fill(&c, 1, 1, 4, work, 16), -FX_ENOSPC);
    FX_CHECK_EQ(fx_flood_fill(&c, 1, 1, 4, NULL, 0), -FX_ENOSPC);
    FX_CHECK_EQ(fx_flood_fill(&c, -1, 1, 4, work, sizeof work), 0); /* seed outside: nothing */
    FX_CHECK_EQ(px[0], 0);
    /* the X byte does not split a region */
    px[5] = 0xFF000000u;
    FX_CHECK_EQ(fx_flood_fill(&c, 0, 0, 4, work, sizeof work), 0);
    FX_CHECK_EQ(px[5], 0xFFFFFF);
    FX_CHECK_EQ(px[255], 0xFFFFFF);
}

/* A perfect maze on odd cells of a size x size GRAY8 image: 255 passages,
 * 0 walls; every passage pixel is reachable from (1, 1). */
static uint8_t *make_maze(int size, uint32_t seed, long *passages)
{
    uint8_t *img = calloc((size_t)size * size, 1);
    int cells = (size - 1) / 2;
    int *stack = malloc(sizeof(int) * (size_t)cells * cells);
    int top = 0;
    long n = 1;
    img[1 * size + 1] = 255;
    stack[top++] = 0;
    while (top > 0) {
        int cur = stack[top - 1], cx = cur % cells, cy = cur / cells;
        int dirs[4], nd = 0;
        static const int ddx[4] = {1, -1, 0, 0}, ddy[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; d++) {
            int nx = cx + ddx[d], ny = cy + ddy[d];
            if (nx >= 0 && ny >= 0 && nx < cells && ny < cells && !img[(2 * ny + 1) * size + 2 * nx + 1])
                dirs[nd++] = d;
        }
        if (!nd) {
            top--;
            continue;
        }
        int d = dirs[fx_test_rand(&seed) % (uint32_t)nd];
        int nx = cx + ddx[d], ny = cy + ddy[d];
        img[(2 * cy + 1 + ddy[d]) * size + 2 * cx + 1 + ddx[d]] = 255;
        img[(2 * ny + 1) * size + 2 * nx + 1] = 255;
        n += 2;
        stack[top++] = ny * cells + nx;
    }
    free(stack);
    *passages = n;
    return img;
}

FX_TEST(seedfill_big_maze_fills_without_recursion)
{
    enum { S = 4096 };
    long passages;
    uint8_t *img = make_maze(S, 77, &passages);
    fx_surface s;
    fx_surface_init(&s, img, S, S, S, FX_FMT_GRAY8);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    fx_ctx_set_color(&c, 0xFF808080u);
    size_t size = fx_seed_work_size(&c);
    void *work = malloc(size);
    FX_CHECK_EQ(fx_flood_fill(&c, 1, 1, 4, work, size), 0);
    long filled = 0, other = 0;
    uint8_t g = (uint8_t)fx_pack(FX_FMT_GRAY8, 0xFF808080u);
    for (long i = 0; i < (long)S * S; i++) {
        filled += img[i] == g;
        other += img[i] == 255;
    }
    FX_CHECK_EQ(filled, passages);
    FX_CHECK_EQ(other, 0);
    /* boundary fill, 8-connected, back to white: walls stop it (diagonal
     * gaps do not exist in a maze of 2-pixel cells) */
    fx_ctx_set_color(&c, 0xFFFFFFFFu);
    FX_CHECK_EQ(fx_boundary_fill(&c, 1, 1, 0xFF000000u, 8, work, size), 0);
    other = 0;
    for (long i = 0; i < (long)S * S; i++)
        other += img[i] == 255;
    FX_CHECK_EQ(other, passages);
    free(work);
    free(img);
}

FX_TEST(seedfill_with_pattern_terminates_and_stays_inside)
{
    enum { W = 40, H = 30 };
    static uint8_t img[W * H];
    memset(img, 0, sizeof img);
    for (int x = 0; x < W; x++)
        img[15 * W + x] = 255; /* a wall splitting the image */
    fx_surface s;
    fx_surface_init(&s, img, W, H, W, FX_FMT_GRAY8);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    static const uint8_t bits[1] = {0xAA};
    fx_fill_style st = {.kind = FX_FILL_PATTERN, .bits = bits, .w = 8, .h = 1, .stride = 1, .bg = 0xFF000000u};
    c.fill_style = &st; /* half the painted pixels keep the seed colour */
    static uint64_t work[1024];
    FX_CHECK_EQ(fx_flood_fill(&c, 3, 3, 8, work, sizeof work), 0);
    int lit_top = 0, lit_bottom = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (y < 15)
                lit_top += img[y * W + x] == 255;
            else if (y > 15)
                lit_bottom += img[y * W + x] != 0;
    FX_CHECK_EQ(lit_top, W * 15 / 2);
    FX_CHECK_EQ(lit_bottom, 0);
}
