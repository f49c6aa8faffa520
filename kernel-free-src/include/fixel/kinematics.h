/* SPDX-License-Identifier: MIT */
/* fixel — kinematics of a jointed chain, an arm reaching a target.
 *
 * Issue #44, the notes' "motion" (kinematics and goal-directed systems):
 * forward kinematics (joint angles and link lengths give the joint
 * positions), inverse kinematics by cyclic coordinate descent, and a
 * goal-directed motion (a point moving at a bounded speed toward a goal,
 * the arm following it).
 *
 * A planar chain of n links hangs from a base (x, y). Joint i turns link i
 * by theta[i] relative to link i - 1 (link 0 relative to the chain's
 * direction `dir`), so link i points along dir + theta[0] + ... + theta[i].
 * Angles are binary (fx_angle, counter-clockwise from +x with y up; on a
 * y-down screen the same numbers turn clockwise, and nothing here depends
 * on which). Positions and lengths are Q16.16 in any unit.
 *
 * Everything is integer, allocation-free and deterministic (the same
 * arguments give the same bits on every machine). docs/ANIMATION.md
 * describes the method, its limits and its tests.
 */
#ifndef FIXEL_KINEMATICS_H
#define FIXEL_KINEMATICS_H

#include <stdint.h>
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

/* At most this many links (and joints) in a chain. */
#define FX_KIN_MAX_JOINTS 16
/* |base|, |target| and |goal| coordinates at most this many units, and the
 * links' total length at most FX_KIN_REACH: every joint then lies within
 * 2^14 units of the origin and every difference fits Q16.16. */
#define FX_KIN_COORD 8192
#define FX_KIN_REACH 8192
/* At most this many CCD sweeps per solve. */
#define FX_KIN_MAX_ITER 4096

typedef struct fx_kin_chain {
    fx16 x, y;        /* the base, |x|, |y| <= FX_KIN_COORD units */
    fx_angle dir;     /* the direction link 0 points in at theta[0] = 0 */
    int32_t n;        /* links, 1..FX_KIN_MAX_JOINTS */
    const fx16 *len;  /* n lengths, each >= 0, their sum <= FX_KIN_REACH units */
} fx_kin_chain;

/* What a solve achieved. */
typedef struct fx_kin_result {
    int32_t iterations; /* CCD sweeps used (0 when already there, or stretched) */
    int32_t reached;    /* 1 when the end is within the tolerance of the target */
    fx16 distance;      /* |end - target| after the solve, rounded to nearest */
} fx_kin_result;

/* Forward kinematics: the n + 1 points of the chain, base first and the end
 * (the effector) last, as x, y pairs in xy[0 .. 2n + 1]. Each point is
 * the base plus the sum of len[i] (cos a_i, sin a_i) with the sines of
 * fx_sin30/fx_cos30 (|error| <= 2^-21), summed with 46 fraction bits and
 * rounded to nearest once per point: |error| <= 2^-17 + reach * 2^-20
 * units. Returns n + 1, or -FX_EINVAL (NULL pointer, n out of range, a
 * negative length, total length or base past the limits above). */
int fx_kin_forward(const fx_kin_chain *c, const fx_angle *theta, fx16 *xy);

/* Inverse kinematics by cyclic coordinate descent: each sweep turns the
 * joints from the last to the first, each so that the line from that joint
 * to the end passes through the target (fx_atan2 of the two directions),
 * except that joint 1 takes, when it exists, the closed-form bend of the
 * triangle (link 0, the rest of the chain as one rigid piece, the
 * base-to-target distance) by the law of cosines, since plain CCD creeps
 * when the arm is nearly straight; joint 0 then turns the end onto the
 * target. The sweeps run until |end - target| <= tol or max_iter sweeps
 * have run. theta holds the start on entry (the previous frame's pose: the
 * arm moves continuously) and the pose on return. A target at or beyond
 * the reach less the tolerance (|target - base| >= total length - tol) is
 * answered in closed form: the straight arm pointing at it (theta[0]
 * toward the target, the others 0), the nearest the end can come. Targets inside the reach that no pose touches (a long
 * first link and short others leave a hole round the base) give the best
 * pose found within max_iter, reached 0.
 * Returns the sweeps used (0..max_iter), res filled when not NULL; or
 * -FX_EINVAL (a bad chain as in fx_kin_forward, theta NULL, |tx| or |ty|
 * > FX_KIN_COORD units, tol < 0 or > FX_KIN_REACH units, max_iter < 0 or >
 * FX_KIN_MAX_ITER). */
int fx_kin_ccd(const fx_kin_chain *c, fx_angle *theta, fx16 tx, fx16 ty, fx16 tol, int32_t max_iter,
               fx_kin_result *res);

/* A goal-directed step: the point (*px, *py) moves toward the goal (gx, gy)
 * along the straight line between them by at most `speed` units (rounded
 * to nearest; the last step lands exactly on the goal). Returns 1 when the
 * point is at the goal after the step, 0 before, or -FX_EINVAL (NULL, a
 * coordinate past FX_KIN_COORD units, speed < 0 or > FX_KIN_REACH units). */
int fx_kin_step(fx16 *px, fx16 *py, fx16 gx, fx16 gy, fx16 speed);

/* The goal-directed motion of the arm: `frames` steps of fx_kin_step moving
 * the aim point (*px, *py) toward the goal, each followed by
 * fx_kin_ccd(c, theta, *px, *py, tol, iter) from the previous pose, so the
 * end tracks a target that moves at a bounded speed rather than jumping.
 * When trail is not NULL the end's position after each frame goes to
 * trail[2f], trail[2f + 1] (2 * frames values). Returns the frame (1-based)
 * at which the aim point arrived, 0 when it has not, or -FX_EINVAL (any
 * argument as in fx_kin_step and fx_kin_ccd, frames < 0 or > 65536). */
int fx_kin_follow(const fx_kin_chain *c, fx_angle *theta, fx16 *px, fx16 *py, fx16 gx, fx16 gy, fx16 speed,
                  int32_t frames, fx16 tol, int32_t iter, fx16 *trail);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif
