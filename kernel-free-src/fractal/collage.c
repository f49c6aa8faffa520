/* SPDX-License-Identifier: MIT */
/* fixel — collage search and fractal image compression (contracts in
 * collage.h). */
#include "fixel/collage.h"
#include "fixel/boxdim.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

static int collage_ok(const uint8_t *t, int32_t w, int32_t h, const uint8_t *work)
{
    return t && work && w >= 12 && h >= 12 && w <= FX_COLLAGE_MAX_SIDE && h <= FX_COLLAGE_MAX_SIDE && w % 12 == 0 &&
           h % 12 == 0;
}

/* M(T) of a map with ratio 1/den lights pixel offset + floor(x / den): the
 * OR of each den_x x den_y block of T, at the map's offset. */
static inline int image_at(const uint8_t *t, int32_t w, int dx, int dy, int32_t i, int32_t j)
{
    for (int b = 0; b < dy; b++)
        for (int a = 0; a < dx; a++)
            if (t[(j * dy + b) * w + i * dx + a])
                return 1;
    return 0;
}

/* Mark (mark = 1) or score against the collage in work: +1 for a target
 * pixel newly covered, -4 for a new pixel outside the target. */
static int32_t apply(const uint8_t *t, int32_t w, int32_t h, fx_collage_map m, uint8_t *work, int mark)
{
    int32_t bw = w / m.ax_den, bh = h / m.ay_den, ox = m.ex * w / 12, oy = m.ey * h / 12, score = 0;
    for (int32_t j = 0; j < bh; j++)
        for (int32_t i = 0; i < bw; i++) {
            uint8_t *c = &work[(oy + j) * w + ox + i];
            if (*c || !image_at(t, w, m.ax_den, m.ay_den, i, j))
                continue;
            if (mark)
                *c = 1;
            else
                score += t[(oy + j) * w + ox + i] ? 1 : -4;
        }
    return score;
}

static void tally(const uint8_t *t, int32_t w, int32_t h, const uint8_t *work, fx_collage_result *res)
{
    res->target = res->missed = res->extra = 0;
    for (int32_t k = 0; k < w * h; k++) {
        res->target += t[k] != 0;
        res->missed += t[k] && !work[k];
        res->extra += !t[k] && work[k];
    }
}

int fx_collage_search(const uint8_t *target, int32_t w, int32_t h, int maxmaps, uint8_t *work,
                      fx_collage_result *res)
{
    if (!collage_ok(target, w, h, work) || !res || maxmaps < 1 || maxmaps > FX_IFS_MAX_MAPS)
        return -FX_EINVAL;
    fx_memset(work, 0, (size_t)w * h);
    res->n = 0;
    while (res->n < maxmaps) {
        fx_collage_map best = {0, 0, 0, 0};
        int32_t bs = 0;
        for (int dy = 2; dy <= 4; dy++)
            for (int dx = 2; dx <= 4; dx++)
                for (int ey = 0; ey <= 12 - 12 / dy; ey++)
                    for (int ex = 0; ex <= 12 - 12 / dx; ex++) {
                        fx_collage_map m = {(uint8_t)dx, (uint8_t)dy, (uint8_t)ex, (uint8_t)ey};
                        int32_t s = apply(target, w, h, m, work, 0);
                        if (s > bs) {
                            bs = s;
                            best = m;
                        }
                    }
        if (bs <= 0)
            break;
        apply(target, w, h, best, work, 1);
        res->maps[res->n++] = best;
    }
    tally(target, w, h, work, res);
    return res->n;
}

int32_t fx_collage_distance(const uint8_t *target, int32_t w, int32_t h, const fx_collage_map *maps, int n,
                            uint8_t *work, fx_collage_result *res)
{
    if (!collage_ok(target, w, h, work) || !res || n < 0 || n > FX_IFS_MAX_MAPS || (n && !maps))
        return -FX_EINVAL;
    for (int i = 0; i < n; i++)
        if (maps[i].ax_den < 2 || maps[i].ax_den > 4 || maps[i].ay_den < 2 || maps[i].ay_den > 4 ||
            maps[i].ex > 12 - 12 / maps[i].ax_den || maps[i].ey > 12 - 12 / maps[i].ay_den)
            return -FX_EINVAL;
    fx_memset(work, 0, (size_t)w * h);
    for (int i = 0; i < n; i++)
        apply(target, w, h, maps[i], work, 1);
    tally(target, w, h, work, res);
    res->n = n;
    for (int i = 0; i < n; i++)
        res->maps[i] = maps[i];
    return res->missed + res->extra;
}

