/* SPDX-License-Identifier: MIT */
/* The fixed-point DDA: the course example, exact rounding of the ideal
 * coordinate, the documented tie difference from Bresenham, long lines,
 * exact clipping for any int32 endpoints, and the --trace table. */
#include <stdlib.h>
#include <string.h>

#include "fixel/line.h"
#include "canvas.h"
#include "trace.h"
#include "fx_test.h"

/* floor(start + k*d/M + 1/2) by exact integer arithmetic (the definition). */
static int64_t exact_round(int64_t start, int64_t d, int64_t M, int64_t k)
{
    if (!M)
        return start;
    __int128 num = (__int128)2 * k * d + M, den = 2 * (__int128)M; /* floor(num / den) */
    __int128 q = num / den;
    if (num % den && num < 0)
        q--;
    return start + (int64_t)q;
}

FX_TEST(dda_course_example)
{
    fx_dda_iter d;
    fx_dda_init(&d, 10, 12, 15, 15);
    int want[][2] = {{10, 12}, {11, 13}, {12, 13}, {13, 14}, {14, 14}, {15, 15}};
    FX_CHECK_EQ(d.major, 5);
    for (uint32_t k = 0; k <= 5; k++) {
        int32_t x, y;
        fx_dda_point(&d, k, &x, &y);
        FX_CHECK_EQ(x, want[k][0]);
        FX_CHECK_EQ(y, want[k][1]);
    }
}

FX_TEST(dda_rounds_the_ideal_coordinate_exactly)
{
    uint32_t s = 2024;
    for (int i = 0; i < 4000; i++) {
        int len = i < 3500 ? (int)(fx_test_rand(&s) % 400) : 46340;
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 200001) - 100000;
        int32_t y0 = (int32_t)(fx_test_rand(&s) % 200001) - 100000;
        int32_t x1 = x0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        int32_t y1 = y0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        fx_dda_iter d;
        fx_dda_init(&d, x0, y0, x1, y1);
        int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
        int64_t M = llabs(dx) > llabs(dy) ? llabs(dx) : llabs(dy);
        FX_CHECK_EQ(d.major, M);
        for (int t = 0; t < 64; t++) {
            int64_t k = t < 2 ? t * M : (int64_t)(fx_test_rand(&s) % (uint32_t)(M + 1));
            int32_t x, y;
            fx_dda_point(&d, (uint32_t)k, &x, &y);
            if (x != exact_round(x0, dx, M, k) || y != exact_round(y0, dy, M, k)) {
                FX_CHECK_MSG(0, "(%d,%d)->(%d,%d) k=%lld: (%d,%d) vs (%lld,%lld)", x0, y0, x1, y1,
                             (long long)k, x, y, (long long)exact_round(x0, dx, M, k),
                             (long long)exact_round(y0, dy, M, k));
                break;
            }
        }
    }
}

/* Bresenham rounds the offset from the start half up, the DDA the absolute
 * coordinate: they differ exactly at ties on lines going towards -inf on
 * the minor axis. */
FX_TEST(dda_differs_from_bresenham_only_at_negative_ties)
{
    uint32_t s = 31337;
    int diffs = 0;
    for (int i = 0; i < 3000; i++) {
        int len = (int)(fx_test_rand(&s) % 60);
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 201) - 100, y0 = (int32_t)(fx_test_rand(&s) % 201) - 100;
        int32_t x1 = x0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        int32_t y1 = y0 + (int32_t)(fx_test_rand(&s) % (2 * len + 1)) - len;
        fx_dda_iter d;
        fx_bres b;
        fx_dda_init(&d, x0, y0, x1, y1);
        fx_bres_init(&b, x0, y0, x1, y1);
        int neg = (b.ymajor ? b.sx : b.sy) < 0;
        for (uint32_t k = 0; k <= b.major; k++) {
            int32_t x, y;
            fx_dda_point(&d, k, &x, &y);
            uint64_t t2 = 2 * (uint64_t)k * b.minor;
            int tie = b.major && t2 % (2 * (uint64_t)b.major) == b.major;
            int same = x == b.x && y == b.y;
            FX_CHECK_MSG(same == !(tie && neg), "(%d,%d)->(%d,%d) k=%u", x0, y0, x1, y1, k);
            diffs += !same;
            if (!same) { /* the DDA took the pixel one step back towards the start */
                int32_t mi_d = b.ymajor ? x : y, mi_b = b.ymajor ? b.x : b.y;
                FX_CHECK_EQ(mi_d - mi_b, 1);
            }
            if (k < b.major)
                fx_bres_step(&b);
        }
    }
    FX_CHECK(diffs > 0);
}

