/* SPDX-License-Identifier: MIT */
/* Polygon clipping: Sutherland-Hodgman and the Weiler-Atherton pieces keep
 * exactly the pixels (centres, top-left rule) of the unclipped polygon inside
 * the window, concave polygons fall apart into separate pieces, and the
 * library's Q16.16 fill agrees with an independent reference fill. */
#include <stdlib.h>
#include <string.h>

#include "fixel/clip.h"
#include "fixel/error.h"
#include "fx_test.h"

enum { W = 64, H = 48 };

/* Reference: pixel (X, Y) is in when an odd number of edges cross its row
 * at or left of its centre, edges taken half-open in y (y0 <= Y < y1). This
 * is the top-left rule: a centre on a left edge counts that edge, one on a
 * right edge counts it too and so falls out. */
static int ref_inside(const fx_pt16 *p, const int *starts, int npieces, int64_t X, int64_t Y)
{
    int odd = 0;
    X *= 65536;
    Y *= 65536;
    for (int pc = 0; pc < npieces; pc++) {
        int a = starts[pc], n = starts[pc + 1] - a;
        for (int i = 0; i < n; i++) {
            int64_t x0 = p[a + i].x, y0 = p[a + i].y, x1 = p[a + (i + 1) % n].x, y1 = p[a + (i + 1) % n].y;
            if (y0 == y1)
                continue;
            if (y0 > y1) {
                int64_t t = x0; x0 = x1; x1 = t;
                t = y0; y0 = y1; y1 = t;
            }
            if (Y < y0 || Y >= y1)
                continue;
            /* crossing x <= X  <=>  x0 (y1 - y0) + (Y - y0)(x1 - x0) <= X (y1 - y0) */
            /* the test's coordinates stay below 2^24 raw (256 pixels), so
             * these products fit in 64 bits */
            int64_t l = x0 * (y1 - y0) + (Y - y0) * (x1 - x0);
            odd ^= l <= X * (y1 - y0);
        }
    }
    return odd;
}

/* The reference needs |raw coordinates| < 2^24; every test polygon checks it. */
static int small(const fx_pt16 *p, int n)
{
    for (int i = 0; i < n; i++)
        if (p[i].x <= -(1 << 24) || p[i].x >= (1 << 24) || p[i].y <= -(1 << 24) || p[i].y >= (1 << 24))
            return 0;
    return 1;
}

static void ref_mask(const fx_pt16 *p, const int *starts, int npieces, fx_rect win, uint8_t *mask)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            mask[y * W + x] = x >= win.x0 && x < win.x1 && y >= win.y0 && y < win.y1 &&
                              ref_inside(p, starts, npieces, x, y);
}

/* A star-shaped (so simple), usually concave polygon around (cx, cy). */
static int star(uint32_t *s, fx_pt16 *p, int frac)
{
    int n = 3 + (int)(fx_test_rand(s) % 14);
    int32_t cx = (int32_t)(fx_test_rand(s) % 80) - 8, cy = (int32_t)(fx_test_rand(s) % 60) - 6;
    int32_t rmax = 5 + (int32_t)(fx_test_rand(s) % 60);
    for (int i = 0; i < n; i++) {
        /* angle steps of 360/n degrees with jitter, radius anywhere */
        int64_t ang = (int64_t)i * 65536 / n + (int64_t)(fx_test_rand(s) % (uint32_t)(32768 / n));
        int32_t r = 1 + (int32_t)(fx_test_rand(s) % (uint32_t)rmax);
        /* integer cos/sin approximations are fine: the polygon only needs to
         * be star-shaped around the centre */
        int64_t c = 0, sn = 0;
        {
            /* quarter-wave by a small table-free polynomial on [0, 65536) */
            int64_t a = ang & 65535, q = a >> 14, t = a & 16383; /* quadrant, position */
            int64_t co = 16384 - t * t / 16384 * 4 / 10 - t * t / 16384 * 6 / 10 * t / 16384;
            int64_t si = 16384 - (16384 - t) * (16384 - t) / 16384 * 4 / 10 -
                         (16384 - t) * (16384 - t) / 16384 * 6 / 10 * (16384 - t) / 16384;
            switch (q) {
            case 0: c = co, sn = si; break;
            case 1: c = -si, sn = co; break;
            case 2: c = -co, sn = -si; break;
            default: c = si, sn = -co; break;
            }
        }
        int64_t x = (int64_t)cx * 65536 + r * c * 4, y = (int64_t)cy * 65536 + r * sn * 4;
        if (!frac) { /* integer vertices: many centres lie exactly on edges */
            x = (x + 32768) & ~(int64_t)65535;
            y = (y + 32768) & ~(int64_t)65535;
        }
        p[i].x = (fx16)x;
        p[i].y = (fx16)y;
    }
    FX_CHECK(small(p, n));
    return n;
}

