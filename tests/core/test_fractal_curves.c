/* SPDX-License-Identifier: MIT */
/* Koch curves, random fractals, space-filling curves and IFS: segment
 * counts, exact culling (a clipped drawing lights exactly the pixels of the
 * unclipped one inside the clip), reproducibility of seeded randomness and
 * the structure of the curves. */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/ifs.h"
#include "fixel/koch.h"
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
}

static long lit(const canvas *k, fx_rect r)
{
    long n = 0;
    for (int32_t y = r.y0; y < r.y1; y++)
        for (int32_t x = r.x0; x < r.x1; x++)
            n += k->px[y * k->s.w + x] != 0;
    return n;
}

/* pixels of a inside r equal those of b inside r, and b is blank outside r */
static int same_in(const canvas *a, const canvas *b, fx_rect r)
{
    for (int32_t y = 0; y < a->s.h; y++)
        for (int32_t x = 0; x < a->s.w; x++) {
            int in = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
            uint8_t pa = a->px[y * a->s.w + x], pb = b->px[y * b->s.w + x];
            if (in ? pa != pb : pb != 0)
                return 0;
        }
    return 1;
}

FX_TEST(koch_segment_counts)
{
    canvas k;
    canvas_new(&k, 760, 420);
    uint64_t want = 1;
    for (uint32_t n = 0; n <= 6; n++, want *= 4) {
        FX_CHECK_EQ(fx_koch(&k.c, 15, 20, 15 + 729, 20, n), want); /* bumps towards +y, down */
        FX_CHECK_EQ(fx_koch_snowflake(&k.c, 380, 220, 190, n), 3 * want);
    }
    free(k.px);
    /* endpoints are lit, and the order-1 peak sits sqrt(3)/6 of the chord
     * towards +y: down the y-down screen (issue #44) */
    canvas_new(&k, 100, 60);
    fx_koch(&k.c, 5, 9, 95, 9, 1);
    FX_CHECK(k.px[9 * 100 + 5] && k.px[9 * 100 + 95]);
    FX_CHECK(k.px[(9 + 26) * 100 + 50] != 0); /* 90 * 0.2887 = 25.98 */
    FX_CHECK_EQ(lit(&k, (fx_rect){0, 9 + 27, 100, 60}), 0);
    FX_CHECK_EQ(lit(&k, (fx_rect){0, 0, 100, 9}), 0);
    free(k.px);
}

FX_TEST(koch_culling_is_exact)
{
    canvas full, part;
    canvas_new(&full, 300, 300);
    canvas_new(&part, 300, 300);
    fx_rect clip = {40, 120, 170, 260};
    fx_ctx_set_clip(&part.c, clip);
    for (uint32_t n = 3; n <= 7; n += 2) {
        memset(full.px, 0, 300 * 300);
        memset(part.px, 0, 300 * 300);
        uint64_t a = fx_koch_snowflake(&full.c, 150, 160, 140, n);
        uint64_t b = fx_koch_snowflake(&part.c, 150, 160, 140, n);
        FX_CHECK(same_in(&full, &part, clip));
        FX_CHECK(b < a / 2); /* most of the curve was never walked */
    }
    /* any order: beyond a pixel per piece the picture no longer changes */
    memset(full.px, 0, 300 * 300);
    memset(part.px, 0, 300 * 300);
    fx_ctx_reset_clip(&part.c);
    uint64_t a = fx_koch(&full.c, 10, 200, 290, 200, 30);
    uint64_t b = fx_koch(&part.c, 10, 200, 290, 200, 1000000);
    FX_CHECK_EQ(a, b);
    FX_CHECK(memcmp(full.px, part.px, 300 * 300) == 0);
    /* a curve far off the surface walks nothing */
    FX_CHECK_EQ(fx_koch(&full.c, 100000, 5, 200000, 5, 40), 0);
    free(full.px);
    free(part.px);
}

FX_TEST(random_gauss_and_exp2)
{
    uint32_t st = 12345;
    int64_t sum = 0, sum2 = 0;
    const int n = 100000;
    for (int i = 0; i < n; i++) {
        int64_t g = fx_gauss16(&st);
        FX_CHECK(g >= -6 * 65536 && g <= 6 * 65536);
        sum += g;
        sum2 += g * g;
    }
    int64_t mean = sum / n;                /* Q16 */
    int64_t var = sum2 / n / 65536;         /* Q16 */
    FX_CHECK_MSG(mean > -1311 && mean < 1311, "mean %lld/65536", (long long)mean); /* |mean| < 0.02 */
    FX_CHECK_MSG(var > 63570 && var < 67502, "variance %lld/65536", (long long)var); /* 1 +- 0.03 */
    for (int e = -16; e <= 14; e++)
        FX_CHECK_EQ(fx16_exp2(e * 65536), e >= 0 ? 65536 << e : 65536 >> -e);
    FX_CHECK(abs(fx16_exp2(32768) - 92682) <= 1);  /* sqrt 2 */
    FX_CHECK(abs(fx16_exp2(-16384) - 55109) <= 1); /* 2^-0.25 */
    FX_CHECK_EQ(fx16_exp2(0), 65536);
}

