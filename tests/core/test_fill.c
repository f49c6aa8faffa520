/* SPDX-License-Identifier: MIT */
/* Polygon, triangle and Gouraud fills against a pixel-centre reference
 * rasterizer written here from the definition (docs/BENCHMARK.md, reference pictures,
 * generalised to fx8 vertices and to the nonzero rule). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/fill.h"
#include "fx_test.h"

#define W 64
#define H 48

static uint32_t img[H * W];

static void setup(fx_surface *s, fx_ctx *c, uint32_t *buf)
{
    memset(buf, 0, sizeof(uint32_t) * W * H);
    fx_surface_init(s, buf, W, H, W * 4, FX_FMT_XRGB8888);
    fx_ctx_init(c, s);
}

static __int128 floordiv128(__int128 a, __int128 b)
{
    __int128 q = a / b;
    return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

/* The definition: row y samples vertex coordinate y << s; an edge counts iff
 * min <= Y < max; crossing pixel = ceil(xc / 2^s); rule applied to the
 * crossings sorted by that pixel. cover[] gets +1 for each filled pixel. */
static void ref_fill(int *cover, const int64_t *xs, const int64_t *ys, int nv, unsigned s, int nonzero,
                     fx_rect clip)
{
    for (int y = clip.y0; y < clip.y1; y++) {
        __int128 Y = (__int128)y << s;
        int64_t xc[64];
        int dir[64], k = 0;
        for (int i = 0; i < nv; i++) {
            int j = (i + 1) % nv;
            int64_t lo = ys[i] < ys[j] ? ys[i] : ys[j], hi = ys[i] < ys[j] ? ys[j] : ys[i];
            if (!(lo <= Y && Y < hi))
                continue;
            /* ceil((x0*dy + (Y-y0)*dx) / (dy << s)) */
            __int128 dy = (__int128)ys[j] - ys[i], dx = (__int128)xs[j] - xs[i];
            __int128 num = (__int128)xs[i] * dy + (Y - ys[i]) * dx, den = dy * ((__int128)1 << s);
            int64_t v = (int64_t)-floordiv128(-num, den);
            int d = ys[j] > ys[i] ? 1 : -1, m = k++;
            while (m > 0 && xc[m - 1] > v) {
                xc[m] = xc[m - 1];
                dir[m] = dir[m - 1];
                m--;
            }
            xc[m] = v;
            dir[m] = d;
        }
        for (int x = clip.x0; x < clip.x1; x++) {
            int par = 0, wind = 0;
            for (int i = 0; i < k; i++)
                if (xc[i] <= x) {
                    par ^= 1;
                    wind += dir[i];
                }
            if (nonzero ? wind != 0 : par)
                cover[y * W + x]++;
        }
    }
}

static int cover_ref[H * W];

static int compare_img(const uint32_t *got, uint32_t col)
{
    int bad = 0;
    for (int i = 0; i < W * H; i++)
        bad += (got[i] == col) != (cover_ref[i] != 0);
    return bad;
}

FX_TEST(fill_random_polygons_match_reference_both_rules)
{
    uint32_t seed = 777;
    for (int iter = 0; iter < 600; iter++) {
        int nv = 3 + (int)(fx_test_rand(&seed) % 9);
        unsigned s = (iter & 1) ? 8 : 0;
        int nonzero = (iter >> 1) & 1;
        int32_t xy[24];
        int64_t xs[12], ys[12];
        int span = s ? 100 * 256 : 100;
        for (int i = 0; i < nv; i++) {
            xs[i] = xy[2 * i] = (int32_t)(fx_test_rand(&seed) % (uint32_t)span) - span / 5;
            ys[i] = xy[2 * i + 1] = (int32_t)(fx_test_rand(&seed) % (uint32_t)(span * 3 / 4)) - span / 8;
            if (i > 0 && fx_test_rand(&seed) % 8 == 0) { /* horizontal and repeated vertices */
                ys[i] = xy[2 * i + 1] = xy[2 * i - 1];
                if (fx_test_rand(&seed) % 2)
                    xs[i] = xy[2 * i] = xy[2 * i - 2];
            }
        }
        fx_surface sf;
        fx_ctx c;
        setup(&sf, &c, img);
        fx_rect clip = {0, 0, W, H};
        if (iter % 5 == 4) {
            clip = (fx_rect){7, 5, 50, 40};
            fx_ctx_set_clip(&c, clip);
        }
        fx_ctx_set_color(&c, 0xFFFFFFFF);
        int r = s ? fx_fill_poly8(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD)
                  : fx_fill_poly(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD);
        FX_CHECK_EQ(r, 0);
        memset(cover_ref, 0, sizeof cover_ref);
        ref_fill(cover_ref, xs, ys, nv, s, nonzero, clip);
        int bad = compare_img(img, 0xFFFFFF);
        FX_CHECK_MSG(bad == 0, "iter %d (nv %d, s %u, nonzero %d): %d pixels differ", iter, nv, s, nonzero, bad);
        if (bad)
            return;
    }
}

