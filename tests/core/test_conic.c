/* SPDX-License-Identifier: MIT */
/* Circles and conics: the course's r = 10 table, the circle against the W5
 * reference loop, discs and filled ellipses against their definitions,
 * clipped-vs-unclipped identity (centres far off-screen, huge radii), arcs
 * and pie slices partitioning circles and discs, and the ellipse's regions
 * agreeing with the circle and staying connected. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fixel/circle.h"
#include "fx_test.h"

typedef struct {
    fx_surface s;
    uint8_t *mem;
} gray;

static gray gray_make(int w, int h)
{
    gray g;
    g.mem = calloc((size_t)w * h, 1);
    fx_surface_init(&g.s, g.mem, w, h, w, FX_FMT_GRAY8);
    return g;
}

static void gray_clear(gray *g) { memset(g->mem, 0, (size_t)g->s.w * g->s.h); }

static int lit(const gray *g, int x, int y) { return g->mem[(size_t)y * g->s.w + x] != 0; }

/* ---- the reference loop of W5 (docs/BENCHMARK.md), plotted into a mask ---- */

static void ref_put(uint8_t *m, int w, int h, int64_t x, int64_t y)
{
    if (x >= 0 && x < w && y >= 0 && y < h)
        m[y * w + x] = 1;
}

static void ref_circle(uint8_t *m, int w, int h, int64_t cx, int64_t cy, int64_t r)
{
    int64_t x = r, y = 0, d = 1 - r;
    while (y <= x) {
        ref_put(m, w, h, cx + x, cy + y);
        ref_put(m, w, h, cx - x, cy + y);
        ref_put(m, w, h, cx + x, cy - y);
        ref_put(m, w, h, cx - x, cy - y);
        ref_put(m, w, h, cx + y, cy + x);
        ref_put(m, w, h, cx - y, cy + x);
        ref_put(m, w, h, cx + y, cy - x);
        ref_put(m, w, h, cx - y, cy - x);
        y++;
        if (d < 0) {
            d += 2 * y + 1;
        } else {
            x--;
            d += 2 * (y - x) + 1;
        }
    }
}

static char **tr_lines;
static int tr_n;
static void tr_collect(void *u, const char *line)
{
    (void)u;
    tr_lines = realloc(tr_lines, sizeof(char *) * (size_t)(tr_n + 1));
    tr_lines[tr_n++] = strdup(line);
}
static void tr_free(void)
{
    for (int i = 0; i < tr_n; i++)
        free(tr_lines[i]);
    free(tr_lines);
    tr_lines = NULL;
    tr_n = 0;
}

FX_TEST(conic_course_table_r10)
{
    gray g = gray_make(40, 40);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    c.trace = tr_collect;
    fx_circle(&c, 20, 20, 10);
    /* The course: first-octant points (0,10) (1,10) (2,10) (3,10) (4,9) (5,9)
     * (6,8) (7,7) with p_k = -9 -6 -1 6 -3 8 5. */
    static const int pk[] = {-9, -6, -1, 6, -3, 8, 5};
    static const int pt[][2] = {{1, 10}, {2, 10}, {3, 10}, {4, 9}, {5, 9}, {6, 8}, {7, 7}};
    FX_CHECK_EQ(tr_n, 2 + 7);
    if (tr_n == 9) {
        FX_CHECK(strstr(tr_lines[0], "p0=1-r=-9") != NULL);
        FX_CHECK(strstr(tr_lines[0], "5/4-r rounded") != NULL);
        FX_CHECK(strstr(tr_lines[1], "2x_k+1") && strstr(tr_lines[1], "2y_k+1"));
        for (int k = 0; k < 7; k++) {
            int kk, p, x, y, x2, y2;
            FX_CHECK_EQ(sscanf(tr_lines[k + 2], "%d %d (%d, %d) %d %d", &kk, &p, &x, &y, &x2, &y2), 6);
            /* the notes' 2x_k+1 and 2y_k+1 columns */
            FX_CHECK_EQ(x2, 2 * x);
            FX_CHECK_EQ(y2, 2 * y);
            FX_CHECK_EQ(kk, k);
            FX_CHECK_EQ(p, pk[k]);
            FX_CHECK_EQ(x, pt[k][0]);
            FX_CHECK_EQ(y, pt[k][1]);
            /* and those pixels are lit, with (0,10) */
            FX_CHECK(lit(&g, 20 + x, 20 - y));
        }
        FX_CHECK(lit(&g, 20, 10));
    }
    tr_free();
    /* the closed form gives the same octant */
    static const int a[] = {10, 10, 10, 10, 9, 9, 8, 7};
    FX_CHECK_EQ(fx_circle_octant_end(10), 7);
    for (int b = 0; b < 8; b++)
        FX_CHECK_EQ(fx_circle_octant_a(10, (uint32_t)b), a[b]);
    free(g.mem);
}

