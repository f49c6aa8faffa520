/* SPDX-License-Identifier: MIT */
/* Transparency in the 3D pipeline (fx3d_alpha, fx3d_set_translucent):
 * translucent triangles blended after the opaque ones, farthest first,
 * depth-tested against the opaque surfaces without writing depth. The
 * order test is one that submission order gets wrong. */
#include <stdlib.h>
#include <string.h>
#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define W 80
#define H 60

typedef struct arig {
    uint32_t px[W * H];
    uint32_t z[W * H];
    fx_surface s;
    fx3d r;
    fx_mat4 ms[2], ps[2];
    unsigned char tbuf[64 * 1024];
} arig;

static arig *arig_new(int sorted)
{
    arig *g = calloc(1, sizeof *g);
    FX_CHECK(g != NULL);
    fx_surface_init(&g->s, g->px, W, H, W * 4, FX_FMT_XRGB8888);
    for (int i = 0; i < W * H; i++)
        g->px[i] = 0xFF102030u;
    FX_CHECK_EQ(fx3d_init(&g->r, &g->s, g->ms, 2, g->ps, 2), 0);
    FX_CHECK_EQ(fx3d_perspective(&g->r, fx_angle_from_deg(60), fx16_from_ratio(W, H), ONE / 2, 50 * ONE), 0);
    FX_CHECK(fx3d_depth_bytes(&g->s, 32) <= sizeof g->z);
    FX_CHECK_EQ(fx3d_set_depth(&g->r, g->z, 32), 0);
    if (sorted)
        FX_CHECK_EQ(fx3d_set_translucent(&g->r, g->tbuf, sizeof g->tbuf), 0);
    g->r.shading = FX3D_FLAT;
    return g;
}

/* A square facing the camera at depth z, half-width h, in colour c
 * (emission only, so the colour is c exactly). */
static void square(fx3d *r, fx16 x0, fx16 x1, fx16 z, fx_color c)
{
    fx_vec3 pos[4] = {fx_vec3_make(x0, -ONE, z), fx_vec3_make(x1, -ONE, z), fx_vec3_make(x1, ONE, z),
                      fx_vec3_make(x0, ONE, z)};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, NULL, NULL};
    memset(&r->mat, 0, sizeof r->mat);
    r->ambient = fx3d_rgb_from_color(0);
    r->mat.emission = fx3d_rgb_from_color(c);
    FX_CHECK_EQ(fx3d_draw(r, &m), 0);
}

#define RED 0xFF2010u
#define BLUE 0x1030F0u
#define GREY 0x808080u

/* Blue near (z = -3) submitted first, red far (z = -5) second, both at
 * alpha 128, overlapping in the middle column. */
static void two_translucent(arig *g)
{
    fx3d_alpha(&g->r, 128);
    square(&g->r, -2 * ONE, ONE / 2, -3 * ONE, BLUE);
    square(&g->r, -ONE / 2, 4 * ONE, -5 * ONE, RED);
    fx3d_flush(&g->r);
    fx3d_alpha(&g->r, 255);
}

FX_TEST(alpha3d_translucent_triangles_blend_back_to_front)
{
    arig *a = arig_new(1), *u = arig_new(0);
    two_translucent(a);
    two_translucent(u);
    uint32_t bg = 0xFF102030u;
    uint32_t right = fx_blend_over(FX_FMT_XRGB8888, fx_blend_over(FX_FMT_XRGB8888, bg, RED | 128u << 24),
                                   BLUE | 128u << 24);
    uint32_t wrong = fx_blend_over(FX_FMT_XRGB8888, fx_blend_over(FX_FMT_XRGB8888, bg, BLUE | 128u << 24),
                                   RED | 128u << 24);
    FX_CHECK(right != wrong); /* the picture is one where the order shows */
    int cx = W / 2, cy = H / 2;
    FX_CHECK_EQ_HEX(a->px[cy * W + cx] & 0xFFFFFFu, right & 0xFFFFFFu);
    /* unsorted (no translucent buffer: drawn as submitted) gets it wrong */
    FX_CHECK_EQ_HEX(u->px[cy * W + cx] & 0xFFFFFFu, wrong & 0xFFFFFFu);
    /* a single layer (blue alone, x = 10) is one blend over the background */
    FX_CHECK_EQ_HEX(a->px[cy * W + 10] & 0xFFFFFFu,
                    fx_blend_over(FX_FMT_XRGB8888, bg, BLUE | 128u << 24) & 0xFFFFFFu);
    /* translucent surfaces never write depth */
    for (int i = 0; i < W * H; i++)
        if (a->z[i] != a->z[0]) {
            FX_CHECK_MSG(0, "depth written at (%d, %d)", i % W, i / W);
            break;
        }
    free(a), free(u);
}

FX_TEST(alpha3d_opaque_surfaces_hide_translucent_ones_behind_them)
{
    arig *g = arig_new(1);
    /* translucent red far, submitted before the opaque grey that covers the
     * right half in front of it: depth-tested at flush, it stays hidden there */
    fx3d_alpha(&g->r, 128);
    square(&g->r, -4 * ONE, 4 * ONE, -5 * ONE, RED);
    fx3d_alpha(&g->r, 255);
    square(&g->r, 0, 4 * ONE, -4 * ONE, GREY);
    FX_CHECK_EQ(g->r.tcount, 2);
    fx3d_flush(&g->r);
    FX_CHECK_EQ(g->r.tcount, 0);
    FX_CHECK_EQ(g->r.tdropped, 0);
    uint32_t bg = 0xFF102030u;
    FX_CHECK_EQ_HEX(g->px[(H / 2) * W + W - 3] & 0xFFFFFFu, GREY);
    FX_CHECK_EQ_HEX(g->px[(H / 2) * W + 2] & 0xFFFFFFu,
                    fx_blend_over(FX_FMT_XRGB8888, bg, RED | 128u << 24) & 0xFFFFFFu);
    free(g);
}

FX_TEST(alpha3d_buffer_overflow_is_counted)
{
    arig *g = arig_new(0);
    FX_CHECK_EQ(fx3d_set_translucent(&g->r, g->tbuf, 1), -FX_EINVAL);
    FX_CHECK_EQ(fx3d_set_translucent(&g->r, g->tbuf, fx3d_painter_bytes(1)), 0);
    fx3d_alpha(&g->r, 100);
    square(&g->r, -ONE, ONE, -3 * ONE, RED);
    FX_CHECK_EQ(g->r.tcount, 1);
    FX_CHECK_EQ(g->r.tdropped, 1);
    fx3d_flush(&g->r);
    free(g);
}
