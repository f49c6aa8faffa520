/* SPDX-License-Identifier: MIT */
/* The fast line walk (line.c: a DDA whose minor coordinate must equal
 * Bresenham's, unrolled, one loop per format, octant and direction) against
 * a plain reference built from fx_bres_minor_at: every pixel of every line,
 * in 32-, 16- and 8-bit formats, for random and adversarial lines (all
 * octants, slopes 0, 1 and exact ties, lengths 1..4096), clipped starts
 * (k0 > 0 through fx_line_steps and fx_line_steps_inside), endpoints far
 * off-screen, and lines on both sides of the DDA's length limit. */
#include <stdlib.h>
#include <string.h>

#include "fixel/draw.h"
#include "fixel/line.h"
#include "fixel/surface.h"
#include "fx_test.h"

typedef struct {
    fx_surface s;
    uint8_t *mem, *want;
    size_t size;
    int bytes;
    fx_rect clip; /* the drawing context's clip: the surface unless a test sets it */
} canvas;

/* stride_pad extra bytes per row; flip: row 0 at the bottom (negative stride). */
static canvas make(int w, int h, fx_format f, int stride_pad, int flip)
{
    canvas c;
    c.bytes = fx_format_get(f)->bits_per_pixel / 8;
    int32_t stride = w * c.bytes + stride_pad;
    c.size = (size_t)stride * (size_t)h;
    c.mem = malloc(c.size);
    c.want = malloc(c.size);
    uint8_t *row0 = flip ? c.mem + (size_t)stride * (size_t)(h - 1) : c.mem;
    FX_CHECK_EQ(fx_surface_init(&c.s, row0, w, h, flip ? -stride : stride, f), 0);
    c.clip = fx_surface_rect(&c.s);
    return c;
}

static void drop(canvas *c)
{
    free(c->mem);
    free(c->want);
}

/* A background whose first byte differs from the lowest byte of every
 * pixel drawn, so no pixel can be lit (or missed) unseen. */
static void clear(canvas *c, uint32_t native)
{
    int bg = (int)(~native & 0xFF);
    memset(c->mem, bg, c->size);
    memset(c->want, bg, c->size);
}

static void want_pixel(canvas *c, int64_t x, int64_t y, uint32_t native)
{
    if (x < c->clip.x0 || y < c->clip.y0 || x >= c->clip.x1 || y >= c->clip.y1)
        return;
    uint8_t *p = c->s.pixels + (ptrdiff_t)y * c->s.stride + (ptrdiff_t)x * c->bytes;
    uint8_t *w = c->want + (p - c->mem);
    if (c->bytes == 4) {
        uint32_t v = native;
        memcpy(w, &v, 4);
    } else if (c->bytes == 2) {
        uint16_t v = (uint16_t)native;
        memcpy(w, &v, 2);
    } else {
        *w = (uint8_t)native;
    }
}

/* The reference: steps [k0, k1] of the line from the closed form, plotted
 * where they fall inside the surface. Lines longer than 2^16 steps use
 * fx_bres_clip for the visible range (tested in test_line.c and
 * test_clip.c), shorter ones try every step. */
static void reference(canvas *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t k0,
                      uint32_t k1, uint32_t native)
{
    fx_bres b;
    fx_bres_init(&b, x0, y0, x1, y1);
    if (k1 > b.major)
        k1 = b.major;
    if (b.major > 65536) {
        uint32_t c0, c1;
        if (!fx_bres_clip(&b, fx_surface_rect(&c->s), &c0, &c1))
            return;
        k0 = k0 > c0 ? k0 : c0;
        k1 = k1 < c1 ? k1 : c1;
    }
    for (uint64_t k = k0; k <= k1; k++) {
        int64_t m = fx_bres_minor_at(&b, (uint32_t)k), a = (int64_t)k;
        int64_t x = b.ymajor ? x0 + b.sx * m : x0 + b.sx * a;
        int64_t y = b.ymajor ? y0 + b.sy * a : y0 + b.sy * m;
        want_pixel(c, x, y, native);
    }
}

static int n_lines, n_bad;

/* Draws steps [k0, k1] (k1 = UINT32_MAX: the whole line through fx_line)
 * with the library and compares the whole surface with the reference. */