FX_TEST(fill_huge_coordinates_match_reference)
{
    uint32_t seed = 99;
    for (int iter = 0; iter < 300; iter++) {
        int nv = 3 + (int)(fx_test_rand(&seed) % 5);
        int32_t xy[16];
        int64_t xs[8], ys[8];
        for (int i = 0; i < nv; i++) {
            int big = fx_test_rand(&seed) % 2;
            int32_t vx = big ? (int32_t)fx_test_rand(&seed) : (int32_t)(fx_test_rand(&seed) % 200) - 70;
            int32_t vy = big ? (int32_t)fx_test_rand(&seed) : (int32_t)(fx_test_rand(&seed) % 150) - 50;
            if (fx_test_rand(&seed) % 7 == 0)
                vx = (fx_test_rand(&seed) & 1) ? INT32_MAX : INT32_MIN;
            xs[i] = xy[2 * i] = vx;
            ys[i] = xy[2 * i + 1] = vy;
        }
        unsigned s = iter % 3 == 0 ? 8 : 0;
        int nonzero = iter % 2;
        fx_surface sf;
        fx_ctx c;
        setup(&sf, &c, img);
        int r = s ? fx_fill_poly8(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD)
                  : fx_fill_poly(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD);
        FX_CHECK_EQ(r, 0);
        memset(cover_ref, 0, sizeof cover_ref);
        ref_fill(cover_ref, xs, ys, nv, s, nonzero, (fx_rect){0, 0, W, H});
        int bad = compare_img(img, 0xFFFFFF);
        FX_CHECK_MSG(bad == 0, "iter %d: %d pixels differ", iter, bad);
        if (bad)
            return;
        if (nv == 3 && !s) { /* the triangle fast path and its fallback */
            setup(&sf, &c, img);
            fx_fill_tri(&c, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5]);
            FX_CHECK_EQ(compare_img(img, 0xFFFFFF), 0);
        }
    }
}

FX_TEST(fill_triangles_match_reference)
{
    uint32_t seed = 4242;
    for (int iter = 0; iter < 2000; iter++) {
        unsigned s = iter % 2 ? 8 : 0;
        int32_t xy[6];
        int64_t xs[3], ys[3];
        int span = s ? 90 * 256 : 90;
        for (int i = 0; i < 3; i++) {
            xs[i] = xy[2 * i] = (int32_t)(fx_test_rand(&seed) % (uint32_t)span) - span / 6;
            ys[i] = xy[2 * i + 1] = (int32_t)(fx_test_rand(&seed) % (uint32_t)span) - span / 4;
        }
        if (iter % 7 == 0) /* flat top or bottom */
            ys[1] = xy[3] = xy[1];
        fx_surface sf;
        fx_ctx c;
        setup(&sf, &c, img);
        if (s)
            fx_fill_tri8(&c, xy);
        else
            fx_fill_tri(&c, xy[0], xy[1], xy[2], xy[3], xy[4], xy[5]);
        memset(cover_ref, 0, sizeof cover_ref);
        ref_fill(cover_ref, xs, ys, 3, s, 0, (fx_rect){0, 0, W, H});
        int bad = compare_img(img, 0xFFFFFF);
        FX_CHECK_MSG(bad == 0, "tri %d: %d pixels differ", iter, bad);
        if (bad)
            return;
    }
}

/* A jittered grid split into triangles (both diagonals used, some vertices
 * sub-pixel): every pixel of the covered area is hit exactly once. */
static void mesh_test(unsigned s, uint32_t seed)
{
    enum { GX = 9, GY = 7 };
    int32_t px[GY][GX], py[GY][GX];
    int one = s ? 256 : 1;
    for (int j = 0; j < GY; j++)
        for (int i = 0; i < GX; i++) {
            int jx = (i > 0 && i < GX - 1) ? (int)(fx_test_rand(&seed) % (3u * one)) - one : 0;
            int jy = (j > 0 && j < GY - 1) ? (int)(fx_test_rand(&seed) % (3u * one)) - one : 0;
            px[j][i] = (i * 8 - 4) * one + jx; /* starts off-surface: clipping too */
            py[j][i] = (j * 8 - 3) * one + jy;
        }
    static int count[H * W];
    memset(count, 0, sizeof count);
    fx_rect clip = {0, 0, W, H};
    for (int j = 0; j + 1 < GY; j++)
        for (int i = 0; i + 1 < GX; i++) {
            int32_t a[2] = {px[j][i], py[j][i]}, b[2] = {px[j][i + 1], py[j][i + 1]};
            int32_t cc[2] = {px[j + 1][i + 1], py[j + 1][i + 1]}, d[2] = {px[j + 1][i], py[j + 1][i]};
            int32_t tris[2][6];
            if (fx_test_rand(&seed) & 1) {
                int32_t t0[6] = {a[0], a[1], b[0], b[1], cc[0], cc[1]}, t1[6] = {a[0], a[1], cc[0], cc[1], d[0], d[1]};
                memcpy(tris[0], t0, sizeof t0);
                memcpy(tris[1], t1, sizeof t1);
            } else {
                int32_t t0[6] = {a[0], a[1], b[0], b[1], d[0], d[1]}, t1[6] = {b[0], b[1], cc[0], cc[1], d[0], d[1]};
                memcpy(tris[0], t0, sizeof t0);
                memcpy(tris[1], t1, sizeof t1);
            }
            for (int t = 0; t < 2; t++) {
                fx8 v[6];
                for (int k = 0; k < 6; k++)
                    v[k] = s ? tris[t][k] : tris[t][k] * 256;
                fx_tri tr;
                fx_tri_span sp;
                if (fx_tri_begin(&tr, clip, v, 0, 0) > 0)
                    while (fx_tri_next_span(&tr, &sp))
                        for (int x = sp.x0; x < sp.x1; x++)
                            count[sp.y * W + x]++;
            }
        }
    /* the mesh covers x in [-4, 60], y in [-3, 45] at the outer vertices */
    int bad = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int inside = x < 60 && y < 45;
            if (count[y * W + x] != inside)
                bad++;
        }
    FX_CHECK_MSG(bad == 0, "mesh s=%u: %d pixels not covered exactly once", s, bad);
}

