/* SPDX-License-Identifier: MIT */
/* fixel — meshes in the ray tracer: a bounding volume hierarchy over the
 * triangles of an fx_mesh (built once, over caller memory), and the
 * Moller-Trumbore ray/triangle test in integers.
 *
 * Bounds: vertices within +-FX_RT_MESH_LIMIT = 32 units (2^21 raw), so
 * edges are below 2^22 raw; the object-space ray is S (Q16.16, < 2^31.4
 * raw) + c (Q8.24, < 2^29.6 raw) t. Then p = c x e2 (Q40) and q = (S - v0) x
 * e1 (Q32) fit int64, and det = e1.p, u = (S - v0).p, v = c.q (all Q56)
 * and e2.q (Q48) are exact in 128 bits: the inside test u >= 0, v >= 0,
 * u + v <= det is exact, so a ray through a shared edge meets at least one
 * of its two triangles (no cracks), and t, u/det, v/det are each rounded
 * once. */
#include "fixel/error.h"
#include "rt_int.h"

#define ONE ((int64_t)FX16_ONE)
#define LIMIT ((int64_t)FX_RT_MESH_LIMIT * FX16_ONE)

static fx_vec3 vtx(const fx_mesh *m, uint32_t t, int k) { return m->pos[m->tri[3 * t + (uint32_t)k]]; }

static int64_t centroid3(const fx_mesh *m, uint32_t t, int axis) /* 3 x the centroid */
{
    int64_t s = 0;
    for (int k = 0; k < 3; k++) {
        fx_vec3 p = vtx(m, t, k);
        s += axis == 0 ? p.x : axis == 1 ? p.y : p.z;
    }
    return s;
}

static void grow(fx_rt_bvh_node *n, fx_vec3 p)
{
    const fx16 v[3] = {p.x, p.y, p.z};
    for (int i = 0; i < 3; i++) {
        if (v[i] < n->lo[i])
            n->lo[i] = v[i];
        if (v[i] > n->hi[i])
            n->hi[i] = v[i];
    }
}

/* Put the k-th smallest (by centroid on axis) of a[0..n) at a[k] (Hoare's
 * selection). */
static void select_k(const fx_mesh *m, uint32_t *a, int32_t n, int32_t k, int axis)
{
    int32_t lo = 0, hi = n - 1;
    while (lo < hi) {
        int64_t pivot = centroid3(m, a[lo + (hi - lo) / 2], axis);
        int32_t i = lo, j = hi;
        while (i <= j) {
            while (centroid3(m, a[i], axis) < pivot)
                i++;
            while (centroid3(m, a[j], axis) > pivot)
                j--;
            if (i <= j) {
                uint32_t t = a[i];
                a[i++] = a[j];
                a[j--] = t;
            }
        }
        if (k <= j)
            hi = j;
        else if (k >= i)
            lo = i;
        else
            return;
    }
}

static void build(fx_rt_mesh *rm, int32_t ni, int32_t begin, int32_t end)
{
    const fx_mesh *m = rm->mesh;
    fx_rt_bvh_node *n = &rm->node[ni];
    for (int i = 0; i < 3; i++)
        n->lo[i] = INT32_MAX, n->hi[i] = INT32_MIN;
    int64_t clo[3] = {INT64_MAX, INT64_MAX, INT64_MAX}, chi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};
    for (int32_t i = begin; i < end; i++) {
        for (int k = 0; k < 3; k++)
            grow(n, vtx(m, rm->order[i], k));
        for (int a = 0; a < 3; a++) {
            int64_t c = centroid3(m, rm->order[i], a);
            clo[a] = c < clo[a] ? c : clo[a];
            chi[a] = c > chi[a] ? c : chi[a];
        }
    }
    if (end - begin <= FX_RT_BVH_LEAF) {
        n->first = begin;
        n->count = end - begin;
        return;
    }
    int axis = 0;
    for (int a = 1; a < 3; a++)
        if (chi[a] - clo[a] > chi[axis] - clo[axis])
            axis = a;
    int32_t mid = begin + (end - begin) / 2;
    select_k(m, rm->order + begin, end - begin, mid - begin, axis);
    int32_t left = rm->nnodes;
    rm->nnodes += 2;
    n->first = left;
    n->count = 0;
    build(rm, left, begin, mid);
    build(rm, left + 1, mid, end);
}