FX_TEST(fractline_reproducible)
{
    canvas a, b;
    canvas_new(&a, 200, 120);
    canvas_new(&b, 200, 120);
    fx_fract_params p = {98304 /* 1.5 */, 19661 /* 0.3 */, 2, 77};
    uint32_t sa = p.seed, sb = p.seed;
    uint32_t na = fx_fractline(&a.c, 10, 60, 190, 60, &p, &sa);
    uint32_t nb = fx_fractline(&b.c, 10, 60, 190, 60, &p, &sb);
    FX_CHECK_EQ(na, nb);
    FX_CHECK_EQ(sa, sb);
    FX_CHECK(memcmp(a.px, b.px, 200 * 120) == 0);
    FX_CHECK(a.px[60 * 200 + 10] && a.px[60 * 200 + 190]);
    FX_CHECK(na >= 64); /* 180 px in pieces under 2 px */
    /* it wanders: not just the straight chord */
    long off_chord = lit(&a, (fx_rect){0, 0, 200, 60}) + lit(&a, (fx_rect){0, 61, 200, 120});
    FX_CHECK(off_chord > 20);
    /* another seed, another line; the same seed under a clip, the same pixels */
    memset(b.px, 0, 200 * 120);
    sb = 78;
    fx_fractline(&b.c, 10, 60, 190, 60, &p, &sb);
    FX_CHECK(memcmp(a.px, b.px, 200 * 120) != 0);
    memset(b.px, 0, 200 * 120);
    fx_rect clip = {50, 0, 120, 120};
    fx_ctx_set_clip(&b.c, clip);
    sb = 77;
    fx_fractline(&b.c, 10, 60, 190, 60, &p, &sb);
    FX_CHECK(same_in(&a, &b, clip));
    /* beta = 1: the deviation is not scaled (factor exactly 1) */
    FX_CHECK_EQ(fx16_exp2((FX16_ONE - FX16_ONE) / 2), FX16_ONE);
    free(a.px);
    free(b.px);
}

FX_TEST(terrain_reproducible)
{
    int32_t a[33 * 33], b[33 * 33];
    FX_CHECK_EQ(fx_terrain(a, 33, 5, 1000, 32768, 5), 0);
    FX_CHECK_EQ(fx_terrain(b, 33, 5, 1000, 32768, 5), 0);
    FX_CHECK(memcmp(a, b, sizeof a) == 0);
    FX_CHECK_EQ(fx_terrain(b, 33, 5, 1000, 32768, 6), 0);
    FX_CHECK(memcmp(a, b, sizeof a) != 0);
    /* heights stay within the summed amplitudes (1000 * sum of 2^-H/2 ...) */
    int32_t lo = a[0], hi = a[0];
    for (int i = 0; i < 33 * 33; i++) {
        lo = a[i] < lo ? a[i] : lo;
        hi = a[i] > hi ? a[i] : hi;
        FX_CHECK(a[i] > -4000 && a[i] < 4000);
    }
    FX_CHECK(hi - lo > 200);
    /* rougher terrain has larger neighbour differences */
    int32_t r[33 * 33], s[33 * 33];
    fx_terrain(r, 33, 5, 1000, 6554 /* 0.1 */, 9);
    fx_terrain(s, 33, 5, 1000, 58982 /* 0.9 */, 9);
    int64_t dr = 0, ds = 0;
    for (int j = 0; j < 33; j++)
        for (int i = 0; i + 1 < 33; i++) {
            dr += llabs((long long)r[j * 33 + i + 1] - r[j * 33 + i]);
            ds += llabs((long long)s[j * 33 + i + 1] - s[j * 33 + i]);
        }
    FX_CHECK(dr > 2 * ds);
    FX_CHECK_EQ(fx_terrain(a, 32, 5, 1000, 0, 1), -FX_EINVAL);
}

