/* SPDX-License-Identifier: MIT */
/* Issue #23's fractals: the turtle, J_c by inverse iteration, fixed points,
 * attracting cycles and basins, box-counting dimensions of the course's
 * figures against their known values, grass, fire and the terrain mesh. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/boxdim.h"
#include "fixel/error.h"
#include "fixel/ifs.h"
#include "fixel/julia.h"
#include "fixel/koch.h"
#include "fixel/randfract.h"
#include "fixel/turtle.h"
#include "fx_test.h"

typedef struct {
    uint8_t *px;
    fx_surface s;
    fx_ctx c;
} canvas;

static void canvas_new(canvas *k, int32_t w, int32_t h)
{
    k->px = calloc((size_t)w * h, 1);
    fx_surface_init(&k->s, k->px, w, h, w, FX_FMT_GRAY8);
    fx_ctx_init(&k->c, &k->s);
    fx_ctx_set_color(&k->c, 0xFFFFFFFFu);
}

static long lit(const canvas *k)
{
    long n = 0;
    for (int32_t i = 0; i < k->s.w * k->s.h; i++)
        n += k->px[i] != 0;
    return n;
}

/* ---- turtle ---- */

FX_TEST(turtle_moves_and_lines)
{
    canvas k;
    canvas_new(&k, 40, 30);
    fx_turtle t;
    fx_turtle_init(&t, &k.c, 5 << 16, 5 << 16, 0);
    fx16 x, y;
    fx_turtle_line_rel(&t, 10 << 16, 0);
    fx_turtle_pos(&t, &x, &y);
    FX_CHECK_EQ(x, 15 << 16);
    FX_CHECK_EQ(y, 5 << 16);
    FX_CHECK_EQ(lit(&k), 11);
    fx_turtle_move_to(&t, 20 << 16, 20 << 16);
    FX_CHECK_EQ(lit(&k), 11); /* moves draw nothing */
    fx_turtle_turn(&t, 90 << 16);
    FX_CHECK_EQ(fx_turtle_heading(&t), 90 << 16);
    fx_turtle_forward(&t, 5 << 16, 1); /* heading 90: towards +y, down the screen (issue #44) */
    fx_turtle_pos(&t, &x, &y);
    FX_CHECK(abs(x - (20 << 16)) <= 2 && abs(y - (25 << 16)) <= 2);
    FX_CHECK(k.px[25 * 40 + 20] && k.px[20 * 40 + 20] && k.px[22 * 40 + 20] && !k.px[15 * 40 + 20]);
    FX_CHECK_EQ(t.segs, 2);
    fx_turtle_forward(&t, 5 << 16, 0);
    FX_CHECK_EQ(t.segs, 2);
    fx_turtle_turn_to(&t, 180 << 16);
    fx_turtle_line_to(&t, 0, 0);
    FX_CHECK_EQ(t.segs, 3);
    free(k.px);
}

FX_TEST(turtle_koch_and_hilbert)
{
    canvas k;
    canvas_new(&k, 760, 300);
    fx_turtle t;
    for (uint32_t n = 0; n <= 6; n++) {
        fx_turtle_init(&t, &k.c, 15 << 16, 20 << 16, 0);
        FX_CHECK_EQ(fx_turtle_koch(&t, 729 << 16, n), 1ull << (2 * n));
        /* the turtle ends one length along its heading, heading unchanged */
        FX_CHECK_MSG(abs(t.x - (744 << 16)) < 256 && abs(t.y - (20 << 16)) < 256, "order %u ends at %d,%d", n,
                     t.x, t.y);
        FX_CHECK_EQ(fx_turtle_heading(&t), 0);
    }
    /* the order-1 peak stands 729 sqrt(3)/6 = 210.4 px from the base, towards
     * +y: below it on the y-down screen (issue #44; above it in course mode) */
    memset(k.px, 0, 760 * 300);
    fx_turtle_init(&t, &k.c, 15 << 16, 20 << 16, 0);
    fx_turtle_koch(&t, 729 << 16, 1);
    FX_CHECK(k.px[(20 + 210) * 760 + 15 + 364] != 0);
    for (int y = 20 + 211; y < 300; y++)
        for (int x = 0; x < 760; x++)
            FX_CHECK(k.px[y * 760 + x] == 0);
    FX_CHECK_EQ(fx_turtle_koch(&t, 1 << 16, FX_TURTLE_MAX_ORDER + 1), 0);
    free(k.px);

    /* Hilbert order 4, step 4: 255 segments through all 16 x 16 cell
     * centres; parity +1 turns towards +y first, down the screen */
    canvas_new(&k, 70, 70);
    fx_turtle_init(&t, &k.c, 2 << 16, 4 << 16, 0);
    FX_CHECK_EQ(fx_turtle_hilbert(&t, 4 << 16, 4, 1), 255);
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            FX_CHECK_MSG(k.px[(4 + 4 * j) * 70 + 2 + 4 * i], "cell %d,%d", i, j);
    FX_CHECK(abs(t.x - (62 << 16)) < 64 && abs(t.y - (4 << 16)) < 64); /* ends at the other top corner */
    free(k.px);
}

/* ---- Julia ---- */

FX_TEST(julia_csqrt_squares_back)
{
    uint32_t st = 99;
    for (int i = 0; i < 20000; i++) {
        int64_t a = (int64_t)(fx_test_rand(&st) % (8u << 28)) - (4 << 28);
        int64_t b = (int64_t)(fx_test_rand(&st) % (8u << 28)) - (4 << 28);
        int64_t u, v;
        fx_csqrt28(a, b, &u, &v);
        FX_CHECK(u >= 0);
        double du = u / 268435456.0, dv = v / 268435456.0;
        double ra = du * du - dv * dv, rb = 2 * du * dv;
        FX_CHECK_MSG(fabs(ra - a / 268435456.0) < 1e-6 && fabs(rb - b / 268435456.0) < 1e-6, "sqrt(%lld, %lld)",
                     (long long)a, (long long)b);
    }
}

