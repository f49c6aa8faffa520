/* SPDX-License-Identifier: MIT */
/* The documented aliases (fx_fill_circle, fx_fill_polygon, fx_fill_triangle,
 * fx_put_pixel) light exactly the pixels of the functions they stand for,
 * and something at all (so an alias that forgot its call fails). */
#include <stdlib.h>
#include <string.h>

#include "fixel/fixel.h"
#include "fx_test.h"

#define W 64
#define H 48

typedef struct {
    uint8_t a[W * H], b[W * H];
    fx_surface sa, sb;
    fx_ctx ca, cb;
} pair;

static void pair_init(pair *p)
{
    memset(p->a, 0, sizeof p->a);
    memset(p->b, 0, sizeof p->b);
    fx_surface_init(&p->sa, p->a, W, H, W, FX_FMT_GRAY8);
    fx_surface_init(&p->sb, p->b, W, H, W, FX_FMT_GRAY8);
    fx_ctx_init(&p->ca, &p->sa);
    fx_ctx_init(&p->cb, &p->sb);
}

static int lit_count(const uint8_t *m)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += m[i] != 0;
    return n;
}

FX_TEST(alias_fill_circle_is_disc)
{
    pair p;
    pair_init(&p);
    fx_fill_circle(&p.ca, 30, 20, 13);
    fx_disc(&p.cb, 30, 20, 13);
    FX_CHECK(lit_count(p.a) > 400);
    FX_CHECK(memcmp(p.a, p.b, sizeof p.a) == 0);
}

FX_TEST(alias_fill_polygon_and_triangle)
{
    static const int32_t xy[] = {3, 4, 60, 10, 40, 44, 8, 30};
    pair p;
    pair_init(&p);
    FX_CHECK_EQ(fx_fill_polygon(&p.ca, xy, 4, FX_FILL_EVENODD), 0);
    FX_CHECK_EQ(fx_fill_poly(&p.cb, xy, 4, FX_FILL_EVENODD), 0);
    FX_CHECK(lit_count(p.a) > 500);
    FX_CHECK(memcmp(p.a, p.b, sizeof p.a) == 0);
    FX_CHECK_EQ(fx_fill_polygon(&p.ca, NULL, 3, FX_FILL_EVENODD), -FX_EINVAL);

    pair_init(&p);
    fx_fill_triangle(&p.ca, 2, 3, 61, 20, 15, 46);
    fx_fill_tri(&p.cb, 2, 3, 61, 20, 15, 46);
    FX_CHECK(lit_count(p.a) > 500);
    FX_CHECK(memcmp(p.a, p.b, sizeof p.a) == 0);
}

FX_TEST(alias_put_pixel_is_plot)
{
    pair p;
    pair_init(&p);
    fx_put_pixel(&p.ca, 5, 7);
    fx_put_pixel(&p.ca, -1, 7); /* clipped, as fx_plot */
    fx_plot(&p.cb, 5, 7);
    FX_CHECK_EQ(lit_count(p.a), 1);
    FX_CHECK_EQ(p.a[7 * W + 5], 0xFF);
    FX_CHECK(memcmp(p.a, p.b, sizeof p.a) == 0);
}
