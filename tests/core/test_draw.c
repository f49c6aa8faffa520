/* SPDX-License-Identifier: MIT */
/* Drawing context: isolation between contexts (two threads), clipped
 * rectangles with extreme arguments, exact source-over blending, the trace
 * formatter. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/draw.h"
#include "fixel/line.h"
#include "fx_test.h"

typedef struct {
    fx_surface s;
    uint32_t seed;
    fx_color base;
} job;

static void scene(const fx_surface *s, uint32_t seed, fx_color base)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    for (int i = 0; i < 3000; i++) {
        fx_ctx_set_color(&c, base ^ (fx_test_rand(&seed) & 0xFFFF));
        fx_rect r = {(int32_t)(fx_test_rand(&seed) % 200), (int32_t)(fx_test_rand(&seed) % 150), 0, 0};
        fx_ctx_set_clip(&c, (fx_rect){r.x0, r.y0, r.x0 + 90, r.y0 + 70});
        fx_line(&c, (int32_t)(fx_test_rand(&seed) % 400) - 100, (int32_t)(fx_test_rand(&seed) % 300) - 100,
                (int32_t)(fx_test_rand(&seed) % 400) - 100, (int32_t)(fx_test_rand(&seed) % 300) - 100);
        fx_fill_rect(&c, r.x0 - 5, r.y0 - 5, 20, 10);
    }
}

static void *run(void *p)
{
    job *j = p;
    scene(&j->s, j->seed, j->base);
    return NULL;
}

FX_TEST(two_contexts_on_two_threads_never_interfere)
{
    enum { W = 200, H = 150 };
    uint32_t *m[4];
    fx_surface s[4];
    for (int i = 0; i < 4; i++) {
        m[i] = calloc(W * H, 4);
        fx_surface_init(&s[i], m[i], W, H, W * 4, FX_FMT_XRGB8888);
    }
    job a = {s[0], 1, 0xFF00FF00u}, b = {s[1], 2, 0xFFFF0000u};
    pthread_t ta, tb;
    pthread_create(&ta, NULL, run, &a);
    pthread_create(&tb, NULL, run, &b);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    scene(&s[2], 1, 0xFF00FF00u);
    scene(&s[3], 2, 0xFFFF0000u);
    FX_CHECK(memcmp(m[0], m[2], W * H * 4) == 0);
    FX_CHECK(memcmp(m[1], m[3], W * H * 4) == 0);
    FX_CHECK(memcmp(m[0], m[1], W * H * 4) != 0);
    for (int i = 0; i < 4; i++)
        free(m[i]);
}

FX_TEST(rectangles_clip_for_any_int32_arguments)
{
    uint32_t mem[16 * 12];
    fx_surface s;
    fx_surface_init(&s, mem, 16, 12, 64, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    uint32_t seed = 5;
    for (int i = 0; i < 20000; i++) {
        memset(mem, 0, sizeof mem);
        int32_t x = (int32_t)fx_test_rand(&seed), y = (int32_t)fx_test_rand(&seed);
        int32_t w = (int32_t)fx_test_rand(&seed), h = (int32_t)fx_test_rand(&seed);
        if (i & 1)
            x %= 40, y %= 40, w %= 40, h %= 40;
        int outline = i & 2;
        if (outline)
            fx_rect_outline(&c, x, y, w, h);
        else
            fx_fill_rect(&c, x, y, w, h);
        int64_t x1 = (int64_t)x + w, y1 = (int64_t)y + h;
        if (x1 > INT32_MAX)
            x1 = INT32_MAX;
        if (y1 > INT32_MAX)
            y1 = INT32_MAX;
        for (int py = 0; py < 12; py++)
            for (int px = 0; px < 16; px++) {
                int in = w > 0 && h > 0 && px >= x && px < x1 && py >= y && py < y1;
                if (outline)
                    in = in && (px == x || px == x1 - 1 || py == y || py == y1 - 1);
                if ((mem[py * 16 + px] != 0) != in) {
                    FX_CHECK_MSG(0, "%s %d %d %d %d at %d,%d", outline ? "outline" : "fill", x, y, w,
                                 h, px, py);
                    return;
                }
            }
    }
}

/* (s*a + d*(255-a)) / 255, rounded to nearest, for every s, d, a. */
FX_TEST(source_over_is_exact_for_every_8bit_triple)
{
    for (uint32_t a = 0; a < 256; a++)
        for (uint32_t sv = 0; sv < 256; sv++)
            for (uint32_t d = 0; d < 256; d++) {
                uint32_t x = sv * a + d * (255 - a);
                uint32_t want = (2 * x + 255) / 510;
                uint32_t got = fx_blend_over(FX_FMT_XRGB8888, d, (a << 24) | sv) & 0xFF;
                if (got != want) {
                    FX_CHECK_MSG(0, "s=%u d=%u a=%u: %u != %u", sv, d, a, got, want);
                    return;
                }
            }
    /* alpha channel of ARGB8888: a + da*(255-a)/255 */
    FX_CHECK_EQ_HEX(fx_blend_over(FX_FMT_ARGB8888, 0x80000000u, 0x80FFFFFFu) >> 24, 0x80 + 64);
    FX_CHECK_EQ_HEX(fx_blend_over(FX_FMT_RGB565, 0x0000, 0xFFFFFFFFu), 0xFFFF);
}

