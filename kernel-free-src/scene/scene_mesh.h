/* SPDX-License-Identifier: MIT */
/* Meshes the 3D and ray-tracing commands share (private to the core). */
#ifndef FIXEL_SCENE_MESH_H
#define FIXEL_SCENE_MESH_H

#include "fixel/mesh.h"
#include "fixel/scene.h"
#include "fixel/texture.h"

/* The rest of the line is "FILE": read it through the host, parse it as
 * Wavefront OBJ into arena memory (at most FX_SCENE_MAX_TRIANGLES
 * triangles). 0, or the error recorded on the scene. */
int fx_scene_obj_mesh(fx_scene *sc, fx_mesh *m);

/* The texture the last 'texture' command made (scene_fill.c), or NULL. */
const fx_texture *fx_scene_texture(fx_scene *sc);

/* A mesh of nv vertices (positions, normals, and (s, t) when want_uv) and
 * nt triangles in the 3D state's reusable block (at most
 * FX_SCENE_MAX_TRIANGLES): 0, or the error recorded on the scene. */
int fx_scene_mesh_alloc(fx_scene *sc, int32_t nv, int32_t nt, int want_uv, fx_mesh *m);
/* Draw m with the 3D state: camera, model matrix, lights, material, shading. */
int fx_scene_mesh_draw(fx_scene *sc, fx_mesh *m);

/* Where the viewer is in object coordinates (the inverse of view x model):
 * the eye point, or with a parallel projection (*parallel set) the
 * direction of view. 0, or the error recorded. */
int fx_scene_object_view(fx_scene *sc, fx_vec3 *eye, int *parallel);

#endif