static fx56 d56(double v) { return (fx56)llround(v * 72057594037927936.0); }

FX_TEST(julia_fixed_points_classified)
{
    fx_julia_fixed f[2];
    FX_CHECK_EQ(fx_julia_fixed_points(0, 0, f), 0);
    FX_CHECK_EQ(f[0].re, FX56_ONE);
    FX_CHECK_EQ(f[0].kind, FX_FIXED_REPELLING);
    FX_CHECK_EQ(f[0].mult, 2 * FX16_ONE);
    FX_CHECK_EQ(f[1].re, 0);
    FX_CHECK_EQ(f[1].kind, FX_FIXED_ATTRACTING);
    /* c = -1: the golden ratio and its conjugate, both repelling */
    fx_julia_fixed_points(-FX56_ONE, 0, f);
    FX_CHECK(fabs(f[0].re / 72057594037927936.0 - 1.6180339887) < 1e-7);
    FX_CHECK(fabs(f[1].re / 72057594037927936.0 + 0.6180339887) < 1e-7);
    FX_CHECK(f[0].kind == FX_FIXED_REPELLING && f[1].kind == FX_FIXED_REPELLING);
    /* c = 1/4: the parabolic double point 1/2 */
    fx_julia_fixed_points(FX56_ONE / 4, 0, f);
    FX_CHECK(f[0].kind == FX_FIXED_NEUTRAL && f[1].kind == FX_FIXED_NEUTRAL);
    /* c = 0.2 + 0.1i: z = 1/2 - sqrt(0.05 - 0.1i) attracts */
    fx_julia_fixed_points(d56(0.2), d56(0.1), f);
    FX_CHECK(f[1].kind == FX_FIXED_ATTRACTING && f[0].kind == FX_FIXED_REPELLING);
    FX_CHECK_EQ(fx_julia_fixed_points(3 * FX56_ONE, 0, f), -FX_EINVAL);
}

FX_TEST(julia_attracting_cycles)
{
    fx_julia_cycle cy;
    FX_CHECK_EQ(fx_julia_attractor(0, 0, &cy), 1);
    FX_CHECK(llabs(cy.re[0]) < 16 && llabs(cy.im[0]) < 16);
    FX_CHECK_EQ(fx_julia_attractor(-FX56_ONE, 0, &cy), 2); /* the basilica: 0 <-> -1 */
    /* one point is 0, the other -1 (Q4.28), both on the real axis */
    FX_CHECK(llabs(cy.re[0]) < 16 || llabs(cy.re[1]) < 16);
    FX_CHECK(llabs(cy.re[0] + cy.re[1] + (1 << 28)) < 32);
    FX_CHECK(llabs(cy.im[0]) < 16 && llabs(cy.im[1]) < 16);
    FX_CHECK_EQ(fx_julia_attractor(d56(-0.123), d56(0.745), &cy), 3); /* Douady's rabbit */
    FX_CHECK_EQ(fx_julia_attractor(d56(0.5), 0, &cy), 0);             /* outside M */
    FX_CHECK_EQ(fx_julia_attractor(0, FX56_ONE, &cy), 0);             /* c = i: a dendrite */
}

/* Every pixel inverse iteration lights is next to both K_c and its outside
 * (it lies on the boundary J_c). */
FX_TEST(julia_inverse_iteration_on_boundary)
{
    const int32_t w = 160, h = 120;
    fx_fractal_view v = fx_julia_view(0, 0, -FX56_ONE, 0, 4 * FX56_ONE, w, h, 400);
    v.precision = 64;
    uint32_t *d = malloc(sizeof *d * w * h);
    FX_CHECK_EQ(fx_fractal_dwell(&v, (fx_rect){0, 0, w, h}, d, w), 0);
    canvas k;
    canvas_new(&k, w, h);
    int32_t hits = fx_julia_inverse_random(&k.c, &v, 50000, 3);
    FX_CHECK_EQ(hits, 50001);
    long on = 0, n = 0;
    for (int32_t y = 2; y < h - 2; y++)
        for (int32_t x = 2; x < w - 2; x++) {
            if (!k.px[y * w + x])
                continue;
            int in = 0, out = 0;
            for (int dy = -2; dy <= 2; dy++)
                for (int dx = -2; dx <= 2; dx++) {
                    uint32_t dw = d[(y + dy) * w + x + dx];
                    in += dw == 400;
                    out += dw < 400;
                }
            n++;
            on += in && out;
        }
    FX_CHECK(n > 400);
    FX_CHECK_MSG(on * 100 >= n * 99, "%ld of %ld lit pixels on the boundary", on, n);
    /* the tree: 2^(depth+1) - 1 points, all inside this view */
    memset(k.px, 0, (size_t)w * h);
    FX_CHECK_EQ(fx_julia_inverse_tree(&k.c, &v, 12), (1 << 13) - 1);
    FX_CHECK_EQ(fx_julia_inverse_tree(&k.c, &v, FX_JULIA_MAX_DEPTH + 1), -FX_EINVAL);
    fx_fractal_view bad = v;
    bad.jre = 3 * FX56_ONE;
    FX_CHECK_EQ(fx_julia_inverse_random(&k.c, &bad, 10, 1), -FX_EINVAL);
    free(k.px);
    free(d);
}

