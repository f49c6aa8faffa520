/* SPDX-License-Identifier: MIT */
/* fixel — scene commands of visible-surface detection (fixel/vsd.h):
 *   vsdscene N              the course's scene (cyclic bars, interpenetrating
 *                           triangles) plus N random triangles, fitted to the surface
 *   vsdpoly #RGB X Y Z ...  one convex planar polygon, 3..8 vertices
 *   vsdcull on|off          drop back faces from now on
 *   vsdclear                empty the scene
 *   vsd METHOD [ROW]        draw it with one method; --trace shows the
 *                           method working (ROW: the scan line traced)
 *   vsdoctree K SCALE       the course's voxel solid (2^K cube) by the octree
 *                           method, SCALE pixels per voxel, grey by depth
 * State lives in the arena (sc->mod[FX_SCENE_MOD_VSD]). */
#include "scene_frame.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/vsd.h"
#include "scene_vsd.h"

#define TRY(x)                   \
    do {                         \
        int r_ = (x);            \
        if (r_ < 0)              \
            return r_;           \
    } while (0)

#define FX_SCENE_VSD_POLYS 1024

typedef struct svsd {
    fx_vsd_scene s;
    fx_vsd_vertex v[FX_SCENE_VSD_POLYS * 3];
    fx_vsd_edge e[FX_SCENE_VSD_POLYS * 3];
    fx_vsd_poly p[FX_SCENE_VSD_POLYS];
    int32_t *ids;
    void *work;
    size_t work_bytes;
} svsd;

static int get(fx_scene *sc, svsd **out)
{
    TRY(fx_scene_surface(sc));
    svsd *st = sc->mod[FX_SCENE_MOD_VSD];
    if (!st) {
        st = fx_scene_alloc(sc, sizeof *st);
        if (!st)
            return fx_scene_error(sc, "out of scene memory for the visible-surface tables");
        int32_t w = sc->w > FX_VSD_COORD_MAX + 1 ? FX_VSD_COORD_MAX + 1 : sc->w;
        int32_t h = sc->h > FX_VSD_COORD_MAX + 1 ? FX_VSD_COORD_MAX + 1 : sc->h;
        fx_vsd_init(&st->s, w, h, st->v, FX_SCENE_VSD_POLYS * 3, st->e, FX_SCENE_VSD_POLYS * 3, st->p,
                    FX_SCENE_VSD_POLYS);
        st->ids = 0;
        st->work = 0;
        st->work_bytes = 0;
        sc->mod[FX_SCENE_MOD_VSD] = st;
    }
    *out = st;
    return 0;
}

static int cmd_vsdscene(fx_scene *sc)
{
    svsd *st;
    int32_t n;
    TRY(fx_scene_arg_int(sc, &n));
    TRY(fx_scene_end(sc));
    TRY(get(sc, &st));
    st->s.npoly = st->s.nedge = st->s.nvert = 0;
    int e = fx_vsd_demo_scene(&st->s, n);
    if (e < 0)
        return fx_scene_error(sc, "vsdscene: %d triangles do not fit the %d-polygon tables", n,
                              FX_SCENE_VSD_POLYS);
    return 0;
}

static int cmd_vsdpoly(fx_scene *sc)
{
    svsd *st;
    fx_color c;
    fx_vsd_vertex v[FX_VSD_MAX_VERTS];
    int n = 0;
    TRY(fx_scene_arg_color(sc, &c));
    while (fx_scene_more(sc)) {
        if (n == FX_VSD_MAX_VERTS)
            return fx_scene_error(sc, "vsdpoly takes at most %d vertices", FX_VSD_MAX_VERTS);
        TRY(fx_scene_arg_int(sc, &v[n].x));
        TRY(fx_scene_arg_int(sc, &v[n].y));
        TRY(fx_scene_arg_int(sc, &v[n].z));
        n++;
    }
    TRY(fx_scene_end(sc));
    TRY(get(sc, &st));
    int e = fx_vsd_add(&st->s, v, n, c);
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "vsdpoly: the %d-polygon tables are full", FX_SCENE_VSD_POLYS);
    if (e < 0)
        return fx_scene_error(sc, "vsdpoly: the polygon is not convex and planar, or has a "
                                  "repeated vertex, or leaves 0..%d", FX_VSD_COORD_MAX);
    return 0;
}

