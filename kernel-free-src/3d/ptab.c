/* SPDX-License-Identifier: MIT */
/* fixel — the course's vertex, edge and polygon tables with plane
 * equations, the inside/outside and back-face tests on them, and solids as
 * voxels for the octree (contracts in fixel/objects.h). */
#include "fixel/objects.h"
#include "fixel/error.h"
#include "objects_int.h"

#define LIM (1024 * FX16_ONE)

void fx_ptab_init(fx_ptab *t, fx_ptab_vertex *v, int32_t vcap, fx_ptab_edge *e, int32_t ecap, fx_ptab_poly *p,
                  int32_t pcap, int32_t *use, int32_t ucap)
{
    t->vert = v, t->edge = e, t->poly = p, t->use = use;
    t->nvert = t->nedge = t->npoly = t->nuse = 0;
    t->vcap = v ? vcap : 0, t->ecap = e ? ecap : 0, t->pcap = p ? pcap : 0, t->ucap = use ? ucap : 0;
}

static int in_range(fx_vec3 p)
{
    return p.x >= -LIM && p.x <= LIM && p.y >= -LIM && p.y <= LIM && p.z >= -LIM && p.z <= LIM;
}

int32_t fx_ptab_add_vertex(fx_ptab *t, fx_vec3 p)
{
    if (!in_range(p))
        return -FX_EINVAL;
    if (t->nvert >= t->vcap)
        return -FX_ENOSPC;
    t->vert[t->nvert].p = p;
    t->vert[t->nvert].first_edge = -1;
    return t->nvert++;
}

static int32_t find_edge(const fx_ptab *t, int32_t a, int32_t b)
{
    for (int32_t e = t->vert[a].first_edge; e >= 0;) {
        const fx_ptab_edge *E = &t->edge[e];
        if ((E->v[0] == a && E->v[1] == b) || (E->v[0] == b && E->v[1] == a))
            return e;
        e = E->v[0] == a ? E->next[0] : E->next[1];
    }
    return -1;
}

static int64_t iabs64(int64_t v) { return v < 0 ? -v : v; }

static int64_t fx_obj_side_raw(const fx_ptab_poly *P, fx_vec3 q)
{
    return P->a * q.x + P->b * q.y + P->c * q.z + P->d;
}

int32_t fx_ptab_add_polygon(fx_ptab *t, const int32_t *vi, int32_t n, uint32_t color, int32_t attr)
{
    if (!t || !vi || n < 3 || n > FX_PTAB_MAX_VERTS)
        return -FX_EINVAL;
    for (int32_t i = 0; i < n; i++)
        if (vi[i] < 0 || vi[i] >= t->nvert || vi[i] == vi[(i + 1) % n])
            return -FX_EINVAL;
    for (int32_t i = 0; i < n; i++)
        for (int32_t j = i + 1; j < n; j++) {
            int32_t a = vi[i], b = vi[(i + 1) % n], c = vi[j], d = vi[(j + 1) % n];
            if ((a == c && b == d) || (a == d && b == c))
                return -FX_EINVAL;
        }
    /* Newell's sums: twice the projected areas, the normal of any planar
     * polygon however its vertices turn. */
    int64_t A = 0, B = 0, C = 0, mx = 0, my = 0, mz = 0;
    for (int32_t i = 0; i < n; i++) {
        fx_vec3 p = t->vert[vi[i]].p, q = t->vert[vi[(i + 1) % n]].p;
        A += ((int64_t)p.y - q.y) * ((int64_t)p.z + q.z);
        B += ((int64_t)p.z - q.z) * ((int64_t)p.x + q.x);
        C += ((int64_t)p.x - q.x) * ((int64_t)p.y + q.y);
        mx += p.x, my += p.y, mz += p.z;
    }
    if (!A && !B && !C)
        return -FX_EDOM;
    while (iabs64(A) >= ((int64_t)1 << 31) || iabs64(B) >= ((int64_t)1 << 31) || iabs64(C) >= ((int64_t)1 << 31))
        A /= 2, B /= 2, C /= 2;
    if (!A && !B && !C)
        return -FX_EDOM;
    fx_ptab_poly P = {0, n, A, B, C, 0, color, attr};
    P.d = -(A * (mx / n) + B * (my / n) + C * (mz / n));
    uint64_t len = fx_isqrt64((uint64_t)(A * A) + (uint64_t)(B * B) + (uint64_t)(C * C)) + 1;
    for (int32_t i = 0; i < n; i++)
        if ((uint64_t)iabs64(fx_obj_side_raw(&P, t->vert[vi[i]].p)) > len * (FX16_ONE / 256))
            return -FX_EINVAL;
    int32_t fresh = 0;
    for (int32_t i = 0; i < n; i++) {
        int32_t a = vi[i], b = vi[(i + 1) % n], e = find_edge(t, a, b);
        if (e < 0)
            fresh++;
        else if (t->edge[e].v[0] == a || t->edge[e].poly[1] >= 0)
            return -FX_EINVAL;
    }
    if (t->npoly >= t->pcap || t->nedge + fresh > t->ecap || t->nuse + n > t->ucap)
        return -FX_ENOSPC;
    int32_t p = t->npoly++;
    P.first = t->nuse;
    t->poly[p] = P;
    for (int32_t i = 0; i < n; i++) {
        int32_t a = vi[i], b = vi[(i + 1) % n], e = find_edge(t, a, b);
        if (e >= 0) {
            t->edge[e].poly[1] = p;
            t->use[t->nuse++] = 2 * e + 1;
            continue;
        }
        e = t->nedge++;
        fx_ptab_edge E = {{a, b}, {p, -1}, {t->vert[a].first_edge, t->vert[b].first_edge}};
        t->edge[e] = E;
        t->vert[a].first_edge = t->vert[b].first_edge = e;
        t->use[t->nuse++] = 2 * e;
    }
    return p;
}

