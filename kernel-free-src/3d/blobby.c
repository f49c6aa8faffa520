/* SPDX-License-Identifier: MIT */
/* fixel — blobby objects (Wyvill's soft objects) polygonized by marching
 * tetrahedra over a caller's grid (contracts in fixel/objects.h). */
#include "fixel/objects.h"
#include "fixel/error.h"
#include "objects_int.h"

#define LIM ((int64_t)1024 * FX16_ONE)

/* d^2 / r^2 in Q30 for d^2 < r^2 (both Q32, up to 2^56). */
static int64_t ratio30(int64_t d2, int64_t r2)
{
    int sh = 0;
    while ((r2 >> sh) >= ((int64_t)1 << 32))
        sh++;
    return ((d2 >> sh) << 30) / (r2 >> sh);
}

static int64_t sq(int64_t v) { return v * v; }

/* The field in Q30: the grid keeps this precision, since where the field
 * changes slowly along an edge, a unit of Q16 would move the vertex. */
static int64_t field30(const fx_blobby *b, fx_vec3 p)
{
    int64_t f = 0;
    for (int32_t i = 0; i < b->nball; i++) {
        const fx_blob_ball *o = &b->ball[i];
        int64_t d2 = sq((int64_t)p.x - o->c.x) + sq((int64_t)p.y - o->c.y) + sq((int64_t)p.z - o->c.z);
        int64_t r2 = sq(o->r);
        if (d2 >= r2)
            continue;
        int64_t s = ratio30(d2, r2), s2 = (s * s) >> 30, s3 = (s2 * s) >> 30;
        int64_t g = (9 * ((int64_t)1 << 30) - 22 * s + 17 * s2 - 4 * s3 + 4) / 9; /* Q30, in [0, 1] */
        f += ((int64_t)o->w * g) >> 16;
    }
    return f;
}

fx16 fx_blobby_field(const fx_blobby *b, fx_vec3 p)
{
    int64_t f = (field30(b, p) + (1 << 13)) >> 14;
    return f > INT32_MAX ? INT32_MAX : f < INT32_MIN ? INT32_MIN : (fx16)f;
}

/* The field's negated gradient at p, as a unit vector: Σ w (-g'(s)) (p - c) / r^2
 * with -g'(s) = (22 - 34 s + 12 s^2) / 9 >= 0. */
static fx_vec3 normal_at(const fx_blobby *b, fx_vec3 p)
{
    int64_t n[3] = {0, 0, 0};
    for (int32_t i = 0; i < b->nball; i++) {
        const fx_blob_ball *o = &b->ball[i];
        int64_t d[3] = {(int64_t)p.x - o->c.x, (int64_t)p.y - o->c.y, (int64_t)p.z - o->c.z};
        int64_t d2 = sq(d[0]) + sq(d[1]) + sq(d[2]), r2 = sq(o->r);
        if (d2 >= r2)
            continue;
        int64_t s = ratio30(d2, r2) >> 14, s2 = (s * s) >> 16;
        int64_t gd = (22 * (int64_t)FX16_ONE - 34 * s + 12 * s2) / 9; /* Q16 */
        int64_t k = ((int64_t)o->w * gd) >> 16;                    /* Q16 */
        /* (p - c) / r in Q16 keeps the sum in range; the common 1/r of a
         * ball stays as the weight it must be. */
        for (int a = 0; a < 3; a++)
            n[a] += (k * (d[a] * 65536 / o->r) / o->r);
    }
    return fx_obj_unit64(n[0], n[1], n[2]);
}

static int valid(const fx_blobby *b)
{
    if (!b || b->nx < 1 || b->ny < 1 || b->nz < 1 || b->nx > FX_BLOBBY_MAX_GRID || b->ny > FX_BLOBBY_MAX_GRID ||
        b->nz > FX_BLOBBY_MAX_GRID || b->step <= 0 || b->iso <= 0 || b->nball < 0 ||
        b->nball > FX_BLOBBY_MAX_BALLS || (b->nball && !b->ball))
        return 0;
    const fx16 *o = &b->org.x;
    int32_t ns[3] = {b->nx, b->ny, b->nz};
    for (int a = 0; a < 3; a++)
        if (o[a] < -LIM || o[a] + (int64_t)b->step * ns[a] > LIM)
            return 0;
    for (int32_t i = 0; i < b->nball; i++) {
        const fx_blob_ball *q = &b->ball[i];
        if (q->r <= 0 || q->r > LIM || q->c.x < -LIM || q->c.x > LIM || q->c.y < -LIM || q->c.y > LIM ||
            q->c.z < -LIM || q->c.z > LIM || q->w < -64 * FX16_ONE || q->w > 64 * FX16_ONE)
            return 0;
    }
    return 1;
}

