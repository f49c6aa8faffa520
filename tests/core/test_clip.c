/* SPDX-License-Identifier: MIT */
/* Line clipping: the course's region codes, the three clippers agreeing with
 * each other and with the unclipped Bresenham line pixel for pixel (any int32
 * endpoints), their traces, exterior clipping and the clip stack. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/clip.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "canvas.h"
#include "refline.h"
#include "trace.h"
#include "fx_test.h"

FX_TEST(course_region_codes)
{
    fx_rect w = {10, 20, 51, 41}; /* xwmin 10, xwmax 50, ywmin 20, ywmax 40 */
    FX_CHECK_EQ(fx_clip_region_code(w, 30, 30), 0);
    FX_CHECK_EQ(fx_clip_region_code(w, 10, 20), 0);
    FX_CHECK_EQ(fx_clip_region_code(w, 50, 40), 0);
    FX_CHECK_EQ(fx_clip_region_code(w, 9, 30), 1);   /* 0001 left */
    FX_CHECK_EQ(fx_clip_region_code(w, 51, 30), 2);  /* 0010 right */
    FX_CHECK_EQ(fx_clip_region_code(w, 30, 19), 4);  /* 0100 below */
    FX_CHECK_EQ(fx_clip_region_code(w, 30, 41), 8);  /* 1000 above */
    FX_CHECK_EQ(fx_clip_region_code(w, 0, 100), 9);  /* 1001 above-left */
    FX_CHECK_EQ(fx_clip_region_code(w, 0, 0), 5);    /* 0101 below-left */
    FX_CHECK_EQ(fx_clip_region_code(w, 99, 0), 6);   /* 0110 below-right */
    FX_CHECK_EQ(fx_clip_region_code(w, 99, 99), 10); /* 1010 above-right */
    FX_CHECK_EQ(fx_clip_trivial(0, 0), 1);
    FX_CHECK_EQ(fx_clip_trivial(9, 5), -1); /* 1001 AND 0101 = 0001 */
    FX_CHECK_EQ(fx_clip_trivial(9, 6), 0);  /* 1001 AND 0110 = 0000: undecided */
    FX_CHECK_EQ(fx_clip_trivial(0, 2), 0);
    FX_CHECK(fx_clip_point(w, 10, 40) && !fx_clip_point(w, 51, 40) && !fx_clip_point(w, 10, 41));
}

static int ties;
static void count_ties(void *u, const char *line)
{
    (void)u;
    ties += strstr(line, "half-pixel tie") != NULL;
}

/* The reference: the foundation's exact step clip. */
static int ref_steps(fx_rect w, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t *k0, uint32_t *k1)
{
    fx_bres b;
    fx_bres_init(&b, x0, y0, x1, y1);
    return fx_bres_clip(&b, w, k0, k1);
}

static int32_t rnd_coord(uint32_t *s, int kind, int j)
{
    uint32_t r = fx_test_rand(s);
    switch (kind) {
    case 0: case 6: return (int32_t)r;                    /* anywhere in int32 */
    case 1: return (int32_t)(r % 200) - 50;               /* near the window */
    case 2: return (int32_t)(r % 200000) - 100000;        /* medium */
    case 3: return j & 1 ? (int32_t)(r % 90) - 10 : (int32_t)r; /* long and shallow */
    case 4: return j & 1 ? (int32_t)r : (int32_t)(r % 90) - 10; /* long and steep */
    default: return (int32_t)(r % 9) + 20;                /* short, around a corner */
    case 5: return (int32_t)(r % 80) - 8;                 /* short: made tie-prone below */
    }
}

