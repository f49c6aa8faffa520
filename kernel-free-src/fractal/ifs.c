/* SPDX-License-Identifier: MIT */
/* fixel — iterated function systems (contracts in ifs.h). */
#include "fixel/ifs.h"
#include "fixel/error.h"
#include "fixel/koch.h"
#include "fixel/line.h"
#include "../base/fx_internal.h"

/* Coefficients: the published decimals rounded to Q16.16. */
static const fx_ifs_map sierpinski_maps[3] = {
    {32768, 0, 0, 32768, 0, 0, 21845},
    {32768, 0, 0, 32768, 32768, 0, 21845},
    {32768, 0, 0, 32768, 16384, 32768, 21846},
};
const fx_ifs fx_ifs_sierpinski = {sierpinski_maps, 3, 0, 0, 65536, 65536};

/* Barnsley: f1 (stem) 0 0 0 .16 0 0 p .01; f2 .85 .04 -.04 .85 0 1.6 p .85;
 * f3 .2 -.26 .23 .22 0 1.6 p .07; f4 -.15 .28 .26 .24 0 .44 p .07. */
static const fx_ifs_map fern_maps[4] = {
    {0, 0, 0, 10486, 0, 0, 655},
    {55706, 2621, -2621, 55706, 0, 104858, 55706},
    {13107, -17039, 15073, 14418, 0, 104858, 4588},
    {-9830, 18350, 17039, 15729, 0, 28836, 4587},
};
const fx_ifs fx_ifs_fern = {fern_maps, 4, -157286 /* -2.4 */, 0, 176947 /* 2.7 */, 655360 /* 10 */};

int fx_ifs_check(const fx_ifs *s)
{
    if (!s || !s->maps || s->n < 1 || s->n > FX_IFS_MAX_MAPS || s->wx1 <= s->wx0 ||
        s->wy1 <= s->wy0 || (int64_t)s->wx1 - s->wx0 > ((int64_t)1 << 30) ||
        (int64_t)s->wy1 - s->wy0 > ((int64_t)1 << 30))
        return -FX_EINVAL;
    int64_t sum = 0;
    for (int i = 0; i < s->n; i++) {
        if (s->maps[i].p < 0)
            return -FX_EINVAL;
        sum += s->maps[i].p;
    }
    return sum >= 65536 - s->n && sum <= 65536 + s->n ? 0 : -FX_EINVAL;
}

