/* SPDX-License-Identifier: MIT */
/* Tests of the 3D pipeline: matrices (identities, round trips with stated
 * error), the camera, projections of known points, coverage, culling,
 * depth on interpenetrating shapes, near-plane clipping, painter's mode,
 * shadows and the benchmark frame. */
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fx_test.h"
#include "../../tools/fixel-bench/workloads.h"

#define ONE FX16_ONE

static int32_t iabs32(int32_t v) { return v < 0 ? -v : v; }

static int32_t mat_err_identity(const fx_mat4 *m)
{
    int32_t e = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            int32_t d = iabs32(m->m[i][j] - (i == j ? ONE : 0));
            if (d > e)
                e = d;
        }
    return e;
}

static int32_t vec_err(fx_vec4 v, fx16 x, fx16 y, fx16 z, fx16 w)
{
    int32_t e = iabs32(v.x - x);
    if (iabs32(v.y - y) > e)
        e = iabs32(v.y - y);
    if (iabs32(v.z - z) > e)
        e = iabs32(v.z - z);
    if (iabs32(v.w - w) > e)
        e = iabs32(v.w - w);
    return e;
}

FX_TEST(mat3d_builders_move_known_points)
{
    fx_mat4 m;
    fx_mat4_rotate_x(&m, FX_ANGLE_90);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(0, ONE, 0)), 0, 0, ONE, ONE), 0);
    fx_mat4_rotate_y(&m, FX_ANGLE_90);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(0, 0, ONE)), ONE, 0, 0, ONE), 0);
    fx_mat4_rotate_z(&m, FX_ANGLE_90);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(ONE, 0, 0)), 0, ONE, 0, ONE), 0);
    fx_mat4_translate(&m, ONE, -2 * ONE, 3 * ONE);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(ONE, ONE, ONE)), 2 * ONE, -ONE, 4 * ONE, ONE), 0);
    /* directions ignore translation */
    fx_vec3 d = fx_mat4_apply_dir(&m, fx_vec3_make(ONE, 0, 0));
    FX_CHECK(d.x == ONE && d.y == 0 && d.z == 0);
    fx_mat4_scale(&m, 2 * ONE, ONE / 2, -ONE);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(ONE, ONE, ONE)), 2 * ONE, ONE / 2, -ONE, ONE), 0);
    /* SHz: x' = x + a z, y' = y + b z */
    fx_mat4_shear_z(&m, ONE / 2, -ONE);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(ONE, 2 * ONE, 4 * ONE)), 3 * ONE, -2 * ONE, 4 * ONE, ONE), 0);
    /* reflection about y = 1 */
    FX_CHECK_EQ(fx_mat4_reflect(&m, fx_vec3_make(0, 5 * ONE, 0), ONE), 0);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&m, fx_vec3_make(2 * ONE, 3 * ONE, 4 * ONE)), 2 * ONE, -ONE, 4 * ONE, ONE), 0);
    FX_CHECK_EQ(fx_mat4_reflect(&m, fx_vec3_make(0, 0, 0), ONE), -FX_EDOM);
}

FX_TEST(mat3d_arbitrary_axis_rotation)
{
    fx_mat4 a, b;
    /* about z equals rotate_z to the rounding of the two formulas */
    for (uint32_t k = 0; k < 16; k++) {
        fx_angle t = k * 0x10000000u + 12345u;
        fx_mat4_rotate(&a, t, fx_vec3_make(0, 0, 3 * ONE));
        fx_mat4_rotate_z(&b, t);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                FX_CHECK_MSG(iabs32(a.m[i][j] - b.m[i][j]) <= 2, "k=%u [%d][%d] %d vs %d", k, i, j,
                             a.m[i][j], b.m[i][j]);
    }
    /* 120 degrees about (1,1,1) cycles the axes x -> y -> z */
    fx_mat4_rotate(&a, fx_angle_from_deg(120), fx_vec3_make(ONE, ONE, ONE));
    FX_CHECK_MSG(vec_err(fx_mat4_apply_point(&a, fx_vec3_make(ONE, 0, 0)), 0, ONE, 0, ONE) <= 4, "x->y");
    FX_CHECK_MSG(vec_err(fx_mat4_apply_point(&a, fx_vec3_make(0, ONE, 0)), 0, 0, ONE, ONE) <= 4, "y->z");
    FX_CHECK_EQ(fx_mat4_rotate(&a, FX_ANGLE_90, fx_vec3_make(0, 0, 0)), -FX_EDOM);
}

/* The stated error of fx_mat4_invert: M * inverse(M) = I within 2^-12 per
 * entry for rigid motions with scales in [1/16, 16]. Measured: see the
 * message on failure. */
