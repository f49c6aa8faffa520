/* SPDX-License-Identifier: MIT */
/* Textures on 3D meshes: perspective-correct texture coordinates against a
 * double-precision ray cast, the texture environment (modulate, replace,
 * decal), repeat against clamp, nearest against bilinear, and the
 * generators' texture coordinates. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fixel/rt.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define W 160
#define H 120

typedef struct trig {
    uint32_t px[W * H];
    fx_surface s;
    fx3d r;
    fx_mat4 ms[4], ps[2];
} trig;

/* A 90-degree-ish perspective view from the origin down -z, no culling. */
static trig *trig_new(int fovy)
{
    trig *g = calloc(1, sizeof *g);
    FX_CHECK(g != NULL);
    fx_surface_init(&g->s, g->px, W, H, W * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx3d_init(&g->r, &g->s, g->ms, 4, g->ps, 2), 0);
    FX_CHECK_EQ(fx3d_perspective(&g->r, fx_angle_from_deg(fovy), fx16_from_ratio(W, H), ONE / 2, 50 * ONE), 0);
    g->r.cull = FX3D_CULL_NONE;
    return g;
}

/* Texel (i, j) of the coordinate texture holds i in red and j in green,
 * blue 255 marks a textured pixel. */
static uint32_t coord_px[256 * 256];

static void coord_texture(fx_texture *tx)
{
    for (int j = 0; j < 256; j++)
        for (int i = 0; i < 256; i++)
            coord_px[j * 256 + i] = 0xFF0000FFu | (uint32_t)i << 16 | (uint32_t)j << 8;
    memset(tx, 0, sizeof *tx);
    fx_surface_init(&tx->img, coord_px, 256, 256, 256 * 4, FX_FMT_XRGB8888);
    tx->filter = FX_TEX_NEAREST;
    tx->wrap = FX_TEX_CLAMP;
}

/* The floor y = -1, x in [-10, 10], z in [-21, -1], s along x, t along -z. */
static void floor_quad(fx3d *r)
{
    fx_vec3 pos[4] = {fx_vec3_make(-10 * ONE, -ONE, -ONE), fx_vec3_make(10 * ONE, -ONE, -ONE),
                      fx_vec3_make(10 * ONE, -ONE, -21 * ONE), fx_vec3_make(-10 * ONE, -ONE, -21 * ONE)};
    fx16 uv[8] = {0, 0, ONE, 0, ONE, ONE, 0, ONE};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, uv, NULL};
    FX_CHECK_EQ(fx3d_draw(r, &m), 0);
}

/* The exact (s, t) seen through pixel (x, y)'s centre: a ray from the eye
 * through the pixel centre meets y = -1. Returns 0 when it misses. */
static int exact_st(int x, int y, double th, double *s, double *t)
{
    double nx = (2.0 * x + 1) / W - 1, ny = 1 - (2.0 * y + 1) / H;
    double dx = nx * th * W / H, dy = ny * th;
    if (dy >= 0)
        return 0;
    double k = -1.0 / dy;
    double px = k * dx, pz = -k;
    *s = (px + 10) / 20;
    *t = (-1 - pz) / 20;
    return 1;
}

