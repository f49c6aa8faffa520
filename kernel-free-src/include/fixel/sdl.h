/* SPDX-License-Identifier: MIT */
/* fixel — the course textbook's Scene Description Language (SDL), read
 * into a ray-tracer scene (fixel/rt.h). Integer-only like the rest of the
 * core: numbers are decimal text rounded to Q16.16 by fx16_parse.
 *
 * The language: whitespace-separated tokens, '!' starts a comment to the
 * end of the line. Attributes (light, globalAmbient, background, ambient,
 * diffuse, specular, emissive, specularExponent, reflectivity,
 * transparency, speedOfLight, minReflectivity, minTransparency,
 * maxRecursionDepth, defaultMaterials, push, pop, translate, scale, rotate,
 * identityAffine) change the state; a shape (sphere, cube, plane, square,
 * cylinder, cone, taperedCylinder S, torus, teapot, tetrahedron,
 * octahedron, dodecahedron, icosahedron, buckyball, mesh FILE) takes the
 * current material and transform; union, intersection and difference are
 * prefix operators over the next two objects; def NAME { ... } stores
 * text and use NAME reads it in place. docs/RAYTRACE.md has the semantics,
 * the defaults and the limits.
 *
 * Files (mesh FILE.3vn) come from the caller's load_file; memory for
 * meshes and their BVHs from the caller's alloc. Errors name the place:
 * "FILE:LINE:COL: message" (and the use that expanded a macro).
 */
#ifndef FIXEL_SDL_H
#define FIXEL_SDL_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/rt.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FX_SDL_MAX_DEFS 64          /* def names in one file */
#define FX_SDL_MAX_NESTING 16       /* use inside use inside ... */
#define FX_SDL_MAX_EXPANSION 200000 /* tokens read out of macros in one file */
#define FX_SDL_MAX_SCAN 8000000     /* bytes read out of macros in one file: blanks and
                                     * comments cost no token, but each use reads them again */
#define FX_SDL_STACK 32             /* push depth */
#define FX_SDL_MESH_MAX 20000       /* vertices, normals, faces and triangles of one mesh file */
#define FX_SDL_FACE_MAX 64          /* corners of one mesh face */

typedef struct fx_sdl_env {
    void *user;
    /* size bytes of zeroed memory, 8-byte aligned, living as long as the
     * scene; NULL when none is left. */
    void *(*alloc)(void *user, size_t size);
    /* A whole file (mesh FILE); NULL: mesh files are refused. */
    int (*load_file)(void *user, const char *path, const uint8_t **data, size_t *len);
} fx_sdl_env;

typedef struct fx_sdl_error {
    char msg[256]; /* "FILE:LINE:COL: ..." */
    int32_t line, col;
} fx_sdl_error;

/* Read the SDL text (len bytes, named fname in messages and used as the
 * folder of relative mesh paths) into s, which the caller has initialised
 * (fx_rt_scene_init): lights, ambient, background, recursion depth and
 * objects are set or added. Returns the number of top-level objects read,
 * or a negative error with err filled. */
int fx_sdl_read(fx_rt_scene *s, const char *text, size_t len, const char *fname, const fx_sdl_env *env,
                fx_sdl_error *err);

/* The default camera of a file that sets none (SDL has no camera
 * statement): looking at the centre of the bounded top-level objects'
 * world box (planes left out) from the direction (1, 1.2, 3) (right,
 * above, in front; y up) at the distance where a sphere around the box
 * fills fovy, kept inside the scene limit. An empty scene gets
 * fx_rt_scene_init's camera. */
int fx_sdl_default_camera(fx_rt_scene *s, fx16 fovy_deg);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
