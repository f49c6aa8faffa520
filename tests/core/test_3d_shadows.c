/* SPDX-License-Identifier: MIT */
/* Shadow maps from several lights (fx3d_shadow_use) and the course's
 * multi-pass shadows (fx3d_pass). A cube stands on a floor between two
 * point lights; each light has its own map. The exact tests colour the
 * lights so that their terms land in different channels (light A red,
 * light B blue, the ambient green): a map that removed the wrong light's
 * terms, or both, changes a channel it must not touch. */
#include <stdlib.h>
#include <string.h>
#include "fixel/draw.h"
#include "fixel/error.h"
#include "fixel/render3d.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define W 96
#define H 72
#define SM 128

typedef struct srig {
    uint32_t px[W * H];
    uint16_t px16[W * H];
    uint32_t z[W * H];
    uint32_t smd[2][SM * SM];
    fx_surface s;
    fx3d r;
    fx_mat4 ms[4], ps[2];
    fx3d_shadowmap sm[2];
    fx_mesh floor, cube;
    fx_vec3 buf_pos[2][400], buf_nrm[2][400];
    uint32_t buf_tri[2][1200];
} srig;

static void make_mesh(fx_mesh *m, fx_vec3 *pos, fx_vec3 *nrm, uint32_t *tri, fx_mesh_kind kind, fx16 a, int n)
{
    fx_mesh_params p = {kind, a, 0, 0, n, 0};
    int32_t nv, nt;
    FX_CHECK_EQ(fx_mesh_size(&p, &nv, &nt), 0);
    FX_CHECK(nv <= 400 && nt <= 400);
    memset(m, 0, sizeof *m);
    m->pos = pos, m->nrm = nrm, m->tri = tri;
    m->cap_verts = 400, m->cap_tris = 400;
    FX_CHECK_EQ(fx_mesh_make(m, &p), 0);
}

/* colours: light A, light B, the global ambient; fmt: the surface's format */
static srig *srig_new(fx_color ca, fx_color cb, fx_color amb, fx_format fmt)
{
    srig *g = calloc(1, sizeof *g);
    FX_CHECK(g != NULL);
    if (fmt == FX_FMT_RGB565)
        fx_surface_init(&g->s, g->px16, W, H, W * 2, fmt);
    else
        fx_surface_init(&g->s, g->px, W, H, W * 4, fmt);
    FX_CHECK_EQ(fx3d_init(&g->r, &g->s, g->ms, 4, g->ps, 2), 0);
    FX_CHECK_EQ(fx3d_perspective(&g->r, fx_angle_from_deg(50), fx16_from_ratio(W, H), ONE / 2, 50 * ONE), 0);
    fx_camera c;
    fx_camera_set(&c, fx_vec3_make(0, 6 * ONE, 6 * ONE), fx_vec3_make(0, 0, 0), fx_vec3_make(0, ONE, 0));
    fx_camera_view(&c, &g->r.view);
    FX_CHECK_EQ(fx3d_set_depth(&g->r, g->z, 32), 0);
    g->r.ambient = fx3d_rgb_from_color(amb);
    fx3d_light *l = g->r.light;
    memset(l, 0, 2 * sizeof *l);
    l[0].type = l[1].type = FX3D_LIGHT_POINT;
    l[0].pos = fx_vec3_make(-3 * ONE / 2, 3 * ONE, -2 * ONE);
    l[1].pos = fx_vec3_make(3 * ONE / 2, 3 * ONE, -2 * ONE);
    l[0].diffuse = l[0].specular = fx3d_rgb_from_color(ca);
    l[1].diffuse = l[1].specular = fx3d_rgb_from_color(cb);
    g->r.mat.ambient = g->r.mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
    g->r.mat.specular = fx3d_rgb_from_color(0x808080);
    g->r.mat.shininess = 16;
    make_mesh(&g->floor, g->buf_pos[0], g->buf_nrm[0], g->buf_tri[0], FX_MESH_PLANE, 8 * ONE, 8);
    make_mesh(&g->cube, g->buf_pos[1], g->buf_nrm[1], g->buf_tri[1], FX_MESH_CUBE, 3 * ONE / 2, 0);
    for (int k = 0; k < 2; k++) {
        FX_CHECK_EQ(fx3d_shadow_init(&g->sm[k], g->smd[k], SM, k), 0);
        FX_CHECK_EQ(fx3d_shadow_aim(&g->sm[k], l[k].pos, fx_vec3_make(0, 0, 0), fx_angle_from_deg(120), ONE / 2,
                                    20 * ONE),
                    0);
    }
    return g;
}

