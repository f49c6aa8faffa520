/* SPDX-License-Identifier: MIT */
/* fixel-demo — the visible-surface page (issue #23): the course scene drawn
 * by one method at a time, keys 1-8 switching like the clipping page's
 * clippers (9: the octree method on a voxel solid), with an overlay of the method at work collected from its trace:
 * Warnock's regions, the BSP tree, the active edge list of one scan line,
 * Newell's moves and cuts. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"
#include "fixel/vsd.h"
#include "fixel/font.h"
#include "fixel/line.h"

#define VW 400
#define VH 300
#define MAXL 48

typedef struct vsd_log {
    fx_rect reg[4096];
    int nreg;
    char line[MAXL][72];
    int nline, total;
    int cases[5]; /* Warnock: empty, one polygon, surrounding in front, pixel, subdivided */
} vsd_log;

static void collect(void *user, const char *line)
{
    vsd_log *lg = user;
    int x0, x1, y0, y1;
    if (sscanf(line, "warnock [%d,%d)x[%d,%d)", &x0, &x1, &y0, &y1) == 4) {
        static const char *const kinds[5] = {"empty", "polygons, contained", "in front", "pixel", "subdivide"};
        for (int k = 0; k < 5; k++)
            if (strstr(line, kinds[k]))
                lg->cases[k]++;
        if (strstr(line, "polygons, intersecting") || strstr(line, "polygons, surrounding:"))
            lg->cases[1]++;
        if (x1 - x0 >= 8 && lg->nreg < 4096)
            lg->reg[lg->nreg++] = (fx_rect){x0, y0, x1, y1};
        return;
    }
    lg->total++;
    if (lg->nline < MAXL)
        snprintf(lg->line[lg->nline++], sizeof lg->line[0], "%s", line);
}

static const char *const titles[FX_VSD_METHODS + 1] = {
    "z-buffer", "painter (mean depth)", "Newell depth sort", "BSP tree",
    "scan-line", "Warnock subdivision", "ray casting", "A-buffer", "octree (voxels)"};

/* The octree method works on a voxel solid, not on the polygons. */
static void octree_view(fx_ctx *c, const fx_surface *view, int32_t px, int32_t y)
{
    enum { K = 5, N = 32, SC = 9 };
    static uint8_t vox[N * N * N];
    static fx_vsd_onode nodes[(8 * N * N * N - 1) / 7 + 8];
    static int32_t depth[N * SC * N * SC];
    fx_vsd_demo_solid(vox, K);
    fx_vsd_octree o;
    if (fx_vsd_octree_build(&o, nodes, (int32_t)(sizeof nodes / sizeof nodes[0]), vox, K) < 0)
        return;
    int32_t visited = fx_vsd_octree_render(&o, SC, depth, N * SC, N * SC);
    fx_surface_clear(view, 0xFF0C121Au);
    for (int32_t yy = 0; yy < N * SC && yy < view->h; yy++)
        for (int32_t x = 0; x < N * SC && x < view->w; x++) {
            int32_t z = depth[yy * N * SC + x];
            if (z >= 0) {
                uint32_t g = (uint32_t)(230 - z * 170 / N);
                fx_surface_put(view, x + (view->w - N * SC) / 2, yy + (view->h - N * SC) / 2,
                               0xFF000000u | g << 16 | g << 8 | (g * 3 / 4));
            }
        }
    demo_text(c, px + 6, y, 0xFFE8E8E8u, "a 32^3 voxel solid, %d octree nodes", o.nnode);
    demo_text(c, px + 6, y + 12, 0xFFE8E8E8u, "%d visited front to back; the rest", visited);
    demo_text(c, px + 6, y + 24, 0xFFE8E8E8u, "lie behind squares already painted");
    demo_text(c, px + 6, y + 40, 0xFF7A8AA0u, "grey by depth: the tunnel shows the wall,");
    demo_text(c, px + 6, y + 52, 0xFF7A8AA0u, "the bite the inside of the ball");
}

