/* SPDX-License-Identifier: MIT */
/* Frame mapping (issue #44): the frame map's frames are orthonormal and
 * follow the grain, Kajiya-Kay's highlight is the formula, and in both the
 * ray tracer and the rasterizer's Phong path the highlight stretches
 * across the grain, while strength 0 leaves the picture as it was. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/mesh.h"
#include "fixel/render3d.h"
#include "fixel/rt.h"
#include "fixel/surface.h"
#include "fx_test.h"

#define Q 65536.0
#define FX(v) ((fx16)lround((v) * Q))

static double urand(uint32_t *s, double lo, double hi)
{
    *s = *s * 1664525u + 1013904223u;
    return lo + (hi - lo) * (*s >> 8) / 16777216.0;
}

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static void to_d(fx_vec3 v, double *d)
{
    d[0] = v.x / Q;
    d[1] = v.y / Q;
    d[2] = v.z / Q;
}

FX_TEST(frame_maps_give_orthonormal_frames_along_the_grain)
{
    uint32_t seed = 44;
    double worst_len = 0, worst_dot = 0, worst_ang = 0, mean_jit = 0;
    int n = 0;
    for (int i = 0; i < 6000; i++) {
        double nd[3] = {urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1)};
        fx_vec3 nv = fx_vec3_make(FX(nd[0]), FX(nd[1]), FX(nd[2]));
        if (fx_vec3_normalize(&nv) < 0)
            continue;
        int kind = 1 + (i & 1);
        fx_vec3 q = fx_vec3_make(FX(urand(&seed, -300, 300)), FX(urand(&seed, -300, 300)), FX(urand(&seed, -300, 300)));
        fx_vec3 dir = fx_rt_frame_dir(kind, q), t, b;
        fx_rt_frame(dir, nv, &t, &b);
        double T[3], B[3], N[3], D[3];
        to_d(t, T);
        to_d(b, B);
        to_d(nv, N);
        to_d(dir, D);
        double l[2] = {sqrt(dot3(T, T)), sqrt(dot3(B, B))}, d[3] = {dot3(T, N), dot3(B, N), dot3(T, B)};
        for (int k = 0; k < 2; k++)
            worst_len = fmax(worst_len, fabs(l[k] - 1));
        for (int k = 0; k < 3; k++)
            worst_dot = fmax(worst_dot, fabs(d[k]));
        /* right-handed: B = N x T */
        double c[3] = {N[1] * T[2] - N[2] * T[1], N[2] * T[0] - N[0] * T[2], N[0] * T[1] - N[1] * T[0]};
        FX_CHECK_MSG(dot3(c, B) > 0.99, "B is not N x T (%f)", dot3(c, B));
        /* T is the grain with its normal part removed (where that is not
         * degenerate) */
        double dn = dot3(D, N), r[3] = {D[0] - dn * N[0], D[1] - dn * N[1], D[2] - dn * N[2]};
        double rl = sqrt(dot3(r, r));
        if (rl > 0.2 * sqrt(dot3(D, D))) {
            double ca = dot3(r, T) / rl / l[0];
            worst_ang = fmax(worst_ang, acos(fmin(1, ca)) * 180 / M_PI);
        }
        /* the map's grain: brushed leans along x, spun along the circle
         * about y; the jitter tilts it by a little, not by nothing */
        double dl = sqrt(dot3(D, D));
        if (kind == FX_RT_FRAME_BRUSHED) {
            FX_CHECK_MSG(D[0] / dl > 0.9, "brushed grain (%f %f %f) leaves x", D[0], D[1], D[2]);
            mean_jit += acos(D[0] / dl) * 180 / M_PI;
        } else {
            double qx = q.x / Q, qz = q.z / Q, qr = sqrt(qx * qx + qz * qz);
            double circ[3] = {-qz / qr, 0, qx / qr};
            FX_CHECK_MSG(dot3(circ, D) / dl > 0.9, "spun grain (%f %f %f) leaves the circle", D[0], D[1], D[2]);
        }
        n++;
    }
    mean_jit /= n / 2;
    FX_CHECK(n > 5000);
    FX_CHECK_MSG(worst_len < 1.0 / 1024, "frame vector length off by %g", worst_len);
    FX_CHECK_MSG(worst_dot < 1.0 / 1024, "frame vectors off perpendicular by %g", worst_dot);
    FX_CHECK_MSG(worst_ang < 0.25, "tangent %.3f degrees from the grain", worst_ang);
    FX_CHECK_MSG(mean_jit > 2 && mean_jit < 15, "mean jitter %.2f degrees", mean_jit);
    printf("  frames: |len - 1| <= %.2g, |dot| <= %.2g, tangent within %.3f deg of the grain, mean jitter %.2f deg\n",
           worst_len, worst_dot, worst_ang, mean_jit);
    /* the grain along the normal itself: still a frame */
    fx_vec3 t, b, nx = fx_vec3_make(FX16_ONE, 0, 0);
    fx_rt_frame(fx_vec3_make(FX16_ONE, 0, 0), nx, &t, &b);
    FX_CHECK(abs(fx_vec3_dot(t, nx)) < 64 && abs(fx_vec3_dot(b, nx)) < 64 && abs(fx_vec3_dot(t, b)) < 64);
    FX_CHECK(abs(fx_vec3_length(t) - FX16_ONE) < 64 && abs(fx_vec3_length(b) - FX16_ONE) < 64);
}