FX_TEST(fill_triangle_mesh_covers_each_pixel_once)
{
    for (uint32_t k = 1; k < 40; k++) {
        mesh_test(0, k * 31);
        mesh_test(8, k * 17);
    }
}

FX_TEST(fill_polygon_pair_shares_edge_without_gap)
{
    /* two quads sharing a slanted edge, filled with the polygon path */
    uint32_t seed = 5;
    for (int iter = 0; iter < 200; iter++) {
        int32_t tx = (int32_t)(fx_test_rand(&seed) % 40) + 10, bx = (int32_t)(fx_test_rand(&seed) % 40) + 10;
        int32_t left[8] = {0, 0, tx, 0, bx, 47, 0, 47}, right[8] = {tx, 0, 63, 0, 63, 47, bx, 47};
        static int count[H * W];
        memset(count, 0, sizeof count);
        fx_fill_edge e[8];
        fx_surface sf;
        fx_ctx c;
        for (int side = 0; side < 2; side++) {
            setup(&sf, &c, img);
            int32_t n = 4;
            FX_CHECK_EQ(fx_fill_path(&c, side ? right : left, &n, 1, 0, FX_FILL_NONZERO, e, 8), 0);
            for (int i = 0; i < W * H; i++)
                count[i] += img[i] != 0;
        }
        int bad = 0;
        for (int y = 0; y < 47; y++)
            for (int x = 0; x < 63; x++)
                bad += count[y * W + x] != 1;
        FX_CHECK_EQ(bad, 0);
    }
}

FX_TEST(fill_path_reports_small_table_and_bad_args)
{
    fx_surface sf;
    fx_ctx c;
    setup(&sf, &c, img);
    int32_t sq[8] = {1, 1, 20, 1, 20, 20, 1, 20}, n = 4;
    fx_fill_edge e[2];
    int32_t zig[10] = {0, 0, 10, 10, 20, 0, 20, 30, 0, 30}, nz = 5; /* not y-monotone: needs the table */
    FX_CHECK_EQ(fx_fill_path(&c, zig, &nz, 1, 0, FX_FILL_EVENODD, e, 1), -FX_E2BIG);
    FX_CHECK_EQ(fx_fill_path(&c, sq, &n, 1, 3, FX_FILL_EVENODD, e, 2), -FX_EINVAL);
    setup(&sf, &c, img);
    FX_CHECK_EQ(fx_fill_path(&c, sq, &n, 1, 0, FX_FILL_EVENODD, e, 2), 0);
    FX_CHECK_EQ(img[1 * W + 1], 0xFFFFFF);  /* top-left corner pixel is in */
    FX_CHECK_EQ(img[19 * W + 19], 0xFFFFFF);
    FX_CHECK_EQ(img[20 * W + 19], 0);       /* bottom and right edges are out */
    FX_CHECK_EQ(img[19 * W + 20], 0);
    FX_CHECK_EQ(fx_fill_poly(&c, sq, -1, FX_FILL_EVENODD), -FX_EINVAL);
    /* a square with a hole: two contours */
    setup(&sf, &c, img);
    int32_t two[16] = {0, 0, 30, 0, 30, 30, 0, 30, 10, 10, 20, 10, 20, 20, 10, 20}, cnt[2] = {4, 4};
    fx_fill_edge e8[8];
    FX_CHECK_EQ(fx_fill_path(&c, two, cnt, 2, 0, FX_FILL_EVENODD, e8, 8), 0);
    FX_CHECK_EQ(img[5 * W + 5], 0xFFFFFF);
    FX_CHECK_EQ(img[15 * W + 15], 0);
    /* same orientation: nonzero fills the hole */
    setup(&sf, &c, img);
    FX_CHECK_EQ(fx_fill_path(&c, two, cnt, 2, 0, FX_FILL_NONZERO, e8, 8), 0);
    FX_CHECK_EQ(img[15 * W + 15], 0xFFFFFF);
}

static double exact_attr(const int64_t *vx, const int64_t *vy, const double *a, double x, double y)
{
    double e1x = (double)(vx[1] - vx[0]), e1y = (double)(vy[1] - vy[0]);
    double e2x = (double)(vx[2] - vx[0]), e2y = (double)(vy[2] - vy[0]);
    double px = x - (double)vx[0], py = y - (double)vy[0], ar = e1x * e2y - e1y * e2x;
    double l1 = (px * e2y - py * e2x) / ar, l2 = (e1x * py - e1y * px) / ar;
    return a[0] + (a[1] - a[0]) * l1 + (a[2] - a[0]) * l2;
}

