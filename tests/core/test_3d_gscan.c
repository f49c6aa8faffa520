/* SPDX-License-Identifier: MIT */
/* The notes' scan-line Gouraud in fx3d (FX3D_GOURAUD_SCAN, issue #44):
 * the notes' red-green-blue-white quad has centre (128,128,128) there and
 * (128,0,128) under the triangle rule; triangles draw the same under both;
 * the faces' depth, and so what hides what, is the same under both. */
#include <stdlib.h>
#include <string.h>
#include "fixel/render3d.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define N 65 /* odd: the view's centre is a pixel centre */

typedef struct gs {
    uint32_t px[N * N];
    uint32_t depth[N * N];
    fx_surface s;
    fx3d r;
    fx_mat4 ms[4], ps[2];
} gs;

/* An orthographic view of [-1, 1]^2 down -z, the colours of the vertices
 * shown as they are: no lights, white global ambient, black emission. */
static gs *gs_new(fx3d_shading sh, int depth)
{
    gs *g = calloc(1, sizeof *g);
    FX_CHECK(g != NULL);
    fx_surface_init(&g->s, g->px, N, N, N * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(fx3d_init(&g->r, &g->s, g->ms, 4, g->ps, 2), 0);
    FX_CHECK_EQ(fx3d_ortho(&g->r, -ONE, ONE, -ONE, ONE, ONE, 10 * ONE), 0);
    g->r.cull = FX3D_CULL_NONE;
    g->r.shading = sh;
    g->r.light[0].type = FX3D_LIGHT_OFF;
    g->r.ambient = fx3d_rgb_from_color(0xFFFFFF);
    if (depth)
        FX_CHECK_EQ(fx3d_set_depth(&g->r, g->depth, 32), 0);
    return g;
}

static uint32_t at(const gs *g, int x, int y) { return g->px[y * N + x] & 0xFFFFFFu; }

static int near_tol(uint32_t c, int r, int gr, int b, int tol)
{
    int cr = (int)(c >> 16 & 255), cg = (int)(c >> 8 & 255), cb = (int)(c & 255);
    return abs(cr - r) <= tol && abs(cg - gr) <= tol && abs(cb - b) <= tol;
}

static int near_rgb(uint32_t c, int r, int gr, int b) { return near_tol(c, r, gr, b, 2); }

/* The notes' quad, counter-clockwise toward the viewer: red, green, blue,
 * white, split as the generators and polygon3d split it, from red. */
static void draw_notes_quad(gs *g)
{
    fx_vec3 pos[4] = {fx_vec3_make(-ONE * 4 / 5, -ONE * 4 / 5, -2 * ONE),
                      fx_vec3_make(ONE * 4 / 5, -ONE * 4 / 5, -2 * ONE),
                      fx_vec3_make(ONE * 4 / 5, ONE * 4 / 5, -2 * ONE),
                      fx_vec3_make(-ONE * 4 / 5, ONE * 4 / 5, -2 * ONE)};
    uint32_t col[4] = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu, 0xFFFFFFFFu};
    uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    fx_mesh m = {pos, NULL, tri, 4, 2, 4, 2, NULL, col};
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
}