FX_TEST(tex3d_perspective_matches_a_ray_cast_within_one_texel)
{
    /* Two triangles spanning a floor from 1 to 21 units away: texture
     * coordinates interpolated linearly in screen space would be wrong by
     * dozens of texels; perspective-correct ones must give the texel the
     * exact ray hits, to within one texel (rounding of Q16.16 matrices and
     * of the 24.8 vertices), at every textured pixel. */
    trig *g = trig_new(60);
    fx_texture tx;
    coord_texture(&tx);
    fx3d_texture(&g->r, &tx, FX3D_TEX_REPLACE);
    floor_quad(&g->r);
    double th = tan(30.0 * M_PI / 180.0);
    int checked = 0, worst = 0;
    double affine_worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            uint32_t c = g->px[y * W + x];
            double s, t;
            if (!exact_st(x, y, th, &s, &t) || s < 0.004 || s > 0.996 || t < 0.004 || t > 0.996)
                continue;
            FX_CHECK_MSG((c & 0xFF) == 0xFF, "pixel (%d, %d) on the floor was not drawn: %08x", x, y, c);
            int i = (int)(c >> 16 & 255), j = (int)(c >> 8 & 255);
            int ei = (int)floor(s * 256), ej = (int)floor(t * 256);
            int d = abs(i - ei) > abs(j - ej) ? abs(i - ei) : abs(j - ej);
            if (d > worst)
                worst = d;
            if (d > 1) {
                FX_CHECK_MSG(0, "pixel (%d, %d): texel (%d, %d), exact (%d, %d)", x, y, i, j, ei, ej);
                y = H;
                break;
            }
            /* what screen-linear t would give on this row: t is affine in
             * 1/depth, screen y is too, so the linear value between the near
             * (t = 0 at depth 1) and far (t = 1 at depth 21) edges' rows */
            double ny = 1 - (2.0 * y + 1) / H, yn = -1 / th, yf = -1 / (21 * th);
            double lin = (ny - yn) / (yf - yn);
            if (fabs(lin - t) * 256 > affine_worst)
                affine_worst = fabs(lin - t) * 256;
            checked++;
        }
    FX_CHECK_MSG(checked > 4000, "only %d pixels checked", checked);
    FX_CHECK_MSG(affine_worst > 50, "affine texturing would be off by only %.1f texels", affine_worst);
    FX_CHECK(worst <= 1);
    free(g);
}

/* A square facing the camera at z = -2 filling NDC [-1/2, 1/2]^2 (pixels
 * 40..119 by 30..89), texture coordinates from lo to hi on both axes. */
static void facing_quad(fx3d *r, fx16 lo, fx16 hi)
{
    fx16 hx = ONE * 2 / 3, hy = ONE / 2;
    fx_vec3 pos[4] = {fx_vec3_make(-hx, -hy, -2 * ONE), fx_vec3_make(hx, -hy, -2 * ONE),
                      fx_vec3_make(hx, hy, -2 * ONE), fx_vec3_make(-hx, hy, -2 * ONE)};
    fx16 uv[8] = {lo, lo, hi, lo, hi, hi, lo, hi};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, uv, NULL};
    FX_CHECK_EQ(fx3d_draw(r, &m), 0);
}

static uint32_t one_px[4];

static void flat_texture(fx_texture *tx, fx_color c)
{
    for (int i = 0; i < 4; i++)
        one_px[i] = c;
    memset(tx, 0, sizeof *tx);
    fx_surface_init(&tx->img, one_px, 2, 2, 8, FX_FMT_ARGB8888);
}

FX_TEST(tex3d_modulate_replace_decal_combine_texel_and_light)
{
    trig *g = trig_new(53);
    g->r.shading = FX3D_FLAT;
    g->r.mat.specular = fx3d_rgb_from_color(0);
    g->r.mat.diffuse = fx3d_rgb_from_color(0x806040);
    facing_quad(&g->r, 0, ONE);
    uint32_t lit = g->px[60 * W + 80] & 0xFFFFFF;
    FX_CHECK(lit != 0 && lit != 0xFFFFFF);
    fx_texture tx;
    static const fx_color texel = 0x80C04020u; /* alpha 128 */
    flat_texture(&tx, texel);
    fx3d_texture(&g->r, &tx, FX3D_TEX_MODULATE);
    facing_quad(&g->r, 0, ONE);
    uint32_t got = g->px[60 * W + 80] & 0xFFFFFF, want = 0;
    for (int sh = 0; sh < 24; sh += 8)
        want |= (((lit >> sh & 255) * (texel >> sh & 255) + 127) / 255) << sh;
    FX_CHECK_EQ(got, want);
    fx3d_texture(&g->r, &tx, FX3D_TEX_REPLACE);
    facing_quad(&g->r, 0, ONE);
    FX_CHECK_EQ(g->px[60 * W + 80] & 0xFFFFFF, texel & 0xFFFFFF);
    fx3d_texture(&g->r, &tx, FX3D_TEX_DECAL);
    facing_quad(&g->r, 0, ONE);
    want = 0;
    for (int sh = 0; sh < 24; sh += 8)
        want |= (((lit >> sh & 255) * 127 + (texel >> sh & 255) * 128 + 127) / 255) << sh;
    FX_CHECK_EQ(g->px[60 * W + 80] & 0xFFFFFF, want);
    /* a mesh without texture coordinates stays untextured */
    fx_vec3 pos[3] = {fx_vec3_make(-ONE, -ONE, -2 * ONE), fx_vec3_make(ONE, -ONE, -2 * ONE),
                      fx_vec3_make(0, ONE, -2 * ONE)};
    uint32_t tri[3] = {0, 1, 2};
    fx_mesh m = {pos, NULL, tri, 3, 1, 3, 1, NULL, NULL};
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
    FX_CHECK_EQ(g->px[60 * W + 80] & 0xFFFFFF, lit);
    free(g);
}

