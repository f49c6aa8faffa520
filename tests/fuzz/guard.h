/* SPDX-License-Identifier: MIT */
/* Surfaces between guard pages: the pixel memory ends exactly at a
 * PROT_NONE page and starts right after another, so a write one byte out of
 * bounds faults at once (ASan does not see into mmap'd memory). */
#ifndef FX_FUZZ_GUARD_H
#define FX_FUZZ_GUARD_H

#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "fixel/surface.h"

typedef struct guarded {
    uint8_t *map;
    size_t map_len;
    fx_surface s;
} guarded;

/* flip: bottom-up memory (negative stride). Returns 0 on success. */
static int guarded_make(guarded *g, int32_t w, int32_t h, fx_format f, int flip)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    int32_t stride = fx_format_min_stride(f, w);
    unsigned bpp = fx_format_get(f)->bits_per_pixel;
    if (bpp == 32)
        stride = (stride + 3) & ~3;
    else if (bpp == 16)
        stride = (stride + 1) & ~1;
    size_t bytes = (size_t)stride * (size_t)h;
    size_t body = (bytes + page - 1) / page * page;
    g->map_len = body + 2 * page;
    g->map = mmap(NULL, g->map_len, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (g->map == MAP_FAILED)
        return -1;
    if (mprotect(g->map + page, body, PROT_READ | PROT_WRITE) != 0)
        return -1;
    /* the buffer's last byte touches the trailing guard page; word formats
     * stay aligned because bytes is a multiple of the word size */
    uint8_t *mem = g->map + page + (body - bytes);
    memset(mem, 0x5A, bytes);
    if (flip)
        return fx_surface_init(&g->s, mem + (size_t)stride * (size_t)(h - 1), w, h, -stride, f);
    return fx_surface_init(&g->s, mem, w, h, stride, f);
}

static void guarded_free(guarded *g) { munmap(g->map, g->map_len); }

#endif
