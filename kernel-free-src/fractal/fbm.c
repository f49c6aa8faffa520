/* SPDX-License-Identifier: MIT */
/* fixel — fractional Brownian curves by spectral synthesis (contracts in
 * koch.h, issue #44). */
#include "fixel/koch.h"
#include "fixel/boxdim.h"
#include "fixel/error.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

/* k^(-beta/2) in Q2.30 for k >= 1, beta in 0..4 Q16.16: the exponent
 * -beta/2 log2 k lies in [-24, 0], split into an integer shift and a
 * fraction for fx16_exp2 (whose range stops at -16), so the smallest
 * amplitude (4096^-2 = 2^-24) keeps 7 significant bits. */
static int64_t amplitude(uint32_t k, fx16 beta)
{
    int64_t e = -(((int64_t)beta * fx_log2_16(k) + (1 << 16)) >> 17); /* Q16.16, <= 0 */
    int64_t whole = e >> 16;                                           /* floor */
    fx16 frac = (fx16)(e - whole * 65536);                             /* [0, 1) */
    return ((int64_t)fx16_exp2(frac) << 14) >> -whole;
}

int fx_fbm_heights(fx16 *h, int32_t n, const fx_fbm_params *p)
{
    if (!h || !p || n < 3 || n > FX_FBM_MAX_SAMPLES || p->beta < 0 || p->beta > 4 * FX16_ONE || p->terms < 1 ||
        p->terms > FX_FBM_MAX_TERMS || p->terms > (uint32_t)(n - 1) / 2)
        return -FX_EINVAL;
    uint32_t m = (uint32_t)n - 1;
    /* The mean square of the sum is sum a_k^2 / 2 (the phases are
     * independent of t), so the heights come out in standard deviations
     * whatever beta and terms are. a_k < 2^31, S < 2^44. */
    uint64_t s = 0;
    for (uint32_t k = 1; k <= p->terms; k++) {
        int64_t a = amplitude(k, p->beta);
        s += (uint64_t)(a * a) >> 30;
    }
    int64_t rms15 = (int64_t)fx_isqrt64(s / 2); /* Q17.15, >= 0.707 */
    for (int32_t i = 0; i < n; i++)
        h[i] = 0;
    uint32_t st = p->seed;
    for (uint32_t k = 1; k <= p->terms; k++) {
        /* a_k / rms <= sqrt(2), so c < 2^31 and c * sin30 < 2^62 */
        int64_t c = ((amplitude(k, p->beta) << 15) + rms15 / 2) / rms15;
        fx_angle ang = (fx_angle)fx_rand32(&st);
        /* The phase advances by exactly k * 2^32 / m per sample: the whole
         * part q every step, plus one whenever the remainders f add up to
         * m, so sample m returns to the phase of sample 0 bit for bit. */
        uint64_t turn = (uint64_t)k << 32;
        fx_angle q = (fx_angle)(turn / m);
        uint32_t f = (uint32_t)(turn % m), fr = 0;
        for (int32_t i = 0; i < n; i++) {
            h[i] += (fx16)((c * fx_sin30(ang) + ((int64_t)1 << 43)) >> 44);
            ang += q;
            fr += f;
            if (fr >= m) {
                fr -= m;
                ang++;
            }
        }
    }
    fx16 h0 = h[0];
    for (int32_t i = 0; i < n; i++)
        h[i] -= h0;
    return 0;
}

/* d * i / m in Q16.16 (truncated), d within +-2^32, 0 <= i <= m < 2^20. */
static int64_t lerp16(int64_t d, int32_t i, int32_t m)
{
    int64_t v = d * i;
    return v / m * 65536 + v % m * 65536 / m;
}

static int32_t round_px(int64_t v16)
{
    int64_t v = (v16 + 32768) >> 16;
    return v > INT32_MAX ? INT32_MAX : v < INT32_MIN ? INT32_MIN : (int32_t)v;
}

int32_t fx_fbm_draw(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const fx16 *h, int32_t n,
                    fx16 sd)
{
    if (!c || !h || n < 2 || n > FX_FBM_MAX_SAMPLES || sd < 0 || sd > FX16_ONE)
        return -FX_EINVAL;
    int64_t dx = (int64_t)x1 - x0, dy = (int64_t)y1 - y0;
    int32_t px = 0, py = 0;
    for (int32_t i = 0; i < n; i++) {
        /* |h| < 2^24 and sd <= 2^16 in Q16.16: hs < 2^40 in Q32, and
         * |d * hs| < 2^72 is taken down to Q16.16 by the wide multiply */
        int64_t hs = (int64_t)h[i] * sd;
        int64_t x = (int64_t)x0 * 65536 + lerp16(dx, i, n - 1) + fx_mul64_shift(-dy, hs, 16);
        int64_t y = (int64_t)y0 * 65536 + lerp16(dy, i, n - 1) + fx_mul64_shift(dx, hs, 16);
        int32_t qx = round_px(x), qy = round_px(y);
        if (i > 0)
            fx_line(c, px, py, qx, qy);
        px = qx;
        py = qy;
    }
    return n - 1;
}

int32_t fx_fbm_spectral(const fx_ctx *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const fx_fbm_params *p,
                        fx16 *work, int32_t n)
{
    if (!c || !p || p->sd < 0 || p->sd > FX16_ONE)
        return -FX_EINVAL;
    int r = fx_fbm_heights(work, n, p);
    if (r < 0)
        return r;
    return fx_fbm_draw(c, x0, y0, x1, y1, work, n, p->sd);
}