FX_TEST(fill_gouraud_exact_at_vertices_and_linear)
{
    uint32_t seed = 31337;
    for (int iter = 0; iter < 400; iter++) {
        int32_t xy[6];
        fx_color col[3];
        int64_t vx[3], vy[3];
        for (int i = 0; i < 3; i++) {
            vx[i] = xy[2 * i] = (int32_t)(fx_test_rand(&seed) % 70) - 3;
            vy[i] = xy[2 * i + 1] = (int32_t)(fx_test_rand(&seed) % 54) - 3;
            col[i] = 0xFF000000u | (fx_test_rand(&seed) & 0xFFFFFF);
        }
        fx_surface sf;
        fx_ctx c;
        setup(&sf, &c, img);
        memset(img, 0xAB, sizeof img);
        fx_fill_tri_gouraud(&c, xy, col);
        memset(cover_ref, 0, sizeof cover_ref);
        ref_fill(cover_ref, vx, vy, 3, 0, 0, (fx_rect){0, 0, W, H});
        int bad = 0, far = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint32_t p = img[y * W + x];
                if (!cover_ref[y * W + x]) {
                    bad += p != 0xABABABABu;
                    continue;
                }
                for (int ch = 0; ch < 3; ch++) {
                    double a[3] = {(col[0] >> (8 * ch)) & 0xFF, (col[1] >> (8 * ch)) & 0xFF,
                                   (col[2] >> (8 * ch)) & 0xFF};
                    double e = exact_attr(vx, vy, a, x, y);
                    double got = (p >> (8 * ch)) & 0xFF;
                    if (got - e > 0.5001 || e - got > 0.5001)
                        far++;
                }
                for (int v = 0; v < 3; v++)
                    if (x == vx[v] && y == vy[v])
                        bad += (p & 0xFFFFFF) != (col[v] & 0xFFFFFF);
            }
        FX_CHECK_MSG(bad == 0 && far == 0, "gouraud %d: %d wrong, %d off by more than rounding", iter, bad, far);
        if (bad || far)
            return;
    }
}

FX_TEST(fill_tri_attributes_for_3d)
{
    /* a wide attribute (z-like, 2^29) interpolated from sub-pixel vertices */
    fx8 v[6] = {10 * 256 + 77, 3 * 256 + 10, 60 * 256 + 5, 20 * 256 + 128, 20 * 256 + 200, 45 * 256 + 3};
    int32_t attr[6] = {0, -5, 1 << 29, 1000, 12345, 1 << 28};
    fx_tri t;
    FX_CHECK_EQ(fx_tri_begin(&t, (fx_rect){0, 0, W, H}, v, attr, 2), 1);
    int64_t vx[3] = {v[0], v[2], v[4]}, vy[3] = {v[1], v[3], v[5]};
    double a0[3] = {0, 1 << 29, 12345}, a1[3] = {-5, 1000, 1 << 28};
    fx_tri_span s;
    int spans = 0, bad = 0;
    while (fx_tri_next_span(&t, &s)) {
        spans++;
        uint64_t z = fx_tri_attr_at(&t, 0, s.x0, s.y), w = fx_tri_attr_at(&t, 1, s.x0, s.y);
        for (int x = s.x0; x < s.x1; x++) {
            double e0 = exact_attr(vx, vy, a0, x * 256.0, s.y * 256.0);
            double e1 = exact_attr(vx, vy, a1, x * 256.0, s.y * 256.0);
            double g0 = (double)(int64_t)z / 4294967296.0, g1 = (double)(int64_t)w / 4294967296.0;
            if (g0 - e0 > 0.01 || e0 - g0 > 0.01 || g1 - e1 > 0.01 || e1 - g1 > 0.01)
                bad++;
            z += t.gx[0];
            w += t.gx[1];
        }
    }
    FX_CHECK(spans > 20);
    FX_CHECK_EQ(bad, 0);
    /* degenerate and out of range */
    fx8 line[6] = {0, 0, 256, 256, 512, 512};
    FX_CHECK_EQ(fx_tri_begin(&t, (fx_rect){0, 0, W, H}, line, 0, 0), 0);
    fx8 far[6] = {0, 0, 1 << 30, 0, 0, 256};
    FX_CHECK_EQ(fx_tri_begin(&t, (fx_rect){0, 0, W, H}, far, 0, 0), -FX_ERANGE);
}