static int cmd_vsdcull(fx_scene *sc)
{
    static const char *const words[] = {"on", "off", 0};
    svsd *st;
    int k = fx_scene_arg_choice(sc, words);
    TRY(k);
    TRY(fx_scene_end(sc));
    TRY(get(sc, &st));
    st->s.cull = k == 0;
    return 0;
}

static int cmd_vsdclear(fx_scene *sc)
{
    svsd *st;
    TRY(fx_scene_end(sc));
    TRY(get(sc, &st));
    st->s.npoly = st->s.nedge = st->s.nvert = st->s.culled = 0;
    return 0;
}

static int cmd_vsd(fx_scene *sc)
{
    static const char *const names[] = {"zbuffer", "painter", "newell",  "bsp",
                                        "scanline", "warnock", "raycast", "abuffer", 0};
    svsd *st;
    int m = fx_scene_arg_choice(sc, names);
    TRY(m);
    int32_t row = -1;
    if (fx_scene_more(sc))
        TRY(fx_scene_arg_int(sc, &row));
    TRY(fx_scene_end(sc));
    TRY(get(sc, &st));
    fx_vsd_scene *s = &st->s;
    if (row < 0)
        row = s->h / 2;
    /* pieces: sixteen per polygon is far more than the course's scenes
     * split into; a scene that needs more gets the error below */
    int32_t frags = 16 * s->npoly + 256;
    size_t need = fx_vsd_work_bytes(s, (fx_vsd_method)m, m == FX_VSD_ABUFFER ? 4 * s->w * s->h : frags);
    if (need > st->work_bytes) {
        st->work = fx_scene_alloc(sc, need);
        st->work_bytes = st->work ? need : 0;
        if (!st->work)
            return fx_scene_error(sc, "vsd %s: out of scene memory (%lu bytes of work)", names[m],
                                  (unsigned long)need);
    }
    const fx_ctx *c = sc->ctx.trace ? &sc->ctx : 0;
    fx_surface scr = fx_scene_screen_surf(&sc->ctx);
    int e;
    if (m == FX_VSD_ABUFFER) {
        int32_t edges = 0;
        e = fx_vsd_abuffer(s, &scr, 0, 0, st->work, st->work_bytes, &edges);
        if (c && e == 0)
            fx_trace(c, "abuffer: %d polygons, %d edge pixels blended", s->npoly, edges);
    } else {
        if (!st->ids) {
            st->ids = fx_scene_alloc(sc, (size_t)s->w * (size_t)s->h * sizeof(int32_t));
            if (!st->ids)
                return fx_scene_error(sc, "vsd: out of scene memory for the id buffer");
        }
        fx_vsd_stats stats;
        e = fx_vsd_render(s, (fx_vsd_method)m, st->ids, st->work, st->work_bytes, c, row, &stats);
        if (e == 0) {
            fx_vsd_paint(s, st->ids, &scr, 0, 0);
            if (c)
                fx_trace(c, "%s: %d polygons, %d pieces, %d splits, %d moves, %d regions, "
                            "longest active edge list %d",
                         names[m], s->npoly, stats.frags, stats.splits, stats.moves, stats.regions,
                         stats.max_active);
        }
    }
    if (e == -FX_ENOSPC)
        return fx_scene_error(sc, "vsd %s: the scene needs more than %d pieces (or %lu bytes)",
                              names[m], frags, (unsigned long)st->work_bytes);
    if (e == -FX_E2BIG)
        return fx_scene_error(sc, "vsd %s: a piece would need more than %d cutting planes", names[m],
                              FX_VSD_MAX_CUTS);
    if (e < 0)
        return fx_scene_error(sc, "vsd %s failed (%d)", names[m], e);
    return 0;
}