void demo_vsd_page(fx_ctx *c, demo_state *st, int32_t top)
{
    static fx_vsd_vertex v[1024 * 4];
    static fx_vsd_edge e[1024 * 4];
    static fx_vsd_poly p[1024];
    static vsd_log lg;
    fx_vsd_scene s;
    int m = st->vsd_method;
    fx_vsd_init(&s, VW, VH, v, 4096, e, 4096, p, 1024);
    s.background = 0xFF0C121Au;
    if (st->vsd_mesh) {
        static fx_vec3 pos[24 * 12 + 64], nrm[24 * 12 + 64];
        static uint32_t tri[3 * 2 * 24 * 12 + 64];
        fx_mesh_params mp = {FX_MESH_TORUS, FX16_ONE * 3 / 2, FX16_ONE * 3 / 5, 0, 24, 12};
        fx_mesh mesh = {pos, nrm, tri, 0, 0, 24 * 12 + 64, 2 * 24 * 12 + 21, NULL, NULL};
        fx_mesh_make(&mesh, &mp);
        fx_mat4 proj, view, model, pv, mvp;
        fx_camera cam;
        fx_camera_set(&cam, fx_vec3_make(0, 2 * FX16_ONE, 5 * FX16_ONE), fx_vec3_make(0, 0, 0),
                      fx_vec3_make(0, FX16_ONE, 0));
        fx_camera_view(&cam, &view);
        fx_mat4_perspective(&proj, fx_angle_from_deg(45), FX16_ONE * 4 / 3, FX16_ONE, 20 * FX16_ONE);
        fx_mat4_identity(&model);
        fx_mat4_rotate(&model, fx_angle_from_deg(st->vsd_turn), fx_vec3_make(FX16_ONE, FX16_ONE / 2, 0));
        fx_mat4_mul(&pv, &proj, &view);
        fx_mat4_mul(&mvp, &pv, &model);
        s.cull = 1;
        fx_vsd_add_mesh(&s, &mvp, &mesh, 0xFF4D9DE0u);
    } else {
        fx_vsd_demo_scene(&s, st->vsd_extra);
    }
    int32_t ox = 10, oy = top + 2;
    fx_surface view = fx_surface_sub(c->surf, (fx_rect){ox, oy, ox + VW, oy + VH});
    if (m == FX_VSD_METHODS) {
        int32_t px = 420;
        fx_ctx_set_color(c, 0xFF18263Au);
        fx_fill_rect(c, px, top, st->w - px - 8, st->h - 8 - top);
        demo_text(c, px + 6, top + 5, 0xFFF2C14Eu, "Visible surfaces: %s", titles[m]);
        demo_text(c, px + 6, top + 19, 0xFF7A8AA0u, "keys 1-9 method");
        octree_view(c, &view, px, top + 60);
        return;
    }
    memset(&lg, 0, sizeof lg);
    fx_ctx tc = *c;
    tc.trace = collect;
    tc.trace_user = &lg;
    size_t bytes = fx_vsd_work_bytes(&s, (fx_vsd_method)m, m == FX_VSD_ABUFFER ? 6 * VW * VH : 32 * s.npoly + 256);
    void *work = malloc(bytes + 8);
    int32_t *ids = malloc(sizeof(int32_t) * VW * VH);
    fx_vsd_stats stats = {0};
    int32_t edges = 0;
    int err = -1;
    if (work && ids) {
        if (m == FX_VSD_ABUFFER) {
            err = fx_vsd_abuffer(&s, &view, 0, 0, work, bytes, &edges);
        } else {
            err = fx_vsd_render(&s, (fx_vsd_method)m, ids, work, bytes, &tc, st->vsd_row, &stats);
            if (!err)
                fx_vsd_paint(&s, ids, &view, 0, 0);
        }
    }
    int32_t differ = -1;
    if (!err && m != FX_VSD_ABUFFER && m != FX_VSD_ZBUFFER) {
        int32_t *ref = malloc(sizeof(int32_t) * VW * VH);
        if (ref && fx_vsd_render(&s, FX_VSD_ZBUFFER, ref, NULL, 0, NULL, 0, NULL) == 0) {
            differ = 0;
            for (int32_t i = 0; i < VW * VH; i++)
                differ += ref[i] != ids[i];
        }
        free(ref);
    }
    free(work);
    free(ids);
    fx_ctx a = *c;
    fx_ctx_set_clip(&a, (fx_rect){ox, oy, ox + VW, oy + VH});
    fx_ctx_set_color(&a, 0xFF2E4A6Bu);
    fx_rect_outline(c, ox - 1, oy - 1, VW + 2, VH + 2);
    if (m == FX_VSD_WARNOCK) {
        fx_ctx_set_color(&a, 0xFFB08A30u);
        for (int i = 0; i < lg.nreg; i++)
            fx_rect_outline(&a, ox + lg.reg[i].x0, oy + lg.reg[i].y0, lg.reg[i].x1 - lg.reg[i].x0,
                            lg.reg[i].y1 - lg.reg[i].y0);
    }
    if (m == FX_VSD_SCANLINE) {
        fx_ctx_set_color(&a, 0xFFF2C14Eu);
        fx_line(&a, ox, oy + st->vsd_row, ox + VW - 1, oy + st->vsd_row);
    }
    /* the readout */
    int32_t px = 420, y = top;
    fx_ctx_set_color(c, 0xFF18263Au);
    fx_fill_rect(c, px, y, st->w - px - 8, st->h - 8 - y);
    demo_text(c, px + 6, y + 5, 0xFFF2C14Eu, "Visible surfaces: %s", titles[m]);
    demo_text(c, px + 6, y + 19, 0xFF7A8AA0u, "keys 1-9 method, [ ] scan line, m torus/scene,");
    demo_text(c, px + 6, y + 55, 0xFF7A8AA0u, "+/- more triangles (scene) or turn (torus)");
    demo_text(c, px + 6, y + 31, 0xFF7A8AA0u, "1 zbuf 2 painter 3 newell 4 bsp 5 scan 6 warnock");
    demo_text(c, px + 6, y + 43, 0xFF7A8AA0u, "7 ray 8 a-buffer 9 octree");
    y += 72;
    if (err) {
        demo_text(c, px + 6, y, 0xFFE15554u, "error %d (out of work memory?)", err);
        return;
    }
    if (st->vsd_mesh)
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "torus: %d triangles, %d culled or off screen", s.npoly, s.culled);
    else
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d polygons (%d random)", s.npoly, st->vsd_extra);
    y += 12;
    if (differ >= 0) {
        demo_text(c, px + 6, y, differ ? 0xFFE15554u : 0xFF7BC96Fu, "%d pixels differ from the z-buffer", differ);
        y += 12;
    }
    switch (m) {
    case FX_VSD_NEWELL:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d pieces, %d cuts, %d moves", stats.frags, stats.splits, stats.moves);
        break;
    case FX_VSD_BSP:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d nodes, %d cuts, depth %d", stats.nodes, stats.splits, stats.depth);
        break;
    case FX_VSD_WARNOCK:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d regions (outlined: 8 px and more)", stats.regions);
        y += 12;
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d empty, %d one polygon, %d surrounder in front,", lg.cases[0],
                  lg.cases[1], lg.cases[2]);
        y += 12;
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d subdivided into quadrants", lg.cases[4]);
        break;
    case FX_VSD_SCANLINE:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "row %d; longest active edge list %d", st->vsd_row, stats.max_active);
        break;
    case FX_VSD_ABUFFER:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "%d edge pixels blended from 4x4 masks", edges);
        break;
    case FX_VSD_PAINTER:
        demo_text(c, px + 6, y, 0xFFE15554u, "no overlap tests: the cycle comes out wrong");
        break;
    default:
        demo_text(c, px + 6, y, 0xFFE8E8E8u, "the reference every method is tested against");
        break;
    }
    y += 16;
    /* the trace: the BSP tree, the active edge list, Newell's steps */
    int room = (st->h - 16 - y) / 11;
    for (int i = 0; i < lg.nline && i < room; i++) {
        const char *l = lg.line[i];
        if (!strncmp(l, "bsp depth", 9)) {
            int d = atoi(l + 10);
            const char *node = strstr(l, "node");
            char buf[72];
            snprintf(buf, sizeof buf, "%*s%.*s", 2 * d, "", (int)(strchr(node, ' ') ? 40 : 40), node);
            char *cut = strstr(buf, " plane");
            const char *fb = strstr(l, "front");
            if (cut && fb)
                snprintf(cut, sizeof buf - (size_t)(cut - buf), " %s", fb);
            demo_text(c, px + 6, y, 0xFFE8E8E8u, "%s", buf);
        } else {
            demo_text(c, px + 6, y, 0xFFE8E8E8u, "%.52s", l);
        }
        y += 11;
    }
    if (lg.total > room && room > 0)
        demo_text(c, px + 6, y, 0xFF7A8AA0u, "... %d trace lines in all", lg.total);
}

int demo_vsd_key(demo_state *st, int key)
{
    if (key >= '1' && key <= '9') {
        st->vsd_method = key - '1';
        return 1;
    }
    if (key == '[' && st->vsd_row > 0) {
        st->vsd_row -= 4;
        return 1;
    }
    if (key == ']' && st->vsd_row < VH - 4) {
        st->vsd_row += 4;
        return 1;
    }
    if (key == 'm') {
        st->vsd_mesh = !st->vsd_mesh;
        return 1;
    }
    if (st->vsd_mesh && (key == '+' || key == '-')) {
        st->vsd_turn = (st->vsd_turn + (key == '+' ? 10 : 350)) % 360;
        return 1;
    }
    if (key == '+' && st->vsd_extra < 400) {
        st->vsd_extra += 20;
        return 1;
    }
    if (key == '-' && st->vsd_extra > 0) {
        st->vsd_extra -= 20;
        return 1;
    }
    return 0;
}
