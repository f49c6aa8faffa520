/* SPDX-License-Identifier: MIT */
/* Whole frames in bands (boards/posix/par.c): fx_par_bands hands each band
 * its rows once; fx_scene_run_mt draws the one-thread picture, traces
 * 'raytrace' once on all threads with later drawing on top, falls back to
 * one thread for serial commands and tracing, and reports errors as
 * fx_scene_run does. (Every golden script and demo page: tests/boards/bands.sh.) */
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/memfb.h"
#include "fixel/par.h"
#include "fx_test.h"

typedef struct seen {
    atomic_int rows[100];
    atomic_int calls;
    int bad;
} seen;

static void mark(void *u, fx_ctx *c, int band)
{
    seen *s = u;
    atomic_fetch_add(&s->calls, 1);
    if (band < 0 || c->clip.x0 != 3 || c->clip.x1 != 50)
        s->bad = 1;
    for (int32_t y = c->clip.y0; y < c->clip.y1; y++)
        atomic_fetch_add(&s->rows[y], 1);
    fx_fill_rect(c, 0, 0, 100, 100); /* only the band's part lands */
}

FX_TEST(par_bands_cover_the_clip_once)
{
    fx_memfb fb;
    FX_CHECK_EQ(fx_memfb_create(&fb, 60, 100, FX_FMT_XRGB8888), 0);
    fx_ctx c;
    fx_ctx_init(&c, &fb.surf);
    fx_ctx_set_clip(&c, (fx_rect){3, 10, 50, 97});
    fx_ctx_set_color(&c, 0xFF00FF00u);
    const int bands[] = {0, 1, 5, 87, 1024};
    for (int k = 0; k < 5; k++)
        for (int n = 1; n <= 4; n++) {
            static seen s;
            memset(&s, 0, sizeof s);
            memset(fb.surf.pixels, 0, (size_t)fb.surf.stride * 100);
            FX_CHECK_EQ(fx_par_bands(&c, bands[k], n, mark, &s), 0);
            FX_CHECK(!s.bad);
            for (int y = 0; y < 100; y++)
                FX_CHECK_EQ(atomic_load(&s.rows[y]), y >= 10 && y < 97);
            int want = bands[k] ? (bands[k] > 87 ? 87 : bands[k]) : n; /* empty bands are not drawn */
            FX_CHECK_EQ(atomic_load(&s.calls), want);
            uint32_t *px = (uint32_t *)fb.surf.pixels;
            FX_CHECK_EQ(px[5 * 60 + 5] & 0xFFFFFF, 0);       /* above the clip */
            FX_CHECK_EQ(px[50 * 60 + 2] & 0xFFFFFF, 0);      /* left of it */
            FX_CHECK_EQ(px[50 * 60 + 20] & 0xFFFFFF, 0x00FF00); /* inside */
        }
    FX_CHECK_EQ(fx_par_bands(&c, 0, 0, mark, NULL), -FX_EINVAL);
    FX_CHECK_EQ(fx_par_bands(&c, 1025, 2, mark, NULL), -FX_EINVAL);
    FX_CHECK_EQ(fx_par_bands(&c, 2, 65, mark, NULL), -FX_EINVAL);
    FX_CHECK(fx_par_cpu_count() >= 1);
    fx_memfb_destroy(&fb);
}

typedef struct host {
    fx_memfb fb;
    int have, surfaces, traced;
} host;

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    host *H = u;
    H->surfaces++;
    int r = fx_memfb_create(&H->fb, w, h, f);
    if (r == 0) {
        H->have = 1;
        *out = H->fb.surf;
    }
    return r;
}

static void trace_line(void *u, const char *line)
{
    (void)line;
    ((host *)u)->traced++;
}