FX_TEST(fill_honours_blend_and_pattern)
{
    fx_surface sf;
    fx_ctx c;
    setup(&sf, &c, img);
    for (int i = 0; i < W * H; i++)
        img[i] = 0x204080;
    fx_ctx_set_color(&c, 0x80FF0000u);
    c.blend = FX_BLEND_OVER;
    fx_fill_tri(&c, 0, 0, 40, 0, 0, 40);
    FX_CHECK_EQ_HEX(img[1 * W + 1], fx_blend_over(FX_FMT_XRGB8888, 0x204080, 0x80FF0000u));
    FX_CHECK_EQ_HEX(img[45 * W + 60], 0x204080);
    /* checkerboard pattern anchored at (1, 0), transparent background */
    static const uint8_t bits[2] = {0x80, 0x40};
    fx_fill_style st = {.kind = FX_FILL_PATTERN, .bits = bits, .w = 2, .h = 2, .stride = 1, .ax = 1, .ay = 0,
                        .bg_transparent = 1};
    setup(&sf, &c, img);
    c.fill_style = &st;
    fx_ctx_set_color(&c, 0xFF00FF00u);
    int32_t sq[8] = {0, 0, 10, 0, 10, 10, 0, 10};
    FX_CHECK_EQ(fx_fill_poly(&c, sq, 4, FX_FILL_EVENODD), 0);
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++) {
            int on = (((x - 1) & 1) == (y & 1));
            FX_CHECK_EQ_HEX(img[y * W + x], on ? 0x00FF00u : 0u);
        }
}

FX_TEST(fill_spans_exact_at_every_alignment_and_length)
{
    /* rectangles as polygons: every start column and length against the
     * surface's own span writer, in each pixel format, on an odd stride */
    enum { N = 4 * 130 * 3 + 8 };
    static uint32_t a32[N / 4], b32[N / 4];
    uint8_t *a = (uint8_t *)a32, *b = (uint8_t *)b32;
    for (int f = 0; f < FX_FMT_COUNT; f++) {
        int32_t stride = fx_format_min_stride((fx_format)f, 130) + 4;
        int bad = 0;
        for (int x0 = 0; x0 < 40; x0++)
            for (int len = 0; len < 80; len += (len < 20 ? 1 : 7)) {
                memset(a, 0x5A, N);
                memset(b, 0x5A, N);
                fx_surface sa, sb;
                FX_CHECK_EQ(fx_surface_init(&sa, a + 4, 130, 2, stride, (fx_format)f), 0);
                FX_CHECK_EQ(fx_surface_init(&sb, b + 4, 130, 2, stride, (fx_format)f), 0);
                fx_ctx c;
                fx_ctx_init(&c, &sa);
                fx_ctx_set_color(&c, 0xFF123456u + (uint32_t)len);
                int32_t q[8] = {x0, 1, x0 + len, 1, x0 + len, 2, x0, 2};
                fx_fill_poly(&c, q, 4, FX_FILL_EVENODD);
                if (len)
                    fx_span_fill(&sb, 1, x0, x0 + len, c.native);
                bad += memcmp(a, b, N) != 0;
            }
        FX_CHECK_MSG(bad == 0, "format %d: %d spans differ", f, bad);
    }
}

FX_TEST(fill_monotone_fast_path_matches_reference)
{
    /* convex polygons (sorted angles round a centre), y-monotone zigzags
     * and bow-ties, in integers and fx8, clipped or not, both rules */
    uint32_t seed = 1234;
    for (int iter = 0; iter < 800; iter++) {
        unsigned s = iter % 2 ? 8 : 0;
        int one = s ? 256 : 1, nv = 4 + (int)(fx_test_rand(&seed) % 8);
        int32_t xy[24];
        int64_t xs[12], ys[12];
        if (iter % 3 == 0) { /* y-monotone but self-crossing: left and right chains swap */
            for (int i = 0; i < nv; i++) {
                int down = i < nv / 2;
                int k = down ? i : nv - 1 - i;
                xy[2 * i] = (int32_t)(fx_test_rand(&seed) % 80) * one - 8 * one + (int32_t)(fx_test_rand(&seed) % (uint32_t)one);
                xy[2 * i + 1] = (k * 50 / nv - 5 + (down ? 0 : 3)) * one + (int32_t)(fx_test_rand(&seed) % (uint32_t)one);
            }
        } else { /* convex: points on an ellipse at increasing angles */
            int32_t cx = 32 * one, cy = 24 * one, rx = (int32_t)(5 + fx_test_rand(&seed) % 40) * one,
                    ry = (int32_t)(5 + fx_test_rand(&seed) % 30) * one;
            double a = 0;
            for (int i = 0; i < nv; i++) {
                a += 6.2831853 / nv * (0.5 + (fx_test_rand(&seed) % 100) / 100.0);
                if (a > 6.2831853)
                    a = 6.2831853;
                xy[2 * i] = cx + (int32_t)(rx * cos(a));
                xy[2 * i + 1] = cy + (int32_t)(ry * sin(a));
            }
        }
        for (int i = 0; i < nv; i++) {
            xs[i] = xy[2 * i];
            ys[i] = xy[2 * i + 1];
        }
        fx_surface sf;
        fx_ctx c;
        setup(&sf, &c, img);
        fx_rect clip = {0, 0, W, H};
        if (iter % 4 == 3) {
            clip = (fx_rect){9, 7, 41, 30};
            fx_ctx_set_clip(&c, clip);
        }
        int nonzero = (iter >> 2) & 1;
        int r = s ? fx_fill_poly8(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD)
                  : fx_fill_poly(&c, xy, nv, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD);
        FX_CHECK_EQ(r, 0);
        memset(cover_ref, 0, sizeof cover_ref);
        ref_fill(cover_ref, xs, ys, nv, s, nonzero, clip);
        int bad = compare_img(img, 0xFFFFFF);
        FX_CHECK_MSG(bad == 0, "monotone %d (nv %d, s %u): %d pixels differ", iter, nv, s, bad);
        if (bad)
            return;
    }
}

