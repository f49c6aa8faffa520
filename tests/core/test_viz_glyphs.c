/* SPDX-License-Identifier: MIT */
/* Tensor glyphs (the integer eigen decomposition against a double
 * reference, glyph fill and orientation), star and multi-part glyphs, the
 * CIE 1931 tables and the chromaticity diagram, cross-hatching and the
 * colour solids (issue #23). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/colour.h"
#include "fixel/error.h"
#include "fixel/fill.h"
#include "fixel/mesh.h"
#include "fixel/viz.h"
#include "fx_test.h"

typedef struct {
    uint32_t *px;
    fx_surface s;
    fx_ctx c;
} cnv;

static void cnv_new(cnv *k, int32_t w, int32_t h)
{
    k->px = calloc((size_t)w * h, 4);
    fx_surface_init(&k->s, k->px, w, h, w * 4, FX_FMT_XRGB8888);
    fx_ctx_init(&k->c, &k->s);
}

static uint32_t at(const cnv *k, int32_t x, int32_t y) { return k->px[y * k->s.w + x] & 0xFFFFFF; }

static uint32_t rng = 12345;
static int32_t rnd(int32_t lim) /* uniform in [-lim, lim] */
{
    uint64_t r = fx_rand32(&rng);
    r = r << 32 | fx_rand32(&rng);
    return (int32_t)(r % (2 * (uint64_t)lim + 1)) - lim;
}

/* The residual |A v - l v| of an integer eigenpair, in the matrix's units. */
static double residual(int32_t a, int32_t b, int32_t c, int32_t l, fx16 vx, fx16 vy)
{
    double x = vx / 65536.0, y = vy / 65536.0;
    double rx = a * x + b * y - l * x, ry = b * x + c * y - l * y;
    return sqrt(rx * rx + ry * ry);
}

FX_TEST(eigen2_matches_a_double_reference)
{
    static const int32_t lims[4] = {1000, 100000, 1 << 20, FX_TENSOR_MAX};
    double worst = 0;
    for (int li = 0; li < 4; li++)
        for (int n = 0; n < 5000; n++) {
            int32_t a = rnd(lims[li]), b = rnd(lims[li]), c = rnd(lims[li]);
            if (n % 7 == 0)
                b = 0;
            if (n % 11 == 0)
                c = a;
            fx_eigen2 e;
            FX_CHECK_EQ(fx_eigen2_sym(a, b, c, &e), 0);
            double tr = (double)a + c, d = (double)a - c;
            double D = sqrt(d * d + 4.0 * b * b);
            double l1 = (tr + D) / 2, l2 = (tr - D) / 2;
            FX_CHECK_MSG(fabs(e.l1 - l1) <= 1.0 && fabs(e.l2 - l2) <= 1.0, "%d %d %d: l %d %d", a, b, c, e.l1,
                         e.l2);
            FX_CHECK(e.l1 >= e.l2);
            /* unit, orthogonal, right-handed, v1 in the upper half plane */
            int64_t n1 = (int64_t)e.v1x * e.v1x + (int64_t)e.v1y * e.v1y;
            int64_t n2 = (int64_t)e.v2x * e.v2x + (int64_t)e.v2y * e.v2y;
            int64_t dot = (int64_t)e.v1x * e.v2x + (int64_t)e.v1y * e.v2y;
            int64_t crs = (int64_t)e.v1x * e.v2y - (int64_t)e.v1y * e.v2x;
            FX_CHECK_MSG(llabs(n1 - ((int64_t)1 << 32)) <= 4 * 65536 && llabs(n2 - ((int64_t)1 << 32)) <= 4 * 65536,
                         "%d %d %d: |v| %lld %lld", a, b, c, (long long)n1, (long long)n2);
            FX_CHECK_MSG(llabs(dot) <= 4 * 65536, "%d %d %d: v1.v2 = %lld", a, b, c, (long long)dot);
            FX_CHECK(crs > 0);
            FX_CHECK(e.v1y > 0 || (e.v1y == 0 && e.v1x > 0));
            FX_CHECK(e.angle < FX_ANGLE_180);
            /* A v = l v within 2^-14 of the largest component, plus 1 */
            double m = fabs((double)a);
            m = fabs((double)b) > m ? fabs((double)b) : m;
            m = fabs((double)c) > m ? fabs((double)c) : m;
            double r1 = residual(a, b, c, e.l1, e.v1x, e.v1y), r2 = residual(a, b, c, e.l2, e.v2x, e.v2y);
            double bound = m / 16384 + 1;
            FX_CHECK_MSG(r1 <= bound && r2 <= bound, "%d %d %d: residuals %g %g > %g", a, b, c, r1, r2, bound);
            if (m >= (1 << 20)) {
                double q = (r1 > r2 ? r1 : r2) / m;
                worst = q > worst ? q : worst;
            }
            /* the angle is v1's direction */
            double ang = atan2(e.v1y, e.v1x) / (2 * M_PI) * 4294967296.0;
            FX_CHECK_MSG(fabs(ang - (double)e.angle) < 65536.0 * 8, "angle %u vs %g", e.angle, ang);
        }
    /* for large entries the residual is set by the Q16 eigenvectors */
    fprintf(stderr, "    worst relative residual %.3g (2^%.1f)\n", worst, log2(worst));
    FX_CHECK(worst < 1.0 / 16384);
}