static void draw_cube(srig *g)
{
    fx_mat_stack_push(&g->r.model);
    fx_mat4 t;
    fx_mat4_translate(&t, 0, 3 * ONE / 4, 0);
    fx_mat_stack_mult(&g->r.model, &t);
    FX_CHECK_EQ(fx3d_draw(&g->r, &g->cube), 0);
    fx_mat_stack_pop(&g->r.model);
}

static void fill_maps(srig *g)
{
    for (int k = 0; k < 2; k++) {
        fx3d_shadow_begin(&g->r, &g->sm[k]);
        draw_cube(g);
    }
}

static void draw_scene(srig *g)
{
    FX_CHECK_EQ(fx3d_draw(&g->r, &g->floor), 0);
    draw_cube(g);
}

static void clear(srig *g)
{
    memset(g->px, 0, sizeof g->px);
    memset(g->px16, 0, sizeof g->px16);
    fx3d_clear_depth(&g->r);
}

/* which maps: bit 0 light A's, bit 1 light B's; 4: both through
 * fx3d_shadow_use, 8: only A's through fx3d_shadow_use */
static void render(srig *g, fx3d_shading sh, int which, uint32_t *out)
{
    fx3d_shadow_off(&g->r);
    if (which & 3)
        fill_maps(g);
    fx3d_shadowmap *both[2] = {&g->sm[0], &g->sm[1]};
    if (which == 3) {
        FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 2), 0);
    } else if (which == 9) {
        FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 1), 0);
    } else if (which & 3) {
        /* the one map of the classic path */
        fx3d_shadow_begin(&g->r, &g->sm[which == 1 ? 0 : 1]);
        draw_cube(g);
        fx3d_shadow_end(&g->r);
    }
    g->r.shading = sh;
    clear(g);
    draw_scene(g);
    fx3d_shadow_off(&g->r);
    memcpy(out, g->px, sizeof g->px);
}

#define CH(c, sh) (((c) >> (sh)) & 255)

static void separate_channels(fx3d_shading shading)
{
    srig *g = srig_new(0xFF0000, 0x0000FF, 0x00FF00, FX_FMT_XRGB8888);
    static uint32_t none[W * H], a[W * H], b[W * H], both[W * H];
    render(g, shading, 0, none);
    render(g, shading, 1, a);
    render(g, shading, 2, b);
    render(g, shading, 3, both);
    int only_b = 0, only_a = 0, both_sh = 0;
    for (int i = 0; i < W * H; i++) {
        /* each map removes its own light's channel and nothing else */
        FX_CHECK_MSG(CH(both[i], 16) == CH(a[i], 16), "pixel %d red %06x vs %06x", i, both[i], a[i]);
        FX_CHECK_MSG(CH(both[i], 0) == CH(b[i], 0), "pixel %d blue %06x vs %06x", i, both[i], b[i]);
        FX_CHECK_MSG(CH(both[i], 8) == CH(none[i], 8), "pixel %d green %06x vs %06x", i, both[i], none[i]);
        FX_CHECK_EQ(CH(a[i], 0), CH(none[i], 0));
        FX_CHECK_EQ(CH(b[i], 16), CH(none[i], 16));
        int sa = CH(a[i], 16) < CH(none[i], 16), sb = CH(b[i], 0) < CH(none[i], 0);
        /* lit by A, shadowed from B: exactly A's terms, no B */
        if (sb && !sa && CH(none[i], 16) > 20) {
            only_b++;
            FX_CHECK_EQ(CH(both[i], 16), CH(none[i], 16));
            FX_CHECK_EQ(CH(both[i], 0), 0u);
        }
        if (sa && !sb && CH(none[i], 0) > 20) {
            only_a++;
            FX_CHECK_EQ(CH(both[i], 0), CH(none[i], 0));
            FX_CHECK_EQ(CH(both[i], 16), 0u);
        }
        both_sh += sa && sb;
    }
    /* two shadows, one on each side of the cube */
    FX_CHECK_MSG(only_a > 100 && only_b > 100, "shadowed from A only %d, from B only %d", only_a, only_b);
    free(g);
}