/* Every radius 0..300 fully visible (fast path) and thousands of random
 * circles with radii up to 2000 and centres off-screen (clipped path). */
FX_TEST(conic_circle_matches_w5_reference)
{
    int W = 640, H = 640;
    gray g = gray_make(W, H);
    uint8_t *m = calloc((size_t)W * H, 1);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    int bad = 0;
    for (int r = 0; r <= 300; r++) {
        gray_clear(&g);
        memset(m, 0, (size_t)W * H);
        fx_circle(&c, 320, 319, r);
        ref_circle(m, W, H, 320, 319, r);
        for (int i = 0; i < W * H; i++)
            bad += (g.mem[i] != 0) != m[i];
    }
    FX_CHECK_EQ(bad, 0);
    free(m);
    free(g.mem);

    W = 160, H = 120;
    g = gray_make(W, H);
    m = calloc((size_t)W * H, 1);
    fx_ctx_init(&c, &g.s);
    uint32_t seed = 77;
    bad = 0;
    int drawn = 0;
    for (int i = 0; i < 3000; i++) {
        int r = (int)(fx_test_rand(&seed) % 2001);
        int cx = (int)(fx_test_rand(&seed) % 4400) - 2200, cy = (int)(fx_test_rand(&seed) % 4400) - 2200;
        if (i % 3 == 0) { /* make sure many of them cross the surface */
            cx = (int)(fx_test_rand(&seed) % 200) - 20 + (i % 2 ? r : -r);
            cy = (int)(fx_test_rand(&seed) % 160) - 20;
        }
        gray_clear(&g);
        memset(m, 0, (size_t)W * H);
        fx_circle(&c, cx, cy, r);
        ref_circle(m, W, H, cx, cy, r);
        int any = 0;
        for (int k = 0; k < W * H; k++) {
            bad += (g.mem[k] != 0) != m[k];
            any |= m[k];
        }
        drawn += any;
    }
    FX_CHECK_EQ(bad, 0);
    FX_CHECK(drawn > 800);
    free(m);
    free(g.mem);
}

/* Each pixel of a circle, arc or ellipse is written once: a translucent
 * colour blended over black gives one value everywhere. */
