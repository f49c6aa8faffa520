/* SPDX-License-Identifier: MIT */
/* The scene-script interpreter: tokens, comments versus colours, strings,
 * fixed-point arguments, errors with line and column, arena. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/mesh.h"
#include "fixel/render3d.h"
#include "fixel/scene.h"
#include "fx_test.h"
#include "scenebuf.h"

static uint32_t mem[64 * 64];
static scene_buf buf = {mem, 64 * 64};

static int run(fx_scene *sc, const char *text)
{
    static uint8_t arena[4096];
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(sc, &h, arena, sizeof arena);
    return fx_scene_run(sc, text, strlen(text));
}

FX_TEST(scene_draws_and_ignores_comments)
{
    fx_scene sc;
    FX_CHECK_EQ(run(&sc, "size 8 4   # small\n# whole-line comment\r\nclear #102030 # note\n"
                         "color #80FF0000\n\n   pixel 1 2\nfillrect 6 0 5 5 #deadbeef trailing comment? no\n"),
                -FX_EINVAL);
    FX_CHECK_EQ(sc.err_line, 7);
    FX_CHECK_MSG(strstr(sc.err, "unexpected argument '#deadbeef'") != NULL, "%s", sc.err);
    FX_CHECK_EQ(run(&sc, "size 8 4   # small\nclear #102030 # note\ncolor #80FF0000\npixel 1 2\n"
                         "fillrect 6 0 5 5 # fade"),
                0);
    FX_CHECK_EQ(sc.w, 8);
    FX_CHECK_EQ_HEX(mem[0], 0x102030);
    FX_CHECK_EQ_HEX(mem[2 * 8 + 1], 0xFF0000); /* alpha ignored in SRC mode, X byte 0 */
    FX_CHECK_EQ_HEX(mem[3 * 8 + 7], 0xFF0000);
}

FX_TEST(scene_reports_line_and_column)
{
    fx_scene sc;
    FX_CHECK_EQ(run(&sc, "size 8 8\n  line 1 2 x 4\n"), -FX_EINVAL);
    FX_CHECK_EQ(sc.err_line, 2);
    FX_CHECK_EQ(sc.err_col, 12);
    FX_CHECK(!strcmp(sc.err, "expected an integer, got 'x'"));
    FX_CHECK_EQ(run(&sc, "size 100 100\n"), -FX_EINVAL); /* host refuses the surface */
    FX_CHECK(strstr(sc.err, "cannot create a 100x100 XRGB8888 surface") != NULL);
}

static int cmd_probe_result;
static fx16 probe_fx;
static fx56 probe_56;
static char probe_str[32];
static int probe(fx_scene *sc)
{
    static const char *const modes[] = {"alpha", "beta", NULL};
    int r;
    if ((r = fx_scene_arg_fx16(sc, &probe_fx)) < 0 || (r = fx_scene_arg_fx56(sc, &probe_56)) < 0 ||
        (r = fx_scene_arg_string(sc, probe_str, sizeof probe_str)) < 0 ||
        (r = fx_scene_arg_choice(sc, modes)) < 0)
        return r;
    cmd_probe_result = r;
    return fx_scene_end(sc);
}

FX_TEST(scene_argument_helpers)
{
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    uint8_t arena[256];
    fx_scene_init(&sc, &h, arena, sizeof arena);
    const fx_scene_cmd cmd = {"probe", probe, "probe", 0};
    const char *line = "probe -5.5 -0.75 \"a \\\"q\\\" b\" beta";
    sc.text = line;
    sc.len = (int)strlen(line);
    sc.pos = 5;
    FX_CHECK_EQ(cmd.run(&sc), 0);
    FX_CHECK_EQ(probe_fx, -360448);
    FX_CHECK_EQ(probe_56, -(3 * (FX56_ONE / 4)));
    FX_CHECK(!strcmp(probe_str, "a \"q\" b"));
    FX_CHECK_EQ(cmd_probe_result, 1);
    line = "probe 1 2 \"s\" gamma";
    sc.text = line;
    sc.len = (int)strlen(line);
    sc.pos = 5;
    FX_CHECK_EQ(cmd.run(&sc), -FX_EINVAL);
    FX_CHECK(!strcmp(sc.err, "expected one of alpha|beta, got 'gamma'"));
    /* arena: aligned, zeroed, bounded */
    void *a = fx_scene_alloc(&sc, 10), *b = fx_scene_alloc(&sc, 8);
    FX_CHECK(a && b && ((uintptr_t)b & 7) == 0 && (uint8_t *)b - (uint8_t *)a == 16);
    FX_CHECK(fx_scene_alloc(&sc, 1000) == NULL);
}

FX_TEST(scene_command_names_with_nul_bytes)
{
    /* found by fuzz_scene: a NUL inside a command word read past the name */
    fx_scene sc;
    static const char text[] = "size 8 8\nline\0xyz 1 2 3 4\n";
    static uint8_t arena[256];
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, arena, sizeof arena);
    FX_CHECK_EQ(fx_scene_run(&sc, text, sizeof text - 1), -FX_EINVAL);
    FX_CHECK_EQ(sc.err_line, 2);
}