/* Run text with nthreads; the picture in *fb (caller destroys), the result. */
static int run(const char *text, int nthreads, int trace, host *H, int *bands, fx_scene *sc)
{
    static uint8_t arena[1 << 20];
    memset(H, 0, sizeof *H);
    fx_scene_host hs = {H, make_surface, NULL, NULL, trace ? trace_line : NULL, NULL};
    fx_scene_init(sc, &hs, arena, sizeof arena);
    return fx_scene_run_mt(sc, text, strlen(text), nthreads, bands);
}

static const char picture[] =
    "size 64 48\n"
    "clear #203040\n"
    "color #FF8000\n"
    "fillpoly evenodd 3 5 60 20 10 44\n"
    "rtcamera 0 0 5 0 0 0 0 1 0 40\n"
    "rtlight 3 4 5 #FFFFFF\n"
    "rtmaterial #202020 #C08040 #FFFFFF 30 0.3 0 1\n"
    "rtshape sphere\n"
    "raytrace 5 7 40 33\n"
    "color #00FF00\n"
    "line 0 0 63 47\n"
    "depth 16\n"
    "cube 1.5\n";

FX_TEST(scene_run_mt_is_the_one_thread_picture)
{
    static fx_scene sc;
    host one, many;
    int bands = 0;
    FX_CHECK_EQ(run(picture, 1, 0, &one, &bands, &sc), 0);
    FX_CHECK_EQ(bands, 1);
    for (int n = 2; n <= 7; n++) {
        FX_CHECK_EQ(run(picture, n, 0, &many, &bands, &sc), 0);
        FX_CHECK_EQ(bands, n);
        FX_CHECK_EQ(many.surfaces, 1); /* the host made one surface for all bands */
        FX_CHECK(memcmp(one.fb.surf.pixels, many.fb.surf.pixels, (size_t)64 * 48 * 4) == 0);
        /* the scene goes on unbanded, on the whole surface */
        FX_CHECK_EQ(sc.banded, 0);
        FX_CHECK_EQ(sc.ctx.clip.y1, 48);
        FX_CHECK_EQ(fx_scene_exec_line(&sc, "pixel 1 47", 10, 99), 0);
        FX_CHECK_EQ(((uint32_t *)many.fb.surf.pixels)[47 * 64 + 1] & 0xFFFFFF, 0x00FF00);
        fx_memfb_destroy(&many.fb);
    }
    fx_memfb_destroy(&one.fb);
}

FX_TEST(scene_run_mt_falls_back_and_reports_errors)
{
    static fx_scene sc;
    host H;
    int bands = 0;
    /* a seed fill reads the picture: one thread, still right */
    FX_CHECK_EQ(fx_scene_script_serial("size 8 8\nclear #000000\n  flood 1 1 4\n", 36), 3);
    FX_CHECK_EQ(run("size 8 8\nclear #000000\nflood 1 1 4\n", 4, 0, &H, &bands, &sc), 0);
    FX_CHECK_EQ(bands, 1);
    fx_memfb_destroy(&H.fb);
    /* tracing prints each step once: one thread */
    FX_CHECK_EQ(run("size 8 8\nline 0 0 7 7\n", 4, 1, &H, &bands, &sc), 0);
    FX_CHECK_EQ(bands, 1);
    FX_CHECK(H.traced > 0);
    fx_memfb_destroy(&H.fb);
    /* an error on line 3 is reported as on one thread, and no band hangs
     * at the ray tracer's barrier waiting for the others */
    FX_CHECK_EQ(run("size 16 16\nclear #000000\nline 0 0 zz 3\nraytrace\n", 3, 0, &H, &bands, &sc), -FX_EINVAL);
    FX_CHECK_EQ(bands, 3);
    FX_CHECK_EQ(sc.err_line, 3);
    FX_CHECK(strstr(sc.err, "zz") != NULL);
    if (H.have)
        fx_memfb_destroy(&H.fb);
    FX_CHECK_EQ(fx_scene_run_mt(&sc, "", 0, 0, NULL), -FX_EINVAL);
}
