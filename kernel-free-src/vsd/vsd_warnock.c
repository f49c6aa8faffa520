/* SPDX-License-Identifier: MIT */
/* fixel — area subdivision (Warnock).
 *
 * A region (a rectangle of pixels) sorts the polygons it was handed into
 * the course's four kinds, judged on the pixel centres: disjoint (outside
 * its box, or wholly on the outer side of one of its edges: dropped),
 * surrounding (every edge passes all four corner centres: a convex polygon
 * then covers every centre), contained and intersecting (the rest). The
 * region is settled when nothing is left (background), when one polygon
 * is left (its own pixels), or when a surrounding polygon is nearest at
 * all four corners against every other polygon's plane (depth differences
 * are linear, so it is nearest everywhere). Otherwise it splits into four
 * quadrants, down to single pixels, decided at their centre. */
#include "vsd_int.h"

enum { W_DISJOINT, W_SURROUNDING, W_CONTAINED, W_INTERSECTING };

typedef struct wk {
    const fx_vsd_scene *s;
    int32_t *ids;
    int32_t *mem, cap; /* list stack */
    const fx_ctx *c;
    fx_vsd_stats *st;
} wk;

size_t fx_vsd_warnock_bytes(const fx_vsd_scene *s)
{
    /* one list per level; a level at least halves the longer side */
    int32_t levels = 2;
    for (int32_t m = s->w > s->h ? s->w : s->h; m > 1; m = (m + 1) / 2)
        levels += 2;
    return (size_t)levels * ((size_t)s->npoly + 1) * sizeof(int32_t) + 16;
}

static int classify(const fx_vsd_scene *s, int32_t p, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    const fx_vsd_poly *P = &s->poly[p];
    if (x1 - 1 < P->xmin || x0 > P->xmax || y1 - 1 < P->ymin || y0 > P->ymax)
        return W_DISJOINT;
    int all = 1;
    for (int32_t i = 0; i < P->nedges; i++) {
        const fx_vsd_edge *e = &s->edge[P->first_edge + i];
        int in = 0;
        int32_t cx[4] = {x0, x1 - 1, x0, x1 - 1}, cy[4] = {y0, y0, y1 - 1, y1 - 1};
        for (int k = 0; k < 4; k++) {
            int64_t v = e->ea * cx[k] + e->eb * cy[k] + e->ec;
            in += v > 0 || (v == 0 && e->incl);
        }
        if (in == 0)
            return W_DISJOINT;
        if (in < 4)
            all = 0;
    }
    if (all)
        return W_SURROUNDING;
    if (P->xmin >= x0 && P->xmax < x1 && P->ymin >= y0 && P->ymax < y1)
        return W_CONTAINED;
    return W_INTERSECTING;
}

static void fill_poly(wk *k, int32_t p, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
    for (int32_t y = y0; y < y1; y++) {
        int32_t lo, hi;
        fx_vsd_poly_span(k->s, p, y, &lo, &hi);
        if (lo < x0) lo = x0;
        if (hi > x1) hi = x1;
        for (int32_t x = lo; x < hi; x++)
            k->ids[(size_t)y * (size_t)k->s->w + (size_t)x] = p;
    }
}

static const char *const kind_name[] = {"disjoint", "surrounding", "contained", "intersecting"};

static int region(wk *k, const int32_t *list, int32_t n, int32_t x0, int32_t y0, int32_t x1, int32_t y1,
                  int32_t *top)
{
    const fx_vsd_scene *s = k->s;
    k->st->regions++;
    if (*top + n + 1 > k->cap)
        return -FX_ENOSPC;
    int32_t *mine = k->mem + *top, m = 0, nsur = 0, lastkind = W_DISJOINT;
    for (int32_t i = 0; i < n; i++) {
        int kind = classify(s, list[i], x0, y0, x1, y1);
        if (kind == W_DISJOINT)
            continue;
        mine[m++] = list[i];
        nsur += kind == W_SURROUNDING;
        lastkind = kind;
    }
    const char *how;
    int32_t shown = -1;
    if (m == 0) {
        how = "empty";
    } else if (m == 1) {
        how = kind_name[lastkind];
        shown = mine[0];
        fill_poly(k, mine[0], x0, y0, x1, y1);
    } else {
        how = 0;
        for (int32_t i = 0; i < m && nsur && !how; i++) {
            int32_t p = mine[i];
            if (classify(s, p, x0, y0, x1, y1) != W_SURROUNDING)
                continue;
            int front = 1;
            int32_t cx[4] = {x0, x1 - 1, x0, x1 - 1}, cy[4] = {y0, y0, y1 - 1, y1 - 1};
            for (int32_t j = 0; j < m && front; j++)
                for (int q = 0; q < 4 && front; q++)
                    if (mine[j] != p && !fx_vsd_beats(s, p, mine[j], cx[q], cy[q]))
                        front = 0;
            if (front) {
                how = "surrounding in front";
                shown = p;
                fill_poly(k, p, x0, y0, x1, y1);
            }
        }
        if (!how && x1 - x0 == 1 && y1 - y0 == 1) {
            int32_t best = -1;
            for (int32_t i = 0; i < m; i++)
                if (fx_vsd_inside(s, mine[i], x0, y0) && fx_vsd_beats(s, mine[i], best, x0, y0))
                    best = mine[i];
            k->ids[(size_t)y0 * (size_t)s->w + (size_t)x0] = best;
            how = "pixel";
            shown = best;
        }
    }
    if (k->c)
        fx_trace(k->c, "warnock [%d,%d)x[%d,%d): %d polygons, %s%s %d", x0, x1, y0, y1, m,
                 how ? how : "subdivide", how ? ":" : "", how ? shown : m);
    if (how)
        return 0;
    int32_t xm = x0 + (x1 - x0 + 1) / 2, ym = y0 + (y1 - y0 + 1) / 2;
    int32_t t = *top + m;
    int32_t qx[4][2] = {{x0, xm}, {xm, x1}, {x0, xm}, {xm, x1}};
    int32_t qy[4][2] = {{y0, ym}, {y0, ym}, {ym, y1}, {ym, y1}};
    for (int q = 0; q < 4; q++) {
        if (qx[q][0] >= qx[q][1] || qy[q][0] >= qy[q][1])
            continue;
        int e = region(k, mine, m, qx[q][0], qy[q][0], qx[q][1], qy[q][1], &t);
        if (e < 0)
            return e;
    }
    return 0;
}

int fx_vsd_warnock(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
                fx_vsd_stats *st)
{
    if (bytes < fx_vsd_warnock_bytes(s) || !work)
        return -FX_ENOSPC;
    wk k = {s, ids, work, (int32_t)((bytes - 16) / sizeof(int32_t)), c, st};
    int32_t *all = k.mem, top = s->npoly;
    for (int32_t p = 0; p < s->npoly; p++)
        all[p] = p;
    return region(&k, all, s->npoly, 0, 0, s->w, s->h, &top);
}