FX_TEST(mat3d_inverse_round_trip_error)
{
    uint32_t seed = 0x3d3d3d3du;
    int32_t worst = 0, worst2 = 0;
    for (int it = 0; it < 500; it++) {
        fx_mat4 m, t, s;
        fx_mat4_rotate(&m, fx_test_rand(&seed),
                       fx_vec3_make((fx16)(fx_test_rand(&seed) % (2 * ONE)) - ONE,
                                    (fx16)(fx_test_rand(&seed) % (2 * ONE)) - ONE, ONE / 3));
        fx16 sc[3];
        for (int k = 0; k < 3; k++) /* 1/16 .. 16 */
            sc[k] = (fx16)(ONE / 16 + fx_test_rand(&seed) % (16 * ONE - ONE / 16));
        fx_mat4_scale(&s, sc[0], sc[1], sc[2]);
        fx_mat4_mul(&m, &m, &s);
        fx_mat4_translate(&t, (fx16)(fx_test_rand(&seed) % (16 * ONE)) - 8 * ONE,
                          (fx16)(fx_test_rand(&seed) % (16 * ONE)) - 8 * ONE, ONE * 7);
        fx_mat4_mul(&m, &t, &m);
        fx_mat4 inv, p, back;
        FX_CHECK_EQ(fx_mat4_invert(&inv, &m), 0);
        fx_mat4_mul(&p, &m, &inv);
        int32_t e = mat_err_identity(&p);
        if (e > worst)
            worst = e;
        /* inverse of the inverse returns M to within a few units */
        FX_CHECK_EQ(fx_mat4_invert(&back, &inv), 0);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                int32_t d = iabs32(back.m[i][j] - m.m[i][j]);
                if (d > worst2)
                    worst2 = d;
            }
    }
    FX_CHECK_MSG(worst <= 16, "M * inv(M) deviates from I by %d units (2^-16)", worst);
    FX_CHECK_MSG(worst2 <= 256, "inv(inv(M)) deviates from M by %d units", worst2);
    fx_mat4 z, r;
    fx_mat4_scale(&z, ONE, 0, ONE);
    FX_CHECK_EQ(fx_mat4_invert(&r, &z), -FX_EDOM);
}

FX_TEST(mat3d_compose_matches_sequential_application)
{
    fx_mat4 a, b, ab;
    fx_mat4_rotate_y(&a, fx_angle_from_deg(30));
    fx_mat4_translate(&b, ONE, 2 * ONE, 3 * ONE);
    fx_mat4_mul(&ab, &a, &b);
    fx_vec3 p = fx_vec3_make(ONE / 3, -ONE, 5 * ONE);
    fx_vec4 q = fx_mat4_apply_point(&b, p);
    fx_vec4 seq = fx_mat4_apply(&a, q);
    fx_vec4 one = fx_mat4_apply_point(&ab, p);
    FX_CHECK(vec_err(one, seq.x, seq.y, seq.z, seq.w) <= 2);
    /* the stack composes like glMultMatrix and restores on pop */
    fx_mat4 mem[3];
    fx_mat_stack st;
    FX_CHECK_EQ(fx_mat_stack_init(&st, mem, 3), 0);
    FX_CHECK_EQ(fx_mat_stack_pop(&st), -FX_ERANGE);
    fx_mat_stack_mult(&st, &a);
    FX_CHECK_EQ(fx_mat_stack_push(&st), 0);
    fx_mat_stack_mult(&st, &b);
    FX_CHECK(memcmp(fx_mat_stack_top(&st), &ab, sizeof ab) == 0);
    FX_CHECK_EQ(fx_mat_stack_push(&st), 0);
    FX_CHECK_EQ(fx_mat_stack_push(&st), -FX_ENOSPC);
    FX_CHECK_EQ(fx_mat_stack_pop(&st), 0);
    FX_CHECK_EQ(fx_mat_stack_pop(&st), 0);
    FX_CHECK(memcmp(fx_mat_stack_top(&st), &a, sizeof a) == 0);
}

FX_TEST(camera_look_at_slide_and_turns)
{
    fx_camera c;
    FX_CHECK_EQ(fx_camera_set(&c, fx_vec3_make(0, 0, 5 * ONE), fx_vec3_make(0, 0, 0), fx_vec3_make(0, ONE, 0)), 0);
    FX_CHECK(c.u.x == ONE && c.v.y == ONE && c.n.z == ONE);
    fx_mat4 v;
    fx_camera_view(&c, &v);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&v, fx_vec3_make(0, 0, 0)), 0, 0, -5 * ONE, ONE), 0);
    FX_CHECK_EQ(vec_err(fx_mat4_apply_point(&v, fx_vec3_make(0, 0, 5 * ONE)), 0, 0, 0, ONE), 0);
    /* an oblique look: the look point lands on the -z axis */
    FX_CHECK_EQ(fx_camera_set(&c, fx_vec3_make(3 * ONE, 4 * ONE, 5 * ONE), fx_vec3_make(ONE, 0, -ONE),
                              fx_vec3_make(0, ONE, 0)), 0);
    fx_camera_view(&c, &v);
    fx_vec4 q = fx_mat4_apply_point(&v, fx_vec3_make(ONE, 0, -ONE));
    FX_CHECK_MSG(iabs32(q.x) <= 8 && iabs32(q.y) <= 8 && iabs32(q.z + 490426) <= 8, "look at (%d %d %d)", q.x, q.y, q.z);
    /* slide along n moves the eye back */
    fx_camera_set(&c, fx_vec3_make(0, 0, 5 * ONE), fx_vec3_make(0, 0, 0), fx_vec3_make(0, ONE, 0));
    fx_camera_slide(&c, ONE, 0, ONE);
    FX_CHECK(c.eye.x == ONE && c.eye.y == 0 && c.eye.z == 6 * ONE);
    /* yaw left by 90: looking along -x; pitch up by 90: looking along +y */
    fx_camera y = c, p = c, r = c;
    fx_camera_yaw(&y, FX_ANGLE_90);
    FX_CHECK_MSG(iabs32(y.n.x - ONE) <= 2 && iabs32(y.n.z) <= 2, "yaw n = (%d %d %d)", y.n.x, y.n.y, y.n.z);
    fx_camera_pitch(&p, FX_ANGLE_90);
    FX_CHECK_MSG(iabs32(p.n.y + ONE) <= 2 && iabs32(p.v.z - ONE) <= 2, "pitch n = (%d %d %d)", p.n.x, p.n.y, p.n.z);
    fx_camera_roll(&r, FX_ANGLE_90);
    FX_CHECK_MSG(iabs32(r.u.y - ONE) <= 2 && iabs32(r.v.x + ONE) <= 2, "roll u = (%d %d %d)", r.u.x, r.u.y, r.u.z);
    /* many small turns keep the basis orthonormal */
    for (int i = 0; i < 1000; i++) {
        fx_camera_yaw(&c, fx_angle_from_deg(7));
        fx_camera_pitch(&c, fx_angle_from_deg(3));
        fx_camera_roll(&c, fx_angle_from_deg(11));
    }
    FX_CHECK(iabs32(fx_vec3_dot(c.u, c.v)) <= 8 && iabs32(fx_vec3_dot(c.v, c.n)) <= 8);
    FX_CHECK(iabs32(fx_vec3_dot(c.u, c.u) - ONE) <= 8);
    FX_CHECK_EQ(fx_camera_set(&c, fx_vec3_make(0, 0, 0), fx_vec3_make(0, 0, 0), fx_vec3_make(0, ONE, 0)), -FX_EDOM);
    FX_CHECK_EQ(fx_camera_set(&c, fx_vec3_make(0, 5 * ONE, 0), fx_vec3_make(0, 0, 0), fx_vec3_make(0, ONE, 0)), -FX_EDOM);
}