void fx_collage_to_ifs(const fx_collage_map *maps, int n, fx_ifs_map *out, fx_ifs *ifs)
{
    int64_t area = 0;
    for (int i = 0; i < n; i++)
        area += 65536 / (maps[i].ax_den * maps[i].ay_den);
    int32_t left = 65536;
    for (int i = 0; i < n; i++) {
        /* picture (u, v) with v down -> world (X, Y) with Y = 1 - v:
         * Y' = d Y + (1 - d - f) */
        fx16 a = 65536 / maps[i].ax_den, d = 65536 / maps[i].ay_den;
        fx16 e = maps[i].ex * 65536 / 12, f = maps[i].ey * 65536 / 12;
        fx16 p = i == n - 1 ? left : (fx16)(65536 / (maps[i].ax_den * maps[i].ay_den) * 65536 / area);
        left -= p;
        fx_ifs_map m = {a, 0, 0, d, e, 65536 - d - f, p};
        out[i] = m;
    }
    ifs->maps = out;
    ifs->n = n;
    ifs->wx0 = 0;
    ifs->wy0 = 0;
    ifs->wx1 = 65536;
    ifs->wy1 = 65536;
}

/* ---- fractal image compression ---- */

/* the 8 symmetries of a 4 x 4 block: out[y * 4 + x] = in[perm[k][y * 4 + x]] */
/* (k & 3) quarter turns, after a left-right mirror for k >= 4 */
static const uint8_t perm[8][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {12, 8, 4, 0, 13, 9, 5, 1, 14, 10, 6, 2, 15, 11, 7, 3},
    {15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0},
    {3, 7, 11, 15, 2, 6, 10, 14, 1, 5, 9, 13, 0, 4, 8, 12},
    {3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12},
    {0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15},
    {12, 13, 14, 15, 8, 9, 10, 11, 4, 5, 6, 7, 0, 1, 2, 3},
    {15, 11, 7, 3, 14, 10, 6, 2, 13, 9, 5, 1, 12, 8, 4, 0},
};

/* The domain block at (dx, dy) of img (n wide), averaged 2 x 2 down to 4 x 4. */
static void shrink(const uint8_t *img, int32_t n, int32_t dx, int32_t dy, int32_t d[16])
{
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            const uint8_t *p = img + (dy + 2 * y) * n + dx + 2 * x;
            d[y * 4 + x] = (p[0] + p[1] + p[n] + p[n + 1] + 2) >> 2;
        }
}

