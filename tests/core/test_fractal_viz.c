/* SPDX-License-Identifier: MIT */
/* Visualisation: contour positions by exact interpolation, heatmap and
 * colour-bar colours from the maps, arrow directions, streamlines of a
 * vortex staying on their circle. */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/viz.h"
#include "fx_test.h"

typedef struct {
    uint32_t *px;
    fx_surface s;
    fx_ctx c;
} canvas;

static void canvas_new(canvas *k, int32_t w, int32_t h)
{
    k->px = calloc((size_t)w * h, 4);
    fx_surface_init(&k->s, k->px, w, h, w * 4, FX_FMT_XRGB8888);
    fx_ctx_init(&k->c, &k->s);
}

static uint32_t at(const canvas *k, int32_t x, int32_t y) { return k->px[y * k->s.w + x] & 0xFFFFFF; }

FX_TEST(contour_of_a_ramp_is_exact)
{
    /* v = 100 i on 11 x 5 nodes over 101 x 41 px: nodes every 10 px */
    int32_t g[5 * 11];
    for (int j = 0; j < 5; j++)
        for (int i = 0; i < 11; i++)
            g[j * 11 + i] = 100 * i;
    fx_grid grid = {g, 11, 5, 11};
    canvas k;
    canvas_new(&k, 120, 60);
    fx_rect d = {5, 7, 106, 48};
    /* level 250 crosses every row of cells at x = 5 + 25; 333 at 5 + 33.3 */
    FX_CHECK_EQ(fx_contour(&k.c, d, &grid, 250), 4);
    FX_CHECK_EQ(fx_contour(&k.c, d, &grid, 333), 4);
    for (int32_t y = 0; y < 60; y++)
        for (int32_t x = 0; x < 120; x++) {
            int want = (x == 30 || x == 38) && y >= 7 && y <= 47;
            FX_CHECK_MSG((at(&k, x, y) != 0) == want, "pixel %d,%d", x, y);
        }
    /* a level outside the range draws nothing; one on a node row is >= */
    FX_CHECK_EQ(fx_contour(&k.c, d, &grid, 5000), 0);
    FX_CHECK_EQ(fx_contour(&k.c, d, &grid, -1), 0);
    free(k.px);
}

FX_TEST(contour_of_a_bump_closes)
{
    /* a cone: v = 1000 - 100 * (|i - 8| + |j - 8|) on 17 x 17 nodes */
    int32_t g[17 * 17];
    for (int j = 0; j < 17; j++)
        for (int i = 0; i < 17; i++)
            g[j * 17 + i] = 1000 - 100 * (abs(i - 8) + abs(j - 8));
    fx_grid grid = {g, 17, 17, 17};
    canvas k;
    canvas_new(&k, 90, 90);
    fx_rect d = {5, 5, 86, 86}; /* 5 px per cell */
    int32_t segs = fx_contour(&k.c, d, &grid, 550);
    FX_CHECK(segs > 8);
    /* the diamond |x - 45| + |y - 45| = 22.5: every lit pixel is on it (+-1) */
    long n = 0;
    for (int32_t y = 0; y < 90; y++)
        for (int32_t x = 0; x < 90; x++)
            if (at(&k, x, y)) {
                int r = abs(x - 45) + abs(y - 45);
                FX_CHECK_MSG(r >= 21 && r <= 24, "pixel %d,%d off the diamond", x, y);
                n++;
            }
    FX_CHECK(n > 60);
    /* each of the four quadrants is crossed: the loop is closed all round */
    FX_CHECK(at(&k, 45, 45 - 22) || at(&k, 45, 45 - 23));
    FX_CHECK(at(&k, 45, 45 + 22) || at(&k, 45, 45 + 23));
    FX_CHECK(at(&k, 45 - 22, 45) || at(&k, 45 - 23, 45));
    FX_CHECK(at(&k, 45 + 22, 45) || at(&k, 45 + 23, 45));
    free(k.px);
}

FX_TEST(heatmap_and_colorbar_colours)
{
    int32_t g[2 * 3] = {0, 500, 1000, 0, 500, 1000};
    fx_grid grid = {g, 3, 2, 3};
    canvas k;
    canvas_new(&k, 64, 40);
    fx_rect d = {0, 0, 51, 20};
    FX_CHECK_EQ(fx_heatmap(&k.c, d, &grid, 0, 1000, FX_CMAP_HOT), 0);
    FX_CHECK_EQ_HEX(at(&k, 0, 5), fx_cmap_color(FX_CMAP_HOT, 0) & 0xFFFFFF);
    FX_CHECK_EQ_HEX(at(&k, 50, 5), fx_cmap_color(FX_CMAP_HOT, 65536) & 0xFFFFFF);
    /* 500 is step round(500 * 255 / 1000) = 128 of the 256 */
    fx_color tab[256];
    fx_cmap_table(FX_CMAP_HOT, tab, 256);
    FX_CHECK_EQ_HEX(at(&k, 25, 19), tab[128] & 0xFFFFFF);
    FX_CHECK_EQ(at(&k, 51, 5), 0); /* nothing outside dest */
    /* brightness never falls from left to right (hot is monotonic) */
    for (int32_t x = 1; x < 51; x++) {
        uint32_t a = at(&k, x - 1, 3), b = at(&k, x, 3);
        FX_CHECK((b >> 16) >= (a >> 16) && (b >> 8 & 255) >= (a >> 8 & 255));
    }
    /* clamping outside [lo, hi] */
    FX_CHECK_EQ(fx_heatmap(&k.c, d, &grid, 200, 300, FX_CMAP_GREY), 0);
    FX_CHECK_EQ_HEX(at(&k, 0, 0), 0x000000);
    FX_CHECK_EQ_HEX(at(&k, 50, 0), 0xFFFFFF);
    /* a vertical bar runs from the map's start at the bottom to its end on top */
    memset(k.px, 0, 64 * 40 * 4);
    fx_rect bar = {10, 5, 16, 35};
    fx_colorbar(&k.c, bar, FX_CMAP_VIRIDIS, 3);
    FX_CHECK_EQ_HEX(at(&k, 12, 34), 0x440154);
    FX_CHECK_EQ_HEX(at(&k, 12, 5), 0xFDE725);
    FX_CHECK_EQ_HEX(at(&k, 9, 20), 0xFFFFFF);  /* frame */
    FX_CHECK_EQ_HEX(at(&k, 18, 34), 0xFFFFFF); /* bottom tick */
    FX_CHECK_EQ_HEX(at(&k, 18, 19), 0xFFFFFF); /* middle tick: 34 - round(29 / 2) */
    FX_CHECK_EQ_HEX(at(&k, 18, 20), 0);
    free(k.px);
}