/* A mesh too big for the arena fails alone: the next, smaller mesh is
 * built in the block the earlier one left (the failed allocation used to
 * leave a NULL block with the old size, and the next mesh wrote through it;
 * found by fuzz_grammar). */
FX_TEST(scene_mesh_after_a_failed_allocation)
{
    static uint8_t arena[96 << 10];
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, arena, sizeof arena);
    static const char *const lines[] = {"size 16 16", "cube 1", "sphere 1 256 256", "cube 1", "octahedron 1"};
    static const int want[] = {0, 0, -FX_ENOMEM, 0, 0};
    for (int i = 0; i < 5; i++) {
        int r = fx_scene_exec_line(&sc, lines[i], strlen(lines[i]), i + 1);
        FX_CHECK_MSG(want[i] ? r < 0 : r == 0, "line %d '%s': %d %s", i + 1, lines[i], r, sc.err);
        if (want[i])
            FX_CHECK_MSG(strstr(sc.err, "out of scene memory") != NULL, "%s", sc.err);
    }
}

/* The painter draws its triangles at flush time: a texture switched off (or
 * changed) after a mesh was emitted must not reach them (it was read then,
 * through a NULL texture: found in review). The picture equals the one
 * flushed before the switch. */
FX_TEST(scene_painter_keeps_the_texture_of_each_triangle)
{
    static const char *const head = "size 48 48\nclear #102030\nperspective 40 0.5 50\ncamera 0 0 5 0 0 0 0 1 0\npainter 256\n"
                                    "texture checker 8 8 2 #000000 #FFFFFF\ntexture3d modulate\n"
                                    "solid3d marble #202020 #E0E0E0 1\ncube 1\n";
    static uint8_t arena[1 << 20];
    static uint32_t want[48 * 48];
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    char text[512];
    snprintf(text, sizeof text, "%sflush\ntexture3d off\nsolid3d off\n", head);
    fx_scene_init(&sc, &h, arena, sizeof arena);
    FX_CHECK_MSG(fx_scene_run(&sc, text, strlen(text)) == 0, "%d: %s", sc.err_line, sc.err);
    memcpy(want, mem, sizeof want);
    int lit = 0;
    for (int i = 0; i < 48 * 48; i++)
        lit += (want[i] & 0xFFFFFF) != 0x102030;
    FX_CHECK_MSG(lit > 40, "%d", lit); /* the cube is there */
    snprintf(text, sizeof text, "%stexture3d off\nsolid3d off\nflush\n", head);
    fx_scene_init(&sc, &h, arena, sizeof arena);
    FX_CHECK_MSG(fx_scene_run(&sc, text, strlen(text)) == 0, "%d: %s", sc.err_line, sc.err);
    FX_CHECK(memcmp(want, mem, sizeof want) == 0);
}

/* ---- the vertex cache of fx_scene_mesh_draw: scratch from the arena ---- */

static uint64_t cache_arena[(1 << 20) / 8];

static int run_in(fx_scene *sc, void *arena, size_t size, const char *text)
{
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(sc, &h, arena, size);
    return fx_scene_run(sc, text, strlen(text));
}

/* Whether the free arena past `used` was written (the cache was there):
 * the arena is filled with 0xA5 before the run. */
static int arena_touched(const fx_scene *sc, size_t used, size_t bytes)
{
    const uint8_t *a = sc->arena;
    for (size_t i = used; i < used + bytes && i < sc->arena_size; i++)
        if (a[i] != 0xA5)
            return 1;
    return 0;
}

/* Many mesh draws: each takes its cache from the free arena and gives it
 * back (the arena in use is the same after every draw of a mesh of one
 * size), so in an arena just big enough without the cache the last,
 * bigger mesh still finds room for its block (a cache kept would have
 * taken it: the first sphere's cache fits in what the last mesh needs). */
