/* SPDX-License-Identifier: MIT */
/* Line attributes: patterned 1-pixel lines and polylines (phase carried
 * across vertices), thick lines against the distance definition, and exact
 * clipping of thick, dashed and joined strokes for any int32 endpoints. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/line.h"
#include "canvas.h"
#include "fx_test.h"

FX_TEST(style_plain_means_the_foundation_line)
{
    fx_line_style st;
    fx_line_style_init(&st);
    FX_CHECK(fx_line_style_is_plain(&st));
    FX_CHECK(fx_line_style_is_plain(NULL));
    st.pattern = 0x7;
    st.pattern_len = 3; /* all lit: still solid */
    FX_CHECK(fx_line_style_is_plain(&st));
    st.pattern_len = 4;
    FX_CHECK(!fx_line_style_is_plain(&st));
    st.pattern_len = 0;
    st.width = 2;
    FX_CHECK(!fx_line_style_is_plain(&st));
}

/* Each Bresenham step k is lit iff pattern unit ((phase + k) / unit) % len is. */
FX_TEST(dashed_1px_line_follows_the_pixel_mask)
{
    uint32_t s = 3;
    for (int i = 0; i < 1500; i++) {
        canvas c = canvas_make(80, 60);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &c.s);
        fx_line_style st;
        fx_line_style_init(&st);
        st.pattern_len = (uint8_t)(1 + fx_test_rand(&s) % 32);
        st.pattern = fx_test_rand(&s);
        st.unit = (uint16_t)(fx_test_rand(&s) % 4);
        st.phase = fx_test_rand(&s) % 1000;
        ctx.line_style = &st;
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 80), y0 = (int32_t)(fx_test_rand(&s) % 60);
        int32_t x1 = (int32_t)(fx_test_rand(&s) % 80), y1 = (int32_t)(fx_test_rand(&s) % 60);
        fx_line(&ctx, x0, y0, x1, y1);
        fx_bres b;
        fx_bres_init(&b, x0, y0, x1, y1);
        unsigned unit = st.unit ? st.unit : 1;
        int lit = 0;
        for (uint32_t k = 0;; k++) {
            int on = st.pattern >> (((st.phase + k) / unit) % st.pattern_len) & 1;
            FX_CHECK_MSG((c.mem[b.y * 80 + b.x] != 0) == on, "(%d,%d)->(%d,%d) k=%u", x0, y0, x1, y1, k);
            lit += on;
            if (k == b.major)
                break;
            fx_bres_step(&b);
        }
        int total = 0;
        for (int p = 0; p < 80 * 60; p++)
            total += c.mem[p] != 0;
        FX_CHECK_EQ(total, lit);
        free(c.mem);
    }
}

/* A polyline equals its segments drawn one by one with the phase each
 * starts at: the pattern runs on across the vertices. */
FX_TEST(polyline_carries_the_pattern_phase)
{
    uint32_t s = 17;
    for (int i = 0; i < 500; i++) {
        canvas a = canvas_make(90, 70), b = canvas_make(90, 70);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_line_style st;
        fx_line_style_init(&st);
        st.pattern_len = (uint8_t)(2 + fx_test_rand(&s) % 20);
        st.pattern = fx_test_rand(&s);
        st.unit = (uint16_t)(1 + fx_test_rand(&s) % 3);
        ca.line_style = &st;
        int n = 2 + (int)(fx_test_rand(&s) % 6);
        int32_t xy[16];
        for (int j = 0; j < n; j++) {
            xy[2 * j] = (int32_t)(fx_test_rand(&s) % 90);
            xy[2 * j + 1] = (int32_t)(fx_test_rand(&s) % 70);
        }
        fx_polyline(&ca, xy, n);
        fx_line_style seg = st;
        cb.line_style = &seg;
        uint32_t phase = 0;
        for (int j = 0; j + 1 < n; j++) {
            if (xy[2 * j] == xy[2 * j + 2] && xy[2 * j + 1] == xy[2 * j + 3])
                continue;
            seg.phase = phase;
            fx_line(&cb, xy[2 * j], xy[2 * j + 1], xy[2 * j + 2], xy[2 * j + 3]);
            fx_bres br;
            fx_bres_init(&br, xy[2 * j], xy[2 * j + 1], xy[2 * j + 2], xy[2 * j + 3]);
            phase += br.major;
        }
        /* segments drawn separately repeat their shared vertex; the
         * polyline decides it by the next segment's first step, which
         * has the same phase, so the pictures agree exactly */
        FX_CHECK(memcmp(a.mem, b.mem, 90 * 70 * 4) == 0);
        free(a.mem);
        free(b.mem);
    }
}

