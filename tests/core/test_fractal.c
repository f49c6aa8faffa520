/* SPDX-License-Identifier: MIT */
/* Escape-time fractals: agreement with floating-point references computed
 * here (W9 and zoomed views on both arithmetic paths, a 10^-13 deep zoom
 * against long double), the exact grid, the 64-bit path against a plain
 * fx56_mul loop, symmetry of K_c, tiles == whole, and W9 colouring. */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/colormap.h"
#include "fixel/error.h"
#include "fixel/fractal.h"
#include "fixel/ifs.h"
#include "fixel/circle.h"
#include "fixel/fill.h"
#include "fixel/scene.h"
#include "fx_test.h"
#include "scenebuf.h"
#include "../../tools/fixel-bench/workloads.h"

/* Where long double is wider than double (x86: 64-bit mantissa, aarch64:
 * 113) it is the reference that double cannot be at deep zooms; on 32-bit
 * ARM it is double itself and the tests that need more are not built. */
#define WIDE_LD (LDBL_MANT_DIG > DBL_MANT_DIG && wide_ld_at_run_time())

/* Valgrind runs x87 code in 64-bit doubles: long double is then no wider
 * than double whatever LDBL_MANT_DIG says, and cannot be the reference. */
static int wide_ld_at_run_time(void)
{
    volatile long double one = 1.0L, tiny = 1.0L / 1152921504606846976.0L; /* 2^-60 */
    return one + tiny != one;
}

/* The course's loop in long double on the exact pixel coordinates the view
 * uses (long double holds every fx56 exactly on x86). */
static uint32_t ref_dwell_ld(long double zr, long double zi, long double cr, long double ci,
                             uint32_t max)
{
    uint32_t n = 0;
    while (n < max) {
        long double rr = zr * zr, ii = zi * zi;
        if (rr + ii > 4.0L)
            break;
        zi = 2 * zr * zi + ci;
        zr = rr - ii + cr;
        n++;
    }
    return n;
}

/* The W9 loop of docs/BENCHMARK.md in double, for any view given in doubles:
 * z starts at (zr, zi), 0 for the Mandelbrot set, the pixel for a Julia set. */
static uint32_t ref_dwell_d(double zr, double zi, double cr, double ci, uint32_t max)
{
    uint32_t n = 0;
    while (n < max) {
        double zr2 = zr * zr, zi2 = zi * zi;
        if (zr2 + zi2 > 4.0)
            break;
        zi = 2 * zr * zi + ci;
        zr = zr2 - zi2 + cr;
        n++;
    }
    return n;
}

static fx56 fx56_of(const char *s)
{
    fx56 v = 0;
    int n = fx56_parse(s, (int)strlen(s), &v);
    FX_CHECK(n == (int)strlen(s));
    return v;
}

static long double ld56(fx56 v) { return (long double)v / 72057594037927936.0L; }

/* The requirement itself: the full 1920x1080 W9 picture (colours, as the
 * benchmark compares them) against the double loop of docs/BENCHMARK.md. */
FX_TEST(fractal_w9_agrees_with_double)
{
    const int32_t w = 1920, h = 1080;
    uint32_t *px = malloc((size_t)w * h * 4);
    fx_surface s;
    fx_surface_init(&s, px, w, h, w * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(bench_mandel_w9(&s), 0);
    fx_fractal_view v = fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, w, h, 256);
    FX_CHECK_EQ(fx_fractal_precision(&v), 32);
    const double st = 3.0 / 1920;
    int64_t same = 0;
    for (int32_t y = 0; y < h; y++) {
        double ci = (540.0 - (y + 0.5)) * st;
        for (int32_t x = 0; x < w; x++) {
            double cr = -0.5 + ((x + 0.5) - 960.0) * st;
            uint32_t n = ref_dwell_d(0, 0, cr, ci, 256), g = 4 * n > 255 ? 255 : 4 * n;
            same += (px[(size_t)y * w + x] & 0xFFFFFF) == (n == 256 ? 0 : g * 0x010101u);
        }
    }
    free(px);
    int64_t a = same * 100000 / ((int64_t)w * h);
    FX_CHECK_MSG(a >= 99900, "W9 agreement %lld/100000", (long long)a);
}