FX_TEST(frame_aniso_spec_is_kajiya_kay)
{
    uint32_t seed = 7;
    double worst = 0;
    for (int i = 0; i < 3000; i++) {
        fx_vec3 t = fx_vec3_make(FX(urand(&seed, -1, 1)), FX(urand(&seed, -1, 1)), FX(urand(&seed, -1, 1)));
        fx_vec3 h = fx_vec3_make(FX(urand(&seed, -1, 1)), FX(urand(&seed, -1, 1)), FX(urand(&seed, -1, 1)));
        if (fx_vec3_normalize(&t) < 0 || fx_vec3_normalize(&h) < 0)
            continue;
        int32_t e = (int32_t)urand(&seed, 1, 120);
        double k = urand(&seed, 0, 1), spec = urand(&seed, 0, 1);
        double T[3], H[3];
        to_d(t, T);
        to_d(h, H);
        double th = dot3(T, H), kk = pow(sqrt(fmax(0, 1 - th * th)), e);
        double nl = urand(&seed, 0, 1), want = spec + k * (kk * nl - spec);
        fx16 got = fx_rt_aniso_spec(FX(spec), FX(k), t, h, FX(nl), e);
        worst = fmax(worst, fabs(got / Q - want));
    }
    FX_CHECK_MSG(worst < 0.01, "worst %.4f from spec + k (kk - spec)", worst);
    printf("  Kajiya-Kay highlight: worst %.5f from the formula\n", worst);
    /* strength 0: the highlight untouched, bit for bit */
    fx_vec3 t = fx_vec3_make(FX16_ONE, 0, 0), h = fx_vec3_make(0, 0, FX16_ONE);
    FX_CHECK_EQ(fx_rt_aniso_spec(12345, 0, t, h, FX16_ONE, 40), 12345);
    FX_CHECK_EQ(fx_rt_aniso_spec(12345, FX16_ONE, t, h, FX16_ONE, 40), FX16_ONE); /* T perpendicular to H: brightest */
    FX_CHECK_EQ(fx_rt_aniso_spec(12345, FX16_ONE, t, t, FX16_ONE, 40), 0);        /* along it: none */
    FX_CHECK_EQ(fx_rt_aniso_spec(12345, FX16_ONE, t, h, 0, 40), 0);               /* grazing light: none */
}

/* The bright pixels' extent (in x and y) of a w x h XRGB8888 picture:
 * green above 128. Returns their count. */
static int bright_extent(const uint32_t *px, int w, int h, int *ex, int *ey)
{
    int x0 = w, x1 = -1, y0 = h, y1 = -1, n = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if ((px[y * w + x] >> 8 & 255) > 128) {
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
                n++;
            }
    *ex = n ? x1 - x0 + 1 : 0;
    *ey = n ? y1 - y0 + 1 : 0;
    return n;
}

