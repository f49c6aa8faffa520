/* SPDX-License-Identifier: MIT */
/* The clip module's scene commands: inclusive clip windows and their stack,
 * the clipper choice, exterior clipping, the transform stack acting on the
 * foundation's commands, window-to-viewport, and their error messages. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/scene.h"
#include "fx_test.h"
#include "scenebuf.h"

static uint32_t mem[32 * 32];
static scene_buf buf = {mem, 32 * 32};

static fx_scene sc;
static int run(const char *text)
{
    static uint64_t arena[1024];
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, arena, sizeof arena);
    return fx_scene_run(&sc, text, strlen(text));
}

static int lit(int x, int y) { return mem[y * 32 + x] != 0; }
static int count(void)
{
    int n = 0;
    for (int i = 0; i < 32 * 32; i++)
        n += mem[i] != 0;
    return n;
}

FX_TEST(scene_clip_windows_are_inclusive_and_nest)
{
    FX_CHECK_EQ(run("size 32 32\nclip 4 5 10 8\nfillrect 0 0 32 32\n"), 0);
    FX_CHECK_EQ(count(), 7 * 4);
    FX_CHECK(lit(4, 5) && lit(10, 8) && !lit(11, 8) && !lit(10, 9));
    /* corners in either order; push intersects, pop restores */
    FX_CHECK_EQ(run("size 32 32\nclip 20 20 0 0\nclip push 10 10 30 30\nfillrect 0 0 32 32\nclip pop\n"
                    "color #FF0000\nline 0 31 31 31\nclip off\nline 0 31 31 31\n"),
                0);
    FX_CHECK(lit(10, 10) && lit(20, 20) && !lit(9, 10) && !lit(21, 20));
    FX_CHECK_EQ(count(), 11 * 11 + 32);
    FX_CHECK_EQ(run("size 32 32\nclip pop\n"), -FX_EINVAL);
    FX_CHECK(strstr(sc.err, "without a matching 'clip push'") != NULL);
}

FX_TEST(scene_cliplines_choice_keeps_the_pixels)
{
    static uint32_t ref[32 * 32];
    const char *algos[] = {"direct", "cohen", "liang", "nln"};
    for (int a = 0; a < 4; a++) {
        char script[256];
        snprintf(script, sizeof script,
                 "size 32 32\ncliplines %s\nclip 3 4 27 25\nline -100 -37 200 90\nline 15 -5000 16 5000\n"
                 "line 40 2 -9 30\n",
                 algos[a]);
        FX_CHECK_EQ(run(script), 0);
        FX_CHECK_EQ(sc.ctx.line_clipper, a);
        if (a == 0)
            memcpy(ref, mem, sizeof ref);
        else
            FX_CHECK_MSG(memcmp(ref, mem, sizeof ref) == 0, "%s differs from direct", algos[a]);
    }
    FX_CHECK(count() > 40);
    FX_CHECK_EQ(run("size 32 32\ncliplines sutherland\n"), -FX_EINVAL);
}

FX_TEST(scene_exterior_keeps_a_window_free)
{
    FX_CHECK_EQ(run("size 32 32\nexterior 8 8 15 15\nfillrect 0 0 32 32\nline 0 0 31 31\n"), 0);
    FX_CHECK_EQ(count(), 32 * 32 - 64);
    FX_CHECK(!lit(8, 8) && !lit(15, 15) && lit(7, 7) && lit(16, 16));
    FX_CHECK_EQ(run("size 32 32\nexterior 8 8 15 15\nexterior off\nfillrect 0 0 32 32\nexterior on\n"
                    "color #000000\nfillrect 0 0 32 32\n"),
                0);
    FX_CHECK_EQ(count(), 64);
    FX_CHECK_EQ(run("size 32 32\nexterior on\n"), -FX_EINVAL);
}

FX_TEST(scene_transform_stack_moves_the_foundation_commands)
{
    /* translate (5, 3): pixel, line and rect all move */
    FX_CHECK_EQ(run("size 32 32\ntranslate 5 3\npixel 1 1\nline 0 10 4 10\nrect 10 10 3 2\n"), 0);
    FX_CHECK(lit(6, 4) && !lit(1, 1));
    for (int x = 5; x <= 9; x++)
        FX_CHECK(lit(x, 13));
    FX_CHECK(lit(15, 13) && lit(17, 14) && !lit(10, 10));
    FX_CHECK_EQ(count(), 1 + 5 + 6);
    /* push/pop: the saved transform comes back; commands post-multiply, so
     * the last one acts first */
    FX_CHECK_EQ(run("size 32 32\npush\ntranslate 10 0\nrotate 90\npixel 3 0\npop\npixel 3 0\n"), 0);
    FX_CHECK(lit(10, 3) && lit(3, 0));
    FX_CHECK_EQ(count(), 2);
    /* a rotated fillrect is the rotated block of pixels */
    FX_CHECK_EQ(run("size 32 32\nrotate 90 16 16\nfillrect 18 14 6 3\n"), 0);
    FX_CHECK_EQ(count(), 18);
    FX_CHECK(lit(16, 18) && lit(18, 23) && !lit(15, 20) && !lit(18, 14));
    /* scale about a fixed point, then identity resets */
    FX_CHECK_EQ(run("size 32 32\nscale 2 3 4 4\npixel 5 5\nidentity\npixel 0 0\n"), 0);
    FX_CHECK(lit(6, 7) && lit(0, 0));
    FX_CHECK_EQ(run("size 32 32\npop\n"), -FX_EINVAL);
    FX_CHECK(strstr(sc.err, "'pop' without a matching 'push'") != NULL);
    FX_CHECK_EQ(run("size 32 32\nreflect line 1 1 1 1\n"), -FX_EINVAL);
}

