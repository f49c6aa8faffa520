/* SPDX-License-Identifier: MIT */
/* fixel — the orbit of 0 under z^2 + c and its classification (contract in
 * julia.h). */
#include "fixel/julia.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

#define CLOSE ((int64_t)1 << (FX56_SHIFT - 20)) /* 2^-20: a cycle has closed */

static int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

int fx_orbit0(fx56 cre, fx56 cim, uint32_t n, fx56 *zre, fx56 *zim, fx_orbit0_info *out)
{
    if (!out || n < 1 || n > FX_ORBIT0_MAX || abs64(cre) > 16 * FX56_ONE || abs64(cim) > 16 * FX56_ONE)
        return -FX_EINVAL;
    fx_memset(out, 0, sizeof *out);
    /* the last FX_JULIA_MAX_PERIOD + 1 values, for the cycle test */
    fx56 hr[FX_JULIA_MAX_PERIOD + 1], hi[FX_JULIA_MAX_PERIOD + 1];
    fx56 x = 0, y = 0;
    uint32_t k = 0;
    for (;; k++) {
        hr[k % (FX_JULIA_MAX_PERIOD + 1)] = x, hi[k % (FX_JULIA_MAX_PERIOD + 1)] = y;
        if (zre)
            zre[k] = x;
        if (zim)
            zim[k] = y;
        /* |z|^2 > 4 in Q8.56. z_1 = c may be 16 a part, whose square leaves
         * Q8.56 (the corner suite found the overflow): a part over 2 escapes
         * before anything is squared. Past that test |x|, |y| <= 2, so
         * x^2 + y^2 <= 8 and z^2 + c (|c| parts <= 16) stays below 28. */
        int far = abs64(x) > 2 * FX56_ONE || abs64(y) > 2 * FX56_ONE;
        fx56 x2 = far ? 0 : fx56_mul(x, x), y2 = far ? 0 : fx56_mul(y, y);
        if (far || x2 + y2 > 4 * FX56_ONE) {
            out->kind = FX_ORBIT0_ESCAPES;
            out->steps = k;
            out->re = x, out->im = y;
            return (int)out->kind;
        }
        if (k == n - 1)
            break;
        fx56 ny = 2 * fx56_mul(x, y) + cim;
        x = x2 - y2 + cre;
        y = ny;
    }
    out->steps = n - 1;
    out->re = x, out->im = y;
    /* the smallest p with z_n = z_(n-p) to within 2^-20 */
    for (int p = 1; p <= FX_JULIA_MAX_PERIOD && (uint32_t)p <= k; p++) {
        uint32_t j = (k - (uint32_t)p) % (FX_JULIA_MAX_PERIOD + 1);
        if (abs64(hr[j] - x) < CLOSE && abs64(hi[j] - y) < CLOSE) {
            out->period = p;
            /* a fixed point with a non-real multiplier 2 z* turns the orbit
             * around it: the notes' spiral; a real one approaches along a
             * line (or sits on it) */
            out->kind = p > 1 ? FX_ORBIT0_CYCLE : abs64(y) >= CLOSE ? FX_ORBIT0_SPIRAL : FX_ORBIT0_FIXED;
            return (int)out->kind;
        }
    }
    out->kind = FX_ORBIT0_BOUNDED;
    return (int)out->kind;
}