FX_TEST(gscan3d_notes_quad_centre_grey_where_triangles_give_magenta)
{
    gs *scan = gs_new(FX3D_GOURAUD_SCAN, 0), *tri = gs_new(FX3D_GOURAUD, 0);
    draw_notes_quad(scan);
    draw_notes_quad(tri);
    uint32_t cs = at(scan, N / 2, N / 2), ct = at(tri, N / 2, N / 2);
    FX_CHECK_MSG(near_rgb(cs, 128, 128, 128), "scan-line centre %06X, wanted (128,128,128)", (unsigned)cs);
    FX_CHECK_MSG(near_rgb(ct, 128, 0, 128), "triangle-rule centre %06X, wanted (128,0,128)", (unsigned)ct);
    FX_CHECK(cs != ct);
    /* the corners keep their colours under both (screen y down: red is
     * bottom left; the pixels nearest the corners, a pixel or so in), and
     * the two cover the same pixels */
    int x0 = 7, x1 = N - 8;
    FX_CHECK(near_tol(at(scan, x0, x1), 255, 0, 0, 12) && near_tol(at(tri, x0, x1), 255, 0, 0, 12));
    FX_CHECK(near_tol(at(scan, x1, x0), 0, 0, 255, 12) && near_tol(at(tri, x1, x0), 0, 0, 255, 12));
    FX_CHECK(near_tol(at(scan, x0, x0), 255, 255, 255, 12));
    for (int i = 0; i < N * N; i++)
        FX_CHECK((scan->px[i] == 0) == (tri->px[i] == 0));
    /* along the edges both rules agree: the bottom edge runs red to green */
    uint32_t e = at(scan, N / 2, x1);
    FX_CHECK_MSG(near_tol(e, 128, 128, 0, 12) && near_tol(at(tri, N / 2, x1), 128, 128, 0, 12), "bottom edge %06X",
                 (unsigned)e);
    free(scan);
    free(tri);
}

FX_TEST(gscan3d_triangles_draw_the_same_under_both_rules)
{
    gs *a = gs_new(FX3D_GOURAUD_SCAN, 1), *b = gs_new(FX3D_GOURAUD, 1);
    gs *gg[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        fx3d *r = &gg[k]->r;
        /* a coloured triangle, then a lit icosahedron (triangle faces) over it */
        fx_vec3 pos[3] = {fx_vec3_make(-ONE * 9 / 10, -ONE * 7 / 10, -3 * ONE),
                          fx_vec3_make(ONE * 8 / 10, -ONE * 9 / 10, -2 * ONE),
                          fx_vec3_make(ONE / 10, ONE * 9 / 10, -4 * ONE)};
        uint32_t col[3] = {0xFFFF2000u, 0xFF10E040u, 0xFF3020F0u};
        uint32_t tri[3] = {0, 1, 2};
        fx_mesh m = {pos, NULL, tri, 3, 1, 3, 1, NULL, col};
        FX_CHECK_EQ(fx3d_draw(r, &m), 0);
        r->light[0].type = FX3D_LIGHT_DIRECTIONAL;
        r->ambient = fx3d_rgb_from_color(0x202020);
        fx_vec3 ip[60], in[60];
        uint32_t it[60];
        fx_mesh ico = {ip, in, it, 0, 0, 60, 20, NULL, NULL};
        fx_mesh_params p = {FX_MESH_ICOSAHEDRON, ONE * 3 / 4, 0, 0, 0, 0};
        FX_CHECK_EQ(fx_mesh_make(&ico, &p), 0);
        FX_CHECK_EQ(ico.ntris, 20);
        fx_mat4 t, rot;
        fx_mat4_translate(&t, 0, 0, -3 * ONE);
        FX_CHECK_EQ(fx_mat4_rotate(&rot, fx_angle_from_deg(30), fx_vec3_make(ONE, ONE, 0)), 0);
        fx_mat_stack_load(&r->model, &t);
        fx_mat_stack_mult(&r->model, &rot);
        FX_CHECK_EQ(fx3d_draw(r, &ico), 0);
    }
    int lit = 0;
    for (int i = 0; i < N * N; i++)
        lit += a->px[i] != 0;
    FX_CHECK(lit > N * N / 4);
    FX_CHECK(memcmp(a->px, b->px, sizeof a->px) == 0);
    FX_CHECK(memcmp(a->depth, b->depth, sizeof a->depth) == 0);
    free(a);
    free(b);
}

/* Two quads crossing at x = 0: A (reds) nearer on the left, B (blues)
 * nearer on the right. */