/* Zoomed views: dwell of every pixel against the double loop on W9-style
 * pixel centres, and against long double on the library's exact grid, where
 * fixel must be at least as close as double itself is (within 0.1 %). */
static void zoom_case(const char *cre, const char *cim, const char *width, int32_t w, int32_t h,
                      uint32_t max, int want_prec, int64_t min_vs_double)
{
    fx_fractal_view v = fx_mandel_view(fx56_of(cre), fx56_of(cim), fx56_of(width), w, h, max);
    FX_CHECK_EQ(fx_fractal_precision(&v), want_prec);
    uint32_t *d = malloc(sizeof *d * (size_t)w * h);
    fx_rect r = {0, 0, w, h};
    FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
    const double dre = atof(cre), dim = atof(cim), s = atof(width) / w;
    int64_t vs_d = 0, vs_ld = 0, d_ld = 0, escaped = 0;
    for (int32_t y = 0; y < h; y++) {
        double ci = dim + (h / 2.0 - (y + 0.5)) * s;
        long double li = ld56(fx_fractal_im(&v, y));
        for (int32_t x = 0; x < w; x++) {
            double cr = dre + ((x + 0.5) - w / 2.0) * s;
            uint32_t got = d[(size_t)y * w + x], nd = ref_dwell_d(0, 0, cr, ci, max);
            uint32_t nl = ref_dwell_ld(0, 0, ld56(fx_fractal_re(&v, x)), li, max);
            vs_d += got == nd;
            vs_ld += got == nl;
            d_ld += nd == nl;
            escaped += got < max;
        }
    }
    free(d);
    int64_t n = (int64_t)w * h;
    FX_CHECK_MSG(vs_d * 100000 / n >= min_vs_double, "%s %si/%s: %lld/100000 vs double", cre, cim,
                 width, (long long)(vs_d * 100000 / n));
    /* the 64-bit path is as precise as double; the 32-bit one (2^-28) is not */
    if (want_prec == 64 && WIDE_LD)
        FX_CHECK_MSG(vs_ld * 1000 >= d_ld * 1000 - n, "%s %si/%s: vs long double %lld, double %lld",
                     cre, cim, width, (long long)vs_ld, (long long)d_ld);
    FX_CHECK(escaped > n / 4); /* the view holds structure, not only the inside */
}

FX_TEST(fractal_zoomed_views_agree_with_double)
{
    /* the 32-bit path: a pixel step of 1/800 and 256 iterations */
    zoom_case("-1.25", "0.05", "0.4", 320, 240, 256, 32, 99500);
    /* the 64-bit path, down to 3e-6 wide (where double itself starts to drift) */
    zoom_case("-0.7453", "0.1127", "0.00065", 160, 120, 1000, 64, 99500);
    zoom_case("-0.16070135", "1.0375665", "0.00001", 160, 120, 2000, 64, 99500);
    zoom_case("-0.743643887", "0.131825904", "0.000003", 128, 96, 2000, 64, 98500);
}

#if LDBL_MANT_DIG > DBL_MANT_DIG
/* A 10^-13 wide view: pixels 8e-16 apart, below what double resolves near
 * -0.74; long double (64-bit mantissa) is the reference, on the exact grid
 * coordinates, and the picture must hold structure (many distinct dwells). */