FX_TEST(shadow3d_each_map_removes_only_its_own_light_flat) { separate_channels(FX3D_FLAT); }
FX_TEST(shadow3d_each_map_removes_only_its_own_light_gouraud) { separate_channels(FX3D_GOURAUD); }
FX_TEST(shadow3d_each_map_removes_only_its_own_light_phong) { separate_channels(FX3D_PHONG); }

/* Grey lights (all terms in every channel, so the removal has to subtract
 * the right share): a pixel shadowed from B only equals the picture drawn
 * with light B switched off (its ambient term is 0), one shadowed from both
 * equals the picture with both off. The lights are dim enough that no
 * channel saturates, so every shadowed pixel differs from the unshadowed
 * picture and is counted. */
static void white_lights(fx3d_shading shading)
{
    srig *g = srig_new(0x686868, 0x585858, 0x202020, FX_FMT_XRGB8888);
    g->r.mat.specular = fx3d_rgb_from_color(0x202020);
    static uint32_t a[W * H], b[W * H], both[W * H], offa[W * H], offb[W * H], offab[W * H];
    render(g, shading, 1, a);
    render(g, shading, 2, b);
    render(g, shading, 3, both);
    g->r.light[1].type = FX3D_LIGHT_OFF;
    render(g, shading, 0, offb);
    g->r.light[0].type = FX3D_LIGHT_OFF;
    render(g, shading, 0, offab);
    g->r.light[1].type = FX3D_LIGHT_POINT;
    render(g, shading, 0, offa);
    g->r.light[0].type = FX3D_LIGHT_POINT;
    int nb = 0, na = 0, nab = 0;
    static uint32_t none[W * H];
    render(g, shading, 0, none);
    for (int i = 0; i < W * H; i++) {
        /* no channel saturates, or a shadow could leave a pixel unchanged */
        FX_CHECK(CH(none[i], 16) < 255 && CH(none[i], 8) < 255 && CH(none[i], 0) < 255);
        int in_a = a[i] != none[i], in_b = b[i] != none[i];
        if (in_b && !in_a) {
            nb++;
            FX_CHECK_MSG(both[i] == offb[i], "pixel %d: %06x, light B off %06x", i, both[i], offb[i]);
        } else if (in_a && !in_b) {
            na++;
            FX_CHECK_MSG(both[i] == offa[i], "pixel %d: %06x, light A off %06x", i, both[i], offa[i]);
        } else if (in_a && in_b) {
            nab++;
            FX_CHECK_MSG(both[i] == offab[i], "pixel %d: %06x, both off %06x", i, both[i], offab[i]);
        } else {
            FX_CHECK_MSG(both[i] == none[i], "pixel %d: %06x, no shadow %06x", i, both[i], none[i]);
        }
    }
    FX_CHECK_MSG(na > 100 && nb > 100 && nab > 10, "A only %d, B only %d, both %d", na, nb, nab);
    free(g);
}