static double seg_dist(double px, double py, double ax, double ay, double bx, double by, double *t)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    *t = l2 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    double tt = *t < 0 ? 0 : *t > 1 ? 1 : *t;
    double qx = ax + tt * dx - px, qy = ay + tt * dy - py;
    return sqrt(qx * qx + qy * qy);
}

/* Pixel centres clearly inside the ideal stroke are lit and those clearly
 * outside are not (the outline is rounded to 1/256 px). */
FX_TEST(thick_line_matches_the_ideal_stroke)
{
    uint32_t s = 23;
    for (int i = 0; i < 1200; i++) {
        canvas c = canvas_make(100, 80);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &c.s);
        fx_line_style st;
        fx_line_style_init(&st);
        st.width = 2 + (int32_t)(fx_test_rand(&s) % 20);
        st.cap = (uint8_t)(fx_test_rand(&s) % 3);
        ctx.line_style = &st;
        int32_t x0 = (int32_t)(fx_test_rand(&s) % 100), y0 = (int32_t)(fx_test_rand(&s) % 80);
        int32_t x1 = (int32_t)(fx_test_rand(&s) % 100), y1 = (int32_t)(fx_test_rand(&s) % 80);
        if (i % 5 == 0)
            y1 = y0; /* level lines: exact symmetric cases */
        fx_line(&ctx, x0, y0, x1, y1);
        double ax = x0 + 0.5, ay = y0 + 0.5, bx = x1 + 0.5, by = y1 + 0.5, h = st.width / 2.0;
        double len = sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
        const double eps = 0.02;
        int bad = 0;
        for (int y = 0; y < 80 && !bad; y++)
            for (int x = 0; x < 100; x++) {
                double t, d = seg_dist(x + 0.5, y + 0.5, ax, ay, bx, by, &t);
                double along = t * len; /* signed distance along the segment from A */
                double perp = 0;
                if (len) {
                    double nx = -(by - ay) / len, ny = (bx - ax) / len;
                    perp = fabs((x + 0.5 - ax) * nx + (y + 0.5 - ay) * ny);
                }
                int in, out;
                if (st.cap == FX_CAP_ROUND) {
                    in = d < h - eps;
                    out = d > h + eps;
                } else {
                    double ext = st.cap == FX_CAP_SQUARE ? h : 0;
                    if (!len) {
                        double m = fmax(fabs(x + 0.5 - ax), fabs(y + 0.5 - ay));
                        in = ext > 0 && m < h - eps;
                        out = !ext || m > h + eps;
                    } else {
                        in = perp < h - eps && along > -ext + eps && along < len + ext - eps;
                        out = perp > h + eps || along < -ext - eps || along > len + ext + eps;
                    }
                }
                int lit = c.mem[y * 100 + x] != 0;
                if ((in && !lit) || (out && lit)) {
                    FX_CHECK_MSG(0, "w=%d cap=%d (%d,%d)->(%d,%d) pixel %d,%d lit=%d", st.width, st.cap,
                                 x0, y0, x1, y1, x, y, lit);
                    bad = 1;
                    break;
                }
            }
        free(c.mem);
    }
}

/* Odd widths on level lines are exactly symmetric; butt caps stop at the
 * endpoint centres (x1 - x0 columns), square caps add w/2 each side. */