static void check(canvas *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint32_t k0,
                  uint32_t k1, int inside, uint32_t colour)
{
    fx_ctx ctx;
    fx_ctx_init(&ctx, &c->s);
    fx_ctx_set_clip(&ctx, c->clip);
    fx_ctx_set_color(&ctx, 0xFF000000u | colour);
    clear(c, ctx.native);
    if (inside) {
        fx_bres b;
        uint32_t c0, c1;
        fx_bres_init(&b, x0, y0, x1, y1);
        if (fx_bres_clip(&b, fx_surface_rect(&c->s), &c0, &c1)) {
            c0 = c0 > k0 ? c0 : k0;
            c1 = c1 < k1 ? c1 : k1;
            if (c0 <= c1) {
                fx_line_steps_inside(&ctx, x0, y0, x1, y1, c0, c1);
                reference(c, x0, y0, x1, y1, c0, c1, ctx.native);
            }
        }
    } else if (k1 == UINT32_MAX) {
        fx_line(&ctx, x0, y0, x1, y1);
        reference(c, x0, y0, x1, y1, 0, UINT32_MAX, ctx.native);
    } else {
        fx_line_steps(&ctx, x0, y0, x1, y1, k0, k1);
        reference(c, x0, y0, x1, y1, k0, k1, ctx.native);
    }
    n_lines++;
    if (memcmp(c->mem, c->want, c->size) != 0) {
        n_bad++;
        if (n_bad <= 5) {
            size_t i = 0;
            while (c->mem[i] == c->want[i])
                i++;
            FX_CHECK_MSG(0, "%d bpp (%d,%d)->(%d,%d) steps %u..%u%s: byte %zu is %02x, want %02x",
                         c->bytes * 8, x0, y0, x1, y1, k0, k1, inside ? " inside" : "", i,
                         c->mem[i], c->want[i]);
        }
    }
}

static const fx_format formats[] = {FX_FMT_XRGB8888, FX_FMT_RGB565, FX_FMT_GRAY8};
#define FX_ARRAY_LEN_T(a) (sizeof(a) / sizeof((a)[0]))

static uint32_t colour_of(uint32_t r) { return r & 0xFFFFFF; }

FX_TEST(fast_walk_random_lines_all_formats)
{
    uint32_t s = 0x13u;
    n_lines = n_bad = 0;
    for (size_t f = 0; f < FX_ARRAY_LEN_T(formats); f++) {
        for (int layout = 0; layout < 3; layout++) {
            canvas c = make(97, 61, formats[f], layout == 1 ? 12 : 0, layout == 2);
            for (int i = 0; i < 400; i++) {
                /* half inside, half sticking out by up to 150 pixels */
                int spread = i & 1 ? 400 : 0, off = i & 1 ? 150 : 0;
                int32_t x0 = (int32_t)(fx_test_rand(&s) % (uint32_t)(97 + spread)) - off;
                int32_t y0 = (int32_t)(fx_test_rand(&s) % (uint32_t)(61 + spread)) - off;
                int32_t x1 = (int32_t)(fx_test_rand(&s) % (uint32_t)(97 + spread)) - off;
                int32_t y1 = (int32_t)(fx_test_rand(&s) % (uint32_t)(61 + spread)) - off;
                uint32_t col = colour_of(fx_test_rand(&s));
                check(&c, x0, y0, x1, y1, 0, UINT32_MAX, 0, col);
                uint32_t k0 = fx_test_rand(&s) % 200, k1 = k0 + fx_test_rand(&s) % 200;
                check(&c, x0, y0, x1, y1, k0, k1, 0, col);
                check(&c, x0, y0, x1, y1, k0, k1, 1, col);
            }
            drop(&c);
        }
    }
    FX_CHECK_EQ(n_bad, 0);
    FX_CHECK(n_lines == 3 * 3 * 400 * 3);
}

/* Every octant, exact slopes (0, 1, 1/2, 1/3, 2/3, (n-1)/n, 1/n ...) whose
 * steps land exactly on the rounding ties, lengths 1..4096; long lines are
 * clipped with starts k0 anywhere along them. */
