/* SPDX-License-Identifier: MIT */
/* fixel — animation (issue #23): key frames and in-betweens, ease-in and
 * ease-out, morphing polygons with different vertex counts, a bouncing
 * ball under gravity, and the accumulation buffer of motion blur.
 *
 * Times are Q16.16 seconds (or any unit the caller likes: nothing here
 * knows a frame rate). Everything is integer and allocation-free: key
 * arrays, matched polygons and accumulation buffers belong to the caller.
 * docs/ANIMATION.md explains the methods and their error bounds.
 */
#ifndef FIXEL_ANIM_H
#define FIXEL_ANIM_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/fixed.h"
#include "fixel/surface.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- key frames and in-betweens ---- */

#define FX_ANIM_MAX_CH 8 /* values per key: x y z, angles, colour channels... */

typedef struct fx_anim_key {
    fx16 t;                    /* strictly increasing along a track */
    fx16 v[FX_ANIM_MAX_CH];    /* the first nch are used */
} fx_anim_key;

typedef enum fx_anim_interp {
    FX_ANIM_LINEAR, /* straight in-betweens, corners at the keys */
    FX_ANIM_SPLINE, /* Catmull-Rom through the keys (C1), see fx_anim_eval */
    FX_ANIM_STEP,   /* hold each key's value until the next key */
} fx_anim_interp;

typedef enum fx_anim_ease {
    FX_EASE_NONE,   /* s */
    FX_EASE_IN,     /* 1 - cos(s * 90 deg): starts at rest, accelerates */
    FX_EASE_OUT,    /* sin(s * 90 deg): decelerates to rest */
    FX_EASE_INOUT,  /* (1 - cos(s * 180 deg)) / 2: both */
    FX_EASE_SMOOTH, /* 3s^2 - 2s^3 (smoothstep): both, a cubic */
    FX_EASE_COUNT
} fx_anim_ease;

typedef struct fx_anim_track {
    const fx_anim_key *keys;
    int32_t n;      /* number of keys, >= 1 */
    int32_t nch;    /* values per key, 1..FX_ANIM_MAX_CH */
    uint8_t interp; /* fx_anim_interp */
    uint8_t ease;   /* fx_anim_ease, applied to the whole track's time span */
} fx_anim_track;

/* The ease function on s in [0, 1] (clamped): a monotone time warp with
 * ease(0) = 0 and ease(1) = 1 exactly. IN/OUT/INOUT use fx_sin/fx_cos (the
 * quarter-wave table, exact at multiples of 90 degrees, error < 2^-15
 * elsewhere); SMOOTH is exact up to the final rounding to nearest. */
fx16 fx_anim_ease_apply(fx_anim_ease e, fx16 s);

/* The values of the track at time t (out[0..nch)). Before the first key
 * and after the last the end values hold. The ease warps t over
 * [first key, last key]; then the segment [t_i, t_i+1] holding it is found
 * and s = (t - t_i) / (t_i+1 - t_i) interpolated:
 *   LINEAR  p_i + s (p_i+1 - p_i)
 *   SPLINE  the cubic Hermite of p_i, p_i+1 with tangents
 *           m_i = (p_i+1 - p_i-1) / (t_i+1 - t_i-1) (one-sided at the ends),
 *           i.e. Catmull-Rom for unevenly spaced keys.
 * At a key's time the key's value comes out exactly (s = 0). Arithmetic is
 * 64-bit with 128-bit products (fx_mul64_shift); s has 30 fraction bits;
 * each result is rounded to nearest and saturated to int32 (a spline may
 * overshoot between keys). Returns the segment index (0..n-1), or
 * -FX_EINVAL for a bad track (no keys, nch out of range, times not
 * strictly increasing). */
int fx_anim_eval(const fx_anim_track *tr, fx16 t, fx16 *out);

/* The direction of motion at time t along the track's path (channels 0..nch):
 * the difference of the un-eased path a small step (1/1024 of the key span,
 * at least 2^-16) either side of the warped time, clamped to the span, so an
 * ease that stops the object does not lose its heading. Returns as
 * fx_anim_eval; out is all zero for a one-key track. */
int fx_anim_tangent(const fx_anim_track *tr, fx16 t, fx16 *out);

/* a + s (b - a), s in Q16.16 (not clamped), rounded to nearest, saturated. */
fx16 fx_anim_lerp(fx16 a, fx16 b, fx16 s);
/* Each channel (A, R, G, B) of a + s (b - a), s clamped to [0, 1], rounded
 * to nearest: s = 0 gives a, s = 1 gives b exactly. */
fx_color fx_anim_color_lerp(fx_color a, fx_color b, fx16 s);

/* ---- morphing ---- */