FX_TEST(thick_level_line_exact_pixels)
{
    for (int w = 2; w <= 9; w++)
        for (int cap = 0; cap < 2; cap++) {
            canvas c = canvas_make(64, 40);
            fx_ctx ctx;
            fx_ctx_init(&ctx, &c.s);
            fx_line_style st;
            fx_line_style_init(&st);
            st.width = w;
            st.cap = (uint8_t)cap;
            ctx.line_style = &st;
            fx_line(&ctx, 20, 20, 40, 20);
            /* rows with centre in [20.5 - w/2, 20.5 + w/2): top edge in, bottom out */
            int r0 = 20 - w / 2, r1 = 20 + (w - 1) / 2;
            int c0 = cap ? 20 - w / 2 : 20, c1 = cap ? 40 + (w - 1) / 2 : 39;
            for (int y = 0; y < 40; y++)
                for (int x = 0; x < 64; x++) {
                    int want = y >= r0 && y <= r1 && x >= c0 && x <= c1;
                    FX_CHECK_MSG((c.mem[y * 64 + x] != 0) == want, "w=%d cap=%d pixel %d,%d", w, cap, x, y);
                }
            free(c.mem);
        }
}

static void random_style(fx_line_style *st, uint32_t *s)
{
    fx_line_style_init(st);
    st->width = 1 + (int32_t)(fx_test_rand(s) % 12);
    st->cap = (uint8_t)(fx_test_rand(s) % 3);
    st->join = (uint8_t)(fx_test_rand(s) % 3);
    if (fx_test_rand(s) % 2) {
        st->pattern_len = (uint8_t)(2 + fx_test_rand(s) % 12);
        st->pattern = fx_test_rand(s);
        st->unit = (uint16_t)(fx_test_rand(s) % 5);
        st->phase = fx_test_rand(s) % 100;
    }
}

/* The same stroke drawn with the whole surface and with a window: inside
 * the window the pixels agree exactly, outside nothing is drawn. */
FX_TEST(thick_dashed_joined_strokes_clip_exactly)
{
    uint32_t s = 4711;
    fx_rect win = {9, 6, 50, 41};
    for (int i = 0; i < 1500; i++) {
        canvas a = canvas_make(64, 48), b = canvas_make(64, 48);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_ctx_set_clip(&cb, win);
        fx_line_style st;
        random_style(&st, &s);
        ca.line_style = cb.line_style = &st;
        int n = 2 + (int)(fx_test_rand(&s) % 4);
        int32_t xy[10];
        for (int j = 0; j < 2 * n; j++) {
            uint32_t r = fx_test_rand(&s);
            switch (i % 4) {
            case 0: xy[j] = (int32_t)r; break;
            case 1: xy[j] = (int32_t)(r % 200) - 70; break;
            case 2: xy[j] = (int32_t)(r % 200000) - 100000; break;
            default: xy[j] = j & 1 ? (int32_t)(r % 48) : (int32_t)(r % 2000001) - 1000000; break;
            }
        }
        fx_polyline(&ca, xy, n);
        fx_polyline(&cb, xy, n);
        for (int y = 0; y < 48; y++)
            for (int x = 0; x < 64; x++) {
                int in = x >= win.x0 && x < win.x1 && y >= win.y0 && y < win.y1;
                uint32_t va = a.mem[y * 64 + x], vb = b.mem[y * 64 + x];
                if (in ? va != vb : vb != 0) {
                    FX_CHECK_MSG(0, "case %d w=%d pixel %d,%d", i, st.width, x, y);
                    y = 48;
                    break;
                }
            }
        free(a.mem);
        free(b.mem);
    }
}

/* The classic far-reaching line, thick and dashed, on a tiny surface: two
 * different windows agree where they overlap. */