FX_TEST(julia_basins_coloured)
{
    const int32_t w = 160, h = 120;
    uint32_t px[160 * 120];
    fx_surface s;
    fx_surface_init(&s, px, w, h, w * 4, FX_FMT_XRGB8888);
    uint32_t lut[2] = {0x111111, 0x222222};
    fx_dwell_pal pal = {lut, 2, 65536, 0, 0x333333};
    const fx_color basin[3] = {0xFF0000FFu, 0xFF00FF00u, 0xFFFF0000u};
    fx_fractal_view v = fx_julia_view(0, 0, -FX56_ONE, 0, 4 * FX56_ONE, w, h, 300);
    FX_CHECK_EQ(fx_julia_basins(&s, (fx_rect){0, 0, w, h}, &v, &pal, basin, 3), 2);
    int32_t x0, y0, x1, y1, xe, ye;
    fx_julia_to_pixel(&v, 0, 0, &x0, &y0);
    fx_julia_to_pixel(&v, -FX56_ONE, 0, &x1, &y1);
    fx_julia_to_pixel(&v, d56(1.9), d56(1.2), &xe, &ye);
    uint32_t a = px[y0 * w + x0], b = px[y1 * w + x1];
    /* z = 0 and z = -1 lie in the two immediate basins: different basin
     * colours (their pixels' centres are a step or two from the cycle) */
    FX_CHECK(a != b);
    int ablue = (a & 0xFFFF00) == 0 && a, agreen = (a & 0xFF00FF) == 0 && a;
    int bblue = (b & 0xFFFF00) == 0 && b, bgreen = (b & 0xFF00FF) == 0 && b;
    FX_CHECK_MSG((ablue && bgreen) || (agreen && bblue), "%06x %06x", a, b);
    FX_CHECK(px[ye * w + xe] == 0x111111 || px[ye * w + xe] == 0x222222);
    /* the basilica's basins: every pixel is escape, a basin colour (possibly
     * dimmed) or inside; both basins are large */
    long na = 0, nb = 0;
    for (int i = 0; i < w * h; i++) {
        na += (px[i] & 0xFFFF00) == 0 && px[i] != 0;
        nb += (px[i] & 0xFF00FF) == 0 && px[i] != 0;
    }
    FX_CHECK(na > 800 && nb > 800);
    /* c = 0.5 is outside M: no cycle, no basin colour anywhere */
    v.jre = FX56_ONE / 2;
    FX_CHECK_EQ(fx_julia_basins(&s, (fx_rect){0, 0, w, h}, &v, &pal, basin, 3), 0);
    for (int i = 0; i < w * h; i++)
        FX_CHECK(px[i] == 0x111111 || px[i] == 0x222222 || px[i] == 0x333333);
}

/* ---- box counting ---- */

FX_TEST(boxdim_log2_and_fit)
{
    FX_CHECK_EQ(fx_log2_16(1), 0);
    FX_CHECK_EQ(fx_log2_16(8), 3 << 16);
    FX_CHECK_EQ(fx_log2_16(1ull << 40), 40 << 16);
    for (uint64_t v = 2; v < 100000; v = v * 3 + 1)
        FX_CHECK_MSG(fabs(fx_log2_16(v) / 65536.0 - log2((double)v)) < 1.0 / 32768, "log2 %llu", (unsigned long long)v);
    /* N = s^-2 exactly: slope 2 */
    int32_t sz[4] = {1, 2, 4, 8}, ct[4] = {4096, 1024, 256, 64};
    fx16 d;
    FX_CHECK_EQ(fx_boxdim_fit(sz, ct, 4, &d), 0);
    FX_CHECK_EQ(d, 2 << 16);
    /* the Koch counts 4^k at sizes 3^-k: log 4 / log 3 */
    int32_t ks[4] = {81, 27, 9, 3}, kc[4] = {1, 4, 16, 64};
    FX_CHECK_EQ(fx_boxdim_fit(ks, kc, 4, &d), 0);
    FX_CHECK_MSG(abs(d - 82697) <= 2, "%d", d); /* 1.261860 * 65536 = 82697.4 */
    int32_t same[2] = {4, 4};
    FX_CHECK_EQ(fx_boxdim_fit(same, ct, 2, &d), -FX_EINVAL);
}

static double measure(const canvas *k, int32_t smin, int32_t smax)
{
    fx16 d = 0;
    FX_CHECK_EQ(fx_boxdim_surface(&k->s, fx_surface_rect(&k->s), 0, smin, smax, &d, NULL, NULL), 0);
    return d / 65536.0;
}

/* The course's figures against their known dimensions, boxes of 2..64 px.
 * Tolerances: the pictures are finite (Koch order 6, 1-px pieces), so the
 * smallest and largest boxes see pixels and the whole figure. */
FX_TEST(boxdim_known_figures)
{
    canvas k;
    canvas_new(&k, 760, 300);
    /* bumps turn from +x towards +y (issue #44's one angle rule): below
     * the base line on the y-down canvas, so the base is near the top */
    fx_koch(&k.c, 15, 20, 15 + 729, 20, 6);
    double dk = measure(&k, 2, 64);
    FX_CHECK_MSG(fabs(dk - log(4) / log(3)) < 0.05, "Koch %.4f", dk);
    free(k.px);

    canvas_new(&k, 256, 256);
    fx_hilbert(&k.c, 0, 0, 256, 7);
    double dh = measure(&k, 2, 64);
    FX_CHECK_MSG(fabs(dh - 2) < 0.02, "Hilbert %.4f", dh);
    /* a coarse order does not fill the plane yet at these scales */
    memset(k.px, 0, 256 * 256);
    fx_hilbert(&k.c, 0, 0, 256, 4);
    FX_CHECK(measure(&k, 2, 64) < 1.8);
    free(k.px);

    canvas_new(&k, 243, 243);
    fx_peano(&k.c, 0, 0, 243, 5);
    double dp = measure(&k, 2, 64);
    /* 243 px: the boxes of 2^k px overhang its edge, which costs ~0.035 */
    FX_CHECK_MSG(fabs(dp - 2) < 0.045, "Peano %.4f", dp);
    free(k.px);

    canvas_new(&k, 512, 512);
    fx_ifs_chaos(&k.c, (fx_rect){0, 0, 512, 512}, &fx_ifs_sierpinski, 400000, 1);
    double ds = measure(&k, 2, 64);
    FX_CHECK_MSG(fabs(ds - log(3) / log(2)) < 0.03, "Sierpinski %.4f", ds);
    free(k.px);
}