int fx_fic_encode(const uint8_t *img, int32_t n, fx_fic_code *codes)
{
    if (!img || !codes || n < 8 || n > FX_FIC_MAX_SIDE || n % 8)
        return -FX_EINVAL;
    int32_t nr = n / 4;
    for (int32_t ry = 0; ry < nr; ry++)
        for (int32_t rx = 0; rx < nr; rx++) {
            int32_t r[16], sr = 0;
            for (int y = 0; y < 4; y++)
                for (int x = 0; x < 4; x++) {
                    r[y * 4 + x] = img[(4 * ry + y) * n + 4 * rx + x];
                    sr += r[y * 4 + x];
                }
            fx_fic_code best = {0, 0, 0, 0, (int16_t)((sr + 8) / 16)};
            int64_t berr = INT64_MAX;
            for (int32_t dy = 0; dy + 8 <= n && berr; dy += 4)
                for (int32_t dx = 0; dx + 8 <= n && berr; dx += 4) {
                    int32_t d[16], sd = 0, sdd = 0;
                    shrink(img, n, dx, dy, d);
                    for (int i = 0; i < 16; i++) {
                        sd += d[i];
                        sdd += d[i] * d[i];
                    }
                    int64_t den = 16 * (int64_t)sdd - (int64_t)sd * sd;
                    for (int k = 0; k < 8; k++) {
                        int32_t sdr = 0;
                        for (int i = 0; i < 16; i++)
                            sdr += d[perm[k][i]] * r[i];
                        /* least squares s = (16 sdr - sd sr) / den, in
                         * sixteenths rounded, |s| <= 15/16 keeps decoding
                         * contractive; then o for that s */
                        int64_t num = 16 * ((int64_t)16 * sdr - (int64_t)sd * sr);
                        int32_t sq = 0;
                        if (den > 0) {
                            int64_t q = (num >= 0 ? num + den / 2 : num - den / 2) / den;
                            sq = (int32_t)(q > 15 ? 15 : q < -15 ? -15 : q);
                        }
                        int32_t onum = 16 * sr - sq * sd; /* o = onum / 256 */
                        int32_t oq = onum >= 0 ? (onum + 128) / 256 : -((-onum + 128) / 256);
                        if (oq > 1023)
                            oq = 1023;
                        if (oq < -1023)
                            oq = -1023;
                        int64_t err = 0;
                        for (int i = 0; i < 16; i++) {
                            int64_t e = (int64_t)sq * d[perm[k][i]] + 16 * oq - 16 * r[i];
                            err += e * e;
                        }
                        if (err < berr) {
                            berr = err;
                            best.dx = (uint16_t)dx;
                            best.dy = (uint16_t)dy;
                            best.iso = (uint8_t)k;
                            best.s = (int8_t)sq;
                            best.o = (int16_t)oq;
                        }
                    }
                }
            codes[ry * nr + rx] = best;
        }
    return 0;
}

int fx_fic_decode(const fx_fic_code *codes, int32_t n, uint32_t iters, uint8_t *out, uint8_t *tmp)
{
    if (!codes || !out || !tmp || n < 8 || n > FX_FIC_MAX_SIDE || n % 8 || iters > 1000)
        return -FX_EINVAL;
    int32_t nr = n / 4;
    for (int32_t i = 0; i < nr * nr; i++)
        if (codes[i].dx + 8 > n || codes[i].dy + 8 > n || codes[i].dx % 4 || codes[i].dy % 4 || codes[i].iso > 7 ||
            codes[i].s < -15 || codes[i].s > 15)
            return -FX_EINVAL;
    fx_memset(out, 128, (size_t)n * n);
    uint8_t *cur = out, *nxt = tmp;
    for (uint32_t it = 0; it < iters; it++) {
        for (int32_t ry = 0; ry < nr; ry++)
            for (int32_t rx = 0; rx < nr; rx++) {
                const fx_fic_code *c = &codes[ry * nr + rx];
                int32_t d[16];
                shrink(cur, n, c->dx, c->dy, d);
                for (int i = 0; i < 16; i++) {
                    int32_t v = (c->s * d[perm[c->iso][i]] + 16 * c->o + 8) >> 4;
                    nxt[(4 * ry + i / 4) * n + 4 * rx + i % 4] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
                }
            }
        uint8_t *t = cur;
        cur = nxt;
        nxt = t;
    }
    if (cur != out)
        fx_memcpy(out, cur, (size_t)n * n);
    return 0;
}

fx16 fx_psnr(const uint8_t *a, const uint8_t *b, int32_t count)
{
    if (!a || !b || count < 1)
        return 0;
    uint64_t sse = 0;
    for (int32_t i = 0; i < count; i++) {
        int32_t e = (int32_t)a[i] - b[i];
        sse += (uint64_t)(e * e);
    }
    if (sse == 0)
        return INT32_MAX;
    /* log2 MSE = log2(sse 2^16 / count) - 16; sse < 2^16 count, so
     * sse << 16 < 2^63 for any int32 count */
    uint64_t mse16 = (sse << 16) / (uint64_t)count;
    if (mse16 == 0)
        mse16 = 1;
    int64_t l = (int64_t)fx_log2_16(65025) - ((int64_t)fx_log2_16(mse16) - (16 << 16));
    return (fx16)((l * 197283 + 32768) >> 16); /* 10 / log2(10) = 3.0103 in Q16.16 */
}
