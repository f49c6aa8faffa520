/* SPDX-License-Identifier: MIT */
/* Library versions for the table header, so that a table says what it
 * measured. */
#include "bench.h"

#include <stdio.h>

#ifdef BENCH_PEERS
#include <SDL.h>
#include <SDL2_gfxPrimitives.h>
#include <cairo.h>
#include <pixman.h>
#endif

const char *peer_versions(void)
{
    static char buf[160];
#ifdef BENCH_PEERS
    SDL_version v;
    SDL_GetVersion(&v);
    snprintf(buf, sizeof buf, "cairo %s, pixman %s, SDL2 %d.%d.%d, SDL2_gfx %d.%d.%d; gcc %s",
             cairo_version_string(), pixman_version_string(), v.major, v.minor, v.patch,
             SDL2_GFXPRIMITIVES_MAJOR, SDL2_GFXPRIMITIVES_MINOR, SDL2_GFXPRIMITIVES_MICRO, __VERSION__);
#else
    snprintf(buf, sizeof buf, "built without peer libraries; gcc %s", __VERSION__);
#endif
    return buf;
}