static void curve_props(int (*d2xy)(uint32_t, uint64_t, uint32_t *, uint32_t *), uint32_t base,
                        uint32_t n)
{
    uint32_t side = 1;
    for (uint32_t i = 0; i < n; i++)
        side *= base;
    uint8_t *seen = calloc((size_t)side * side, 1);
    uint32_t px = 0, py = 0;
    for (uint64_t d = 0; d < (uint64_t)side * side; d++) {
        uint32_t x, y;
        FX_CHECK_EQ(d2xy(n, d, &x, &y), 0);
        FX_CHECK(x < side && y < side);
        FX_CHECK(!seen[y * side + x]);
        seen[y * side + x] = 1;
        if (d)
            FX_CHECK_MSG((x == px && (y == py + 1 || y + 1 == py)) ||
                             (y == py && (x == px + 1 || x + 1 == px)),
                         "order %u step %llu jumps", n, (unsigned long long)d);
        px = x;
        py = y;
    }
    free(seen);
}

FX_TEST(space_filling_curves)
{
    for (uint32_t n = 1; n <= 6; n++)
        curve_props(fx_hilbert_d2xy, 2, n);
    for (uint32_t n = 1; n <= 4; n++)
        curve_props(fx_peano_d2xy, 3, n);
    /* at one pixel per cell the curve lights its whole square */
    canvas a, b;
    canvas_new(&a, 100, 100);
    canvas_new(&b, 100, 100);
    FX_CHECK_EQ(fx_hilbert(&a.c, 10, 10, 64, 6), 4095u);
    FX_CHECK_EQ(lit(&a, (fx_rect){10, 10, 74, 74}), 64 * 64);
    FX_CHECK_EQ(lit(&a, (fx_rect){0, 0, 100, 100}), 64 * 64);
    /* finer orders draw the finest order that still has whole pixels */
    FX_CHECK_EQ(fx_hilbert(&b.c, 10, 10, 64, 99), 4095u);
    FX_CHECK(memcmp(a.px, b.px, 100 * 100) == 0);
    memset(a.px, 0, 100 * 100);
    memset(b.px, 0, 100 * 100);
    FX_CHECK_EQ(fx_peano(&a.c, 5, 5, 81, 4), 6560u);
    FX_CHECK_EQ(lit(&a, (fx_rect){5, 5, 86, 86}), 81 * 81);
    /* clipped drawings skip blocks without moving a pixel */
    memset(a.px, 0, 100 * 100);
    fx_rect clip = {23, 37, 61, 90};
    fx_ctx_set_clip(&b.c, clip);
    for (int peano = 0; peano < 2; peano++) {
        memset(a.px, 0, 100 * 100);
        memset(b.px, 0, 100 * 100);
        uint32_t na = peano ? fx_peano(&a.c, 3, 4, 90, 3) : fx_hilbert(&a.c, 3, 4, 90, 5);
        uint32_t nb = peano ? fx_peano(&b.c, 3, 4, 90, 3) : fx_hilbert(&b.c, 3, 4, 90, 5);
        FX_CHECK(same_in(&a, &b, clip));
        FX_CHECK(nb < na);
    }
    free(a.px);
    free(b.px);
}

FX_TEST(ifs_chaos_and_copier)
{
    FX_CHECK_EQ(fx_ifs_check(&fx_ifs_sierpinski), 0);
    FX_CHECK_EQ(fx_ifs_check(&fx_ifs_fern), 0);
    canvas a, b;
    canvas_new(&a, 128, 128);
    canvas_new(&b, 128, 128);
    fx_rect d = {0, 0, 128, 128};
    FX_CHECK_EQ(fx_ifs_chaos(&a.c, d, &fx_ifs_sierpinski, 30000, 4), 30000);
    FX_CHECK_EQ(fx_ifs_chaos(&b.c, d, &fx_ifs_sierpinski, 30000, 4), 30000);
    FX_CHECK(memcmp(a.px, b.px, 128 * 128) == 0);
    /* the big hole (the middle triangle, centroid (1/2, 1/3)) stays empty,
     * and so do the top corners outside the triangle */
    FX_CHECK_EQ(lit(&a, (fx_rect){58, 80, 70, 90}), 0);
    FX_CHECK_EQ(lit(&a, (fx_rect){0, 0, 20, 20}), 0);
    FX_CHECK(lit(&a, d) > 2000);
    /* the three corners of the triangle are reached */
    FX_CHECK(lit(&a, (fx_rect){0, 120, 8, 128}) > 0 && lit(&a, (fx_rect){120, 120, 128, 128}) > 0);
    FX_CHECK(lit(&a, (fx_rect){60, 0, 68, 8}) > 0);
    /* copier: n^depth copies, all inside the window's picture */
    memset(b.px, 0, 128 * 128);
    FX_CHECK_EQ(fx_ifs_copier(&b.c, d, &fx_ifs_sierpinski, 5), 243);
    FX_CHECK_EQ(lit(&b, (fx_rect){58, 80, 70, 90}), 0);
    FX_CHECK_EQ(fx_ifs_copier(&b.c, d, &fx_ifs_fern, 11), -FX_EINVAL); /* 4^11 > 2^20 */
    /* the fern: points land, and the seed changes them */
    memset(a.px, 0, 128 * 128);
    memset(b.px, 0, 128 * 128);
    FX_CHECK(fx_ifs_chaos(&a.c, d, &fx_ifs_fern, 20000, 1) > 19000);
    fx_ifs_chaos(&b.c, d, &fx_ifs_fern, 20000, 2);
    FX_CHECK(memcmp(a.px, b.px, 128 * 128) != 0);
    /* a user system: probabilities must sum to one */
    fx_ifs_map m[2] = {{32768, 0, 0, 32768, 0, 0, 30000}, {32768, 0, 0, 32768, 32768, 0, 30000}};
    fx_ifs u = {m, 2, 0, 0, 65536, 65536};
    FX_CHECK_EQ(fx_ifs_check(&u), -FX_EINVAL);
    m[1].p = 35536;
    FX_CHECK_EQ(fx_ifs_check(&u), 0);
    free(a.px);
    free(b.px);
}

