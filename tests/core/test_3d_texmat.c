/* SPDX-License-Identifier: MIT */
/* The texture matrix of the 3D pipeline (OpenGL's GL_TEXTURE matrix mode,
 * fx3d_texture_stack): the transformed coordinates against a double
 * reference, the push/pop stack and the projective divide. The rasterizer's
 * use of it is in test_3d_tex.c (next to its facing quad). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define W 160
#define H 120

typedef struct tm_rig {
    uint32_t px[W * H];
    fx_surface s;
    fx3d r;
    fx_mat4 ms[4], ps[2], ts[3];
} tm_rig;

static tm_rig *rig_new(void)
{
    tm_rig *g = calloc(1, sizeof *g);
    FX_CHECK(g != NULL);
    fx_surface_init(&g->s, g->px, W, H, W * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx3d_init(&g->r, &g->s, g->ms, 4, g->ps, 2), 0);
    FX_CHECK_EQ(fx3d_perspective(&g->r, fx_angle_from_deg(60), fx16_from_ratio(W, H), ONE / 2, 50 * ONE), 0);
    g->r.cull = FX3D_CULL_NONE;
    return g;
}

/* 2x2 linear part and translation of a 2D texture transform, in doubles. */
typedef struct dmat {
    double a, b, c, d, e, f; /* s' = a s + b t + e, t' = c s + d t + f */
} dmat;

static dmat dmul(dmat x, dmat y)
{
    dmat r = {x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c,
              x.c * y.b + x.d * y.d, x.a * y.e + x.b * y.f + x.e, x.c * y.e + x.d * y.f + x.f};
    return r;
}

/* Worst distance, in units of 2^-16, between fx3d_tex_coord and the
 * double transform over a grid of (s, t) in [-2, 2]^2. */
static double worst_error(const fx3d *r, dmat m)
{
    double worst = 0;
    for (int j = -8; j <= 8; j++)
        for (int i = -8; i <= 8; i++) {
            fx16 s = i * ONE / 4 + i * 37, t = j * ONE / 4 - j * 53;
            fx16 out[2];
            fx3d_tex_coord(r, s, t, out);
            double ds = s / 65536.0, dt = t / 65536.0;
            double es = m.a * ds + m.b * dt + m.e, et = m.c * ds + m.d * dt + m.f;
            double e0 = fabs(out[0] - es * 65536), e1 = fabs(out[1] - et * 65536);
            if (e0 > worst)
                worst = e0;
            if (e1 > worst)
                worst = e1;
        }
    return worst;
}

