/* SPDX-License-Identifier: MIT */
/* fixel — frame mapping (issue #44): a procedural map of the local frame
 * and Kajiya-Kay's anisotropic highlight, shared by the ray tracer and the
 * rasterizer's Phong path (rt.h has the model). */
#include "fixel/fixed.h"
#include "rt_int.h"
#include "../base/fx_internal.h"

#define ONE ((int64_t)FX16_ONE)

/* A jitter in [-amp/2, amp/2) from the noise at p. */
static int64_t jitter(fx_vec3 p, int64_t amp) { return rt_mul((int64_t)fx_rt_noise3(p) - ONE / 2, amp); }

/* Wrapping arithmetic on lattice coordinates: the noise repeats, so a
 * wrapped coordinate is as good as any (and q may hold any fx16). */
static fx16 wrap_add(fx16 a, int64_t b) { return (fx16)(uint32_t)((uint32_t)a + (uint32_t)(int32_t)b); }

/* Tilts of about +-0.2 (12 degrees): enough to break a highlight of
 * exponent 20..100 into streaks, small enough that the grain still reads
 * as one direction. */
#define AMP (ONE * 2 / 5)

fx_vec3 fx_rt_frame_dir(int kind, fx_vec3 q)
{
    if (kind == FX_RT_FRAME_BRUSHED) {
        /* one noise cell across the grain, sixteen along it */
        fx_vec3 a = fx_vec3_make(q.x >> 4, q.y, q.z);
        fx_vec3 b = fx_vec3_make(wrap_add(a.x, 17 * ONE), wrap_add(a.y, 5 * ONE), wrap_add(a.z, 11 * ONE));
        return fx_vec3_make(FX16_ONE, (fx16)jitter(a, AMP), (fx16)jitter(b, AMP));
    }
    if (kind == FX_RT_FRAME_SPUN) {
        fx_vec3 rad = fx_vec3_make(q.x, 0, q.z);
        if (fx_vec3_normalize(&rad) < 0)
            return fx_vec3_make(FX16_ONE, 0, 0);
        /* the distance from the axis in cells: the grain's rings vary
         * across it; slowly along the ring (its arc is not at hand, the
         * angle's cosine stands in) */
        fx16 r = rt_sat(rt_mul(q.x, rad.x) + rt_mul(q.z, rad.z));
        fx_vec3 a = fx_vec3_make(r, q.y, rad.x);
        fx_vec3 b = fx_vec3_make(wrap_add(r, 13 * ONE), wrap_add(q.y, 7 * ONE), rad.z);
        int64_t j1 = jitter(a, AMP), j2 = jitter(b, AMP);
        /* the circle's tangent (-z, 0, x), tilted up (y) and outward */
        return fx_vec3_make(rt_sat(-(int64_t)rad.z + rt_mul(j2, rad.x)), (fx16)j1,
                            rt_sat(rad.x + rt_mul(j2, rad.z)));
    }
    return fx_vec3_make(FX16_ONE, 0, 0);
}

void fx_rt_frame(fx_vec3 dir, fx_vec3 n, fx_vec3 *t, fx_vec3 *b)
{
    for (int pass = 0; pass < 3; pass++) {
        int64_t dn = fx_vec3_dot(dir, n);
        fx_vec3 o = fx_vec3_make(rt_sat(dir.x - rt_mul(dn, n.x)), rt_sat(dir.y - rt_mul(dn, n.y)),
                                 rt_sat(dir.z - rt_mul(dn, n.z)));
        /* below 1/16 of dir's length the direction of what is left is
         * mostly rounding: take an axis away from n instead */
        if (fx_vec3_length(o) >= fx_vec3_length(dir) / 16 && fx_vec3_normalize(&o) == 0) {
            fx_vec3 c = fx_vec3_cross(n, o);
            if (fx_vec3_normalize(&c) < 0)
                c = o;
            *t = o;
            *b = c;
            return;
        }
        dir = pass == 0 ? fx_vec3_make(FX16_ONE, 0, 0) : fx_vec3_make(0, FX16_ONE, 0);
        if (pass == 0 && (n.x > FX16_ONE * 9 / 10 || n.x < -FX16_ONE * 9 / 10))
            dir = fx_vec3_make(0, FX16_ONE, 0);
    }
    /* n not unit (zero): any frame */
    *t = fx_vec3_make(FX16_ONE, 0, 0);
    *b = fx_vec3_make(0, FX16_ONE, 0);
}

fx16 fx_rt_aniso_spec(fx16 spec, fx16 k, fx_vec3 t, fx_vec3 h, fx16 nl, int32_t n)
{
    if (k <= 0)
        return spec;
    if (k > FX16_ONE)
        k = FX16_ONE;
    int64_t th = fx_vec3_dot(t, h);
    int64_t s2 = ONE - rt_mul(th, th);
    fx16 kk = 0;
    if (s2 > 0) {
        if (s2 > ONE)
            s2 = ONE;
        kk = fx16_powi(fx16_sqrt((fx16)s2), n < 0 ? 0 : n > 256 ? 256 : n);
        kk = (fx16)rt_mul(kk, nl < 0 ? 0 : nl > FX16_ONE ? FX16_ONE : nl);
    }
    return rt_sat(spec + rt_mul((int64_t)kk - spec, k));
}
