/* SPDX-License-Identifier: MIT */
/* fixel — what the ray tracer's files share; not installed. */
#ifndef FIXEL_RT_INT_H
#define FIXEL_RT_INT_H

#include "fixel/rt.h"
#include "../base/fx_wide.h"

/* The 3D noise's lattice hash (fx_rt_noise3 takes its top 16 bits as the
 * value at integer point (x, y, z)); the tests' double noise uses it too. */
static inline uint32_t rt_hash3(int32_t x, int32_t y, int32_t z)
{
    uint32_t h = (uint32_t)x * 0x8DA6B343u ^ (uint32_t)y * 0xD8163841u ^ (uint32_t)z * 0xCB1AB31Fu;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h;
}

/* Q16.16 saturation of a 64-bit value. */
static inline fx16 rt_sat(int64_t v) { return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : (fx16)v; }
/* a * b in Q16.16, rounded to nearest (ties up), from 64-bit operands whose
 * product fits in int64. */
static inline int64_t rt_mul(int64_t a, int64_t b) { return (a * b + 0x8000) >> 16; }

/* m * (p, w) for w = 1 (points) or 0 (directions): three 64-bit dot
 * products, each rounded once and saturated. */
fx_vec3 fx_rt_xform(const fx_mat4 *m, fx_vec3 p, int w);
/* m * (d, 0) with 8 more fraction bits: the object-space direction in
 * Q8.24 (int32 under the scene-scale limit: |d| <= 1, entries <= 16). */
fx_vec3 fx_rt_xform_dir24(const fx_mat4 *m, fx_vec3 d);
/* M^-T n: the object-space normal n taken to world space (not unit). */
fx_vec3 fx_rt_normal_to_world(const fx_mat4 *inv, fx_vec3 n);
/* floor(sqrt(n)) of a non-negative 128-bit value (exact). */
uint64_t fx_rt_isqrt128(fx_s128 n);
/* round(n * 2^shift / d) for d > 0, saturated to int32 (0 < shift < 64). */
fx16 fx_rt_div_shift(fx_s128 n, int64_t d, unsigned shift);
/* The ray S + c t meets the box somewhere on the whole line. */
int fx_rt_box_meets(const fx_rt_box *b, fx_vec3 S, fx_vec3 c);
/* Leaf crossings in object space (S in Q16.16, c24 in Q8.24), sorted. */
void fx_rt_leaf_hits(const fx_rt_object *o, int idx, fx_vec3 S, fx_vec3 c24, fx_rt_hitlist *out);

/* A mesh's nearest crossing with tmin < t (object space, c in Q8.24),
 * appended as an entering and a leaving hit at that t. */
void fx_rt_mesh_hits(const fx_rt_mesh *rm, int idx, fx_vec3 S, fx_vec3 c24, int64_t tmin, fx_rt_hitlist *out);

/* What a shadow feeler from S along c lets through to t = tmax (issue #44):
 * the product of the transparency kt of every surface it crosses with
 * tmin < t < tmax (so a glass ball of kt passes kt^2, an opaque one 0). The
 * documented approximation: the feeler goes straight (no refraction, no
 * caustics) and is dimmed, not tinted. *blocker = the first opaque leaf hit,
 * or -1. Q16.16, 0..1. */
fx16 fx_rt_feeler_transmit(const fx_rt_scene *s, fx_vec3 S, fx_vec3 c, fx16 tmin, fx16 tmax, int *blocker);

#endif