FX_TEST(eigen2_special_cases)
{
    fx_eigen2 e;
    /* isotropic: the axes */
    FX_CHECK_EQ(fx_eigen2_sym(5, 0, 5, &e), 0);
    FX_CHECK(e.l1 == 5 && e.l2 == 5 && e.v1x == FX16_ONE && e.v1y == 0 && e.v2x == 0 && e.v2y == FX16_ONE);
    /* diagonal: x then y, or y then x when c is the larger */
    FX_CHECK_EQ(fx_eigen2_sym(3, 0, -7, &e), 0);
    FX_CHECK(e.l1 == 3 && e.l2 == -7 && e.v1x == FX16_ONE && e.v1y == 0 && e.angle == 0);
    FX_CHECK_EQ(fx_eigen2_sym(-7, 0, 3, &e), 0);
    FX_CHECK(e.l1 == 3 && e.l2 == -7 && e.v1x == 0 && e.v1y == FX16_ONE && e.angle == FX_ANGLE_90);
    /* [[2 1] [1 2]]: 3 along 45 degrees, 1 along 135 */
    FX_CHECK_EQ(fx_eigen2_sym(2000, 1000, 2000, &e), 0);
    FX_CHECK(e.l1 == 3000 && e.l2 == 1000);
    FX_CHECK(abs(e.v1x - 46341) <= 1 && abs(e.v1y - 46341) <= 1 && abs(e.v2x + 46341) <= 1);
    FX_CHECK(labs((long)e.angle - (long)FX_ANGLE_45) < 4096);
    /* range: the largest magnitude still works, one more is refused */
    FX_CHECK_EQ(fx_eigen2_sym(FX_TENSOR_MAX, FX_TENSOR_MAX, FX_TENSOR_MAX, &e), 0);
    FX_CHECK_EQ(e.l1, 2 * FX_TENSOR_MAX);
    FX_CHECK_EQ(fx_eigen2_sym(-FX_TENSOR_MAX, FX_TENSOR_MAX, -FX_TENSOR_MAX, &e), 0);
    FX_CHECK_EQ(e.l2, -2 * FX_TENSOR_MAX);
    FX_CHECK_EQ(fx_eigen2_sym(FX_TENSOR_MAX + 1, 0, 0, &e), -FX_ERANGE);
    FX_CHECK_EQ(fx_eigen2_sym(0, INT32_MIN, 0, &e), -FX_ERANGE);
}

#define POS 0x3070D0u
#define NEG 0xD04040u
#define MIX 0x90C070u