FX_TEST(fractal_deep_zoom_64bit)
{
    const int32_t w = 96, h = 64;
    fx_fractal_view v = fx_mandel_view(fx56_of("-0.743643887037158704752191506114774"),
                                       fx56_of("0.131825904205311970493132056385139"),
                                       fx56_of("0.0000000000001"), w, h, 3000);
    FX_CHECK_EQ(fx_fractal_precision(&v), 64);
    uint32_t *d = malloc(sizeof *d * (size_t)w * h);
    fx_rect r = {0, 0, w, h};
    FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
    int64_t same = 0;
    uint32_t lo = UINT32_MAX, hi = 0;
    static uint8_t seen[3001];
    memset(seen, 0, sizeof seen);
    int distinct = 0;
    for (int32_t y = 0; y < h; y++) {
        long double ci = ld56(fx_fractal_im(&v, y));
        for (int32_t x = 0; x < w; x++) {
            long double cr = ld56(fx_fractal_re(&v, x));
            uint32_t got = d[y * w + x];
            same += got == ref_dwell_ld(0, 0, cr, ci, 3000);
            lo = got < lo ? got : lo;
            hi = got > hi ? got : hi;
            distinct += !seen[got];
            seen[got] = 1;
        }
    }
    free(d);
    int64_t a = same * 100000 / (w * h);
    /* measured 98.2 %: Q8.56 keeps 8 bits fewer than long double, and a
     * pixel here is only ~75 units of 2^-56 */
    if (WIDE_LD)
        FX_CHECK_MSG(a >= 97000, "deep zoom agreement %lld/100000", (long long)a);
    else
        printf("     (long double is not wider than double here: agreement not checked)\n");
    FX_CHECK_MSG(distinct >= 64 && lo < hi, "only %d distinct dwells (%u..%u)", distinct, lo, hi);
}

#endif

#if defined(__SIZEOF_INT128__)
/* The grid: each pixel centre is the exact rational coordinate rounded to
 * the nearest 2^-56 (ties away from zero), computed here with __int128. */
FX_TEST(fractal_grid_exact)
{
    const char *widths[] = {"3.0", "0.0000000000001", "0.7", "15.999"};
    for (int wi = 0; wi < 4; wi++)
        for (int32_t fw = 1; fw < 700; fw += 97) {
            fx_fractal_view v = fx_mandel_view(fx56_of("-0.5"), fx56_of("0.25"), fx56_of(widths[wi]),
                                               fw, fw / 2 + 1, 10);
            FX_CHECK_EQ(fx_fractal_check(&v), 0);
            for (int32_t x = 0; x < fw; x += 13) {
                __int128 num = (__int128)(2 * x + 1 - fw) * v.width, den = 2 * (__int128)fw;
                __int128 q = (num < 0 ? -num : num) * 2 + den;
                q /= 2 * den; /* round half away on |num| */
                int64_t off = (int64_t)(num < 0 ? -q : q);
                FX_CHECK_EQ(fx_fractal_re(&v, x), v.cre + off);
            }
            for (int32_t y = 0; y < v.fh; y += 7) {
                __int128 num = (__int128)(v.fh - 2 * y - 1) * v.width, den = 2 * (__int128)fw;
                __int128 q = ((num < 0 ? -num : num) * 2 + den) / (2 * den);
                FX_CHECK_EQ(fx_fractal_im(&v, y), v.cim + (int64_t)(num < 0 ? -q : q));
            }
        }
}

#endif

/* The 64-bit path is the plain Q8.56 loop with the library's portable
 * fx56_mul / fx_mul64_shift products (the fast product must round alike). */
