/* SPDX-License-Identifier: MIT */
/* Shared test helper: scene_buf_make (tests/lib/scenebuf.h). */
#include "scenebuf.h"

#include <string.h>

#include "fixel/error.h"

int scene_buf_make(void *user, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    scene_buf *b = user;
    if ((int64_t)w * h > (int64_t)b->n)
        return -FX_ENOMEM;
    memset(b->mem, 0, b->n * sizeof *b->mem);
    return fx_surface_init(out, b->mem, w, h, w * 4, f);
}
