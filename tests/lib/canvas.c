/* SPDX-License-Identifier: MIT */
/* Shared test helper: canvas_make (tests/lib/canvas.h). */
#include "canvas.h"

#include <stdlib.h>

canvas canvas_make(int w, int h)
{
    canvas c;
    c.mem = calloc((size_t)w * h, 4);
    c.w = w;
    c.h = h;
    fx_surface_init(&c.s, c.mem, w, h, w * 4, FX_FMT_XRGB8888);
    return c;
}