FX_TEST(projections_map_known_points)
{
    fx_mat4 p;
    FX_CHECK_EQ(fx_mat4_perspective(&p, FX_ANGLE_90, ONE, ONE, 10 * ONE), 0);
    /* near plane -> z/w = -1, far plane -> +1, the 45-degree corner -> (1, 1) */
    fx_vec4 a = fx_mat4_apply_point(&p, fx_vec3_make(0, 0, -ONE));
    FX_CHECK(a.w == ONE && iabs32(a.z + ONE) <= 1);
    fx_vec4 b = fx_mat4_apply_point(&p, fx_vec3_make(0, 0, -10 * ONE));
    FX_CHECK(b.w == 10 * ONE && iabs32(b.z - 10 * ONE) <= 8);
    fx_vec4 c = fx_mat4_apply_point(&p, fx_vec3_make(3 * ONE, 3 * ONE, -3 * ONE));
    FX_CHECK(iabs32(c.x - c.w) <= 2 && iabs32(c.y - c.w) <= 2);
    FX_CHECK_EQ(fx_mat4_perspective(&p, FX_ANGLE_90, ONE, 0, 10 * ONE), -FX_EINVAL);
    FX_CHECK_EQ(fx_mat4_ortho(&p, -2 * ONE, 2 * ONE, -ONE, ONE, ONE, 9 * ONE), 0);
    fx_vec4 o = fx_mat4_apply_point(&p, fx_vec3_make(2 * ONE, -ONE, -ONE));
    FX_CHECK_EQ(vec_err(o, ONE, -ONE, -ONE, ONE), 0);
    o = fx_mat4_apply_point(&p, fx_vec3_make(-ONE, ONE / 2, -9 * ONE));
    FX_CHECK_EQ(vec_err(o, -ONE / 2, ONE / 2, ONE, ONE), 0);
    /* cabinet at 45 degrees: a point 2 units behind the near plane moves by
     * (1/2 * 2 * cos 45, 1/2 * 2 * sin 45) in eye units before the ortho */
    FX_CHECK_EQ(fx_mat4_oblique(&p, -2 * ONE, 2 * ONE, -2 * ONE, 2 * ONE, ONE, 9 * ONE, FX_ANGLE_45, FX_OBLIQUE_CABINET, ONE), 0);
    o = fx_mat4_apply_point(&p, fx_vec3_make(0, 0, -3 * ONE));
    FX_CHECK_MSG(iabs32(o.x - 23170) <= 3 && iabs32(o.y - 23170) <= 3, "cabinet (%d %d)", o.x, o.y);
    o = fx_mat4_apply_point(&p, fx_vec3_make(ONE, 0, -ONE));
    FX_CHECK_EQ(vec_err(o, ONE / 2, 0, -ONE, ONE), 0);
}

/* ---- rendering helpers ---- */

typedef struct rig {
    uint32_t px[100 * 100];
    uint32_t z[100 * 100];
    fx_surface s;
    fx_mat4 ms[4], ps[2];
    fx3d r;
} rig;

static rig *rig_new(void)
{
    rig *g = calloc(1, sizeof *g);
    fx_surface_init(&g->s, g->px, 100, 100, 400, FX_FMT_XRGB8888);
    fx3d_init(&g->r, &g->s, g->ms, 4, g->ps, 2);
    fx3d_perspective(&g->r, FX_ANGLE_90, ONE, ONE / 4, 20 * ONE);
    /* unlit, emission only: each surface is exactly its colour */
    g->r.light[0].type = FX3D_LIGHT_OFF;
    g->r.ambient = fx3d_rgb_from_color(0);
    return g;
}

static void emissive(fx3d *r, fx_color c)
{
    r->mat.ambient = r->mat.diffuse = r->mat.specular = fx3d_rgb_from_color(0);
    r->mat.emission = fx3d_rgb_from_color(c);
}