FX_TEST(shadow3d_two_maps_equal_lights_switched_off_gouraud) { white_lights(FX3D_GOURAUD); }
FX_TEST(shadow3d_two_maps_equal_lights_switched_off_phong) { white_lights(FX3D_PHONG); }
FX_TEST(shadow3d_two_maps_equal_lights_switched_off_flat) { white_lights(FX3D_FLAT); }

FX_TEST(shadow3d_one_map_through_use_equals_shadow_end)
{
    srig *g = srig_new(0xC0A080, 0x6080C0, 0x303030, FX_FMT_XRGB8888);
    static uint32_t classic[W * H], used[W * H];
    for (int sh = FX3D_FLAT; sh <= FX3D_PHONG; sh++) {
        render(g, (fx3d_shading)sh, 1, classic);
        render(g, (fx3d_shading)sh, 9, used);
        FX_CHECK(memcmp(classic, used, sizeof used) == 0);
    }
    free(g);
}

FX_TEST(shadow3d_use_rejects_bad_sets)
{
    srig *g = srig_new(0xFFFFFF, 0xFFFFFF, 0, FX_FMT_XRGB8888);
    fx3d_shadowmap *two[2] = {&g->sm[0], &g->sm[0]};
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, two, 2), -FX_EINVAL); /* one light twice */
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, two, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, two, FX3D_MAX_SHADOWS + 1), -FX_EINVAL);
    two[1] = NULL;
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, two, 2), -FX_EINVAL);
    FX_CHECK_EQ(g->r.sm_n, 0);
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_LIGHT, FX3D_MAX_LIGHTS), -FX_EINVAL);
    FX_CHECK_EQ(fx3d_pass(&g->r, 7, 0), -FX_EINVAL);
    free(g);
}

/* The multi-pass picture: ambient, then one additive pass per light. */
static void render_passes(srig *g, fx3d_shading sh, void *out, size_t bytes)
{
    fx3d_shadow_off(&g->r);
    fill_maps(g);
    fx3d_shadowmap *both[2] = {&g->sm[0], &g->sm[1]};
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 2), 0);
    g->r.shading = sh;
    clear(g);
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_AMBIENT, 0), 0);
    draw_scene(g);
    for (int k = 0; k < 2; k++) {
        FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_LIGHT, k), 0);
        draw_scene(g);
    }
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_ALL, 0), 0);
    fx3d_shadow_off(&g->r);
    memcpy(out, g->s.pixels, bytes);
}

static int multipass_vs_single(fx3d_shading sh, fx_format fmt, int *unequal)
{
    srig *g = srig_new(0xC0A080, 0x6080C0, 0x303030, fmt);
    static uint32_t single[W * H], multi[W * H];
    size_t bytes = fmt == FX_FMT_RGB565 ? sizeof g->px16 : sizeof g->px;
    fx3d_shadow_off(&g->r);
    fill_maps(g);
    fx3d_shadowmap *both[2] = {&g->sm[0], &g->sm[1]};
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 2), 0);
    g->r.shading = sh;
    clear(g);
    draw_scene(g);
    memcpy(single, g->s.pixels, bytes);
    render_passes(g, sh, multi, bytes);
    int worst = 0;
    *unequal = 0;
    fx_surface a = g->s, b = g->s;
    a.pixels = (uint8_t *)single, b.pixels = (uint8_t *)multi;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            fx_color p = fx_surface_get(&a, x, y), q = fx_surface_get(&b, x, y);
            *unequal += p != q;
            for (int s = 0; s < 24; s += 8) {
                int d = (int)CH(p, s) - (int)CH(q, s);
                worst = (d < 0 ? -d : d) > worst ? (d < 0 ? -d : d) : worst;
            }
        }
    free(g);
    return worst;
}

/* Three passes (ambient, A, B) each rounded to 8 bits: the sum of three
 * roundings is within (-1.5, 1.5] of the exact sum, the single pass's one
 * rounding within (-0.5, 0.5], so they differ by at most one level. */