static int same(const fx_vec3 *a, const fx_vec3 *b) { return a->x == b->x && a->y == b->y && a->z == b->z; }

int32_t fx_ptab_from_mesh(fx_ptab *t, const fx_mesh *m, uint32_t color)
{
    if (!t || !m || !m->pos || (m->ntris && !m->tri))
        return -FX_EINVAL;
    if (t->nvert + m->nverts > t->vcap)
        return -FX_ENOSPC;
    for (int32_t i = 0; i < m->nverts; i++)
        if (!in_range(m->pos[i]))
            return -FX_EINVAL;
    int32_t base = t->nvert, skipped = 0;
    for (int32_t i = 0; i < m->nverts; i++)
        fx_ptab_add_vertex(t, m->pos[i]);
    for (int32_t i = 0; i < m->ntris; i++) {
        int32_t v[3];
        for (int k = 0; k < 3; k++) {
            if (m->tri[3 * i + k] >= (uint32_t)m->nverts)
                return -FX_EINVAL;
            v[k] = base + (int32_t)m->tri[3 * i + k];
        }
        const fx_vec3 *p0 = &m->pos[v[0] - base], *p1 = &m->pos[v[1] - base], *p2 = &m->pos[v[2] - base];
        if (same(p0, p1) || same(p1, p2) || same(p0, p2)) {
            skipped++; /* collapsed, as at a pole */
            continue;
        }
        int32_t r = fx_ptab_add_polygon(t, v, 3, color, i);
        if (r == -FX_EDOM) {
            skipped++;
            continue;
        }
        if (r < 0)
            return r;
    }
    return skipped;
}

int32_t fx_ptab_poly_vertex(const fx_ptab *t, int32_t p, int32_t k)
{
    int32_t u = t->use[t->poly[p].first + k];
    return t->edge[u >> 1].v[u & 1];
}

static int sgn(int64_t v) { return (v > 0) - (v < 0); }

int fx_ptab_side(const fx_ptab *t, int32_t p, fx_vec3 q) { return sgn(fx_obj_side_raw(&t->poly[p], q)); }

int fx_ptab_inside_convex(const fx_ptab *t, fx_vec3 q)
{
    if (t->npoly == 0)
        return 0;
    for (int32_t p = 0; p < t->npoly; p++)
        if (fx_obj_side_raw(&t->poly[p], q) >= 0)
            return 0;
    return 1;
}

/* Does the line through (y0, z0) along x meet polygon p's projection on the
 * yz plane? Crossing-number test with half-open rules, in exact integers,
 * so that of polygons sharing an edge the line meets the right ones. */
