/* SPDX-License-Identifier: MIT */
/* fixel — mesh generators (solids, the teapot) and the OBJ parser, writing
 * into caller arrays (contracts in fixel/mesh.h). */
#include <stdarg.h>
#include "fixel/mesh.h"
#include "fixel/draw.h"
#include "fixel/error.h"
#include "../base/fx_internal.h"
#include "teapot_data.h"
#include "objects_int.h"

static const char *const kind_names[FX_MESH_KIND_COUNT] = {
    "cube", "tetrahedron", "octahedron", "dodecahedron", "icosahedron", "sphere",
    "ellipsoid", "torus", "cone", "cylinder", "teapot", "plane",
};

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b)
        a++, b++;
    return *a == *b;
}

fx_mesh_kind fx_mesh_kind_from_name(const char *name)
{
    for (int i = 0; i < FX_MESH_KIND_COUNT; i++)
        if (streq(name, kind_names[i]))
            return (fx_mesh_kind)i;
    return FX_MESH_KIND_COUNT;
}

int fx_mesh_size(const fx_mesh_params *p, int32_t *nv, int32_t *nt)
{
    int32_t n = p->n, k = p->k;
    int seg_ok = n >= 3 && n <= FX_MESH_MAX_SEG;
    switch (p->kind) {
    case FX_MESH_CUBE: *nv = 24, *nt = 12; return 0;
    case FX_MESH_TETRAHEDRON: *nv = 12, *nt = 4; return 0;
    case FX_MESH_OCTAHEDRON: *nv = 24, *nt = 8; return 0;
    case FX_MESH_DODECAHEDRON: *nv = 60, *nt = 36; return 0;
    case FX_MESH_ICOSAHEDRON: *nv = 60, *nt = 20; return 0;
    case FX_MESH_SPHERE:
    case FX_MESH_ELLIPSOID:
        if (!seg_ok || k < 2 || k > FX_MESH_MAX_SEG)
            return -FX_EINVAL;
        *nv = (k + 1) * (n + 1), *nt = 2 * n * (k - 1);
        return 0;
    case FX_MESH_TORUS:
        if (!seg_ok || k < 3 || k > FX_MESH_MAX_SEG)
            return -FX_EINVAL;
        *nv = n * k, *nt = 2 * n * k;
        return 0;
    case FX_MESH_CONE:
        if (!seg_ok)
            return -FX_EINVAL;
        *nv = 3 * n + 2, *nt = 2 * n;
        return 0;
    case FX_MESH_CYLINDER:
        if (!seg_ok)
            return -FX_EINVAL;
        *nv = 4 * n + 4, *nt = 4 * n;
        return 0;
    case FX_MESH_TEAPOT:
        if (n < 1 || n > 64)
            return -FX_EINVAL;
        *nv = FX_TEAPOT_PATCHES * (n + 1) * (n + 1), *nt = FX_TEAPOT_PATCHES * 2 * n * n;
        return 0;
    case FX_MESH_PLANE:
        if (n < 1 || n > FX_MESH_MAX_SEG)
            return -FX_EINVAL;
        *nv = (n + 1) * (n + 1), *nt = 2 * n * n;
        return 0;
    default:
        return -FX_EINVAL;
    }
}

/* ---- helpers ---- */

void fx_obj_put(fx_mesh *m, fx_vec3 p, fx_vec3 n)
{
    m->pos[m->nverts] = p;
    m->nrm[m->nverts] = n;
    m->nverts++;
}

/* Texture coordinates of the vertex put last (a mesh without uv ignores them). */
static void put_uv(fx_mesh *m, fx16 s, fx16 t)
{
    if (m->uv) {
        m->uv[2 * (m->nverts - 1)] = s;
        m->uv[2 * (m->nverts - 1) + 1] = t;
    }
}

void fx_obj_tri(fx_mesh *m, int32_t a, int32_t b, int32_t c)
{
    uint32_t *t = &m->tri[3 * m->ntris++];
    t[0] = (uint32_t)a;
    t[1] = (uint32_t)b;
    t[2] = (uint32_t)c;
}

void fx_obj_grid_tris(fx_mesh *m, int32_t base, int32_t n, int32_t k, int pole0, int polek)
{
    for (int32_t i = 0; i < k; i++)
        for (int32_t j = 0; j < n; j++) {
            int32_t a = base + i * (n + 1) + j, b = a + n + 1, c = b + 1, d = a + 1;
            if (!(polek && i == k - 1))
                fx_obj_tri(m, a, b, c);
            if (!(pole0 && i == 0))
                fx_obj_tri(m, a, c, d);
        }
}

void fx_obj_ring_tris(fx_mesh *m, int32_t n, int32_t k)
{
    for (int32_t i = 0; i < k; i++)
        for (int32_t j = 0; j < n; j++) {
            int32_t i1 = (i + 1) % k, j1 = (j + 1) % n;
            int32_t a = i * n + j, b = i1 * n + j, c = i1 * n + j1, d = i * n + j1;
            fx_obj_tri(m, a, b, c);
            fx_obj_tri(m, a, c, d);
        }
}

