/* SPDX-License-Identifier: MIT */
/* fixel — 3D vectors, 4x4 matrices, the matrix stack, the camera and the
 * projections, all in Q16.16.
 *
 * Conventions (those of the OpenGL 1.x fixed pipeline):
 *   - column vectors, p' = M p; m[row][col]; translation in column 3.
 *   - right-handed eye space: the camera sits at the origin looking down -z,
 *     +y up. Clip space is GL's: after division x, y, z are in [-1, 1] with
 *     z = -1 on the near plane.
 *   - "Post-multiply" operations (fx_mat_stack_mult and the builders used
 *     through it) compose like glMultMatrix: the last one named acts first.
 *
 * Arithmetic: every product of two Q16.16 values is formed in 64 bits and
 * rounded to nearest once per output entry (a row-column dot product is
 * summed exactly, then rounded), so one matrix product or one transform has
 * error <= 1/2 unit (2^-17) per entry plus the saturation of values beyond
 * +-32768. Rotations use fx_sin/fx_cos (|error| <= 2^-16), so a rotation
 * matrix is orthonormal to within 2^-15 per entry.
 */
#ifndef FIXEL_MAT3D_H
#define FIXEL_MAT3D_H

#include <stdint.h>
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fx_vec3 {
    fx16 x, y, z;
} fx_vec3;

typedef struct fx_vec4 {
    fx16 x, y, z, w;
} fx_vec4;

typedef struct fx_mat4 {
    fx16 m[4][4]; /* m[row][col] */
} fx_mat4;

/* The vector (x, y, z); sums, differences and scaling by s (Q16.16, saturating). */
static inline fx_vec3 fx_vec3_make(fx16 x, fx16 y, fx16 z)
{
    fx_vec3 v = {x, y, z};
    return v;
}
fx_vec3 fx_vec3_add(fx_vec3 a, fx_vec3 b);
fx_vec3 fx_vec3_sub(fx_vec3 a, fx_vec3 b);
fx_vec3 fx_vec3_scale(fx_vec3 a, fx16 s);
/* Dot product rounded to nearest, saturating. */
fx16 fx_vec3_dot(fx_vec3 a, fx_vec3 b);
fx_vec3 fx_vec3_cross(fx_vec3 a, fx_vec3 b);
/* Length, rounded down (exact floor of the true length in Q16.16). */
fx16 fx_vec3_length(fx_vec3 a);
/* a / |a|, each component rounded to nearest; works for any non-zero
 * vector, however short (the division happens at 32 extra bits). The zero
 * vector gives itself and the return value is -FX_EDOM, otherwise 0. */
int fx_vec3_normalize(fx_vec3 *a);

/* ---- matrices ---- */
void fx_mat4_identity(fx_mat4 *m);
/* r = a * b (r may be a or b). */
void fx_mat4_mul(fx_mat4 *r, const fx_mat4 *a, const fx_mat4 *b);
fx_vec4 fx_mat4_apply(const fx_mat4 *m, fx_vec4 v);
/* M (x, y, z, 1) and the direction M (x, y, z, 0). */
fx_vec4 fx_mat4_apply_point(const fx_mat4 *m, fx_vec3 p);
fx_vec3 fx_mat4_apply_dir(const fx_mat4 *m, fx_vec3 d);
void fx_mat4_transpose(fx_mat4 *r, const fx_mat4 *m);

/* Builders: each writes a complete matrix. */
void fx_mat4_translate(fx_mat4 *m, fx16 x, fx16 y, fx16 z);
void fx_mat4_scale(fx_mat4 *m, fx16 x, fx16 y, fx16 z);
void fx_mat4_rotate_x(fx_mat4 *m, fx_angle a);
void fx_mat4_rotate_y(fx_mat4 *m, fx_angle a);
void fx_mat4_rotate_z(fx_mat4 *m, fx_angle a);
/* Rotation by a about the axis (normalised here; need not be unit),
 * counter-clockwise looking from the axis tip, as glRotate. A zero axis
 * gives the identity and -FX_EDOM. */
int fx_mat4_rotate(fx_mat4 *m, fx_angle a, fx_vec3 axis);
/* The course's z-axis shear SHz: x' = x + a z, y' = y + b z. */
void fx_mat4_shear_z(fx_mat4 *m, fx16 a, fx16 b);
/* Reflection about the plane n . p = d (n normalised here). A zero normal
 * gives the identity and -FX_EDOM. */
int fx_mat4_reflect(fx_mat4 *m, fx_vec3 n, fx16 d);