static fx_rect rnd_window(uint32_t *s)
{
    int32_t x0 = (int32_t)(fx_test_rand(s) % 40), y0 = (int32_t)(fx_test_rand(s) % 30);
    fx_rect w = {x0, y0, x0 + 1 + (int32_t)(fx_test_rand(s) % (uint32_t)(W - x0)),
                 y0 + 1 + (int32_t)(fx_test_rand(s) % (uint32_t)(H - y0))};
    return w;
}

FX_TEST(sutherland_hodgman_keeps_the_pixels_inside_the_window)
{
    uint32_t s = 1234;
    static uint8_t want[W * H], got[W * H];
    int nonempty = 0, partial = 0;
    for (int i = 0; i < 3000; i++) {
        fx_pt16 p[16], out[16 * 12];
        int n = star(&s, p, i & 1);
        fx_rect win = rnd_window(&s);
        int st0[2] = {0, n};
        ref_mask(p, st0, 1, win, want);
        int m = fx_clip_poly_sh(win, p, n, out, 16 * 12);
        FX_CHECK(m >= 0);
        int st1[2] = {0, m > 0 ? m : 0};
        memset(got, 0, sizeof got);
        if (m > 0)
            ref_mask(out, st1, 1, (fx_rect){0, 0, W, H}, got);
        int diff = memcmp(want, got, sizeof got) != 0, area = 0;
        for (int k = 0; k < W * H; k++)
            area += want[k];
        nonempty += area > 0;
        partial += area > 0 && m != n;
        if (diff) {
            FX_CHECK_MSG(0, "polygon %d (%d vertices, window %d,%d..%d,%d): pixels differ", i, n, win.x0, win.y0,
                         win.x1, win.y1);
            return;
        }
        /* every output vertex is inside the closed window region */
        for (int k = 0; k < m; k++)
            FX_CHECK(out[k].x >= win.x0 * 65536 - 32768 && out[k].x <= win.x1 * 65536 - 32768 &&
                     out[k].y >= win.y0 * 65536 - 32768 && out[k].y <= win.y1 * 65536 - 32768);
    }
    FX_CHECK(nonempty > 1000 && partial > 500);
}

FX_TEST(weiler_atherton_pieces_keep_the_pixels_inside_the_window)
{
    uint32_t s = 4321;
    static uint8_t want[W * H], got[W * H];
    static unsigned char work[1 << 14];
    int multi = 0;
    for (int i = 0; i < 3000; i++) {
        fx_pt16 p[16], out[256];
        int starts[33];
        int n = star(&s, p, i & 1);
        if (i & 2) /* the other orientation */
            for (int k = 0; k < n / 2; k++) {
                fx_pt16 t = p[k];
                p[k] = p[n - 1 - k];
                p[n - 1 - k] = t;
            }
        fx_rect win = rnd_window(&s);
        int st0[2] = {0, n};
        ref_mask(p, st0, 1, win, want);
        int np = fx_clip_poly_pieces(win, p, n, out, 256, starts, 32, work, sizeof work);
        FX_CHECK(np >= 0);
        memset(got, 0, sizeof got);
        if (np > 0)
            ref_mask(out, starts, np, (fx_rect){0, 0, W, H}, got);
        multi += np > 1;
        if (memcmp(want, got, sizeof got)) {
            FX_CHECK_MSG(0, "polygon %d (%d vertices, window %d,%d..%d,%d): %d pieces, pixels differ", i, n,
                         win.x0, win.y0, win.x1, win.y1, np);
            return;
        }
        /* pieces are proper polygons: at least 3 vertices, no repeated
         * neighbours */
        for (int k = 0; k < np; k++) {
            FX_CHECK(starts[k + 1] - starts[k] >= 3);
            for (int j = starts[k]; j < starts[k + 1]; j++) {
                int nx = j + 1 < starts[k + 1] ? j + 1 : starts[k];
                FX_CHECK(out[j].x != out[nx].x || out[j].y != out[nx].y);
            }
        }
    }
    FX_CHECK(multi > 50); /* concave polygons really fall apart */
}

