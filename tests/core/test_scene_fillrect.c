/* SPDX-License-Identifier: MIT */
/* fillrect with a fill style (issue #23: it ignored pattern, gradient and
 * texture styles that fillpoly honours): every rectangle, on and off the
 * surface, is pixel-for-pixel the fillpolyf of its pixel-edge outline, and
 * a style that changes the picture of fillpoly changes fillrect's too. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "fx_test.h"
#include "scenebuf.h"

static uint32_t mem_a[64 * 48], mem_b[64 * 48], mem_c[64 * 48];

static int render(uint32_t *mem, const char *style, const char *draw)
{
    static uint8_t arena[1 << 20];
    char text[1024];
    scene_buf buf = {mem, 64 * 48};
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene sc;
    fx_scene_init(&sc, &h, arena, sizeof arena);
    snprintf(text, sizeof text, "size 64 48\nclear #203040\ncolor #FFD000\n%s\n%s\n", style, draw);
    int r = fx_scene_run(&sc, text, strlen(text));
    if (r < 0)
        fprintf(stderr, "  %d: %s\n", sc.err_line, sc.err);
    return r;
}

FX_TEST(fillrect_styles_match_fillpoly)
{
    static const char *const styles[] = {
        "pattern 8 8 88 44 22 11 88 44 22 11\npattern bg #402000",
        "pattern 4 4 F0 F0 0F 0F\npattern bg none\npattern anchor 1 2",
        "gradient linear 0 0 63 0 #FF0000 #FFFF00 #0000FF",
        "gradient radial 20 20 15 #FFFFFF #008000",
        "blend over\npattern 2 2 80 40\npattern bg #80FF0000",
    };
    static const int32_t rects[][4] = {
        {4, 4, 40, 30}, {0, 0, 64, 48}, {-10, -7, 30, 20}, {50, 40, 100, 100}, {-2000000000, 5, 2000000030, 10},
        {10, 10, 1, 1}, {63, 47, 1, 1},
    };
    for (size_t s = 0; s < sizeof styles / sizeof styles[0]; s++)
        for (size_t k = 0; k < sizeof rects / sizeof rects[0]; k++) {
            const int32_t *q = rects[k];
            char a[128], b[256];
            snprintf(a, sizeof a, "fillrect %d %d %d %d", q[0], q[1], q[2], q[3]);
            /* pixel-edge outline, in Q16.16 text: centres x..x+w-1 */
            double x0 = q[0] - 0.5, y0 = q[1] - 0.5, x1 = (double)q[0] + q[2] - 0.5, y1 = (double)q[1] + q[3] - 0.5;
            if (x0 < -32000) /* fillpolyf takes +-32767: the clip makes them equal */
                x0 = -32000;
            if (x1 > 32000)
                x1 = 32000;
            snprintf(b, sizeof b, "fillpolyf evenodd %.1f %.1f %.1f %.1f %.1f %.1f %.1f %.1f", x0, y0, x1, y0, x1, y1,
                     x0, y1);
            FX_CHECK(render(mem_a, styles[s], a) == 0);
            FX_CHECK(render(mem_b, styles[s], b) == 0);
            FX_CHECK_MSG(!memcmp(mem_a, mem_b, sizeof mem_a), "style %zu, %s", s, a);
            /* and the style shows: the solid rectangle is another picture
             * (a single pixel may fall on a set pattern bit) */
            FX_CHECK(render(mem_c, "", a) == 0);
            if (q[2] > 1)
                FX_CHECK_MSG(memcmp(mem_a, mem_c, sizeof mem_a) != 0, "style %zu made no difference to %s", s, a);
        }
}

FX_TEST(fillrect_styled_empty_and_negative_draw_nothing)
{
    FX_CHECK(render(mem_c, "", "") == 0);
    static const char *const draws[] = {"fillrect 5 5 0 10", "fillrect 5 5 10 0", "fillrect 5 5 -3 10",
                                        "fillrect 100 100 10 10", "fillrect 5 -2147483648 10 10"};
    for (size_t k = 0; k < sizeof draws / sizeof draws[0]; k++) {
        FX_CHECK(render(mem_a, "gradient linear 0 0 63 0 #FF0000 #0000FF", draws[k]) == 0);
        FX_CHECK_MSG(!memcmp(mem_a, mem_c, sizeof mem_a), "%s drew", draws[k]);
    }
}