FX_TEST(conic_translucent_outlines_blend_each_pixel_once)
{
    int W = 200, H = 160;
    uint32_t *mem = calloc((size_t)W * H, 4);
    fx_surface s;
    fx_surface_init(&s, mem, W, H, W * 4, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    c.blend = FX_BLEND_OVER;
    fx_ctx_set_color(&c, 0x80FFFFFFu);
    uint32_t once = fx_blend_over(FX_FMT_XRGB8888, 0, 0x80FFFFFFu);
    for (int r = 0; r < 60; r += 7) {
        memset(mem, 0, (size_t)W * H * 4);
        fx_circle(&c, 100, 80, r);
        fx_ellipse(&c, 100, 80, r + 30, r / 2 + 1);
        fx_arc(&c, 10, 10, r + 5, fx_angle_from_deg(10), fx_angle_from_deg(300));
        fx_pie(&c, 190, 150, r + 3, fx_angle_from_deg(200), fx_angle_from_deg(100));
        int n = 0, bad = 0;
        for (int i = 0; i < W * H; i++) {
            if (mem[i]) {
                n++;
                /* overlaps between different primitives are allowed: only
                 * count pixels darker or brighter than 1 or 2 layers */
                uint32_t twice = fx_blend_over(FX_FMT_XRGB8888, once, 0x80FFFFFFu);
                uint32_t thrice = fx_blend_over(FX_FMT_XRGB8888, twice, 0x80FFFFFFu);
                bad += (mem[i] & 0xFFFFFF) != once && (mem[i] & 0xFFFFFF) != twice &&
                       (mem[i] & 0xFFFFFF) != thrice;
            }
        }
        FX_CHECK(n > 0);
        FX_CHECK_EQ(bad, 0);
        /* a lone circle: exactly one layer everywhere */
        memset(mem, 0, (size_t)W * H * 4);
        fx_circle(&c, 100, 80, r);
        bad = 0;
        for (int i = 0; i < W * H; i++)
            bad += mem[i] && (mem[i] & 0xFFFFFF) != once;
        FX_CHECK_EQ(bad, 0);
        memset(mem, 0, (size_t)W * H * 4);
        fx_ellipse(&c, 100, 80, r + 30, r / 2 + 1);
        bad = 0;
        for (int i = 0; i < W * H; i++)
            bad += mem[i] && (mem[i] & 0xFFFFFF) != once;
        FX_CHECK_EQ(bad, 0);
    }
    free(mem);
}

FX_TEST(conic_disc_is_its_definition)
{
    int W = 120, H = 90;
    gray g = gray_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    uint32_t seed = 4242;
    int bad = 0, drawn = 0;
    for (int i = 0; i < 4000; i++) {
        int64_t r = fx_test_rand(&seed) % 2001;
        int64_t cx = (int64_t)(fx_test_rand(&seed) % 300) - 90, cy = (int64_t)(fx_test_rand(&seed) % 240) - 75;
        if (i & 1) { /* centre off-screen, edge through the surface */
            cx = (i & 2) ? -r + (int64_t)(fx_test_rand(&seed) % 100) : W + r - (int64_t)(fx_test_rand(&seed) % 100);
            cy = (int64_t)(fx_test_rand(&seed) % 300) - 100;
        }
        gray_clear(&g);
        fx_disc(&c, (int32_t)cx, (int32_t)cy, (int32_t)r);
        int any = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int in = (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
                bad += in != lit(&g, x, y);
                any |= in;
            }
        drawn += any;
    }
    FX_CHECK_EQ(bad, 0);
    FX_CHECK(drawn > 1000);
    free(g.mem);
}

/* Membership in the W5 pixel set by the closed form, written out here. */
static int w5_member(int64_t dx, int64_t dy, int64_t r)
{
    /* 128-bit: offsets reach 2^32 when both centre and pixel are extreme */
    __int128 a = dx < 0 ? -dx : dx, b = dy < 0 ? -dy : dy, R = r;
    if (a < b) {
        __int128 t = a;
        a = b;
        b = t;
    }
    if (r == 0)
        return a == 0;
    /* octant step b (b(2b-1) < r^2) whose pixel is a: a(a-1) < r^2-b^2 <= a(a+1) */
    __int128 n = R * R - b * b;
    return b * (2 * b - 1) < R * R && a * (a - 1) < n && n <= a * (a + 1);
}

FX_TEST(conic_huge_circles_clip_at_once)
{
    int W = 320, H = 240;
    gray g = gray_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    struct { int32_t cx, cy, r; } cases[] = {
        {160, 100000000 + 120, 100000000},           /* top of the circle crosses the middle */
        {-100000000 + 160, 120, 100000000},          /* right side */
        {160 + 70710678, 120 + 70710678, 100000000}, /* the diagonal seam */
        {INT32_MIN, INT32_MIN, INT32_MAX},
        {INT32_MAX, 0, INT32_MAX},
        {0, INT32_MAX, INT32_MAX},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gray_clear(&g);
        clock_t t0 = clock();
        fx_circle(&c, cases[i].cx, cases[i].cy, cases[i].r);
        fx_aacircle(&c, cases[i].cx, cases[i].cy, cases[i].r);
        fx_ellipse(&c, cases[i].cx, cases[i].cy, cases[i].r, cases[i].r);
        fx_disc(&c, cases[i].cx, cases[i].cy, cases[i].r);
        fx_fill_ellipse(&c, cases[i].cx, cases[i].cy, cases[i].r, cases[i].r / 2);
        fx_pie(&c, cases[i].cx, cases[i].cy, cases[i].r, 1000, 2000000000u);
        fx_arc(&c, cases[i].cx, cases[i].cy, cases[i].r, 1000, 2000000000u);
        double ms = (double)(clock() - t0) * 1000.0 / CLOCKS_PER_SEC;
        FX_CHECK_MSG(ms < 200, "case %zu took %.1f ms", i, ms);
        /* the outline alone, pixel for pixel */
        gray_clear(&g);
        fx_circle(&c, cases[i].cx, cases[i].cy, cases[i].r);
        int bad = 0, n = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int in = w5_member((int64_t)x - cases[i].cx, (int64_t)y - cases[i].cy, cases[i].r);
                bad += in != lit(&g, x, y);
                n += in;
            }
        FX_CHECK_MSG(bad == 0, "case %zu: %d pixels differ", i, bad);
        if (i < 3)
            FX_CHECK(n > 100);
        /* the ellipse with equal axes is the circle */
        gray g2 = gray_make(W, H);
        fx_ctx c2;
        fx_ctx_init(&c2, &g2.s);
        fx_ellipse(&c2, cases[i].cx, cases[i].cy, cases[i].r, cases[i].r);
        FX_CHECK(memcmp(g.mem, g2.mem, (size_t)W * H) == 0);
        free(g2.mem);
    }
    free(g.mem);
}

