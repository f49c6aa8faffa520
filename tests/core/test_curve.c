/* SPDX-License-Identifier: MIT */
/* Curves: flattened Béziers of every degree keep their endpoints and stay
 * within the tolerance of the true curve (both ways: every chord near the
 * curve, every curve point near the polyline); splines meet their pieces'
 * defining points; huge curves stay bounded. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "fx_test.h"

typedef struct {
    int n;
    int64_t *xy;
    int cap;
} pts;

/* Doubling, not one point per realloc: the depth-limit test collects 65,537
 * points, and ASan's realloc copies every time (quadratic: 130 s of the
 * sanitized unit run, against 0.02 s plain). */
static void collect(void *u, int64_t x, int64_t y)
{
    pts *p = u;
    if (p->n == p->cap) {
        p->cap = p->cap ? 2 * p->cap : 64;
        p->xy = realloc(p->xy, sizeof(int64_t) * 2 * (size_t)p->cap);
    }
    p->xy[2 * p->n] = x;
    p->xy[2 * p->n + 1] = y;
    p->n++;
}

/* de Casteljau in double, in 1/256 px (exact enough: values < 2^20) */
static void eval(const int64_t *c, int n, double t, double *x, double *y)
{
    double bx[9], by[9];
    for (int i = 0; i < n; i++) {
        bx[i] = (double)c[2 * i];
        by[i] = (double)c[2 * i + 1];
    }
    for (int k = 1; k < n; k++)
        for (int i = 0; i < n - k; i++) {
            bx[i] += t * (bx[i + 1] - bx[i]);
            by[i] += t * (by[i + 1] - by[i]);
        }
    *x = bx[0];
    *y = by[0];
}

static double dist_to_seg(double px, double py, const int64_t *a, const int64_t *b)
{
    double ax = (double)a[0], ay = (double)a[1];
    double dx = (double)b[0] - ax, dy = (double)b[1] - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double qx = ax + t * dx - px, qy = ay + t * dy - py;
    return sqrt(qx * qx + qy * qy);
}

FX_TEST(bezier_flattening_keeps_endpoints_and_tolerance)
{
    uint32_t s = 12;
    for (int i = 0; i < 240; i++) {
        int n = 3 + i % 7; /* degree 2..8 */
        int64_t c[18];
        int64_t range = i % 3 == 0 ? 256 * 100 : i % 3 == 1 ? 256 * 600 : 256 * 20;
        for (int j = 0; j < 2 * n; j++)
            c[j] = (int64_t)(fx_test_rand(&s) % (uint32_t)(2 * range)) - range;
        uint32_t tol = 8 + fx_test_rand(&s) % 200;
        pts p = {0, NULL, 0};
        int r = fx_bezier_flatten(c, n, tol, collect, &p);
        FX_CHECK_EQ(r, p.n);
        FX_CHECK(p.n >= 2);
        FX_CHECK(p.xy[0] == c[0] && p.xy[1] == c[1]);
        FX_CHECK(p.xy[2 * p.n - 2] == c[2 * n - 2] && p.xy[2 * p.n - 1] == c[2 * n - 1]);
        /* every vertex is a curve point (up to fixed-point rounding) and
         * every curve point is within tol of the polyline */
        double worst = 0;
        for (int k = 0; k <= 400; k++) {
            double x, y, best = 1e30;
            eval(c, n, (double)k / 400, &x, &y);
            for (int q = 0; q + 1 < p.n; q++) {
                double d = dist_to_seg(x, y, &p.xy[2 * q], &p.xy[2 * q + 2]);
                if (d < best)
                    best = d;
            }
            if (best > worst)
                worst = best;
        }
        FX_CHECK_MSG(worst <= tol + 1.0, "degree %d tol %u: %f", n - 1, tol, worst);
        free(p.xy);
    }
}

FX_TEST(bezier_flattening_adapts_to_the_tolerance)
{
    int64_t c[8] = {0, 0, 256 * 300, 256 * 400, 256 * 600, -256 * 200, 256 * 800, 0};
    int last = 0;
    for (uint32_t tol = 256; tol >= 4; tol /= 4) {
        pts p = {0, NULL, 0};
        fx_bezier_flatten(c, 4, tol, collect, &p);
        FX_CHECK(p.n > last); /* finer tolerance, more chords */
        last = p.n;
        free(p.xy);
    }
    FX_CHECK(fx_bezier_flatten(c, 1, 64, collect, NULL) == -FX_EINVAL);
    FX_CHECK(fx_bezier_flatten(c, 10, 64, collect, NULL) == -FX_EINVAL);
}