int fx_rt_mesh_build(fx_rt_mesh *rm, const fx_mesh *m, fx_rt_bvh_node *nodes, int32_t cap_nodes, uint32_t *order)
{
    if (!rm || !m || !nodes || !order || m->ntris < 1 || m->nverts < 1)
        return -FX_EINVAL;
    if (m->ntris > INT32_MAX / 2 || cap_nodes < 2 * m->ntris)
        return -FX_ENOSPC;
    for (int32_t i = 0; i < m->nverts; i++) {
        fx_vec3 p = m->pos[i];
        if (p.x < -LIMIT || p.x > LIMIT || p.y < -LIMIT || p.y > LIMIT || p.z < -LIMIT || p.z > LIMIT)
            return -FX_ERANGE;
    }
    for (int32_t i = 0; i < 3 * m->ntris; i++)
        if (m->tri[i] >= (uint32_t)m->nverts)
            return -FX_EINVAL;
    rm->mesh = m;
    rm->node = nodes;
    rm->order = order;
    rm->nnodes = 1;
    for (int32_t i = 0; i < m->ntris; i++)
        order[i] = (uint32_t)i;
    build(rm, 0, 0, m->ntris);
    return 0;
}

/* ---- 128-bit helpers ---- */

static fx_s128 dot128(int64_t a0, int64_t b0, int64_t a1, int64_t b1, int64_t a2, int64_t b2)
{
    return fx_w_add(fx_w_add(fx_w_mul(a0, b0), fx_w_mul(a1, b1)), fx_w_mul(a2, b2));
}

static fx_s128 sar128(fx_s128 a, unsigned k) /* 0 < k < 64 */
{
    fx_s128 r;
    r.lo = (a.lo >> k) | ((uint64_t)a.hi << (64 - k));
    r.hi = a.hi >> k;
    return r;
}

/* round(n / d) for d > 0 (both 128-bit), saturated to int32: d is brought
 * below 2^62 first (its relative precision stays 2^-62). */
static fx16 wdiv(fx_s128 n, fx_s128 d)
{
    if (d.hi) {
        unsigned k = 64 - (unsigned)__builtin_clzll((uint64_t)d.hi) + 2;
        n = sar128(n, k);
        d = sar128(d, k);
    } else if (d.lo >> 62) {
        n = sar128(n, 2);
        d = sar128(d, 2);
    }
    if (d.lo == 0)
        return 0;
    return rt_sat(fx_w_rounddiv_away(n, (int64_t)d.lo));
}

/* ---- traversal ---- */

/* t where S + c t (c Q8.24) crosses the value v on one axis, in Q16.16:
 * (v - S) 2^24 / c fits int64 (|v - S| < 2^32). */
static int64_t cross_t(int64_t v, int64_t S, int64_t c) { return ((v - S) * ((int64_t)1 << 24)) / c; }

static int box_range(const fx_rt_bvh_node *n, fx_vec3 S, fx_vec3 c, int64_t tmin, int64_t tmax)
{
    const int64_t s[3] = {S.x, S.y, S.z}, d[3] = {c.x, c.y, c.z};
    for (int i = 0; i < 3; i++) {
        if (d[i] == 0) {
            if (s[i] < n->lo[i] || s[i] > n->hi[i])
                return 0;
            continue;
        }
        int64_t a = cross_t(n->lo[i], s[i], d[i]), b = cross_t(n->hi[i], s[i], d[i]);
        if (a > b) {
            int64_t x = a;
            a = b, b = x;
        }
        if (a - 1 > tmin)
            tmin = a - 1;
        if (b + 1 < tmax)
            tmax = b + 1;
        if (tmin > tmax)
            return 0;
    }
    return 1;
}

/* Moller-Trumbore: 1 and t, barycentrics when the ray meets triangle tr
 * with tmin < t < *best. */
