/* SPDX-License-Identifier: MIT */
/* fixel — the demo's ray-tracing page (issue #22): the course's CSG
 * objects (lens L = S1 n S2, bowl B = (S1 - S2) - C, rocket
 * R = C1 u C2 u C3 u C4) behind a glass and a mirror sphere on a marble
 * floor, traced by the fixed-point ray tracer on every core. On a display
 * the picture builds up a few bands a frame, so it appears row by row;
 * headless it is traced whole, on st->threads (fixel-demo -j, fixel-bench
 * --frames) or every core: the same pixels (every pixel depends on its own
 * rays only). */
#include <string.h>

#include "demo.h"
#include "fixel/rt_mt.h"

#define IW DEMO_RT_W
#define IH DEMO_RT_H
#define FX(v) ((fx16)((v) * 65536.0 + ((v) < 0 ? -0.5 : 0.5)))

static fx_rt_object objs[24];
static fx_rt_scene scene;
static int built;
static uint32_t img[IW * IH];
static int32_t rows_done; /* interactive: rows traced so far */

static fx_rt_material mat(fx_color amb, fx_color diff, fx_color spec, int shine, double kr, double kt, double ior)
{
    return fx_rt_material_make(amb, diff, spec, shine, FX(kr), FX(kt), FX(ior));
}

/* T(at) Rx(rx) Ry(ry) T(off) S(scale): an object placed in its group,
 * the group turned and set down at `at` */
static fx_mat4 place(const double at[3], double rx, double ry, double ox, double oy, double oz, double sx, double sy,
                     double sz)
{
    fx_mat4 m, t;
    fx_mat4_translate(&m, FX(at[0]), FX(at[1]), FX(at[2]));
    fx_mat4_rotate_x(&t, fx_angle_from_deg((int)rx));
    fx_mat4_mul(&m, &m, &t);
    fx_mat4_rotate_y(&t, fx_angle_from_deg((int)ry));
    fx_mat4_mul(&m, &m, &t);
    fx_mat4_translate(&t, FX(ox), FX(oy), FX(oz));
    fx_mat4_mul(&m, &m, &t);
    fx_mat4_scale(&t, FX(sx), FX(sy), FX(sz));
    fx_mat4_mul(&m, &m, &t);
    return m;
}

/* an upright cylinder-family shape: object z turned to world +y */
static fx_mat4 upright(const double at[3], double y0, double r, double h)
{
    fx_mat4 m = place(at, 0, 0, 0, y0, 0, 1, 1, 1), t;
    fx_mat4_rotate_x(&t, fx_angle_from_deg(-90));
    fx_mat4_mul(&m, &m, &t);
    fx_mat4_scale(&t, FX(r), FX(r), FX(h));
    fx_mat4_mul(&m, &m, &t);
    return m;
}

static int add(fx_rt_kind k, double taper, fx_mat4 m, const fx_rt_material *mt)
{
    return fx_rt_add_shape(&scene, k, FX(taper), &m, mt);
}