FX_TEST(thick_line_across_int32_agrees_between_windows)
{
    fx_line_style st;
    fx_line_style_init(&st);
    st.width = 7;
    st.cap = FX_CAP_ROUND;
    for (int dashed = 0; dashed < 2; dashed++) {
        st.pattern_len = dashed ? 9 : 0;
        st.pattern = 0x3F;
        canvas a = canvas_make(64, 48), b = canvas_make(64, 48);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_rect win = {20, 10, 44, 40};
        fx_ctx_set_clip(&cb, win);
        ca.line_style = cb.line_style = &st;
        fx_line(&ca, -2147483647, -2147483647, 2147483647, 2147483647);
        fx_line(&cb, -2147483647, -2147483647, 2147483647, 2147483647);
        int lit = 0;
        for (int y = win.y0; y < win.y1; y++)
            for (int x = win.x0; x < win.x1; x++) {
                FX_CHECK(a.mem[y * 64 + x] == b.mem[y * 64 + x]);
                lit += a.mem[y * 64 + x] != 0;
            }
        FX_CHECK(lit > 0);
        /* the diagonal through the surface: its centre pixels near the
         * middle are lit when solid */
        if (!dashed)
            FX_CHECK(a.mem[30 * 64 + 30] != 0);
        free(a.mem);
        free(b.mem);
    }
}

/* Collinear vertices change nothing: a level or plumb dashed thick line
 * split at interior points is the same picture (phase carried exactly). */
FX_TEST(thick_dash_phase_runs_through_vertices)
{
    uint32_t s = 8;
    for (int i = 0; i < 300; i++) {
        canvas a = canvas_make(120, 120), b = canvas_make(120, 120);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &a.s);
        fx_ctx_init(&cb, &b.s);
        fx_line_style st;
        fx_line_style_init(&st);
        st.width = 2 + (int32_t)(fx_test_rand(&s) % 8);
        st.cap = (uint8_t)(fx_test_rand(&s) % 3);
        st.pattern_len = (uint8_t)(2 + fx_test_rand(&s) % 10);
        st.pattern = fx_test_rand(&s);
        st.unit = (uint16_t)(1 + fx_test_rand(&s) % 4);
        ca.line_style = cb.line_style = &st;
        int32_t c0 = 10 + (int32_t)(fx_test_rand(&s) % 100);
        int32_t p[5];
        for (int j = 0; j < 5; j++)
            p[j] = 5 + (int32_t)(fx_test_rand(&s) % 110);
        /* sorted so the split points lie between the ends */
        for (int j = 0; j < 5; j++)
            for (int k = j + 1; k < 5; k++)
                if (p[k] < p[j]) {
                    int32_t t = p[j];
                    p[j] = p[k];
                    p[k] = t;
                }
        int32_t xy[10];
        for (int j = 0; j < 5; j++) {
            xy[2 * j] = i & 1 ? c0 : p[j];
            xy[2 * j + 1] = i & 1 ? p[j] : c0;
        }
        fx_polyline(&ca, xy, 5);
        int32_t ends[4] = {xy[0], xy[1], xy[8], xy[9]};
        fx_polyline(&cb, ends, 2);
        FX_CHECK_MSG(memcmp(a.mem, b.mem, 120 * 120 * 4) == 0, "case %d", i);
        free(a.mem);
        free(b.mem);
    }
}

/* Joins: a right-angle polyline with mitre joins fills the outer corner
 * square; bevel cuts it; round fills the quarter disc. */
FX_TEST(joins_shape_the_outer_corner)
{
    for (int j = 0; j < 3; j++) {
        canvas c = canvas_make(60, 60);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &c.s);
        fx_line_style st;
        fx_line_style_init(&st);
        st.width = 11;
        st.join = (uint8_t)j;
        ctx.line_style = &st;
        int32_t xy[6] = {10, 30, 30, 30, 30, 50}; /* right, then down: outer corner up-right */
        fx_polyline(&ctx, xy, 3);
        /* outer corner region: x in (30.5, 36), y in (25, 30.5) */
        int corner = c.mem[25 * 60 + 35] != 0; /* near the mitre tip (35.5, 25.5) */
        int diag = c.mem[28 * 60 + 32] != 0;   /* inside the bevel triangle, outside both bodies */
        FX_CHECK_EQ(corner, j == FX_JOIN_MITER);
        FX_CHECK(diag);
        /* the inner side is covered by the bodies either way */
        FX_CHECK(c.mem[34 * 60 + 27] != 0);
        free(c.mem);
    }
}
