/* SPDX-License-Identifier: MIT */
/* The scene host callbacks the scene fuzz targets share (fuzz_scene.c,
 * fuzz_grammar.c): one surface at a time, capped at 128x128, between guard
 * pages (bottom-up when w + h is odd); every path names the same tiny
 * (truncated) PSF1 font, so file commands run, the loader's error paths
 * too, without touching the disk ("missing" is not found). */
#ifndef FX_FUZZ_SCENEHOST_H
#define FX_FUZZ_SCENEHOST_H

#include <stdint.h>
#include <string.h>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "guard.h"

static guarded g;
static int have;
static int32_t max_w = 128, max_h = 128; /* larger surfaces are refused (ENOMEM) */
static const uint8_t font_file[] = {0x36, 0x04, 0x00, 0x08, 0xFF, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xFF};

static int make_surface(void *u, int32_t w, int32_t h, fx_format f, fx_surface *out)
{
    (void)u;
    if (w > max_w || h > max_h)
        return -FX_ENOMEM;
    if (guarded_make(&g, w, h, f, (w + h) & 1) < 0)
        return -FX_ENOMEM;
    have = 1;
    *out = g.s;
    return 0;
}

static int load_file(void *u, const char *path, const uint8_t **data, size_t *len)
{
    (void)u;
    if (!strcmp(path, "missing"))
        return -FX_ENOENT;
    *data = font_file;
    *len = sizeof font_file;
    return 0;
}

/* After a run: the surface the script made, if any, goes. */
static void free_surface(void)
{
    if (have) {
        guarded_free(&g);
        have = 0;
    }
}

#endif