FX_TEST(scene_reflect_and_shear)
{
    FX_CHECK_EQ(run("size 32 32\nreflect diagonal\npixel 3 20\nidentity\nshear x 0.5 10\npixel 4 14\n"
                    "identity\nreflect line 0 16 31 16\npixel 7 10\n"),
                0);
    FX_CHECK(lit(20, 3) && lit(6, 14) && lit(7, 22));
    FX_CHECK_EQ(count(), 3);
}

FX_TEST(scene_window_to_viewport)
{
    FX_CHECK_EQ(run("size 32 32\nwindow 0 0 1 1\nviewport 10 10 20 20\npixel 0 0\npixel 1 1\n"
                    "xpoly fill 0 0 1 0 1 1 0 1\n"),
                0);
    FX_CHECK(lit(10, 10) && lit(20, 20));
    /* the polygon covers the centres 10..20 x 10..20 minus the right and
     * bottom edges (top-left rule); the two pixels add (20, 20) */
    FX_CHECK_EQ(count(), 10 * 10 + 1);
    /* the viewport is also the clip window */
    FX_CHECK_EQ(run("size 32 32\nwindow 0 0 2 2\nviewport 10 10 20 20\nline -5 1 5 1\n"), 0);
    FX_CHECK_EQ(count(), 11);
    FX_CHECK_EQ(run("size 32 32\nviewport 0 0 5 5\n"), -FX_EINVAL);
    FX_CHECK(strstr(sc.err, "needs a world 'window' first") != NULL);
    FX_CHECK_EQ(run("size 32 32\nwindow 0 0 0 5\n"), -FX_EINVAL);
}

FX_TEST(scene_clippoly_pieces)
{
    /* a U whose base is outside the clip window: two prongs, 2 x (3 x 5) pixels */
    FX_CHECK_EQ(run("size 32 32\nclip 0 0 31 4\nclippoly wa fill 0 0 3 0 3 8 6 8 6 0 9 0 9 10 0 10\n"), 0);
    FX_CHECK_EQ(count(), 2 * 3 * 5);
    FX_CHECK(lit(0, 0) && lit(2, 4) && !lit(3, 0) && lit(6, 0) && !lit(9, 0));
    FX_CHECK_EQ(run("size 32 32\nclip 0 0 31 4\nclippoly sh fill 0 0 3 0 3 8 6 8 6 0 9 0 9 10 0 10\n"), 0);
    FX_CHECK_EQ(count(), 2 * 3 * 5);
    FX_CHECK_EQ(run("size 32 32\nclippoly wa fill 0 0 3 0\n"), -FX_EINVAL);
    FX_CHECK(strstr(sc.err, "at least 3 vertices") != NULL);
}

/* Issue #44: a clipped outline keeps its border lines on all four window
 * edges, the right and bottom ones as well as the left and top (they lie
 * half a pixel out, on the pixel squares' border, and used to round out of
 * the clip: 40 pixels in the left column, 1 in the right one). */
static int col_lit(int x, int y0, int y1)
{
    int n = 0;
    for (int y = y0; y <= y1; y++)
        n += lit(x, y);
    return n;
}
static int row_lit(int y, int x0, int x1)
{
    int n = 0;
    for (int x = x0; x <= x1; x++)
        n += lit(x, y);
    return n;
}

FX_TEST(scene_clippoly_outline_keeps_every_window_edge)
{
    const char *algo[] = {"sh", "wa"};
    for (int a = 0; a < 2; a++) {
        char s[200];
        /* the window's frame: a polygon covering it draws exactly its border */
        snprintf(s, sizeof s, "size 32 32\nclip 5 6 26 20\nclippoly %s outline -10 -10 50 -10 50 50 -10 50\n", algo[a]);
        FX_CHECK_EQ(run(s), 0);
        FX_CHECK_MSG(col_lit(5, 6, 20) == 15 && col_lit(26, 6, 20) == 15, "%s: left %d right %d", algo[a],
                     col_lit(5, 6, 20), col_lit(26, 6, 20));
        FX_CHECK_MSG(row_lit(6, 5, 26) == 22 && row_lit(20, 5, 26) == 22, "%s: top %d bottom %d", algo[a],
                     row_lit(6, 5, 26), row_lit(20, 5, 26));
        FX_CHECK_EQ(count(), 2 * 15 + 2 * 22 - 4);
        /* crossing the right edge only: the cut side is column 26, rows 8..18 */
        snprintf(s, sizeof s, "size 32 32\nclip 5 6 26 20\nclippoly %s outline 10 8 40 8 40 18 10 18\n", algo[a]);
        FX_CHECK_EQ(run(s), 0);
        FX_CHECK_MSG(col_lit(26, 8, 18) == 11 && col_lit(10, 8, 18) == 11, "%s: cut side %d", algo[a],
                     col_lit(26, 8, 18));
        FX_CHECK_EQ(count(), 2 * 11 + 2 * 17 - 4);
        /* and the bottom edge only */
        snprintf(s, sizeof s, "size 32 32\nclip 5 6 26 20\nclippoly %s outline 8 10 20 10 20 40 8 40\n", algo[a]);
        FX_CHECK_EQ(run(s), 0);
        FX_CHECK_MSG(row_lit(20, 8, 20) == 13, "%s: cut side %d", algo[a], row_lit(20, 8, 20));
        FX_CHECK_EQ(count(), 2 * 13 + 2 * 11 - 4);
    }
}