FX_TEST(scene_mesh_draws_give_the_vertex_cache_back)
{
    static const char *const head[] = {"size 48 48", "depth 32", "perspective 40 0.5 50",
                                       "camera 0 0 8 0 0 0 0 1 0"};
    static char text[2048];
    static uint32_t want[64 * 64];
    fx_scene sc;
    int32_t nv_small, nt;
    fx_mesh_params ps = {FX_MESH_SPHERE, FX16_ONE, 0, 0, 24, 16};
    FX_CHECK_EQ(fx_mesh_size(&ps, &nv_small, &nt), 0);
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    memset(cache_arena, 0xA5, sizeof cache_arena);
    fx_scene_init(&sc, &h, cache_arena, sizeof cache_arena);
    text[0] = 0;
    int n = 0;
    for (int i = 0; i < 4; i++) {
        FX_CHECK_EQ(fx_scene_exec_line(&sc, head[i], strlen(head[i]), ++n), 0);
        strcat(strcat(text, head[i]), "\n");
    }
    size_t first = 0;
    for (int i = 0; i < 13; i++) {
        const char *l = i == 12 ? "sphere 1 32 24"
                        : i & 1 ? "translate3d 0.1 0 0"
                                : "sphere 1 24 16";
        FX_CHECK_MSG(fx_scene_exec_line(&sc, l, strlen(l), ++n) == 0, "%s: %s", l, sc.err);
        strcat(strcat(text, l), "\n");
        if (i == 0)
            first = sc.arena_used;
        else if (i < 12)
            FX_CHECK_MSG(sc.arena_used == first,
                         "after line %d '%s': %zu bytes in use, %zu after the first sphere", n, l,
                         sc.arena_used, first);
    }
    size_t need = sc.arena_used;
    FX_CHECK(arena_touched(&sc, need, 64)); /* the last draw had its cache */
    memcpy(want, mem, sizeof want);
    int lit = 0;
    for (int i = 0; i < 48 * 48; i++)
        lit += (mem[i] & 0xFFFFFF) != 0;
    FX_CHECK_MSG(lit > 200, "%d", lit);
    FX_CHECK_MSG(fx3d_vertex_cache_bytes(nv_small) + 8 <= need - first, "cache %zu, free %zu",
                 fx3d_vertex_cache_bytes(nv_small), need - first);
    memset(mem, 0, sizeof mem);
    FX_CHECK_MSG(run_in(&sc, cache_arena, need, text) == 0, "%d: %s", sc.err_line, sc.err);
    FX_CHECK_EQ(sc.arena_used, need);
    FX_CHECK(memcmp(want, mem, sizeof want) == 0);
}

/* A Gouraud teapot drawn with the cache (room in the arena) and without it
 * (an arena just big enough for the rest): the same picture. (Memory off
 * the cache's alignment is render3d_vertex_cache_keeps_the_pixels's: an
 * arena off 8 bytes misaligns the scene's own state too.) */
FX_TEST(scene_teapot_pixels_with_and_without_the_vertex_cache)
{
    static const char text[] = "size 64 64\ndepth 32\nshading gouraud\ncull none\n"
                               "perspective 40 0.5 50\n"
                               "camera 0 2 6 0 0 0 0 1 0\nlight 0 directional 1 1 1 #FFFFFF\n"
                               "light 1 point -3 2 2 #4060FF\nambient #202020\n"
                               "material #C04020 #C04020 #FFFFFF 40\nteapot 1 6\n";
    static uint32_t want[64 * 64];
    fx_scene sc;
    memset(cache_arena, 0xA5, sizeof cache_arena);
    FX_CHECK_MSG(run_in(&sc, cache_arena, sizeof cache_arena, text) == 0, "%d: %s", sc.err_line,
                 sc.err);
    size_t need = sc.arena_used;
    FX_CHECK(arena_touched(&sc, need, 64));
    memcpy(want, mem, sizeof want);
    int lit = 0;
    for (int i = 0; i < 64 * 64; i++)
        lit += (mem[i] & 0xFFFFFF) != 0;
    FX_CHECK_MSG(lit > 800, "%d", lit);
    memset(mem, 0, sizeof mem);
    FX_CHECK_MSG(run_in(&sc, cache_arena, need, text) == 0, "%d: %s", sc.err_line, sc.err);
    FX_CHECK(memcmp(want, mem, sizeof want) == 0);
}

/* An arena of any alignment: the scene starts it at the first 8-byte
 * boundary and keeps whole 8-byte units (module state holds 64-bit fields;
 * it used to start at the caller's pointer, which UBSan reported as
 * misaligned accesses), and draws the same picture as from an aligned one. */
FX_TEST(scene_arena_of_any_alignment)
{
    static const char *text = "size 48 48\ndepth 32\nperspective 40 0.5 50\ncamera 0 0 8 0 0 0 0 1 0\n"
                              "shading gouraud\nlight 0 directional 1 1 1 #FFFFFF\nsphere 2 12 8\n";
    static uint32_t want[48 * 48];
    fx_scene sc;
    FX_CHECK_EQ(run_in(&sc, cache_arena, sizeof cache_arena, text), 0);
    memcpy(want, mem, sizeof want);
    int lit = 0;
    for (size_t i = 0; i < 48 * 48; i++)
        lit += want[i] != want[0];
    FX_CHECK(lit > 100); /* the sphere is there to compare */
    for (size_t off = 1; off < 8; off++) {
        uint8_t *a = (uint8_t *)cache_arena + off;
        size_t size = sizeof cache_arena - off - 3;
        memset(mem, 0, sizeof mem);
        FX_CHECK_EQ(run_in(&sc, a, size, text), 0);
        FX_CHECK_EQ((uintptr_t)sc.arena % 8, 0u);
        FX_CHECK_EQ(sc.arena_size % 8, 0u);
        FX_CHECK(sc.arena >= a && sc.arena + sc.arena_size <= a + size);
        FX_CHECK(memcmp(want, mem, sizeof want) == 0);
    }
    /* fewer bytes than reach the boundary: no arena, not a wrapped size */
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, (uint8_t *)cache_arena + 1, 5);
    FX_CHECK(sc.arena == NULL);
    FX_CHECK_EQ(sc.arena_size, 0u);
}