/* The expected dimension of fract() with beta = 1 (each piece splits into
 * two of relative length sqrt(1/4 + t^2), t ~ N(0, sd^2), at every scale):
 * D solves 2 E[(1/4 + t^2)^(D/2)] = 1 (a random self-similar curve). */
static double moran(double sd)
{
    double lo = 1, hi = 3;
    for (int it = 0; it < 50; it++) {
        double m = (lo + hi) / 2, e = 0, wsum = 0;
        for (int i = 0; i <= 2000; i++) {
            double t = -6 * sd + 12 * sd * i / 2000, g = exp(-t * t / (2 * sd * sd));
            e += g * pow(0.25 + t * t, m / 2);
            wsum += g;
        }
        if (2 * e / wsum > 1)
            lo = m;
        else
            hi = m;
    }
    return lo;
}

FX_TEST(boxdim_coastline)
{
    canvas k;
    canvas_new(&k, 1024, 1024);
    const int32_t sq[8] = {200, 200, 824, 200, 824, 824, 200, 824};
    for (int sd = 20; sd <= 30; sd += 10) {
        double sum = 0;
        for (uint32_t seed = 1; seed <= 3; seed++) {
            memset(k.px, 0, 1024 * 1024);
            fx_fract_params p = {FX16_ONE, sd * 65536 / 100, 1, seed};
            fx_coastline(&k.c, sq, 4, &p);
            sum += measure(&k, 2, 64);
        }
        double want = moran(sd / 100.0);
        FX_CHECK_MSG(fabs(sum / 3 - want) < 0.06, "sd %d: %.4f, expected %.4f", sd, sum / 3, want);
    }
    /* a larger beta damps the small scales: a smoother, lower-dimensional coast */
    double d12 = 0, d18 = 0;
    for (int b = 0; b < 2; b++) {
        memset(k.px, 0, 1024 * 1024);
        fx_fract_params p = {b ? 117965 : 78643, 19661, 1, 4};
        fx_coastline(&k.c, sq, 4, &p);
        *(b ? &d18 : &d12) = measure(&k, 2, 64);
    }
    FX_CHECK_MSG(d12 > d18 + 0.03 && d18 >= 0.98, "beta 1.2: %.4f, 1.8: %.4f", d12, d18);
    free(k.px);
}

/* ---- grass, fire, terrain ---- */

FX_TEST(grass_reproducible_inside)
{
    canvas a, b;
    canvas_new(&a, 200, 120);
    canvas_new(&b, 200, 120);
    fx_rect r = {20, 30, 180, 110};
    int32_t sa = fx_grass(&a.c, r, 60, 7), sb = fx_grass(&b.c, r, 60, 7);
    FX_CHECK_EQ(sa, sb);
    FX_CHECK(sa >= 60 * 8 && sa <= 60 * 248);
    FX_CHECK(memcmp(a.px, b.px, 200 * 120) == 0);
    /* nothing below the root row; blades grow upward from it */
    for (int y = 110; y < 120; y++)
        for (int x = 0; x < 200; x++)
            FX_CHECK(a.px[y * 200 + x] == 0);
    long bottom = 0, top = 0;
    for (int x = 0; x < 200; x++) {
        bottom += a.px[100 * 200 + x] != 0;
        top += a.px[40 * 200 + x] != 0;
    }
    FX_CHECK(bottom > top);
    memset(b.px, 0, 200 * 120);
    fx_grass(&b.c, r, 60, 8);
    FX_CHECK(memcmp(a.px, b.px, 200 * 120) != 0);
    FX_CHECK_EQ(fx_grass(&a.c, r, FX_GRASS_MAX_BLADES + 1, 1), -FX_EINVAL);
    free(a.px);
    free(b.px);
}