FX_TEST(tensor_glyph_lies_along_its_eigenvectors)
{
    static const fx_tensor_style st = {0xFF000000u | POS, 0xFF000000u | NEG, 0xFF000000u | MIX};
    /* l1 = 1000 along 30 degrees, l2 = 250 along 120, built as R diag R^T */
    double c30 = cos(M_PI / 6), s30 = sin(M_PI / 6);
    int32_t a = (int32_t)lround(1000 * c30 * c30 + 250 * s30 * s30);
    int32_t b = (int32_t)lround(750 * c30 * s30);
    int32_t c = (int32_t)lround(1000 * s30 * s30 + 250 * c30 * c30);
    for (int sign = 0; sign < 3; sign++) {
        int32_t ta = a, tb = b, tc = c;
        if (sign == 1)
            ta = -a, tb = -b, tc = -c; /* negative definite */
        fx_eigen2 e;
        if (sign == 2) {
            /* 1000 along 30 and -250 along 120: a saddle */
            ta = (int32_t)lround(1000 * c30 * c30 - 250 * s30 * s30);
            tb = (int32_t)lround(1250 * c30 * s30);
            tc = (int32_t)lround(1000 * s30 * s30 - 250 * c30 * c30);
        }
        FX_CHECK_EQ(fx_eigen2_sym(ta, tb, tc, &e), 0);
        cnv k;
        cnv_new(&k, 120, 120);
        fx_ctx_set_color(&k.c, 0xFFFFFFFFu);
        fx_tensor_glyph(&k.c, 60 * 256, 60 * 256, &e, 1000, 40 * 256, &st);
        uint32_t want = sign == 0 ? POS : sign == 1 ? NEG : MIX;
        /* the long axis is the eigenvector of the eigenvalue of larger
         * magnitude: 30 degrees (y up), 40 px; the short one 10 px */
        /* in every case the magnitude 1000 lies along 30 degrees */
        double ux = c30, uy = s30;
        /* 20 px along the long axis, 4 px to its side: inside (the half
         * width there is 8.7 px), clear of the axis line and the outline */
        int32_t fx = (int32_t)lround(60 + 20 * ux - 4 * uy), fy = (int32_t)lround(60 - 20 * uy - 4 * ux);
        FX_CHECK_MSG(at(&k, fx, fy) == want, "sign case %d: %06X at %d,%d", sign, at(&k, fx, fy), fx, fy);
        /* across the short axis 20 px out is outside */
        int32_t ox = (int32_t)lround(60 - 20 * uy), oy = (int32_t)lround(60 - 20 * ux);
        FX_CHECK_MSG(at(&k, ox, oy) == 0, "sign case %d: %06X at %d,%d", sign, at(&k, ox, oy), ox, oy);
        /* the long axis line reaches 39 px out (white), and not 44 */
        int32_t lx = (int32_t)lround(60 + 39 * ux), ly = (int32_t)lround(60 - 39 * uy);
        int lit = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++)
                lit |= at(&k, lx + dx, ly + dy) == 0xFFFFFF;
        FX_CHECK_MSG(lit, "sign case %d: axis end", sign);
        FX_CHECK(at(&k, (int32_t)lround(60 + 46 * ux), (int32_t)lround(60 - 46 * uy)) == 0);
        free(k.px);
    }
}

FX_TEST(tensor_glyph_heads_show_the_sign)
{
    /* a diagonal tensor: l1 along x. Tension (> 0) puts the barbs inside
     * the tip (toward the centre), compression outside it. */
    for (int s = -1; s <= 1; s += 2) {
        fx_eigen2 e;
        FX_CHECK_EQ(fx_eigen2_sym(1000 * s, 0, 10 * s, &e), 0);
        cnv k;
        cnv_new(&k, 120, 120);
        fx_ctx_set_color(&k.c, 0xFFFFFFFFu);
        fx_tensor_glyph(&k.c, 60 * 256, 60 * 256, &e, 1000, 40 * 256, NULL);
        /* the tip on the right is at x = 100; barbs 6 px long at 30 degrees */
        int inside = 0, outside = 0;
        for (int y = 55; y <= 65; y++) {
            if (y == 60)
                continue;
            for (int x = 94; x < 100; x++)
                inside += at(&k, x, y) == 0xFFFFFF;
            for (int x = 101; x <= 106; x++)
                outside += at(&k, x, y) == 0xFFFFFF;
        }
        if (s > 0)
            FX_CHECK_MSG(inside >= 4 && outside == 0, "tension: %d in, %d out", inside, outside);
        else
            FX_CHECK_MSG(outside >= 4, "compression: %d out", outside);
        free(k.px);
    }
}