/* Draw with a clip rectangle and without: inside the clip the pictures are
 * equal, outside it the clipped one is untouched. */
typedef void (*drawfn)(const fx_ctx *, int32_t, int32_t, int32_t, int32_t, uint32_t);

static void d_circle(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)r2, (void)a;
    fx_circle(c, x, y, r);
}
static void d_disc(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)r2, (void)a;
    fx_disc(c, x, y, r);
}
static void d_aa(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)r2, (void)a;
    fx_aacircle(c, x, y, r);
}
static void d_ell(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)a;
    fx_ellipse(c, x, y, r, r2);
}
static void d_fell(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)a;
    fx_fill_ellipse(c, x, y, r, r2);
}
static void d_arc(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)r2;
    fx_arc(c, x, y, r, a, a * 7u);
}
static void d_pie(const fx_ctx *c, int32_t x, int32_t y, int32_t r, int32_t r2, uint32_t a)
{
    (void)r2;
    fx_pie(c, x, y, r, a, a * 5u);
}

FX_TEST(conic_clipped_equals_unclipped)
{
    int W = 300, H = 240;
    gray full = gray_make(W, H), part = gray_make(W, H);
    fx_ctx cf, cp;
    fx_ctx_init(&cf, &full.s);
    fx_ctx_init(&cp, &part.s);
    drawfn fns[] = {d_circle, d_disc, d_aa, d_ell, d_fell, d_arc, d_pie};
    uint32_t seed = 99;
    int bad = 0, out = 0;
    for (int i = 0; i < 1400; i++) {
        drawfn f = fns[i % 7];
        int32_t r = (int32_t)(fx_test_rand(&seed) % 110), r2 = (int32_t)(fx_test_rand(&seed) % 110);
        int32_t x = (int32_t)(fx_test_rand(&seed) % 80) + 110, y = (int32_t)(fx_test_rand(&seed) % 40) + 110;
        uint32_t a = fx_test_rand(&seed);
        fx_rect cl = {(int32_t)(fx_test_rand(&seed) % 250), (int32_t)(fx_test_rand(&seed) % 200), 0, 0};
        cl.x1 = cl.x0 + 1 + (int32_t)(fx_test_rand(&seed) % 120);
        cl.y1 = cl.y0 + 1 + (int32_t)(fx_test_rand(&seed) % 120);
        gray_clear(&full);
        gray_clear(&part);
        fx_ctx_set_clip(&cp, cl);
        fx_ctx_set_color(&cf, 0xFFFFFFFFu);
        fx_ctx_set_color(&cp, 0xFFFFFFFFu);
        f(&cf, x, y, r, r2, a);
        f(&cp, x, y, r, r2, a);
        for (int yy = 0; yy < H; yy++)
            for (int xx = 0; xx < W; xx++) {
                int inside = xx >= cp.clip.x0 && xx < cp.clip.x1 && yy >= cp.clip.y0 && yy < cp.clip.y1;
                uint8_t pv = part.mem[yy * W + xx], fv = full.mem[yy * W + xx];
                if (inside)
                    bad += pv != fv;
                else
                    out += pv != 0;
            }
    }
    FX_CHECK_EQ(bad, 0);
    FX_CHECK_EQ(out, 0);
    free(full.mem);
    free(part.mem);
}