/* Colour changes along row 60 between pixels 40 and 119. */
static int transitions(const trig *g)
{
    int n = 0;
    for (int x = 41; x < 120; x++)
        n += g->px[60 * W + x] != g->px[60 * W + x - 1];
    return n;
}

FX_TEST(tex3d_repeat_clamp_nearest_bilinear)
{
    trig *g = trig_new(53);
    static uint32_t ck[4] = {0xFF000000u, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFF000000u};
    fx_texture tx;
    memset(&tx, 0, sizeof tx);
    fx_surface_init(&tx.img, ck, 2, 2, 8, FX_FMT_ARGB8888);
    fx3d_texture(&g->r, &tx, FX3D_TEX_REPLACE);
    /* s from -1 to 2: three periods of two texels under repeat, six cells
     * and five changes across the row */
    tx.wrap = FX_TEX_REPEAT;
    facing_quad(&g->r, -ONE, 2 * ONE);
    FX_CHECK_EQ(g->px[60 * W + 39], 0);
    FX_CHECK_EQ(g->px[60 * W + 120], 0);
    FX_CHECK_EQ(transitions(g), 5);
    /* clamped, s < 0 reads texel 0 and s >= 1 texel 1: one change */
    tx.wrap = FX_TEX_CLAMP;
    facing_quad(&g->r, -ONE, 2 * ONE);
    FX_CHECK_EQ(transitions(g), 1);
    FX_CHECK_EQ(g->px[60 * W + 40] & 0xFFFFFF, 0);
    FX_CHECK_EQ(g->px[60 * W + 119] & 0xFFFFFF, 0xFFFFFF);
    /* bilinear over one period: grey ramps between the texel centres */
    tx.wrap = FX_TEX_REPEAT;
    tx.filter = FX_TEX_NEAREST;
    facing_quad(&g->r, 0, ONE);
    int greys = 0;
    for (int x = 40; x < 120; x++)
        greys += (g->px[60 * W + x] & 0xFFFFFF) != 0 && (g->px[60 * W + x] & 0xFFFFFF) != 0xFFFFFF;
    FX_CHECK_EQ(greys, 0);
    tx.filter = FX_TEX_BILINEAR;
    facing_quad(&g->r, 0, ONE);
    for (int x = 40; x < 120; x++)
        greys += (g->px[60 * W + x] & 0xFFFFFF) != 0 && (g->px[60 * W + x] & 0xFFFFFF) != 0xFFFFFF;
    FX_CHECK_MSG(greys > 60, "%d grey pixels", greys);
    free(g);
}

FX_TEST(tex3d_generators_write_texture_coordinates)
{
    static fx_vec3 pos[2000], nrm[2000];
    static uint32_t tri[3 * 4000];
    static fx16 uv[4000];
    fx_mesh m = {pos, nrm, tri, 0, 0, 2000, 4000, uv, NULL};
    fx_mesh_params cube = {FX_MESH_CUBE, ONE, 0, 0, 0, 0};
    FX_CHECK_EQ(fx_mesh_make(&m, &cube), 0);
    for (int f = 0; f < 6; f++) { /* each face the unit square, once per corner */
        int seen = 0;
        for (int k = 0; k < 4; k++) {
            fx16 s = uv[2 * (4 * f + k)], t = uv[2 * (4 * f + k) + 1];
            FX_CHECK((s == 0 || s == ONE) && (t == 0 || t == ONE));
            seen |= 1 << ((s != 0) + 2 * (t != 0));
        }
        FX_CHECK_EQ(seen, 15);
    }
    fx_mesh_params sph = {FX_MESH_SPHERE, ONE, 0, 0, 8, 4};
    FX_CHECK_EQ(fx_mesh_make(&m, &sph), 0);
    /* rows of 9 (a seam column) from the north pole (t = 0) to the south */
    FX_CHECK_EQ(uv[0], 0);
    FX_CHECK_EQ(uv[1], 0);
    FX_CHECK_EQ(uv[2 * 8], ONE);
    FX_CHECK_EQ(uv[2 * (m.nverts - 1) + 1], ONE);
    FX_CHECK(pos[0].y == ONE);
    fx_mesh_params tp = {FX_MESH_TEAPOT, ONE, 0, 0, 2, 0};
    FX_CHECK_EQ(fx_mesh_make(&m, &tp), 0);
    /* each of the 32 patches a 3 x 3 grid over the unit square */
    for (int p = 0; p < 32; p++)
        for (int i = 0; i < 9; i++) {
            FX_CHECK_EQ(uv[2 * (9 * p + i)], (i / 3) * ONE / 2);
            FX_CHECK_EQ(uv[2 * (9 * p + i) + 1], (i % 3) * ONE / 2);
        }
}