FX_TEST(tensor_glyphs_over_a_grid)
{
    int32_t a[9], b[9], c[9];
    for (int i = 0; i < 9; i++)
        a[i] = 100 * (i + 1), b[i] = 0, c[i] = -50 * i;
    fx_tgrid g = {a, b, c, 3, 3, 3};
    cnv k;
    cnv_new(&k, 100, 100);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){0, 0, 100, 100}, &g, 2, NULL), 4);
    memset(k.px, 0, 100 * 100 * 4);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){0, 0, 100, 100}, &g, 1, NULL), 9);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){0, 0, 100, 100}, &g, 0, NULL), -FX_EINVAL);
    /* the largest eigenvalue (900, node 8 at the bottom-right) gets 0.45
     * of the 49.5 px spacing: its axis ends near (99 - 22, 99) */
    FX_CHECK(at(&k, 78, 99) == 0xFFFFFF || at(&k, 77, 99) == 0xFFFFFF);
    FX_CHECK(at(&k, 74, 99) == 0);
    c[4] = FX_TENSOR_MAX + 1;
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){0, 0, 100, 100}, &g, 1, NULL), -FX_ERANGE);
    /* far off the surface: nothing drawn, nothing overflows */
    c[4] = 0;
    memset(k.px, 0, 100 * 100 * 4);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){INT32_MAX - 1000, 0, INT32_MAX, 100}, &g, 1, NULL), 9);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){-1048576, -1048576, 1048576, 1048576}, &g, 1, NULL), 9);
    /* the whole int32 plane, any step: no overflow (the sanitized build checks) */
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX}, &g, 1, NULL), 9);
    FX_CHECK_EQ(fx_tensor_glyphs(&k.c, (fx_rect){INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX}, &g, INT32_MAX, NULL), 1);
    free(k.px);
}