FX_TEST(fractal_64bit_path_is_fx56_loop)
{
    const int32_t w = 64, h = 48;
    fx_fractal_view views[2] = {
        fx_mandel_view(fx56_of("-0.7436438870"), fx56_of("0.1318259042"), fx56_of("0.00001"), w, h, 800),
        fx_julia_view(fx56_of("0.1"), fx56_of("0.05"), fx56_of("-0.8"), fx56_of("0.156"),
                      fx56_of("0.3"), w, h, 500),
    };
    for (int k = 0; k < 2; k++) {
        fx_fractal_view v = views[k];
        v.precision = 64;
        uint32_t d[64 * 48];
        fx_rect r = {0, 0, w, h};
        FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
        for (int32_t y = 0; y < h; y++)
            for (int32_t x = 0; x < w; x++) {
                fx56 pr = fx_fractal_re(&v, x), pi = fx_fractal_im(&v, y);
                fx56 zr = v.julia ? pr : 0, zi = v.julia ? pi : 0;
                fx56 cr = v.julia ? v.jre : pr, ci = v.julia ? v.jim : pi;
                uint32_t n = 0;
                while (n < v.maxiter) {
                    fx56 rr = fx56_mul(zr, zr), ii = fx56_mul(zi, zi);
                    if (rr + ii > 4 * FX56_ONE)
                        break;
                    zi = fx_mul64_shift(zr, zi, 55) + ci;
                    zr = rr - ii + cr;
                    n++;
                }
                FX_CHECK_EQ(d[y * w + x], n);
            }
    }
}

FX_TEST(fractal_julia_symmetry)
{
    /* even and odd frame sizes; both paths; the douady rabbit and a dendrite */
    const char *cs[][2] = {{"-0.123", "0.745"}, {"0", "1"}, {"-0.8", "0.156"}};
    for (int k = 0; k < 3; k++)
        for (int prec = 32; prec <= 64; prec += 32) {
            int32_t w = 61 + k, h = 40 + k;
            fx_fractal_view v = fx_julia_view(0, 0, fx56_of(cs[k][0]), fx56_of(cs[k][1]),
                                              fx56_of("3.2"), w, h, 300);
            v.precision = (uint8_t)prec;
            uint32_t d[63 * 42], one[1];
            fx_rect r = {0, 0, w, h};
            FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
            int interesting = 0;
            for (int32_t y = 0; y < h; y++)
                for (int32_t x = 0; x < w; x++) {
                    /* the mirror pixel is the negated point */
                    FX_CHECK_EQ(fx_fractal_re(&v, x), -fx_fractal_re(&v, w - 1 - x));
                    FX_CHECK_EQ(d[y * w + x], d[(h - 1 - y) * w + (w - 1 - x)]);
                    interesting += d[y * w + x] > 3;
                    /* 1x1 tiles cannot use the symmetry: same dwell */
                    if ((x * 7 + y * 3) % 11 == 0) {
                        fx_rect p = {x, y, x + 1, y + 1};
                        FX_CHECK_EQ(fx_fractal_dwell(&v, p, one, 1), 0);
                        FX_CHECK_EQ(one[0], d[y * w + x]);
                    }
                }
            FX_CHECK(interesting > w * h / 8);
        }
}

static int render_tiles_equal(const fx_fractal_view *v, uint32_t seed)
{
    int32_t w = v->fw, h = v->fh;
    uint32_t *whole = calloc((size_t)w * h, 4), *tiled = calloc((size_t)w * h, 4);
    uint32_t lut[65];
    fx_dwell_pal pal;
    fx_dwell_pal_w9(&pal, lut, FX_FMT_XRGB8888);
    fx_surface a, b;
    fx_surface_init(&a, whole, w, h, w * 4, FX_FMT_XRGB8888);
    fx_surface_init(&b, tiled, w, h, w * 4, FX_FMT_XRGB8888);
    memset(tiled, 0x55, (size_t)w * h * 4);
    FX_CHECK_EQ(fx_fractal_render(&a, fx_surface_rect(&a), v, &pal), 0);
    /* random cuts into a grid of tiles, rendered in a scrambled order */
    int32_t xs[6] = {0, 0, 0, 0, 0, w}, ys[6] = {0, 0, 0, 0, 0, h};
    for (int i = 1; i < 5; i++) {
        xs[i] = (int32_t)(fx_test_rand(&seed) % (uint32_t)w);
        ys[i] = (int32_t)(fx_test_rand(&seed) % (uint32_t)h);
    }
    for (int i = 1; i < 5; i++)
        for (int j = i + 1; j < 5; j++) {
            if (xs[j] < xs[i]) { int32_t t = xs[i]; xs[i] = xs[j]; xs[j] = t; }
            if (ys[j] < ys[i]) { int32_t t = ys[i]; ys[i] = ys[j]; ys[j] = t; }
        }
    for (int k = 0; k < 25; k++) {
        int t = (k * 7) % 25, i = t % 5, j = t / 5;
        fx_rect r = {xs[i], ys[j], xs[i + 1], ys[j + 1]};
        FX_CHECK_EQ(fx_fractal_render(&b, r, v, &pal), 0);
    }
    int eq = memcmp(whole, tiled, (size_t)w * h * 4) == 0;
    free(whole);
    free(tiled);
    return eq;
}

