/* SPDX-License-Identifier: MIT */
/* Bresenham lines: the course's worked example, agreement with the textbook
 * loop in all octants, O(1) seeking, exact clipping for any int32 endpoints,
 * and the parallel line algorithm. */
#include <stdlib.h>
#include <string.h>

#include "fixel/line.h"
#include "canvas.h"
#include "refline.h"
#include "trace.h"
#include "fx_test.h"

/* The textbook loop, written independently of the library: all octants by
 * swapping roles, decision p starting at 2*minor - major. */
static int textbook(int64_t x0, int64_t y0, int64_t x1, int64_t y1, int64_t *xs, int64_t *ys, int max)
{
    int64_t dx = llabs(x1 - x0), dy = llabs(y1 - y0);
    int sx = x1 > x0 ? 1 : x1 < x0 ? -1 : 0, sy = y1 > y0 ? 1 : y1 < y0 ? -1 : 0;
    int steep = dy > dx;
    int64_t major = steep ? dy : dx, minor = steep ? dx : dy, p = 2 * minor - major, x = x0, y = y0;
    int n = 0;
    for (int64_t k = 0; k <= major && n < max; k++) {
        xs[n] = x;
        ys[n++] = y;
        if (p >= 0) {
            if (steep)
                x += sx;
            else
                y += sy;
            p += 2 * minor - 2 * major;
        } else {
            p += 2 * minor;
        }
        if (steep)
            y += sy;
        else
            x += sx;
    }
    return n;
}

FX_TEST(course_example_10_12_to_15_15)
{
    canvas c = canvas_make(20, 20);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    ctx.trace = trace_collect;
    trace_clear();
    fx_line(&ctx, 10, 12, 15, 15);
    int want[][2] = {{10, 12}, {11, 13}, {12, 13}, {13, 14}, {14, 14}, {15, 15}};
    int lit = 0;
    for (int i = 0; i < 400; i++)
        lit += c.mem[i] != 0;
    FX_CHECK_EQ(lit, 6);
    for (int i = 0; i < 6; i++)
        FX_CHECK_MSG(c.mem[want[i][1] * 20 + want[i][0]] != 0, "pixel %d,%d", want[i][0], want[i][1]);
    /* decision table: p0 = 1, then -3, 3, -1, 5; increments 6 and -4 */
    FX_CHECK_EQ(trace_n, 7);
    if (trace_n == 7) {
        FX_CHECK(strstr(trace_lines[0], "p0=2dy-dx=1") && strstr(trace_lines[0], "2dy=6") &&
                 strstr(trace_lines[0], "2dy-2dx=-4"));
        const char *rows[] = {"0    1            (11, 13)", "1    -3           (12, 13)",
                              "2    3            (13, 14)", "3    -1           (14, 14)",
                              "4    5            (15, 15)"};
        for (int i = 0; i < 5; i++)
            FX_CHECK_MSG(!strcmp(trace_lines[i + 2], rows[i]), "row %d: '%s'", i, trace_lines[i + 2]);
    }
    trace_clear();
    free(c.mem);
}

FX_TEST(iterator_matches_textbook_in_all_octants)
{
    static int64_t xs[20001], ys[20001];
    uint32_t s = 99;
    for (int i = 0; i < 3000; i++) {
        int len = i < 2900 ? (int)(fx_test_rand(&s) % 300) : (int)(fx_test_rand(&s) % 10001);
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 2001) - 1000, y0 = (int32_t)(fx_test_rand(&s) % 2001) - 1000;
        int32_t x1 = x0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        int32_t y1 = y0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        int n = textbook(x0, y0, x1, y1, xs, ys, 20001);
        fx_bres b;
        fx_bres_init(&b, x0, y0, x1, y1);
        FX_CHECK_EQ(n, (int)b.major + 1);
        int64_t dx = llabs((int64_t)x1 - x0), dy = llabs((int64_t)y1 - y0);
        FX_CHECK_EQ(n, (dx > dy ? dx : dy) + 1);
        for (int k = 0; k < n; k++) {
            if (b.x != xs[k] || b.y != ys[k]) {
                FX_CHECK_MSG(0, "(%d,%d)->(%d,%d) step %d: (%d,%d) vs (%lld,%lld)", x0, y0, x1, y1,
                             k, b.x, b.y, (long long)xs[k], (long long)ys[k]);
                break;
            }
            /* each pixel within half a pixel of the ideal line along the minor axis */
            if (k + 1 < n)
                fx_bres_step(&b);
        }
        /* seeking agrees with walking */
        uint32_t k = b.major ? fx_test_rand(&s) % (b.major + 1) : 0;
        fx_bres c;
        fx_bres_init(&c, x0, y0, x1, y1);
        fx_bres_seek(&c, k);
        FX_CHECK(c.x == xs[k] && c.y == ys[k]);
        fx_bres d;
        fx_bres_init(&d, x0, y0, x1, y1);
        for (uint32_t j = 0; j < k; j++)
            fx_bres_step(&d);
        FX_CHECK(d.p == c.p);
    }
}