/* A quad as two triangles, counter-clockwise as given. */
static void quad(fx3d *r, fx_vec3 a, fx_vec3 b, fx_vec3 c, fx_vec3 d)
{
    fx_vec3 pos[4] = {a, b, c, d};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, NULL, NULL};
    FX_CHECK_EQ(fx3d_draw(r, &m), 0);
}

static uint32_t px(const rig *g, int x, int y) { return g->px[y * 100 + x] & 0xFFFFFF; }

FX_TEST(render3d_projection_covers_the_exact_pixels)
{
    rig *g = rig_new();
    emissive(&g->r, 0xFFFFFF);
    /* a 2x2 square at z = -2 under a 90-degree view spans NDC [-1/2, 1/2]:
     * edges at pixel coordinates 24.5 and 74.5, so pixels 25..74 */
    quad(&g->r, fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE),
         fx_vec3_make(ONE, ONE, -2 * ONE), fx_vec3_make(-ONE, ONE, -2 * ONE));
    int lit = 0;
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 100; x++) {
            int in = x >= 25 && x <= 74 && y >= 25 && y <= 74;
            lit += px(g, x, y) != 0;
            if ((px(g, x, y) == 0xFFFFFF) != in) {
                FX_CHECK_MSG(0, "pixel (%d, %d) = %06x", x, y, px(g, x, y));
                x = y = 100;
            }
        }
    FX_CHECK_EQ(lit, 50 * 50);
    FX_CHECK_EQ(g->r.stat_drawn, 2);
    free(g);
}

FX_TEST(render3d_back_faces_are_culled)
{
    rig *g = rig_new();
    emissive(&g->r, 0xFF0000);
    /* clockwise seen from the camera: a back face */
    quad(&g->r, fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(-ONE, ONE, -2 * ONE),
         fx_vec3_make(ONE, ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE));
    FX_CHECK_EQ(g->r.stat_culled, 2);
    FX_CHECK_EQ(px(g, 50, 50), 0);
    g->r.cull = FX3D_CULL_FRONT;
    quad(&g->r, fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(-ONE, ONE, -2 * ONE),
         fx_vec3_make(ONE, ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE));
    FX_CHECK_EQ(px(g, 50, 50), 0xFF0000);
    /* a cube up and to the right: its front, left and bottom faces face the camera */
    g->r.cull = FX3D_CULL_BACK;
    fx_vec3 pos[24], nrm[24];
    uint32_t tri[36];
    fx_mesh m = {pos, nrm, tri, 0, 0, 24, 12, NULL, NULL};
    fx_mesh_params p = {FX_MESH_CUBE, ONE, 0, 0, 0, 0};
    FX_CHECK_EQ(fx_mesh_make(&m, &p), 0);
    fx_mat4 t;
    fx_mat4_translate(&t, 2 * ONE, 2 * ONE, -5 * ONE);
    fx_mat_stack_load(&g->r.model, &t);
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
    FX_CHECK_EQ(g->r.stat_drawn, 6);
    FX_CHECK_EQ(g->r.stat_culled, 6);
    free(g);
}

/* Two planes crossing along x = 0: A (red) is z = -3 + x/2, B (green) is
 * z = -3. Right of the crossing A is nearer, left of it B, whatever the
 * drawing order. */
FX_TEST(render3d_depth_resolves_interpenetrating_planes)
{
    for (int bits = 16; bits <= 32; bits += 16)
        for (int order = 0; order < 2; order++) {
            rig *g = rig_new();
            FX_CHECK_EQ(fx3d_set_depth(&g->r, g->z, bits), 0);
            for (int k = 0; k < 2; k++) {
                if ((k ^ order) == 0) {
                    emissive(&g->r, 0xFF0000);
                    quad(&g->r, fx_vec3_make(-2 * ONE, -2 * ONE, -4 * ONE), fx_vec3_make(2 * ONE, -2 * ONE, -2 * ONE),
                         fx_vec3_make(2 * ONE, 2 * ONE, -2 * ONE), fx_vec3_make(-2 * ONE, 2 * ONE, -4 * ONE));
                } else {
                    emissive(&g->r, 0x00FF00);
                    quad(&g->r, fx_vec3_make(-2 * ONE, -2 * ONE, -3 * ONE), fx_vec3_make(2 * ONE, -2 * ONE, -3 * ONE),
                         fx_vec3_make(2 * ONE, 2 * ONE, -3 * ONE), fx_vec3_make(-2 * ONE, 2 * ONE, -3 * ONE));
                }
            }
            int bad = 0;
            for (int y = 20; y < 80; y++)
                for (int x = 20; x < 80; x++) {
                    if (x >= 48 && x <= 51)
                        continue; /* the crossing itself */
                    uint32_t want = x < 50 ? 0x00FF00 : 0xFF0000;
                    if (px(g, x, y) != want)
                        bad++;
                }
            FX_CHECK_MSG(bad == 0, "bits %d order %d: %d wrong pixels", bits, order, bad);
            free(g);
        }
}

/* A floor from behind the camera to far in front of it: the part in front
 * must render (the near-plane clip), the part behind must not wrap around. */