int fx_obj_mesh_begin(fx_mesh *m, int e, int32_t nv, int32_t nt)
{
    if (e < 0)
        return e;
    if (!m->pos || !m->nrm || !m->tri)
        return -FX_EINVAL;
    if (nv > m->cap_verts || nt > m->cap_tris)
        return -FX_ENOSPC;
    m->nverts = m->ntris = 0;
    return 0;
}

/* Unit normal of the 64-bit cross product a x b, for vectors too short or
 * too long for a Q16.16 cross product. Returns -FX_EDOM for parallel ones. */
static int cross_unit(fx_vec3 a, fx_vec3 b, fx_vec3 *out)
{
    int64_t c[3] = {(int64_t)a.y * b.z - (int64_t)a.z * b.y, (int64_t)a.z * b.x - (int64_t)a.x * b.z,
                    (int64_t)a.x * b.y - (int64_t)a.y * b.x};
    uint64_t m = 0;
    for (int i = 0; i < 3; i++)
        m |= c[i] < 0 ? (uint64_t)-(c[i] + 1) : (uint64_t)c[i];
    int sh = 0;
    while ((m >> sh) >= ((uint64_t)1 << 30))
        sh++;
    fx_vec3 v = fx_vec3_make((fx16)(c[0] >> sh), (fx16)(c[1] >> sh), (fx16)(c[2] >> sh));
    if (fx_vec3_normalize(&v) < 0)
        return -FX_EDOM;
    *out = v;
    return 0;
}

static fx_angle frac_angle(int32_t i, int32_t n, unsigned turn_shift)
{
    return (fx_angle)((((uint64_t)i) << turn_shift) / (uint64_t)n);
}

/* ---- Platonic solids ---- */

#define PHI 106039 /* golden ratio (1 + sqrt 5) / 2 in Q16.16, rounded */

static int unit_set(fx_vec3 *v, int n)
{
    for (int i = 0; i < n; i++)
        fx_vec3_normalize(&v[i]);
    return n;
}

static int near_edge(const fx_vec3 *v, int a, int b, int64_t e2, int64_t tol)
{
    fx_vec3 d = fx_vec3_sub(v[a], v[b]);
    int64_t l = (int64_t)d.x * d.x + (int64_t)d.y * d.y + (int64_t)d.z * d.z;
    return l > e2 - tol && l < e2 + tol;
}

/* Faces of a triangle-faced regular solid: every triple of vertices at
 * pairwise edge distance, oriented outward. Returns the face count. */
static int tri_faces(const fx_vec3 *v, int nv, int f[][3], int maxf)
{
    int64_t e2 = INT64_MAX;
    for (int i = 1; i < nv; i++) {
        fx_vec3 d = fx_vec3_sub(v[i], v[0]);
        int64_t l = (int64_t)d.x * d.x + (int64_t)d.y * d.y + (int64_t)d.z * d.z;
        if (l < e2)
            e2 = l;
    }
    int64_t tol = e2 / 64;
    int nf = 0;
    for (int i = 0; i < nv; i++)
        for (int j = i + 1; j < nv; j++) {
            if (!near_edge(v, i, j, e2, tol))
                continue;
            for (int k = j + 1; k < nv; k++) {
                if (!near_edge(v, i, k, e2, tol) || !near_edge(v, j, k, e2, tol) || nf == maxf)
                    continue;
                fx_vec3 n = fx_vec3_cross(fx_vec3_sub(v[j], v[i]), fx_vec3_sub(v[k], v[i]));
                fx_vec3 c = fx_vec3_add(fx_vec3_add(v[i], v[j]), v[k]);
                int out = ((int64_t)n.x * c.x + (int64_t)n.y * c.y + (int64_t)n.z * c.z) > 0;
                f[nf][0] = i;
                f[nf][1] = out ? j : k;
                f[nf][2] = out ? k : j;
                nf++;
            }
        }
    return nf;
}

static int icosa_verts(fx_vec3 *v)
{
    int n = 0;
    for (int s1 = -1; s1 <= 1; s1 += 2)
        for (int s2 = -1; s2 <= 1; s2 += 2) {
            v[n++] = fx_vec3_make(0, s1 * FX16_ONE, s2 * PHI);
            v[n++] = fx_vec3_make(s1 * FX16_ONE, s2 * PHI, 0);
            v[n++] = fx_vec3_make(s2 * PHI, 0, s1 * FX16_ONE);
        }
    return unit_set(v, n);
}

/* Emit each face with its own corners and its normal (the corner sum's
 * direction, exact for regular solids). */