int fx_scene_octree_draw(fx_scene *sc, const uint8_t *vox, int32_t k, int32_t scale, int32_t sx, int32_t sy,
                         int32_t *nodes_out)
{
    int32_t n = (int32_t)1 << k, cap = (((int32_t)1 << (3 * k + 3)) - 1) / 7;
    /* the part of the n * scale picture at (sx, sy) left of and above the
     * surface's far edges */
    int64_t pw = (int64_t)sc->w - sx, ph = (int64_t)sc->h - sy, side = (int64_t)n * scale;
    if (pw <= 0 || ph <= 0 || (int64_t)sx + side <= 0 || (int64_t)sy + side <= 0)
        return 0;
    int32_t w = (int32_t)(pw < side ? pw : side), h = (int32_t)(ph < side ? ph : side);
    fx_vsd_onode *nodes = fx_scene_alloc(sc, (size_t)cap * sizeof *nodes);
    int32_t *depth = fx_scene_alloc(sc, (size_t)w * (size_t)h * sizeof *depth);
    if (!nodes || !depth)
        return fx_scene_error(sc, "octree: out of scene memory");
    fx_vsd_octree o;
    if (fx_vsd_octree_build(&o, nodes, cap, vox, k) < 0)
        return fx_scene_error(sc, "the octree did not fit");
    int32_t visited = fx_vsd_octree_render(&o, scale, depth, w, h);
    if (visited < 0)
        return fx_scene_error(sc, "octree rendering failed (%d)", visited);
    fx_surface scr = fx_scene_screen_surf(&sc->ctx);
    for (int32_t y = 0; y < h; y++)
        for (int32_t x = 0; x < w; x++) {
            int32_t z = depth[(size_t)y * (size_t)w + (size_t)x];
            int64_t px = (int64_t)sx + x, py = (int64_t)sy + y;
            if (z < 0 || px < 0 || py < 0)
                continue;
            if (sc->banded && (px < sc->band.x0 || px >= sc->band.x1 || py < sc->band.y0 || py >= sc->band.y1))
                continue; /* another band's pixel */
            uint32_t g = (uint32_t)(230 - z * 170 / n);
            fx_surface_put(&scr, (int32_t)px, (int32_t)py, 0xFF000000u | g << 16 | g << 8 | (g * 3 / 4));
        }
    *nodes_out = o.nnode;
    return visited;
}

static int cmd_vsdoctree(fx_scene *sc)
{
    int32_t k, scale;
    TRY(fx_scene_arg_int(sc, &k));
    TRY(fx_scene_arg_int(sc, &scale));
    TRY(fx_scene_end(sc));
    TRY(fx_scene_surface(sc));
    if (k < 1 || k > 6 || scale < 1 || scale > 64)
        return fx_scene_error(sc, "vsdoctree: K 1..6, SCALE 1..64");
    int32_t n = (int32_t)1 << k, nodes = 0;
    uint8_t *vox = fx_scene_alloc(sc, (size_t)n * (size_t)n * (size_t)n);
    if (!vox)
        return fx_scene_error(sc, "vsdoctree: out of scene memory");
    fx_vsd_demo_solid(vox, k);
    int32_t visited;
    TRY(visited = fx_scene_octree_draw(sc, vox, k, scale, 0, 0, &nodes));
    if (sc->ctx.trace)
        fx_trace(&sc->ctx, "vsdoctree: %d nodes, %d visited front to back (the rest hidden)", nodes, visited);
    return 0;
}

#define D FX_SCENE_DRAWS
const fx_scene_cmd fx_scene_cmds_vsd[] = {
    {"vsdscene", cmd_vsdscene, "vsdscene N", 0},
    {"vsdpoly", cmd_vsdpoly, "vsdpoly #RGB X Y Z X Y Z X Y Z ...", 0},
    {"vsdcull", cmd_vsdcull, "vsdcull on|off", 0},
    {"vsdclear", cmd_vsdclear, "vsdclear", 0},
    {"vsdoctree", cmd_vsdoctree, "vsdoctree K SCALE", D},
    {"vsd", cmd_vsd, "vsd zbuffer|painter|newell|bsp|scanline|warnock|raycast|abuffer [ROW]", D | FX_SCENE_SERIAL},
    {0, 0, 0, 0},
};