FX_TEST(curves_extreme_arguments)
{
    canvas k;
    canvas_new(&k, 64, 64);
    /* a curve 2^31 px long starts on the surface: its start is drawn, and
     * only the few pieces near it are walked */
    uint64_t segs0 = fx_koch(&k.c, 0, 32, INT32_MAX, 32, 100);
    FX_CHECK(segs0 > 0 && segs0 < 2000);
    FX_CHECK(k.px[32 * 64] != 0);
    memset(k.px, 0, 64 * 64);
    fx_hilbert(&k.c, 2000000000, 0, 2000000000, 30);
    fx_peano(&k.c, 2000000000, -5, 2000000000, 30);
    fx_koch_snowflake(&k.c, INT32_MAX, INT32_MAX, INT32_MAX, 50);
    fx_ifs_copier(&k.c, (fx_rect){1 << 30, 0, INT32_MAX, 1 << 30}, &fx_ifs_sierpinski, 3);
    FX_CHECK_EQ(fx_ifs_chaos(&k.c, (fx_rect){1 << 30, 0, INT32_MAX, 1 << 30}, &fx_ifs_fern, 500, 1), 0);
    FX_CHECK_EQ(lit(&k, (fx_rect){0, 0, 64, 64}), 0);
    /* a fractal line across all of int32 stays a bounded walk */
    fx_fract_params p = {98304, 6554, 1, 3};
    uint32_t st = 1;
    uint32_t segs = fx_fractline(&k.c, INT32_MIN, 0, INT32_MAX, 10, &p, &st);
    FX_CHECK(segs > 1000 && segs < (1u << 21));
    free(k.px);
}

/* Issue #40: fx_peano_d2xy(21, ...) wrote past its 40-digit array and
 * fx_hilbert_d2xy(32, ...) shifted by 32. Orders and steps past the end are
 * refused with nothing written; the largest orders still give the curve's
 * last cell (3^20 - 1 and 2^31 - 1 are the far corner's coordinates). */
FX_TEST(space_filling_curves_bound_the_order)
{
    uint32_t x = 7, y = 7;
    FX_CHECK_EQ(fx_peano_d2xy(21, 0, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_peano_d2xy(UINT32_MAX, UINT64_MAX, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_hilbert_d2xy(32, 0, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_hilbert_d2xy(UINT32_MAX, 0, &x, &y), -FX_EINVAL);
    FX_CHECK(x == 7 && y == 7);
    FX_CHECK_EQ(fx_peano_d2xy(1, 9, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_hilbert_d2xy(1, 4, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_peano_d2xy(1, 0, NULL, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_hilbert_d2xy(1, 0, &x, NULL), -FX_EINVAL);
    FX_CHECK(x == 7 && y == 7);
    uint64_t last = 1;
    for (int i = 0; i < 20; i++)
        last *= 9;
    FX_CHECK_EQ(fx_peano_d2xy(20, last - 1, &x, &y), 0);
    FX_CHECK(x == 3486784400u && y == 3486784400u);
    FX_CHECK_EQ(fx_peano_d2xy(20, last, &x, &y), -FX_EINVAL);
    FX_CHECK_EQ(fx_hilbert_d2xy(31, ((uint64_t)1 << 62) - 1, &x, &y), 0);
    FX_CHECK(x == (1u << 31) - 1 && y == 0);
    FX_CHECK_EQ(fx_hilbert_d2xy(31, (uint64_t)1 << 62, &x, &y), -FX_EINVAL);
}