FX_TEST(three_clippers_match_the_exact_step_range)
{
    uint32_t s = 20261122;
    int visible = 0, total = 0;
    fx_ctx tctx; /* only to count the half-pixel ties the traces report */
    memset(&tctx, 0, sizeof tctx);
    tctx.trace = count_ties;
    ties = 0;
    for (int i = 0; i < 60000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++)
            v[j] = rnd_coord(&s, i % 7, j);
        if (i % 7 == 5) { /* even major, odd minor: the middle step is an exact half-pixel tie */
            int32_t h = 1 + (int32_t)(fx_test_rand(&s) % 6), m = 2 * (int32_t)(fx_test_rand(&s) % 3) + 1;
            int flip = fx_test_rand(&s) & 7;
            int32_t ddx = 2 * h, ddy = m;
            if (flip & 1) { int32_t t = ddx; ddx = ddy; ddy = t; }
            v[2] = v[0] + (flip & 2 ? -ddx : ddx);
            v[3] = v[1] + (flip & 4 ? -ddy : ddy);
        }
        if (i % 7 == 6) { /* far endpoints on both sides of a point near the window */
            int64_t cx = fx_test_rand(&s) % 80 - 8, cy = fx_test_rand(&s) % 60 - 6;
            v[2] = (int32_t)(2 * cx - v[0]);
            v[3] = (int32_t)(2 * cy - v[1]);
        }
        fx_rect w;
        if (i % 3 == 0) {
            w = (fx_rect){0, 0, 64, 48};
        } else {
            int32_t x0 = (int32_t)(fx_test_rand(&s) % 60), y0 = (int32_t)(fx_test_rand(&s) % 40);
            w = (fx_rect){x0, y0, x0 + 1 + (int32_t)(fx_test_rand(&s) % 40),
                          y0 + 1 + (int32_t)(fx_test_rand(&s) % 30)};
        }
        if (i % 97 == 0) /* exact diagonals through window corners: half-pixel ties */
            v[0] = w.x0 - 7, v[1] = w.y0 - 7, v[2] = w.x0 + 9, v[3] = w.y0 + 9;
        uint32_t r0, r1;
        int want = ref_steps(w, v[0], v[1], v[2], v[3], &r0, &r1);
        visible += want;
        total++;
        for (int a = FX_CLIP_COHEN; a <= FX_CLIP_NLN; a++) {
            uint32_t k0 = 0, k1 = 0;
            int got = fx_clip_line_steps(&tctx, (fx_line_clipper)a, w, v[0], v[1], v[2], v[3], &k0, &k1);
            if (got != want || (got && (k0 != r0 || k1 != r1))) {
                FX_CHECK_MSG(0, "algo %d (%d,%d)->(%d,%d) in [%d,%d)x[%d,%d): got %d %u..%u want %d %u..%u",
                             a, v[0], v[1], v[2], v[3], w.x0, w.x1, w.y0, w.y1, got, k0, k1, want, r0, r1);
                return;
            }
        }
    }
    /* the sample must exercise both outcomes in quantity */
    FX_CHECK(visible > total / 5 && visible < total * 4 / 5);
    FX_CHECK(ties > 100); /* the end-step check is exercised, not just present */
}

/* sign(a*b - c*d) for non-negative a, b, c, d < 2^62, by 32-bit limbs, so
 * the test also runs on 32-bit targets without 128-bit integers. */