FX_TEST(star_glyph_spokes)
{
    cnv k;
    cnv_new(&k, 80, 80);
    fx_ctx_set_color(&k.c, 0xFF00FF00u);
    fx16 v[4] = {FX16_ONE, FX16_ONE, 2 * FX16_ONE, FX16_ONE / 2};
    FX_CHECK_EQ(fx_star_glyph(&k.c, 40, 40, 20, v, 4, 0xFFFFFFFFu), 0);
    /* up 20 (spoke end, outlined), right 20 (clamped from 2), left 10 */
    FX_CHECK_EQ(at(&k, 40, 20), 0xFFFFFF);
    FX_CHECK_EQ(at(&k, 60, 40), 0xFFFFFF);
    FX_CHECK_EQ(at(&k, 61, 40), 0);
    FX_CHECK_EQ(at(&k, 30, 40), 0xFFFFFF);
    FX_CHECK_EQ(at(&k, 25, 40), 0);
    /* inside the polygon, off the spokes: filled */
    FX_CHECK_EQ(at(&k, 45, 30), 0x00FF00);
    /* outside the up-right edge */
    FX_CHECK_EQ(at(&k, 55, 25), 0);
    FX_CHECK_EQ(fx_star_glyph(&k.c, 40, 40, INT32_MAX, v, 4, 0), 0);
    FX_CHECK_EQ(fx_star_glyph(&k.c, INT32_MIN, INT32_MAX, INT32_MAX, v, 4, 0), 0);
    FX_CHECK_EQ(fx_star_glyph(&k.c, 40, 40, 20, v, 2, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_star_glyph(&k.c, 40, 40, 20, v, 33, 0), -FX_EINVAL);
    free(k.px);
}

FX_TEST(multi_glyph_parts)
{
    cnv k;
    cnv_new(&k, 80, 80);
    fx_ctx_set_color(&k.c, 0xFFFFFFFFu);
    /* arrow up, colour at 0.25 of viridis, bar at half height */
    fx_multi_glyph(&k.c, 40, 40, 64, 0, FX16_ONE, FX16_ONE / 4, FX16_HALF, FX_CMAP_VIRIDIS);
    uint32_t disc = fx_cmap_color(FX_CMAP_VIRIDIS, 16384) & 0xFFFFFF;
    FX_CHECK_EQ(at(&k, 36, 44), disc);
    FX_CHECK_EQ(at(&k, 44, 36) == 0xFFFFFF || at(&k, 44, 36) == disc, 1);
    /* the arrow's shaft up to y = 40 - 32 */
    FX_CHECK_EQ(at(&k, 40, 10), 0xFFFFFF);
    FX_CHECK_EQ(at(&k, 40, 5), 0);
    /* the bar: box x 64..71 (width 8), y 8..71; filled rows 40..71 */
    int filled = 0;
    for (int y = 9; y < 71; y++)
        filled += at(&k, 67, y) == 0xFFFFFF;
    FX_CHECK_MSG(filled == 31, "bar rows %d", filled);
    FX_CHECK_EQ(at(&k, 64, 8), 0xFFFFFF);
    free(k.px);
}

/* ---- CIE 1931 ---- */

FX_TEST(cie_table_and_interpolation)
{
    /* y-bar peaks at 555 nm with exactly 1; z-bar at 445; x-bar at 600 */
    int ymax = 0, zmax = 0, xmax = 0;
    for (int i = 0; i < FX_CIE_N; i++) {
        for (int k = 0; k < 3; k++)
            FX_CHECK(fx_cie1931_cmf[i][k] >= 0);
        ymax = fx_cie1931_cmf[i][1] > fx_cie1931_cmf[ymax][1] ? i : ymax;
        zmax = fx_cie1931_cmf[i][2] > fx_cie1931_cmf[zmax][2] ? i : zmax;
        xmax = fx_cie1931_cmf[i][0] > fx_cie1931_cmf[xmax][0] ? i : xmax;
    }
    FX_CHECK_EQ(FX_CIE_FIRST + FX_CIE_STEP * ymax, 555);
    FX_CHECK_EQ(fx_cie1931_cmf[ymax][1], 1000000);
    FX_CHECK_EQ(FX_CIE_FIRST + FX_CIE_STEP * zmax, 445);
    FX_CHECK_EQ(FX_CIE_FIRST + FX_CIE_STEP * xmax, 600);
    fx_xyz c = fx_wavelength_to_xyz(555 * FX16_ONE);
    FX_CHECK_EQ(c.y, FX16_ONE);
    FX_CHECK_EQ(c.x, 33558); /* 0.51205 * 65536 = 33557.7 */
    /* half-way between 555 and 560: the mean of the rows */
    c = fx_wavelength_to_xyz(555 * FX16_ONE + 5 * FX16_HALF);
    FX_CHECK(abs(c.y - (int32_t)lround((1.0 + 0.995) / 2 * 65536)) <= 1);
    FX_CHECK(abs(c.x - (int32_t)lround((0.51205 + 0.5945) / 2 * 65536)) <= 1);
    /* the ends are in, beyond them nothing */
    FX_CHECK(fx_wavelength_to_xyz(380 * FX16_ONE).z == (int32_t)lround(0.00645 * 65536));
    FX_CHECK(fx_wavelength_to_xyz(780 * FX16_ONE).y == 1);
    c = fx_wavelength_to_xyz(379 * FX16_ONE);
    FX_CHECK(c.x == 0 && c.y == 0 && c.z == 0);
    c = fx_wavelength_to_xyz(781 * FX16_ONE);
    FX_CHECK(c.x == 0 && c.y == 0 && c.z == 0);
}

FX_TEST(wavelength_colours)
{
    fx_color r = fx_wavelength_to_rgb(700 * FX16_ONE);
    FX_CHECK_MSG(((r >> 16) & 255) == 255 && ((r >> 8) & 255) < 40 && (r & 255) < 128, "700 nm: %06X", r);
    fx_color g = fx_wavelength_to_rgb(530 * FX16_ONE);
    FX_CHECK_MSG(((g >> 8) & 255) == 255 && ((g >> 16) & 255) < 160 && (g & 255) < 160, "530 nm: %06X", g);
    fx_color b = fx_wavelength_to_rgb(450 * FX16_ONE);
    FX_CHECK_MSG((b & 255) == 255 && ((b >> 16) & 255) < 200 && ((b >> 8) & 255) < 128, "450 nm: %06X", b);
    fx_color y = fx_wavelength_to_rgb(575 * FX16_ONE);
    FX_CHECK_MSG(((y >> 16) & 255) > 150 && ((y >> 8) & 255) > 150 && (y & 255) < 60, "575 nm: %06X", y);
    FX_CHECK_EQ(fx_wavelength_to_rgb(300 * FX16_ONE), 0xFF000000u);
    /* white stays white: D65 is (1, 1, 1) in linear sRGB */
    fx_xyz w = {FX_XYZ_WHITE_X, FX_XYZ_WHITE_Y, FX_XYZ_WHITE_Z};
    FX_CHECK_EQ(fx_xyz_to_rgb_display(w), 0xFFFFFFFFu);
    /* every wavelength has one channel at full and none negative: hue
     * kept, the display's brightest */
    for (int nm = 380; nm <= 780; nm++) {
        fx_color c = fx_wavelength_to_rgb(nm * FX16_ONE);
        int mx = (int)((c >> 16) & 255);
        mx = (int)((c >> 8) & 255) > mx ? (int)((c >> 8) & 255) : mx;
        mx = (int)(c & 255) > mx ? (int)(c & 255) : mx;
        FX_CHECK_MSG(mx == 255, "%d nm: %06X", nm, c);
    }
}

FX_TEST(chromaticity_sums_to_one)
{
    for (int i = 0; i < FX_CIE_N; i++) {
        fx_xyz c = fx_wavelength_to_xyz((FX_CIE_FIRST + FX_CIE_STEP * i) * FX16_ONE);
        fx16 x, y;
        FX_CHECK_EQ(fx_xyz_to_xy(c, &x, &y), 0);
        int64_t s = (int64_t)c.x + c.y + c.z;
        int32_t z = (int32_t)(((int64_t)c.z * 65536 + s / 2) / s);
        FX_CHECK_MSG(labs((long)x + y + z - 65536) <= 1, "%d nm: %d + %d + %d", FX_CIE_FIRST + FX_CIE_STEP * i, x,
                     y, z);
        FX_CHECK(x >= 0 && y >= 0 && x + y <= 65537);
    }
    fx_xyz zero = {0, 0, 0};
    fx16 x, y;
    FX_CHECK_EQ(fx_xyz_to_xy(zero, &x, &y), -FX_EDOM);
}

/* Winding number of the closed polygon xy (n points) around (px, py). */
static int winding(const fx16 *xy, int n, double px, double py)
{
    double sum = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double a = atan2(xy[2 * i + 1] / 65536.0 - py, xy[2 * i] / 65536.0 - px);
        double b = atan2(xy[2 * j + 1] / 65536.0 - py, xy[2 * j] / 65536.0 - px);
        double d = b - a;
        while (d > M_PI)
            d -= 2 * M_PI;
        while (d < -M_PI)
            d += 2 * M_PI;
        sum += d;
    }
    return (int)lround(sum / (2 * M_PI));
}