/* Arcs over a partition of the turn add up to the circle, pie slices to the
 * disc, and the pieces do not overlap. */
FX_TEST(conic_arcs_and_pies_partition)
{
    int W = 220, H = 220;
    gray g = gray_make(W, H), whole = gray_make(W, H);
    fx_ctx c, cw;
    fx_ctx_init(&c, &g.s);
    fx_ctx_init(&cw, &whole.s);
    uint32_t seed = 5;
    for (int t = 0; t < 60; t++) {
        int32_t r = 1 + (int32_t)(fx_test_rand(&seed) % 100);
        int32_t cx = 110 + (int32_t)(fx_test_rand(&seed) % 40) - 20, cy = 110 + (int32_t)(fx_test_rand(&seed) % 40) - 20;
        fx_angle cuts[4];
        for (int k = 0; k < 4; k++)
            cuts[k] = fx_test_rand(&seed);
        /* sort so the pieces run counter-clockwise around the turn */
        for (int i = 0; i < 4; i++)
            for (int j = i + 1; j < 4; j++)
                if (cuts[j] < cuts[i]) {
                    fx_angle tmp = cuts[i];
                    cuts[i] = cuts[j];
                    cuts[j] = tmp;
                }
        for (int kind = 0; kind < 2; kind++) {
            gray_clear(&g);
            gray_clear(&whole);
            if (kind)
                fx_disc(&cw, cx, cy, r);
            else
                fx_circle(&cw, cx, cy, r);
            for (int k = 0; k < 4; k++) {
                gray tmp = gray_make(W, H);
                fx_ctx ct;
                fx_ctx_init(&ct, &tmp.s);
                if (kind)
                    fx_pie(&ct, cx, cy, r, cuts[k], cuts[(k + 1) % 4]);
                else
                    fx_arc(&ct, cx, cy, r, cuts[k], cuts[(k + 1) % 4]);
                for (int i = 0; i < W * H; i++)
                    if (tmp.mem[i])
                        g.mem[i] = 255;
                free(tmp.mem);
            }
            FX_CHECK_MSG(memcmp(g.mem, whole.mem, (size_t)W * H) == 0, "t=%d kind=%d", t, kind);
        }
    }
    free(g.mem);
    free(whole.mem);
}

FX_TEST(conic_fill_ellipse_is_its_definition)
{
    int W = 100, H = 80;
    gray g = gray_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    uint32_t seed = 31337;
    int bad = 0;
    for (int i = 0; i < 2000; i++) {
        int64_t rx = fx_test_rand(&seed) % 1500, ry = fx_test_rand(&seed) % 1500;
        if (i % 4 == 0)
            ry = fx_test_rand(&seed) % 4;
        int64_t cx = (int64_t)(fx_test_rand(&seed) % 200) - 50 + ((i & 1) ? rx : -rx);
        int64_t cy = (int64_t)(fx_test_rand(&seed) % 160) - 40;
        gray_clear(&g);
        fx_fill_ellipse(&c, (int32_t)cx, (int32_t)cy, (int32_t)rx, (int32_t)ry);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int64_t dx = x - cx, dy = y - cy;
                int in = ry * ry * dx * dx + rx * rx * dy * dy <= rx * rx * ry * ry;
                if (rx == 0 || ry == 0) /* a segment */
                    in = (rx == 0 ? dx == 0 && dy * dy <= ry * ry : dy == 0 && dx * dx <= rx * rx);
                bad += in != lit(&g, x, y);
            }
    }
    FX_CHECK_EQ(bad, 0);
    free(g.mem);
}

