/* SPDX-License-Identifier: MIT */
/* Shared test helper: a scene host's make_surface over a fixed pixel buffer
 * (test_scene.c, test_scene_clip.c, test_fractal.c's script commands). */
#ifndef FX_TEST_SCENEBUF_H
#define FX_TEST_SCENEBUF_H

#include <stddef.h>
#include <stdint.h>

#include "fixel/surface.h"

typedef struct {
    uint32_t *mem;
    size_t n; /* pixels */
} scene_buf;

/* fx_scene_host.make_surface with user a scene_buf: the whole buffer zeroed
 * and a w x h surface of format f over it (stride w * 4), or -FX_ENOMEM
 * when w * h is more than its n pixels. */
int scene_buf_make(void *user, int32_t w, int32_t h, fx_format f, fx_surface *out);

#endif
