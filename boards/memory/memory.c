/* SPDX-License-Identifier: MIT */
/* The memory display backend: one scanout buffer in ordinary memory, shown
 * nowhere. Headless programs and tests draw into it and read it back with
 * fx_display_screen. Needs no device and no board library. */
#include <stdlib.h>

#include "../display/display_int.h"
#include "fixel/error.h"

static int mem_show(fx_display *d, int buf, const fx_rect *phys, int n)
{
    (void)d, (void)buf, (void)phys, (void)n;
    return 0;
}
static int mem_wait(fx_display *d, int t) { (void)d, (void)t; return 0; }
static int mem_dispatch(fx_display *d) { (void)d; return 0; }
static int mem_fd(const fx_display *d) { (void)d; return -1; }
static void mem_close(fx_display *d) { free(d->memory_mem); d->memory_mem = NULL; }

static const struct fx_backend_ops mem_ops = {mem_show, mem_wait, mem_dispatch, mem_fd, mem_close,
                                              NULL, NULL, NULL, NULL, NULL};

int fx_memory_open(fx_display *d)
{
    fx_format f = d->opt.format == FX_FMT_COUNT ? FX_FMT_XRGB8888 : d->opt.format;
    int32_t w = d->opt.memory_w, h = d->opt.memory_h;
    if (w <= 0 || h <= 0 || w > 16384 || h > 16384)
        return -FX_EINVAL;
    int32_t stride = fx_format_min_stride(f, w);
    d->memory_mem = calloc((size_t)h, (size_t)stride);
    if (!d->memory_mem)
        return -FX_ENOMEM;
    int r = fx_surface_init(&d->scan[0], d->memory_mem, w, h, stride, f);
    if (r < 0)
        return r;
    d->nbuf = 1;
    d->ops = &mem_ops;
    d->info.width = w;
    d->info.height = h;
    d->info.format = f;
    return 0;
}