FX_TEST(concave_u_becomes_two_pieces_not_one_with_a_bridge)
{
    /* A U open at the top whose base lies below the window: inside, only the
     * two prongs remain. */
    fx_pt16 u[8] = {{0, 0}, {10 << 16, 0}, {10 << 16, 30 << 16}, {20 << 16, 30 << 16},
                    {20 << 16, 0}, {30 << 16, 0}, {30 << 16, 40 << 16}, {0, 40 << 16}};
    /* (y grows downwards: the base is the row band 30..40; the window ends at 25) */
    fx_rect win = {-5, -5, 40, 26}; /* pixels y -5..25: region y <= 25.5 */
    fx_pt16 out[64];
    int starts[9];
    static unsigned char work[4096];
    int np = fx_clip_poly_pieces(win, u, 8, out, 64, starts, 8, work, sizeof work);
    FX_CHECK_EQ(np, 2);
    for (int k = 0; k < np && k < 2; k++)
        FX_CHECK_EQ(starts[k + 1] - starts[k], 4);
    /* Sutherland-Hodgman gives one polygon that bridges the prongs along the
     * window border (the degenerate edges the pieces avoid) */
    int m = fx_clip_poly_sh(win, u, 8, out, 64);
    FX_CHECK_EQ(m, 8);
    int on_border = 0;
    for (int k = 0; k < m; k++)
        on_border += out[k].y == (26 << 16) - 32768;
    FX_CHECK_EQ(on_border, 4);
    /* a window inside the polygon comes back whole; a disjoint one empty */
    fx_pt16 big[4] = {{-100 * 65536, -100 * 65536}, {100 << 16, -100 * 65536}, {100 << 16, 100 << 16}, {-100 * 65536, 100 << 16}};
    np = fx_clip_poly_pieces((fx_rect){1, 2, 5, 9}, big, 4, out, 64, starts, 8, work, sizeof work);
    FX_CHECK(np == 1 && starts[1] == 4);
    np = fx_clip_poly_pieces((fx_rect){200, 200, 205, 209}, big, 4, out, 64, starts, 8, work, sizeof work);
    FX_CHECK_EQ(np, 0);
    FX_CHECK_EQ(fx_clip_poly_pieces(win, u, 8, out, 64, starts, 8, work, 16), -FX_ENOSPC);
}

typedef struct {
    fx_surface s;
    uint32_t *mem;
} canvas;

FX_TEST(q16_fill_matches_the_reference_fill)
{
    uint32_t s = 99;
    static uint8_t want[W * H];
    canvas c;
    c.mem = calloc(W * H, 4);
    fx_surface_init(&c.s, c.mem, W, H, W * 4, FX_FMT_XRGB8888);
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c.s);
    for (int i = 0; i < 2000; i++) {
        fx_pt16 p[16];
        int n = star(&s, p, i & 1);
        fx_rect win = rnd_window(&s);
        fx_ctx_set_clip(&ctx, win);
        int st[2] = {0, n};
        ref_mask(p, st, 1, win, want);
        memset(c.mem, 0, W * H * 4);
        FX_CHECK_EQ(fx_poly_fill16(&ctx, p, st, 1), 0);
        for (int k = 0; k < W * H; k++)
            if ((c.mem[k] != 0) != want[k]) {
                FX_CHECK_MSG(0, "polygon %d pixel %d,%d", i, k % W, k / W);
                free(c.mem);
                return;
            }
    }
    free(c.mem);
}