FX_TEST(huge_bezier_is_bounded_by_the_depth_limit)
{
    int64_t c[6] = {-((int64_t)1 << 38), -((int64_t)1 << 38), (int64_t)1 << 38, -((int64_t)1 << 38),
                    (int64_t)1 << 38, (int64_t)1 << 38};
    pts p = {0, NULL, 0};
    int r = fx_bezier_flatten(c, 3, 1, collect, &p);
    FX_CHECK(r > 1 && r <= (1 << FX_CURVE_MAX_DEPTH) + 1);
    FX_CHECK(p.xy[2 * r - 2] == c[4] && p.xy[2 * r - 1] == c[5]);
    free(p.xy);
    /* and drawing it on a small surface finishes */
    uint32_t mem[32 * 32] = {0};
    fx_surface sf;
    fx_surface_init(&sf, mem, 32, 32, 128, FX_FMT_XRGB8888);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &sf);
    int32_t xy[6] = {-1000000000, 16, 2000000000, 16, 16, 1000000000};
    FX_CHECK_EQ(fx_bezier(&ctx, xy, 3, 0), 0);
}

/* A 1-pixel Catmull-Rom spline passes through every given point. */
FX_TEST(spline_passes_through_its_points)
{
    uint32_t s = 55;
    for (int i = 0; i < 200; i++) {
        uint32_t mem[100 * 80] = {0};
        fx_surface sf;
        fx_surface_init(&sf, mem, 100, 80, 400, FX_FMT_XRGB8888);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &sf);
        int n = 2 + i % 8;
        int32_t xy[20];
        for (int j = 0; j < n; j++) {
            xy[2 * j] = (int32_t)(fx_test_rand(&s) % 100);
            xy[2 * j + 1] = (int32_t)(fx_test_rand(&s) % 80);
        }
        FX_CHECK_EQ(fx_spline(&ctx, xy, n, 0), 0);
        for (int j = 0; j < n; j++)
            FX_CHECK_MSG(mem[xy[2 * j + 1] * 100 + xy[2 * j]] != 0, "case %d point %d", i, j);
    }
}

/* A uniform B-spline whose control points are collinear and evenly spaced
 * is that straight segment from (P0+4P1+P2)/6 to (P_{n-3}+4P_{n-2}+P_{n-1})/6:
 * exactly the Bresenham line between those pixels when they are integers. */
FX_TEST(bspline_of_evenly_spaced_points_is_its_segment)
{
    uint32_t a[90 * 40] = {0}, b[90 * 40] = {0};
    fx_surface sa, sb;
    fx_surface_init(&sa, a, 90, 40, 360, FX_FMT_XRGB8888);
    fx_surface_init(&sb, b, 90, 40, 360, FX_FMT_XRGB8888);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &sa);
    fx_ctx_init(&cb, &sb);
    int32_t xy[12] = {4, 20, 16, 20, 28, 20, 40, 20, 52, 20, 64, 20};
    FX_CHECK_EQ(fx_bspline(&ca, xy, 6, 0), 0);
    fx_line(&cb, 16, 20, 52, 20);
    FX_CHECK(memcmp(a, b, sizeof a) == 0);
    FX_CHECK_EQ(fx_bspline(&ca, xy, 3, 0), -FX_EINVAL);
}

/* The dash phase runs along a curve: a dashed curve lights a subset of the
 * solid one, and a different phase lights a different subset. */
FX_TEST(dashed_curve_is_a_subset_of_the_solid_curve)
{
    static uint32_t solid[120 * 100], d1[120 * 100], d2[120 * 100];
    uint32_t *bufs[3] = {solid, d1, d2};
    int32_t xy[8] = {5, 90, 30, -40, 90, 140, 115, 10};
    for (int k = 0; k < 3; k++) {
        memset(bufs[k], 0, sizeof solid);
        fx_surface sf;
        fx_surface_init(&sf, bufs[k], 120, 100, 480, FX_FMT_XRGB8888);
        fx_ctx ctx;
        fx_ctx_init(&ctx, &sf);
        fx_line_style st;
        fx_line_style_init(&st);
        st.width = 5;
        if (k) {
            st.pattern = 0x3F;
            st.pattern_len = 9;
            st.phase = k == 1 ? 0 : 20;
        }
        ctx.line_style = &st;
        fx_bezier(&ctx, xy, 4, 0);
    }
    int lit1 = 0, lit2 = 0, differ = 0, extra = 0;
    for (int i = 0; i < 120 * 100; i++) {
        lit1 += d1[i] != 0;
        lit2 += d2[i] != 0;
        differ += (d1[i] != 0) != (d2[i] != 0);
        extra += (d1[i] && !solid[i]) || (d2[i] && !solid[i]);
    }
    FX_CHECK(lit1 > 0 && lit2 > 0 && differ > 0);
    /* dash ends are butt cuts of the same bodies; joins can only shrink */
    FX_CHECK_EQ(extra, 0);
}
