/* SPDX-License-Identifier: MIT */
/* The ray tracer on several threads (boards/posix/rt_mt.c): the same
 * picture as one thread, every row reported finished exactly once. */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/rt_mt.h"
#include "fixel/surface.h"
#include "fx_test.h"

static void scene(fx_rt_scene *s, fx_rt_object *mem)
{
    fx_rt_scene_init(s, mem, 4);
    fx_rt_material m;
    memset(&m, 0, sizeof m);
    m.diffuse = fx3d_rgb_from_color(0xC08040);
    m.specular = fx3d_rgb_from_color(0xFFFFFF);
    m.shininess = 30;
    m.reflectivity = FX16_ONE / 4;
    fx_mat4 a, b;
    fx_mat4_translate(&a, -FX16_ONE / 2, 0, 0);
    fx_rt_add_shape(s, FX_RT_SPHERE, 0, &a, &m);
    fx_mat4_translate(&b, FX16_ONE / 2, 0, 0);
    fx_rt_add_shape(s, FX_RT_CUBE, 0, &b, &m);
    fx_rt_add_csg(s, FX_RT_DIFFERENCE, 0, 1);
    fx_rt_add_light(s, fx_vec3_make(3 * FX16_ONE, 4 * FX16_ONE, 5 * FX16_ONE), fx3d_rgb_from_color(0xFFFFFF), 0);
    s->ambient = fx3d_rgb_from_color(0x202020);
}

typedef struct rows {
    int count[61];
    int calls;
} rows;

static void on_rows(void *u, int32_t y0, int32_t y1)
{
    rows *r = u;
    r->calls++;
    for (int32_t y = y0; y < y1; y++)
        if (y >= 0 && y < 61)
            r->count[y]++;
}

enum { W = 50, H = 61 };

/* the scene, the one-thread picture a and the threaded one b */
typedef struct rig {
    fx_rt_object mem[4];
    fx_rt_scene s;
    uint32_t a[W * H], b[W * H];
    fx_surface sa, sb;
} rig;

static rig *rig_new(void)
{
    static rig g;
    memset(&g, 0, sizeof g);
    scene(&g.s, g.mem);
    fx_surface_init(&g.sa, g.a, W, H, W * 4, FX_FMT_XRGB8888);
    fx_surface_init(&g.sb, g.b, W, H, W * 4, FX_FMT_XRGB8888);
    return &g;
}

FX_TEST(rt_mt_threads_make_the_one_thread_picture)
{
    rig *g = rig_new();
    fx_rt_scene *s = &g->s;
    uint32_t *a = g->a, *b = g->b;
    const fx_surface *sa = &g->sa, *sb = &g->sb;
    fx_rt_render(s, sa, 0, 0, W, H);
    for (int n = 1; n <= 4; n++) {
        memset(b, 0, sizeof g->b);
        rows r;
        memset(&r, 0, sizeof r);
        FX_CHECK_EQ(fx_rt_render_mt(s, sb, n, 3, on_rows, &r), 0);
        FX_CHECK(memcmp(a, b, sizeof g->a) == 0);
        for (int y = 0; y < H; y++)
            FX_CHECK_EQ(r.count[y], 1);
        FX_CHECK_EQ(r.calls, (H + 2) / 3);
    }
    FX_CHECK_EQ(fx_rt_render_mt(s, sb, 0, 0, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_rt_render_mt(s, sb, 65, 0, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_rt_render_mt(s, sb, 2, H + 1, 0, 0), -FX_EINVAL);
    FX_CHECK(fx_rt_cpu_count() >= 1);
}

FX_TEST(rt_mt_rectangle_is_the_one_thread_tile)
{
    /* 'raytrace X Y W H' through the host's threads: the tile fx_rt_render
     * draws, nothing outside it, each of its rows reported once; a tile
     * hanging over the surface's edge is clipped */
    rig *g = rig_new();
    fx_rt_scene *s = &g->s;
    uint32_t *a = g->a, *b = g->b;
    const fx_surface *sa = &g->sa, *sb = &g->sb;
    const int32_t rect[2][4] = {{7, 5, 31, 40}, {-9, 30, 100, 100}};
    for (int k = 0; k < 2; k++) {
        const int32_t *q = rect[k];
        for (int i = 0; i < W * H; i++)
            a[i] = b[i] = 0xFF123456u;
        fx_rt_render(s, sa, q[0], q[1], q[2], q[3]);
        for (int n = 1; n <= 3; n++) {
            rows r;
            memset(&r, 0, sizeof r);
            FX_CHECK_EQ(fx_rt_render_rect_mt(s, sb, q[0], q[1], q[2], q[3], n, 4, on_rows, &r), 0);
            FX_CHECK(memcmp(a, b, sizeof g->a) == 0);
            int y1 = q[1] + q[3] < H ? q[1] + q[3] : H;
            for (int y = 0; y < H; y++)
                FX_CHECK_EQ(r.count[y], y >= q[1] && y < y1);
        }
    }
    /* the last tile (rows 30..) was drawn over the fill, the rows above not */
    FX_CHECK(a[45 * W + 20] != 0xFF123456u);
    FX_CHECK_EQ(a[0], 0xFF123456u);
    /* empty and off-surface rectangles draw nothing */
    rows r;
    memset(&r, 0, sizeof r);
    FX_CHECK_EQ(fx_rt_render_rect_mt(s, sb, 0, 0, 0, 10, 2, 0, on_rows, &r), 0);
    FX_CHECK_EQ(fx_rt_render_rect_mt(s, sb, W, 0, 10, 10, 2, 0, on_rows, &r), 0);
    FX_CHECK_EQ(r.calls, 0);
    FX_CHECK_EQ(fx_rt_render_rect_mt(s, sb, 0, 0, W, H, 0, 0, 0, 0), -FX_EINVAL);
}
