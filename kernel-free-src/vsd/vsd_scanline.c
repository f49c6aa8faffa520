/* SPDX-License-Identifier: MIT */
/* fixel — the scan-line method.
 *
 * The edge table buckets the non-horizontal edges by their first row; row
 * by row, edges enter the active edge list (AEL) and leave it after their
 * last row, each carrying the x where its polygon starts (left edges) or
 * stops (right edges) being covered on that row — the same pixel rule as
 * every other method. The list is kept sorted by that x (insertion sort:
 * the order hardly changes from one row to the next). Walking it, each
 * edge flips its polygon's in/out flag; between two edges the set of
 * polygons flagged "in" is constant. One polygon in: its span. Several:
 * the nearest at both ends of the span wins all of it (depths are linear
 * along the row, so a difference that has one sign at both ends has it
 * throughout); otherwise the span is halved until that holds. */
#include "vsd_int.h"

typedef struct sl_work {
    int32_t *head;  /* h + 1 bucket heads of the edge table */
    int32_t *next;  /* next edge in a bucket */
    int32_t *ael;   /* active edges */
    int32_t *ax;    /* their x on this row */
    int32_t *count; /* per polygon: in/out counter (in when 1) */
    int32_t *pos;   /* per polygon: index in the in-list, -1 when out */
    int32_t *in;    /* polygons flagged in */
} sl_work;

size_t fx_vsd_scanline_bytes(const fx_vsd_scene *s)
{
    return ((size_t)s->h + 1 + 3 * (size_t)s->nedge + 3 * (size_t)s->npoly) * sizeof(int32_t) + 16;
}

static int32_t edge_y0(const fx_vsd_scene *s, const fx_vsd_edge *e)
{
    int32_t a = s->vert[e->v0].y, b = s->vert[e->v1].y;
    return a < b ? a : b;
}
static int32_t edge_y1(const fx_vsd_scene *s, const fx_vsd_edge *e)
{
    int32_t a = s->vert[e->v0].y, b = s->vert[e->v1].y;
    return a > b ? a : b;
}

/* The winner among in[0..n) at pixel (x, y). */
static int32_t nearest(const fx_vsd_scene *s, const int32_t *in, int32_t n, int32_t x, int32_t y)
{
    int32_t best = -1;
    for (int32_t i = 0; i < n; i++)
        if (fx_vsd_beats(s, in[i], best, x, y))
            best = in[i];
    return best;
}

static void resolve(const fx_vsd_scene *s, const int32_t *in, int32_t n, int32_t y, int32_t xa,
                    int32_t xb, int32_t *row)
{
    while (xa < xb) {
        int32_t wa = nearest(s, in, n, xa, y), wb = nearest(s, in, n, xb - 1, y);
        if (wa == wb) {
            for (int32_t x = xa; x < xb; x++)
                row[x] = wa;
            return;
        }
        int32_t mid = xa + (xb - xa) / 2;
        resolve(s, in, n, y, xa, mid, row);
        xa = mid;
    }
}

int fx_vsd_scanline(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c,
                 int32_t trace_row, fx_vsd_stats *st)
{
    if (bytes < fx_vsd_scanline_bytes(s) || !work)
        return -FX_ENOSPC;
    sl_work w;
    w.head = work;
    w.next = w.head + s->h + 1;
    w.ael = w.next + s->nedge;
    w.ax = w.ael + s->nedge;
    w.count = w.ax + s->nedge;
    w.pos = w.count + s->npoly;
    w.in = w.pos + s->npoly;
    for (int32_t y = 0; y <= s->h; y++)
        w.head[y] = -1;
    /* edge table, built backwards so each bucket lists edges in table order */
    for (int32_t i = s->nedge - 1; i >= 0; i--) {
        const fx_vsd_edge *e = &s->edge[i];
        if (e->ea == 0)
            continue; /* horizontal: the edges beside it bound the rows */
        int32_t y0 = edge_y0(s, e), y1 = edge_y1(s, e);
        if (y1 <= 0 || y0 >= s->h)
            continue;
        if (y0 < 0)
            y0 = 0;
        w.next[i] = w.head[y0];
        w.head[y0] = i;
    }
    for (int32_t p = 0; p < s->npoly; p++) {
        w.count[p] = 0;
        w.pos[p] = -1;
    }
    int32_t na = 0;
    for (int32_t y = 0; y < s->h; y++) {
        /* retire finished edges, admit new ones */
        int32_t k = 0;
        for (int32_t i = 0; i < na; i++)
            if (edge_y1(s, &s->edge[w.ael[i]]) > y)
                w.ael[k++] = w.ael[i];
        na = k;
        for (int32_t e = w.head[y]; e >= 0; e = w.next[e])
            w.ael[na++] = e;
        if (na > st->max_active)
            st->max_active = na;
        /* x of each edge on this row, then keep the list sorted by it */
        for (int32_t i = 0; i < na; i++) {
            const fx_vsd_edge *e = &s->edge[w.ael[i]];
            int32_t lo = INT32_MIN / 2, hi = INT32_MAX / 2;
            fx_vsd_hspan(e->ea, e->eb * y + e->ec, e->incl, &lo, &hi);
            w.ax[i] = e->ea > 0 ? lo : hi;
        }
        for (int32_t i = 1; i < na; i++) {
            int32_t e = w.ael[i], x = w.ax[i], j = i;
            while (j > 0 && w.ax[j - 1] > x) {
                w.ael[j] = w.ael[j - 1];
                w.ax[j] = w.ax[j - 1];
                j--;
            }
            w.ael[j] = e;
            w.ax[j] = x;
        }
        int tr = c && y == trace_row;
        if (tr)
            fx_trace(c, "scanline row %d: %d active edges", y, na);
        int32_t *row = ids + (size_t)y * (size_t)s->w;
        int32_t nin = 0, cur = 0;
        for (int32_t i = 0; i < na; i++) {
            int32_t x = w.ax[i] < 0 ? 0 : w.ax[i] > s->w ? s->w : w.ax[i];
            if (x > cur) {
                if (nin)
                    resolve(s, w.in, nin, y, cur, x, row);
                if (tr && nin)
                    fx_trace(c, "  span [%d, %d): %d polygons in, shows %d", cur, x, nin, row[cur]);
                cur = x;
            }
            const fx_vsd_edge *e = &s->edge[w.ael[i]];
            int32_t p = e->poly;
            int on = e->ea > 0;
            if (tr)
                fx_trace(c, "  x %d: edge %d of polygon %d (%s)", w.ax[i], w.ael[i], p,
                         on ? "in" : "out");
            w.count[p] += on ? 1 : -1;
            if (w.count[p] == 1 && w.pos[p] < 0) {
                w.pos[p] = nin;
                w.in[nin++] = p;
            } else if (w.count[p] != 1 && w.pos[p] >= 0) {
                int32_t at = w.pos[p], last = w.in[--nin];
                w.in[at] = last;
                w.pos[last] = at;
                w.pos[p] = -1;
            }
        }
        if (nin && cur < s->w)
            resolve(s, w.in, nin, y, cur, s->w, row);
        /* every polygon's flags are back to out after its right edge */
        for (int32_t i = 0; i < na; i++) {
            int32_t p = s->edge[w.ael[i]].poly;
            w.count[p] = 0;
            w.pos[p] = -1;
        }
    }
    return 0;
}