/* The small-polygon path (at most 16 edges, |x| < 2^28, dy << s < 2^30)
 * against the general edge table on the same shapes. Repeating every
 * contour an odd number of times leaves both rules' pixels unchanged (the
 * crossing parity stays, the winding number is multiplied by K) but gives
 * more than 16 edges, which only the general table takes. */
#define SMALL_COPIES 17

static int draw_path(fx_ctx *c, const int32_t *xy, const int32_t *counts, int nc, unsigned s, int nonzero, int copies)
{
    static int32_t bigxy[2 * 16 * SMALL_COPIES], bigcounts[4 * SMALL_COPIES];
    static fx_fill_edge edges[16 * SMALL_COPIES];
    int nv = 0, k = 0;
    for (int i = 0; i < nc; i++)
        nv += counts[i];
    for (int r = 0; r < copies; r++) {
        memcpy(bigxy + 2 * nv * r, xy, sizeof(int32_t) * 2 * (size_t)nv);
        for (int i = 0; i < nc; i++)
            bigcounts[k++] = counts[i];
    }
    return fx_fill_path(c, bigxy, bigcounts, k, s, nonzero ? FX_FILL_NONZERO : FX_FILL_EVENODD, edges,
                        (int32_t)(sizeof edges / sizeof edges[0]));
}

FX_TEST(fill_small_path_matches_general_path_and_reference)
{
    static const fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_RGB565, FX_FMT_RGB888};
    static uint8_t fa[W * H * 4], fb[W * H * 4];
    uint32_t seed = 4242;
    int checked_ref = 0;
    for (int iter = 0; iter < 1500; iter++) {
        unsigned s = iter % 3 == 2 ? 8 : 0;
        int one = s ? 256 : 1, nonzero = (iter >> 1) & 1;
        int nc = iter % 5 == 4 ? 2 : 1, counts[2] = {0, 0}, nv = 0;
        int32_t xy[32];
        int64_t xs[16], ys[16];
        for (int k = 0; k < nc; k++) {
            counts[k] = (nc == 1 ? 4 : 3) + (int)(fx_test_rand(&seed) % (nc == 1 ? 5 : 3));
            /* a W7-like box, partly outside the surface when clipped */
            int32_t bx = (int32_t)(fx_test_rand(&seed) % 40) - 10, by = (int32_t)(fx_test_rand(&seed) % 30) - 8;
            int32_t bw = 10 + (int32_t)(fx_test_rand(&seed) % 50), bh = 8 + (int32_t)(fx_test_rand(&seed) % 40);
            if (iter % 3 == 0) { /* wholly inside: the unclamped bands */
                bx = (int32_t)(fx_test_rand(&seed) % (uint32_t)(W - bw));
                by = (int32_t)(fx_test_rand(&seed) % (uint32_t)(H - bh / 2));
                bh /= 2;
            }
            for (int i = 0; i < counts[k]; i++, nv++) {
                int32_t vx = (bx + (int32_t)(fx_test_rand(&seed) % (uint32_t)bw)) * one +
                             (int32_t)(fx_test_rand(&seed) % (uint32_t)one);
                int32_t vy = (by + (int32_t)(fx_test_rand(&seed) % (uint32_t)bh)) * one +
                             (int32_t)(fx_test_rand(&seed) % (uint32_t)one);
                uint32_t kind = fx_test_rand(&seed) % (iter % 3 == 0 ? 64 : 16);
                if (i > 0 && kind == 0) /* horizontal edge */
                    vy = xy[2 * nv - 1];
                else if (i > 0 && kind == 1) { /* zero-length edge */
                    vx = xy[2 * nv - 2];
                    vy = xy[2 * nv - 1];
                } else if (kind == 2) /* far outside, still within the small limits */
                    vx = (fx_test_rand(&seed) & 1 ? 1 : -1) * (int32_t)(fx_test_rand(&seed) % (1u << 27));
                else if (kind == 3) /* at the limits: one side of each takes the general path */
                    vx = (fx_test_rand(&seed) & 1 ? 1 : -1) * ((1 << 28) - 1 + (int32_t)(fx_test_rand(&seed) % 3));
                else if (kind == 4 && s == 0)
                    vy = (fx_test_rand(&seed) & 1 ? 1 : -1) * ((1 << 29) - 1 + (int32_t)(fx_test_rand(&seed) % 3));
                else if (kind == 5 && s == 8)
                    vy = (fx_test_rand(&seed) & 1 ? 1 : -1) * ((1 << 21) - 1 + (int32_t)(fx_test_rand(&seed) % 3));
                else if (kind == 6) /* edges too tall for 32-bit records */
                    vy = (fx_test_rand(&seed) & 1 ? 1 : -1) *
                         ((1 << (s ? 23 : 30)) + (int32_t)(fx_test_rand(&seed) % (1u << (s ? 22 : 29))));
                else if (kind == 7) /* edges too wide for 32-bit records */
                    vx = (fx_test_rand(&seed) & 1 ? 1 : -1) * ((1 << 30) + (int32_t)(fx_test_rand(&seed) % (1u << 30)));
                xs[nv] = xy[2 * nv] = vx;
                ys[nv] = xy[2 * nv + 1] = vy;
            }
        }
        static const int fsel[4] = {0, 1, 0, 2};
        fx_format f = fmts[fsel[(iter / 3) % 4]];
        fx_rect clip = {0, 0, W, H};
        if (iter % 4 == 3)
            clip = (fx_rect){3 + (int32_t)(fx_test_rand(&seed) % 20), 2 + (int32_t)(fx_test_rand(&seed) % 15), 0, 0};
        if (iter % 4 == 3) {
            clip.x1 = clip.x0 + 1 + (int32_t)(fx_test_rand(&seed) % (uint32_t)(W - clip.x0));
            clip.y1 = clip.y0 + 1 + (int32_t)(fx_test_rand(&seed) % (uint32_t)(H - clip.y0));
        }
        int32_t stride = fx_format_min_stride(f, W);
        fx_surface sa, sb;
        memset(fa, 0x5A, sizeof fa);
        memset(fb, 0x5A, sizeof fb);
        FX_CHECK_EQ(fx_surface_init(&sa, fa, W, H, stride, f), 0);
        FX_CHECK_EQ(fx_surface_init(&sb, fb, W, H, stride, f), 0);
        fx_ctx ca, cb;
        fx_ctx_init(&ca, &sa);
        fx_ctx_init(&cb, &sb);
        fx_ctx_set_clip(&ca, clip);
        fx_ctx_set_clip(&cb, clip);
        fx_ctx_set_color(&ca, 0xFF8040C0u);
        fx_ctx_set_color(&cb, 0xFF8040C0u);
        FX_CHECK_EQ(draw_path(&ca, xy, counts, nc, s, nonzero, 1), 0);
        FX_CHECK_EQ(draw_path(&cb, xy, counts, nc, s, nonzero, SMALL_COPIES), 0);
        int same = memcmp(fa, fb, sizeof fa) == 0;
        FX_CHECK_MSG(same, "iter %d (nv %d, contours %d, s %u, nonzero %d, format %d): small and general paths differ",
                     iter, nv, nc, s, nonzero, (int)f);
        if (!same)
            return;
        if (f == FX_FMT_XRGB8888 && nc == 1) { /* and both against the definition */
            uint32_t *img32 = img;
            for (int y = 0; y < H; y++)
                memcpy(img32 + y * W, fa + (size_t)y * (size_t)stride, 4 * W);
            memset(cover_ref, 0, sizeof cover_ref);
            ref_fill(cover_ref, xs, ys, nv, s, nonzero, clip);
            int bad = 0;
            for (int i = 0; i < W * H; i++)
                bad += ((img32[i] & 0xFFFFFF) == 0x8040C0) != (cover_ref[i] != 0);
            FX_CHECK_MSG(bad == 0, "iter %d: %d pixels differ from the reference", iter, bad);
            if (bad)
                return;
            checked_ref++;
        }
    }
    FX_CHECK(checked_ref > 300);
}