FX_TEST(light_attenuation_constant_linear_quadratic)
{
    trig *g = trig_new(60);
    fx3d *r = &g->r;
    r->ambient = fx3d_rgb_from_color(0);
    r->mat.ambient = r->mat.specular = r->mat.emission = fx3d_rgb_from_color(0);
    r->mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
    r->light[0].type = FX3D_LIGHT_POINT;
    r->light[0].pos = fx_vec3_make(0, 0, 4 * ONE); /* 4 units in front of P, along N */
    fx_vec3 P = fx_vec3_make(0, 0, 0), N = fx_vec3_make(0, 0, ONE);
    FX_CHECK(abs(fx3d_shade(r, P, N).r - ONE) <= 2); /* no attenuation: full diffuse */
    /* 1 / (1 + 0.25 * 4 + 0.0625 * 16) = 1/3 */
    r->light[0].att_const = ONE;
    r->light[0].att_linear = ONE / 4;
    r->light[0].att_quad = ONE / 16;
    FX_CHECK_MSG(abs(fx3d_shade(r, P, N).g - ONE / 3) <= 4, "%d", fx3d_shade(r, P, N).g);
    /* each term alone */
    r->light[0].att_linear = r->light[0].att_quad = 0;
    r->light[0].att_const = 2 * ONE;
    FX_CHECK(abs(fx3d_shade(r, P, N).b - ONE / 2) <= 4);
    r->light[0].att_const = 0;
    r->light[0].att_linear = ONE;
    FX_CHECK(abs(fx3d_shade(r, P, N).b - ONE / 4) <= 4);
    r->light[0].att_linear = 0;
    r->light[0].att_quad = ONE;
    FX_CHECK(abs(fx3d_shade(r, P, N).b - ONE / 16) <= 4);
    /* a far light fades to nothing without overflow */
    r->light[0].pos = fx_vec3_make(0, 0, 30000 * ONE);
    r->light[0].att_quad = 1024 * ONE;
    FX_CHECK_EQ(fx3d_shade(r, P, N).b, 0);
    /* directional lights are never attenuated */
    r->light[0].type = FX3D_LIGHT_DIRECTIONAL;
    r->light[0].pos = N;
    FX_CHECK(abs(fx3d_shade(r, P, N).r - ONE) <= 2);
    free(g);
}

/* No lights, white global ambient: a pixel's colour is the ambient
 * reflectance (material ka, ambient a). */
static trig *unlit_rig(fx_color ka)
{
    trig *g = trig_new(53);
    g->r.light[0].type = FX3D_LIGHT_OFF;
    g->r.ambient = fx3d_rgb_from_color(0xFFFFFF);
    g->r.mat.ambient = g->r.mat.diffuse = fx3d_rgb_from_color(ka);
    g->r.mat.specular = fx3d_rgb_from_color(0);
    return g;
}