static void emit_faces(fx_mesh *m, const fx_vec3 *v, int f[][3], int nf, fx16 a)
{
    for (int i = 0; i < nf; i++) {
        fx_vec3 n = fx_vec3_add(fx_vec3_add(v[f[i][0]], v[f[i][1]]), v[f[i][2]]);
        fx_vec3_normalize(&n);
        int32_t b = m->nverts;
        for (int k = 0; k < 3; k++)
            fx_obj_put(m, fx_vec3_scale(v[f[i][k]], a), n);
        fx_obj_tri(m, b, b + 1, b + 2);
    }
}

static void make_tri_solid(fx_mesh *m, fx_mesh_kind kind, fx16 a)
{
    fx_vec3 v[12];
    int nv = 0, f[20][3];
    if (kind == FX_MESH_TETRAHEDRON) {
        static const int8_t t[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
        for (int i = 0; i < 4; i++)
            v[nv++] = fx_vec3_make(t[i][0] * FX16_ONE, t[i][1] * FX16_ONE, t[i][2] * FX16_ONE);
    } else if (kind == FX_MESH_OCTAHEDRON) {
        for (int ax = 0; ax < 3; ax++)
            for (int s = -1; s <= 1; s += 2) {
                fx16 c[3] = {0, 0, 0};
                c[ax] = s * FX16_ONE;
                v[nv++] = fx_vec3_make(c[0], c[1], c[2]);
            }
    } else {
        nv = icosa_verts(v);
    }
    unit_set(v, nv);
    int nf = tri_faces(v, nv, f, 20);
    emit_faces(m, v, f, nf, a);
}

static void make_dodecahedron(fx_mesh *m, fx16 a)
{
    fx_vec3 iv[12], dv[20];
    int f[20][3];
    icosa_verts(iv);
    int nf = tri_faces(iv, 12, f, 20);
    /* Vertices of the dual: the icosahedron's face centres. */
    for (int i = 0; i < nf; i++) {
        dv[i] = fx_vec3_add(fx_vec3_add(iv[f[i][0]], iv[f[i][1]]), iv[f[i][2]]);
        fx_vec3_normalize(&dv[i]);
    }
    /* Faces of the dual: the five face centres around each icosahedron
     * vertex, in angular order about it (counter-clockwise from outside). */
    for (int c = 0; c < 12; c++) {
        int ring[5] = {0, 0, 0, 0, 0}, nr = 0;
        for (int i = 0; i < nf && nr < 5; i++)
            if (f[i][0] == c || f[i][1] == c || f[i][2] == c)
                ring[nr++] = i;
        fx_vec3 ax = iv[c];
        fx_vec3 e1 = fx_vec3_sub(dv[ring[0]], fx_vec3_scale(ax, fx_vec3_dot(dv[ring[0]], ax)));
        fx_vec3_normalize(&e1);
        fx_vec3 e2 = fx_vec3_cross(ax, e1);
        fx_angle ang[5];
        for (int i = 0; i < nr; i++)
            ang[i] = fx_atan2(fx_vec3_dot(dv[ring[i]], e2), fx_vec3_dot(dv[ring[i]], e1));
        for (int i = 1; i < nr; i++) /* insertion sort by angle */
            for (int j = i; j > 0 && ang[j] < ang[j - 1]; j--) {
                fx_angle t = ang[j];
                ang[j] = ang[j - 1];
                ang[j - 1] = t;
                int r = ring[j];
                ring[j] = ring[j - 1];
                ring[j - 1] = r;
            }
        int32_t b = m->nverts;
        for (int i = 0; i < 5; i++)
            fx_obj_put(m, fx_vec3_scale(dv[ring[i]], a), ax);
        for (int i = 1; i < 4; i++)
            fx_obj_tri(m, b, b + i, b + i + 1);
    }
}

static void make_cube(fx_mesh *m, fx16 a)
{
    fx16 h = a / 2;
    for (int d = 0; d < 3; d++)
        for (int s = -1; s <= 1; s += 2) {
            fx16 n[3] = {0, 0, 0}, u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
            n[d] = s * FX16_ONE;
            u[(d + 1) % 3] = FX16_ONE;
            v[(d + 2) % 3] = FX16_ONE;
            static const int8_t cu[4] = {-1, 1, 1, -1}, cv[4] = {-1, -1, 1, 1};
            int32_t b = m->nverts;
            fx_vec3 nn = fx_vec3_make(n[0], n[1], n[2]);
            for (int k = 0; k < 4; k++) {
                int kk = s > 0 ? k : 3 - k;
                fx16 c[3];
                for (int i = 0; i < 3; i++)
                    c[i] = fx16_mul(h, n[i] + cu[kk] * u[i] + cv[kk] * v[i]);
                fx_obj_put(m, fx_vec3_make(c[0], c[1], c[2]), nn);
                put_uv(m, cu[kk] > 0 ? FX16_ONE : 0, cv[kk] > 0 ? FX16_ONE : 0);
            }
            fx_obj_tri(m, b, b + 1, b + 2);
            fx_obj_tri(m, b, b + 2, b + 3);
        }
}

/* ---- curved surfaces ---- */

static void make_ellipsoid(fx_mesh *m, fx16 ra, fx16 rb, fx16 rc, int32_t n, int32_t k)
{
    for (int32_t i = 0; i <= k; i++) {
        fx_angle ph = frac_angle(i, k, 31);
        fx16 sp = fx_sin(ph), cp = fx_cos(ph);
        for (int32_t j = 0; j <= n; j++) {
            fx_angle th = frac_angle(j % n, n, 32);
            fx_vec3 u = fx_vec3_make(fx16_mul(sp, fx_sin(th)), cp, fx16_mul(sp, fx_cos(th)));
            fx_vec3 p = fx_vec3_make(fx16_mul(u.x, ra), fx16_mul(u.y, rb), fx16_mul(u.z, rc));
            /* The gradient of x^2/a^2 + ..., scaled by a b c to avoid division. */
            fx_vec3 nn = fx_vec3_make(fx16_mul(u.x, fx16_mul(rb, rc)), fx16_mul(u.y, fx16_mul(ra, rc)),
                                      fx16_mul(u.z, fx16_mul(ra, rb)));
            if (fx_vec3_normalize(&nn) < 0)
                nn = u;
            fx_obj_put(m, p, nn);
            put_uv(m, fx16_from_ratio(j, n), fx16_from_ratio(i, k));
        }
    }
    fx_obj_grid_tris(m, 0, n, k, 1, 1);
}

static void make_torus(fx_mesh *m, fx16 R, fx16 r, int32_t n, int32_t k)
{
    for (int32_t i = 0; i < k; i++) {
        fx_angle th = frac_angle(i, k, 32);
        fx_vec3 D = fx_vec3_make(fx_sin(th), 0, fx_cos(th));
        for (int32_t j = 0; j < n; j++) {
            fx_angle ph = frac_angle(j, n, 32);
            fx16 c = fx_cos(ph), s = fx_sin(ph);
            fx_vec3 nn = fx_vec3_make(fx16_mul(c, D.x), s, fx16_mul(c, D.z));
            fx_vec3 p = fx_vec3_add(fx_vec3_scale(D, R), fx_vec3_scale(nn, r));
            fx_vec3_normalize(&nn);
            fx_obj_put(m, p, nn);
        }
    }
    fx_obj_ring_tris(m, n, k);
}

static void make_cone_cyl(fx_mesh *m, fx16 ra, fx16 h, int32_t n, int cone)
{
    int32_t ring = m->nverts;
    fx_vec3 up = fx_vec3_make(0, FX16_ONE, 0), down = fx_vec3_make(0, -FX16_ONE, 0);
    /* Side: the bottom ring (with a seam vertex), then apexes or the top ring. */
    for (int32_t j = 0; j <= n; j++) {
        fx_angle th = frac_angle(j % n, n, 32);
        fx16 s = fx_sin(th), c = fx_cos(th);
        fx_vec3 nn = cone ? fx_vec3_make(fx16_mul(h, s), ra, fx16_mul(h, c)) : fx_vec3_make(s, 0, c);
        fx_vec3_normalize(&nn);
        fx_obj_put(m, fx_vec3_make(fx16_mul(ra, s), 0, fx16_mul(ra, c)), nn);
        put_uv(m, fx16_from_ratio(j, n), FX16_ONE);
    }
    int32_t top = m->nverts;
    for (int32_t j = 0; j < n + !cone; j++) {
        /* A cone's apex has no single normal: each slice gets the one
         * half-way across it. */
        fx_angle th = cone ? (fx_angle)(((2 * (uint64_t)j + 1) << 31) / (uint64_t)n)
                           : frac_angle(j % n, n, 32);
        fx16 s = fx_sin(th), c = fx_cos(th);
        fx_vec3 nn = cone ? fx_vec3_make(fx16_mul(h, s), ra, fx16_mul(h, c)) : fx_vec3_make(s, 0, c);
        fx_vec3_normalize(&nn);
        fx_vec3 p = cone ? fx_vec3_make(0, h, 0) : fx_vec3_make(fx16_mul(ra, s), h, fx16_mul(ra, c));
        fx_obj_put(m, p, nn);
        put_uv(m, cone ? (fx16)(((2 * (int64_t)j + 1) << 15) / n) : fx16_from_ratio(j, n), 0);
    }
    for (int32_t j = 0; j < n; j++) {
        if (cone) {
            fx_obj_tri(m, ring + j, ring + j + 1, top + j);
        } else {
            fx_obj_tri(m, ring + j, ring + j + 1, top + j + 1);
            fx_obj_tri(m, ring + j, top + j + 1, top + j);
        }
    }
    /* Caps: the base (facing down), and the top for a cylinder. */
    for (int capi = 0; capi < (cone ? 1 : 2); capi++) {
        fx16 y = capi ? h : 0;
        int32_t c0 = m->nverts;
        fx_obj_put(m, fx_vec3_make(0, y, 0), capi ? up : down);
        for (int32_t j = 0; j < n; j++) {
            fx_angle th = frac_angle(j, n, 32);
            fx_obj_put(m, fx_vec3_make(fx16_mul(ra, fx_sin(th)), y, fx16_mul(ra, fx_cos(th))), capi ? up : down);
        }
        for (int32_t j = 0; j < n; j++) {
            int32_t a = c0 + 1 + j, b = c0 + 1 + (j + 1) % n;
            if (capi)
                fx_obj_tri(m, c0, a, b);
            else
                fx_obj_tri(m, c0, b, a);
        }
    }
}

static void make_plane(fx_mesh *m, fx16 a, int32_t n)
{
    fx_vec3 up = fx_vec3_make(0, FX16_ONE, 0);
    for (int32_t i = 0; i <= n; i++)
        for (int32_t j = 0; j <= n; j++) {
            fx16 x = fx16_from_ratio(j, n) - FX16_HALF, z = fx16_from_ratio(i, n) - FX16_HALF;
            fx_obj_put(m, fx_vec3_make(fx16_mul(x, a), 0, fx16_mul(z, a)), up);
            put_uv(m, fx16_from_ratio(j, n), fx16_from_ratio(i, n));
        }
    for (int32_t i = 0; i < n; i++)
        for (int32_t j = 0; j < n; j++) {
            int32_t p = i * (n + 1) + j, b = p + n + 1, c = b + 1, d = p + 1;
            fx_obj_tri(m, p, b, c);
            fx_obj_tri(m, p, c, d);
        }
}

/* ---- the teapot ---- */

/* Point and tangents of patch p at (u, v), Q16.16, already y-up. */
static void patch_eval(int p, fx16 u, fx16 v, fx16 scale, fx_vec3 *pt, fx_vec3 *du, fx_vec3 *dv)
{
    int64_t wu[4], du_[4], wv[4], dv_[4];
    fx_obj_bezier_basis(u, wu, du_);
    fx_obj_bezier_basis(v, wv, dv_);
    int64_t acc[3][3] = {{0}};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            const int16_t *c = fx_teapot_points[fx_teapot_patches[p][i * 4 + j]];
            int64_t k[3] = {wu[i] * wv[j], du_[i] * wv[j], wu[i] * dv_[j]}; /* Q32 */
            for (int q = 0; q < 3; q++) {
                int64_t kk = k[q] >> 8; /* Q24 keeps the sums in range */
                acc[q][0] += kk * c[0];
                acc[q][1] += kk * c[2]; /* y-up: (x, z, -y) */
                acc[q][2] -= kk * c[1];
            }
        }
    /* acc is in 1/8000 units, Q24: to Q16.16 divide by 8000 * 2^8. */
    fx_vec3 *out[3] = {pt, du, dv};
    for (int q = 0; q < 3; q++) {
        fx16 c[3];
        for (int i = 0; i < 3; i++) {
            int64_t a = acc[q][i], den = (int64_t)FX_TEAPOT_UNIT * 256;
            c[i] = (fx16)((a >= 0 ? a + den / 2 : a - den / 2) / den);
        }
        *out[q] = fx_vec3_make(fx16_mul(c[0], scale), fx16_mul(c[1], scale), fx16_mul(c[2], scale));
    }
}

