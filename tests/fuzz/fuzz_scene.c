/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the scene-script parser and interpreter. Any bytes are a
 * script; surfaces are capped at 128x128 and live between guard pages; the
 * arena is small so that its limits are exercised too. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "scenehost.h"

static void trace(void *u, const char *line)
{
    (void)u;
    (void)line;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static uint8_t arena[1 << 20];
    static fx_scene sc;
    if (size > 4096)
        return 0;
    fx_scene_host host = {NULL, make_surface, load_file, NULL, size & 1 ? trace : NULL, NULL};
    fx_scene_init(&sc, &host, arena, sizeof arena);
    fx_scene_run(&sc, (const char *)data, size);
    free_surface();
    return 0;
}