FX_TEST(render3d_near_plane_clipping)
{
    rig *g = rig_new();
    emissive(&g->r, 0x0000FF);
    quad(&g->r, fx_vec3_make(-8 * ONE, -ONE, 8 * ONE), fx_vec3_make(8 * ONE, -ONE, 8 * ONE),
         fx_vec3_make(8 * ONE, -ONE, -15 * ONE), fx_vec3_make(-8 * ONE, -ONE, -15 * ONE));
    FX_CHECK(g->r.stat_clipped > 0);
    /* The floor y = -1 seen with a 90-degree view: row y is at slope
     * (y + 0.5 - 50) / 50 below the horizon; it reaches z = -15 at slope
     * 1/15, so rows from 54 down are floor, rows above 53 are empty. */
    for (int x = 0; x < 100; x += 9) {
        FX_CHECK_EQ(px(g, x, 99), 0x0000FF);
        FX_CHECK_EQ(px(g, x, 60), 0x0000FF);
        FX_CHECK_EQ(px(g, x, 50), 0);
        FX_CHECK_EQ(px(g, x, 0), 0);
    }
    free(g);
}

FX_TEST(render3d_painter_sorts_far_to_near)
{
    rig *g = rig_new();
    static uint8_t mem[64 * 1024];
    FX_CHECK_EQ(fx3d_set_painter(&g->r, mem, sizeof mem), 0);
    /* near quad first, far quad second: a plain renderer would paint the
     * far one over it */
    emissive(&g->r, 0xFF0000);
    quad(&g->r, fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE),
         fx_vec3_make(ONE, ONE, -2 * ONE), fx_vec3_make(-ONE, ONE, -2 * ONE));
    emissive(&g->r, 0x00FF00);
    quad(&g->r, fx_vec3_make(-4 * ONE, -4 * ONE, -5 * ONE), fx_vec3_make(4 * ONE, -4 * ONE, -5 * ONE),
         fx_vec3_make(4 * ONE, 4 * ONE, -5 * ONE), fx_vec3_make(-4 * ONE, 4 * ONE, -5 * ONE));
    FX_CHECK_EQ(px(g, 50, 50), 0); /* nothing before the flush */
    fx3d_flush(&g->r);
    FX_CHECK_EQ(px(g, 50, 50), 0xFF0000);
    FX_CHECK_EQ(px(g, 10, 50), 0x00FF00);
    FX_CHECK_EQ(g->r.pcount, 0);
    free(g);
}

FX_TEST(render3d_hidden_lines_hide_back_edges)
{
    rig *g = rig_new();
    fx_vec3 pos[24], nrm[24];
    uint32_t tri[36];
    fx_mesh m = {pos, nrm, tri, 0, 0, 24, 12, NULL, NULL};
    fx_mesh_params p = {FX_MESH_CUBE, 2 * ONE, 0, 0, 0, 0};
    FX_CHECK_EQ(fx_mesh_make(&m, &p), 0);
    fx_mat4 t, rot;
    fx_mat4_translate(&t, 0, 0, -5 * ONE);
    fx_mat4_rotate(&rot, fx_angle_from_deg(35), fx_vec3_make(ONE, ONE, 0));
    fx_mat4_mul(&t, &t, &rot);
    fx_mat_stack_load(&g->r.model, &t);
    g->r.cull = FX3D_CULL_NONE;
    g->r.polymode = FX3D_WIRE;
    fx_ctx_set_color(&g->r.ctx, 0xFFFFFFFF);
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
    int wire = 0, hidden = 0;
    for (int i = 0; i < 100 * 100; i++)
        wire += (g->px[i] & 0xFFFFFF) == 0xFFFFFF;
    memset(g->px, 0, sizeof g->px);
    fx3d_set_depth(&g->r, g->z, 32);
    g->r.polymode = FX3D_HIDDEN_LINE;
    g->r.background = 0xFF000000u;
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
    for (int i = 0; i < 100 * 100; i++)
        hidden += (g->px[i] & 0xFFFFFF) == 0xFFFFFF;
    /* the cube seen corner-on shows 9 of its 12 edges */
    FX_CHECK_MSG(hidden > wire / 2 && hidden < wire * 7 / 8, "wire %d hidden %d", wire, hidden);
    free(g);
}

FX_TEST(render3d_planar_shadow_falls_below_the_object)
{
    rig *g = rig_new();
    fx3d_set_depth(&g->r, g->z, 32);
    fx_camera c;
    fx_camera_set(&c, fx_vec3_make(0, 6 * ONE, ONE / 100), fx_vec3_make(0, 0, 0), fx_vec3_make(0, 0, -ONE));
    fx_camera_view(&c, &g->r.view);
    emissive(&g->r, 0x808080);
    quad(&g->r, fx_vec3_make(-5 * ONE, 0, 5 * ONE), fx_vec3_make(5 * ONE, 0, 5 * ONE),
         fx_vec3_make(5 * ONE, 0, -5 * ONE), fx_vec3_make(-5 * ONE, 0, -5 * ONE));
    g->r.light[0].type = FX3D_LIGHT_POINT;
    g->r.light[0].pos = fx_vec3_make(4 * ONE, 4 * ONE, 0);
    fx16 plane[4] = {0, ONE, 0, 0};
    fx3d_plane_shadow(&g->r, plane, 0, 0xFF202020);
    /* a small square at height 2 under a light at (4, 4, 0): its shadow is
     * centred at x = -4 (twice as far out as the object, on the far side) */
    emissive(&g->r, 0xFF0000);
    quad(&g->r, fx_vec3_make(-ONE / 2, 2 * ONE, ONE / 2), fx_vec3_make(ONE / 2, 2 * ONE, ONE / 2),
         fx_vec3_make(ONE / 2, 2 * ONE, -ONE / 2), fx_vec3_make(-ONE / 2, 2 * ONE, -ONE / 2));
    FX_CHECK_EQ(px(g, 50, 50), 0xFF0000);
    /* x = -4 on the floor, seen from height 6 with a 90-degree view: 50 - 4/6 * 50 */
    FX_CHECK_EQ(px(g, 17, 50), 0x202020);
    FX_CHECK_EQ(px(g, 83, 50), 0x808080);
    free(g);
}