static void make_teapot(fx_mesh *m, fx16 scale, int32_t n, int (*away)(void *, const fx_vec3 *, int), void *user)
{
    for (int p = 0; p < FX_TEAPOT_PATCHES; p++) {
        if (away) {
            fx_vec3 cp[16];
            for (int i = 0; i < 16; i++) {
                const int16_t *c = fx_teapot_points[fx_teapot_patches[p][i]];
                fx16 q[3] = {fx16_from_ratio(c[0], FX_TEAPOT_UNIT), fx16_from_ratio(c[2], FX_TEAPOT_UNIT),
                             fx16_from_ratio(-c[1], FX_TEAPOT_UNIT)}; /* y-up, as patch_eval */
                cp[i] = fx_vec3_make(fx16_mul(q[0], scale), fx16_mul(q[1], scale), fx16_mul(q[2], scale));
            }
            if (away(user, cp, 16))
                continue;
        }
        int32_t b = m->nverts;
        for (int32_t i = 0; i <= n; i++)
            for (int32_t j = 0; j <= n; j++) {
                fx16 u = fx16_from_ratio(i, n), v = fx16_from_ratio(j, n);
                fx_vec3 pt, du, dv, nn;
                patch_eval(p, u, v, scale, &pt, &du, &dv);
                /* The lid's knob and the bottom collapse a patch edge to a
                 * point, where one tangent vanishes: take the normal a
                 * little way inside the patch instead. */
                if (cross_unit(dv, du, &nn) < 0) {
                    fx_vec3 p2;
                    fx16 u2 = u == 0 ? FX16_ONE / 64 : u == FX16_ONE ? FX16_ONE - FX16_ONE / 64 : u;
                    patch_eval(p, u2, v, scale, &p2, &du, &dv);
                    if (cross_unit(dv, du, &nn) < 0)
                        nn = fx_vec3_make(0, pt.y > 0x18000 ? FX16_ONE : -FX16_ONE, 0);
                }
                fx_obj_put(m, pt, nn);
                put_uv(m, u, v);
            }
        for (int32_t i = 0; i < n; i++)
            for (int32_t j = 0; j < n; j++) {
                int32_t a = b + i * (n + 1) + j, c = a + n + 2, d = a + 1, e = a + n + 1;
                /* Newell's patches run clockwise seen from outside. */
                fx_obj_tri(m, a, d, c);
                fx_obj_tri(m, a, c, e);
            }
    }
}