FX_TEST(shadow3d_multipass_equals_single_pass_to_rounding)
{
    int unequal;
    int w = multipass_vs_single(FX3D_PHONG, FX_FMT_XRGB8888, &unequal);
    FX_CHECK_MSG(w <= 1, "phong: worst %d", w);
    FX_CHECK_MSG(unequal > 0 && unequal < W * H / 2, "phong: %d unequal", unequal);
    w = multipass_vs_single(FX3D_FLAT, FX_FMT_XRGB8888, &unequal);
    FX_CHECK_MSG(w <= 1, "flat: worst %d", w);
    w = multipass_vs_single(FX3D_GOURAUD, FX_FMT_XRGB8888, &unequal);
    FX_CHECK_MSG(w <= 1, "gouraud: worst %d", w);
}

/* RGB565 keeps 5 or 6 bits of each pass: each later pass reads back a
 * rounded value, so the error grows with the passes. */
FX_TEST(shadow3d_multipass_rgb565_error_is_bounded)
{
    int unequal;
    int w = multipass_vs_single(FX3D_PHONG, FX_FMT_RGB565, &unequal);
    FX_CHECK_MSG(w <= 16, "phong 565: worst %d (%d unequal)", w, unequal);
}

/* The light pass adds only where the depth equals the ambient pass's: a
 * surface hidden behind another adds nothing. */
FX_TEST(shadow3d_light_pass_needs_equal_depth)
{
    srig *g = srig_new(0xFF0000, 0x0000FF, 0x00FF00, FX_FMT_XRGB8888);
    static uint32_t base[W * H];
    g->r.shading = FX3D_PHONG;
    clear(g);
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_AMBIENT, 0), 0);
    draw_scene(g);
    memcpy(base, g->px, sizeof base);
    for (int i = 0; i < W * H; i++)
        FX_CHECK_EQ(base[i] & 0xFF00FFu, 0u); /* ambient green only */
    /* a light pass of the floor alone, moved down: every depth differs */
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_LIGHT, 0), 0);
    fx_mat4 t;
    fx_mat4_translate(&t, 0, -ONE / 4, 0);
    fx_mat_stack_mult(&g->r.model, &t);
    FX_CHECK_EQ(fx3d_draw(&g->r, &g->floor), 0);
    FX_CHECK(memcmp(base, g->px, sizeof base) == 0);
    /* in place it adds red (light A) and nothing else */
    fx_mat4_identity(fx_mat_stack_top(&g->r.model));
    FX_CHECK_EQ(fx3d_draw(&g->r, &g->floor), 0);
    int red = 0;
    for (int i = 0; i < W * H; i++) {
        FX_CHECK_EQ(g->px[i] & 0xFFFFu, base[i] & 0xFFFFu);
        red += CH(g->px[i], 16) > 0;
    }
    FX_CHECK(red > W * H / 4);
    free(g);
}

/* Painter's mode keeps triangles until fx3d_flush; maps turned off before
 * the flush no longer shadow them (and are not read), maps still in use
 * do. */
FX_TEST(shadow3d_painter_flush_uses_only_maps_still_in_use)
{
    srig *g = srig_new(0xFF0000, 0x0000FF, 0x00FF00, FX_FMT_XRGB8888);
    static unsigned char mem[400 * 1024];
    static uint32_t plain[W * H], on[W * H];
    fx3d_shadowmap *both[2] = {&g->sm[0], &g->sm[1]};
    g->r.shading = FX3D_PHONG;
    for (int pass = 0; pass < 3; pass++) {
        fx3d_shadow_off(&g->r);
        if (pass)
            fill_maps(g);
        FX_CHECK_EQ(fx3d_set_painter(&g->r, mem, sizeof mem), 0);
        if (pass)
            FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 2), 0);
        memset(g->px, 0, sizeof g->px);
        draw_scene(g);
        if (pass == 2)
            fx3d_shadow_off(&g->r);
        fx3d_flush(&g->r);
        FX_CHECK_EQ(g->r.pdropped, 0);
        if (pass == 0)
            memcpy(plain, g->px, sizeof plain);
        else if (pass == 1)
            memcpy(on, g->px, sizeof on);
    }
    FX_CHECK(memcmp(plain, g->px, sizeof plain) == 0);
    FX_CHECK(memcmp(plain, on, sizeof plain) != 0);
    fx3d_shadow_off(&g->r);
    free(g);
}

