/* SPDX-License-Identifier: MIT */
/* Tests of the course's remaining objects (fixel/objects.h): quadrics and
 * superquadrics, blobby objects, bicubic patches. Every vertex is checked
 * against a double-precision reference computed here from the definitions
 * (not from the code under test); closed shapes must be watertight (every
 * directed edge met once by its reverse, vertices matched by position);
 * normals must be unit and point out.
 *
 * Tolerances: quadric vertices within 2^-12 of the double point at the same
 * parameters (units of the shape's size 1..3), superquadrics within 2^-11
 * (the fixed-point power); normals within 0.5 degree of the double normal
 * (cos > 0.99996); patch points within 2^-13, normals within 0.5 degree;
 * blob vertices within 2^-12 of the double linear interpolation along
 * their lattice edge (the method), and, from that interpolation, within
 * step/8 of the true iso-surface for these blobs. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/mesh.h"
#include "fixel/objects.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define D(v) ((v) / 65536.0)

static const double PI = 3.14159265358979323846;

static int alloc_mesh(fx_mesh *m, int32_t nv, int32_t nt)
{
    memset(m, 0, sizeof *m);
    m->pos = calloc((size_t)nv + 1, sizeof(fx_vec3));
    m->nrm = calloc((size_t)nv + 1, sizeof(fx_vec3));
    m->tri = calloc((size_t)nt * 3 + 1, sizeof(uint32_t));
    m->cap_verts = nv;
    m->cap_tris = nt;
    return m->pos && m->nrm && m->tri;
}

static void free_mesh(fx_mesh *m)
{
    free(m->pos);
    free(m->nrm);
    free(m->tri);
}

/* ---- watertightness ---- */

typedef struct pidx {
    fx_vec3 p;
    int32_t i;
} pidx;