/* The course's vertex-adding method for two outlines with different
 * numbers of edges: with Lmax and Lmin edges, Ns = Lmax / Lmin and
 * Ne = Lmax mod Lmin, Ne edges of the outline with fewer are divided into
 * Ns + 1 equal sections and the other Lmin - Ne into Ns, so both have Lmax
 * edges; the added vertices lie on the old edges (positions rounded to
 * nearest). The Ne longer divisions are spread round the outline: edge i
 * gets one when floor((i+1) Ne / Lmin) > floor(i Ne / Lmin).
 * a (na points) and b (nb points) hold dim coordinates per point (dim 1..4,
 * e.g. 2 for polygons, 3 for 3D outlines); closed: the last point joins the
 * first (edges = points), else a polyline (edges = points - 1). Vertex 0 of
 * a corresponds to vertex 0 of b. The larger outline is copied unchanged.
 * Writes max(na, nb) points to each of a_out and b_out (max points each);
 * returns that count, or -FX_EINVAL (fewer than 2 points, or 3 when closed;
 * dim out of range), -FX_ENOSPC (max too small). */
int fx_anim_morph_match(const fx16 *a, int32_t na, const fx16 *b, int32_t nb, int32_t dim, int closed,
                        fx16 *a_out, fx16 *b_out, int32_t max);
/* The in-between at s: out[i] = fx_anim_lerp(a[i], b[i], s), n values. */
void fx_anim_morph_at(const fx16 *a, const fx16 *b, int32_t n, fx16 s, fx16 *out);

/* ---- a bouncing ball under gravity ---- */

/* Screen axes: y grows downwards, so gravity g >= 0 pulls towards +y and the
 * floor is a maximum y. Between impacts the motion is the exact parabola
 * y = y0 + v t + g t^2 / 2; each impact time is solved in closed form (a
 * 64-bit integer square root), the speed after it is e times the speed
 * before (rounded down, so with e < 1 it strictly falls and the energy
 * never grows), and the walls reflect x elastically. Limits keep every
 * product inside 64 bits: |positions| <= FX_ANIM_BALL_POS, |speeds| <=
 * FX_ANIM_BALL_SPEED, 0 <= g <= FX_ANIM_BALL_G, 0 <= e <= 1, times 0..32767. */
#define FX_ANIM_BALL_POS 16384
#define FX_ANIM_BALL_SPEED 8192
#define FX_ANIM_BALL_G 16384
/* After this many impacts (or once a flight rounds to no time) the ball
 * rests on the floor; e = 1 bounces for ever (periodic). */
#define FX_ANIM_BALL_MAX_BOUNCES 4096

typedef struct fx_anim_ball {
    fx16 x, y, vx, vy;       /* the centre and its velocity at t = 0 (units/s) */
    fx16 g, e;               /* gravity (units/s^2, towards +y), restitution */
    fx16 left, right, floor; /* the centre's bounds: walls at x, the floor at y */
} fx_anim_ball;

typedef struct fx_anim_ball_state {
    fx16 x, y, vx, vy;
    int32_t bounces; /* floor impacts up to and including t */
    int32_t resting; /* 1 once the ball lies on the floor */
} fx_anim_ball_state;

/* The ball at time t. 0, or -FX_ERANGE (a value outside the limits above,
 * left > right, or the start below the floor). */
int fx_anim_ball_at(const fx_anim_ball *b, fx16 t, fx_anim_ball_state *out);
/* The time of the k-th floor impact (k >= 1): 0 and *t, or -FX_ENOENT when
 * the ball never makes that many (it came to rest), or -FX_ERANGE. */
int fx_anim_ball_impact(const fx_anim_ball *b, int32_t k, fx16 *t);
/* Energy per unit mass, g (floor - y) + v^2 / 2, in Q32.32 (int64): exact
 * within the limits above, saturated at INT64_MAX past them; 0 when b or s
 * is NULL. */
int64_t fx_anim_ball_energy(const fx_anim_ball *b, const fx_anim_ball_state *s);

/* ---- temporal antialiasing: the accumulation buffer ---- */

/* Sums of A, R, G, B over up to FX_ACCUM_MAX frames of a w x h picture, in
 * memory the caller gives (fx_accum_size bytes). Motion blur: render the
 * frame at N times across the shutter, add each, resolve the average. */
#define FX_ACCUM_MAX 65536

typedef struct fx_accum {
    uint32_t *sum; /* 4 per pixel */
    int32_t w, h;
    uint32_t n;    /* frames added */
} fx_accum;

/* Bytes of memory an accumulator of a w x h picture needs (0 for a bad size). */
size_t fx_accum_size(int32_t w, int32_t h);
/* -FX_EINVAL for a bad size, -FX_ENOSPC when bytes < fx_accum_size. */
int fx_accum_init(fx_accum *a, void *mem, size_t bytes, int32_t w, int32_t h);
void fx_accum_clear(fx_accum *a);
/* Add the top-left w x h of s (its colours unpacked). -FX_EINVAL when s is
 * smaller, -FX_E2BIG after FX_ACCUM_MAX frames. */
int fx_accum_add(fx_accum *a, const fx_surface *s);
/* Write each channel's average, (sum + n/2) / n (rounded to nearest, ties
 * up), to s, packed in its format: a static scene comes back unchanged.
 * -FX_EINVAL when nothing was added or s is smaller. */
int fx_accum_resolve(const fx_accum *a, const fx_surface *s);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