/* Issue #44: the notes' dim diffuse in the ambient pass ("to prevent curved
 * surfaces from appearing flat in shadow"). Light A is red and alone in the
 * red channel, without specular: with dim 1/4 a floor pixel in A's shadow
 * keeps a quarter of the red A gives it unshadowed, and a lit one keeps
 * all of it (the light pass adds the other 3/4), to rounding. */
static void passes_dim(srig *g, fx16 dim, uint32_t *out)
{
    fx3d_shadow_off(&g->r);
    fill_maps(g);
    fx3d_shadowmap *both[2] = {&g->sm[0], &g->sm[1]};
    FX_CHECK_EQ(fx3d_shadow_use(&g->r, both, 2), 0);
    clear(g);
    FX_CHECK_EQ(fx3d_pass_ambient_dim(&g->r, dim), 0);
    draw_scene(g);
    for (int k = 0; k < 2; k++) {
        FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_LIGHT, k), 0);
        FX_CHECK_EQ(g->r.pass_dim, dim); /* kept by the light passes */
        draw_scene(g);
    }
    FX_CHECK_EQ(fx3d_pass(&g->r, FX3D_PASS_ALL, 0), 0);
    FX_CHECK_EQ(g->r.pass_dim, 0);
    fx3d_shadow_off(&g->r);
    memcpy(out, g->px, sizeof g->px);
}

FX_TEST(shadow3d_ambient_pass_dim_diffuse)
{
    srig *g = srig_new(0xFF0000, 0x0000FF, 0x00FF00, FX_FMT_XRGB8888);
    g->r.mat.specular = fx3d_rgb_from_color(0);
    g->r.shading = FX3D_PHONG;
    static uint32_t unshadowed[W * H], plain[W * H], dimmed[W * H];
    fx3d_shadow_off(&g->r);
    clear(g);
    draw_scene(g);
    memcpy(unshadowed, g->px, sizeof g->px);
    passes_dim(g, 0, plain);
    passes_dim(g, ONE / 4, dimmed);
    int shadowed = 0, lit = 0;
    for (int i = 0; i < W * H; i++) {
        int full = CH(unshadowed[i], 16), p = CH(plain[i], 16), d = CH(dimmed[i], 16);
        if (full < 40)
            continue;
        if (p == 0) { /* in A's shadow: a quarter of A's red */
            shadowed++;
            FX_CHECK_MSG(abs(d - (full + 2) / 4) <= 1, "pixel %d: %d in shadow, unshadowed %d", i, d, full);
        } else if (abs(p - full) <= 1) { /* lit: as bright as without the option */
            lit++;
            FX_CHECK_MSG(abs(d - p) <= 1, "pixel %d: lit %d, plain %d", i, d, p);
        }
        /* the green ambient is the same in both (blue, light B, follows A's rule) */
        FX_CHECK(abs((int)CH(dimmed[i], 8) - (int)CH(plain[i], 8)) <= 1);
    }
    FX_CHECK_MSG(shadowed > 50 && lit > 500, "%d shadowed, %d lit pixels", shadowed, lit);
    FX_CHECK_EQ(fx3d_pass_ambient_dim(&g->r, ONE + 1), -FX_EINVAL);
    FX_CHECK_EQ(fx3d_pass_ambient_dim(&g->r, -1), -FX_EINVAL);
    free(g);
}