static void draw_crossing(gs *g)
{
    fx_vec3 pos[8] = {fx_vec3_make(-ONE * 9 / 10, -ONE * 8 / 10, -2 * ONE), fx_vec3_make(ONE * 9 / 10, -ONE * 8 / 10, -4 * ONE),
                      fx_vec3_make(ONE * 9 / 10, ONE * 8 / 10, -4 * ONE),   fx_vec3_make(-ONE * 9 / 10, ONE * 8 / 10, -2 * ONE),
                      fx_vec3_make(-ONE * 8 / 10, -ONE * 9 / 10, -4 * ONE), fx_vec3_make(ONE * 8 / 10, -ONE * 9 / 10, -2 * ONE),
                      fx_vec3_make(ONE * 8 / 10, ONE * 9 / 10, -2 * ONE),   fx_vec3_make(-ONE * 8 / 10, ONE * 9 / 10, -4 * ONE)};
    uint32_t col[8] = {0xFFFF0000u, 0xFFC00000u, 0xFFFF4000u, 0xFF800000u,
                       0xFF0000FFu, 0xFF0040C0u, 0xFF0000A0u, 0xFF2000FFu};
    uint32_t tri[12] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    fx_mesh m = {pos, NULL, tri, 8, 4, 8, 4, NULL, col};
    FX_CHECK_EQ(fx3d_draw(&g->r, &m), 0);
}

FX_TEST(gscan3d_depth_hides_the_same_under_both_rules)
{
    gs *a = gs_new(FX3D_GOURAUD_SCAN, 1), *b = gs_new(FX3D_GOURAUD, 1);
    draw_crossing(a);
    draw_crossing(b);
    int left = 0, right = 0;
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            uint32_t ca = at(a, x, y), cb = at(b, x, y);
            int ra = (ca >> 16 & 255) > (ca & 255), rb = (cb >> 16 & 255) > (cb & 255);
            FX_CHECK_MSG((ca == 0) == (cb == 0) && ra == rb, "pixel (%d, %d): %06X against %06X", x, y,
                         (unsigned)ca, (unsigned)cb);
            /* away from the crossing, the nearer quad shows */
            if (y > 8 && y < N - 8 && x > 4 && x < N / 2 - 3) {
                FX_CHECK_MSG(ra, "(%d, %d) should show the red quad: %06X", x, y, (unsigned)ca);
                left++;
            }
            if (y > 8 && y < N - 8 && x > N / 2 + 3 && x < N - 8) {
                FX_CHECK_MSG(!ra && ca != 0, "(%d, %d) should show the blue quad: %06X", x, y, (unsigned)ca);
                right++;
            }
        }
    FX_CHECK(left > 500 && right > 500);
    FX_CHECK(memcmp(a->depth, b->depth, sizeof a->depth) == 0);
    /* and the colours differ: the faces were drawn with the notes' rule */
    FX_CHECK(memcmp(a->px, b->px, sizeof a->px) != 0);
    free(a);
    free(b);
}

/* Non-planar fans whose corners zig-zag across the near plane: convex on
 * the screen, a face to the gatherer, but a clip of such a face can need
 * more corners than a convex one (n + 6), and its clipped outline is not
 * its clipped triangles. Drawn without a fault (ASan finds one on the
 * stack), covering the same pixels at the same depths as the triangles. */