static void umul(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
    uint64_t al = a & 0xFFFFFFFFu, ah = a >> 32, bl = b & 0xFFFFFFFFu, bh = b >> 32;
    uint64_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
    uint64_t mid = (ll >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
    *lo = (ll & 0xFFFFFFFFu) | (mid << 32);
    *hi = hh + (lh >> 32) + (hl >> 32) + (mid >> 32);
}
static int prodcmp(int64_t a, int64_t b, int64_t c, int64_t d)
{
    uint64_t h1, l1, h2, l2;
    umul((uint64_t)a, (uint64_t)b, &h1, &l1);
    umul((uint64_t)c, (uint64_t)d, &h2, &l2);
    return h1 != h2 ? (h1 < h2 ? -1 : 1) : l1 != l2 ? (l1 < l2 ? -1 : 1) : 0;
}

FX_TEST(clippers_agree_on_the_parameter_range)
{
    uint32_t s = 31337;
    for (int i = 0; i < 20000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++)
            v[j] = rnd_coord(&s, i % 6, j);
        fx_rect w = {5, 7, 50, 33};
        fx_clip_param p[3];
        int r[3];
        for (int a = 0; a < 3; a++)
            r[a] = fx_clip_line_param(NULL, (fx_line_clipper)(FX_CLIP_COHEN + a), w, v[0], v[1], v[2], v[3], &p[a]);
        for (int a = 1; a < 3; a++) {
            FX_CHECK_EQ(r[a], r[0]);
            if (r[a] && r[0]) {
                FX_CHECK(p[a].u1_den > 0 && p[a].u1_num >= 0 && p[a].u2_den > 0 && p[a].u2_num >= 0);
                FX_CHECK_MSG(!prodcmp(p[a].u1_num, p[0].u1_den, p[0].u1_num, p[a].u1_den) &&
                                 !prodcmp(p[a].u2_num, p[0].u2_den, p[0].u2_num, p[a].u2_den),
                             "algo %d (%d,%d)->(%d,%d): u differ", a, v[0], v[1], v[2], v[3]);
                FX_CHECK(prodcmp(p[a].u1_num, p[a].u2_den, p[a].u2_num, p[a].u1_den) <= 0);
                FX_CHECK(p[a].u2_num <= p[a].u2_den);
            }
        }
    }
}

/* Pixel for pixel on a surface: the reference marks the unclipped line's
 * pixels (from the definition m(k) = round_half_up(k*minor/major)) that fall
 * in the window, and any exterior rectangle removes its own. */
static int check_drawn(fx_line_clipper a, int32_t x0, int32_t y0, int32_t x1, int32_t y1, fx_rect win,
                       const fx_rect *ext)
{
    enum { W = 64, H = 48 };
    canvas c = canvas_make(W, H);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_ctx_set_clip(&ctx, win);
    ctx.line_clipper = (uint8_t)a;
    if (ext)
        fx_ctx_exterior(&ctx, *ext);
    fx_line(&ctx, x0, y0, x1, y1);
    int ok = 1;
    for (int y = 0; y < H && ok; y++)
        for (int x = 0; x < W; x++) {
            int on = refline_lights(x0, y0, x1, y1, x, y);
            int inside = x >= win.x0 && x < win.x1 && y >= win.y0 && y < win.y1;
            if (ext && x >= ext->x0 && x < ext->x1 && y >= ext->y0 && y < ext->y1)
                inside = 0;
            if ((c.mem[y * W + x] != 0) != (on && inside)) {
                FX_CHECK_MSG(0, "algo %d (%d,%d)->(%d,%d) pixel %d,%d: lit %d expected %d", a, x0, y0, x1,
                             y1, x, y, c.mem[y * W + x] != 0, on && inside);
                ok = 0;
                break;
            }
        }
    free(c.mem);
    return ok;
}

FX_TEST(clipped_lines_light_exactly_the_unclipped_pixels)
{
    uint32_t s = 5150;
    fx_rect win = {6, 5, 55, 40};
    for (int i = 0; i < 3000; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++)
            v[j] = rnd_coord(&s, i % 6, j);
        for (int a = FX_CLIP_COHEN; a <= FX_CLIP_NLN; a++)
            if (!check_drawn((fx_line_clipper)a, v[0], v[1], v[2], v[3], win, NULL))
                return;
    }
    FX_CHECK(check_drawn(FX_CLIP_NLN, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX, win, NULL));
    FX_CHECK(check_drawn(FX_CLIP_COHEN, INT32_MAX, 20, INT32_MIN, 21, win, NULL));
    FX_CHECK(check_drawn(FX_CLIP_LIANG, 30, INT32_MIN, 31, INT32_MAX, win, NULL));
}