FX_TEST(fast_walk_adversarial_slopes_and_lengths)
{
    static const uint32_t lengths[] = {1,  2,  3,   4,   5,   6,   7,    8,    9,    15,   16,
                                       17, 31, 63,  64,  65,  127, 255,  256,  1000, 1023, 2047,
                                       4095, 4096};
    uint32_t s = 0x2024u;
    n_lines = n_bad = 0;
    for (size_t f = 0; f < FX_ARRAY_LEN_T(formats); f++) {
        canvas c = make(131, 89, formats[f], 0, 0);
        for (size_t li = 0; li < FX_ARRAY_LEN_T(lengths); li++) {
            uint32_t major = lengths[li];
            uint32_t minors[] = {0, major, major / 2, major / 2 + 1, major / 3, 2 * major / 3,
                                 major - 1, 1, major / 4, 3 * major / 4, major > 7 ? 7 : 0,
                                 fx_test_rand(&s) % (major + 1)};
            for (size_t mi = 0; mi < FX_ARRAY_LEN_T(minors); mi++) {
                for (int oct = 0; oct < 8; oct++) {
                    int32_t sx = oct & 1 ? -1 : 1, sy = oct & 2 ? -1 : 1;
                    int32_t dM = (int32_t)major, dm = (int32_t)minors[mi];
                    int32_t dx = oct & 4 ? dm : dM, dy = oct & 4 ? dM : dm;
                    /* start inside for short lines, anywhere near for long ones */
                    int32_t x0 = (int32_t)(fx_test_rand(&s) % 131), y0 = (int32_t)(fx_test_rand(&s) % 89);
                    if (major > 64) {
                        x0 -= sx * (int32_t)(fx_test_rand(&s) % (uint32_t)(dx + 1)) / 2;
                        y0 -= sy * (int32_t)(fx_test_rand(&s) % (uint32_t)(dy + 1)) / 2;
                    }
                    int32_t x1 = x0 + sx * dx, y1 = y0 + sy * dy;
                    uint32_t col = colour_of(fx_test_rand(&s));
                    check(&c, x0, y0, x1, y1, 0, UINT32_MAX, 0, col);
                    uint32_t k0 = fx_test_rand(&s) % (major + 1);
                    check(&c, x0, y0, x1, y1, k0, major, 0, col);
                    check(&c, x0, y0, x1, y1, k0, k0 + fx_test_rand(&s) % 100, 1, col);
                }
            }
        }
        drop(&c);
    }
    FX_CHECK_EQ(n_bad, 0);
}

/* Endpoints far off-screen (the visible piece starts at a huge k0), and
 * lines just below and above the DDA's limit of 46340 steps. 46411/32592
 * is a line the DDA would get wrong at step 46322 (found by search): it
 * must take the Bresenham walk. */
FX_TEST(fast_walk_long_and_far_lines)
{
    static const int64_t majors[] = {46339, 46340, 46341, 46411, 46413, 100000, 65536 * 3 + 1,
                                     1000000007, 2147483647, 4294967295u};
    uint32_t s = 0x777u;
    n_lines = n_bad = 0;
    for (size_t f = 0; f < FX_ARRAY_LEN_T(formats); f++) {
        canvas c = make(67, 45, formats[f], 4, f == 1);
        for (size_t mj = 0; mj < FX_ARRAY_LEN_T(majors); mj++) {
            int64_t major = majors[mj];
            for (int t = 0; t < 24; t++) {
                int64_t minor = t == 0 ? 32592 * (major == 46411) : (int64_t)(fx_test_rand(&s) % (uint64_t)(major + 1));
                if (t == 1)
                    minor = major;
                if (t == 2)
                    minor = major / 2;
                /* the step whose pixel lands near the middle of the surface */
                int64_t k = major == 46411 && t == 0 ? 46322 : (int64_t)(fx_test_rand(&s) % (uint64_t)(major + 1));
                int oct = t & 7;
                int64_t sx = oct & 1 ? -1 : 1, sy = oct & 2 ? -1 : 1;
                int64_t dx = oct & 4 ? minor : major, dy = oct & 4 ? major : minor;
                /* minor offset at step k, from the closed form */
                uint64_t tk = (uint64_t)k * (uint64_t)minor;
                int64_t m = (int64_t)(tk / (uint64_t)major + (2 * (tk % (uint64_t)major) >= (uint64_t)major));
                int64_t ox = oct & 4 ? m : k, oy = oct & 4 ? k : m;
                int64_t x0 = 33 - sx * ox, y0 = 22 - sy * oy;
                int64_t x1 = x0 + sx * dx, y1 = y0 + sy * dy;
                if (x0 < INT32_MIN || x0 > INT32_MAX || y0 < INT32_MIN || y0 > INT32_MAX ||
                    x1 < INT32_MIN || x1 > INT32_MAX || y1 < INT32_MIN || y1 > INT32_MAX)
                    continue;
                uint32_t col = colour_of(fx_test_rand(&s));
                check(&c, (int32_t)x0, (int32_t)y0, (int32_t)x1, (int32_t)y1, 0, UINT32_MAX, 0, col);
                check(&c, (int32_t)x0, (int32_t)y0, (int32_t)x1, (int32_t)y1, (uint32_t)k, UINT32_MAX - 1, 0, col);
                check(&c, (int32_t)x0, (int32_t)y0, (int32_t)x1, (int32_t)y1, (uint32_t)k, UINT32_MAX - 1, 1, col);
            }
        }
        drop(&c);
    }
    FX_CHECK_EQ(n_bad, 0);
    FX_CHECK(n_lines > 3 * 10 * 12 * 3);
}