enum { W = 120, H = 120 };

/* A unit sphere, specular white only (so what is bright is highlight),
 * lit from the camera, ray traced with frame map kind at strength k. */
static void rt_sphere(uint32_t *px, int kind, fx16 k)
{
    fx_surface surf;
    fx_surface_init(&surf, px, W, H, W * 4, FX_FMT_XRGB8888);
    fx_rt_object obj[2];
    fx_rt_scene s;
    fx_rt_scene_init(&s, obj, 2);
    FX_CHECK(fx_rt_add_light(&s, fx_vec3_make(0, 0, 20 * FX16_ONE), fx3d_rgb_from_color(0xFFFFFF), 0) >= 0);
    fx_rt_material m = fx_rt_material_make(0, 0, 0xFFFFFF, 40, 0, 0, FX16_ONE);
    m.frame = kind;
    m.frame_k = k;
    m.frame_scale = FX16_ONE / 16;
    fx_mat4 id;
    fx_mat4_identity(&id);
    FX_CHECK(fx_rt_add_shape(&s, FX_RT_SPHERE, 0, &id, &m) >= 0);
    fx_rt_render(&s, &surf, 0, 0, W, H);
}

FX_TEST(frame_rt_highlight_stretches_across_the_grain)
{
    static uint32_t plain[W * H], zero[W * H], brushed[W * H];
    rt_sphere(plain, FX_RT_FRAME_NONE, 0);
    rt_sphere(zero, FX_RT_FRAME_BRUSHED, 0);
    rt_sphere(brushed, FX_RT_FRAME_BRUSHED, FX16_ONE);
    FX_CHECK(memcmp(plain, zero, sizeof plain) == 0);
    int px, py, bx, by;
    int np = bright_extent(plain, W, H, &px, &py), nb = bright_extent(brushed, W, H, &bx, &by);
    printf("  ray traced highlight: plain %d px, %d x %d; brushed along x %d px, %d x %d\n", np, px, py, nb, bx, by);
    FX_CHECK(np > 10 && nb > 10);
    FX_CHECK_MSG(abs(px - py) <= 2, "plain highlight %d x %d is not round", px, py);
    /* grain along x: a band up and down the sphere, narrow across */
    FX_CHECK_MSG(by >= 2 * bx, "brushed highlight %d x %d is not stretched across the grain", bx, by);
    FX_CHECK_MSG(by >= 2 * py, "brushed highlight %d tall against the plain %d", by, py);
}

/* The same sphere as a mesh under fx3d's Phong (or other) shading. */
static void r3d_sphere(uint32_t *px, fx3d_shading sh, int kind, fx16 k, int turn)
{
    enum { NV = 2000, NT = 4000 };
    static fx_vec3 pos[NV], nrm[NV];
    static uint32_t tri[3 * NT];
    fx_mesh mesh;
    memset(&mesh, 0, sizeof mesh);
    mesh.pos = pos;
    mesh.nrm = nrm;
    mesh.tri = tri;
    mesh.cap_verts = NV;
    mesh.cap_tris = NT;
    fx_mesh_params mp = {FX_MESH_SPHERE, FX16_ONE, 0, 0, 32, 16};
    FX_CHECK_EQ(fx_mesh_make(&mesh, &mp), 0);
    fx_surface surf;
    fx_surface_init(&surf, px, W, H, W * 4, FX_FMT_XRGB8888);
    memset(px, 0, sizeof(uint32_t) * W * H);
    static uint32_t zb[W * H];
    fx_mat4 ms[4], ps[2];
    static fx3d r;
    FX_CHECK_EQ(fx3d_init(&r, &surf, ms, 4, ps, 2), 0);
    fx3d_set_depth(&r, zb, 32);
    fx3d_clear_depth(&r);
    FX_CHECK_EQ(fx3d_perspective(&r, fx_angle_from_deg(45), FX16_ONE, FX16_ONE / 2, 50 * FX16_ONE), 0);
    r.shading = sh;
    r.ambient = fx3d_rgb_from_color(0);
    r.light[0].type = FX3D_LIGHT_DIRECTIONAL;
    r.light[0].pos = fx_vec3_make(0, 0, FX16_ONE);
    r.light[0].ambient = fx3d_rgb_from_color(0);
    r.light[0].diffuse = r.light[0].specular = fx3d_rgb_from_color(0xFFFFFF);
    r.mat.ambient = r.mat.diffuse = r.mat.emission = fx3d_rgb_from_color(0);
    r.mat.specular = fx3d_rgb_from_color(0xFFFFFF);
    r.mat.shininess = 40;
    fx3d_frame(&r, kind, k, FX16_ONE / 16);
    fx_mat4_translate(fx_mat_stack_top(&r.model), 0, 0, -3 * FX16_ONE);
    if (turn) {
        fx_mat4 rz, *top = fx_mat_stack_top(&r.model);
        fx_mat4_rotate_z(&rz, FX_ANGLE_90);
        fx_mat4_mul(top, top, &rz);
    }
    FX_CHECK_EQ(fx3d_draw(&r, &mesh), 0);
}

