/* SPDX-License-Identifier: MIT */
/* What the visible-surface commands lend other scene modules (private to
 * the core). */
#ifndef FIXEL_SCENE_VSD_H
#define FIXEL_SCENE_VSD_H

#include "fixel/scene.h"

/* Voxels vox (2^k a side, fixel/vsd.h's layout) as an octree in arena
 * memory, drawn by the octree method at (sx, sy), scale pixels a voxel,
 * grey by depth, clipped to the surface. Returns the nodes visited (and
 * the octree's size in *nodes), or the error recorded on the scene. */
int fx_scene_octree_draw(fx_scene *sc, const uint8_t *vox, int32_t k, int32_t scale, int32_t sx, int32_t sy,
                         int32_t *nodes);

#endif