FX_TEST(fractal_tiles_equal_whole)
{
    uint32_t seed = 99;
    fx_fractal_view m = fx_mandel_view(fx56_of("-0.5"), 0, fx56_of("3"), 97, 61, 256);
    fx_fractal_view deep = fx_mandel_view(fx56_of("-1.7548776662"), 0, fx56_of("0.00025"), 80, 50, 600);
    fx_fractal_view j = fx_julia_view(0, 0, fx56_of("-0.123"), fx56_of("0.745"), fx56_of("3.2"), 81, 60, 300);
    fx_fractal_view j64 = j;
    j64.precision = 64;
    for (int k = 0; k < 6; k++) {
        FX_CHECK(render_tiles_equal(&m, seed + k));
        FX_CHECK(render_tiles_equal(&deep, seed + 10 + k));
        FX_CHECK(render_tiles_equal(&j, seed + 20 + k));
        FX_CHECK(render_tiles_equal(&j64, seed + 30 + k));
    }
}

FX_TEST(fractal_precision_and_limits)
{
    fx_fractal_view v = fx_mandel_view(fx56_of("-0.5"), 0, fx56_of("3"), 1920, 1080, 256);
    FX_CHECK_EQ(fx_fractal_precision(&v), 32);
    v.width = fx56_of("0.4"); /* 2e-4 per pixel: below 2^-12 */
    FX_CHECK_EQ(fx_fractal_precision(&v), 64);
    v.width = fx56_of("3");
    v.maxiter = 100000;
    FX_CHECK_EQ(fx_fractal_precision(&v), 64);
    fx_fractal_view j = fx_julia_view(0, 0, fx56_of("2.5"), 0, fx56_of("3"), 64, 64, 100);
    FX_CHECK_EQ(fx_fractal_precision(&j), 64);
    /* invalid views are refused, not rendered */
    uint32_t d[4];
    fx_rect r = {0, 0, 2, 2};
    fx_fractal_view bad = v;
    bad.width = 0;
    FX_CHECK_EQ(fx_fractal_dwell(&bad, r, d, 2), -FX_EINVAL);
    bad = v;
    bad.cre = fx56_of("17");
    FX_CHECK_EQ(fx_fractal_check(&bad), -FX_EINVAL);
    bad = fx_mandel_view(0, 0, fx56_of("16"), 1, 16384, 10); /* 128k tall */
    FX_CHECK_EQ(fx_fractal_check(&bad), -FX_EINVAL);
    bad = v;
    bad.precision = 48;
    FX_CHECK_EQ(fx_fractal_check(&bad), -FX_EINVAL);
    /* maxiter 0: every point "inside"; maxiter 1: the loop runs once */
    fx_fractal_view z = fx_mandel_view(0, 0, fx56_of("8"), 2, 2, 0);
    FX_CHECK_EQ(fx_fractal_dwell(&z, r, d, 2), 0);
    FX_CHECK(d[0] == 0 && d[3] == 0);
}

/* W9 colouring on an XRGB8888 surface, checked pixel by pixel against the
 * W9 formula applied to the library's own dwell. */