FX_TEST(fire_hot_at_the_foot)
{
    uint32_t px[120 * 100];
    fx_surface s;
    fx_surface_init(&s, px, 120, 100, 480, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    for (int i = 0; i < 120 * 100; i++)
        px[i] = 0x000040;
    fx_rect r = {10, 10, 110, 100};
    FX_CHECK_EQ(fx_fire(&c, r, 39322, 3), 0);
    long heat_lo = 0, heat_hi = 0;
    for (int y = 0; y < 100; y++)
        for (int x = 0; x < 120; x++) {
            uint32_t p = px[y * 120 + x];
            int in = x >= 10 && x < 110 && y >= 10;
            if (!in)
                FX_CHECK(p == 0x000040);
            /* fire colours: red >= green >= blue */
            if (p != 0x000040)
                FX_CHECK((p >> 16 & 255) >= (p >> 8 & 255) && (p >> 8 & 255) >= (p & 255));
            long v = (p >> 16 & 255) + (p >> 8 & 255) + (p & 255);
            if (y >= 88)
                heat_lo += v;
            else if (y >= 10 && y < 22)
                heat_hi += v;
        }
    FX_CHECK(heat_lo > 3 * heat_hi);
    FX_CHECK_EQ(fx_fire_color(0), 0xFF000000u);
    FX_CHECK_EQ(fx_fire_color(255), 0xFFFFFFFFu);
    FX_CHECK_EQ(fx_fire(&c, r, 2 * FX16_ONE, 3), -FX_EINVAL);
}

FX_TEST(terrain_mesh_faces_up)
{
    enum { K = 4, N = 17 };
    int32_t h[N * N];
    FX_CHECK_EQ(fx_terrain(h, N, K, 1000, 45875, 5), 0);
    FX_CHECK_EQ(fx_terrain_peak(h, N, K, 3000), 0);
    int32_t nv, nt;
    FX_CHECK_EQ(fx_terrain_mesh_size(K, &nv, &nt), 0);
    FX_CHECK_EQ(nv, N * N);
    FX_CHECK_EQ(nt, 2 * 16 * 16);
    fx_vec3 pos[N * N], nrm[N * N];
    uint32_t tri[3 * 512], col[N * N];
    fx_mesh m = {pos, nrm, tri, 0, 0, N * N, 512, NULL, col};
    FX_CHECK_EQ(fx_terrain_mesh(&m, h, N, K, 4 << 16, 1 << 16, 13107), 0);
    FX_CHECK_EQ(m.ntris, 512);
    fx16 top = 0;
    for (int i = 0; i < nv; i++) {
        top = pos[i].y > top ? pos[i].y : top;
        FX_CHECK(pos[i].y >= 13107 / 1 * 1 - 1 && pos[i].y <= (1 << 16));
        FX_CHECK(nrm[i].y > 0);
        /* water exactly at the sea's level */
        if (col[i] == 0xFF1E4A8Cu)
            FX_CHECK(pos[i].y == 13107);
    }
    FX_CHECK_EQ(top, 1 << 16);
    for (int t = 0; t < nt; t++) {
        fx_vec3 a = pos[tri[3 * t]], b = pos[tri[3 * t + 1]], c = pos[tri[3 * t + 2]];
        int64_t ux = b.x - a.x, uz = b.z - a.z, vx = c.x - a.x, vz = c.z - a.z;
        FX_CHECK(uz * vx - ux * vz > 0); /* (b - a) x (c - a) has y > 0 */
    }
    /* the peak: the centre is higher than the corners */
    FX_CHECK(pos[8 * N + 8].y > pos[0].y && pos[8 * N + 8].y > pos[N * N - 1].y);
    FX_CHECK(fx_terrain_color(0) != fx_terrain_color(1 << 16));
    FX_CHECK_EQ(fx_terrain_color(1 << 16), 0xFFFFFFFFu);
}

/* ---- collage and fractal compression ---- */

#include "fixel/collage.h"

/* The right-angled Sierpinski triangle (Pascal's triangle mod 2) on a
 * 64-cell grid drawn n px wide: cell (u, v), v up, is in it when u & v == 0. */
static void sierpinski_bitmap(uint8_t *t, int32_t n)
{
    for (int32_t y = 0; y < n; y++)
        for (int32_t x = 0; x < n; x++) {
            int32_t u = x * 64 / n, v = (n - 1 - y) * 64 / n;
            t[y * n + x] = (u & v) == 0;
        }
}

FX_TEST(collage_finds_sierpinski)
{
    enum { N = 96 };
    uint8_t t[N * N], work[N * N];
    sierpinski_bitmap(t, N);
    fx_collage_result res;
    int n = fx_collage_search(t, N, N, 8, work, &res);
    /* three maps of ratio 1/2 at (0, 0), (1/2, 0) and (0, 1/2) of the
     * right-angled triangle, and a collage equal to the target */
    FX_CHECK_EQ(n, 3);
    FX_CHECK_EQ(res.missed + res.extra, 0);
    int found[3] = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        FX_CHECK(res.maps[i].ax_den == 2 && res.maps[i].ay_den == 2);
        int k = res.maps[i].ex == 0 && res.maps[i].ey == 6 ? 0 : res.maps[i].ex == 6 && res.maps[i].ey == 6 ? 1
              : res.maps[i].ex == 0 && res.maps[i].ey == 0 ? 2 : -1;
        FX_CHECK(k >= 0);
        if (k >= 0)
            found[k]++;
    }
    FX_CHECK(found[0] == 1 && found[1] == 1 && found[2] == 1);
    /* a wrong map costs: the distance counts the missed and the extra pixels */
    fx_collage_map bad[3] = {res.maps[0], res.maps[1], {2, 2, 6, 0}};
    FX_CHECK(fx_collage_distance(t, N, N, bad, 3, work, &res) > 0);
    FX_CHECK(res.extra > 0);
    /* the IFS of the maps draws the triangle back by the chaos game */
    fx_ifs_map im[3];
    fx_ifs ifs;
    fx_collage_to_ifs(res.maps, 2, im, &ifs);
    FX_CHECK_EQ(fx_ifs_check(&ifs), 0);
    fx_collage_search(t, N, N, 8, work, &res);
    fx_collage_to_ifs(res.maps, res.n, im, &ifs);
    FX_CHECK_EQ(fx_ifs_check(&ifs), 0);
    canvas k;
    canvas_new(&k, N, N);
    fx_ifs_chaos(&k.c, (fx_rect){0, 0, N, N}, &ifs, 60000, 1);
    long off = 0, on = 0;
    for (int i = 0; i < N * N; i++) {
        off += k.px[i] && !t[i];
        on += k.px[i] && t[i];
    }
    FX_CHECK_MSG(off * 100 <= on, "%ld of %ld chaos points off the target", off, on + off);
    free(k.px);
    FX_CHECK_EQ(fx_collage_search(t, 100, 96, 8, work, &res), -FX_EINVAL);
}

static void test_picture(uint8_t *img, int32_t n)
{
    /* a lit sphere on a diagonal ramp with a dark stripe: edges, a
     * gradient, smooth shading */
    for (int32_t y = 0; y < n; y++)
        for (int32_t x = 0; x < n; x++) {
            int32_t v = 40 + (x + y) * 100 / (2 * n);
            int32_t dx = x - n / 2, dy = y - n / 2, r2 = dx * dx + dy * dy, R = n / 3;
            if (r2 < R * R)
                v = 255 - r2 * 150 / (R * R) - (dx + dy) * 40 / n;
            if (x > n / 8 && x < n / 8 + 3)
                v = 10;
            img[y * n + x] = (uint8_t)v;
        }
}