/* General inverse by Gauss-Jordan elimination with partial pivoting on
 * Q32.32 intermediates, each entry rounded to nearest at the end. For
 * matrices whose entries and whose inverse's entries are within +-256 and
 * whose pivots stay above 2^-8 (rigid motions, scales in [1/16, 16], the
 * projections of this file) M * inverse(M) equals I to within 2^-12 per
 * entry (tests/core/test_3d.c measures it). Returns -FX_EDOM for a
 * singular (or numerically singular: pivot below 2^-24) matrix and leaves
 * r untouched. */
int fx_mat4_invert(fx_mat4 *r, const fx_mat4 *m);

/* ---- matrix stack (memory from the caller) ---- */
typedef struct fx_mat_stack {
    fx_mat4 *slot; /* slot[0 .. cap-1] */
    int cap, top;  /* slot[top] is the current matrix */
} fx_mat_stack;

/* cap >= 1 slots; the current matrix starts as the identity. */
int fx_mat_stack_init(fx_mat_stack *s, fx_mat4 *mem, int cap);
static inline fx_mat4 *fx_mat_stack_top(fx_mat_stack *s) { return &s->slot[s->top]; }
/* push duplicates the current matrix: -FX_ENOSPC when full. pop: -FX_ERANGE
 * when only one matrix is left. */
int fx_mat_stack_push(fx_mat_stack *s);
int fx_mat_stack_pop(fx_mat_stack *s);
void fx_mat_stack_load(fx_mat_stack *s, const fx_mat4 *m);
/* current = current * m (glMultMatrix). */
void fx_mat_stack_mult(fx_mat_stack *s, const fx_mat4 *m);

/* ---- camera (the course's Camera class) ----
 * eye and an orthonormal basis u (right), v (up), n (backwards: the camera
 * looks along -n). */
typedef struct fx_camera {
    fx_vec3 eye, u, v, n;
} fx_camera;

/* gluLookAt: n = eye - look, u = up x n, v = n x u (all unit). -FX_EDOM when
 * eye == look or up is parallel to the view direction (camera unchanged). */
int fx_camera_set(fx_camera *c, fx_vec3 eye, fx_vec3 look, fx_vec3 up);
/* Move along the camera's own axes: eye += du u + dv v + dn n. */
void fx_camera_slide(fx_camera *c, fx16 du, fx16 dv, fx16 dn);
/* Rotations about the camera's own axes; positive angles turn the view
 * counter-clockwise (roll, about n), nose up (pitch, about u) and to the
 * left (yaw, about v). The basis is re-orthonormalised after each turn so
 * that rounding does not accumulate. */
void fx_camera_roll(fx_camera *c, fx_angle a);
void fx_camera_pitch(fx_camera *c, fx_angle a);
void fx_camera_yaw(fx_camera *c, fx_angle a);
/* The view matrix: world -> eye (rows u, v, n; translation -eye . axis). */
void fx_camera_view(const fx_camera *c, fx_mat4 *m);

/* ---- projections (gluPerspective, glOrtho, oblique parallel) ----
 * All return -FX_EINVAL for empty or inverted volumes (near <= 0 for
 * perspective, left == right, ...). */
int fx_mat4_perspective(fx_mat4 *m, fx_angle fovy, fx16 aspect, fx16 znear, fx16 zfar);
int fx_mat4_ortho(fx_mat4 *m, fx16 l, fx16 r, fx16 b, fx16 t, fx16 znear, fx16 zfar);
/* Non-square pixels (the pixel aspect ratio, e.g. the notes' 3/4): m =
 * S(num/den, 1, 1) . m, the first row of a projection multiplied by
 * num/den, each entry rounded to nearest (ties away from zero), so every
 * projected x (about the viewport's centre) is num/den of what it was and
 * a sphere is drawn num/den as many pixels wide as it is tall. For 3/4
 * (and any den that is a power of two) the entries are exact. num, den in
 * 1..65536, else -FX_EINVAL and m unchanged. */
int fx_mat4_pixel_aspect(fx_mat4 *m, int32_t num, int32_t den);
/* Oblique parallel projection: a point at depth d = -z in front of the
 * camera moves by (L (d - plane) cos alpha, L (d - plane) sin alpha)
 * before the orthographic projection, so the plane at depth `plane` (the
 * projection plane, usually through the object's front) is drawn true to
 * size and receding edges slant up and to the side. L = 1 is cavalier,
 * L = 1/2 cabinet; alpha is often 45 or 30 degrees. */
int fx_mat4_oblique(fx_mat4 *m, fx16 l, fx16 r, fx16 b, fx16 t, fx16 znear, fx16 zfar,
                    fx_angle alpha, fx16 len, fx16 plane);
#define FX_OBLIQUE_CAVALIER FX16_ONE
#define FX_OBLIQUE_CABINET  FX16_HALF

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
