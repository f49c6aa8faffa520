/* SPDX-License-Identifier: MIT */
/* libFuzzer target: the scene-script parser and interpreter. Any bytes are a
 * script; surfaces are capped at 128x128 and live between guard pages; the
 * arena is small so that its limits are exercised too. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "guard.h"

static guarded g;
static int have;
static const uint8_t font_file[] = {0x36, 0x04, 0x00, 0x08, 0xFF, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xFF};

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    (void)u;
    if (w > 128 || h > 128)
        return -FX_ENOMEM;
    if (guarded_make(&g, w, h, f, (w + h) & 1) < 0)
        return -FX_ENOMEM;
    have = 1;
    *out = g.s;
    return 0;
}

/* Every path names the same tiny (truncated) PSF1 font: file commands run,
 * the loader's error paths too, without touching the disk. */
static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    (void)u;
    if (!strcmp(path, "missing"))
        return -FX_ENOENT;
    *data = font_file;
    *len = sizeof font_file;
    return 0;
}

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
    fx_scene_host host = {NULL, make_surface, load_file, NULL, size & 1 ? trace : NULL};
    fx_scene_init(&sc, &host, arena, sizeof arena);
    fx_scene_run(&sc, (const char *)data, size);
    if (have) {
        guarded_free(&g);
        have = 0;
    }
    return 0;
}