/* The outline of every ellipse is one 8-connected curve, symmetric in both
 * axes, and its row runs sit on the curve (within a pixel of the ideal). */
FX_TEST(conic_ellipse_connected_and_close)
{
    int W = 420, H = 420;
    gray g = gray_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    int *stack = malloc(sizeof(int) * (size_t)W * H);
    uint32_t seed = 2024;
    for (int i = 0; i < 400; i++) {
        int rx = 1 + (int)(fx_test_rand(&seed) % 200), ry = 1 + (int)(fx_test_rand(&seed) % 200);
        if (i % 5 == 0)
            ry = 1 + (int)(fx_test_rand(&seed) % 3);
        if (i % 5 == 1)
            rx = 1 + (int)(fx_test_rand(&seed) % 3);
        gray_clear(&g);
        fx_ellipse(&c, 210, 210, rx, ry);
        int n = 0, start = -1, far = 0, asym = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                if (lit(&g, x, y)) {
                    n++;
                    start = y * W + x;
                    asym += !lit(&g, 420 - x, y) || !lit(&g, x, 420 - y);
                    /* the ideal curve passes within one pixel (L-inf) of
                     * the pixel centre: F changes sign over the 3x3 block */
                    int neg = 0, pos = 0;
                    for (int j = -1; j <= 1; j++)
                        for (int k = -1; k <= 1; k++) {
                            double dx = x + k - 210, dy = y + j - 210;
                            double F = dx * dx / ((double)rx * rx) + dy * dy / ((double)ry * ry) - 1;
                            neg |= F <= 0;
                            pos |= F >= 0;
                        }
                    far += !(neg && pos);
                }
        FX_CHECK_MSG(asym == 0, "rx=%d ry=%d asymmetric", rx, ry);
        FX_CHECK_MSG(far == 0, "rx=%d ry=%d: %d pixels far from the curve", rx, ry, far);
        /* flood the lit set from one pixel with 8-neighbours */
        int sp = 0, seen = 0;
        stack[sp++] = start;
        g.mem[start] = 2;
        while (sp) {
            int p = stack[--sp], px = p % W, py = p / W;
            seen++;
            for (int oy = -1; oy <= 1; oy++)
                for (int ox = -1; ox <= 1; ox++) {
                    int qx = px + ox, qy = py + oy;
                    if (qx < 0 || qy < 0 || qx >= W || qy >= H)
                        continue;
                    if (g.mem[qy * W + qx] == 255) {
                        g.mem[qy * W + qx] = 2;
                        stack[sp++] = qy * W + qx;
                    }
                }
        }
        FX_CHECK_MSG(seen == n, "rx=%d ry=%d: %d of %d pixels connected", rx, ry, seen, n);
    }
    free(stack);
    free(g.mem);
}

/* The incremental walk (whole ellipse visible) and the per-row closed form
 * (any part clipped) agree for every semi-axis pair up to 120, and the
 * ellipse with equal axes is the circle. */