FX_TEST(fill_small_path_spans_at_every_alignment_and_length)
{
    /* two contours (so not the monotone walker): a one-row bar of every
     * start and length, and a far square; 32- and 16-bit runs against the
     * surface's own span writer, guard pixels around the bar untouched */
    enum { N = 4 * 200 * 4 + 8 };
    static uint32_t a32[N / 4], b32[N / 4];
    uint8_t *a = (uint8_t *)a32, *b = (uint8_t *)b32;
    static const fx_format fmts[] = {FX_FMT_XRGB8888, FX_FMT_RGB565};
    for (int fi = 0; fi < 2; fi++) {
        fx_format f = fmts[fi];
        int32_t stride = fx_format_min_stride(f, 200);
        int bad = 0;
        for (int x0 = 0; x0 < 24; x0++)
            for (int len = 0; len < 150; len += (len < 40 ? 1 : 5)) {
                memset(a, 0x5A, N);
                memset(b, 0x5A, N);
                fx_surface sa, sb;
                FX_CHECK_EQ(fx_surface_init(&sa, a, 200, 4, stride, f), 0);
                FX_CHECK_EQ(fx_surface_init(&sb, b, 200, 4, stride, f), 0);
                fx_ctx c;
                fx_ctx_init(&c, &sa);
                fx_ctx_set_color(&c, 0xFF123456u + (uint32_t)len);
                int32_t q[16] = {x0, 1, x0 + len, 1, x0 + len, 2, x0, 2, 190, 0, 195, 0, 195, 3, 190, 3};
                int32_t counts[2] = {4, 4};
                fx_fill_edge edges[8];
                FX_CHECK_EQ(fx_fill_path(&c, q, counts, 2, 0, FX_FILL_EVENODD, edges, 8), 0);
                if (len)
                    fx_span_fill(&sb, 1, x0, x0 + len, c.native);
                for (int y = 0; y < 3; y++)
                    fx_span_fill(&sb, y, 190, 195, c.native);
                bad += memcmp(a, b, N) != 0;
            }
        FX_CHECK_MSG(bad == 0, "format %d: %d spans differ", (int)f, bad);
    }
}