FX_TEST(render3d_gouraud_interpolates_between_vertex_colours)
{
    rig *g = rig_new();
    /* A lit quad whose normals tilt from the light on the left to away from
     * it on the right: brightness must fall monotonically across. */
    g->r.light[0].type = FX3D_LIGHT_DIRECTIONAL;
    g->r.light[0].pos = fx_vec3_make(0, 0, ONE);
    g->r.light[0].diffuse = fx3d_rgb_from_color(0xFFFFFF);
    g->r.mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
    g->r.mat.specular = fx3d_rgb_from_color(0);
    fx_vec3 pos[4] = {fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE),
                      fx_vec3_make(ONE, ONE, -2 * ONE), fx_vec3_make(-ONE, ONE, -2 * ONE)};
    fx_vec3 nrm[4] = {fx_vec3_make(0, 0, ONE), fx_vec3_make(ONE, 0, 0), fx_vec3_make(ONE, 0, 0),
                      fx_vec3_make(0, 0, ONE)};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, nrm, tri, 4, 2, 4, 2, NULL, NULL};
    for (int mode = FX3D_GOURAUD; mode <= FX3D_PHONG; mode++) {
        g->r.shading = (fx3d_shading)mode;
        FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
        FX_CHECK_MSG((px(g, 25, 50) & 255) >= 240, "left %06x", px(g, 25, 50));
        uint32_t prev = 256;
        for (int x = 25; x <= 74; x++) {
            uint32_t v = px(g, x, 50) & 255;
            FX_CHECK_MSG(v <= prev, "mode %d x %d: %u after %u", mode, x, v, prev);
            prev = v;
        }
        FX_CHECK(prev < 16);
    }
    free(g);
}

FX_TEST(render3d_bench_frame_draws_the_teapot)
{
    fx_surface s;
    static uint32_t pix[192 * 108];
    FX_CHECK_EQ(fx_surface_init(&s, pix, 192, 108, 192 * 4, FX_FMT_XRGB8888), 0);
    size_t n = bench_teapot_bytes(&s);
    void *mem = malloc(n);
    FX_CHECK_EQ(bench_teapot(&s, mem, n - 8, 0), -FX_EINVAL);
    FX_CHECK_EQ(bench_teapot(&s, mem, n, 0), 0);
    int teapot = 0;
    for (int i = 0; i < 192 * 108; i++)
        teapot += (pix[i] & 0xFFFFFF) != 0x182028;
    /* the teapot fills a good part of the frame, not all of it */
    FX_CHECK_MSG(teapot > 192 * 108 / 8 && teapot < 192 * 108 / 2, "%d teapot pixels", teapot);
    free(mem);
}

/* ---- the per-band savings: vertex cache, hull test, depth rows ---- */

static void lit_teapot(rig *g, fx_mesh *m, int depth)
{
    memset(g->px, 0, sizeof g->px);
    fx3d_set_depth(&g->r, depth ? g->z : NULL, 32);
    FX_CHECK_EQ(fx3d_draw(&g->r, m), 0);
}

/* Transformed and lit once per vertex (fx3d_set_vertex_cache) or once per
 * triangle, a Gouraud teapot under three lights, its inside seen through
 * the open top with culling off (each vertex lit from both sides), with
 * and without vertex colours, is the same picture; a cache too small for
 * the mesh is not used, and misaligned memory is no cache at all. */