FX_TEST(fractal_w9_colours)
{
    const int32_t w = 120, h = 68;
    uint32_t *px = calloc((size_t)w * h, 4), *d = calloc((size_t)w * h, 4);
    fx_surface s;
    fx_surface_init(&s, px, w, h, w * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(bench_mandel_w9(&s), 0);
    fx_fractal_view v = fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, w, h, 256);
    fx_rect r = {0, 0, w, h};
    FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
    int inside = 0, grey = 0;
    for (int i = 0; i < w * h; i++) {
        uint32_t n = d[i], g = 4 * n > 255 ? 255 : 4 * n;
        uint32_t want = n == 256 ? 0 : g * 0x010101u;
        FX_CHECK_EQ_HEX(px[i] & 0xFFFFFF, want);
        inside += n == 256;
        grey += n < 256 && n > 3;
    }
    FX_CHECK(inside > w * h / 8 && grey > w * h / 20);
    free(px);
    free(d);
}

FX_TEST(colormap_definitions)
{
    /* ends of the clamped maps and their clamping above 1.0 */
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_GREY, 0), 0xFF000000u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_GREY, 65536), 0xFFFFFFFFu);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_GREY, 32768), 0xFF808080u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HOT, 0), 0xFF000000u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HOT, 65536 / 3 + 1), 0xFFFF0000u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HOT, 2 * 65536 / 3 + 1), 0xFFFFFF00u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HOT, 1000000), 0xFFFFFFFFu);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_VIRIDIS, 0), 0xFF440154u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_VIRIDIS, 32768), 0xFF21908Du);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_VIRIDIS, 65536), 0xFFFDE725u);
    /* HSV: primaries at sextant starts; cyclic */
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HSV, 0), 0xFFFF0000u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HSV, 65536 / 3), fx_cmap_color(FX_CMAP_HSV, 21845));
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HSV, 65536), 0xFFFF0000u);
    FX_CHECK_EQ_HEX(fx_cmap_color(FX_CMAP_HSV, 65536 + 1234), fx_cmap_color(FX_CMAP_HSV, 1234));
    /* every map is continuous: neighbouring t differ by at most a few levels,
     * except HSV which also stays continuous across its wrap */
    for (int m = 0; m < FX_CMAP_COUNT; m++) {
        fx_color prev = fx_cmap_color((fx_cmap)m, 0);
        int32_t lum_prev = -1, mono = 1;
        /* steps of 1/64: fine enough to catch a wrong control point, coarse
         * enough that per-channel rounding cannot reverse the luminance */
        for (uint32_t t = 0; t <= 65536 + 1024; t += 1024) {
            fx_color c = fx_cmap_color((fx_cmap)m, t);
            for (int sh = 0; sh < 24; sh += 8) {
                int dd = (int)(c >> sh & 255) - (int)(prev >> sh & 255);
                FX_CHECK_MSG(dd >= -24 && dd <= 24, "map %d jumps at t=%u", m, t);
            }
            int32_t lum = (int32_t)(77 * (c >> 16 & 255) + 150 * (c >> 8 & 255) + 29 * (c & 255));
            mono &= lum >= lum_prev;
            lum_prev = lum;
            prev = c;
        }
        /* grey, hot and viridis rise in luminance from start to end */
        if (m != FX_CMAP_HSV)
            FX_CHECK_MSG(mono, "map %d luminance not monotonic", m);
    }
    fx_color tab[5];
    fx_cmap_table(FX_CMAP_GREY, tab, 5);
    FX_CHECK_EQ_HEX(tab[0], 0xFF000000u);
    FX_CHECK_EQ_HEX(tab[4], 0xFFFFFFFFu);
    fx_cmap_table(FX_CMAP_HSV, tab, 3); /* red, green, blue */
    FX_CHECK_EQ_HEX(tab[0], 0xFFFF0000u);
    FX_CHECK_EQ_HEX(tab[1] & 0xFF00FF00u, 0xFF00FF00u);
    FX_CHECK_EQ(fx_cmap_from_name("Viridis"), FX_CMAP_VIRIDIS);
    FX_CHECK_EQ(fx_cmap_from_name("gray"), FX_CMAP_GREY);
    FX_CHECK_EQ(fx_cmap_from_name("jet"), FX_CMAP_COUNT);
}

