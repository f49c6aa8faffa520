/* SPDX-License-Identifier: MIT */
/* fixel — the A-buffer.
 *
 * Each polygon leaves, in every pixel it touches, a fragment: its 4 x 4
 * coverage mask (samples at offsets (2i - 3) / 8 of a pixel from the
 * centre, i = 0..3, the pixel rule applied to each) and its depth at the
 * pixel centre. A pixel's fragments are kept in a list sorted front to
 * back (the z-buffer's order: exact depth, then table order); a fragment
 * behind one that covers the whole pixel is never stored. Resolving walks
 * the list: each fragment adds its colour weighted by the samples it
 * covers that nothing nearer did; the background takes the samples left.
 * A pixel whose fragments all cover it whole therefore gets exactly the
 * z-buffer's colour; partly covered (edge) pixels get the blend. */
#include "vsd_int.h"

typedef struct abuf {
    int32_t *head;
    int32_t *poly, *mask, *next; /* the fragment pool */
    int32_t cap, used, freel;
} abuf;

static int sample_in(const fx_vsd_scene *s, int32_t p, int64_t x8, int64_t y8)
{
    const fx_vsd_poly *P = &s->poly[p];
    for (int32_t i = 0; i < P->nedges; i++) {
        const fx_vsd_edge *e = &s->edge[P->first_edge + i];
        int64_t v = e->ea * x8 + e->eb * y8 + e->ec * 8;
        if (v < 0 || (v == 0 && !e->incl))
            return 0;
    }
    return 1;
}

static int32_t coverage(const fx_vsd_scene *s, int32_t p, int32_t x, int32_t y)
{
    int32_t m = 0;
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            if (sample_in(s, p, (int64_t)x * 8 + 2 * i - 3, (int64_t)y * 8 + 2 * j - 3))
                m |= 1 << (j * 4 + i);
    return m;
}

static int insert(const fx_vsd_scene *s, abuf *a, int32_t p, int32_t m, int32_t x, int32_t y)
{
    int32_t *link = &a->head[(size_t)y * (size_t)s->w + (size_t)x];
    while (*link >= 0 && fx_vsd_beats(s, a->poly[*link], p, x, y)) {
        if (a->mask[*link] == 0xFFFF)
            return 0; /* hidden whole */
        link = &a->next[*link];
    }
    int32_t f;
    if (a->freel >= 0) {
        f = a->freel;
        a->freel = a->next[f];
    } else {
        if (a->used >= a->cap)
            return -FX_ENOSPC;
        f = a->used++;
    }
    a->poly[f] = p;
    a->mask[f] = m;
    a->next[f] = *link;
    *link = f;
    if (m == 0xFFFF) { /* what is behind it can never show: recycle it */
        int32_t r = a->next[f];
        a->next[f] = -1;
        while (r >= 0) {
            int32_t nx = a->next[r];
            a->next[r] = a->freel;
            a->freel = r;
            r = nx;
        }
    }
    return 0;
}

static int popcount16(int32_t m)
{
    int n = 0;
    for (; m; m &= m - 1)
        n++;
    return n;
}

int fx_vsd_abuffer(const fx_vsd_scene *s, const fx_surface *dst, int32_t ox, int32_t oy, void *work,
                   size_t bytes, int32_t *edge_px)
{
    if (!s || !dst || !work || ((uintptr_t)work & 7))
        return -FX_EINVAL;
    size_t npx = (size_t)s->w * (size_t)s->h;
    if (bytes < npx * sizeof(int32_t) + 3 * sizeof(int32_t) + 16)
        return -FX_ENOSPC;
    abuf a;
    a.head = work;
    a.cap = (int32_t)(((bytes - 16) / sizeof(int32_t) - npx) / 3 > INT32_MAX / 4
                          ? INT32_MAX / 4
                          : ((bytes - 16) / sizeof(int32_t) - npx) / 3);
    a.poly = a.head + npx;
    a.mask = a.poly + a.cap;
    a.next = a.mask + a.cap;
    a.used = 0;
    a.freel = -1;
    for (size_t i = 0; i < npx; i++)
        a.head[i] = -1;
    for (int32_t p = 0; p < s->npoly; p++) {
        const fx_vsd_poly *P = &s->poly[p];
        /* samples reach 3/8 pixel beyond the centres: one pixel more each way */
        int32_t x0 = P->xmin - 1 < 0 ? 0 : P->xmin - 1, x1 = P->xmax + 2 > s->w ? s->w : P->xmax + 2;
        int32_t y0 = P->ymin - 1 < 0 ? 0 : P->ymin - 1, y1 = P->ymax + 2 > s->h ? s->h : P->ymax + 2;
        for (int32_t y = y0; y < y1; y++)
            for (int32_t x = x0; x < x1; x++) {
                int32_t m = coverage(s, p, x, y);
                if (m) {
                    int e = insert(s, &a, p, m, x, y);
                    if (e < 0)
                        return e;
                }
            }
    }
    int32_t edges = 0;
    fx_color bg = s->background;
    for (int32_t y = 0; y < s->h; y++)
        for (int32_t x = 0; x < s->w; x++) {
            int32_t cov = 0, partial = 0;
            int32_t r = 0, g = 0, b = 0;
            for (int32_t f = a.head[(size_t)y * (size_t)s->w + (size_t)x]; f >= 0; f = a.next[f]) {
                int32_t vis = a.mask[f] & ~cov, k = popcount16(vis);
                fx_color col = s->poly[a.poly[f]].color;
                partial |= a.mask[f] != 0xFFFF;
                r += (int32_t)((col >> 16) & 255) * k;
                g += (int32_t)((col >> 8) & 255) * k;
                b += (int32_t)(col & 255) * k;
                cov |= a.mask[f];
                if (cov == 0xFFFF)
                    break;
            }
            int32_t k = 16 - popcount16(cov);
            r += (int32_t)((bg >> 16) & 255) * k;
            g += (int32_t)((bg >> 8) & 255) * k;
            b += (int32_t)(bg & 255) * k;
            edges += partial;
            fx_color out = 0xFF000000u | (fx_color)((r + 8) / 16) << 16 |
                           (fx_color)((g + 8) / 16) << 8 | (fx_color)((b + 8) / 16);
            int64_t dx = (int64_t)ox + x, dy = (int64_t)oy + y;
            if (dx >= 0 && dy >= 0 && dx < dst->w && dy < dst->h)
                fx_surface_put(dst, (int32_t)dx, (int32_t)dy, out);
        }
    if (edge_px)
        *edge_px = edges;
    return 0;
}