FX_TEST(blend_mode_applies_to_spans_and_plots)
{
    uint32_t mem[4 * 4];
    fx_surface s;
    fx_surface_init(&s, mem, 4, 4, 16, FX_FMT_XRGB8888);
    fx_surface_clear(&s, 0x000000);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    c.blend = FX_BLEND_OVER;
    fx_ctx_set_color(&c, 0x80FF0000u);
    fx_fill_rect(&c, 0, 0, 2, 2);
    fx_plot(&c, 3, 3);
    FX_CHECK_EQ_HEX(mem[0], 0x800000);
    FX_CHECK_EQ_HEX(mem[15], 0x800000);
    FX_CHECK_EQ_HEX(mem[2], 0);
    c.blend = FX_BLEND_SRC;
    fx_plot(&c, 2, 0);
    FX_CHECK_EQ_HEX(mem[2], 0xFF0000);
}

FX_TEST(exterior_clipping_keeps_the_window_free)
{
    uint32_t mem[10 * 10] = {0};
    fx_surface s;
    fx_surface_init(&s, mem, 10, 10, 40, FX_FMT_XRGB8888);
    fx_ctx c;
    fx_ctx_init(&c, &s);
    c.exterior = 1;
    c.exterior_rect = (fx_rect){2, 3, 7, 6};
    fx_clear(&c);
    fx_line(&c, 0, 4, 9, 4);
    for (int y = 0; y < 10; y++)
        for (int x = 0; x < 10; x++)
            FX_CHECK((mem[y * 10 + x] != 0) == !(x >= 2 && x < 7 && y >= 3 && y < 6));
}

FX_TEST(formatter_handles_the_trace_conversions)
{
    char b[64];
    FX_CHECK_EQ(fx_fmt(b, sizeof b, "%d|%-4d|%04d|%u|%x|%s|%c|%%", -12, 7, -3, 42u, 255u, "ok", 'z'), 26);
    FX_CHECK(!strcmp(b, "-12|7   |-003|42|ff|ok|z|%"));
    fx_fmt(b, sizeof b, "%lld %ld", -9000000000ll, 123456l);
    FX_CHECK(!strcmp(b, "-9000000000 123456"));
    FX_CHECK_EQ(fx_fmt(b, 4, "%s", "truncated"), 9);
    FX_CHECK(!strcmp(b, "tru"));
    fx_fmt(b, sizeof b, "[%.*s|%.2s]", 3, "abcdef", "xyz");
    FX_CHECK(!strcmp(b, "[abc|xy]"));
}
