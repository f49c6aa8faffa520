/* SPDX-License-Identifier: MIT */
/* fixel — the notes' scan-line Gouraud shading of a convex polygon
 * (contract in fill.h). */
#include "fixel/fill.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"

/* round(n / d) for d > 0, halves away from zero */
static int64_t div_round(int64_t n, int64_t d) { return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d); }

typedef struct xing {
    int64_t x;    /* Q16.16 crossing, for the colours */
    int64_t px;   /* the first pixel centre at or right of the exact crossing */
    int64_t c[4]; /* A, R, G, B at the crossing, Q16.16 */
} xing;

static int64_t chan(fx_color c, int k) { return (int64_t)((c >> (24 - 8 * k)) & 255) << 16; }

int fx_fill_poly_gouraud_scan(const fx_ctx *c, const int32_t *xy, const fx_color *col, int32_t n)
{
    if (!c || !xy || !col || n < 3 || n > FX_GOURAUD_SCAN_MAX)
        return -FX_EINVAL;
    int32_t ymin = INT32_MAX, ymax = INT32_MIN;
    for (int32_t i = 0; i < n; i++) {
        if (xy[2 * i] < -FX_GOURAUD_SCAN_COORD || xy[2 * i] > FX_GOURAUD_SCAN_COORD ||
            xy[2 * i + 1] < -FX_GOURAUD_SCAN_COORD || xy[2 * i + 1] > FX_GOURAUD_SCAN_COORD)
            return -FX_EINVAL;
        ymin = FX_MIN(ymin, xy[2 * i + 1]);
        ymax = FX_MAX(ymax, xy[2 * i + 1]);
    }
    /* rows the clip shows only: the work is bounded by what is visible */
    int32_t y0 = FX_MAX(ymin, c->clip.y0), y1 = FX_MIN(ymax, c->clip.y1); /* rows y0 <= y < y1 */
    fx_ctx cc = *c;
    for (int32_t y = y0; y < y1; y++) {
        /* along the edges: a crossing and its colour on each edge the row
         * meets (min(ya, yb) <= y < max: fill.h's rule; a convex polygon
         * has two) */
        xing l = {INT64_MAX, 0, {0}}, r = {INT64_MIN, 0, {0}};
        for (int32_t i = 0; i < n; i++) {
            int32_t j = (i + 1) % n;
            int64_t xa = xy[2 * i], ya = xy[2 * i + 1], xb = xy[2 * j], yb = xy[2 * j + 1];
            if (ya == yb || y < FX_MIN(ya, yb) || y >= FX_MAX(ya, yb))
                continue;
            int64_t dy = yb - ya, t = y - ya;
            xing e;
            e.x = xa * 65536 + div_round(t * (xb - xa) * 65536, dy);
            /* ceil of the exact rational crossing xa + t (xb - xa) / dy, as fill.h's rule */
            int64_t num = xa * dy + t * (xb - xa), den = dy;
            if (den < 0)
                num = -num, den = -den;
            e.px = num >= 0 ? (num + den - 1) / den : -((-num) / den);
            for (int k = 0; k < 4; k++)
                e.c[k] = chan(col[i], k) + div_round(t * (chan(col[j], k) - chan(col[i], k)), dy);
            if (e.x < l.x)
                l = e;
            if (e.x > r.x)
                r = e;
        }
        if (l.x > r.x)
            continue;
        /* then across the span: centres with l.x <= x < r.x */
        int64_t xa = l.px, xb = r.px;
        xa = FX_MAX(xa, (int64_t)c->clip.x0);
        xb = FX_MIN(xb, (int64_t)c->clip.x1);
        int64_t w = r.x - l.x;
        for (int64_t x = xa; x < xb; x++) {
            fx_color out = 0;
            for (int k = 0; k < 4; k++) {
                int64_t v = l.c[k] + div_round((r.c[k] - l.c[k]) * (x * 65536 - l.x), w);
                int64_t b = (v + 32768) >> 16;
                out |= (fx_color)(b < 0 ? 0 : b > 255 ? 255 : b) << (24 - 8 * k);
            }
            fx_ctx_set_color(&cc, out);
            fx_plot(&cc, (int32_t)x, y);
        }
    }
    return 0;
}