static int64_t floor_div(int64_t a, int64_t b)
{
    int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

/* x, y in Q32.32 world units. floor((x - wx0) dw / ww) is split as
 * u q + floor(u r / ww) with dw = q ww + r, which keeps every product within
 * 64 bits for windows under 2^14 units and any int32 rectangle. Points more
 * than a window away from the window are off the rectangle: they get a far
 * point instead of an overflow. */
static void to_pixel(const fx_ifs *s, fx_rect d, int64_t x, int64_t y, int32_t *px, int32_t *py)
{
    int64_t ww = (int64_t)s->wx1 - s->wx0, wh = (int64_t)s->wy1 - s->wy0;
    int64_t dw = (int64_t)d.x1 - d.x0, dh = (int64_t)d.y1 - d.y0;
    int64_t ux = (x >> 16) - s->wx0, uy = (y >> 16) - s->wy0;
    if (ux < -ww || ux > 2 * ww || uy < -wh || uy > 2 * wh) {
        *px = INT32_MIN;
        *py = INT32_MIN;
        return;
    }
    int64_t qx = dw / ww, rx = dw % ww, qy = dh / wh, ry = dh % wh;
    *px = fx_sat32((int64_t)d.x0 + ux * qx + floor_div(ux * rx, ww));
    *py = fx_sat32((int64_t)d.y1 - 1 - (uy * qy + floor_div(uy * ry, wh)));
}

void fx_ifs_to_pixel(const fx_ifs *s, fx_rect dest, int64_t x, int64_t y, int32_t *px,
                     int32_t *py)
{
    to_pixel(s, dest, x * 65536, y * 65536, px, py);
}

int32_t fx_ifs_chaos(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t npoints,
                     uint32_t seed)
{
    if (fx_ifs_check(s) < 0 || fx_rect_empty(dest))
        return -FX_EINVAL;
    uint32_t cum[FX_IFS_MAX_MAPS];
    uint32_t acc = 0;
    for (int i = 0; i < s->n; i++) {
        acc += (uint32_t)s->maps[i].p;
        cum[i] = acc;
    }
    cum[s->n - 1] = 65536; /* absorb rounding of the probabilities */
    fx_ctx cc = *c;
    cc.clip = fx_rect_intersect(c->clip, dest);
    uint32_t st = seed;
    int64_t x = 0, y = 0; /* Q32.32 */
    int32_t inside = 0;
    for (uint32_t k = 0; k < npoints + 20; k++) {
        uint32_t r = fx_rand32(&st) >> 16;
        int i = 0;
        while (r >= cum[i])
            i++;
        const fx_ifs_map *m = &s->maps[i];
        int64_t nx = ((m->a * x + m->b * y) >> 16) + ((int64_t)m->e * 65536);
        int64_t ny = ((m->c * x + m->d * y) >> 16) + ((int64_t)m->f * 65536);
        x = nx;
        y = ny;
        if (k < 20)
            continue;
        int32_t px, py;
        to_pixel(s, dest, x, y, &px, &py);
        if (px >= cc.clip.x0 && px < cc.clip.x1 && py >= cc.clip.y0 && py < cc.clip.y1) {
            fx_plot(&cc, px, py);
            inside++;
        }
    }
    return inside;
}

typedef struct aff {
    int64_t a, b, c, d, e, f; /* Q16.16 linear part, Q32.32 translation */
} aff;

static int32_t copier_rec(const fx_ctx *c, fx_rect dest, const fx_ifs *s, aff m, uint32_t depth)
{
    if (depth == 0) {
        const int64_t wx[4] = {s->wx0, s->wx1, s->wx1, s->wx0}, wy[4] = {s->wy0, s->wy0, s->wy1, s->wy1};
        int32_t px[4], py[4];
        for (int i = 0; i < 4; i++) {
            int64_t x = m.a * wx[i] + m.b * wy[i] + m.e; /* Q32.32 */
            int64_t y = m.c * wx[i] + m.d * wy[i] + m.f;
            to_pixel(s, dest, x, y, &px[i], &py[i]);
        }
        for (int i = 0; i < 4; i++)
            fx_line(c, px[i], py[i], px[(i + 1) % 4], py[(i + 1) % 4]);
        return 1;
    }
    int32_t n = 0;
    for (int i = 0; i < s->n; i++) {
        const fx_ifs_map *q = &s->maps[i];
        /* m o q: linear parts multiply, q's translation goes through m */
        aff r;
        r.a = (m.a * q->a + m.b * q->c + 0x8000) >> 16;
        r.b = (m.a * q->b + m.b * q->d + 0x8000) >> 16;
        r.c = (m.c * q->a + m.d * q->c + 0x8000) >> 16;
        r.d = (m.c * q->b + m.d * q->d + 0x8000) >> 16;
        r.e = m.a * q->e + m.b * q->f + m.e;
        r.f = m.c * q->e + m.d * q->f + m.f;
        n += copier_rec(c, dest, s, r, depth - 1);
    }
    return n;
}

int32_t fx_ifs_copier(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t depth)
{
    if (fx_ifs_check(s) < 0 || fx_rect_empty(dest))
        return -FX_EINVAL;
    uint64_t total = 1;
    for (uint32_t i = 0; i < depth; i++) {
        total *= (uint64_t)s->n;
        if (total > (1u << 20))
            return -FX_EINVAL;
    }
    fx_ctx cc = *c;
    cc.clip = fx_rect_intersect(c->clip, dest);
    aff id = {65536, 0, 0, 65536, 0, 0};
    return copier_rec(&cc, dest, s, id, depth);
}

/* ---- the copier from any picture (issue #44) ---- */

typedef struct pic_job {
    const fx_ctx *c;
    fx_rect dest;
    const fx_ifs *s;
    const fx_ifs_pixel *px;
    uint32_t n;
} pic_job;

static int32_t picture_rec(const pic_job *j, aff m, uint32_t depth)
{
    if (depth == 0) {
        fx_ctx cc = *j->c;
        for (uint32_t i = 0; i < j->n; i++) {
            int64_t x = m.a * j->px[i].x + m.b * j->px[i].y + m.e; /* Q32.32 */
            int64_t y = m.c * j->px[i].x + m.d * j->px[i].y + m.f;
            int32_t px, py;
            to_pixel(j->s, j->dest, x, y, &px, &py);
            fx_ctx_set_color(&cc, j->px[i].color);
            fx_plot(&cc, px, py);
        }
        return 1;
    }
    int32_t n = 0;
    for (int i = 0; i < j->s->n; i++) {
        const fx_ifs_map *q = &j->s->maps[i];
        aff r;
        r.a = (m.a * q->a + m.b * q->c + 0x8000) >> 16;
        r.b = (m.a * q->b + m.b * q->d + 0x8000) >> 16;
        r.c = (m.c * q->a + m.d * q->c + 0x8000) >> 16;
        r.d = (m.c * q->b + m.d * q->d + 0x8000) >> 16;
        r.e = m.a * q->e + m.b * q->f + m.e;
        r.f = m.c * q->e + m.d * q->f + m.f;
        n += picture_rec(j, r, depth - 1);
    }
    return n;
}

int32_t fx_ifs_copier_picture(const fx_ctx *c, fx_rect dest, const fx_ifs *s, uint32_t depth, fx_color bg,
                              fx_ifs_pixel *work, uint32_t cap)
{
    if (!c || fx_ifs_check(s) < 0 || fx_rect_empty(dest) || (!work && cap))
        return -FX_EINVAL;
    fx_rect r = fx_rect_intersect(dest, fx_rect_intersect(c->clip, fx_surface_rect(&c->surf)));
    /* the picture: every pixel of dest not in bg, as the world point at its
     * centre (the inverse of to_pixel) */
    int64_t ww = (int64_t)s->wx1 - s->wx0, wh = (int64_t)s->wy1 - s->wy0;
    int64_t dw = (int64_t)dest.x1 - dest.x0, dh = (int64_t)dest.y1 - dest.y0;
    uint32_t n = 0;
    fx_color key = fx_unpack(c->surf.format, fx_pack(c->surf.format, bg));
    for (int32_t y = r.y0; y < r.y1; y++)
        for (int32_t x = r.x0; x < r.x1; x++) {
            fx_color p = fx_surface_get(&c->surf, x, y);
            if ((p & 0xFFFFFFu) == (key & 0xFFFFFFu))
                continue;
            if (n == cap)
                return -FX_ENOSPC;
            work[n].x = fx_sat32(s->wx0 + ((2 * ((int64_t)x - dest.x0) + 1) * ww) / (2 * dw));
            work[n].y = fx_sat32(s->wy0 + ((2 * ((int64_t)dest.y1 - 1 - y) + 1) * wh) / (2 * dh));
            work[n].color = p | 0xFF000000u;
            n++;
        }
    uint64_t total = n;
    for (uint32_t i = 0; i < depth; i++) {
        total *= (uint64_t)s->n;
        if (total > FX_IFS_PICTURE_WORK)
            return -FX_E2BIG;
    }
    /* the machine's output replaces its input */
    fx_ctx cc = *c;
    cc.clip = r;
    fx_ctx_set_color(&cc, bg | 0xFF000000u);
    fx_fill_rect(&cc, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
    pic_job j = {&cc, dest, s, work, n};
    aff id = {65536, 0, 0, 65536, 0, 0};
    picture_rec(&j, id, depth);
    return (int32_t)n;
}