FX_TEST(render3d_vertex_cache_keeps_the_pixels)
{
    rig *g = rig_new();
    fx_mesh_params p = {FX_MESH_TEAPOT, ONE, 0, 0, 5, 0};
    int32_t nv, nt;
    FX_CHECK_EQ(fx_mesh_size(&p, &nv, &nt), 0);
    fx_mesh m = {calloc((size_t)nv, sizeof(fx_vec3)), calloc((size_t)nv, sizeof(fx_vec3)),
                 calloc((size_t)nt * 3, sizeof(uint32_t)), 0, 0, nv, nt, NULL, NULL};
    FX_CHECK_EQ(fx_mesh_make(&m, &p), 0);
    fx_color *col = calloc((size_t)nv, sizeof *col);
    for (int32_t i = 0; i < nv; i++)
        col[i] = 0xFF000000u | (uint32_t)(i * 2654435761u >> 8);
    g->r.light[0] = (fx3d_light){0};
    g->r.light[0].type = FX3D_LIGHT_DIRECTIONAL;
    g->r.light[0].pos = fx_vec3_make(ONE, ONE, ONE);
    g->r.light[0].diffuse = g->r.light[0].specular = fx3d_rgb_from_color(0xFFFFFF);
    g->r.light[1] = g->r.light[0];
    g->r.light[1].type = FX3D_LIGHT_POINT;
    g->r.light[1].pos = fx_vec3_make(-3 * ONE, 2 * ONE, 0);
    g->r.light[1].diffuse = fx3d_rgb_from_color(0x4060FF);
    g->r.light[1].att_const = ONE, g->r.light[1].att_quad = ONE / 16;
    g->r.light[2] = g->r.light[1];
    g->r.light[2].type = FX3D_LIGHT_SPOT;
    g->r.light[2].pos = fx_vec3_make(0, 4 * ONE, -4 * ONE);
    g->r.light[2].spot_dir = fx_vec3_make(0, -ONE, 0);
    g->r.light[2].cutoff = fx_angle_from_deg(40);
    g->r.light[2].spot_exp = 2;
    g->r.ambient = fx3d_rgb_from_color(0x202020);
    g->r.mat.ambient = g->r.mat.diffuse = fx3d_rgb_from_color(0xC04020);
    g->r.mat.specular = fx3d_rgb_from_color(0xFFFFFF);
    g->r.mat.shininess = 40;
    g->r.cull = FX3D_CULL_NONE;
    fx_mat4 look;
    fx_mat4_rotate_x(&look, fx_angle_from_deg(35));
    fx_mat4_translate(&g->r.view, 0, -ONE, -6 * ONE);
    fx_mat4_mul(&g->r.view, &g->r.view, &look);
    static uint32_t plain[100 * 100];
    void *mem = malloc(fx3d_vertex_cache_bytes(nv) + FX3D_VERTEX_CACHE_ALIGN);
    for (int vcol = 0; vcol < 2; vcol++) {
        m.col = vcol ? col : NULL;
        fx3d_set_vertex_cache(&g->r, NULL, 0);
        lit_teapot(g, &m, 1);
        memcpy(plain, g->px, sizeof plain);
        int lit = 0;
        for (int i = 0; i < 100 * 100; i++)
            lit += (plain[i] & 0xFFFFFF) != 0;
        FX_CHECK(lit > 1000);
        fx3d_set_vertex_cache(&g->r, mem, fx3d_vertex_cache_bytes(nv));
        FX_CHECK_EQ(g->r.vcache_n, nv);
        for (int k = 0; k < 2; k++) { /* a second draw finds last draw's entries stale */
            lit_teapot(g, &m, 1);
            FX_CHECK(memcmp(plain, g->px, sizeof plain) == 0);
        }
        g->r.vcache_gen = UINT32_MAX; /* the generation wraps: entries cleared */
        lit_teapot(g, &m, 1);
        FX_CHECK(memcmp(plain, g->px, sizeof plain) == 0);
        fx3d_set_vertex_cache(&g->r, mem, fx3d_vertex_cache_bytes(nv - 1));
        lit_teapot(g, &m, 1);
        FX_CHECK(memcmp(plain, g->px, sizeof plain) == 0);
        /* memory off FX3D_VERTEX_CACHE_ALIGN (room enough), or less than
         * one entry: no cache, the same pixels */
        for (int off = 1; off < FX3D_VERTEX_CACHE_ALIGN; off++) {
            fx3d_set_vertex_cache(&g->r, (char *)mem + off, fx3d_vertex_cache_bytes(nv));
            FX_CHECK_MSG(g->r.vcache == NULL && g->r.vcache_n == 0, "offset %d", off);
        }
        lit_teapot(g, &m, 1);
        FX_CHECK(memcmp(plain, g->px, sizeof plain) == 0);
        fx3d_set_vertex_cache(&g->r, mem, fx3d_vertex_cache_bytes(1) - 1);
        FX_CHECK(g->r.vcache == NULL && g->r.vcache_n == 0);
        fx3d_set_vertex_cache(&g->r, mem, fx3d_vertex_cache_bytes(1));
        FX_CHECK(g->r.vcache == mem && g->r.vcache_n == 1);
    }
    /* no wrap where size_t has 32 bits */
    FX_CHECK(fx3d_vertex_cache_bytes(INT32_MAX) >= (size_t)INT32_MAX);
    free(mem);
    free(col);
    free(m.pos);
    free(m.nrm);
    free(m.tri);
    free(g);
}

/* fx3d_hull_away: points beyond one edge of the clip (widened by a margin)
 * are away; points across it, behind the eye, or under painter's mode or a
 * planar shadow are not. fx3d_depth_rows: only those rows are cleared. */
