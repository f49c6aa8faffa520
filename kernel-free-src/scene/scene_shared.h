/* SPDX-License-Identifier: MIT */
/* State one scene module lends another (private to the core): the
 * animation commands (scene_anim.c) move the 2D transform and the 3D camera
 * and model matrix by a track's value, and record the lines of a blur block
 * as fx_scene_exec_line meets them. */
#ifndef FIXEL_SCENE_SHARED_H
#define FIXEL_SCENE_SHARED_H

#include "fixel/mat3d.h"
#include "fixel/scene.h"
#include "fixel/xform.h"

/* The current 2D transform (scene_clip.c), made on first use; NULL when
 * the arena is full (the error is recorded). */
fx_xform2 *fx_scene_ctm(fx_scene *sc);

/* The 3D camera (scene_3d.c): 0, or the error recorded. */
int fx_scene_3d_camera(fx_scene *sc, fx_vec3 eye, fx_vec3 look, fx_vec3 up);
/* Multiply m into the 3D model matrix, as 'translate3d' does. */
int fx_scene_3d_model(fx_scene *sc, const fx_mat4 *m);

/* 1 while a 'blur' block is being recorded (scene_anim.c). */
int fx_scene_anim_recording(const fx_scene *sc);
/* Keep one line of the block (run later, once per sub-frame). */
int fx_scene_anim_record(fx_scene *sc, const char *line, size_t len, int lineno);

#endif