int fx_mesh_make_teapot(fx_mesh *m, fx16 scale, int32_t n, int (*away)(void *user, const fx_vec3 *pts, int npts),
                        void *user)
{
    fx_mesh_params p = {FX_MESH_TEAPOT, scale, 0, 0, n, 0};
    int32_t nv = 0, nt = 0;
    int e = fx_mesh_size(&p, &nv, &nt);
    e = fx_obj_mesh_begin(m, e, nv, nt);
    if (e < 0)
        return e;
    if (m->uv)
        fx_memset(m->uv, 0, sizeof(fx16) * 2 * (size_t)nv);
    make_teapot(m, scale, n, away, user);
    return 0;
}

int fx_mesh_make(fx_mesh *m, const fx_mesh_params *p)
{
    int32_t nv = 0, nt = 0;
    int e = fx_mesh_size(p, &nv, &nt);
    e = fx_obj_mesh_begin(m, e, nv, nt);
    if (e < 0)
        return e;
    if (m->uv)
        fx_memset(m->uv, 0, sizeof(fx16) * 2 * (size_t)nv);
    switch (p->kind) {
    case FX_MESH_CUBE: make_cube(m, p->a); break;
    case FX_MESH_TETRAHEDRON:
    case FX_MESH_OCTAHEDRON:
    case FX_MESH_ICOSAHEDRON: make_tri_solid(m, p->kind, p->a); break;
    case FX_MESH_DODECAHEDRON: make_dodecahedron(m, p->a); break;
    case FX_MESH_SPHERE: make_ellipsoid(m, p->a, p->a, p->a, p->n, p->k); break;
    case FX_MESH_ELLIPSOID: make_ellipsoid(m, p->a, p->b, p->c, p->n, p->k); break;
    case FX_MESH_TORUS: make_torus(m, p->a, p->b, p->n, p->k); break;
    case FX_MESH_CONE: make_cone_cyl(m, p->a, p->b, p->n, 1); break;
    case FX_MESH_CYLINDER: make_cone_cyl(m, p->a, p->b, p->n, 0); break;
    case FX_MESH_TEAPOT: make_teapot(m, p->a, p->n, NULL, NULL); break;
    case FX_MESH_PLANE: make_plane(m, p->a, p->n); break;
    default: return -FX_EINVAL;
    }
    return 0;
}