/* Issue #44: the notes' scan-line Gouraud. Their quad with red, green, blue
 * and white corners: along the left edge the middle is (R + W) / 2, along
 * the right (G + B) / 2, so across the middle row the centre is
 * (127.5, 127.5, 127.5) -> (128, 128, 128); the fan cuts along the red-blue
 * diagonal, where it is (R + B) / 2 -> (128, 0, 128). */
FX_TEST(gouraud_scan_is_the_notes_scan_line_rule)
{
    static uint32_t a[32 * 32], b[32 * 32];
    fx_surface sa, sb;
    fx_surface_init(&sa, a, 32, 32, 32 * 4, FX_FMT_XRGB8888);
    fx_surface_init(&sb, b, 32, 32, 32 * 4, FX_FMT_XRGB8888);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &sa);
    fx_ctx_init(&cb, &sb);
    const int32_t quad[8] = {2, 2, 18, 2, 18, 18, 2, 18};
    const fx_color col[4] = {0xFFFF0000u, 0xFF00FF00u, 0xFF0000FFu, 0xFFFFFFFFu};
    memset(a, 0, sizeof a), memset(b, 0, sizeof b);
    FX_CHECK_EQ(fx_fill_poly_gouraud_scan(&ca, quad, col, 4), 0);
    fx_fill_poly_gouraud(&cb, quad, col, 4);
    FX_CHECK_EQ(a[10 * 32 + 10] & 0xFFFFFF, 0x808080u);
    FX_CHECK_EQ(b[10 * 32 + 10] & 0xFFFFFF, 0x800080u);
    /* corners exactly, edges interpolated along: (2,10) is halfway red-white */
    FX_CHECK_EQ(a[2 * 32 + 2] & 0xFFFFFF, 0xFF0000u);
    FX_CHECK_EQ(a[10 * 32 + 2] & 0xFFFFFF, 0xFF8080u);
    FX_CHECK_EQ(a[2 * 32 + 10] & 0xFFFFFF, 0x808000u); /* halfway red-green */
    /* the same pixels as the fan and as fx_fill_poly (top-left rule: 16 x 16) */
    int na = 0, nb = 0, same = 1;
    for (int i = 0; i < 32 * 32; i++) {
        na += a[i] != 0, nb += b[i] != 0;
        same &= (a[i] != 0) == (b[i] != 0);
    }
    FX_CHECK(same && na == 16 * 16 && nb == na);
    /* a triangle is linear either way: the same colours to one level */
    memset(a, 0, sizeof a), memset(b, 0, sizeof b);
    const int32_t tri[6] = {1, 3, 29, 9, 7, 30};
    FX_CHECK_EQ(fx_fill_poly_gouraud_scan(&ca, tri, col + 1, 3), 0);
    fx_fill_tri_gouraud(&cb, tri, col + 1);
    int worst = 0;
    for (int i = 0; i < 32 * 32; i++) {
        FX_CHECK((a[i] != 0) == (b[i] != 0));
        for (int s = 0; s < 24; s += 8) {
            int d = abs((int)((a[i] >> s) & 255) - (int)((b[i] >> s) & 255));
            worst = d > worst ? d : worst;
        }
    }
    FX_CHECK_MSG(worst <= 1, "triangle: worst %d", worst);
    /* bounds */
    FX_CHECK_EQ(fx_fill_poly_gouraud_scan(&ca, quad, col, 2), -FX_EINVAL);
    const int32_t far[6] = {0, 0, FX_GOURAUD_SCAN_COORD + 1, 0, 0, 5};
    FX_CHECK_EQ(fx_fill_poly_gouraud_scan(&ca, far, col, 3), -FX_EINVAL);
    /* off the left edge and at the coordinate limits: the crossings of
     * negative x were shifted left (UB, found by fuzz_grammar); the
     * visible part is the same as fx_fill_poly's */
    const int32_t left[6] = {-14, 0, 30, 2, 5, 30};
    const int32_t huge[6] = {-FX_GOURAUD_SCAN_COORD, -FX_GOURAUD_SCAN_COORD, FX_GOURAUD_SCAN_COORD, 3,
                             -FX_GOURAUD_SCAN_COORD, FX_GOURAUD_SCAN_COORD};
    const int32_t *cases[2] = {left, huge};
    for (int k = 0; k < 2; k++) {
        memset(a, 0, sizeof a), memset(b, 0, sizeof b);
        FX_CHECK_EQ(fx_fill_poly_gouraud_scan(&ca, cases[k], col, 3), 0);
        cb.color = 0xFFFFFFFFu;
        FX_CHECK_EQ(fx_fill_poly(&cb, cases[k], 3, FX_FILL_EVENODD), 0);
        int lit = 0, agree = 1;
        for (int i = 0; i < 32 * 32; i++) {
            lit += a[i] != 0;
            agree &= (a[i] != 0) == (b[i] != 0);
        }
        FX_CHECK_MSG(lit > 0 && agree, "case %d: %d lit", k, lit);
    }
}