static int build(void)
{
    fx_rt_scene *s = &scene;
    fx_rt_scene_init(s, objs, (int)(sizeof objs / sizeof objs[0]));
    int e = fx_rt_set_camera(s, fx_vec3_make(0, FX(1.9), FX(7.2)), fx_vec3_make(0, FX(-0.15), 0),
                             fx_vec3_make(0, FX16_ONE, 0), FX(40));
    /* a warm key light high on the left, a cool fill on the right, an
     * evening sky */
    s->ambient = fx3d_rgb_from_color(0x282830);
    s->background = fx3d_rgb_from_color(0x28385A);
    s->max_depth = 5;
    s->cutoff = FX(1.0 / 256);
    fx_rt_add_light(s, fx_vec3_make(FX(-5), FX(7), FX(5)), fx3d_rgb_from_color(0xF0E8D8), FX(0.004));
    fx_rt_add_light(s, fx_vec3_make(FX(6), FX(3), FX(4)), fx3d_rgb_from_color(0x404860), 0);
    /* the marble floor y = -1: cream with brown veins */
    fx_rt_material marble = mat(0x383430, 0xE8E4DC, 0x303030, 12, 0.12, 0, 1);
    marble.texture = FX_RT_TEX_MARBLE;
    marble.tex_color = fx3d_rgb_from_color(0x5A4030);
    marble.tex_scale = FX(1.1);
    const double floor_at[3] = {0, -1, 0};
    e |= add(FX_RT_PLANE, 0, place(floor_at, -90, 0, 0, 0, 0, 1, 1, 1), &marble);
    /* glass and mirror spheres in front */
    fx_rt_material glass = mat(0, 0x101010, 0xFFFFFF, 120, 0.1, 0.85, 1.5);
    fx_rt_material mirror = mat(0x101010, 0x202020, 0xFFFFFF, 100, 0.85, 0, 1);
    const double g_at[3] = {-1.3, -0.25, 1.4}, m_at[3] = {1.3, -0.25, 1.4};
    e |= add(FX_RT_SPHERE, 0, place(g_at, 0, 0, 0, 0, 0, 0.75, 0.75, 0.75), &glass);
    e |= add(FX_RT_SPHERE, 0, place(m_at, 0, 0, 0, 0, 0, 0.75, 0.75, 0.75), &mirror);
    /* the lens: two unit spheres 1.2 apart, intersected, turned toward us */
    fx_rt_material red = mat(0x401010, 0xE03020, 0xFFFFFF, 60, 0.1, 0, 1);
    const double l_at[3] = {-3.2, -0.2, -1.0};
    int a = add(FX_RT_SPHERE, 0, place(l_at, 0, 20, -0.54, 0, 0, 0.9, 0.9, 0.9), &red);
    int b = add(FX_RT_SPHERE, 0, place(l_at, 0, 20, 0.54, 0, 0, 0.9, 0.9, 0.9), &red);
    e |= fx_rt_add_csg(s, FX_RT_INTERSECTION, a, b);
    /* the bowl: a sphere less a smaller one, less a box over the rim,
     * tipped toward us to show the inside */
    fx_rt_material blue = mat(0x102040, 0x3070D0, 0xFFFFFF, 40, 0.05, 0, 1);
    const double b_at[3] = {0, -0.15, -1.4};
    a = add(FX_RT_SPHERE, 0, place(b_at, 30, 0, 0, 0, 0, 0.85, 0.85, 0.85), &blue);
    b = add(FX_RT_SPHERE, 0, place(b_at, 30, 0, 0, 0, 0, 0.77, 0.77, 0.77), &blue);
    int bowl = fx_rt_add_csg(s, FX_RT_DIFFERENCE, a, b);
    int cut = add(FX_RT_CUBE, 0, place(b_at, 30, 0, 0, 1.1, 0, 1.1, 1, 1.1), &blue);
    e |= bowl | fx_rt_add_csg(s, FX_RT_DIFFERENCE, bowl, cut);
    /* the rocket: body, nose cone, tapered nozzle and a fin plate, united */
    fx_rt_material white = mat(0x303030, 0xD8D8D8, 0xFFFFFF, 50, 0.1, 0, 1);
    fx_rt_material dark = mat(0x101010, 0x404040, 0x808080, 20, 0, 0, 1);
    const double r_at[3] = {3.0, 0, -1.2};
    fx_mat4 body = upright(r_at, -0.75, 0.32, 1.35), nose = upright(r_at, 0.6, 0.32, 0.6),
            nozzle = upright(r_at, -1.0, 0.26, 0.25);
    int c1 = fx_rt_add_shape(s, FX_RT_CYLINDER, FX16_ONE, &body, &white);
    int c2 = fx_rt_add_shape(s, FX_RT_CYLINDER, 0, &nose, &red);
    int u = fx_rt_add_csg(s, FX_RT_UNION, c1, c2);
    int c3 = fx_rt_add_shape(s, FX_RT_CYLINDER, FX(0.65), &nozzle, &dark);
    u = fx_rt_add_csg(s, FX_RT_UNION, u, c3);
    int c4 = add(FX_RT_CUBE, 0, place(r_at, 0, 25, 0, -0.6, 0, 0.65, 0.3, 0.07), &red);
    e |= fx_rt_add_csg(s, FX_RT_UNION, u, c4);
    return e < 0 ? -1 : 0;
}

int demo_rt_busy(const demo_state *st) { return st->interactive && rows_done < IH; }

int demo_rt_key(demo_state *st, int key)
{
    (void)st;
    if (key != 'g')
        return 0;
    rows_done = 0; /* trace it again, row by row, from a blank picture */
    memset(img, 0, sizeof img);
    return 1;
}

void demo_rt_page(fx_ctx *c, demo_state *st, int32_t top)
{
    fx_surface im;
    fx_surface_init(&im, img, IW, IH, IW * 4, FX_FMT_XRGB8888);
    if (!built) {
        if (build() < 0) {
            demo_text(c, 16, top + 8, 0xFFFF6060u, "ray tracer: the scene could not be built");
            return;
        }
        built = 1;
        rows_done = 0;
    }
    int cpus = st->threads > 0 ? st->threads : fx_rt_cpu_count();
    if (!st->interactive) {
        fx_rt_render_mt(&scene, &im, cpus, 8, NULL, NULL);
        rows_done = IH;
    } else if (rows_done < IH) {
        /* a few bands a frame on every core: the picture builds up */
        int32_t n = 6 * cpus;
        fx_rt_render_rect_mt(&scene, &im, 0, rows_done, IW, n, cpus, 2, NULL, NULL);
        rows_done = rows_done + n < IH ? rows_done + n : IH;
    }
    fx_surface done = im;
    done.h = rows_done;
    fx_ctx_set_color(c, 0xFF000000u);
    fx_fill_rect(c, DEMO_RT_X, top, IW, IH);
    fx_blit(&c->surf, DEMO_RT_X, top, &done);
    demo_text(c, 16, top + IH + 6, 0xFFE8E8E8u,
              "Fixed-point ray tracing: lens L = S1 n S2, bowl B = (S1 - S2) - C, rocket R = C1 u C2 u C3 u C4,");
    demo_text(c, 16, top + IH + 20, 0xFFE8E8E8u,
              "glass (n = 1.5) and mirror spheres, marble floor.  %s  g: trace again",
              rows_done < IH ? "tracing..." : "done.");
    if (st->interactive)
        demo_text(c, 560, top + IH + 20, 0xFF7A8AA0u, "%d/%d rows, %d thread%s", rows_done, IH, cpus,
                  cpus == 1 ? "" : "s");
}