FX_TEST(gscan3d_zigzag_faces_across_the_near_plane)
{
    uint32_t seed = 12345;
    for (int it = 0; it < 400; it++) {
        gs *a = gs_new(FX3D_GOURAUD_SCAN, 1), *b = gs_new(FX3D_GOURAUD, 1);
        gs *gg[2] = {a, b};
        fx_vec3 pos[8];
        uint32_t col[8], tri[18];
        for (int i = 0; i < 8; i++) {
            fx_angle th = (fx_angle)((uint32_t)i << 29);
            seed = seed * 1103515245u + 12345u;
            fx16 z = (i & 1 ? -ONE / 2 : -2 * ONE) + (fx16)(seed >> 16 & 0x3FFF);
            seed = seed * 1103515245u + 12345u;
            /* every other time the near corners far out too, beyond the
             * guard band (4 w) */
            fx16 rr = ((i & it & 1) ? 20 * ONE : ONE / 4) + (fx16)(seed >> 15 & 0xFFFF);
            pos[i] = fx_vec3_make(fx16_mul(rr, fx_cos(th)), fx16_mul(rr, fx_sin(th)), z);
            col[i] = 0xFF000000u | seed;
        }
        for (int i = 0; i < 6; i++) {
            tri[3 * i] = 0;
            tri[3 * i + 1] = (uint32_t)i + 1;
            tri[3 * i + 2] = (uint32_t)i + 2;
        }
        fx_mesh m = {pos, NULL, tri, 8, 6, 8, 6, NULL, col};
        for (int k = 0; k < 2; k++) {
            FX_CHECK_EQ(fx3d_perspective(&gg[k]->r, fx_angle_from_deg(90), ONE, ONE, 10 * ONE), 0);
            FX_CHECK_EQ(fx3d_draw(&gg[k]->r, &m), 0);
        }
        int same = 1;
        for (int i = 0; i < N * N; i++)
            same &= (a->px[i] == 0) == (b->px[i] == 0);
        FX_CHECK_MSG(same, "iteration %d: the rules cover different pixels", it);
        FX_CHECK_MSG(memcmp(a->depth, b->depth, sizeof a->depth) == 0, "iteration %d: different depths", it);
        free(a);
        free(b);
    }
}

/* An OBJ quad (the parser's fan is a face) lit by a point light near one
 * corner: the centre is the mean of the four lit corners under the notes'
 * rule (half-way along the side edges, then half-way across), the mean of
 * the two on the split diagonal under the triangle rule. */
FX_TEST(gscan3d_obj_quad_is_one_face)
{
    const char *t = "v -0.8 -0.8 -2\nv 0.8 -0.8 -2\nv 0.8 0.8 -2\nv -0.8 0.8 -2\nf 1 2 3 4\n";
    fx_vec3 pos[4], nrm[4];
    uint32_t tri[6];
    fx_mesh m = {pos, nrm, tri, 0, 0, 4, 2, NULL, NULL};
    fx_obj_error err;
    FX_CHECK_EQ(fx_mesh_obj_parse(&m, t, strlen(t), &err), 0);
    FX_CHECK_EQ(m.ntris, 2);
    gs *g[2] = {gs_new(FX3D_GOURAUD_SCAN, 1), gs_new(FX3D_GOURAUD, 1)};
    fx_color c[4];
    for (int k = 0; k < 2; k++) {
        fx3d *r = &g[k]->r;
        r->ambient = fx3d_rgb_from_color(0);
        r->mat.specular = fx3d_rgb_from_color(0);
        r->mat.diffuse = fx3d_rgb_from_color(0xFFFFFF);
        r->light[0].type = FX3D_LIGHT_POINT;
        r->light[0].pos = fx_vec3_make(-ONE * 7 / 10, -ONE * 7 / 10, -ONE * 17 / 10);
        FX_CHECK_EQ(fx3d_draw(r, &m), 0);
        for (int i = 0; i < 4 && k == 0; i++)
            c[i] = fx3d_rgb_to_color(fx3d_shade(r, pos[i], fx_vec3_make(0, 0, ONE)));
    }
    int all = 0, diag = 0;
    for (int i = 0; i < 4; i++)
        all += (int)(c[i] & 255);
    diag = (int)(c[0] & 255) + (int)(c[2] & 255);
    all = (all + 2) / 4;
    diag = (diag + 1) / 2;
    FX_CHECK_MSG(abs(all - diag) > 8, "corners %06X %06X %06X %06X do not tell the rules apart", (unsigned)c[0],
                 (unsigned)c[1], (unsigned)c[2], (unsigned)c[3]);
    uint32_t cs = at(g[0], N / 2, N / 2), ct = at(g[1], N / 2, N / 2);
    FX_CHECK_MSG(near_rgb(cs, all, all, all), "scan-line centre %06X, wanted %d", (unsigned)cs, all);
    FX_CHECK_MSG(near_rgb(ct, diag, diag, diag), "triangle-rule centre %06X, wanted %d", (unsigned)ct, diag);
    free(g[0]);
    free(g[1]);
}
