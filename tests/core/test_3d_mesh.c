/* SPDX-License-Identifier: MIT */
/* Tests of the mesh generators and the OBJ parser: sizes match, indices
 * are in range, normals are unit and outward, closed solids enclose the
 * right volume, malformed OBJ files are rejected with their line. */
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/mesh.h"
#include "fx_test.h"

#define ONE FX16_ONE

typedef struct mbuf {
    fx_mesh m;
} mbuf;

static int make(fx_mesh *m, fx_mesh_params p)
{
    int32_t nv, nt;
    if (fx_mesh_size(&p, &nv, &nt) < 0)
        return -1;
    m->pos = calloc((size_t)nv, sizeof(fx_vec3));
    m->nrm = calloc((size_t)nv, sizeof(fx_vec3));
    m->tri = calloc((size_t)nt * 3, sizeof(uint32_t));
    m->cap_verts = nv;
    m->cap_tris = nt;
    int e = fx_mesh_make(m, &p);
    if (e == 0 && (m->nverts != nv || m->ntris != nt))
        return -2;
    return e;
}

static void drop(fx_mesh *m)
{
    free(m->pos);
    free(m->nrm);
    free(m->tri);
}

/* Six times the signed volume, in units of 2^-48 (Q16 cubed), as a double
 * only in the test. */