FX_TEST(fic_round_trip_psnr)
{
    enum { N = 64 };
    uint8_t img[N * N], out[N * N], tmp[N * N];
    fx_fic_code codes[(N / 4) * (N / 4)];
    test_picture(img, N);
    FX_CHECK_EQ(fx_fic_encode(img, N, codes), 0);
    FX_CHECK_EQ(fx_fic_decode(codes, N, 10, out, tmp), 0);
    fx16 p10 = fx_psnr(img, out, N * N);
    /* measured 10 log10(255^2 / MSE) in floating point agrees */
    double sse = 0;
    for (int i = 0; i < N * N; i++)
        sse += (double)(img[i] - out[i]) * (img[i] - out[i]);
    double want = 10 * log10(65025.0 * N * N / sse);
    FX_CHECK_MSG(fabs(p10 / 65536.0 - want) < 0.01, "psnr %.3f vs %.3f", p10 / 65536.0, want);
    FX_CHECK_MSG(p10 > 28 * 65536, "PSNR %.2f dB after 10 rounds", p10 / 65536.0);
    /* one round from flat grey is far worse: the decoder converges */
    FX_CHECK_EQ(fx_fic_decode(codes, N, 1, out, tmp), 0);
    fx16 p1 = fx_psnr(img, out, N * N);
    FX_CHECK(p1 + 5 * 65536 < p10);
    /* converged: another ten rounds change next to nothing */
    FX_CHECK_EQ(fx_fic_decode(codes, N, 20, out, tmp), 0);
    FX_CHECK(abs(fx_psnr(img, out, N * N) - p10) < 65536 / 4);
    FX_CHECK_EQ(fx_psnr(img, img, N * N), INT32_MAX);
    /* contractive codes only */
    codes[3].s = 16;
    FX_CHECK_EQ(fx_fic_decode(codes, N, 1, out, tmp), -FX_EINVAL);
    FX_CHECK_EQ(fx_fic_encode(img, 60, codes), -FX_EINVAL);
}

/* ---- through the scene: the trace path prints what the commands measured ---- */

#include <stdio.h>
#include "fixel/scene.h"
#include "scenebuf.h"

typedef struct {
    scene_buf b; /* first: scene_buf_make's user */
    char log[8192];
    size_t len;
} traced;

static void keep_line(void *user, const char *line)
{
    traced *t = user;
    /* only the commands' reports: the line drawing traces its every step */
    static const char *const keep[] = {"boxdim:", "turtle:", "julia", "collage:", "fractcompress:", "orbit:"};
    int want = 0;
    for (unsigned i = 0; i < sizeof keep / sizeof keep[0]; i++)
        want |= strncmp(line, keep[i], strlen(keep[i])) == 0;
    if (!want)
        return;
    int n = snprintf(t->log + t->len, sizeof t->log - t->len, "%s\n", line);
    if (n > 0 && t->len + (size_t)n < sizeof t->log)
        t->len += (size_t)n;
}

static int run_traced(traced *t, const char *script, fx_scene *sc)
{
    static uint32_t mem[800 * 300];
    static uint8_t arena[1 << 20];
    t->b.mem = mem;
    t->b.n = 800 * 300;
    t->len = 0;
    t->log[0] = 0;
    fx_scene_host h = {t, scene_buf_make, NULL, NULL, keep_line, NULL};
    fx_scene_init(sc, &h, arena, sizeof arena);
    return fx_scene_run(sc, script, strlen(script));
}