FX_TEST(vertex_colours_stand_for_ambient_and_diffuse)
{
    trig *g = unlit_rig(0x101010); /* replaced by the vertex colours */
    fx3d *r = &g->r;
    fx16 hx = ONE * 2 / 3, hy = ONE / 2;
    fx_vec3 pos[4] = {fx_vec3_make(-hx, -hy, -2 * ONE), fx_vec3_make(hx, -hy, -2 * ONE),
                      fx_vec3_make(hx, hy, -2 * ONE), fx_vec3_make(-hx, hy, -2 * ONE)};
    uint32_t col[4] = {0xFF0000, 0x00FF00, 0x0000FF, 0xFFFF00};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, NULL, col};
    for (int mode = 0; mode < 3; mode++) {
        r->shading = mode == 0 ? FX3D_GOURAUD : mode == 1 ? FX3D_PHONG : FX3D_FLAT;
        FX_CHECK_EQ(fx3d_draw(r, &m), 0);
        /* the corner pixels (40, 89) bottom left ... (119, 30) top right */
        uint32_t bl = g->px[89 * W + 40] & 0xFFFFFF, tr = g->px[30 * W + 119] & 0xFFFFFF;
        uint32_t mid = g->px[60 * W + 80] & 0xFFFFFF;
        if (mode < 2) {
            FX_CHECK_MSG((bl >> 16) > 0xF0 && (bl & 0xFFFF) < 0x1010, "mode %d bottom left %06x", mode, bl);
            FX_CHECK_MSG((tr & 0xFF) > 0xF0 && (tr >> 8) < 0x1010, "mode %d top right %06x", mode, tr);
            /* the middle lies on the diagonal 0-2: half red, half blue */
            FX_CHECK_MSG((mid >> 16) > 0x70 && (mid >> 16) < 0x90 && (mid >> 8 & 255) < 0x10 &&
                             (mid & 255) > 0x70 && (mid & 255) < 0x90,
                         "mode %d middle %06x", mode, mid);
        } else { /* flat: each triangle its last vertex's colour */
            FX_CHECK_EQ(g->px[85 * W + 110] & 0xFFFFFF, 0x0000FFu); /* triangle 0 1 2 */
            FX_CHECK_EQ(g->px[35 * W + 50] & 0xFFFFFF, 0xFFFF00u);  /* triangle 0 2 3 */
        }
    }
    free(g);
}

FX_TEST(solid_textures_use_the_ray_tracers_function_in_object_space)
{
    trig *g = unlit_rig(0xFFFFFF); /* lit colour white: the pixel is the mix */
    fx3d *r = &g->r;
    fx3d_solid(r, FX_RT_TEX_CHECKER, 0x204060, 0xC08040, ONE);
    facing_quad(r, 0, ONE);
    /* unit cells: object x < 0, y < 0, z = -2 sums to an even cell (c0);
     * crossing x = 0 or y = 0 flips it */
    FX_CHECK_EQ(g->px[80 * W + 50] & 0xFFFFFF, 0x204060u);
    FX_CHECK_EQ(g->px[80 * W + 110] & 0xFFFFFF, 0xC08040u);
    FX_CHECK_EQ(g->px[40 * W + 50] & 0xFFFFFF, 0xC08040u);
    FX_CHECK_EQ(g->px[40 * W + 110] & 0xFFFFFF, 0x204060u);
    /* marble: each pixel the mix fx_rt_solid gives at its object point,
     * here at the quad's centre (object (0, 0, -2)) */
    fx3d_solid(r, FX_RT_TEX_MARBLE, 0x000000, 0xFFFFFF, ONE);
    facing_quad(r, 0, ONE);
    /* pixel (80, 60)'s centre: 60 pixels a unit, half a pixel right of and
     * below the centre */
    fx16 w = fx_rt_solid(FX_RT_TEX_MARBLE, fx_vec3_make(ONE / 120, -ONE / 120, -2 * ONE));
    int want = (int)(((int64_t)w * 255 + 0x8000) >> 16);
    int got = (int)(g->px[60 * W + 80] & 255);
    FX_CHECK_MSG(abs(got - want) <= 3, "marble %d, want %d", got, want);
    /* the grain moves with the object: translating the quad in x keeps the
     * pixel pattern relative to the quad */
    fx3d_solid(r, FX_RT_TEX_CHECKER, 0x204060, 0xC08040, ONE);
    facing_quad(r, 0, ONE);
    FX_CHECK_EQ(g->px[80 * W + 80] & 0xFFFFFF, 0xC08040u); /* world and object x > 0 */
    fx_mat4 t;
    fx_mat4_translate(&t, ONE / 4, 0, 0);
    fx_mat_stack_load(&r->model, &t);
    memset(g->px, 0, sizeof g->px);
    facing_quad(r, 0, ONE);
    FX_CHECK_EQ(g->px[80 * W + 80] & 0xFFFFFF, 0x204060u); /* object x = -0.24 */
    free(g);
}