FX_TEST(render3d_hull_away_and_depth_rows)
{
    rig *g = rig_new();
    /* at z = -2 the view spans x, y in [-2, 2]: 25 pixels a unit */
    fx_vec3 left[2] = {fx_vec3_make(-5 * ONE, 0, -2 * ONE), fx_vec3_make(-3 * ONE, ONE, -2 * ONE)};
    fx_vec3 mid[2] = {fx_vec3_make(-5 * ONE, 0, -2 * ONE), fx_vec3_make(ONE, ONE, -2 * ONE)};
    fx_vec3 behind[2] = {fx_vec3_make(-5 * ONE, 0, 2 * ONE), fx_vec3_make(-3 * ONE, 0, -2 * ONE)};
    FX_CHECK_EQ(fx3d_hull_away(&g->r, left, 2), 1);
    FX_CHECK_EQ(fx3d_hull_away(&g->r, mid, 2), 0);
    FX_CHECK_EQ(fx3d_hull_away(&g->r, behind, 2), 0);
    FX_CHECK_EQ(fx3d_hull_away(&g->r, left, 0), 0);
    /* a band of rows 0..29: y = -1 (pixel 74) is below it, y = 0.4 (pixel
     * 40) beyond the 8-pixel margin, y = 0.6 (pixel 35) within it */
    g->r.ctx.clip = (fx_rect){0, 0, 100, 30};
    fx_vec3 low[1] = {fx_vec3_make(0, -ONE, -2 * ONE)};
    fx_vec3 near_edge[1] = {fx_vec3_make(0, ONE * 4 / 10, -2 * ONE)};
    fx_vec3 past_edge[1] = {fx_vec3_make(0, ONE * 6 / 10, -2 * ONE)};
    FX_CHECK_EQ(fx3d_hull_away(&g->r, low, 1), 1);
    FX_CHECK_EQ(fx3d_hull_away(&g->r, near_edge, 1), 1);
    FX_CHECK_EQ(fx3d_hull_away(&g->r, past_edge, 1), 0);
    g->r.visibility = FX3D_VIS_PAINTER;
    FX_CHECK_EQ(fx3d_hull_away(&g->r, low, 1), 0);
    g->r.visibility = FX3D_VIS_NONE;
    g->r.plane_shadow = 1;
    FX_CHECK_EQ(fx3d_hull_away(&g->r, low, 1), 0);
    g->r.plane_shadow = 0;
    /* depth rows */
    memset(g->z, 0x11, sizeof g->z);
    fx3d_depth_rows(&g->r, 10, 20);
    FX_CHECK_EQ(fx3d_set_depth(&g->r, g->z, 32), 0);
    for (int y = 0; y < 100; y++)
        FX_CHECK_EQ(g->z[y * 100 + 37], y >= 10 && y < 20 ? 0xFFFFFFFFu : 0x11111111u);
    fx3d_depth_rows(&g->r, 0, 0);
    fx3d_clear_depth(&g->r);
    FX_CHECK_EQ(g->z[99 * 100 + 99], 0xFFFFFFFFu);
    free(g);
}

/* fx3d_hull_away with a box whose far corners clamp in fixed point. The
 * model matrix puts object (X, Y, 0) at eye (-1228.8 - 947 X, 4000 Y,
 * -(2048 + 16384 X)); the points span X in [0, 16], Y in [-1, 1]. The
 * corners at X = 16 lie 265000 units away, beyond int32 in Q16.16, and
 * fx_mat4_apply clamps their eye z to -32768: with w cut to an eighth,
 * x/w = -0.5 instead of -0.06, so all eight corners seemed beyond the
 * left edge of a clip from column 40 (margin included), and the old code
 * said "away". The hull holds the quad X in [1/4, 3/2], whose vertices do
 * not clamp (w at most 26624) and which has pixels from column 40 on: it must
 * say unsure. */
FX_TEST(render3d_hull_away_unsure_when_corners_clamp)
{
    rig *g = rig_new();
    emissive(&g->r, 0xFFFFFF);
    g->r.cull = FX3D_CULL_NONE;
    FX_CHECK_EQ(fx3d_perspective(&g->r, FX_ANGLE_90, ONE, ONE, 32000 * ONE), 0);
    fx_mat4 m;
    memset(&m, 0, sizeof m);
    m.m[0][0] = -947 * ONE;
    m.m[0][3] = -(int32_t)(1228.8 * ONE);
    m.m[1][1] = 4000 * ONE;
    m.m[2][0] = -16384 * ONE;
    m.m[2][3] = -2048 * ONE;
    m.m[3][3] = ONE;
    fx_mat_stack_load(&g->r.model, &m);
    fx_vec3 pts[2] = {fx_vec3_make(0, -ONE, 0), fx_vec3_make(16 * ONE, ONE, 0)};
    /* the far corner clamps; the quad's far vertex does not */
    fx_vec4 far_corner = fx_mat4_apply_point(&m, fx_vec3_make(16 * ONE, ONE, 0));
    fx_vec4 far_vertex = fx_mat4_apply_point(&m, fx_vec3_make(3 * ONE / 2, ONE / 2, 0));
    FX_CHECK_EQ(far_corner.z, INT32_MIN);
    FX_CHECK(far_vertex.z > -32000 * ONE && far_vertex.z < -26000 * ONE);
    fx_vec3 a = fx_vec3_make(ONE / 4, -ONE / 2, 0), b = fx_vec3_make(3 * ONE / 2, -ONE / 2, 0),
            c = fx_vec3_make(3 * ONE / 2, ONE / 2, 0), d = fx_vec3_make(ONE / 4, ONE / 2, 0);
    quad(&g->r, a, b, c, d);
    static uint32_t full[100 * 100];
    memcpy(full, g->px, sizeof full);
    int in_band = 0;
    for (int y = 0; y < 100; y++)
        for (int x = 40; x < 100; x++)
            in_band += px(g, x, y) != 0;
    FX_CHECK_MSG(in_band > 20, "%d pixels of the quad in columns 40..99", in_band);
    g->r.ctx.clip = (fx_rect){40, 0, 100, 100};
    FX_CHECK_EQ(fx3d_hull_away(&g->r, pts, 2), 0);
    /* and the band drawn by itself has those pixels */
    memset(g->px, 0, sizeof g->px);
    quad(&g->r, a, b, c, d);
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 100; x++)
            if (g->px[y * 100 + x] != (x >= 40 ? full[y * 100 + x] : 0)) {
                FX_CHECK_MSG(0, "band pixel (%d, %d) %06x, full %06x", x, y, g->px[y * 100 + x],
                             full[y * 100 + x]);
                y = x = 100;
            }
    free(g);
}
