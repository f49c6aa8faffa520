/* SPDX-License-Identifier: MIT */
/* fixel — visible-surface detection: the vertex, edge and polygon tables,
 * plane equations, coverage and exact depth comparison that every method
 * shares; polygon pieces for the splitting methods. */
#include "vsd_int.h"

static int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

static int64_t gcd64(int64_t a, int64_t b)
{
    a = abs64(a);
    b = abs64(b);
    while (b) {
        int64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

int64_t fx_vsd_floordiv(int64_t n, int64_t d)
{
    int64_t q = n / d;
    if ((n % d != 0) && ((n < 0) != (d < 0)))
        q--;
    return q;
}

static int32_t clamp32(int64_t v)
{
    return v < INT32_MIN ? INT32_MIN : v > INT32_MAX ? INT32_MAX : (int32_t)v;
}

void fx_vsd_hspan(int64_t a, int64_t k, int incl, int32_t *lo, int32_t *hi)
{
    if (a == 0) {
        if (!(k > 0 || (incl && k == 0)))
            *hi = *lo;
        return;
    }
    if (a > 0) {
        /* x >= -k / a, or x > -k / a */
        int64_t b = incl ? -fx_vsd_floordiv(k, a) : fx_vsd_floordiv(-k, a) + 1;
        if (b > *lo)
            *lo = clamp32(b);
    } else {
        /* x <= k / |a|, or x < k / |a| */
        int64_t b = incl ? fx_vsd_floordiv(k, -a) + 1 : -fx_vsd_floordiv(-k, -a);
        if (b < *hi)
            *hi = clamp32(b);
    }
    if (*hi < *lo)
        *hi = *lo;
}

const char *fx_vsd_method_name(fx_vsd_method m)
{
    static const char *const names[FX_VSD_METHODS] = {"zbuffer", "painter", "newell", "bsp",
                                                      "scanline", "warnock", "raycast", "abuffer"};
    return (unsigned)m < FX_VSD_METHODS ? names[m] : 0;
}

int fx_vsd_init(fx_vsd_scene *s, int32_t w, int32_t h, fx_vsd_vertex *vert, int32_t vcap,
                fx_vsd_edge *edge, int32_t ecap, fx_vsd_poly *poly, int32_t pcap)
{
    if (!s || w < 1 || h < 1 || w > FX_VSD_COORD_MAX + 1 || h > FX_VSD_COORD_MAX + 1 || vcap < 0 ||
        ecap < 0 || pcap < 0 || (vcap && !vert) || (ecap && !edge) || (pcap && !poly))
        return -FX_EINVAL;
    *s = (fx_vsd_scene){.vert = vert, .edge = edge, .poly = poly, .vcap = vcap, .ecap = ecap,
                        .pcap = pcap, .w = w, .h = h, .background = 0xFF000000u};
    return 0;
}

int fx_vsd_add(fx_vsd_scene *s, const fx_vsd_vertex *v, int n, fx_color color)
{
    if (!s || !v || n < 3 || n > FX_VSD_MAX_VERTS)
        return -FX_EINVAL;
    for (int i = 0; i < n; i++)
        if (v[i].x < 0 || v[i].y < 0 || v[i].z < 0 || v[i].x > FX_VSD_COORD_MAX ||
            v[i].y > FX_VSD_COORD_MAX || v[i].z > FX_VSD_COORD_MAX)
            return -FX_EINVAL;
    /* Newell's sums: twice the projected areas, the plane's normal even for
     * a polygon whose first three vertices are collinear. */
    int64_t a = 0, b = 0, c = 0;
    int turn = 0;
    for (int i = 0; i < n; i++) {
        const fx_vsd_vertex *p = &v[i], *q = &v[(i + 1) % n], *r = &v[(i + 2) % n];
        if (p->x == q->x && p->y == q->y)
            return -FX_EINVAL; /* a repeated vertex, or an edge seen end-on */
        a += (int64_t)(p->y - q->y) * (p->z + q->z);
        b += (int64_t)(p->z - q->z) * (p->x + q->x);
        c += (int64_t)(p->x - q->x) * (p->y + q->y);
        int64_t cr = (int64_t)(q->x - p->x) * (r->y - q->y) - (int64_t)(q->y - p->y) * (r->x - q->x);
        int sg = cr > 0 ? 1 : cr < 0 ? -1 : 0;
        if (sg && turn && sg != turn)
            return -FX_EINVAL; /* concave */
        if (sg)
            turn = sg;
    }
    {
        /* same turn everywhere can still wind round twice (a pentagram):
         * a convex polygon goes down once and up once */
        int changes = 0, firstdy = 0, prev = 0;
        for (int i = 0; i < n; i++) {
            int dy = v[(i + 1) % n].y > v[i].y ? 1 : v[(i + 1) % n].y < v[i].y ? -1 : 0;
            if (!dy)
                continue;
            if (!firstdy)
                firstdy = dy;
            else if (dy != prev)
                changes++;
            prev = dy;
        }
        if (prev && prev != firstdy)
            changes++;
        if (changes > 2)
            return -FX_EINVAL;
    }
    if (c == 0) { /* edge-on: no pixel centre is inside */
        s->culled++;
        return 0;
    }
    int back = c > 0; /* the normal points away from the viewer (who looks along +z) */
    if (back && s->cull) {
        s->culled++;
        return 0;
    }
    int64_t g = gcd64(gcd64(a, b), c);
    a /= g;
    b /= g;
    c /= g;
    if (c < 0) {
        a = -a;
        b = -b;
        c = -c;
    }
    int64_t d = -(a * v[0].x + b * v[0].y + c * v[0].z);
    for (int i = 1; i < n; i++)
        if (a * v[i].x + b * v[i].y + c * v[i].z + d != 0)
            return -FX_EINVAL; /* not planar */
    if (s->npoly >= s->pcap || s->nedge + n > s->ecap || s->nvert + n > s->vcap)
        return -FX_ENOSPC;
    int sg = back ? 1 : -1; /* sign of the screen area (Newell's c before orienting) */
    fx_vsd_poly *P = &s->poly[s->npoly];
    *P = (fx_vsd_poly){.first_edge = s->nedge, .nedges = n, .a = a, .b = b, .c = c, .d = d,
                       .back = back, .color = color, .xmin = v[0].x, .ymin = v[0].y,
                       .zmin = v[0].z, .xmax = v[0].x, .ymax = v[0].y, .zmax = v[0].z};
    int32_t v0 = s->nvert;
    for (int i = 0; i < n; i++) {
        s->vert[v0 + i] = v[i];
        if (v[i].x < P->xmin) P->xmin = v[i].x;
        if (v[i].x > P->xmax) P->xmax = v[i].x;
        if (v[i].y < P->ymin) P->ymin = v[i].y;
        if (v[i].y > P->ymax) P->ymax = v[i].y;
        if (v[i].z < P->zmin) P->zmin = v[i].z;
        if (v[i].z > P->zmax) P->zmax = v[i].z;
    }
    for (int i = 0; i < n; i++) {
        const fx_vsd_vertex *p = &v[i], *q = &v[(i + 1) % n];
        fx_vsd_edge *e = &s->edge[s->nedge + i];
        e->v0 = v0 + i;
        e->v1 = v0 + (i + 1) % n;
        e->poly = s->npoly;
        /* inside is to the side the polygon's area sign says */
        e->ea = -(int64_t)(q->y - p->y) * sg;
        e->eb = (int64_t)(q->x - p->x) * sg;
        e->ec = -(e->ea * p->x + e->eb * p->y);
        e->incl = e->ea > 0 || (e->ea == 0 && e->eb > 0); /* left or top edge */
    }
    s->nvert += n;
    s->nedge += n;
    s->npoly++;
    return 0;
}

int fx_vsd_depth_cmp(const fx_vsd_scene *s, int32_t p, int32_t q, int32_t x, int32_t y)
{
    const fx_vsd_poly *P = &s->poly[p], *Q = &s->poly[q];
    int64_t l = vsd_num(P, x, y) * Q->c, r = vsd_num(Q, x, y) * P->c;
    return l < r ? -1 : l > r;
}

int fx_vsd_beats(const fx_vsd_scene *s, int32_t p, int32_t q, int32_t x, int32_t y)
{
    if (q < 0)
        return 1;
    int c = fx_vsd_depth_cmp(s, p, q, x, y);
    return c < 0 || (c == 0 && p < q);
}

int fx_vsd_inside(const fx_vsd_scene *s, int32_t p, int32_t x, int32_t y)
{
    const fx_vsd_poly *P = &s->poly[p];
    for (int32_t i = 0; i < P->nedges; i++) {
        const fx_vsd_edge *e = &s->edge[P->first_edge + i];
        int64_t v = e->ea * x + e->eb * y + e->ec;
        if (v < 0 || (v == 0 && !e->incl))
            return 0;
    }
    return 1;
}

void fx_vsd_poly_rows(const fx_vsd_scene *s, int32_t p, int32_t *y0, int32_t *y1)
{
    const fx_vsd_poly *P = &s->poly[p];
    *y0 = P->ymin < 0 ? 0 : P->ymin;
    *y1 = P->ymax + 1 > s->h ? s->h : P->ymax + 1;
}

void fx_vsd_poly_span(const fx_vsd_scene *s, int32_t p, int32_t y, int32_t *lo, int32_t *hi)
{
    const fx_vsd_poly *P = &s->poly[p];
    *lo = 0;
    *hi = s->w;
    for (int32_t i = 0; i < P->nedges && *lo < *hi; i++) {
        const fx_vsd_edge *e = &s->edge[P->first_edge + i];
        fx_vsd_hspan(e->ea, e->eb * y + e->ec, e->incl, lo, hi);
    }
}

void fx_vsd_frag_span(const fx_vsd_scene *s, const vsd_frag *f, int32_t y, int32_t *lo, int32_t *hi)
{
    fx_vsd_poly_span(s, f->poly, y, lo, hi);
    for (int32_t i = 0; i < f->ncut && *lo < *hi; i++)
        fx_vsd_hspan(f->ca[i], f->cb[i] * y + f->cc[i], f->cincl[i], lo, hi);
}

void fx_vsd_frag_paint(const fx_vsd_scene *s, const vsd_frag *f, int32_t *ids)
{
    int32_t y0, y1;
    fx_vsd_poly_rows(s, f->poly, &y0, &y1);
    for (int32_t y = y0; y < y1; y++) {
        int32_t lo, hi;
        fx_vsd_frag_span(s, f, y, &lo, &hi);
        for (int32_t x = lo; x < hi; x++)
            ids[(size_t)y * (size_t)s->w + (size_t)x] = f->poly;
    }
}

int32_t fx_vsd_frag_work(const fx_vsd_scene *s, void *work, size_t bytes, vsd_frag **fr, int32_t **ints)
{
    size_t per = sizeof(vsd_frag) + 2 * sizeof(int32_t);
    int32_t cap = (int32_t)((bytes / per) > INT32_MAX ? INT32_MAX : bytes / per);
    if ((!work && s->npoly) || cap < s->npoly)
        return -FX_ENOSPC;
    *fr = work;
    *ints = (int32_t *)(*fr + cap);
    return cap;
}

static void frag_extents(vsd_frag *f)
{
    f->x0 = f->x1 = f->x[0];
    f->y0 = f->y1 = f->y[0];
    f->z0 = f->z1 = f->z[0];
    for (int32_t i = 1; i < f->nv; i++) {
        if (f->x[i] < f->x0) f->x0 = f->x[i];
        if (f->x[i] > f->x1) f->x1 = f->x[i];
        if (f->y[i] < f->y0) f->y0 = f->y[i];
        if (f->y[i] > f->y1) f->y1 = f->y[i];
        if (f->z[i] < f->z0) f->z0 = f->z[i];
        if (f->z[i] > f->z1) f->z1 = f->z[i];
    }
}

void fx_vsd_frag_from_poly(const fx_vsd_scene *s, int32_t p, vsd_frag *f)
{
    const fx_vsd_poly *P = &s->poly[p];
    f->poly = p;
    f->nv = P->nedges;
    f->ncut = 0;
    f->front = f->back = -1;
    f->mark = 0;
    for (int32_t i = 0; i < P->nedges; i++) {
        const fx_vsd_vertex *v = &s->vert[s->edge[P->first_edge + i].v0];
        f->x[i] = v->x * 256;
        f->y[i] = v->y * 256;
        f->z[i] = v->z * 256;
    }
    frag_extents(f);
}

int64_t fx_vsd_plane_side(const fx_vsd_poly *q, int32_t x, int32_t y, int32_t z)
{
    return q->a * x + q->b * y + q->c * z + q->d * 256;
}

int64_t fx_vsd_plane_eps(const fx_vsd_poly *q)
{
    /* a vertex rounded by half a unit on each axis moves the value by at
     * most half this; twice that is the margin */
    return abs64(q->a) + abs64(q->b) + abs64(q->c);
}

int fx_vsd_frag_sides(const fx_vsd_scene *s, const vsd_frag *f, int32_t q)
{
    const fx_vsd_poly *Q = &s->poly[q];
    int64_t eps = fx_vsd_plane_eps(Q);
    int r = 0;
    for (int32_t i = 0; i < f->nv; i++) {
        int64_t v = fx_vsd_plane_side(Q, f->x[i], f->y[i], f->z[i]);
        if (v > eps)
            r |= 1;
        else if (v < -eps)
            r |= 2;
    }
    return r;
}

static int32_t lerp_round(int32_t a, int32_t b, int64_t num, int64_t den)
{
    /* a + (b - a) num / den, den > 0, 0 <= num <= den, rounded to nearest */
    int64_t t = (int64_t)(b - a) * num;
    int64_t q = t >= 0 ? (t + den / 2) / den : -((-t + den / 2) / den);
    return (int32_t)(a + q);
}

/* Drop the cuts a piece lies well inside of (every vertex 1/16 pixel or
 * more within, far beyond the vertices' rounding), so that a piece cut
 * again and again along a deep BSP path keeps only the cuts that shape it.
 * Cuts too large to evaluate in 64 bits at 24.8 stay. */
static void prune_cuts(vsd_frag *f)
{
    const int64_t big = (int64_t)1 << 40;
    int32_t k = 0;
    for (int32_t i = 0; i < f->ncut; i++) {
        int keep = abs64(f->ca[i]) >= big || abs64(f->cb[i]) >= big ||
                   abs64(f->cc[i]) >= ((int64_t)1 << 51);
        int64_t margin = 16 * (abs64(f->ca[i]) + abs64(f->cb[i]));
        for (int32_t j = 0; j < f->nv && !keep; j++)
            keep = f->ca[i] * f->x[j] + f->cb[i] * f->y[j] + f->cc[i] * 256 <= margin;
        if (keep) {
            f->ca[k] = f->ca[i];
            f->cb[k] = f->cb[i];
            f->cc[k] = f->cc[i];
            f->cincl[k++] = f->cincl[i];
        }
    }
    f->ncut = k;
}

int fx_vsd_frag_split(const fx_vsd_scene *s, const vsd_frag *f, int32_t q, vsd_frag *back,
                   vsd_frag *front)
{
    if (f->ncut >= FX_VSD_MAX_CUTS)
        return -FX_E2BIG;
    const fx_vsd_poly *P = &s->poly[f->poly], *Q = &s->poly[q];
    /* The point of P over pixel (x, y) is behind Q when
     * c_P (a_Q x + b_Q y + d_Q) - c_Q (a_P x + b_P y + d_P) >= 0 (c_P > 0):
     * a half-plane of the screen, exact in 64 bits for the coordinate
     * bounds of fixel/vsd.h. */
    int64_t ca = P->c * Q->a - Q->c * P->a, cb = P->c * Q->b - Q->c * P->b,
            cc = P->c * Q->d - Q->c * P->d;
    int64_t g = gcd64(gcd64(ca, cb), cc);
    if (g > 1) {
        ca /= g;
        cb /= g;
        cc /= g;
    }
    /* Where P and Q tie exactly the z-buffer shows the lower index: those
     * pixels go to the piece drawn after Q (the front one) when P < Q, to
     * the one drawn before it otherwise. */
    int tie_front = f->poly < q;
    vsd_frag b = *f, fr = *f;
    b.ca[b.ncut] = ca;
    b.cb[b.ncut] = cb;
    b.cc[b.ncut] = cc;
    b.cincl[b.ncut++] = (int8_t)!tie_front;
    fr.ca[fr.ncut] = -ca;
    fr.cb[fr.ncut] = -cb;
    fr.cc[fr.ncut] = -cc;
    fr.cincl[fr.ncut++] = (int8_t)tie_front;
    b.nv = fr.nv = 0;
    b.front = b.back = fr.front = fr.back = -1;
    b.mark = fr.mark = 0;
    /* Sutherland-Hodgman on the approximate vertices, one cut shared by both */
    for (int32_t i = 0; i < f->nv; i++) {
        int32_t j = (i + 1) % f->nv;
        int64_t si = fx_vsd_plane_side(Q, f->x[i], f->y[i], f->z[i]);
        int64_t sj = fx_vsd_plane_side(Q, f->x[j], f->y[j], f->z[j]);
        if (si >= 0 && b.nv < FX_VSD_FRAG_VERTS) {
            b.x[b.nv] = f->x[i], b.y[b.nv] = f->y[i], b.z[b.nv++] = f->z[i];
        }
        if (si <= 0 && fr.nv < FX_VSD_FRAG_VERTS) {
            fr.x[fr.nv] = f->x[i], fr.y[fr.nv] = f->y[i], fr.z[fr.nv++] = f->z[i];
        }
        if ((si > 0 && sj < 0) || (si < 0 && sj > 0)) {
            int64_t num = si < 0 ? -si : si, den = si < 0 ? sj - si : si - sj;
            while (den >= ((int64_t)1 << 40)) {
                num >>= 1;
                den >>= 1;
            }
            int32_t x = lerp_round(f->x[i], f->x[j], num, den);
            int32_t y = lerp_round(f->y[i], f->y[j], num, den);
            int32_t z = lerp_round(f->z[i], f->z[j], num, den);
            if (b.nv < FX_VSD_FRAG_VERTS)
                b.x[b.nv] = x, b.y[b.nv] = y, b.z[b.nv++] = z;
            if (fr.nv < FX_VSD_FRAG_VERTS)
                fr.x[fr.nv] = x, fr.y[fr.nv] = y, fr.z[fr.nv++] = z;
        }
    }
    if (b.nv < 3 || fr.nv < 3)
        return -FX_EDOM; /* does not straddle after all: the caller keeps f */
    frag_extents(&b);
    frag_extents(&fr);
    prune_cuts(&b);
    prune_cuts(&fr);
    *back = b;
    *front = fr;
    return 0;
}

/* ---- the methods that need no more than the tables ---- */

static void ids_clear(const fx_vsd_scene *s, int32_t *ids)
{
    for (size_t i = 0; i < (size_t)s->w * (size_t)s->h; i++)
        ids[i] = -1;
}

/* The z-buffer: polygons in table order, a pixel taken when the new depth
 * is strictly nearer. The depth buffer holds, instead of a rounded number,
 * the polygon that won (its plane gives the exact depth on demand), so
 * this reference has no rounding of its own. */
static void zbuffer(const fx_vsd_scene *s, int32_t *ids)
{
    for (int32_t p = 0; p < s->npoly; p++) {
        int32_t y0, y1;
        fx_vsd_poly_rows(s, p, &y0, &y1);
        for (int32_t y = y0; y < y1; y++) {
            int32_t lo, hi;
            fx_vsd_poly_span(s, p, y, &lo, &hi);
            int32_t *row = ids + (size_t)y * (size_t)s->w;
            for (int32_t x = lo; x < hi; x++)
                if (fx_vsd_beats(s, p, row[x], x, y))
                    row[x] = p;
        }
    }
}

/* Ray casting: one ray per pixel centre along the view direction; its hit
 * with a polygon's plane is at depth num / c, inside when the centre is
 * (orthographic screen space: the ray's footprint is the centre). */
static void raycast(const fx_vsd_scene *s, int32_t *ids)
{
    for (int32_t y = 0; y < s->h; y++)
        for (int32_t x = 0; x < s->w; x++) {
            int32_t best = -1;
            for (int32_t p = 0; p < s->npoly; p++) {
                const fx_vsd_poly *P = &s->poly[p];
                if (x < P->xmin || x > P->xmax || y < P->ymin || y > P->ymax)
                    continue;
                if (fx_vsd_inside(s, p, x, y) && fx_vsd_beats(s, p, best, x, y))
                    best = p;
            }
            ids[(size_t)y * (size_t)s->w + (size_t)x] = best;
        }
}

/* The plain painter's algorithm: whole polygons sorted by mean depth,
 * farthest first, no overlap tests. */
static int painter(const fx_vsd_scene *s, int32_t *ids, void *work, size_t bytes, const fx_ctx *c)
{
    if (bytes < (size_t)s->npoly * 2 * sizeof(int64_t))
        return -FX_ENOSPC;
    int64_t *key = work; /* mean depth x 8 * 2^20 + index, sorted */
    int32_t n = s->npoly;
    for (int32_t p = 0; p < n; p++) {
        const fx_vsd_poly *P = &s->poly[p];
        int64_t sum = 0;
        for (int32_t i = 0; i < P->nedges; i++)
            sum += s->vert[s->edge[P->first_edge + i].v0].z;
        int64_t mean8 = sum * 8 / P->nedges;
        int64_t k = -mean8 * 1048576 + p, j = p; /* farthest first, then table order */
        while (j > 0 && key[j - 1] > k) {
            key[j] = key[j - 1];
            j--;
        }
        key[j] = k;
    }
    vsd_frag f;
    for (int32_t i = 0; i < n; i++) {
        int32_t p = (int32_t)(((key[i] % 1048576) + 1048576) % 1048576);
        if (c)
            fx_trace(c, "painter %d: polygon %d, mean depth %d/8", i, p,
                     (int)-fx_vsd_floordiv(key[i] - p, 1048576));
        fx_vsd_frag_from_poly(s, p, &f);
        fx_vsd_frag_paint(s, &f, ids);
    }
    return 0;
}

size_t fx_vsd_work_bytes(const fx_vsd_scene *s, fx_vsd_method m, int32_t max_frags)
{
    if (!s)
        return 0;
    if (max_frags < s->npoly)
        max_frags = s->npoly;
    switch (m) {
    case FX_VSD_PAINTER:
        return (size_t)s->npoly * 2 * sizeof(int64_t) + 8;
    case FX_VSD_NEWELL:
    case FX_VSD_BSP:
        return (size_t)max_frags * (sizeof(vsd_frag) + 2 * sizeof(int32_t)) + 16; /* fx_vsd_frag_work */
    case FX_VSD_SCANLINE:
        return fx_vsd_scanline_bytes(s);
    case FX_VSD_WARNOCK:
        return fx_vsd_warnock_bytes(s);
    case FX_VSD_ABUFFER:
        return (size_t)s->w * (size_t)s->h * sizeof(int32_t) +
               (size_t)max_frags * 3 * sizeof(int32_t) + 16;
    default:
        return 0;
    }
}

int fx_vsd_render(const fx_vsd_scene *s, fx_vsd_method m, int32_t *ids, void *work, size_t bytes,
                  const fx_ctx *c, int32_t trace_row, fx_vsd_stats *st)
{
    fx_vsd_stats dummy;
    if (!st)
        st = &dummy;
    *st = (fx_vsd_stats){0};
    if (!s || !ids || (unsigned)m >= FX_VSD_METHODS || m == FX_VSD_ABUFFER)
        return -FX_EINVAL;
    if (c && !c->trace)
        c = 0;
    /* work memory is used as int64 and struct arrays */
    if (work && ((uintptr_t)work & 7))
        return -FX_EINVAL;
    ids_clear(s, ids);
    switch (m) {
    case FX_VSD_ZBUFFER:
        zbuffer(s, ids);
        return 0;
    case FX_VSD_RAYCAST:
        raycast(s, ids);
        return 0;
    case FX_VSD_PAINTER:
        return painter(s, ids, work, bytes, c);
    case FX_VSD_NEWELL:
        return fx_vsd_newell(s, ids, work, bytes, c, st);
    case FX_VSD_BSP:
        return fx_vsd_bsp(s, ids, work, bytes, c, st);
    case FX_VSD_SCANLINE:
        return fx_vsd_scanline(s, ids, work, bytes, c, trace_row, st);
    case FX_VSD_WARNOCK:
        return fx_vsd_warnock(s, ids, work, bytes, c, st);
    default:
        return -FX_EINVAL;
    }
}

void fx_vsd_paint(const fx_vsd_scene *s, const int32_t *ids, const fx_surface *dst, int32_t ox,
                  int32_t oy)
{
    for (int32_t y = 0; y < s->h; y++) {
        int64_t dy = (int64_t)oy + y;
        if (dy < 0 || dy >= dst->h)
            continue;
        for (int32_t x = 0; x < s->w; x++) {
            int64_t dx = (int64_t)ox + x;
            if (dx < 0 || dx >= dst->w)
                continue;
            int32_t p = ids[(size_t)y * (size_t)s->w + (size_t)x];
            fx_surface_put(dst, (int32_t)dx, (int32_t)dy, p < 0 ? s->background : s->poly[p].color);
        }
    }
}
