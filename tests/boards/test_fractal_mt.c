/* SPDX-License-Identifier: MIT */
/* The threaded escape-time renderer: identical pictures for any thread
 * count, on both arithmetic paths, for Mandelbrot and Julia views. */
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/fractal_mt.h"
#include "fx_test.h"

static fx56 P(const char *s)
{
    fx56 v = 0;
    FX_CHECK(fx56_parse(s, (int)strlen(s), &v) > 0);
    return v;
}

FX_TEST(fractal_mt_equals_one_thread)
{
    const int32_t w = 203, h = 117;
    fx_fractal_view views[3] = {
        fx_mandel_view(-(FX56_ONE / 2), 0, 3 * FX56_ONE, w, h, 256),
        fx_mandel_view(P("-0.7453"), P("0.1127"), P("0.00065"), w, h, 700),
        fx_julia_view(0, 0, P("-0.8"), P("0.156"), P("3.1"), w, h, 300),
    };
    uint32_t *one = malloc((size_t)w * h * 2), *many = malloc((size_t)w * h * 2);
    uint32_t lut[65];
    fx_dwell_pal pal;
    fx_dwell_pal_w9(&pal, lut, FX_FMT_RGB565);
    fx_surface a, b;
    fx_surface_init(&a, one, w, h, w * 2, FX_FMT_RGB565);
    fx_surface_init(&b, many, w, h, w * 2, FX_FMT_RGB565);
    for (int k = 0; k < 3; k++) {
        memset(one, 0, (size_t)w * h * 2);
        FX_CHECK_EQ(fx_fractal_render(&a, fx_surface_rect(&a), &views[k], &pal), 0);
        for (int n = 1; n <= 5; n += 2) {
            memset(many, 0xAA, (size_t)w * h * 2);
            FX_CHECK_EQ(fx_fractal_render_mt(&b, fx_surface_rect(&b), &views[k], &pal, n), 0);
            FX_CHECK_MSG(memcmp(one, many, (size_t)w * h * 2) == 0, "view %d, %d threads", k, n);
        }
    }
    /* a sub-rectangle leaves the rest alone */
    memset(many, 0xAA, (size_t)w * h * 2);
    fx_rect r = {10, 20, 90, 100};
    FX_CHECK_EQ(fx_fractal_render_mt(&b, r, &views[0], &pal, 3), 0);
    FX_CHECK_EQ(((uint16_t *)(void *)many)[0], 0xAAAA);
    FX_CHECK_EQ(fx_fractal_render_mt(&b, r, &views[0], &pal, 0), -FX_EINVAL);
    free(one);
    free(many);
}