FX_TEST(dda_long_lines_keep_endpoints_and_steps)
{
    uint32_t s = 7;
    for (int i = 0; i < 2000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++)
            v[j] = (int32_t)fx_test_rand(&s);
        fx_dda_iter d;
        fx_dda_init(&d, v[0], v[1], v[2], v[3]);
        int32_t x, y;
        fx_dda_point(&d, 0, &x, &y);
        FX_CHECK(x == v[0] && y == v[1]);
        fx_dda_point(&d, d.major, &x, &y);
        FX_CHECK(x == v[2] && y == v[3]);
        int64_t dx = (int64_t)v[2] - v[0], dy = (int64_t)v[3] - v[1];
        for (int t = 0; t < 20; t++) {
            uint32_t k = d.major ? fx_test_rand(&s) % d.major : 0;
            int32_t xa, ya, xb, yb;
            fx_dda_point(&d, k, &xa, &ya);
            fx_dda_point(&d, k + (k < d.major), &xb, &yb);
            /* within one pixel of the exact rounding, and 0/1 minor steps */
            FX_CHECK(llabs(xa - exact_round(v[0], dx, d.major, k)) <= 1);
            FX_CHECK(llabs(ya - exact_round(v[1], dy, d.major, k)) <= 1);
            FX_CHECK(llabs((int64_t)xb - xa) <= 1 && llabs((int64_t)yb - ya) <= 1);
        }
    }
}

/* Every pixel of the window is checked against the definition: the step k
 * of its major coordinate, then fx_dda_point(k). */
static void check_clip(int32_t x0, int32_t y0, int32_t x1, int32_t y1, fx_rect clip, int w, int h)
{
    canvas c = canvas_make(w, h);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_ctx_set_clip(&ctx, clip);
    fx_dda(&ctx, x0, y0, x1, y1);
    fx_dda_iter d;
    fx_dda_init(&d, x0, y0, x1, y1);
    int64_t ma0 = d.ymajor ? y0 : x0, sa = d.ymajor ? d.sy : d.sx;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int64_t a = d.ymajor ? y : x, k = sa ? (a - ma0) * sa : (a == ma0 ? 0 : -1);
            int on = 0;
            if (k >= 0 && k <= d.major) {
                int32_t px, py;
                fx_dda_point(&d, (uint32_t)k, &px, &py);
                on = px == x && py == y;
            }
            int inside = x >= clip.x0 && x < clip.x1 && y >= clip.y0 && y < clip.y1;
            if ((c.mem[y * w + x] != 0) != (on && inside)) {
                FX_CHECK_MSG(0, "(%d,%d)->(%d,%d) pixel %d,%d", x0, y0, x1, y1, x, y);
                free(c.mem);
                return;
            }
        }
    free(c.mem);
}

FX_TEST(dda_clipping_never_moves_a_pixel)
{
    fx_rect full = {0, 0, 64, 48}, win = {5, 7, 50, 33};
    check_clip(-2147483647, -2147483647, 2147483647, 2147483647, full, 64, 48);
    check_clip(INT32_MIN, 20, INT32_MAX, 21, win, 64, 48);
    check_clip(30, INT32_MIN, 31, INT32_MAX, win, 64, 48);
    uint32_t s = 99;
    for (int i = 0; i < 3000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++) {
            uint32_t r = fx_test_rand(&s);
            v[j] = i % 3 == 0 ? (int32_t)r : i % 3 == 1 ? (int32_t)(r % 300) - 120 : (int32_t)(r % 100000) - 50000;
        }
        check_clip(v[0], v[1], v[2], v[3], i & 1 ? win : full, 64, 48);
    }
}

FX_TEST(dda_trace_prints_k_x_y)
{
    canvas c = canvas_make(20, 20);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    ctx.trace = trace_collect;
    trace_clear();
    fx_dda(&ctx, 10, 12, 15, 15);
    FX_CHECK_EQ(trace_n, 9);
    if (trace_n == 9) {
        FX_CHECK(strstr(trace_lines[1], "steps=5") && strstr(trace_lines[1], "xinc=1.0000") && strstr(trace_lines[1], "yinc=0.6000"));
        /* y_k = 12 + 0.6k and the pixel rounds it */
        const char *y[] = {"12.0000", "12.6000", "13.2000", "13.8000", "14.4000", "15.0000"};
        const char *px[] = {"(10, 12)", "(11, 13)", "(12, 13)", "(13, 14)", "(14, 14)", "(15, 15)"};
        for (int k = 0; k < 6; k++)
            FX_CHECK_MSG(strstr(trace_lines[3 + k], y[k]) && strstr(trace_lines[3 + k], px[k]), "row %d: %s", k, trace_lines[3 + k]);
    }
    /* a falling line: y_1 = 1.5 is a tie, rounded up (towards the start) */
    trace_clear();
    fx_dda(&ctx, 5, 2, 1, 0);
    FX_CHECK_EQ(trace_n, 8);
    if (trace_n == 8) {
        FX_CHECK_MSG(strstr(trace_lines[1], "xinc=-1.0000") && strstr(trace_lines[1], "yinc=-0.5000"), "%s", trace_lines[1]);
        FX_CHECK_MSG(strstr(trace_lines[4], "1.5000") && strstr(trace_lines[4], "(4, 2)"), "%s", trace_lines[4]);
    }
    trace_clear();
    free(c.mem);
}