static int triangle(const fx_mesh *m, uint32_t tr, fx_vec3 S, fx_vec3 c, int64_t tmin, int64_t best, fx16 *t,
                    fx16 *bu, fx16 *bv)
{
    fx_vec3 v0 = vtx(m, tr, 0), v1 = vtx(m, tr, 1), v2 = vtx(m, tr, 2);
    int64_t e1[3] = {(int64_t)v1.x - v0.x, (int64_t)v1.y - v0.y, (int64_t)v1.z - v0.z};
    int64_t e2[3] = {(int64_t)v2.x - v0.x, (int64_t)v2.y - v0.y, (int64_t)v2.z - v0.z};
    int64_t d[3] = {c.x, c.y, c.z};
    int64_t p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    fx_s128 det = dot128(e1[0], p[0], e1[1], p[1], e1[2], p[2]);
    if (!det.hi && !det.lo)
        return 0; /* the ray is parallel to the triangle */
    int64_t tv[3] = {(int64_t)S.x - v0.x, (int64_t)S.y - v0.y, (int64_t)S.z - v0.z};
    fx_s128 u = dot128(tv[0], p[0], tv[1], p[1], tv[2], p[2]);
    int64_t q[3] = {tv[1] * e1[2] - tv[2] * e1[1], tv[2] * e1[0] - tv[0] * e1[2], tv[0] * e1[1] - tv[1] * e1[0]};
    fx_s128 v = dot128(d[0], q[0], d[1], q[1], d[2], q[2]);
    fx_s128 tn = dot128(e2[0], q[0], e2[1], q[1], e2[2], q[2]); /* Q48 */
    if (det.hi < 0) {
        det = fx_w_neg(det);
        u = fx_w_neg(u);
        v = fx_w_neg(v);
        tn = fx_w_neg(tn);
    }
    if (u.hi < 0 || v.hi < 0 || fx_w_cmp(fx_w_add(u, v), det) > 0)
        return 0;
    fx16 tt = wdiv(fx_w_shl(tn, 24), det); /* Q48 / Q56 = Q-8, 24 more bits make Q16 */
    if (tt <= tmin || tt >= best)
        return 0;
    *t = tt;
    *bu = wdiv(fx_w_shl(u, 16), det);
    *bv = wdiv(fx_w_shl(v, 16), det);
    return 1;
}

static fx_vec3 mesh_normal(const fx_mesh *m, uint32_t tr, fx16 bu, fx16 bv)
{
    if (m->nrm) {
        fx_vec3 n0 = m->nrm[m->tri[3 * tr]], n1 = m->nrm[m->tri[3 * tr + 1]], n2 = m->nrm[m->tri[3 * tr + 2]];
        int64_t w0 = ONE - bu - bv;
        fx_vec3 n = fx_vec3_make(rt_sat(rt_mul(w0, n0.x) + rt_mul(bu, n1.x) + rt_mul(bv, n2.x)),
                                 rt_sat(rt_mul(w0, n0.y) + rt_mul(bu, n1.y) + rt_mul(bv, n2.y)),
                                 rt_sat(rt_mul(w0, n0.z) + rt_mul(bu, n1.z) + rt_mul(bv, n2.z)));
        if (n.x || n.y || n.z)
            return n;
    }
    fx_vec3 v0 = vtx(m, tr, 0), v1 = vtx(m, tr, 1), v2 = vtx(m, tr, 2);
    int64_t a[3] = {(int64_t)v1.x - v0.x, (int64_t)v1.y - v0.y, (int64_t)v1.z - v0.z};
    int64_t b[3] = {(int64_t)v2.x - v0.x, (int64_t)v2.y - v0.y, (int64_t)v2.z - v0.z};
    int64_t n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    int64_t big = 0;
    for (int i = 0; i < 3; i++)
        big |= n[i] < 0 ? -n[i] : n[i];
    int sh = 0;
    while ((big >> sh) >= ((int64_t)1 << 30))
        sh++;
    return fx_vec3_make((fx16)(n[0] >> sh), (fx16)(n[1] >> sh), (fx16)(n[2] >> sh));
}

void fx_rt_mesh_hits(const fx_rt_mesh *rm, int idx, fx_vec3 S, fx_vec3 c, int64_t tmin, fx_rt_hitlist *out)
{
    int32_t stack[64];
    int sp = 0;
    stack[sp++] = 0;
    int64_t best = INT32_MAX;
    uint32_t best_tri = 0;
    fx16 bu = 0, bv = 0;
    int found = 0;
    while (sp) {
        const fx_rt_bvh_node *n = &rm->node[stack[--sp]];
        if (!box_range(n, S, c, tmin, best))
            continue;
        if (n->count) {
            for (int32_t i = 0; i < n->count; i++) {
                uint32_t tr = rm->order[n->first + i];
                fx16 t, u, v;
                if (triangle(rm->mesh, tr, S, c, tmin, best, &t, &u, &v)) {
                    best = t, best_tri = tr, bu = u, bv = v;
                    found = 1;
                }
            }
        } else if (sp + 2 <= 64) {
            stack[sp++] = n->first + 1;
            stack[sp++] = n->first;
        }
    }
    if (!found || out->n + 2 > FX_RT_MAX_HITS)
        return;
    fx_vec3 nrm = mesh_normal(rm->mesh, best_tri, bu, bv);
    fx_rt_hit *h = &out->h[out->n];
    h[0].t = h[1].t = (fx16)best;
    h[0].obj = h[1].obj = (int16_t)idx;
    h[0].entering = 1;
    h[1].entering = 0;
    h[0].flip = h[1].flip = 0;
    h[0].normal = h[1].normal = nrm;
    out->n += 2;
}