static int covers_yz(const fx_ptab *t, int32_t p, int64_t y0, int64_t z0)
{
    const fx_ptab_poly *P = &t->poly[p];
    int in = 0;
    for (int32_t k = 0; k < P->n; k++) {
        fx_vec3 a = t->vert[fx_ptab_poly_vertex(t, p, k)].p, b = t->vert[fx_ptab_poly_vertex(t, p, (k + 1) % P->n)].p;
        if ((a.z > z0) == (b.z > z0))
            continue;
        /* sign of (y at z0 - y0) times (bz - az) */
        int64_t s = ((int64_t)a.y - y0) * ((int64_t)b.z - a.z) + ((int64_t)b.y - a.y) * (z0 - a.z);
        if (b.z > a.z ? s > 0 : s < 0)
            in = !in;
    }
    return in;
}

int fx_ptab_inside(const fx_ptab *t, fx_vec3 q)
{
    int odd = 0;
    for (int32_t p = 0; p < t->npoly; p++) {
        const fx_ptab_poly *P = &t->poly[p];
        if (P->a == 0 || !covers_yz(t, p, q.y, q.z))
            continue;
        int64_t s = fx_obj_side_raw(P, q);
        if (P->a > 0 ? s < 0 : s > 0)
            odd = !odd;
    }
    return odd;
}

int fx_ptab_back_face(const fx_ptab *t, int32_t p, fx_vec3 eye) { return fx_obj_side_raw(&t->poly[p], eye) <= 0; }

int fx_ptab_back_face_dir(const fx_ptab *t, int32_t p, fx_vec3 v)
{
    const fx_ptab_poly *P = &t->poly[p];
    return P->a * v.x + P->b * v.y + P->c * v.z >= 0;
}

int32_t fx_ptab_open_edges(const fx_ptab *t)
{
    int32_t n = 0;
    for (int32_t e = 0; e < t->nedge; e++)
        n += t->edge[e].poly[1] < 0;
    return n;
}

/* ---- voxels ---- */

static int cube_ok(int32_t k, fx_vec3 org, fx16 side)
{
    return k >= 1 && k <= 8 && side > 0 && in_range(org) && org.x + (int64_t)side <= LIM &&
           org.y + (int64_t)side <= LIM && org.z + (int64_t)side <= LIM;
}

static fx16 centre(fx16 org, fx16 side, int32_t i, int32_t k)
{
    return (fx16)(org + (((2 * (int64_t)i + 1) * side) >> (k + 1)));
}

int fx_voxels_from_implicit(uint8_t *vox, int32_t k, fx_vec3 org, fx16 side,
                            fx16 (*f)(const void *user, fx_vec3 p), const void *user)
{
    if (!vox || !f || !cube_ok(k, org, side))
        return -FX_EINVAL;
    int32_t n = (int32_t)1 << k;
    for (int32_t z = 0; z < n; z++)
        for (int32_t y = 0; y < n; y++)
            for (int32_t x = 0; x < n; x++) {
                fx_vec3 c = fx_vec3_make(centre(org.x, side, x, k), centre(org.y, side, y, k), centre(org.z, side, z, k));
                vox[((size_t)z * (size_t)n + (size_t)y) * (size_t)n + (size_t)x] = f(user, c) > 0;
            }
    return 0;
}

int fx_voxels_from_ptab(uint8_t *vox, int32_t k, fx_vec3 org, fx16 side, const fx_ptab *t)
{
    if (!vox || !t || !cube_ok(k, org, side))
        return -FX_EINVAL;
    int32_t n = (int32_t)1 << k;
    for (int32_t z = 0; z < n; z++)
        for (int32_t y = 0; y < n; y++) {
            uint8_t *row = vox + ((size_t)z * (size_t)n + (size_t)y) * (size_t)n;
            int64_t cy = centre(org.y, side, y, k), cz = centre(org.z, side, z, k);
            for (int32_t x = 0; x < n; x++)
                row[x] = 0;
            /* each polygon the row's line meets flips the voxels before it */
            for (int32_t p = 0; p < t->npoly; p++) {
                const fx_ptab_poly *P = &t->poly[p];
                if (P->a == 0 || !covers_yz(t, p, cy, cz))
                    continue;
                for (int32_t x = 0; x < n; x++) {
                    int64_t s = fx_obj_side_raw(P, fx_vec3_make(centre(org.x, side, x, k), (fx16)cy, (fx16)cz));
                    if (P->a > 0 ? s < 0 : s > 0)
                        row[x] ^= 1;
                }
            }
        }
    return 0;
}