static int cmp_pidx(const void *a, const void *b)
{
    const pidx *x = a, *y = b;
    if (x->p.x != y->p.x)
        return x->p.x < y->p.x ? -1 : 1;
    if (x->p.y != y->p.y)
        return x->p.y < y->p.y ? -1 : 1;
    if (x->p.z != y->p.z)
        return x->p.z < y->p.z ? -1 : 1;
    return 0;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static int count_edge(const uint64_t *e, size_t n, uint64_t key)
{
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (e[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    int c = 0;
    while (lo < n && e[lo] == key)
        c++, lo++;
    return c;
}

/* Directed edges that are not met exactly once by their reverse (and met
 * only once themselves); by_pos: vertices with equal positions are one.
 * Triangles that collapse (two corners the same) are left out. */
static int open_edges(const fx_mesh *m, int by_pos)
{
    int32_t *id = malloc(sizeof(int32_t) * (size_t)m->nverts);
    if (by_pos) {
        pidx *s = malloc(sizeof(pidx) * (size_t)m->nverts);
        for (int32_t i = 0; i < m->nverts; i++)
            s[i].p = m->pos[i], s[i].i = i;
        qsort(s, (size_t)m->nverts, sizeof *s, cmp_pidx);
        int32_t cur = -1;
        for (int32_t i = 0; i < m->nverts; i++) {
            if (i == 0 || cmp_pidx(&s[i], &s[i - 1]))
                cur++;
            id[s[i].i] = cur;
        }
        free(s);
    } else {
        for (int32_t i = 0; i < m->nverts; i++)
            id[i] = i;
    }
    uint64_t *e = malloc(sizeof(uint64_t) * 3 * (size_t)m->ntris + 1);
    size_t ne = 0;
    for (int32_t t = 0; t < m->ntris; t++) {
        uint32_t a = (uint32_t)id[m->tri[3 * t]], b = (uint32_t)id[m->tri[3 * t + 1]], c = (uint32_t)id[m->tri[3 * t + 2]];
        if (a == b || b == c || a == c)
            continue;
        e[ne++] = (uint64_t)a << 32 | b;
        e[ne++] = (uint64_t)b << 32 | c;
        e[ne++] = (uint64_t)c << 32 | a;
    }
    qsort(e, ne, sizeof *e, cmp_u64);
    int bad = 0;
    for (size_t i = 0; i < ne; i++) {
        uint64_t rev = (e[i] << 32) | (e[i] >> 32);
        bad += count_edge(e, ne, e[i]) != 1 || count_edge(e, ne, rev) != 1;
    }
    free(e);
    free(id);
    return bad;
}

static double volume(const fx_mesh *m)
{
    double v = 0;
    for (int32_t t = 0; t < m->ntris; t++) {
        const fx_vec3 *a = &m->pos[m->tri[3 * t]], *b = &m->pos[m->tri[3 * t + 1]], *c = &m->pos[m->tri[3 * t + 2]];
        double ax = D(a->x), ay = D(a->y), az = D(a->z), bx = D(b->x), by = D(b->y), bz = D(b->z);
        double cx = D(c->x), cy = D(c->y), cz = D(c->z);
        v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return v / 6;
}

static int normals_unit(const fx_mesh *m)
{
    int bad = 0;
    for (int32_t i = 0; i < m->nverts; i++) {
        double l = sqrt(D(m->nrm[i].x) * D(m->nrm[i].x) + D(m->nrm[i].y) * D(m->nrm[i].y) +
                        D(m->nrm[i].z) * D(m->nrm[i].z));
        bad += fabs(l - 1) > 1.0 / 4096;
    }
    return bad;
}

/* Faces whose geometric normal points against their corners' normals. */
static int faces_against_normals(const fx_mesh *m)
{
    int bad = 0;
    for (int32_t t = 0; t < m->ntris; t++) {
        const uint32_t *q = &m->tri[3 * t];
        const fx_vec3 *a = &m->pos[q[0]], *b = &m->pos[q[1]], *c = &m->pos[q[2]];
        double e1[3] = {D(b->x - a->x), D(b->y - a->y), D(b->z - a->z)};
        double e2[3] = {D(c->x - a->x), D(c->y - a->y), D(c->z - a->z)};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double s = 0;
        for (int k = 0; k < 3; k++)
            s += n[0] * D(m->nrm[q[k]].x) + n[1] * D(m->nrm[q[k]].y) + n[2] * D(m->nrm[q[k]].z);
        bad += s < 0;
    }
    return bad;
}

static double angle_cos(fx_vec3 n, const double r[3])
{
    double l = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    double nl = sqrt(D(n.x) * D(n.x) + D(n.y) * D(n.y) + D(n.z) * D(n.z));
    return (D(n.x) * r[0] + D(n.y) * r[1] + D(n.z) * r[2]) / (l * nl);
}

/* ---- quadric references ---- */

static double spow(double x, double e)
{
    if (x == 0)
        return 0;
    return x < 0 ? -pow(-x, e) : pow(x, e);
}

/* The double point and normal of side vertex (i, j) of a shape of
 * revolution, or of grid vertex (i, j) of a superquadric. sheet: +1/-1. */
static void quadric_ref(const fx_quadric *q, int sheet, int i, int j, double p[3], double n[3])
{
    double a = D(q->a), b = D(q->b), c = D(q->c), h = D(q->h), e1 = D(q->e1), e2 = D(q->e2);
    int N = q->n, K = q->k;
    double th = 2 * PI * (j % N) / N, s = sin(th), co = cos(th);
    switch (q->kind) {
    case FX_QUADRIC_PARABOLOID: {
        double r = 1 - (double)i / K;
        p[0] = a * r * s, p[1] = h * r * r, p[2] = b * r * co;
        n[0] = 2 * h * p[0] / (a * a), n[1] = -1, n[2] = 2 * h * p[2] / (b * b);
        return;
    }
    case FX_QUADRIC_HYPERBOLOID1: {
        double y = h - 2 * h * i / K, r = sqrt(1 + y * y / (c * c));
        p[0] = a * r * s, p[1] = y, p[2] = b * r * co;
        n[0] = p[0] / (a * a), n[1] = -y / (c * c), n[2] = p[2] / (b * b);
        return;
    }
    case FX_QUADRIC_HYPERBOLOID2: {
        double rmax = sqrt(h * h / (c * c) - 1);
        int jj = sheet > 0 ? i : K - i;
        double rho = rmax * (1 - (double)jj / K), y = sheet * c * sqrt(1 + rho * rho);
        p[0] = a * rho * s, p[1] = y, p[2] = b * rho * co;
        n[0] = p[0] / (a * a), n[1] = -y / (c * c), n[2] = p[2] / (b * b);
        return;
    }
    case FX_QUADRIC_SUPERELLIPSOID: {
        double ph = PI * i / K, sp = sin(ph), cp = cos(ph);
        if (i * 2 == K)
            cp = 0;
        if (i == K)
            sp = 0;
        if ((j % N) * 2 == N)
            s = 0;
        if ((j % N) * 4 == N || (j % N) * 4 == 3 * N)
            co = 0;
        p[0] = a * spow(sp, e1) * spow(s, e2), p[1] = b * spow(cp, e1), p[2] = c * spow(sp, e1) * spow(co, e2);
        n[0] = spow(sp, 2 - e1) * spow(s, 2 - e2) / a, n[1] = spow(cp, 2 - e1) / b,
        n[2] = spow(sp, 2 - e1) * spow(co, 2 - e2) / c;
        return;
    }
    default: { /* supertoroid: vertex index i * n + j, i the ring, j the side */
        double t = 2 * PI * i / K, st = sin(t), ct = cos(t), ph = 2 * PI * j / N, sp = sin(ph), cp = cos(ph);
        if (i * 2 == K)
            st = 0;
        if (i * 4 == K || i * 4 == 3 * K)
            ct = 0;
        if (j * 2 == N)
            sp = 0;
        if (j * 4 == N || j * 4 == 3 * N)
            cp = 0;
        double rr = a + b * spow(cp, e1);
        p[0] = rr * spow(st, e2), p[1] = b * spow(sp, e1), p[2] = rr * spow(ct, e2);
        n[0] = spow(cp, 2 - e1) * spow(st, 2 - e2), n[1] = spow(sp, 2 - e1), n[2] = spow(cp, 2 - e1) * spow(ct, 2 - e2);
        return;
    }
    }
}

typedef struct qcase {
    fx_quadric q;
    const char *name;
    double vol, voltol, ptol;
} qcase;

static void check_quadric(const qcase *c)
{
    const fx_quadric *q = &c->q;
    int32_t nv, nt;
    FX_CHECK_EQ(fx_quadric_size(q, &nv, &nt), 0);
    fx_mesh m;
    FX_CHECK(alloc_mesh(&m, nv, nt));
    FX_CHECK_EQ(fx_quadric_make(&m, q), 0);
    FX_CHECK_EQ(m.nverts, nv);
    FX_CHECK_EQ(m.ntris, nt);
    int bad_idx = 0;
    for (int32_t i = 0; i < 3 * m.ntris; i++)
        bad_idx += m.tri[i] >= (uint32_t)m.nverts;
    FX_CHECK_MSG(bad_idx == 0, "%s: %d indices out of range", c->name, bad_idx);
    if (bad_idx) {
        free_mesh(&m);
        return;
    }
    /* side vertices against the reference */
    double worst = 0, worst_cos = 1;
    int N = q->n, K = q->k;
    int sides = q->kind == FX_QUADRIC_HYPERBOLOID2 ? 2 : 1;
    int32_t side_len = q->kind == FX_QUADRIC_SUPERTOROID ? N * K : (K + 1) * (N + 1);
    int32_t stride = q->kind == FX_QUADRIC_HYPERBOLOID2 ? side_len + 1 + N : 0;
    for (int sh = 0; sh < sides; sh++)
        for (int32_t v = 0; v < side_len; v++) {
            int32_t idx = sh * stride + v;
            int i = q->kind == FX_QUADRIC_SUPERTOROID ? v / N : v / (N + 1);
            int j = q->kind == FX_QUADRIC_SUPERTOROID ? v % N : v % (N + 1);
            double p[3], n[3];
            quadric_ref(q, sh ? -1 : 1, i, j, p, n);
            double d = fmax(fabs(D(m.pos[idx].x) - p[0]), fmax(fabs(D(m.pos[idx].y) - p[1]), fabs(D(m.pos[idx].z) - p[2])));
            worst = fmax(worst, d);
            if (n[0] != 0 || n[1] != 0 || n[2] != 0)
                worst_cos = fmin(worst_cos, angle_cos(m.nrm[idx], n));
        }
    FX_CHECK_MSG(worst <= c->ptol, "%s: a vertex %g off its point (tolerance %g)", c->name, worst, c->ptol);
    FX_CHECK_MSG(worst_cos > 0.99996, "%s: a normal off by %g degrees", c->name, acos(worst_cos) * 180 / PI);
    FX_CHECK_MSG(normals_unit(&m) == 0, "%s: %d normals not unit", c->name, normals_unit(&m));
    int open = open_edges(&m, 1);
    FX_CHECK_MSG(open == 0, "%s: %d open edges", c->name, open);
    int against = faces_against_normals(&m);
    FX_CHECK_MSG(against == 0, "%s: %d faces against their normals", c->name, against);
    double v = volume(&m);
    FX_CHECK_MSG(fabs(v - c->vol) <= c->vol * c->voltol, "%s: volume %f, want %f", c->name, v, c->vol);
    free_mesh(&m);
}

/* Barr's superellipsoid volume: 2 a b c e1 e2 B(e1/2 + 1, e1) B(e2/2, e2/2). */
static double beta(double x, double y) { return exp(lgamma(x) + lgamma(y) - lgamma(x + y)); }
static double se_volume(double a, double b, double c, double e1, double e2)
{
    return 2 * a * b * c * e1 * e2 * beta(e1 / 2 + 1, e1) * beta(e2 / 2, e2 / 2);
}

FX_TEST(objects_quadrics_lie_on_their_surfaces_closed_and_outward)
{
    double a = 1.5, b = 1, c = 0.75, h = 2;
    double hyp1 = PI * a * b * (2 * h + 2 * h * h * h / (3 * c * c));
    double hyp2 = 2 * PI * a * b * ((h * h * h - c * c * c) / (3 * c * c) - (h - c));
    qcase cs[] = {
        {{FX_QUADRIC_PARABOLOID, 3 * ONE / 2, ONE, 0, 2 * ONE, 0, 0, 48, 24}, "paraboloid", PI * a * b * h / 2, 0.01,
         1.0 / 4096},
        {{FX_QUADRIC_HYPERBOLOID1, 3 * ONE / 2, ONE, 3 * ONE / 4, 2 * ONE, 0, 0, 48, 32}, "hyperboloid1", hyp1, 0.01,
         1.0 / 4096},
        {{FX_QUADRIC_HYPERBOLOID2, 3 * ONE / 2, ONE, 3 * ONE / 4, 2 * ONE, 0, 0, 48, 24}, "hyperboloid2", hyp2, 0.02,
         1.0 / 4096},
        {{FX_QUADRIC_SUPERELLIPSOID, ONE, 3 * ONE / 2, 2 * ONE, 0, ONE, ONE, 48, 32}, "superellipsoid 1 1",
         se_volume(1, 1.5, 2, 1, 1), 0.01, 1.0 / 2048},
        {{FX_QUADRIC_SUPERELLIPSOID, ONE, 3 * ONE / 2, 2 * ONE, 0, ONE / 4, ONE / 2, 64, 48}, "superellipsoid .25 .5",
         se_volume(1, 1.5, 2, 0.25, 0.5), 0.03, 1.0 / 2048},
        {{FX_QUADRIC_SUPERELLIPSOID, ONE, ONE, ONE, 0, 2 * ONE, 3 * ONE / 2, 48, 32}, "superellipsoid 2 1.5",
         se_volume(1, 1, 1, 2, 1.5), 0.03, 1.0 / 2048},
        {{FX_QUADRIC_SUPERTOROID, 2 * ONE, ONE / 2, 0, 0, ONE, ONE, 24, 48}, "supertoroid 1 1",
         2 * PI * PI * 2 * 0.25, 0.03, 1.0 / 2048},
        {{FX_QUADRIC_SUPERTOROID, 2 * ONE, 3 * ONE / 4, 0, 0, ONE / 3, 3 * ONE / 2, 32, 48}, "supertoroid .33 1.5",
         0, 1e9, 1.0 / 2048},
    };
    for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++) {
        if (cs[i].vol == 0) {
            /* no closed form: a volume that is positive and below the
             * bounding ring's */
            cs[i].vol = 2 * PI * 2 * 2 * 0.75 * 0.75;
            cs[i].voltol = 1;
        }
        check_quadric(&cs[i]);
    }
}

FX_TEST(objects_superellipsoid_1_1_is_the_ellipsoid)
{
    fx_quadric q = {FX_QUADRIC_SUPERELLIPSOID, ONE, 2 * ONE, 3 * ONE, 0, ONE, ONE, 24, 12};
    fx_mesh_params p = {FX_MESH_ELLIPSOID, ONE, 2 * ONE, 3 * ONE, 24, 12};
    int32_t nv, nt, nv2, nt2;
    FX_CHECK_EQ(fx_quadric_size(&q, &nv, &nt), 0);
    FX_CHECK_EQ(fx_mesh_size(&p, &nv2, &nt2), 0);
    FX_CHECK_EQ(nv, nv2);
    FX_CHECK_EQ(nt, nt2);
    fx_mesh a, b;
    FX_CHECK(alloc_mesh(&a, nv, nt) && alloc_mesh(&b, nv, nt));
    FX_CHECK_EQ(fx_quadric_make(&a, &q), 0);
    FX_CHECK_EQ(fx_mesh_make(&b, &p), 0);
    int32_t worst = 0;
    for (int32_t i = 0; i < nv; i++) {
        int32_t d[3] = {a.pos[i].x - b.pos[i].x, a.pos[i].y - b.pos[i].y, a.pos[i].z - b.pos[i].z};
        for (int k = 0; k < 3; k++)
            worst = abs(d[k]) > worst ? abs(d[k]) : worst;
    }
    FX_CHECK_MSG(worst <= 8, "superellipsoid 1 1 off the ellipsoid by %d units of 2^-16", worst);
    FX_CHECK_EQ(memcmp(a.tri, b.tri, sizeof(uint32_t) * 3 * (size_t)nt), 0);
    free_mesh(&a);
    free_mesh(&b);
}

FX_TEST(objects_quadric_parameters_are_checked)
{
    int32_t nv, nt;
    fx_quadric bad[] = {
        {FX_QUADRIC_PARABOLOID, 0, ONE, 0, ONE, 0, 0, 8, 8},
        {FX_QUADRIC_PARABOLOID, ONE, ONE, 0, ONE, 0, 0, 2, 8},
        {FX_QUADRIC_HYPERBOLOID2, ONE, ONE, ONE, ONE, 0, 0, 8, 8},          /* h <= c */
        {FX_QUADRIC_HYPERBOLOID1, 1000 * ONE, ONE, ONE / 16, 64 * ONE, 0, 0, 8, 8}, /* rim beyond 1024 */
        {FX_QUADRIC_SUPERELLIPSOID, ONE, ONE, ONE, 0, ONE / 20, ONE, 8, 8},  /* exponent below 0.1 */
        {FX_QUADRIC_SUPERTOROID, ONE, ONE, 0, 0, ONE, 3 * ONE, 8, 8},        /* exponent above 2 */
        {FX_QUADRIC_SUPERTOROID, ONE, ONE, 0, 0, ONE, ONE, 8, 2},            /* 2 rings */
        {FX_QUADRIC_KIND_COUNT, ONE, ONE, ONE, ONE, ONE, ONE, 8, 8},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        FX_CHECK_MSG(fx_quadric_size(&bad[i], &nv, &nt) == -FX_EINVAL, "bad case %zu accepted", i);
    fx_quadric q = {FX_QUADRIC_PARABOLOID, ONE, ONE, 0, ONE, 0, 0, 8, 8};
    fx_mesh m;
    FX_CHECK_EQ(fx_quadric_size(&q, &nv, &nt), 0);
    FX_CHECK(alloc_mesh(&m, nv - 1, nt));
    FX_CHECK_EQ(fx_quadric_make(&m, &q), -FX_ENOSPC);
    free_mesh(&m);
}

FX_TEST(objects_signed_pow_agrees_with_double)
{
    double worst = 0;
    for (int32_t x = -ONE; x <= ONE; x += 97)
        for (int32_t e = 0; e <= 4 * ONE; e += 1311) {
            double r = spow(D(x), D(e)), got = D(fx_signed_pow(x, e));
            if (x == 0)
                r = 0;
            double err = fabs(got - r) - fabs(r) / 16384;
            worst = fmax(worst, err);
        }
    FX_CHECK_MSG(worst <= 2.0 / 65536, "signed_pow beyond 2^-14 relative + 2 units: %g", worst);
    FX_CHECK_EQ(fx_signed_pow(ONE, 3 * ONE / 2), ONE);
    FX_CHECK_EQ(fx_signed_pow(-ONE / 4, ONE / 2), -ONE / 2);
    FX_CHECK_EQ(fx_signed_pow(ONE / 2, 0), ONE);
}

/* ---- patches ---- */

static void bspl_d(double t, double w[4], double d[4])
{
    double s = 1 - t;
    w[0] = s * s * s / 6, w[1] = (3 * t * t * t - 6 * t * t + 4) / 6, w[2] = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
    w[3] = t * t * t / 6;
    d[0] = -s * s / 2, d[1] = (3 * t * t - 4 * t) / 2, d[2] = (-3 * t * t + 2 * t + 1) / 2, d[3] = t * t / 2;
}

/* de Casteljau on 4 points, the point and the derivative. */
static void casteljau(const double p[4][3], double t, double out[3], double der[3])
{
    double q[4][3];
    memcpy(q, p, sizeof q);
    for (int r = 3; r >= 1; r--) {
        if (r == 1)
            for (int k = 0; k < 3; k++)
                der[k] = 3 * (q[1][k] - q[0][k]);
        for (int i = 0; i < r; i++)
            for (int k = 0; k < 3; k++)
                q[i][k] = (1 - t) * q[i][k] + t * q[i + 1][k];
    }
    memcpy(out, q[0], sizeof(double) * 3);
}

/* The Bézier patch by repeated de Casteljau (rows in u, then v), and its
 * tangents. */
static void bezier_ref(const fx_vec3 P[16], double u, double v, double pt[3], double du[3], double dv[3])
{
    double col[4][3], dcol[4][3];
    for (int j = 0; j < 4; j++) {
        double line[4][3];
        for (int i = 0; i < 4; i++)
            line[i][0] = D(P[i * 4 + j].x), line[i][1] = D(P[i * 4 + j].y), line[i][2] = D(P[i * 4 + j].z);
        casteljau(line, u, col[j], dcol[j]);
    }
    casteljau(col, v, pt, dv);
    double t[3];
    casteljau(dcol, v, du, t);
}

static void bspline_ref(const fx_vec3 P[16], double u, double v, double pt[3], double du[3], double dv[3])
{
    double wu[4], dwu[4], wv[4], dwv[4];
    bspl_d(u, wu, dwu);
    bspl_d(v, wv, dwv);
    for (int k = 0; k < 3; k++)
        pt[k] = du[k] = dv[k] = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double c[3] = {D(P[i * 4 + j].x), D(P[i * 4 + j].y), D(P[i * 4 + j].z)};
            for (int k = 0; k < 3; k++) {
                pt[k] += wu[i] * wv[j] * c[k];
                du[k] += dwu[i] * wv[j] * c[k];
                dv[k] += wu[i] * dwv[j] * c[k];
            }
        }
}

FX_TEST(objects_patches_agree_with_de_casteljau_and_the_basis)
{
    uint32_t seed = 12345;
    double worst_p = 0, worst_c = 1;
    for (int trial = 0; trial < 40; trial++) {
        fx_vec3 P[16];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) {
                /* a bumpy sheet over the xz square, size up to 100 */
                int32_t sc = trial < 20 ? ONE : 100 * ONE;
                int32_t bump = (int32_t)(fx_test_rand(&seed) % (uint32_t)ONE) - ONE / 2;
                P[i * 4 + j] = fx_vec3_make((fx16)((int64_t)i * sc / 3), (fx16)((int64_t)bump * (sc / ONE)),
                                            (fx16)((int64_t)j * sc / 3));
            }
        fx_patch_basis basis = trial & 1 ? FX_PATCH_BSPLINE : FX_PATCH_BEZIER;
        double scale = trial < 20 ? 1 : 100;
        for (int a = 0; a <= 8; a++)
            for (int b = 0; b <= 8; b++) {
                fx16 u = a * ONE / 8, v = b * ONE / 8;
                fx_vec3 p, n;
                FX_CHECK_EQ(fx_patch_eval(P, basis, u, v, &p, &n), 0);
                double rp[3], du[3], dv[3];
                if (basis == FX_PATCH_BEZIER)
                    bezier_ref(P, D(u), D(v), rp, du, dv);
                else
                    bspline_ref(P, D(u), D(v), rp, du, dv);
                double e = fmax(fabs(D(p.x) - rp[0]), fmax(fabs(D(p.y) - rp[1]), fabs(D(p.z) - rp[2]))) / scale;
                worst_p = fmax(worst_p, e);
                double rn[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
                worst_c = fmin(worst_c, angle_cos(n, rn));
            }
    }
    FX_CHECK_MSG(worst_p <= 1.0 / 8192, "patch point off the reference by %g (relative)", worst_p);
    FX_CHECK_MSG(worst_c > 0.99996, "patch normal off by %g degrees", acos(worst_c) * 180 / PI);

    /* a Bézier patch interpolates its corners, a B-spline patch does not */
    fx_vec3 P[16];
    for (int i = 0; i < 16; i++)
        P[i] = fx_vec3_make((i / 4) * ONE, (i * 7 % 5) * ONE / 4, (i % 4) * ONE);
    fx_vec3 p, n;
    FX_CHECK_EQ(fx_patch_eval(P, FX_PATCH_BEZIER, ONE, 0, &p, &n), 0);
    FX_CHECK(p.x == P[12].x && p.y == P[12].y && p.z == P[12].z);
    FX_CHECK_EQ(fx_patch_eval(P, FX_PATCH_BSPLINE, 0, 0, &p, &n), 0);
    FX_CHECK(p.y != P[0].y);
    FX_CHECK_EQ(fx_patch_eval(P, FX_PATCH_BEZIER, ONE + 1, 0, &p, &n), -FX_EINVAL);
    /* all control points at one place: no normal anywhere, nothing written */
    fx_vec3 Q[16], pos[25], nrm[25];
    uint32_t tri[96];
    for (int i = 0; i < 16; i++)
        Q[i] = fx_vec3_make(ONE, 2 * ONE, 3 * ONE);
    fx_mesh m = {pos, nrm, tri, 0, 0, 25, 32, NULL, NULL};
    FX_CHECK_EQ(fx_patch_eval(Q, FX_PATCH_BSPLINE, ONE / 2, ONE / 2, &p, &n), -FX_EDOM);
    FX_CHECK_EQ(fx_patch_tessellate(&m, Q, FX_PATCH_BEZIER, 4), -FX_EDOM);
    FX_CHECK_EQ(m.nverts, 0);
    FX_CHECK_EQ(m.ntris, 0);
}

FX_TEST(objects_patch_tessellation_appends_and_faces_its_normal)
{
    fx_vec3 P[16];
    for (int i = 0; i < 16; i++)
        P[i] = fx_vec3_make((i / 4) * ONE, ((i * 5 % 7) - 3) * ONE / 8, (i % 4) * ONE);
    fx_mesh m;
    FX_CHECK(alloc_mesh(&m, 2 * 81, 2 * 128));
    FX_CHECK_EQ(fx_patch_tessellate(&m, P, FX_PATCH_BEZIER, 8), 0);
    FX_CHECK_EQ(fx_patch_tessellate(&m, P, FX_PATCH_BSPLINE, 8), 0);
    FX_CHECK_EQ(m.nverts, 162);
    FX_CHECK_EQ(m.ntris, 256);
    FX_CHECK_EQ(fx_patch_tessellate(&m, P, FX_PATCH_BEZIER, 1), -FX_ENOSPC);
    FX_CHECK_EQ(faces_against_normals(&m), 0);
    FX_CHECK_EQ(normals_unit(&m), 0);
    /* each patch alone is a sheet: its boundary is open, its inside shared */
    FX_CHECK_EQ(open_edges(&m, 0), 2 * 4 * 8);
    for (int32_t i = 0; i < 81; i++) {
        fx_vec3 p;
        FX_CHECK_EQ(fx_patch_eval(P, FX_PATCH_BSPLINE, fx16_from_ratio(i / 9, 8), fx16_from_ratio(i % 9, 8), &p, NULL),
                    0);
        FX_CHECK(p.x == m.pos[81 + i].x && p.y == m.pos[81 + i].y && p.z == m.pos[81 + i].z);
    }
    free_mesh(&m);
}

/* ---- blobby objects ---- */

static double wyvill(double s) { return s >= 1 ? 0 : 1 - 22.0 / 9 * s + 17.0 / 9 * s * s - 4.0 / 9 * s * s * s; }

static double field_ref(const fx_blob_ball *b, int n, const double p[3], double g[3])
{
    double f = 0;
    g[0] = g[1] = g[2] = 0;
    for (int i = 0; i < n; i++) {
        double d[3] = {p[0] - D(b[i].c.x), p[1] - D(b[i].c.y), p[2] - D(b[i].c.z)}, r = D(b[i].r), w = D(b[i].w);
        double s = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / (r * r);
        if (s >= 1)
            continue;
        f += w * wyvill(s);
        double gs = -22.0 / 9 + 34.0 / 9 * s - 12.0 / 9 * s * s;
        for (int k = 0; k < 3; k++)
            g[k] += w * gs * 2 * d[k] / (r * r);
    }
    return f;
}

static void check_blob(const fx_blob_ball *balls, int nb, fx16 iso, fx16 step, int32_t nx, fx_vec3 org,
                       double vol_lo, double vol_hi, const char *name)
{
    fx_blobby b = {balls, nb, iso, org, step, nx, nx, nx};
    size_t bytes = fx_blobby_work_bytes(&b);
    FX_CHECK(bytes > 0);
    void *work = malloc(bytes);
    fx_mesh cnt = {0};
    FX_CHECK_EQ(fx_blobby_make(&cnt, &b, work, bytes), 0);
    FX_CHECK(cnt.ntris > 0);
    fx_mesh m;
    FX_CHECK(alloc_mesh(&m, cnt.nverts, cnt.ntris));
    FX_CHECK_EQ(fx_blobby_make(&m, &b, work, bytes), 0);
    FX_CHECK_EQ(m.nverts, cnt.nverts);
    FX_CHECK_EQ(m.ntris, cnt.ntris);
    double worst = 0, worst_cos = 1;
    for (int32_t i = 0; i < m.nverts; i++) {
        double p[3] = {D(m.pos[i].x), D(m.pos[i].y), D(m.pos[i].z)}, g[3];
        double f = field_ref(balls, nb, p, g);
        double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        worst = fmax(worst, fabs(f - D(iso)) / gl);
        double out[3] = {-g[0], -g[1], -g[2]};
        worst_cos = fmin(worst_cos, angle_cos(m.nrm[i], out));
    }
    FX_CHECK_MSG(worst <= D(step) / 8, "%s: a vertex %g from the iso-surface (step %g)", name, worst, D(step));
    /* The method exactly: each vertex on its lattice edge where the
     * double field, interpolated linearly between the edge's ends, is iso. */
    double worst_t = 0;
    int off_lattice = 0;
    for (int32_t i = 0; i < m.nverts; i++) {
        double g[3] = {D(m.pos[i].x - org.x) / D(step), D(m.pos[i].y - org.y) / D(step), D(m.pos[i].z - org.z) / D(step)};
        double lo[3], fr = -1, e = 1e-3;
        int d = 0;
        for (int k = 0; k < 3; k++) {
            lo[k] = floor(g[k] + e);
            double f = g[k] - lo[k];
            if (f > e) {
                d |= 1 << k;
                if (fr >= 0 && fabs(f - fr) > 0.01)
                    off_lattice++;
                fr = f;
            }
        }
        if (!d)
            continue; /* on a grid point: the field there is iso */
        double p0[3], p1[3], gg[3];
        for (int k = 0; k < 3; k++) {
            p0[k] = D(org.x * (k == 0) + org.y * (k == 1) + org.z * (k == 2)) + lo[k] * D(step);
            p1[k] = p0[k] + ((d >> k) & 1) * D(step);
        }
        double f0 = field_ref(balls, nb, p0, gg), f1 = field_ref(balls, nb, p1, gg);
        double t = (D(iso) - f0) / (f1 - f0);
        worst_t = fmax(worst_t, fabs(t - fr) * D(step));
    }
    FX_CHECK_MSG(off_lattice == 0, "%s: %d vertices off the lattice edges", name, off_lattice);
    FX_CHECK_MSG(worst_t <= 1.0 / 4096, "%s: a vertex %g from its edge's linear interpolation", name, worst_t);
    FX_CHECK_MSG(worst_cos > 0.99996, "%s: a normal off by %g degrees", name, acos(worst_cos) * 180 / PI);
    FX_CHECK_EQ(normals_unit(&m), 0);
    int open = open_edges(&m, 0);
    FX_CHECK_MSG(open == 0, "%s: %d open edges", name, open);
    FX_CHECK_EQ(faces_against_normals(&m), 0);
    double v = volume(&m);
    FX_CHECK_MSG(v > vol_lo && v < vol_hi, "%s: volume %f not in (%f, %f)", name, v, vol_lo, vol_hi);
    /* too small a mesh or too little work memory */
    fx_mesh small;
    FX_CHECK(alloc_mesh(&small, cnt.nverts, cnt.ntris - 1));
    FX_CHECK_EQ(fx_blobby_make(&small, &b, work, bytes), -FX_ENOSPC);
    FX_CHECK_EQ(small.ntris, 0);
    FX_CHECK_EQ(fx_blobby_make(&m, &b, work, bytes - 1), -FX_ENOSPC);
    free_mesh(&small);
    free_mesh(&m);
    free(work);
}

FX_TEST(objects_blobby_surfaces_lie_on_the_iso_surface_and_close)
{
    /* one ball: field w g(s) = iso where g(s) = 1/2, a sphere of radius
     * r sqrt(s0) with g(s0) = 1/2 (s0 = 0.2439...) */
    fx_blob_ball one = {fx_vec3_make(ONE / 10, 0, -ONE / 7), 2 * ONE, ONE};
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; i++) {
        double mid = (lo + hi) / 2;
        if (wyvill(mid) > 0.5)
            lo = mid;
        else
            hi = mid;
    }
    double R = 2 * sqrt(lo), V = 4.0 / 3 * PI * R * R * R;
    check_blob(&one, 1, ONE / 2, ONE / 8, 24, fx_vec3_make(-3 * ONE / 2, -3 * ONE / 2, -3 * ONE / 2), V * 0.97,
               V * 1.001, "one ball");
    /* three balls merging into one closed blob */
    fx_blob_ball three[3] = {
        {fx_vec3_make(-ONE, 0, 0), 2 * ONE, ONE},
        {fx_vec3_make(ONE, ONE / 4, 0), 2 * ONE, ONE},
        {fx_vec3_make(0, ONE, ONE / 2), 3 * ONE / 2, ONE},
    };
    check_blob(three, 3, ONE / 2, ONE / 8, 40, fx_vec3_make(-5 * ONE / 2, -5 * ONE / 2, -5 * ONE / 2), V,
               3 * V, "three balls");
    /* a negative ball carves a dimple; the surface stays closed */
    fx_blob_ball carve[2] = {{fx_vec3_make(0, 0, 0), 2 * ONE, ONE}, {fx_vec3_make(ONE, 0, 0), ONE, -ONE / 2}};
    check_blob(carve, 2, ONE / 2, ONE / 10, 30, fx_vec3_make(-3 * ONE / 2, -3 * ONE / 2, -3 * ONE / 2), V * 0.5,
               V, "carved ball");
    fx_blobby bad = {&one, 1, 0, fx_vec3_make(0, 0, 0), ONE, 4, 4, 4};
    FX_CHECK_EQ(fx_blobby_work_bytes(&bad), 0);
    fx_mesh m = {0};
    int32_t w[8];
    FX_CHECK_EQ(fx_blobby_make(&m, &bad, w, sizeof w), -FX_EINVAL);
}