/* The longest lines the DDA takes, every pixel visible: 8-bit surfaces
 * 46341 pixels long, x-major and y-major, both directions. */
FX_TEST(fast_walk_longest_dda_lines_whole)
{
    uint32_t s = 0xBEEFu;
    const int32_t major = 46340;
    n_lines = n_bad = 0;
    for (int t = 0; t < 6; t++) {
        int32_t minor = t == 0 ? 1 : t == 1 ? 39 : 1 + (int32_t)(fx_test_rand(&s) % 40);
        int ymajor = t & 1;
        canvas c = ymajor ? make(minor + 1, major + 1, FX_FMT_GRAY8, 0, 0)
                          : make(major + 1, minor + 1, FX_FMT_GRAY8, 0, 0);
        uint32_t col = colour_of(fx_test_rand(&s));
        int32_t dx = ymajor ? minor : major, dy = ymajor ? major : minor;
        check(&c, 0, 0, dx, dy, 0, UINT32_MAX, 0, col);
        check(&c, dx, dy, 0, 0, 0, UINT32_MAX, 0, col);
        check(&c, dx, 0, 0, dy, 0, UINT32_MAX, 0, col);
        check(&c, 0, dy, dx, 0, 0, UINT32_MAX, 0, col);
        uint32_t k0 = fx_test_rand(&s) % (uint32_t)major;
        check(&c, 0, dy, dx, 0, k0, UINT32_MAX - 1, 1, col);
        drop(&c);
    }
    FX_CHECK_EQ(n_bad, 0);
    FX_CHECK_EQ(n_lines, 30);
}

/* x-major lines with major/minor >= 2 are drawn as horizontal runs:
 * ratios from 1 (still the DDA) to 38 and some of 64-303, past every
 * store-width change of each format (8-byte stores to 16-byte loops for
 * 32-bit pixels, 4 to 16 and loops for 16-bit, 2 to 16 and loops for
 * 8-bit), both strides' signs, both x
 * directions, visible pieces starting and ending anywhere inside a run,
 * and pieces lying on the first or last row only. */