size_t fx_blobby_work_bytes(const fx_blobby *b)
{
    if (!valid(b))
        return 0;
    size_t np = (size_t)(b->nx + 1) * (size_t)(b->ny + 1) * (size_t)(b->nz + 1);
    return np * (sizeof(int64_t) + 7 * sizeof(int32_t));
}

typedef struct mt {
    const fx_blobby *b;
    fx_mesh *m;
    int64_t *field;
    int32_t *slot;
    int32_t sx, sy; /* point strides: 1, sx, sx * sy */
    int full;
} mt;

/* The vertex on the lattice edge from grid point index lo along direction
 * bits d (1..7), made once and shared. */
static int32_t edge_vertex(mt *t, int32_t lo, int d)
{
    int32_t *s = &t->slot[7 * lo + d - 1];
    if (*s >= 0)
        return *s;
    int32_t hi = lo + (d & 1) + ((d >> 1) & 1) * t->sx + ((d >> 2) & 1) * t->sx * t->sy;
    int32_t v = t->m->nverts++;
    *s = v;
    if (t->full) {
        const fx_blobby *b = t->b;
        int64_t f0 = t->field[lo], f1 = t->field[hi];
        /* from lo toward hi, whichever side is inside: the same edge gives
         * the same point from every tetrahedron. */
        int64_t fr = (((int64_t)b->iso * 16384 - f0) * 65536) / (f1 - f0); /* Q16 in [0, 1] */
        int32_t gx = lo % t->sx, gy = (lo / t->sx) % t->sy, gz = lo / (t->sx * t->sy);
        int64_t g[3] = {gx, gy, gz};
        const fx16 *org = &t->b->org.x;
        fx16 c[3];
        for (int a = 0; a < 3; a++) {
            int64_t pos = ((int64_t)g[a] << 16) + ((d >> a) & 1) * fr; /* grid units, Q16 */
            c[a] = (fx16)(org[a] + ((pos * b->step + ((int64_t)1 << 15)) >> 16));
        }
        fx_vec3 p = fx_vec3_make(c[0], c[1], c[2]);
        t->m->pos[v] = p;
        t->m->nrm[v] = normal_at(b, p);
    }
    return v;
}

static void emit(mt *t, int32_t a, int32_t b, int32_t c, int flip)
{
    fx_mesh *m = t->m;
    if (t->full) {
        uint32_t *q = &m->tri[3 * m->ntris];
        q[0] = (uint32_t)a;
        q[1] = (uint32_t)(flip ? c : b);
        q[2] = (uint32_t)(flip ? b : c);
    }
    m->ntris++;
}

static int parity(const int p[4])
{
    int inv = 0;
    for (int i = 0; i < 4; i++)
        for (int j = i + 1; j < 4; j++)
            inv += p[i] > p[j];
    return inv & 1;
}

/* Corner bits of the six tetrahedra around the diagonal 0-7 (one per order
 * of the axes), and the sign of each one's volume. */
static const int tets[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

static int tet_negative(const int c[4])
{
    int64_t v[3][3];
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 3; a++)
            v[i][a] = ((c[i + 1] >> a) & 1) - ((c[0] >> a) & 1);
    int64_t det = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) -
                  v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0]) +
                  v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
    return det < 0;
}

static int32_t corner_index(const mt *t, int32_t base, int bits)
{
    return base + (bits & 1) + ((bits >> 1) & 1) * t->sx + ((bits >> 2) & 1) * t->sx * t->sy;
}

/* The vertex on the tetrahedron edge between corners p and q (corner bits;
 * one is a subset of the other on the monotone path). */
static int32_t tv(mt *t, int32_t base, int p, int q)
{
    int lo = p < q ? p : q, hi = p < q ? q : p;
    return edge_vertex(t, corner_index(t, base, lo), hi ^ lo);
}