FX_TEST(spectral_locus_is_closed_round_the_gamut)
{
    fx16 xy[2 * FX_CIE_N];
    FX_CHECK_EQ(fx_spectral_locus(xy), FX_CIE_N);
    /* 380 nm at (0.1741, 0.0050), 700 nm at (0.7347, 0.2653); 780 nm
     * near 700's (its six-decimal table values give 0.7368, 0.2632) */
    FX_CHECK(abs(xy[0] - 11410) <= 40 && abs(xy[1] - 328) <= 40);
    FX_CHECK(abs(xy[2 * 64] - 48149) <= 40 && abs(xy[2 * 64 + 1] - 17387) <= 40);
    FX_CHECK(abs(xy[2 * 80] - 48149) <= 200 && abs(xy[2 * 80 + 1] - 17387) <= 200);
    /* closed by the line of purples, the locus goes once round white and
     * the sRGB primaries, and not round points outside */
    int w = winding(xy, FX_CIE_N, 0.3127, 0.3290);
    FX_CHECK(w == 1 || w == -1);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.64, 0.33), w);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.30, 0.60), w);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.15, 0.06), w);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.6, 0.6), 0);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.05, 0.05), 0);
    FX_CHECK_EQ(winding(xy, FX_CIE_N, 0.4, 0.1), 0);
    /* the diagram: white at D65, untouched outside the horseshoe */
    cnv k;
    cnv_new(&k, 161, 181);
    FX_CHECK_EQ(fx_chromaticity_diagram(&k.c, (fx_rect){0, 0, 161, 181}, FX_CHROMA_FILL), 0);
    /* x = 0.3127 -> 62.5 px, y = 0.329 -> 180 - 65.8 */
    uint32_t p = at(&k, 63, 114);
    FX_CHECK_MSG((p >> 16) > 240 && ((p >> 8) & 255) > 240 && (p & 255) > 240, "white point %06X", p);
    FX_CHECK_EQ(at(&k, 150, 10), 0);
    FX_CHECK_EQ(at(&k, 5, 175), 0);
    /* red corner of sRGB is red, green is green */
    p = at(&k, 128, 114); /* (0.64, 0.33) */
    FX_CHECK_MSG((p >> 16) == 255 && ((p >> 8) & 255) < 80, "red primary %06X", p);
    p = at(&k, 60, 60); /* (0.30, 0.60) */
    FX_CHECK_MSG(((p >> 8) & 255) == 255 && (p >> 16) < 200, "green primary %06X", p);
    FX_CHECK_EQ(fx_chromaticity_diagram(&k.c, (fx_rect){0, 0, 0, 10}, FX_CHROMA_FILL), -FX_EINVAL);
    FX_CHECK_EQ(fx_chromaticity_diagram(&k.c, (fx_rect){0, 0, 2000000, 10}, FX_CHROMA_FILL), -FX_E2BIG);
    free(k.px);
}