FX_TEST(sphere_map_reflects_the_view_direction)
{
    /* A sphere straight ahead: at its centre the normal faces the eye, the
     * reflection is (0, 0, 1) and the map's centre texel (128, 128) shows;
     * towards the rim s grows to the right, t upwards (as r does). */
    trig *g = trig_new(53);
    fx_texture tx;
    coord_texture(&tx);
    fx3d_texture(&g->r, &tx, FX3D_TEX_REPLACE);
    fx3d_sphere_map(&g->r, 1);
    g->r.cull = FX3D_CULL_BACK;
    static fx_vec3 pos[2000], nrm[2000];
    static uint32_t tri[3 * 4000];
    fx_mesh m = {0};
    m.pos = pos, m.nrm = nrm, m.tri = tri, m.cap_verts = 2000, m.cap_tris = 4000;
    fx_mesh_params sp = {FX_MESH_SPHERE, ONE / 2, 0, 0, 48, 24};
    FX_CHECK_EQ(fx_mesh_make(&m, &sp), 0);
    fx_mat4 t;
    fx_mat4_translate(&t, 0, 0, -2 * ONE);
    fx_mat_stack_load(&g->r.model, &t);
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
    uint32_t c = g->px[60 * W + 80];
    FX_CHECK_MSG(abs((int)(c >> 16 & 255) - 128) <= 3 && abs((int)(c >> 8 & 255) - 128) <= 3, "centre %08x", c);
    uint32_t right = g->px[60 * W + 100], up = g->px[45 * W + 80];
    FX_CHECK_MSG((int)(right >> 16 & 255) > 150, "right %08x", right);
    FX_CHECK_MSG((int)(up >> 8 & 255) > 150, "up %08x", up);
    free(g);
}

/* The texture matrix (fx3d_texture_stack; test_3d_texmat.c checks the
 * coordinates themselves): the rasterizer draws through it. */
static uint32_t coord64_px[64 * 64];

FX_TEST(texmat_rasterizer_draws_through_the_texture_matrix)
{
    /* texel (i, j) holds i in red and j in green: every pixel names its texel */
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++)
            coord64_px[j * 64 + i] = 0xFF0000FFu | (uint32_t)i << 18 | (uint32_t)j << 10;
    fx_texture tx;
    memset(&tx, 0, sizeof tx);
    fx_surface_init(&tx.img, coord64_px, 64, 64, 64 * 4, FX_FMT_XRGB8888);
    tx.filter = FX_TEX_NEAREST;
    tx.wrap = FX_TEX_CLAMP;

    /* uv 0..1 through T(1/4, 1/4) S(1/2) (exact in Q16.16) against uv
     * 1/4..3/4 drawn plainly: the same picture, pixel for pixel */
    trig *a = trig_new(60), *b = trig_new(60), *c = trig_new(60);
    fx_mat4 ts[3];
    fx3d_texture(&a->r, &tx, FX3D_TEX_REPLACE);
    fx3d_texture(&b->r, &tx, FX3D_TEX_REPLACE);
    fx3d_texture(&c->r, &tx, FX3D_TEX_REPLACE);
    FX_CHECK_EQ(fx3d_texture_stack(&a->r, ts, 3), 0);
    fx_mat4 m;
    fx_mat4_translate(&m, ONE / 4, ONE / 4, 0);
    fx_mat_stack_mult(&a->r.texm, &m);
    fx_mat4_scale(&m, ONE / 2, ONE / 2, ONE);
    fx_mat_stack_mult(&a->r.texm, &m);
    facing_quad(&a->r, 0, ONE);
    facing_quad(&b->r, ONE / 4, 3 * ONE / 4);
    facing_quad(&c->r, 0, ONE);
    int drawn = 0, differ_plain = 0;
    for (int i = 0; i < W * H; i++) {
        FX_CHECK_MSG(a->px[i] == b->px[i], "pixel (%d, %d): %08x through the matrix, %08x by hand", i % W, i / W,
                     a->px[i], b->px[i]);
        if (a->px[i] != b->px[i])
            break;
        drawn += (a->px[i] & 0xFF) == 0xFF;
        differ_plain += a->px[i] != c->px[i];
    }
    FX_CHECK_MSG(drawn > 3500, "only %d textured pixels", drawn); /* 70 x 52 at fovy 60 */
    FX_CHECK_MSG(differ_plain > drawn / 2, "the matrix changed only %d of %d pixels", differ_plain, drawn);
    free(a), free(b), free(c);
}