static void tetra(mt *t, int32_t base, const int c[4], int neg)
{
    int in[4], nin = 0;
    for (int i = 0; i < 4; i++) {
        in[i] = t->field[corner_index(t, base, c[i])] > ((int64_t)t->b->iso << 14);
        nin += in[i];
    }
    if (nin == 0 || nin == 4)
        return;
    if (nin == 1 || nin == 3) {
        /* the lone corner i; (i, j, k, l) an even order of the tetrahedron */
        int i = 0;
        while (in[i] != (nin == 1))
            i++;
        int o[4] = {i}, n = 1;
        for (int j = 0; j < 4; j++)
            if (j != i)
                o[n++] = j;
        if (parity(o)) {
            int s = o[2];
            o[2] = o[3], o[3] = s;
        }
        /* normal away from the lone corner; it must leave the inside */
        int flip = neg ^ (nin == 3);
        int32_t a = tv(t, base, c[o[0]], c[o[1]]), b = tv(t, base, c[o[0]], c[o[2]]),
                d = tv(t, base, c[o[0]], c[o[3]]);
        emit(t, a, b, d, flip);
        return;
    }
    /* two in (i, j), two out (k, l), (i, j, k, l) even: the quad
     * ik, il, jl, jk faces from i, j toward k, l */
    int o[4], n = 0;
    for (int j = 0; j < 4; j++)
        if (in[j])
            o[n++] = j;
    for (int j = 0; j < 4; j++)
        if (!in[j])
            o[n++] = j;
    if (parity(o)) {
        int s = o[2];
        o[2] = o[3], o[3] = s;
    }
    int32_t ik = tv(t, base, c[o[0]], c[o[2]]), il = tv(t, base, c[o[0]], c[o[3]]),
            jl = tv(t, base, c[o[1]], c[o[3]]), jk = tv(t, base, c[o[1]], c[o[2]]);
    emit(t, ik, il, jl, neg);
    emit(t, ik, jl, jk, neg);
}

int fx_blobby_make(fx_mesh *m, const fx_blobby *b, void *work, size_t bytes)
{
    if (!m || !valid(b) || !work || ((uintptr_t)work & 7))
        return -FX_EINVAL;
    if (bytes < fx_blobby_work_bytes(b))
        return -FX_ENOSPC;
    int full = m->pos != 0;
    if (full && (!m->nrm || !m->tri))
        return -FX_EINVAL;
    mt t = {b, m, (int64_t *)work, 0, b->nx + 1, b->ny + 1, full};
    int32_t np = (b->nx + 1) * (b->ny + 1) * (b->nz + 1);
    t.slot = (int32_t *)(t.field + np);
    for (int32_t i = 0; i < 7 * np; i++)
        t.slot[i] = -1;
    for (int32_t z = 0; z <= b->nz; z++)
        for (int32_t y = 0; y <= b->ny; y++)
            for (int32_t x = 0; x <= b->nx; x++) {
                fx_vec3 p = fx_vec3_make(b->org.x + x * b->step, b->org.y + y * b->step, b->org.z + z * b->step);
                t.field[(z * t.sy + y) * t.sx + x] = field30(b, p);
            }
    /* Count first (no writes), then fill: the capacities are known before a
     * single vertex is written. */
    int32_t cap_v = m->cap_verts, cap_t = m->cap_tris;
    int neg[6];
    for (int k = 0; k < 6; k++)
        neg[k] = tet_negative(tets[k]);
    for (int pass = full ? 0 : 1; pass < 2; pass++) {
        t.full = full && pass == 1;
        m->nverts = m->ntris = 0;
        for (int32_t i = 0; i < 7 * np; i++)
            t.slot[i] = -1;
        for (int32_t z = 0; z < b->nz; z++)
            for (int32_t y = 0; y < b->ny; y++)
                for (int32_t x = 0; x < b->nx; x++)
                    for (int k = 0; k < 6; k++)
                        tetra(&t, (z * t.sy + y) * t.sx + x, tets[k], neg[k]);
        if (full && pass == 0 && (m->nverts > cap_v || m->ntris > cap_t)) {
            m->nverts = m->ntris = 0;
            return -FX_ENOSPC;
        }
    }
    return 0;
}