/* ---- hatching ---- */

FX_TEST(hatch_density_falls_with_intensity)
{
    FX_CHECK_EQ(fx_hatch_level(255), 0);
    FX_CHECK_EQ(fx_hatch_level(0), FX_HATCH_LEVELS - 1);
    FX_CHECK_EQ(fx_hatch_ink(0), 0);
    for (int l = 1; l < FX_HATCH_LEVELS; l++)
        FX_CHECK_MSG(fx_hatch_ink(l) > fx_hatch_ink(l - 1), "level %d: %d <= %d", l, fx_hatch_ink(l),
                     fx_hatch_ink(l - 1));
    /* drawn: a filled rectangle's ink never rises with the intensity, and
     * the number of hatch directions never falls as it darkens */
    int32_t last_ink = -1;
    int last_dirs = 5;
    for (int v = 0; v <= 255; v++) {
        cnv k;
        cnv_new(&k, 48, 48);
        fx_fill_style st;
        uint8_t bits[FX_HATCH_BYTES];
        int dirs = fx_hatch_style(&st, bits, (uint8_t)v);
        k.c.fill_style = &st;
        /* the pixel centres 0..47 inside (top-left rule: the far edges at 48 are out) */
        static const int32_t sq[8] = {0, 0, 48, 0, 48, 48, 0, 48};
        fx_fill_poly(&k.c, sq, 4, FX_FILL_EVENODD);
        int32_t ink = 0;
        for (int i = 0; i < 48 * 48; i++)
            ink += (k.px[i] & 0xFFFFFF) != 0;
        if (last_ink >= 0)
            FX_CHECK_MSG(ink <= last_ink && dirs <= last_dirs, "intensity %d: ink %d dirs %d", v, ink, dirs);
        /* the tile repeats every 16 px: the ink is 9 tiles' worth */
        FX_CHECK_EQ(ink, 9 * fx_hatch_ink(fx_hatch_level((uint8_t)v)));
        last_ink = ink;
        last_dirs = dirs;
        free(k.px);
    }
    FX_CHECK_EQ(last_ink, 0);
}

/* ---- colour solids ---- */