static double volume(const fx_mesh *m)
{
    double v = 0;
    for (int32_t t = 0; t < m->ntris; t++) {
        const fx_vec3 *a = &m->pos[m->tri[3 * t]], *b = &m->pos[m->tri[3 * t + 1]], *c = &m->pos[m->tri[3 * t + 2]];
        double ax = a->x / 65536.0, ay = a->y / 65536.0, az = a->z / 65536.0;
        double bx = b->x / 65536.0, by = b->y / 65536.0, bz = b->z / 65536.0;
        double cx = c->x / 65536.0, cy = c->y / 65536.0, cz = c->z / 65536.0;
        v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return v / 6;
}

/* Every index in range, every normal unit; for convex solids centred on
 * (0, cy, 0) every face faces away from the centre. */
static void check_mesh(const fx_mesh *m, const char *name, int convex, fx16 cy)
{
    int bad_idx = 0, bad_n = 0, inward = 0;
    for (int32_t i = 0; i < m->ntris * 3; i++)
        bad_idx += m->tri[i] >= (uint32_t)m->nverts;
    for (int32_t i = 0; i < m->nverts; i++) {
        int64_t l = (int64_t)m->nrm[i].x * m->nrm[i].x + (int64_t)m->nrm[i].y * m->nrm[i].y +
                    (int64_t)m->nrm[i].z * m->nrm[i].z;
        int64_t d = l - ((int64_t)1 << 32);
        bad_n += d > ((int64_t)1 << 20) || d < -((int64_t)1 << 20);
    }
    if (convex && !bad_idx)
        for (int32_t t = 0; t < m->ntris; t++) {
            const fx_vec3 *a = &m->pos[m->tri[3 * t]], *b = &m->pos[m->tri[3 * t + 1]], *c = &m->pos[m->tri[3 * t + 2]];
            int64_t e1[3] = {b->x - a->x, b->y - a->y, b->z - a->z}, e2[3] = {c->x - a->x, c->y - a->y, c->z - a->z};
            int64_t n[3] = {(e1[1] * e2[2] - e1[2] * e2[1]) >> 16, (e1[2] * e2[0] - e1[0] * e2[2]) >> 16,
                            (e1[0] * e2[1] - e1[1] * e2[0]) >> 16};
            int64_t cx = (int64_t)a->x + b->x + c->x, cyy = (int64_t)a->y + b->y + c->y - 3 * (int64_t)cy,
                    cz = (int64_t)a->z + b->z + c->z;
            if (n[0] * cx + n[1] * cyy + n[2] * cz < 0)
                inward++;
        }
    FX_CHECK_MSG(bad_idx == 0, "%s: %d indices out of range", name, bad_idx);
    FX_CHECK_MSG(bad_n == 0, "%s: %d normals not unit", name, bad_n);
    FX_CHECK_MSG(inward == 0, "%s: %d faces inward", name, inward);
}

FX_TEST(mesh_platonic_solids_are_closed_and_outward)
{
    static const struct {
        fx_mesh_kind k;
        const char *name;
        double vol; /* for circumradius (edge for the cube) 1 */
    } solids[] = {
        {FX_MESH_CUBE, "cube", 1.0},
        {FX_MESH_TETRAHEDRON, "tetrahedron", 0.51320},
        {FX_MESH_OCTAHEDRON, "octahedron", 1.33333},
        {FX_MESH_DODECAHEDRON, "dodecahedron", 2.78516},
        {FX_MESH_ICOSAHEDRON, "icosahedron", 2.53615},
    };
    for (size_t i = 0; i < sizeof solids / sizeof solids[0]; i++) {
        fx_mesh m = {0};
        fx_mesh_params p = {solids[i].k, ONE, 0, 0, 0, 0};
        FX_CHECK_EQ(make(&m, p), 0);
        check_mesh(&m, solids[i].name, 1, 0);
        double v = volume(&m);
        FX_CHECK_MSG(v > solids[i].vol * 0.999 && v < solids[i].vol * 1.001, "%s volume %f, want %f",
                     solids[i].name, v, solids[i].vol);
        FX_CHECK_EQ(fx_mesh_kind_from_name(solids[i].name), solids[i].k);
        drop(&m);
    }
}

FX_TEST(mesh_curved_surfaces_have_their_volume)
{
    const double pi = 3.14159265358979;
    struct {
        fx_mesh_params p;
        const char *name;
        int convex;
        fx16 cy;
        double vol, tol;
    } c[] = {
        {{FX_MESH_SPHERE, 2 * ONE, 0, 0, 48, 24}, "sphere", 1, 0, 4.0 / 3 * pi * 8, 0.02},
        {{FX_MESH_ELLIPSOID, ONE, 2 * ONE, 3 * ONE, 48, 24}, "ellipsoid", 1, 0, 4.0 / 3 * pi * 6, 0.02},
        {{FX_MESH_TORUS, 2 * ONE, ONE / 2, 0, 24, 48}, "torus", 0, 0, 2 * pi * pi * 2 * 0.25, 0.03},
        {{FX_MESH_CONE, ONE, 2 * ONE, 0, 64, 0}, "cone", 1, ONE / 2, pi * 2 / 3, 0.01},
        {{FX_MESH_CYLINDER, ONE, 2 * ONE, 0, 64, 0}, "cylinder", 1, ONE, pi * 2, 0.01},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        fx_mesh m = {0};
        FX_CHECK_EQ(make(&m, c[i].p), 0);
        check_mesh(&m, c[i].name, c[i].convex, c[i].cy);
        double v = volume(&m);
        FX_CHECK_MSG(v > c[i].vol * (1 - c[i].tol) && v < c[i].vol * (1 + c[i].tol), "%s volume %f, want %f",
                     c[i].name, v, c[i].vol);
        drop(&m);
    }
    fx_mesh_params bad = {FX_MESH_SPHERE, ONE, 0, 0, 2, 8};
    int32_t nv, nt;
    FX_CHECK_EQ(fx_mesh_size(&bad, &nv, &nt), -FX_EINVAL);
}

FX_TEST(mesh_teapot_from_32_patches)
{
    fx_mesh m = {0};
    fx_mesh_params p = {FX_MESH_TEAPOT, ONE, 0, 0, 6, 0};
    FX_CHECK_EQ(make(&m, p), 0);
    FX_CHECK_EQ(m.nverts, 32 * 7 * 7);
    FX_CHECK_EQ(m.ntris, 32 * 2 * 36);
    check_mesh(&m, "teapot", 0, 0);
    /* Newell's teapot: 3.15 tall, from the handle (-3) to the spout */
    fx16 miny = INT32_MAX, maxy = INT32_MIN, minx = INT32_MAX, maxx = INT32_MIN;
    for (int32_t i = 0; i < m.nverts; i++) {
        miny = m.pos[i].y < miny ? m.pos[i].y : miny;
        maxy = m.pos[i].y > maxy ? m.pos[i].y : maxy;
        minx = m.pos[i].x < minx ? m.pos[i].x : minx;
        maxx = m.pos[i].x > maxx ? m.pos[i].x : maxx;
    }
    FX_CHECK_EQ(miny, 0);
    FX_CHECK_EQ(maxy, 206438); /* 3.15 */
    FX_CHECK_EQ(minx, -3 * ONE);
    FX_CHECK(maxx > 216269 && maxx < 231014); /* the spout: beyond 3.3, inside its hull 3.525 */
    /* outward: the enclosed volume is positive (the body is about 15) */
    double v = volume(&m);
    FX_CHECK_MSG(v > 15 && v < 35, "teapot volume %f", v);
    /* the generator refuses arrays that are too small */
    m.cap_tris--;
    FX_CHECK_EQ(fx_mesh_make(&m, &p), -FX_ENOSPC);
    drop(&m);
}

static int obj(const char *text, fx_mesh *m, fx_obj_error *err)
{
    int32_t nv, nt;
    int e = fx_mesh_obj_size(text, strlen(text), &nv, &nt, err);
    if (e < 0)
        return e;
    m->pos = calloc((size_t)nv, sizeof(fx_vec3));
    m->nrm = calloc((size_t)nv, sizeof(fx_vec3));
    m->tri = calloc((size_t)nt * 3, sizeof(uint32_t));
    m->cap_verts = nv;
    m->cap_tris = nt;
    return fx_mesh_obj_parse(m, text, strlen(text), err);
}

FX_TEST(obj_parses_vertices_faces_and_numbers)
{
    const char *t = "# a square pyramid\r\n"
                    "o pyr\n"
                    "v -1 0 -1\nv 1 0 -1\nv 1.0 0 1e0\nv -1 0 1\n"
                    "v 0 2.5E-1 0   # apex\n"
                    "vt 0 0\nvn 0 1 0\n"
                    "s off\n"
                    "f 1/1/1 2/1/1 3/1/1 4/1/1\n" /* quad, two triangles */
                    "f 2//1 1//1 5//1\nf 3 2 5\nf 4 3 5\nf -5 -2 -1\n";
    fx_mesh m = {0};
    fx_obj_error err;
    FX_CHECK_EQ(obj(t, &m, &err), 0);
    FX_CHECK_EQ(m.nverts, 5);
    FX_CHECK_EQ(m.ntris, 6);
    FX_CHECK(m.pos[2].z == ONE && m.pos[4].y == ONE / 4 && m.pos[0].x == -ONE);
    /* the fan of the quad and the negative indices */
    FX_CHECK(m.tri[0] == 0 && m.tri[1] == 1 && m.tri[2] == 2);
    FX_CHECK(m.tri[3] == 0 && m.tri[4] == 2 && m.tri[5] == 3);
    FX_CHECK(m.tri[15] == 0 && m.tri[16] == 3 && m.tri[17] == 4);
    /* rebuilt normals: the apex points up */
    FX_CHECK(m.nrm[4].y > ONE * 99 / 100);
    check_mesh(&m, "pyramid", 0, 0);
    drop(&m);
}

FX_TEST(obj_rejects_malformed_files_with_the_line)
{
    static const struct {
        const char *text, *msg;
    } bad[] = {
        {"v 0 0 0\nv 1 0 0\nf 1 2 3\n", "line 3: vertex index 3 out of range (1..2)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "line 4: a face needs at least 3 corners, got 2"},
        {"v 0 0\n", "line 1: expected a number"},
        {"v 0 0 x\n", "line 1: expected a number"},
        {"v 0 0 1.5.2\n", "line 1: malformed number"},
        {"v 0 0 1e\n", "line 1: malformed exponent"},
        {"v 0 0 40000\n", "line 1: number out of range (|v| > 32767)"},
        {"v 0 0 0\n\nbogus 1 2\n", "line 3: unknown statement 'bogus'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "line 4: vertex index -4 out of range (1..3)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2 3\n", "line 4: texture index 1 out of range (1..0)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3x\n", "line 4: malformed face corner"},
        {"v 0 0 0\n", "no faces in the file"},
        {"", "no vertices in the file (it is empty)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        fx_obj_error err;
        int32_t nv, nt;
        int e = fx_mesh_obj_size(bad[i].text, strlen(bad[i].text), &nv, &nt, &err);
        FX_CHECK_EQ(e, -FX_EBADMSG);
        FX_CHECK_MSG(strcmp(err.msg, bad[i].msg) == 0, "case %zu: '%s' (want '%s')", i, err.msg, bad[i].msg);
    }
}

/* fx_mesh_make_teapot leaves out the patches away() names, keeping the
 * others' vertices, normals and triangles as in the whole teapot (a band
 * of a frame then tessellates only its patches and draws the same ones);
 * away() sees each patch's 16 control points, whose hull holds the patch. */
typedef struct skipper {
    int calls;
    int hull_ok;
    fx_vec3 lo[32], hi[32];
} skipper;

static int odd_patches(void *u, const fx_vec3 *pts, int n)
{
    skipper *s = u;
    int p = s->calls++;
    FX_CHECK_EQ(n, 16);
    fx_vec3 lo = pts[0], hi = pts[0];
    for (int i = 1; i < n; i++) {
        lo.x = pts[i].x < lo.x ? pts[i].x : lo.x, hi.x = pts[i].x > hi.x ? pts[i].x : hi.x;
        lo.y = pts[i].y < lo.y ? pts[i].y : lo.y, hi.y = pts[i].y > hi.y ? pts[i].y : hi.y;
        lo.z = pts[i].z < lo.z ? pts[i].z : lo.z, hi.z = pts[i].z > hi.z ? pts[i].z : hi.z;
    }
    s->lo[p] = lo, s->hi[p] = hi;
    return p & 1;
}

FX_TEST(mesh_teapot_leaves_out_the_patches_asked)
{
    fx_mesh all = {0}, some = {0};
    fx_mesh_params p = {FX_MESH_TEAPOT, 3 * ONE / 2, 0, 0, 5, 0};
    FX_CHECK_EQ(make(&all, p), 0);
    some.pos = calloc((size_t)all.nverts, sizeof(fx_vec3));
    some.nrm = calloc((size_t)all.nverts, sizeof(fx_vec3));
    some.tri = calloc((size_t)all.ntris * 3, sizeof(uint32_t));
    some.cap_verts = all.nverts;
    some.cap_tris = all.ntris;
    /* no callback: the whole teapot */
    FX_CHECK_EQ(fx_mesh_make_teapot(&some, p.a, p.n, NULL, NULL), 0);
    FX_CHECK_EQ(some.nverts, all.nverts);
    FX_CHECK(memcmp(some.pos, all.pos, sizeof(fx_vec3) * (size_t)all.nverts) == 0);
    FX_CHECK(memcmp(some.tri, all.tri, sizeof(uint32_t) * 3 * (size_t)all.ntris) == 0);
    skipper s = {0};
    FX_CHECK_EQ(fx_mesh_make_teapot(&some, p.a, p.n, odd_patches, &s), 0);
    FX_CHECK_EQ(s.calls, 32);
    int32_t pv = 36, pt = 2 * 25; /* a patch: 6x6 vertices, 50 triangles */
    FX_CHECK_EQ(some.nverts, 16 * pv);
    FX_CHECK_EQ(some.ntris, 16 * pt);
    for (int k = 0; k < 16; k++) { /* kept patch k is patch 2k */
        const fx_vec3 *a = all.pos + 2 * k * pv, *b = some.pos + k * pv;
        FX_CHECK(memcmp(a, b, sizeof(fx_vec3) * (size_t)pv) == 0);
        FX_CHECK(memcmp(all.nrm + 2 * k * pv, some.nrm + k * pv, sizeof(fx_vec3) * (size_t)pv) == 0);
        for (int32_t t = 0; t < 3 * pt; t++)
            FX_CHECK_EQ(some.tri[3 * k * pt + t] - (uint32_t)(k * pv), all.tri[3 * 2 * k * pt + t] - (uint32_t)(2 * k * pv));
    }
    /* every tessellated point lies in its patch's control box (the hull's
     * box) widened by the slack fx3d_hull_away allows: 1/256 of the largest
     * coordinate (the weights' rounding strays some 10^-5 of it) */
    for (int q = 0; q < 32; q++) {
        int32_t big = 0;
        fx16 e[6] = {s.lo[q].x, s.lo[q].y, s.lo[q].z, s.hi[q].x, s.hi[q].y, s.hi[q].z};
        for (int k = 0; k < 6; k++)
            big = e[k] > big ? e[k] : -e[k] > big ? -e[k] : big;
        int32_t sl = big / 256 + 64;
        for (int32_t i = 0; i < pv; i++) {
            fx_vec3 v = all.pos[q * pv + i];
            FX_CHECK(v.x >= s.lo[q].x - sl && v.x <= s.hi[q].x + sl && v.y >= s.lo[q].y - sl &&
                     v.y <= s.hi[q].y + sl && v.z >= s.lo[q].z - sl && v.z <= s.hi[q].z + sl);
        }
    }
    drop(&all);
    drop(&some);
}