FX_TEST(texmat_coordinates_match_a_double_reference_and_the_stack_restores)
{
    tm_rig *g = rig_new();
    fx3d *r = &g->r;
    fx16 st[2];
    /* before fx3d_texture_stack: identity, untouched */
    fx3d_tex_coord(r, 12345, -54321, st);
    FX_CHECK_EQ(st[0], 12345);
    FX_CHECK_EQ(st[1], -54321);
    FX_CHECK_EQ(fx3d_texture_stack(r, g->ts, 3), 0);
    fx3d_tex_coord(r, 12345, -54321, st);
    FX_CHECK_EQ(st[0], 12345);
    FX_CHECK_EQ(st[1], -54321);

    /* T(0.25, -0.5) R(30 deg) S(3, 0.5), built the glMultMatrix way */
    fx_mat4 m;
    fx_mat4_translate(&m, ONE / 4, -ONE / 2, 0);
    fx_mat_stack_mult(&r->texm, &m);
    fx_mat4_rotate_z(&m, fx_angle_from_deg(30));
    fx_mat_stack_mult(&r->texm, &m);
    fx_mat4_scale(&m, 3 * ONE, ONE / 2, ONE);
    fx_mat_stack_mult(&r->texm, &m);
    double c = cos(M_PI / 6), s = sin(M_PI / 6);
    dmat dt = {1, 0, 0, 1, 0.25, -0.5}, dr = {c, -s, s, c, 0, 0}, ds = {3, 0, 0, 0.5, 0, 0};
    dmat ref = dmul(dmul(dt, dr), ds);
    /* Error budget (mat3d.h): sin/cos within 1 unit, each product rounded
     * to 1/2 unit, so the entries of T R S are within 3.5 units (the 3x
     * scale triples the rotation's error); |s|, |t| <= 2 give at most
     * 2 * 3.5 + 2 * 1.5 + 1 for the final rounding: 11 units of 2^-16. */
    double e = worst_error(r, ref);
    FX_CHECK_MSG(e <= 11, "texture matrix T R S off by %.2f units of 2^-16", e);
    /* and the transform is not the identity (guards the reference) */
    fx3d_tex_coord(r, ONE, 0, st);
    FX_CHECK(abs(st[0] - (fx16)lround((3 * c + 0.25) * 65536)) <= 11);
    FX_CHECK(abs(st[1] - (fx16)lround((3 * s - 0.5) * 65536)) <= 11);

    /* push, a further rotation, pop: back to T R S exactly */
    fx16 before[2], after[2];
    fx3d_tex_coord(r, 3 * ONE / 7, -ONE / 3, before);
    FX_CHECK_EQ(fx_mat_stack_push(&r->texm), 0);
    fx_mat4_rotate_z(&m, fx_angle_from_deg(-75));
    fx_mat_stack_mult(&r->texm, &m);
    double c2 = cos(-75 * M_PI / 180), s2 = sin(-75 * M_PI / 180);
    dmat ref2 = dmul(ref, (dmat){c2, -s2, s2, c2, 0, 0});
    e = worst_error(r, ref2);
    FX_CHECK_MSG(e <= 16, "T R S R2 off by %.2f units", e); /* one more rotation: +1 unit x 3 x 2, rounded */
    fx3d_tex_coord(r, 3 * ONE / 7, -ONE / 3, after);
    FX_CHECK(after[0] != before[0] || after[1] != before[1]);
    FX_CHECK_EQ(fx_mat_stack_push(&r->texm), 0);
    FX_CHECK_EQ(fx_mat_stack_push(&r->texm), -FX_ENOSPC); /* 3 slots */
    FX_CHECK_EQ(fx_mat_stack_pop(&r->texm), 0);
    FX_CHECK_EQ(fx_mat_stack_pop(&r->texm), 0);
    fx3d_tex_coord(r, 3 * ONE / 7, -ONE / 3, after);
    FX_CHECK_EQ(after[0], before[0]);
    FX_CHECK_EQ(after[1], before[1]);
    FX_CHECK_EQ(fx_mat_stack_pop(&r->texm), -FX_ERANGE);
    free(g);
}

FX_TEST(texmat_projective_matrix_divides_by_q)
{
    tm_rig *g = rig_new();
    FX_CHECK_EQ(fx3d_texture_stack(&g->r, g->ts, 3), 0);
    fx_mat4 m;
    fx_mat4_identity(&m);
    m.m[3][0] = ONE / 2; /* q = s / 2 + 1 */
    fx_mat_stack_load(&g->r.texm, &m);
    for (int i = -3; i <= 8; i++) {
        fx16 s = i * ONE / 3 + 7, t = ONE - i * 1000, st[2];
        fx3d_tex_coord(&g->r, s, t, st);
        double q = s / 131072.0 + 1;
        /* q itself is rounded to 1/2 unit before the division (rounded to
         * 1/2 unit again): a relative error of 0.5 / (q 2^16) on top */
        double tol0 = 0.5 + fabs(s / q) * 0.5 / (q * 65536), tol1 = 0.5 + fabs(t / q) * 0.5 / (q * 65536);
        FX_CHECK_MSG(fabs(st[0] - s / q) <= tol0 && fabs(st[1] - t / q) <= tol1, "(%d, %d) -> (%d, %d), want (%.1f, %.1f)",
                     s, t, st[0], st[1], s / q, t / q);
    }
    free(g);
}