void fx_mesh_compute_normals(fx_mesh *m)
{
    if (!m->nrm)
        return;
    fx_memset(m->nrm, 0, sizeof(fx_vec3) * (size_t)m->nverts);
    for (int32_t t = 0; t < m->ntris; t++) {
        const uint32_t *ix = &m->tri[3 * t];
        fx_vec3 n;
        if (cross_unit(fx_vec3_sub(m->pos[ix[1]], m->pos[ix[0]]),
                       fx_vec3_sub(m->pos[ix[2]], m->pos[ix[0]]), &n) < 0)
            continue;
        /* Unit face normals / 16 add up exactly for any valence below 2^15;
         * beyond (an OBJ may reuse one vertex in 2^19 faces) the sums
         * saturate instead of overflowing. */
        for (int k = 0; k < 3; k++) {
            fx_vec3 *a = &m->nrm[ix[k]];
            a->x = fx_sat32((int64_t)a->x + (n.x >> 4));
            a->y = fx_sat32((int64_t)a->y + (n.y >> 4));
            a->z = fx_sat32((int64_t)a->z + (n.z >> 4));
        }
    }
    for (int32_t i = 0; i < m->nverts; i++)
        if (fx_vec3_normalize(&m->nrm[i]) < 0)
            m->nrm[i] = fx_vec3_make(0, FX16_ONE, 0);
}

/* ---- Wavefront OBJ ---- */

