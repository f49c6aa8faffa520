/* SPDX-License-Identifier: MIT */
/* fixel — box-counting dimension (contracts in boxdim.h). */
#include "fixel/boxdim.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

fx16 fx_log2_16(uint64_t v)
{
    if (v == 0)
        return 0;
    int e = 63;
    while (!(v >> e))
        e--;
    /* mantissa m in [1, 2) as Q1.62; each squaring yields the next bit of
     * log2 m (m^2 >= 2: bit is 1, halve) */
    uint64_t m = e >= 62 ? v >> (e - 62) : v << (62 - e);
    int32_t frac = 0;
    for (int i = 0; i < 17; i++) {
        uint64_t hi, lo;
        fx_umul64_wide(m, m, &hi, &lo);
        /* m^2 in Q2.124 -> back to Q1.62 (or Q2.62 before halving) */
        uint64_t sq = hi << 2 | lo >> 62;
        frac <<= 1;
        if (sq >= (uint64_t)1 << 63) {
            frac |= 1;
            sq >>= 1;
        }
        m = sq;
    }
    /* 17 bits: round to 16 */
    return (fx16)(e * 65536 + ((frac + 1) >> 1));
}

int32_t fx_boxcount(const fx_surface *s, fx_rect r, uint32_t bg, int32_t box)
{
    if (!s || box < 1)
        return -FX_EINVAL;
    r = fx_rect_intersect(r, fx_surface_rect(s));
    int32_t n = 0;
    for (int64_t by = r.y0; by < r.y1; by += box)
        for (int64_t bx = r.x0; bx < r.x1; bx += box) {
            int32_t y1 = (int32_t)FX_MIN(by + box, (int64_t)r.y1), x1 = (int32_t)FX_MIN(bx + box, (int64_t)r.x1);
            int hit = 0;
            for (int32_t y = (int32_t)by; y < y1 && !hit; y++)
                for (int32_t x = (int32_t)bx; x < x1; x++)
                    if (fx_surface_get_native(s, x, y) != bg) {
                        hit = 1;
                        break;
                    }
            n += hit;
        }
    return n;
}

int fx_boxdim_fit(const int32_t *sizes, const int32_t *counts, int n, fx16 *dim)
{
    if (!sizes || !counts || !dim || n < 2 || n > FX_BOXDIM_MAX_SIZES)
        return -FX_EINVAL;
    /* x = -log2 s, y = log2 N, both Q16.16 under 2^21: the sums of
     * products stay under 2^47 */
    int64_t sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) {
        if (sizes[i] < 1 || counts[i] < 1)
            return -FX_EINVAL;
        int64_t x = -(int64_t)fx_log2_16((uint64_t)sizes[i]), y = fx_log2_16((uint64_t)counts[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    int64_t num = n * sxy - sx * sy, den = n * sxx - sx * sx;
    if (den <= 0)
        return -FX_EINVAL; /* all sizes equal */
    /* |num|, den < 2^52: the 16 fraction bits by long division keep every
     * intermediate under 2^53 */
    int neg = num < 0;
    uint64_t a = (uint64_t)(neg ? -num : num), d = (uint64_t)den;
    uint64_t q = a / d, rem = a % d;
    if (q > ((uint64_t)1 << 30))
        q = (uint64_t)1 << 30; /* saturates below */
    for (int i = 0; i < 17; i++) {
        rem <<= 1;
        q <<= 1;
        if (rem >= d) {
            rem -= d;
            q |= 1;
        }
    }
    q = (q + 1) >> 1; /* 17 bits rounded to 16 */
    int64_t v = neg ? -(int64_t)q : (int64_t)q;
    *dim = fx_sat32(v);
    return 0;
}

int fx_boxdim_surface(const fx_surface *s, fx_rect r, uint32_t bg, int32_t smin, int32_t smax, fx16 *dim,
                      int32_t *counts, int *nsizes)
{
    int32_t sz[FX_BOXDIM_MAX_SIZES], ct[FX_BOXDIM_MAX_SIZES];
    int n = 0;
    if (!s || !dim || smin < 1 || smax < smin)
        return -FX_EINVAL;
    for (int64_t b = smin; b <= smax && n < FX_BOXDIM_MAX_SIZES; b *= 2) {
        sz[n] = (int32_t)b;
        ct[n] = fx_boxcount(s, r, bg, (int32_t)b);
        if (ct[n] < 1)
            return -FX_EINVAL; /* an empty picture has no dimension */
        n++;
    }
    if (counts)
        for (int i = 0; i < n; i++)
            counts[i] = ct[i];
    if (nsizes)
        *nsizes = n;
    return fx_boxdim_fit(sz, ct, n, dim);
}
