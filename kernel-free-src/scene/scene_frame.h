/* SPDX-License-Identifier: MIT */
/* fixel — the surface in its own frame for the scene modules that bring a
 * y-up camera of their own (3D, ray tracing, visible-surface methods): they
 * draw the same picture whichever way 'coords' points the 2D commands. */
#ifndef FIXEL_SCENE_FRAME_H
#define FIXEL_SCENE_FRAME_H

#include "fixel/draw.h"
#include "fixel/scene.h"

static inline fx_surface fx_scene_screen_surf(const fx_ctx *c)
{
    fx_ctx t = *c;
    fx_ctx_set_coords(&t, FX_COORDS_SCREEN);
    return t.surf;
}

/* The whole context (colour, styles, clip) in the surface's own frame: the
 * 3D module draws its meshes through a copy of the script's context, which
 * after 'coords course' is the mirrored view (meshes came out upside down). */
static inline fx_ctx fx_scene_screen_ctx(const fx_ctx *c)
{
    fx_ctx t = *c;
    fx_ctx_set_coords(&t, FX_COORDS_SCREEN);
    return t;
}

/* The script's pixel aspect ratio ('pixelaspect NUM DEN', scene_clip.c;
 * 1/1 until set), for the 3D module's projections. */
void fx_scene_pixel_aspect(fx_scene *sc, int32_t *num, int32_t *den);

#endif