typedef struct objp {
    const char *p, *e; /* the current line [p, e) */
    int line;
    fx_obj_error *err;
} objp;

static int obj_fail(objp *o, const char *fmt, ...)
{
    if (o->err) {
        va_list ap;
        va_start(ap, fmt);
        o->err->line = o->line;
        int n = o->line > 0 ? fx_fmt(o->err->msg, sizeof o->err->msg, "line %d: ", o->line) : 0;
        if (n < 0 || (size_t)n >= sizeof o->err->msg)
            n = 0;
        fx_vfmt(o->err->msg + n, sizeof o->err->msg - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -FX_EBADMSG;
}

static void skip_ws(objp *o)
{
    while (o->p < o->e && (*o->p == ' ' || *o->p == '\t'))
        o->p++;
}

static int at_end(objp *o)
{
    skip_ws(o);
    return o->p >= o->e;
}

/* A decimal number with optional fraction and exponent, rounded to nearest
 * Q16.16. Up to 13 significant digits are kept (the rest cannot change a
 * Q16.16 value of an in-range coordinate by more than the rounding). */
static int obj_number(objp *o, fx16 *out)
{
    skip_ws(o);
    const char *p = o->p;
    int neg = 0;
    if (p < o->e && (*p == '-' || *p == '+'))
        neg = *p++ == '-';
    uint64_t mant = 0;
    int e10 = 0, digits = 0, sig = 0;
    while (p < o->e && *p >= '0' && *p <= '9') {
        if (sig < 13) {
            mant = mant * 10 + (uint64_t)(*p - '0');
            if (mant)
                sig++;
        } else {
            e10++;
        }
        p++, digits++;
    }
    if (p < o->e && *p == '.') {
        p++;
        while (p < o->e && *p >= '0' && *p <= '9') {
            if (sig < 13) {
                mant = mant * 10 + (uint64_t)(*p - '0');
                e10--;
                if (mant)
                    sig++;
            }
            p++, digits++;
        }
    }
    if (!digits)
        return obj_fail(o, "expected a number");
    if (p < o->e && (*p == 'e' || *p == 'E')) {
        p++;
        int eneg = 0, ed = 0, ev = 0;
        if (p < o->e && (*p == '-' || *p == '+'))
            eneg = *p++ == '-';
        while (p < o->e && *p >= '0' && *p <= '9') {
            if (ev < 1000)
                ev = ev * 10 + (*p - '0');
            p++, ed++;
        }
        if (!ed)
            return obj_fail(o, "malformed exponent");
        e10 += eneg ? -ev : ev;
    }
    if (p < o->e && *p != ' ' && *p != '\t' && *p != '/')
        return obj_fail(o, "malformed number");
    o->p = p;
    uint64_t v;
    const uint64_t lim = (uint64_t)32767 << 16;
    if (mant == 0) {
        v = 0;
    } else if (e10 >= 0) {
        v = mant << 16;
        for (int i = 0; i < e10; i++) {
            if (v > lim)
                break;
            v *= 10;
        }
    } else {
        uint64_t num = mant << 16, den = 1;
        int k = -e10;
        while (k > 18) { /* far below 2^-16: only the rounding is left */
            num /= 10;
            k--;
        }
        for (int i = 0; i < k; i++)
            den *= 10;
        v = (num + den / 2) / den;
    }
    if (v > lim)
        return obj_fail(o, "number out of range (|v| > 32767)");
    *out = neg ? -(fx16)v : (fx16)v;
    return 0;
}

static int obj_index(objp *o, int32_t count, const char *what, int32_t *out)
{
    const char *p = o->p;
    int neg = 0;
    if (p < o->e && *p == '-')
        neg = 1, p++;
    int64_t v = 0;
    int d = 0;
    while (p < o->e && *p >= '0' && *p <= '9') {
        if (v < ((int64_t)1 << 40))
            v = v * 10 + (*p - '0');
        p++, d++;
    }
    if (!d)
        return obj_fail(o, "expected a %s index", what);
    o->p = p;
    if (neg)
        v = count - v + 1;
    if (v < 1 || v > count)
        return obj_fail(o, "%s index %s%lld out of range (1..%d)", what, neg ? "-" : "",
                        (long long)(neg ? count + 1 - v : v), count);
    *out = (int32_t)(v - 1);
    return 0;
}

static int word_is(const char *p, const char *e, const char *w)
{
    while (*w && p < e && *p == *w)
        p++, w++;
    return !*w && (p == e || *p == ' ' || *p == '\t');
}

static int obj_run(const char *text, size_t len, fx_mesh *m, int32_t *nv_out, int32_t *nt_out,
                   fx_obj_error *err)
{
    objp o;
    o.err = err;
    o.line = 0;
    int32_t nv = 0, nn = 0, nt = 0, ntri = 0;
    const char *t = text, *end = text + len;
    if (err) {
        err->line = 0;
        err->msg[0] = 0;
    }
    while (t < end) {
        const char *le = t;
        while (le < end && *le != '\n')
            le++;
        o.line++;
        o.p = t;
        o.e = le > t && le[-1] == '\r' ? le - 1 : le;
        for (const char *c = o.p; c < o.e; c++)
            if (*c == '#') {
                o.e = c;
                break;
            }
        t = le < end ? le + 1 : le;
        skip_ws(&o);
        if (o.p >= o.e)
            continue;
        const char *w = o.p;
        while (o.p < o.e && *o.p != ' ' && *o.p != '\t')
            o.p++;
        if (word_is(w, o.e, "v")) {
            fx16 c[3];
            for (int i = 0; i < 3; i++)
                if (obj_number(&o, &c[i]) < 0)
                    return -FX_EBADMSG;
            if (!at_end(&o)) { /* optional w */
                fx16 wv;
                if (obj_number(&o, &wv) < 0)
                    return -FX_EBADMSG;
            }
            if (!at_end(&o))
                return obj_fail(&o, "too many values for 'v'");
            if (nv == INT32_MAX / 4)
                return obj_fail(&o, "too many vertices");
            if (m) {
                if (nv >= m->cap_verts)
                    return -FX_ENOSPC;
                m->pos[nv] = fx_vec3_make(c[0], c[1], c[2]);
            }
            nv++;
        } else if (word_is(w, o.e, "vn") || word_is(w, o.e, "vt")) {
            int isn = w[1] == 'n', k = 0;
            while (!at_end(&o)) {
                fx16 c;
                if (obj_number(&o, &c) < 0)
                    return -FX_EBADMSG;
                k++;
            }
            if (isn ? k != 3 : (k < 1 || k > 3))
                return obj_fail(&o, "'%s' needs %s values, got %d", isn ? "vn" : "vt", isn ? "3" : "1 to 3", k);
            if (isn)
                nn++;
            else
                nt++;
        } else if (word_is(w, o.e, "f")) {
            int32_t first = -1, prev = -1, corners = 0;
            while (!at_end(&o)) {
                int32_t vi, dummy;
                if (obj_index(&o, nv, "vertex", &vi) < 0)
                    return -FX_EBADMSG;
                if (o.p < o.e && *o.p == '/') {
                    o.p++;
                    if (o.p < o.e && *o.p != '/' && obj_index(&o, nt, "texture", &dummy) < 0)
                        return -FX_EBADMSG;
                    if (o.p < o.e && *o.p == '/') {
                        o.p++;
                        if (obj_index(&o, nn, "normal", &dummy) < 0)
                            return -FX_EBADMSG;
                    }
                }
                if (o.p < o.e && *o.p != ' ' && *o.p != '\t')
                    return obj_fail(&o, "malformed face corner");
                corners++;
                if (corners == 1)
                    first = vi;
                else if (corners >= 3) {
                    if (m) {
                        if (ntri >= m->cap_tris)
                            return -FX_ENOSPC;
                        m->tri[3 * ntri] = (uint32_t)first;
                        m->tri[3 * ntri + 1] = (uint32_t)prev;
                        m->tri[3 * ntri + 2] = (uint32_t)vi;
                    }
                    if (ntri == INT32_MAX / 4)
                        return obj_fail(&o, "too many faces");
                    ntri++;
                }
                prev = vi;
            }
            if (corners < 3)
                return obj_fail(&o, "a face needs at least 3 corners, got %d", corners);
        } else if (word_is(w, o.e, "o") || word_is(w, o.e, "g") || word_is(w, o.e, "s") ||
                   word_is(w, o.e, "usemtl") || word_is(w, o.e, "mtllib") || word_is(w, o.e, "l") ||
                   word_is(w, o.e, "p")) {
            continue;
        } else {
            int n = (int)(o.p - w);
            return obj_fail(&o, "unknown statement '%.*s'", n > 20 ? 20 : n, w);
        }
    }
    if (nv == 0 || ntri == 0) {
        o.line = 0; /* a property of the whole file, not of a line ("line 0: no vertices") */
        return obj_fail(&o, "no %s in the file%s", nv == 0 ? "vertices" : "faces", len == 0 ? " (it is empty)" : "");
    }
    *nv_out = nv;
    *nt_out = ntri;
    if (m) {
        m->nverts = nv;
        m->ntris = ntri;
        fx_mesh_compute_normals(m);
    }
    return 0;
}

int fx_mesh_obj_size(const char *text, size_t len, int32_t *nverts, int32_t *ntris, fx_obj_error *err)
{
    return obj_run(text, len, NULL, nverts, ntris, err);
}

int fx_mesh_obj_parse(fx_mesh *m, const char *text, size_t len, fx_obj_error *err)
{
    int32_t nv, nt;
    if (!m->pos || !m->tri)
        return -FX_EINVAL;
    return obj_run(text, len, m, &nv, &nt, err);
}