FX_TEST(scene_boxdim_and_turtle_report)
{
    traced t;
    fx_scene sc;
    FX_CHECK_EQ(run_traced(&t,
                           "size 760 300\nclear #000000\ncolor #FFFFFF\nkoch 15 20 744 20 6\n"
                           "boxdim 0 0 760 300 #000000 2 64 1.2619\n",
                           &sc),
                0);
    /* D = 1.29.. against 1.2619: within 0.05 (boxdim_known_figures) */
    const char *d = strstr(t.log, "boxdim: D = ");
    FX_CHECK_MSG(d != NULL, "%s", t.log);
    double v = d ? atof(d + 12) : 0;
    FX_CHECK_MSG(fabs(v - 1.2619) < 0.05, "%s", t.log);
    FX_CHECK(strstr(t.log, "known 1.2619") != NULL);
    FX_CHECK(strstr(t.log, "boxdim: box 64 px:") != NULL);
    /* nothing drawn: a clear error, not a dimension */
    FX_CHECK_EQ(run_traced(&t, "size 64 64\nclear #000000\nboxdim 0 0 64 64 #000000 2 16\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "background") != NULL, "%s", sc.err);
    FX_CHECK_EQ(run_traced(&t, "size 64 64\nboxdim 0 0 64 64 #000000 8 8\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "two box sizes") != NULL, "%s", sc.err);

    /* the turtle keeps its state from line to line */
    FX_CHECK_EQ(run_traced(&t,
                           "size 64 64\nturtle home 10 50 0\nturtle forward 20\nturtle turn 90\n"
                           "turtle forward 10\nturtle linerel -5 0\nturtle where\n",
                           &sc),
                0);
    FX_CHECK_MSG(strstr(t.log, "turtle: CP (25.0000, 60.0000) heading 90.0000, 3 segments") != NULL, "%s", t.log);
    FX_CHECK_EQ(run_traced(&t, "turtle koch 10 11\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "0..10") != NULL, "%s", sc.err);

    /* fixed points and cycle through the trace */
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njuliafixed 0 0 0 0 3\njuliabasins 0 0 -1 0 3 100\n", &sc), 0);
    FX_CHECK_MSG(strstr(t.log, "z1 = 1.0000 0.0000 i, |2z| = 2.0000, repelling") != NULL, "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "z2 = 0.0000 0.0000 i, |2z| = 0.0000, attracting") != NULL, "%s", t.log);
    FX_CHECK(strstr(t.log, "attracting cycle of period 2") != NULL);
    FX_CHECK_EQ(run_traced(&t, "juliaset random 0 0 2.5 0 3 100 1\n", &sc), -FX_EINVAL);

    /* collage and compression report their measures */
    FX_CHECK_EQ(run_traced(&t,
                           "size 200 100\nclear #000000\ncolor #FFFFFF\nifs sierpinski chaos 0 0 96 96 40000 1\n"
                           "collage 0 0 96 #000000 8 100 0 1000 1\nfractcompress 0 0 64 100 0 8\n",
                           &sc),
                0);
    FX_CHECK_MSG(strstr(t.log, "collage: 3 maps; distance 0 px") != NULL, "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "fractcompress: 64x64 grey, 256 range blocks") != NULL, "%s", t.log);
    FX_CHECK(strstr(t.log, "PSNR ") != NULL);
    FX_CHECK_EQ(run_traced(&t, "size 64 64\nfractcompress 0 0 72 0 0 8\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "not inside") != NULL, "%s", sc.err);
}

/* Issue #40: |INT64_MIN| overflowed the range checks (INT64_MIN passed
 * them as a negative "magnitude") and Q8.56 -> Q4.28 rounding overflowed
 * near INT64_MAX. Both ends are refused or mapped to the far side. */
FX_TEST(julia_int64_corners)
{
    const int64_t bad[] = {INT64_MIN, INT64_MIN + 1, INT64_MAX};
    fx_julia_fixed fp[2];
    fx_julia_cycle cyc;
    for (int i = 0; i < 3; i++) {
        FX_CHECK_EQ(fx_julia_fixed_points(bad[i], 0, fp), -FX_EINVAL);
        FX_CHECK_EQ(fx_julia_fixed_points(0, bad[i], fp), -FX_EINVAL);
        FX_CHECK_EQ(fx_julia_attractor(bad[i], 0, &cyc), -FX_EINVAL);
        FX_CHECK_EQ(fx_julia_attractor(0, bad[i], &cyc), -FX_EINVAL);
        fx_fractal_view v = fx_julia_view(0, 0, bad[i], 0, 4 * FX56_ONE, 64, 64, 50);
        FX_CHECK_EQ(fx_fractal_check(&v), -FX_EINVAL);
        FX_CHECK_EQ(fx_julia_check(&v), -FX_EINVAL);
        v = fx_julia_view(0, 0, 0, bad[i], 4 * FX56_ONE, 64, 64, 50);
        FX_CHECK_EQ(fx_julia_check(&v), -FX_EINVAL);
        v = fx_julia_view(bad[i], 0, 0, 0, 4 * FX56_ONE, 64, 64, 50);
        FX_CHECK_EQ(fx_fractal_check(&v), -FX_EINVAL);
    }
    fx_fractal_view v = fx_julia_view(0, 0, -FX56_ONE, 0, 4 * FX56_ONE, 64, 64, 50);
    int32_t x, y;
    /* +-128 (the ends of Q8.56) at 16 pixels per unit: 2048 pixels out */
    fx_julia_to_pixel(&v, INT64_MAX, INT64_MIN, &x, &y);
    FX_CHECK(x == 32 + 2048 && y == 32 + 2048);
    fx_julia_to_pixel(&v, INT64_MIN, INT64_MAX, &x, &y);
    FX_CHECK(x == 32 - 2048 && y == 32 - 2048);
    fx_julia_to_pixel(&v, 0, 0, &x, &y); /* the centre */
    FX_CHECK(x == 32 && y == 32);
}

/* Issue #44: c may come first as c=RE,IM, which cannot be taken for the
 * view's centre; it draws and reports exactly what the positional form does
 * with the same centre and c. */
FX_TEST(julia_c_first_form)
{
    static const char *const pairs[][2] = {
        {"julia 0 0 -0.123 0.745 3 40\n", "julia c=-0.123,0.745 0 0 3 40\n"},
        {"juliaset random 0.1 0 -1 0 3 4000 7\n", "juliaset random c=-1,0 0.1 0 3 4000 7\n"},
        {"juliaset tree 0 0 -0.123 0.745 3 9\n", "juliaset tree c=-0.123,0.745 0 0 3 9\n"},
        {"juliafixed 0 0 -0.75 0.1 3\n", "juliafixed c=-0.75,0.1 0 0 3\n"},
        {"juliabasins 0 0 -0.123 0.745 3 60\n", "juliabasins c=-0.123,0.745 0 0 3 60\n"},
    };
    static uint32_t first[120 * 80];
    static char log0[8192];
    for (unsigned i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        traced t;
        fx_scene sc;
        char s[200];
        snprintf(s, sizeof s, "size 120 80\nclear #000000\ncolor #FFFFFF\n%s", pairs[i][0]);
        FX_CHECK_EQ(run_traced(&t, s, &sc), 0);
        memcpy(first, t.b.mem, sizeof first);
        snprintf(log0, sizeof log0, "%s", t.log);
        int lit = 0;
        for (int k = 0; k < 120 * 80; k++)
            lit += first[k] != 0xFF000000u && first[k] != 0;
        snprintf(s, sizeof s, "size 120 80\nclear #000000\ncolor #FFFFFF\n%s", pairs[i][1]);
        FX_CHECK_EQ(run_traced(&t, s, &sc), 0);
        FX_CHECK_MSG(memcmp(first, t.b.mem, sizeof first) == 0 && lit > 20, "%s: differs (%d lit)", pairs[i][1], lit);
        FX_CHECK_MSG(strcmp(log0, t.log) == 0, "%s\n%s", log0, t.log);
    }
    /* the worked numbers: c = -0.75 + 0.1i has fixed points z = 1/2 +- sqrt(1/4 - c) */
    traced t;
    fx_scene sc;
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njuliafixed c=-0.75,0 0 0 3\n", &sc), 0);
    FX_CHECK_MSG(strstr(t.log, "z1 = 1.5000 0.0000 i, |2z| = 3.0000, repelling") != NULL, "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "z2 = -0.5000 0.0000 i, |2z| = 1.0000, neutral") != NULL, "%s", t.log);
    /* bad c= forms name the form and the part */
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njulia c=0.5 0 0 3 40\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "c=RE,IM") != NULL, "%s", sc.err);
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njuliafixed c=0,2.5 0 0 3\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "IM 2.5 out of range, expected -2..2") != NULL, "%s", sc.err);
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njuliabasins c=x,0 0 0 3 10\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "RE: expected a decimal number, got 'x'") != NULL, "%s", sc.err);
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njulia c=0,0 0 0 3\n", &sc), -FX_EINVAL); /* MAXITER missing */
    /* the positional form's names say which pair is c */
    FX_CHECK_EQ(run_traced(&t, "size 120 80\njulia 0 0 -20 0 3 40\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "C_RE -20 out of range") != NULL, "%s", sc.err);
}

/* Issue #44: the orbit of 0, the notes' way into M, with their cases. */
/* c at the ends of its range: z_1 = c already escapes, and squaring a part
 * of 16 left Q8.56 (the sanitized corner suite found the overflow) */
FX_TEST(orbit0_at_the_range_ends)
{
    const fx56 v[] = {-16 * FX56_ONE, 16 * FX56_ONE, 2 * FX56_ONE + 1, 0};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            if (!v[i] && !v[j])
                continue;
            fx_orbit0_info o;
            FX_CHECK_EQ(fx_orbit0(v[i], v[j], 8, NULL, NULL, &o), (int)FX_ORBIT0_ESCAPES);
            FX_CHECK_EQ(o.steps, 1u);
        }
}

FX_TEST(orbit0_classifies_the_notes_cases)
{
    fx56 zr[300], zi[300];
    fx_orbit0_info o;
    /* c = -1: 0, -1, 0, -1, ...: a cycle of period 2 */
    FX_CHECK_EQ(fx_orbit0(-FX56_ONE, 0, 64, zr, zi, &o), FX_ORBIT0_CYCLE);
    FX_CHECK(o.period == 2 && zr[1] == -FX56_ONE && zr[2] == 0 && zi[3] == 0);
    /* c = 1: 0, 1, 2, 5: explodes at step 3 */
    FX_CHECK_EQ(fx_orbit0(FX56_ONE, 0, 64, zr, zi, &o), FX_ORBIT0_ESCAPES);
    FX_CHECK(o.steps == 3 && o.re == 5 * FX56_ONE && zr[2] == 2 * FX56_ONE);
    /* c = -2: 0, -2, 2, 2: lands on the fixed point 2 */
    FX_CHECK_EQ(fx_orbit0(-2 * FX56_ONE, 0, 64, zr, zi, &o), FX_ORBIT0_FIXED);
    FX_CHECK(o.re == 2 * FX56_ONE && o.period == 1);
    /* c = 0.1 + 0.3i: z* = (1 - sqrt(1 - 4c)) / 2 = 0.0073489 + 0.3044751i,
     * multiplier 2 z* of modulus 0.609 at 88.6 degrees: a spiral */
    FX_CHECK_EQ(fx_orbit0(d56(0.1), d56(0.3), 200, zr, zi, &o), FX_ORBIT0_SPIRAL);
    FX_CHECK_MSG(fabs(o.re / 72057594037927936.0 - 0.007348908) < 1e-5 &&
                     fabs(o.im / 72057594037927936.0 - 0.304475119) < 1e-5,
                 "z* %f %f", o.re / 72057594037927936.0, o.im / 72057594037927936.0);
    /* Douady's rabbit: a 3-cycle */
    FX_CHECK_EQ(fx_orbit0(d56(-0.12), d56(0.74), 200, zr, zi, &o), FX_ORBIT0_CYCLE);
    FX_CHECK_EQ(o.period, 3);
    /* c = 1/4, the cusp: creeps towards 1/2, no cycle within 200 values */
    FX_CHECK_EQ(fx_orbit0(FX56_ONE / 4, 0, 200, NULL, NULL, &o), FX_ORBIT0_BOUNDED);
    FX_CHECK(o.re > FX56_ONE / 2 - FX56_ONE / 100 && o.re < FX56_ONE / 2);
    FX_CHECK_EQ(fx_orbit0(0, 0, 0, NULL, NULL, &o), -FX_EINVAL);
    FX_CHECK_EQ(fx_orbit0(17 * FX56_ONE, 0, 5, NULL, NULL, &o), -FX_EINVAL);
    /* the script command prints the values and the class */
    traced t;
    fx_scene sc;
    FX_CHECK_EQ(run_traced(&t, "size 120 80\norbit -1 0 50\norbit 1 0 50\norbit 0.1 0.3 200 0 0 2\n", &sc), 0);
    FX_CHECK_MSG(strstr(t.log, "orbit: z1 = -1.0000 0.0000 i\norbit: z2 = 0.0000 0.0000 i") != NULL, "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "orbit: c = -1.0000 0.0000 i: cycle of period 2") != NULL, "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "orbit: z3 = 5.0000 0.0000 i\norbit: c = 1.0000 0.0000 i: explodes, |z3| > 2") != NULL,
                 "%s", t.log);
    FX_CHECK_MSG(strstr(t.log, "spiral into a fixed point, z199 = 0.0073 0.3044 i") != NULL ||
                     strstr(t.log, "spiral into a fixed point, z199 = 0.0073 0.3045 i") != NULL,
                 "%s", t.log);
    int lit = 0;
    for (int i = 0; i < 120 * 80; i++)
        lit += t.b.mem[i] != 0 && t.b.mem[i] != 0xFF000000u;
    FX_CHECK(lit > 30);
    FX_CHECK_EQ(run_traced(&t, "size 120 80\norbit 0 0 2000\n", &sc), -FX_EINVAL);
    FX_CHECK_MSG(strstr(sc.err, "1..1024") != NULL, "%s", sc.err);
}