FX_TEST(quiver_arrows_point_along_the_field)
{
    int32_t u[3 * 3], v[3 * 3];
    for (int i = 0; i < 9; i++) {
        u[i] = 0;
        v[i] = 50; /* straight up */
    }
    u[4] = 30; /* centre: right and up, shorter... */
    v[4] = 40; /* ...|(30, 40)| = 50 */
    fx_vgrid g = {u, v, 3, 3, 3};
    canvas k;
    canvas_new(&k, 50, 50);
    fx_rect d = {0, 0, 41, 41}; /* nodes every 20 px */
    FX_CHECK_EQ(fx_quiver(&k.c, d, &g, 1), 9);
    /* up-arrows at (0, 40): shaft up 18 px (0.9 of the spacing), then a gap
     * before the next node's arrow */
    FX_CHECK(at(&k, 0, 40) && at(&k, 0, 30) && at(&k, 0, 22));
    FX_CHECK(!at(&k, 0, 21));
    /* the centre arrow ends at (20 + 10.8, 20 - 14.4) */
    FX_CHECK(at(&k, 31, 6) || at(&k, 31, 5) || at(&k, 30, 6));
    FX_CHECK(!at(&k, 27, 30)); /* nothing downward */
    free(k.px);
}

FX_TEST(streamlines_circle_a_vortex)
{
    enum { N = 21 };
    int32_t u[N * N], v[N * N];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int32_t x = i - 10, y = 10 - j; /* y up */
            u[j * N + i] = -y * 1000;
            v[j * N + i] = x * 1000;
        }
    fx_vgrid g = {u, v, N, N, N};
    canvas k;
    canvas_new(&k, 101, 101);
    fx_rect d = {0, 0, 101, 101}; /* 5 px per node, centre at (50, 50) */
    int32_t steps = fx_streamline(&k.c, d, &g, 80, 50, FX16_ONE, 400);
    FX_CHECK_EQ(steps, 800);
    long n = 0;
    for (int32_t y = 0; y < 101; y++)
        for (int32_t x = 0; x < 101; x++)
            if (at(&k, x, y)) {
                int64_t r2 = (int64_t)(x - 50) * (x - 50) + (int64_t)(y - 50) * (y - 50);
                FX_CHECK_MSG(r2 >= 28 * 28 && r2 <= 32 * 32, "pixel %d,%d strays", x, y);
                n++;
            }
    FX_CHECK(n > 150); /* 2 pi 30 = 188 pixels round */
    /* a stagnation point stops the line at once */
    FX_CHECK_EQ(fx_streamline(&k.c, d, &g, 50, 50, FX16_ONE, 400), 0);
    FX_CHECK_EQ(fx_streamline(&k.c, d, &g, 50, 50, 0, 400), -FX_EINVAL);
    free(k.px);
}

/* Geometry anywhere in int32 neither overflows (the sanitizer build runs
 * this) nor costs more than what is visible; what is off the surface lights
 * nothing. */
FX_TEST(viz_and_curves_extreme_arguments)
{
    canvas k;
    canvas_new(&k, 64, 64);
    int32_t gv[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8}, gu[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    fx_grid gr = {gv, 3, 3, 3};
    fx_vgrid vg = {gu, gv, 3, 3, 3};
    fx_rect all = {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
    FX_CHECK(fx_contour(&k.c, all, &gr, 4) >= 0);
    FX_CHECK_EQ(fx_quiver(&k.c, all, &vg, 1), 9);
    FX_CHECK(fx_streamline(&k.c, all, &vg, 10, 10, FX16_ONE, 100) > 0);
    fx_colorbar(&k.c, all, FX_CMAP_HSV, 3);
    FX_CHECK(fx_heatmap(&k.c, (fx_rect){-5, -5, INT32_MAX, 70}, &gr, 0, 8, FX_CMAP_HOT) == 0);
    memset(k.px, 0, 64 * 64 * 4);
    fx_rect far = {2000000000, 0, INT32_MAX, 2000};
    FX_CHECK(fx_contour(&k.c, far, &gr, 4) >= 0);
    FX_CHECK_EQ(fx_quiver(&k.c, far, &vg, 1), 9);
    FX_CHECK(fx_heatmap(&k.c, far, &gr, 0, 8, FX_CMAP_GREY) == 0);
    long n = 0;
    for (int i = 0; i < 64 * 64; i++)
        n += k.px[i] != 0;
    FX_CHECK_EQ(n, 0);
    free(k.px);
}