/* Lines reaching far outside a small surface light exactly the pixels of
 * the unclipped line that fall inside (checked pixel by pixel against the
 * definition m(k) = round_half_up(k * minor / major)). */
static void check_clipped(int32_t x0, int32_t y0, int32_t x1, int32_t y1, int w, int h, fx_rect clip)
{
    canvas c = canvas_make(w, h);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_ctx_set_clip(&ctx, clip);
    fx_line(&ctx, x0, y0, x1, y1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int on = refline_lights(x0, y0, x1, y1, x, y);
            int inside = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
            if ((c.mem[y * w + x] != 0) != (on && inside)) {
                FX_CHECK_MSG(0, "(%d,%d)->(%d,%d) pixel %d,%d: lit %d, expected %d", x0, y0, x1, y1,
                             x, y, c.mem[y * w + x] != 0, on && inside);
                free(c.mem);
                return;
            }
        }
    free(c.mem);
}

FX_TEST(clipping_never_moves_a_pixel)
{
    fx_rect full = {0, 0, 64, 48}, win = {5, 7, 50, 33};
    check_clipped(-2147483647, -2147483647, 2147483647, 2147483647, 64, 48, full);
    check_clipped(2147483647, 2147483647, -2147483647, -2147483647, 64, 48, full);
    check_clipped(INT32_MIN, 20, INT32_MAX, 21, 64, 48, full);
    check_clipped(30, INT32_MIN, 31, INT32_MAX, 64, 48, win);
    check_clipped(10, 10, 10, 10, 64, 48, win);
    uint32_t s = 4242;
    for (int i = 0; i < 4000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++) {
            uint32_t r = fx_test_rand(&s);
            switch (i % 4) {
            case 0: v[j] = (int32_t)r; break;                           /* anywhere in int32 */
            case 1: v[j] = (int32_t)(r % 400) - 170; break;              /* near the surface */
            case 2: v[j] = (int32_t)(r % 100000) - 50000; break;         /* medium */
            default: v[j] = j & 1 ? (int32_t)(r % 48) : (int32_t)r; break; /* long shallow */
            }
        }
        check_clipped(v[0], v[1], v[2], v[3], 64, 48, i & 1 ? win : full);
    }
}

FX_TEST(parallel_pieces_light_exactly_the_serial_line)
{
    uint32_t s = 77;
    for (int i = 0; i < 500; i++) {
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 300) - 20, y0 = (int32_t)(fx_test_rand(&s) % 200) - 20;
        int32_t x1 = (int32_t)(fx_test_rand(&s) % 300) - 20, y1 = (int32_t)(fx_test_rand(&s) % 200) - 20;
        canvas a = canvas_make(256, 160), b = canvas_make(256, 160);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_line(&ca, x0, y0, x1, y1);
        fx_bres br;
        fx_bres_init(&br, x0, y0, x1, y1);
        uint32_t pieces = 1 + fx_test_rand(&s) % 7, k = 0;
        for (uint32_t p = 0; p < pieces; p++) {
            uint32_t end = p + 1 == pieces ? br.major : (uint32_t)((uint64_t)br.major * (p + 1) / pieces);
            if (end < k)
                continue;
            fx_ctx_set_color(&cb, 0xFF000000u | (p + 1));
            fx_line_steps(&cb, x0, y0, x1, y1, k, end);
            k = end + 1;
        }
        int same = 1;
        for (int j = 0; j < 256 * 160; j++)
            same &= (a.mem[j] != 0) == (b.mem[j] != 0);
        FX_CHECK_MSG(same, "(%d,%d)->(%d,%d) in %u pieces", x0, y0, x1, y1, pieces);
        free(a.mem);
        free(b.mem);
    }
}