FX_TEST(exterior_clipping_skips_the_inside_run)
{
    uint32_t s = 8080;
    fx_rect win = {0, 0, 64, 48}, ext = {20, 12, 44, 36};
    for (int i = 0; i < 1500; i++) {
        int32_t v[4];
        for (int j = 0; j < 4; j++)
            v[j] = rnd_coord(&s, i % 6, j);
        if (!check_drawn((fx_line_clipper)(i % 4), v[0], v[1], v[2], v[3], win, &ext))
            return;
    }
    /* and a fill honours it too */
    canvas c = canvas_make(64, 48);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_ctx_exterior(&ctx, ext);
    fx_fill_rect(&ctx, 0, 0, 64, 48);
    int lit = 0;
    for (int i = 0; i < 64 * 48; i++)
        lit += c.mem[i] != 0;
    FX_CHECK_EQ(lit, 64 * 48 - 24 * 24);
    FX_CHECK_EQ(c.mem[20 * 64 + 30], 0);
    fx_ctx_exterior_off(&ctx);
    fx_fill_rect(&ctx, 0, 0, 64, 48);
    FX_CHECK(c.mem[20 * 64 + 30] != 0);
    free(c.mem);
}

FX_TEST(traces_name_codes_parameters_and_regions)
{
    canvas c = canvas_make(64, 48);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    ctx.trace = trace_collect;
    fx_ctx_set_clip(&ctx, (fx_rect){10, 10, 31, 21}); /* x 10..30, y 10..20 */
    /* Cohen-Sutherland: from above-left (1001) to below-left (0101): AND 0001, reject */
    ctx.line_clipper = FX_CLIP_COHEN;
    trace_clear();
    fx_line(&ctx, 0, 40, 5, 0);
    FX_CHECK(trace_has("codes 1001 0101") && trace_has("AND 0001 != 0000, reject"));
    /* a crossing line: clipped at the left boundary first */
    trace_clear();
    fx_line(&ctx, 0, 15, 40, 15);
    FX_CHECK(trace_has("codes 0001 0010") && trace_has("clip at left boundary"));
    FX_CHECK(trace_has("steps k=10..30 of 40"));
    /* issue #44: the same codes from the sign bits of the four differences
     * (x 10..30, y 10..20): (0,15) has x - xwmin = -10, (40,15) xwmax - x = -10 */
    FX_CHECK(trace_has("P1 sign bits of ywmax-y=5 y-ywmin=5 xwmax-x=30 x-xwmin=-10: 0001"));
    FX_CHECK(trace_has("P2 sign bits of ywmax-y=5 y-ywmin=5 xwmax-x=-10 x-xwmin=30: 0010"));
    trace_clear();
    fx_line(&ctx, 0, 40, 5, 0);
    FX_CHECK(trace_has("P1 sign bits of ywmax-y=-20 y-ywmin=30 xwmax-x=30 x-xwmin=-10: 1001"));
    FX_CHECK(trace_has("P2 sign bits of ywmax-y=20 y-ywmin=-10 xwmax-x=25 x-xwmin=-5: 0101"));
    /* Liang-Barsky: u1 = (2*10-1 - 0) / 80 = 19/80, u2 = (2*30+1)/80 = 61/80 */
    ctx.line_clipper = FX_CLIP_LIANG;
    trace_clear();
    fx_line(&ctx, 0, 15, 40, 15);
    FX_CHECK(trace_has("u1=19/80 (0.237500)") && trace_has("u2=61/80 (0.762500)"));
    /* NLN: P1 in the left edge region, P2 beyond the right edge: region LR */
    ctx.line_clipper = FX_CLIP_NLN;
    trace_clear();
    fx_line(&ctx, 0, 15, 40, 15);
    FX_CHECK(trace_has("P1 in edge region L, P2 in region LR"));
    /* P1 in the corner region x < xwmin, y < ywmin (left, below): enters at
     * the left edge, leaves through the top (y > ywmax, "above") */
    trace_clear();
    fx_line(&ctx, 5, 8, 17, 30);
    FX_CHECK(trace_has("P1 in corner region LB, P2 in region LA"));
    trace_clear();
    fx_line(&ctx, 20, 15, 60, 16);
    FX_CHECK(trace_has("P1 inside, P2 in region R"));
    trace_clear();
    free(c.mem);
}