FX_TEST(conic_ellipse_walk_equals_rows)
{
    int W = 260, H = 260;
    gray a = gray_make(W, H), b = gray_make(W, H);
    fx_ctx ca, cb;
    fx_ctx_init(&ca, &a.s);
    fx_ctx_init(&cb, &b.s);
    /* drawing in two halves, each clipped, forces the row path */
#define HALVES(call)                                   \
    do {                                               \
        fx_ctx_set_clip(&cb, (fx_rect){0, 0, W, 128}); \
        call;                                          \
        fx_ctx_set_clip(&cb, (fx_rect){0, 128, W, H}); \
        call;                                          \
    } while (0)
    int bad = 0;
    for (int rx = 0; rx <= 120; rx++)
        for (int ry = 0; ry <= 120; ry += (rx % 7) + 1) {
            gray_clear(&a);
            gray_clear(&b);
            fx_ellipse(&ca, 128, 128, rx, ry);
            HALVES(fx_ellipse(&cb, 128, 128, rx, ry));
            bad += memcmp(a.mem, b.mem, (size_t)W * H) != 0;
            if (rx == ry) {
                gray_clear(&b);
                HALVES(fx_circle(&cb, 128, 128, rx));
                bad += memcmp(a.mem, b.mem, (size_t)W * H) != 0;
            }
        }
    FX_CHECK_EQ(bad, 0);
    free(a.mem);
    free(b.mem);
}

/* The antialiased circle: mirror-symmetric, the axis pixels at exactly r
 * are full colour, and a pixel's coverage never exceeds the colour. */
FX_TEST(conic_aacircle_coverage)
{
    int W = 201, H = 201;
    gray g = gray_make(W, H);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    for (int r = 1; r < 95; r += 3) {
        gray_clear(&g);
        fx_aacircle(&c, 100, 100, r);
        FX_CHECK_EQ(g.mem[100 * W + 100 + r], 255);
        FX_CHECK_EQ(g.mem[(100 - r) * W + 100], 255);
        int asym = 0, sum = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                uint8_t v = g.mem[y * W + x];
                asym += v != g.mem[y * W + (200 - x)] || v != g.mem[(200 - y) * W + x] ||
                        v != g.mem[x * W + y];
                sum += v;
            }
        FX_CHECK_MSG(asym == 0, "r=%d", r);
        /* one full pixel of ink per step along each octant's major axis:
         * 8 r / sqrt(2) in all */
        double ink = sum / 255.0, want = 8 * r / 1.41421356;
        if (r >= 10)
            FX_CHECK_MSG(ink > want * 0.95 && ink < want * 1.05 + 8, "r=%d ink %.1f want %.1f", r, ink, want);
    }
    free(g.mem);
}

/* The textbook ellipse example rx = 8, ry = 6: region 1 lights (0,6) (1,6)
 * (2,6) (3,6) (4,5) (5,5) (6,4), region 2 (7,3) (8,2) (8,1) (8,0) in each
 * quadrant, and --trace prints both regions' tables with those points. */
FX_TEST(conic_ellipse_course_example_8_6)
{
    gray g = gray_make(40, 40);
    fx_ctx c;
    fx_ctx_init(&c, &g.s);
    c.trace = tr_collect;
    fx_ellipse(&c, 20, 20, 8, 6);
    static const int q[][2] = {{0, 6}, {1, 6}, {2, 6}, {3, 6}, {4, 5}, {5, 5},
                               {6, 4}, {7, 3}, {8, 2}, {8, 1}, {8, 0}};
    uint8_t want[40 * 40] = {0};
    for (int i = 0; i < 11; i++)
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2)
                want[(20 + sy * q[i][1]) * 40 + 20 + sx * q[i][0]] = 1;
    int bad = 0;
    for (int i = 0; i < 40 * 40; i++)
        bad += (g.mem[i] != 0) != want[i];
    FX_CHECK_EQ(bad, 0);
    /* trace: header, column titles, 6 region-1 rows, header, titles, 4 region-2 rows */
    FX_CHECK_EQ(tr_n, 2 + 6 + 2 + 4);
    int seen = 0;
    for (int i = 0; i < tr_n; i++) {
        int k, x, y;
        long long p;
        if (sscanf(tr_lines[i], "%d %lld (%d, %d)", &k, &p, &x, &y) == 4) {
            int found = 0;
            for (int j = 0; j < 11; j++)
                found |= q[j][0] == x && q[j][1] == y;
            FX_CHECK_MSG(found, "trace point (%d, %d)", x, y);
            seen++;
        }
    }
    FX_CHECK_EQ(seen, 10);
    tr_free();
    free(g.mem);
}