FX_TEST(colour_solids_are_closed_outward_and_coloured)
{
    for (int kind = 0; kind < FX_SOLID_COUNT; kind++) {
        fx_vec3 pos[FX_COLOUR_SOLID_VERTS], nrm[1];
        uint32_t tri[3 * FX_COLOUR_SOLID_TRIS], col[FX_COLOUR_SOLID_VERTS];
        fx_mesh m = {pos, nrm, tri, 0, 0, FX_COLOUR_SOLID_VERTS, FX_COLOUR_SOLID_TRIS, NULL, col};
        fx16 size = 2 * FX16_ONE, h = FX16_ONE;
        FX_CHECK_EQ(fx_colour_solid_make(&m, (fx_colour_solid)kind, size), 0);
        FX_CHECK(m.nrm == NULL);
        FX_CHECK_EQ(m.nverts, 8);
        FX_CHECK_EQ(m.ntris, 12);
        /* every directed edge once, and its reverse once: closed, consistently wound */
        int seen[8][8];
        memset(seen, 0, sizeof seen);
        for (int t = 0; t < 12; t++) {
            const uint32_t *v = &tri[3 * t];
            for (int e = 0; e < 3; e++)
                seen[v[e]][v[(e + 1) % 3]]++;
            /* outward: the normal points away from the centre */
            double ax = pos[v[1]].x - pos[v[0]].x, ay = pos[v[1]].y - pos[v[0]].y, az = pos[v[1]].z - pos[v[0]].z;
            double bx = pos[v[2]].x - pos[v[0]].x, by = pos[v[2]].y - pos[v[0]].y, bz = pos[v[2]].z - pos[v[0]].z;
            double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
            double gx = pos[v[0]].x + pos[v[1]].x + pos[v[2]].x, gy = pos[v[0]].y + pos[v[1]].y + pos[v[2]].y,
                   gz = pos[v[0]].z + pos[v[1]].z + pos[v[2]].z;
            FX_CHECK_MSG(nx * gx + ny * gy + nz * gz > 0, "kind %d triangle %d inward", kind, t);
        }
        for (int i = 0; i < 8; i++)
            for (int j = 0; j < 8; j++)
                FX_CHECK_MSG(seen[i][j] == seen[j][i] && seen[i][j] <= 1, "kind %d edge %d-%d", kind, i, j);
        /* the colours are the model's at the positions */
        for (int i = 0; i < 8; i++) {
            fx_color c = col[i];
            if (kind == FX_SOLID_RGB_CUBE) {
                FX_CHECK_EQ((int)((c >> 16) & 255), pos[i].x > 0 ? 255 : 0);
                FX_CHECK_EQ((int)((c >> 8) & 255), pos[i].y > 0 ? 255 : 0);
                FX_CHECK_EQ((int)(c & 255), pos[i].z > 0 ? 255 : 0);
            } else if (kind == FX_SOLID_HSV_HEXCONE) {
                fx_hsv v = fx_rgb_to_hsv(c);
                /* V rises with height, S with the distance from the axis */
                FX_CHECK_EQ(v.v, pos[i].y == h ? FX16_ONE : 0);
                uint32_t r = fx_hypot(pos[i].x, pos[i].z);
                FX_CHECK(pos[i].y != h || abs(v.s - (int32_t)((int64_t)r * FX16_ONE / h)) <= 2);
                if (r > 0) {
                    /* hue = the angle round the axis, counter-clockwise seen from +y toward -z */
                    fx16 hue = fx_angle_to_deg16(fx_atan2(-pos[i].z, pos[i].x));
                    int32_t d = abs(hue - v.h);
                    FX_CHECK_MSG(d <= 2 * FX16_ONE || d >= 358 * FX16_ONE, "hsv hue %d vs %d", v.h >> 16, hue >> 16);
                }
            } else {
                fx_hls l = fx_rgb_to_hls(c);
                FX_CHECK_EQ(l.l, (fx16)(((int64_t)pos[i].y + h) * FX16_ONE / (2 * h)));
            }
        }
    }
    /* bad arguments */
    fx_vec3 pos[8];
    uint32_t tri[36], col[8];
    fx_mesh m = {pos, NULL, tri, 0, 0, 8, 12, NULL, NULL};
    FX_CHECK_EQ(fx_colour_solid_make(&m, FX_SOLID_RGB_CUBE, FX16_ONE), -FX_EINVAL);
    m.col = col;
    FX_CHECK_EQ(fx_colour_solid_make(&m, FX_SOLID_COUNT, FX16_ONE), -FX_EINVAL);
    FX_CHECK_EQ(fx_colour_solid_make(&m, FX_SOLID_RGB_CUBE, 0), -FX_EINVAL);
    m.cap_tris = 11;
    FX_CHECK_EQ(fx_colour_solid_make(&m, FX_SOLID_RGB_CUBE, FX16_ONE), -FX_EINVAL);
}