FX_TEST(clip_stack_nests_and_intersects)
{
    canvas c = canvas_make(64, 48);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    fx_rect mem[2];
    fx_clip_stack st;
    fx_clip_stack_init(&st, mem, 2);
    FX_CHECK_EQ(fx_clip_push(&st, &ctx, (fx_rect){10, 10, 40, 40}), 0);
    FX_CHECK_EQ(fx_clip_push(&st, &ctx, (fx_rect){30, -5, 100, 20}), 0);
    FX_CHECK(ctx.clip.x0 == 30 && ctx.clip.y0 == 10 && ctx.clip.x1 == 40 && ctx.clip.y1 == 20);
    FX_CHECK_EQ(fx_clip_push(&st, &ctx, (fx_rect){0, 0, 1, 1}), -FX_ENOSPC);
    fx_fill_rect(&ctx, 0, 0, 64, 48);
    int lit = 0;
    for (int i = 0; i < 64 * 48; i++)
        lit += c.mem[i] != 0;
    FX_CHECK_EQ(lit, 10 * 10);
    FX_CHECK_EQ(fx_clip_pop(&st, &ctx), 0);
    FX_CHECK(ctx.clip.x0 == 10 && ctx.clip.x1 == 40);
    FX_CHECK_EQ(fx_clip_pop(&st, &ctx), 0);
    FX_CHECK(ctx.clip.x0 == 0 && ctx.clip.x1 == 64 && ctx.clip.y1 == 48);
    FX_CHECK(fx_clip_pop(&st, &ctx) < 0);
    /* disjoint windows nest to an empty one that draws nothing */
    fx_clip_push(&st, &ctx, (fx_rect){0, 0, 10, 10});
    fx_clip_push(&st, &ctx, (fx_rect){20, 20, 30, 30});
    memset(c.mem, 0, 64 * 48 * 4);
    fx_fill_rect(&ctx, 0, 0, 64, 48);
    fx_line(&ctx, 0, 0, 63, 47);
    lit = 0;
    for (int i = 0; i < 64 * 48; i++)
        lit += c.mem[i] != 0;
    FX_CHECK_EQ(lit, 0);
    free(c.mem);
}

/* Issue #44: the sign-bit codes equal the comparison codes everywhere,
 * including the int32 extremes, where an int32 difference would overflow. */
FX_TEST(clip_region_code_from_sign_bits)
{
    uint32_t st = 4404;
    const int32_t edge[] = {INT32_MIN, INT32_MIN + 1, -1, 0, 1, 9, 10, 11, 29, 30, 31, INT32_MAX - 1, INT32_MAX};
    fx_rect w = {10, 10, 31, 21};
    int n = 0;
    for (unsigned i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (unsigned j = 0; j < sizeof edge / sizeof edge[0]; j++, n++)
            FX_CHECK_EQ(fx_clip_region_code_signs(w, edge[i], edge[j], NULL), fx_clip_region_code(w, edge[i], edge[j]));
    for (int k = 0; k < 100000; k++, n++) {
        fx_rect r = {(int32_t)fx_test_rand(&st) % 64 - 32, (int32_t)fx_test_rand(&st) % 64 - 32, 0, 0};
        r.x1 = r.x0 + 1 + (int32_t)(fx_test_rand(&st) % 40);
        r.y1 = r.y0 + 1 + (int32_t)(fx_test_rand(&st) % 40);
        int32_t x = (int32_t)(fx_test_rand(&st) % 160) - 80, y = (int32_t)(fx_test_rand(&st) % 160) - 80;
        FX_CHECK_EQ(fx_clip_region_code_signs(r, x, y, NULL), fx_clip_region_code(r, x, y));
    }
    int64_t d[4];
    FX_CHECK_EQ(fx_clip_region_code_signs(w, INT32_MIN, INT32_MAX, d), FX_CODE_ABOVE | FX_CODE_LEFT);
    FX_CHECK(d[0] == 20 - (int64_t)INT32_MAX && d[3] == (int64_t)INT32_MIN - 10);
    FX_CHECK(n > 100000);
}