/* The script commands: decimals parsed exactly give the library's views. */
static uint32_t scene_mem[192 * 108];
static scene_buf buf = {scene_mem, 192 * 108};

static int scene_run(const char *text)
{
    static uint8_t arena[1 << 16];
    fx_scene sc;
    fx_scene_host h = {&buf, scene_buf_make, NULL, NULL, NULL, NULL};
    fx_scene_init(&sc, &h, arena, sizeof arena);
    return fx_scene_run(&sc, text, strlen(text));
}

FX_TEST(fractal_script_commands)
{
    static uint32_t want[192 * 108];
    fx_surface s;
    fx_surface_init(&s, want, 192, 108, 192 * 4, FX_FMT_XRGB8888);
    FX_CHECK_EQ(bench_mandel_w9(&s), 0);
    FX_CHECK_EQ(scene_run("size 192 108\nmandelbrot -0.5 0 3.0 256\n"), 0);
    FX_CHECK(memcmp(want, scene_mem, sizeof want) == 0);
    /* a Julia set in a colour map with a period and an inside colour */
    fx_fractal_view v = fx_julia_view(0, 0, fx56_of("-0.123"), fx56_of("0.745"), fx56_of("3.2"), 192,
                                      108, 300);
    fx_color tab[256];
    uint32_t lut[256];
    fx_cmap_table(FX_CMAP_HOT, tab, 256);
    for (int i = 0; i < 256; i++)
        lut[i] = fx_pack(FX_FMT_XRGB8888, tab[i]);
    fx_dwell_pal pal = {lut, 256, (256 << 16) / 20, 1, fx_pack(FX_FMT_XRGB8888, 0xFF203040u)};
    FX_CHECK_EQ(fx_fractal_render(&s, fx_surface_rect(&s), &v, &pal), 0);
    FX_CHECK_EQ(scene_run("size 192 108\ncolormap hot 20\ninsidecolor #203040\n"
                          "julia 0 0 -0.123 0.745 3.2 300\n"),
                0);
    FX_CHECK(memcmp(want, scene_mem, sizeof want) == 0);
    int inside = 0;
    for (int i = 0; i < 192 * 108; i++)
        inside += (want[i] & 0xFFFFFF) == 0x203040;
    FX_CHECK(inside > 500);
}

/* Filled Julia sets against the double loop started at the pixel centre. */
static int64_t julia_agree(const char *jre, const char *jim, double djre, double djim, uint32_t max,
                           int prec)
{
    const int32_t w = 160, h = 100;
    fx_fractal_view v = fx_julia_view(0, 0, fx56_of(jre), fx56_of(jim), fx56_of("3.2"), w, h, max);
    v.precision = (uint8_t)prec;
    uint32_t *d = malloc(sizeof *d * (size_t)w * h);
    fx_rect r = {0, 0, w, h};
    FX_CHECK_EQ(fx_fractal_dwell(&v, r, d, w), 0);
    const double s = 3.2 / w;
    int64_t same = 0, escaped = 0;
    for (int32_t y = 0; y < h; y++)
        for (int32_t x = 0; x < w; x++) {
            double zr = ((x + 0.5) - w / 2.0) * s, zi = (h / 2.0 - (y + 0.5)) * s;
            uint32_t n = ref_dwell_d(zr, zi, djre, djim, max);
            same += d[y * w + x] == n;
            escaped += n < max;
        }
    free(d);
    FX_CHECK(escaped > w * h / 4 && escaped < w * h);
    return same * 100000 / (w * h);
}