FX_TEST(frame_fx3d_phong_highlight_stretches_across_the_grain)
{
    static uint32_t plain[W * H], zero[W * H], brushed[W * H], spun[W * H], g0[W * H], g1[W * H];
    r3d_sphere(plain, FX3D_PHONG, FX_RT_FRAME_NONE, FX16_ONE, 0);
    r3d_sphere(zero, FX3D_PHONG, FX_RT_FRAME_BRUSHED, 0, 0);
    r3d_sphere(brushed, FX3D_PHONG, FX_RT_FRAME_BRUSHED, FX16_ONE, 0);
    r3d_sphere(spun, FX3D_PHONG, FX_RT_FRAME_SPUN, FX16_ONE, 0);
    /* strength 0 (or no kind): plain Phong, pixel for pixel */
    FX_CHECK(memcmp(plain, zero, sizeof plain) == 0);
    /* Gouraud ignores it */
    r3d_sphere(g0, FX3D_GOURAUD, FX_RT_FRAME_NONE, 0, 0);
    r3d_sphere(g1, FX3D_GOURAUD, FX_RT_FRAME_BRUSHED, FX16_ONE, 0);
    FX_CHECK(memcmp(g0, g1, sizeof g0) == 0);
    int px, py, bx, by, sx, sy;
    int np = bright_extent(plain, W, H, &px, &py), nb = bright_extent(brushed, W, H, &bx, &by);
    int ns = bright_extent(spun, W, H, &sx, &sy);
    printf("  fx3d Phong highlight: plain %d px, %d x %d; brushed along x %d px, %d x %d; spun about y %d px, %d x %d\n",
           np, px, py, nb, bx, by, ns, sx, sy);
    FX_CHECK(np > 10 && nb > 10 && ns > 10);
    FX_CHECK_MSG(abs(px - py) <= 2, "plain highlight %d x %d is not round", px, py);
    FX_CHECK_MSG(by >= 2 * bx, "brushed highlight %d x %d is not stretched across the grain", bx, by);
    /* spun about y: the grain runs around the sphere's front horizontally
     * too, so the band is upright as well */
    FX_CHECK_MSG(sy >= 2 * sx, "spun highlight %d x %d is not stretched across the grain", sx, sy);
    /* turn the sphere a quarter about z: the grain (object x) runs up and
     * down the picture, and the band lies across it */
    r3d_sphere(brushed, FX3D_PHONG, FX_RT_FRAME_BRUSHED, FX16_ONE, 1);
    nb = bright_extent(brushed, W, H, &bx, &by);
    printf("  turned a quarter about z: brushed %d px, %d x %d\n", nb, bx, by);
    FX_CHECK_MSG(bx >= 2 * by, "turned brushed highlight %d x %d does not turn with the object", bx, by);
}
