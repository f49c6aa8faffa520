/* SPDX-License-Identifier: MIT */
/* fixel-demo's "objects" page: the course's remaining objects
 * (fixel/objects.h, docs/OBJECTS.md) each drawn by a few scene-script
 * lines, the same commands fixel-draw runs, into its own cell of the page:
 * the quadrics, superquadrics, blobby objects, Bezier and B-spline
 * patches (with polygon-table back-face culling) and an octree of voxels. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/scene.h"

#define OBJ_PANEL 0xFF18263Au

/* The lights and camera every cell shares; a cell adds its objects. */
#define COMMON                                                                                          \
    "clear #18263A\ndepth 32\nperspective 35 0.5 50\nlight 0 directional 1 2 2 #D0D0D0\n"             \
    "light 1 point -4 5 6 #806040\nambient #202020\n"

#define CTRL                                                                                             \
    "-1.5 0 -1.5 -0.5 0.3 -1.5 0.5 0.3 -1.5 1.5 0 -1.5 -1.5 0.3 -0.5 -0.5 1.8 -0.5 0.5 1.8 -0.5 1.5 0.3 " \
    "-0.5 -1.5 0.3 0.5 -0.5 1.8 0.5 0.5 1.8 0.5 1.5 0.3 0.5 -1.5 0 1.5 -0.5 0.3 1.5 0.5 0.3 1.5 1.5 0 1.5"

static const struct {
    const char *label;
    const char *script;
} cells[8] = {
    {"Paraboloid",
     COMMON "camera 0 3 7 0 0.4 0 0 1 0\nshading phong\nrotatex 20\nrotatey FRAME\n"
            "material #C05030 #C05030 #FFFFFF 40\nparaboloid 1.2 0.9 2 32 16\n"},
    {"Hyperboloid, one sheet",
     COMMON "camera 0 3 7 0 0 0 0 1 0\nshading phong\nrotatex 15\nrotatey FRAME\n"
            "material #30A060 #30A060 #FFFFFF 40\nhyperboloid 1 0.6 0.6 0.5 1.3 32 16\n"},
    {"Hyperboloid, two sheets",
     COMMON "camera 0 3 7 0 0 0 0 1 0\nshading phong\nrotatey FRAME\nrotatez 90\n"
            "material #4070D0 #4070D0 #FFFFFF 40\nhyperboloid 2 0.6 0.6 0.4 1.3 32 12\n"},
    {"Superellipsoids",
     COMMON "camera 0 3 8 0 0 0 0 1 0\nshading gouraud\nmaterial #C08030 #C08030 #FFFFFF 50\n"
            "push3d\ntranslate3d -1.2 0.9 0\nrotatey FRAME\nrotatex 20\nsuperellipsoid 0.8 0.8 0.8 0.2 0.2 32 24\npop3d\n"
            "push3d\ntranslate3d 1.2 0.9 0\nrotatey FRAME\nsuperellipsoid 0.9 0.9 0.9 2 2 32 24\npop3d\n"
            "push3d\ntranslate3d 0 -1.1 0\nrotatey FRAME\nrotatex 30\nsuperellipsoid 1 0.8 0.7 0.5 1.5 32 24\npop3d\n"},
    {"Supertoroid",
     COMMON "camera 0 4 7 0 0 0 0 1 0\nshading gouraud\nrotatey FRAME\nrotatex 20\n"
            "material #5080D0 #5080D0 #FFFFFF 50\nsupertoroid 1.5 0.6 0.3 1.5 48 32\n"},
    {"Blobby object (metaballs)",
     COMMON "camera 0 2 8 0 0 0 0 1 0\nshading gouraud\nrotatey FRAME\nmaterial #D04060 #D04060 #FFFFFF 60\n"
            "blobball -0.6 0 0 1.3 1\nblobball 0.6 0.4 0 1.1 1\nblobball 0 -0.6 0.5 1 1\nblobball 0.3 1.0 -0.3 0.9 1\n"
            "blobball 0 0 1.2 0.8 -1.2\nblobby 0.5 -2 -2 -1.8 0.1 40 40 36\n"},
    {"Bezier patch, table culling",
     COMMON "camera 0 6 5 0 0.5 0 0 1 0\nshading phong\nptabcull on\nrotatey FRAME\n"
            "material #C0A040 #C0A040 #FFFFFF 40\npatch bezier 12 " CTRL "\n"
            "polymode wire\nmaterial #000000 #000000 #000000 1 #FFFFFF\ntranslate3d 0 0.01 0\npatch bezier 3 " CTRL "\n"},
    {"Octree of voxels (blob)",
     "clear #18263A\nblobball -0.8 -0.3 0 1.4 1\nblobball 0.7 -0.2 0.3 1.3 1\nblobball 0 0.8 -0.2 1.2 1\n"
     "octree blob 0.5 5 5 12 20 -2 -2 -2 4\n"},
};

typedef struct cell_host {
    fx_surface sub;
} cell_host;

static int cell_surface(void *user, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    cell_host *ch = user;
    (void)w;
    (void)h;
    (void)f;
    *out = ch->sub;
    return 0;
}

/* The script with FRAME replaced by the turn (degrees) for this frame. */
static void expand(char *out, size_t size, const char *s, int deg)
{
    size_t o = 0;
    while (*s && o + 8 < size) {
        if (!strncmp(s, "FRAME", 5)) {
            o += (size_t)snprintf(out + o, size - o, "%d", deg);
            s += 5;
        } else {
            out[o++] = *s++;
        }
    }
    out[o] = 0;
}

void demo_objects_page(fx_ctx *c, demo_state *st, int32_t top)
{
    /* the cells' depth buffers and meshes, reused cell after cell */
    const size_t arena_size = 8u << 20;
    uint8_t *arena = malloc(arena_size);
    int32_t cw = 192, chh = 216;
    for (int i = 0; i < 8; i++) {
        int32_t x = 8 + (i % 4) * (cw + 4), y = top + (i / 4) * (chh + 12);
        fx_ctx_set_color(c, OBJ_PANEL);
        fx_fill_rect(c, x, y, cw, chh);
        fx_ctx_set_color(c, 0xFF2E4A6Bu);
        fx_rect_outline(c, x, y, cw, chh);
        fx_rect cell = {x + 1, y + 18, x + cw - 1, y + chh - 1};
        if (arena) {
            cell_host ch = {fx_surface_sub(c->surf, cell)};
            fx_scene_host host;
            memset(&host, 0, sizeof host);
            host.user = &ch;
            host.make_surface = cell_surface;
            fx_scene sc;
            fx_scene_init(&sc, &host, arena, arena_size);
            fx_scene_fix_size(&sc, ch.sub.w, ch.sub.h);
            fx_scene_fix_format(&sc, c->surf.format);
            char text[2048];
            expand(text, sizeof text, cells[i].script, 30 + (int)(st->frame % 360) * 4);
            if (fx_scene_run(&sc, text, strlen(text)) < 0)
                demo_text(c, x + 6, y + 40, 0xFFE15554u, "line %d: %.20s", sc.err_line, sc.err);
        }
        demo_text(c, x + 6, y + 5, 0xFFF2C14Eu, "%s", cells[i].label);
    }
    free(arena);
}