FX_TEST(fractal_julia_agrees_with_double)
{
    fx_fractal_view v = fx_julia_view(0, 0, fx56_of("-0.8"), fx56_of("0.156"), fx56_of("3.2"), 160, 100, 256);
    FX_CHECK_EQ(fx_fractal_precision(&v), 32);
    int64_t a = julia_agree("-0.8", "0.156", -0.8, 0.156, 256, 32);
    /* measured 99.45 %: the boundary of a Julia set is all chaotic pixels */
    FX_CHECK_MSG(a >= 99300, "Julia, 32-bit path: %lld/100000", (long long)a);
    a = julia_agree("-0.8", "0.156", -0.8, 0.156, 256, 64);
    FX_CHECK_MSG(a >= 99900, "Julia, 64-bit path: %lld/100000", (long long)a);
    a = julia_agree("-0.123", "0.745", -0.123, 0.745, 400, 64);
    FX_CHECK_MSG(a >= 99900, "rabbit, 64-bit path: %lld/100000", (long long)a);
}

/* Issue #44: the copier started from any picture tends to the same
 * attractor: a disc and a square, five rounds of the Sierpinski machine,
 * light nearly the same pixels; depth 0 gives the picture back. */
FX_TEST(ifs_copier_from_any_picture)
{
    static uint32_t a[64 * 64], b[64 * 64];
    static fx_ifs_pixel work[64 * 64];
    fx_surface sa, sb;
    fx_surface_init(&sa, a, 64, 64, 64 * 4, FX_FMT_XRGB8888);
    fx_surface_init(&sb, b, 64, 64, 64 * 4, FX_FMT_XRGB8888);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &sa);
    fx_ctx_init(&cb, &sb);
    fx_rect d = {0, 0, 64, 64};
    memset(a, 0, sizeof a), memset(b, 0, sizeof b);
    fx_disc(&ca, 32, 32, 20);
    fx_fill_rect(&cb, 4, 4, 20, 50);
    /* depth 0: the same picture back, pixel for pixel */
    static uint32_t keep[64 * 64];
    memcpy(keep, a, sizeof a);
    int32_t n = fx_ifs_copier_picture(&ca, d, &fx_ifs_sierpinski, 0, 0xFF000000u, work, 64 * 64);
    FX_CHECK(n > 1200 && memcmp(keep, a, sizeof a) == 0);
    FX_CHECK_EQ(fx_ifs_copier_picture(&ca, d, &fx_ifs_sierpinski, 5, 0xFF000000u, work, 64 * 64), n);
    FX_CHECK_EQ(fx_ifs_copier_picture(&cb, d, &fx_ifs_sierpinski, 5, 0xFF000000u, work, 64 * 64), 20 * 50);
    /* 3^5 copies at 1/32 scale: both lie within 64 / 32 = 2 pixels of the
     * attractor, so within 2 + 2 of each other (Hausdorff, in pixels) */
    int lit[2] = {0, 0}, far = 0;
    for (int k = 0; k < 2; k++) {
        const uint32_t *p = k ? b : a, *q = k ? a : b;
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++) {
                if (!(p[y * 64 + x] & 0xFFFFFF))
                    continue;
                lit[k]++;
                int near = 0;
                for (int dy = -4; dy <= 4; dy++)
                    for (int dx = -4; dx <= 4; dx++)
                        if (x + dx >= 0 && x + dx < 64 && y + dy >= 0 && y + dy < 64)
                            near |= (q[(y + dy) * 64 + x + dx] & 0xFFFFFF) != 0;
                far += !near;
            }
    }
    FX_CHECK_MSG(lit[0] > 300 && lit[1] > 150 && far == 0, "%d and %d lit, %d far", lit[0], lit[1], far);
    /* the limits */
    FX_CHECK_EQ(fx_ifs_copier_picture(&ca, d, &fx_ifs_sierpinski, 1, 0xFF000000u, work, 10), -FX_ENOSPC);
    FX_CHECK_EQ(fx_ifs_copier_picture(&ca, d, &fx_ifs_sierpinski, 20, 0xFF000000u, work, 64 * 64), -FX_E2BIG);
}