FX_TEST(fast_walk_shallow_runs)
{
    uint32_t s = 0x5151u;
    n_lines = n_bad = 0;
    for (size_t f = 0; f < FX_ARRAY_LEN_T(formats); f++) {
        /* row 0 at the top and at the bottom (negative stride), wide enough
         * for whole rows of up to 300 pixels */
        canvas cs[2] = {make(320, 37, formats[f], 8, 0), make(320, 37, formats[f], 8, 1)};
        for (int i = 0; i < 600; i++) {
            canvas *cp = &cs[(i >> 3) & 1];
            uint32_t minor = 1 + fx_test_rand(&s) % 30, ratio = 1 + fx_test_rand(&s) % 38;
            int32_t sx = i & 1 ? -1 : 1, sy = i & 2 ? -1 : 1;
            /* rows of 64-303 pixels: the first (half) row starts off the
             * surface, so that the next row lies whole on it */
            int longrows = i % 8 == 5;
            if (longrows) {
                minor = 2 + fx_test_rand(&s) % 3;
                ratio = 64 + fx_test_rand(&s) % 240;
                cp = &cs[(i >> 4) & 1];
            }
            uint32_t major = minor * ratio + fx_test_rand(&s) % minor;
            int32_t x0 = (int32_t)(fx_test_rand(&s) % 320), y0 = (int32_t)(fx_test_rand(&s) % 37);
            if (longrows) {
                int32_t first = (int32_t)(major / (2 * minor)) + 2 - (int32_t)(fx_test_rand(&s) % 4);
                x0 = sx > 0 ? -first : 319 + first;
            } else if (i & 4) { /* start outside so the line crosses the surface */
                x0 -= sx * (int32_t)(fx_test_rand(&s) % (major + 1));
                y0 -= sy * (int32_t)(fx_test_rand(&s) % (minor + 1));
            }
            int32_t x1 = x0 + sx * (int32_t)major, y1 = y0 + sy * (int32_t)minor;
            uint32_t col = colour_of(fx_test_rand(&s));
            check(cp, x0, y0, x1, y1, 0, UINT32_MAX, 0, col);
            uint32_t k0 = fx_test_rand(&s) % (major + 1), k1 = k0 + fx_test_rand(&s) % (major + 1);
            check(cp, x0, y0, x1, y1, k0, k1, 0, col);
            check(cp, x0, y0, x1, y1, k0, k1, 1, col);
            /* the first and the last row alone */
            uint32_t half = major / (2 * minor);
            check(cp, x0, y0, x1, y1, 0, half, 1, col);
            check(cp, x0, y0, x1, y1, major - half, major, 1, col);
            check(cp, x0, y0, x1, y1, major - half - 1, major, 0, col);
        }
        drop(&cs[0]);
        drop(&cs[1]);
    }
    FX_CHECK_EQ(n_bad, 0);
    FX_CHECK_EQ(n_lines, 3 * 600 * 6);
}

/* A clip window smaller than the surface: lines with both end points
 * inside it (fx_line skips the exact step-range clip for them), one or both
 * just outside, and degenerate ones, in every format; pixels outside the
 * window must stay untouched. */
FX_TEST(fast_walk_clip_window)
{
    uint32_t s = 0xC11Bu;
    n_lines = n_bad = 0;
    for (size_t f = 0; f < FX_ARRAY_LEN_T(formats); f++) {
        canvas c = make(97, 61, formats[f], 4, f == 1);
        for (int i = 0; i < 400; i++) {
            int32_t cx0 = (int32_t)(fx_test_rand(&s) % 60), cy0 = (int32_t)(fx_test_rand(&s) % 40);
            fx_rect r = {cx0, cy0, cx0 + 1 + (int32_t)(fx_test_rand(&s) % 37),
                         cy0 + 1 + (int32_t)(fx_test_rand(&s) % 21)};
            c.clip = r;
            /* end points inside the window, or up to 2 pixels around it */
            int32_t m = i % 3 ? 0 : 2, w = r.x1 - r.x0 + 2 * m, h = r.y1 - r.y0 + 2 * m;
            int32_t x0 = r.x0 - m + (int32_t)(fx_test_rand(&s) % (uint32_t)w);
            int32_t y0 = r.y0 - m + (int32_t)(fx_test_rand(&s) % (uint32_t)h);
            int32_t x1 = r.x0 - m + (int32_t)(fx_test_rand(&s) % (uint32_t)w);
            int32_t y1 = r.y0 - m + (int32_t)(fx_test_rand(&s) % (uint32_t)h);
            if (i % 7 == 0)
                x1 = x0;
            check(&c, x0, y0, x1, y1, 0, UINT32_MAX, 0, colour_of(fx_test_rand(&s)));
        }
        drop(&c);
    }
    FX_CHECK_EQ(n_bad, 0);
    FX_CHECK_EQ(n_lines, 3 * 400);
}
