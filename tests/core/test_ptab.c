/* SPDX-License-Identifier: MIT */
/* Tests of the polygon tables (fixel/objects.h): the tables of a cube built
 * by hand, plane equations against a double cross product, the inside/
 * outside and back-face tests against their definitions in double, the
 * checks that keep the tables consistent, and solids as voxels for the
 * octree against a direct double classification. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "fixel/error.h"
#include "fixel/mesh.h"
#include "fixel/objects.h"
#include "fixel/vsd.h"
#include "fx_test.h"

#define ONE FX16_ONE
#define D(v) ((v) / 65536.0)

typedef struct tabs {
    fx_ptab t;
    fx_ptab_vertex *v;
    fx_ptab_edge *e;
    fx_ptab_poly *p;
    int32_t *u;
} tabs;

static void tabs_make(tabs *s, int32_t nv, int32_t ne, int32_t np, int32_t nu)
{
    s->v = calloc((size_t)nv + 1, sizeof *s->v);
    s->e = calloc((size_t)ne + 1, sizeof *s->e);
    s->p = calloc((size_t)np + 1, sizeof *s->p);
    s->u = calloc((size_t)nu + 1, sizeof *s->u);
    fx_ptab_init(&s->t, s->v, nv, s->e, ne, s->p, np, s->u, nu);
}

static void tabs_free(tabs *s)
{
    free(s->v);
    free(s->e);
    free(s->p);
    free(s->u);
}

/* The cube [-1, 1]^3, faces counter-clockwise from outside. */
static const int32_t cube_faces[6][4] = {
    {1, 3, 7, 5}, /* +x */ {0, 4, 6, 2}, /* -x */ {2, 6, 7, 3}, /* +y */
    {0, 1, 5, 4}, /* -y */ {4, 5, 7, 6}, /* +z */ {0, 2, 3, 1}, /* -z */
};

static void make_cube(tabs *s)
{
    tabs_make(s, 8, 12, 6, 24);
    for (int i = 0; i < 8; i++)
        FX_CHECK_EQ(fx_ptab_add_vertex(&s->t, fx_vec3_make(i & 1 ? ONE : -ONE, i & 2 ? ONE : -ONE, i & 4 ? ONE : -ONE)),
                    i);
    for (int f = 0; f < 6; f++)
        FX_CHECK_EQ(fx_ptab_add_polygon(&s->t, cube_faces[f], 4, 0xFF000000u | (uint32_t)f, f), f);
}

FX_TEST(ptab_cube_tables_planes_inside_and_back_faces)
{
    tabs s;
    make_cube(&s);
    fx_ptab *t = &s.t;
    FX_CHECK_EQ(t->nvert, 8);
    FX_CHECK_EQ(t->nedge, 12);
    FX_CHECK_EQ(t->npoly, 6);
    FX_CHECK_EQ(t->nuse, 24);
    FX_CHECK_EQ(fx_ptab_open_edges(t), 0);
    /* every edge between two faces, run once each way */
    for (int32_t e = 0; e < t->nedge; e++) {
        const fx_ptab_edge *E = &t->edge[e];
        FX_CHECK(E->poly[0] >= 0 && E->poly[1] >= 0 && E->poly[0] != E->poly[1]);
    }
    /* each vertex's edge list holds its three edges */
    for (int32_t v = 0; v < 8; v++) {
        int n = 0;
        for (int32_t e = t->vert[v].first_edge; e >= 0 && n < 10; n++)
            e = t->edge[e].v[0] == v ? t->edge[e].next[0] : t->edge[e].next[1];
        FX_CHECK_EQ(n, 3);
    }
    /* planes: axis normals pointing out, through the face */
    static const int axis[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; f++) {
        const fx_ptab_poly *P = &t->poly[f];
        FX_CHECK_EQ(P->attr, f);
        FX_CHECK_EQ(P->n, 4);
        for (int k = 0; k < 4; k++)
            FX_CHECK_EQ(fx_ptab_poly_vertex(t, f, k), cube_faces[f][k]);
        int64_t n[3] = {P->a, P->b, P->c};
        for (int k = 0; k < 3; k++)
            FX_CHECK(axis[f][k] == 0 ? n[k] == 0 : (n[k] > 0) == (axis[f][k] > 0));
        /* D: the plane passes through the face at distance 1 */
        int64_t len = P->a + P->b + P->c;
        len = len < 0 ? -len : len;
        FX_CHECK_EQ(P->d, -len * ONE);
    }
    FX_CHECK(fx_ptab_inside_convex(t, fx_vec3_make(0, 0, 0)));
    FX_CHECK(fx_ptab_inside_convex(t, fx_vec3_make(ONE - 1, -ONE + 1, ONE / 2)));
    FX_CHECK(!fx_ptab_inside_convex(t, fx_vec3_make(ONE, 0, 0))); /* on a face */
    FX_CHECK(!fx_ptab_inside_convex(t, fx_vec3_make(2 * ONE, 0, 0)));
    FX_CHECK_EQ(fx_ptab_side(t, 0, fx_vec3_make(ONE, 5 * ONE, 7 * ONE)), 0);
    FX_CHECK_EQ(fx_ptab_side(t, 0, fx_vec3_make(ONE + 1, 0, 0)), 1);
    FX_CHECK_EQ(fx_ptab_side(t, 0, fx_vec3_make(ONE - 1, 0, 0)), -1);
    /* seen from (5, 4, 3): +x, +y, +z in front, the others back faces */
    fx_vec3 eye = fx_vec3_make(5 * ONE, 4 * ONE, 3 * ONE);
    int back = 0;
    for (int f = 0; f < 6; f++) {
        FX_CHECK_EQ(fx_ptab_back_face(t, f, eye), f & 1);
        FX_CHECK_EQ(fx_ptab_back_face_dir(t, f, fx_vec3_make(-ONE, -ONE, -ONE)), f & 1);
        back += fx_ptab_back_face(t, f, eye);
    }
    FX_CHECK_EQ(back, 3);
    /* from just beside the +x face's plane, that face is edge-on: back */
    FX_CHECK_EQ(fx_ptab_back_face(t, 0, fx_vec3_make(ONE, 9 * ONE, 0)), 1);
    /* the ray test agrees with the convex test on a grid through edges and
     * vertices (rays along +x graze them) */
    int disagree = 0;
    for (int z = -5; z <= 5; z++)
        for (int y = -5; y <= 5; y++)
            for (int x = -5; x <= 5; x++) {
                fx_vec3 q = fx_vec3_make(x * ONE / 4, y * ONE / 4, z * ONE / 4);
                disagree += fx_ptab_inside(t, q) != fx_ptab_inside_convex(t, q) &&
                            abs(x) != 4 && abs(y) != 4 && abs(z) != 4; /* points on the surface may go either way */
            }
    FX_CHECK_EQ(disagree, 0);
    tabs_free(&s);
}

/* Rays through the shared edges of triangulated faces: each crossing must
 * count once (the half-open rules), or parity flips. */
FX_TEST(ptab_rays_through_shared_edges_count_once)
{
    tabs s;
    tabs_make(&s, 8, 18, 12, 36);
    for (int i = 0; i < 8; i++)
        fx_ptab_add_vertex(&s.t, fx_vec3_make(i & 1 ? ONE : -ONE, i & 2 ? ONE : -ONE, i & 4 ? ONE : -ONE));
    for (int f = 0; f < 6; f++) {
        const int32_t *q = cube_faces[f];
        int32_t t1[3] = {q[0], q[1], q[2]}, t2[3] = {q[0], q[2], q[3]};
        FX_CHECK(fx_ptab_add_polygon(&s.t, t1, 3, 0, 0) >= 0);
        FX_CHECK(fx_ptab_add_polygon(&s.t, t2, 3, 0, 0) >= 0);
    }
    FX_CHECK_EQ(fx_ptab_open_edges(&s.t), 0);
    int bad = 0;
    for (int a = -7; a <= 7; a++)
        for (int x = -7; x <= 7; x++) {
            /* on the diagonals y = z and y = -z, and through the edges of the
             * other faces at y or z = +-1 (outside, grazing) */
            bad += fx_ptab_inside(&s.t, fx_vec3_make(x * ONE / 8, a * ONE / 8, a * ONE / 8)) != 1;
            bad += fx_ptab_inside(&s.t, fx_vec3_make(x * ONE / 8, a * ONE / 8, -a * ONE / 8)) != 1;
            bad += fx_ptab_inside(&s.t, fx_vec3_make(x * ONE / 8, a * ONE / 8, 3 * ONE / 2)) != 0;
            /* left of the cube, the ray crosses it (twice, through both diagonals) */
            bad += fx_ptab_inside(&s.t, fx_vec3_make(-2 * ONE, a * ONE / 8, a * ONE / 8)) != 0;
        }
    FX_CHECK_EQ(bad, 0);
    tabs_free(&s);
}

FX_TEST(ptab_rejects_what_would_break_the_tables)
{
    tabs s;
    make_cube(&s);
    fx_ptab *t = &s.t;
    int32_t again[4] = {1, 3, 7, 5};  /* same face: edges in the same direction */
    int32_t third[3] = {1, 3, 0};     /* edge 1-3 already has both sides */
    int32_t dup[4] = {0, 1, 0, 1};
    int32_t out[3] = {0, 1, 8};
    FX_CHECK_EQ(fx_ptab_add_polygon(t, again, 4, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_ptab_add_polygon(t, third, 3, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_ptab_add_polygon(t, dup, 4, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_ptab_add_polygon(t, out, 3, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(fx_ptab_add_polygon(t, out, 2, 0, 0), -FX_EINVAL);
    FX_CHECK_EQ(t->npoly, 6);
    FX_CHECK_EQ(t->nedge, 12);
    FX_CHECK_EQ(t->nuse, 24);
    FX_CHECK_EQ(fx_ptab_add_vertex(t, fx_vec3_make(0, 0, 0)), -FX_ENOSPC);
    tabs_free(&s);

    tabs q;
    tabs_make(&q, 8, 8, 4, 16);
    fx_vec3 pts[5] = {fx_vec3_make(0, 0, 0), fx_vec3_make(ONE, 0, 0), fx_vec3_make(ONE, ONE, 0),
                      fx_vec3_make(0, ONE, ONE / 8), fx_vec3_make(2 * ONE, 0, 0)};
    for (int i = 0; i < 5; i++)
        fx_ptab_add_vertex(&q.t, pts[i]);
    int32_t warped[4] = {0, 1, 2, 3}, line[3] = {0, 1, 4}, flat[3] = {0, 1, 2};
    FX_CHECK_EQ(fx_ptab_add_polygon(&q.t, warped, 4, 0, 0), -FX_EINVAL); /* 1/8 off its plane */
    FX_CHECK_EQ(fx_ptab_add_polygon(&q.t, line, 3, 0, 0), -FX_EDOM);
    FX_CHECK_EQ(fx_ptab_add_polygon(&q.t, flat, 3, 0, 0), 0);
    FX_CHECK_EQ(fx_ptab_open_edges(&q.t), 3);
    FX_CHECK_EQ(fx_ptab_add_vertex(&q.t, fx_vec3_make(1025 * ONE, 0, 0)), -FX_EINVAL);
    tabs_free(&q);
}

static int make_torus(fx_mesh *m, int32_t n, int32_t k)
{
    fx_mesh_params p = {FX_MESH_TORUS, 2 * ONE, 3 * ONE / 4, 0, n, k};
    int32_t nv, nt;
    fx_mesh_size(&p, &nv, &nt);
    memset(m, 0, sizeof *m);
    m->pos = calloc((size_t)nv, sizeof(fx_vec3));
    m->nrm = calloc((size_t)nv, sizeof(fx_vec3));
    m->tri = calloc((size_t)nt * 3, sizeof(uint32_t));
    m->cap_verts = nv, m->cap_tris = nt;
    return fx_mesh_make(m, &p);
}

FX_TEST(ptab_from_a_torus_mesh_agrees_with_double)
{
    fx_mesh m;
    FX_CHECK_EQ(make_torus(&m, 12, 24), 0);
    tabs s;
    tabs_make(&s, m.nverts, 3 * m.ntris, m.ntris, 3 * m.ntris);
    FX_CHECK_EQ(fx_ptab_from_mesh(&s.t, &m, 0xFFFFFFFFu), 0);
    fx_ptab *t = &s.t;
    FX_CHECK_EQ(t->npoly, m.ntris);
    FX_CHECK_EQ(fx_ptab_open_edges(t), 0);
    FX_CHECK_EQ(t->nvert - t->nedge + t->npoly, 0); /* Euler characteristic of a torus */
    uint32_t seed = 99;
    int bad_plane = 0, bad_back = 0, bad_side = 0;
    for (int32_t p = 0; p < t->npoly; p++) {
        const fx_vec3 *a = &t->vert[fx_ptab_poly_vertex(t, p, 0)].p, *b = &t->vert[fx_ptab_poly_vertex(t, p, 1)].p,
                      *c = &t->vert[fx_ptab_poly_vertex(t, p, 2)].p;
        double e1[3] = {D(b->x - a->x), D(b->y - a->y), D(b->z - a->z)}, e2[3] = {D(c->x - a->x), D(c->y - a->y), D(c->z - a->z)};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const fx_ptab_poly *P = &t->poly[p];
        double pl = sqrt((double)P->a * P->a + (double)P->b * P->b + (double)P->c * P->c);
        double cosv = (n[0] * P->a + n[1] * P->b + n[2] * P->c) / (nl * pl);
        bad_plane += cosv < 0.999999;
        /* random eyes: back face exactly when the eye is not strictly in
         * front of the triangle's plane (double, away from the plane) */
        for (int r = 0; r < 4; r++) {
            double e[3];
            for (int k = 0; k < 3; k++)
                e[k] = (double)(int32_t)(fx_test_rand(&seed) % (16 * ONE)) / ONE - 8;
            double side = n[0] * (e[0] - D(a->x)) + n[1] * (e[1] - D(a->y)) + n[2] * (e[2] - D(a->z));
            if (fabs(side) / nl < 1e-3)
                continue;
            fx_vec3 E = fx_vec3_make((fx16)lround(e[0] * ONE), (fx16)lround(e[1] * ONE), (fx16)lround(e[2] * ONE));
            bad_back += fx_ptab_back_face(t, p, E) != (side <= 0);
            bad_side += fx_ptab_side(t, p, E) != (side > 0 ? 1 : -1);
        }
    }
    FX_CHECK_EQ(bad_plane, 0);
    FX_CHECK_EQ(bad_back, 0);
    FX_CHECK_EQ(bad_side, 0);
    /* inside the (non-convex) torus by ray parity, against the torus
     * equation, away from the surface (the mesh is a chordal polyhedron) */
    int bad_in = 0, tested = 0;
    for (int i = 0; i < 4000; i++) {
        double q[3];
        for (int k = 0; k < 3; k++)
            q[k] = (double)(int32_t)(fx_test_rand(&seed) % (7 * ONE)) / ONE - 3.5;
        double rr = sqrt(q[0] * q[0] + q[2] * q[2]) - 2, dist = sqrt(rr * rr + q[1] * q[1]) - 0.75;
        if (fabs(dist) < 0.05)
            continue;
        fx_vec3 Q = fx_vec3_make((fx16)lround(q[0] * ONE), (fx16)lround(q[1] * ONE), (fx16)lround(q[2] * ONE));
        bad_in += fx_ptab_inside(t, Q) != (dist < 0);
        tested++;
    }
    FX_CHECK(tested > 3000);
    FX_CHECK_EQ(bad_in, 0);
    FX_CHECK(!fx_ptab_inside_convex(t, fx_vec3_make(0, 0, 0)));
    tabs_free(&s);
    free(m.pos);
    free(m.nrm);
    free(m.tri);
}


static fx16 blob_minus_iso(const void *user, fx_vec3 p)
{
    const fx_blobby *b = user;
    return fx_blobby_field(b, p) - b->iso;
}

FX_TEST(ptab_voxels_and_octree_from_a_mesh_and_an_implicit_function)
{
    /* the torus mesh as a closed polygon table -> voxels -> octree */
    fx_mesh m;
    FX_CHECK_EQ(make_torus(&m, 16, 32), 0);
    tabs s;
    tabs_make(&s, m.nverts, 3 * m.ntris, m.ntris, 3 * m.ntris);
    FX_CHECK_EQ(fx_ptab_from_mesh(&s.t, &m, 0), 0);
    int32_t k = 5, n = 32;
    uint8_t *vox = malloc((size_t)n * n * n), *vox2 = malloc((size_t)n * n * n);
    fx_vec3 org = fx_vec3_make(-3 * ONE, -3 * ONE, -3 * ONE);
    FX_CHECK_EQ(fx_voxels_from_ptab(vox, k, org, 6 * ONE, &s.t), 0);
    int bad = 0, solid = 0;
    for (int z = 0; z < n; z++)
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                double c[3] = {-3 + (x + 0.5) * 6 / n, -3 + (y + 0.5) * 6 / n, -3 + (z + 0.5) * 6 / n};
                int v = vox[(z * n + y) * n + x];
                solid += v;
                FX_CHECK(v == 0 || v == 1);
                double rr = sqrt(c[0] * c[0] + c[2] * c[2]) - 2, dist = sqrt(rr * rr + c[1] * c[1]) - 0.75;
                if (fabs(dist) > 0.05)
                    bad += v != (dist < 0);
                /* the row fill matches the point test (every 5th voxel: it
                 * is the slow way) */
                if ((x + y + z) % 5)
                    continue;
                fx_vec3 Q = fx_vec3_make(org.x + (fx16)((2 * x + 1) * 6 * ONE / (2 * n)),
                                         org.y + (fx16)((2 * y + 1) * 6 * ONE / (2 * n)),
                                         org.z + (fx16)((2 * z + 1) * 6 * ONE / (2 * n)));
                bad += v != fx_ptab_inside(&s.t, Q);
            }
    FX_CHECK_EQ(bad, 0);
    /* about the torus's volume, 2 pi^2 R r^2 = 22.2, in voxels of (6/32)^3 */
    double vol = solid * pow(6.0 / n, 3);
    FX_CHECK_MSG(fabs(vol - 22.2) < 1.5, "torus voxels: volume %f", vol);
    int32_t cap = (int32_t)(((int64_t)1 << (3 * k + 3)) - 1) / 7;
    fx_vsd_onode *nodes = malloc(sizeof *nodes * (size_t)cap);
    fx_vsd_octree o;
    FX_CHECK_EQ(fx_vsd_octree_build(&o, nodes, cap, vox, k), 0);
    FX_CHECK(o.nnode > 1 && o.nnode < cap / 4); /* the octree merges the solid's uniform regions */

    /* an implicit function: two soft balls, voxel by voxel against double */
    fx_blob_ball balls[2] = {{fx_vec3_make(-ONE, 0, 0), 2 * ONE, ONE}, {fx_vec3_make(ONE, ONE / 2, 0), 2 * ONE, ONE}};
    fx_blobby b = {balls, 2, ONE / 2, fx_vec3_make(0, 0, 0), ONE, 1, 1, 1};
    FX_CHECK_EQ(fx_voxels_from_implicit(vox2, k, org, 6 * ONE, blob_minus_iso, &b), 0);
    bad = 0;
    for (int z = 0; z < n; z++)
        for (int y = 0; y < n; y++)
            for (int x = 0; x < n; x++) {
                double c[3] = {-3 + (x + 0.5) * 6 / n, -3 + (y + 0.5) * 6 / n, -3 + (z + 0.5) * 6 / n}, f = 0;
                for (int i = 0; i < 2; i++) {
                    double d2 = 0;
                    for (int a = 0; a < 3; a++) {
                        double cc = D((&balls[i].c.x)[a]);
                        d2 += (c[a] - cc) * (c[a] - cc);
                    }
                    double s2 = d2 / 4;
                    if (s2 < 1)
                        f += 1 - 22.0 / 9 * s2 + 17.0 / 9 * s2 * s2 - 4.0 / 9 * s2 * s2 * s2;
                }
                if (fabs(f - 0.5) > 1e-3)
                    bad += vox2[(z * n + y) * n + x] != (f > 0.5);
            }
    FX_CHECK_EQ(bad, 0);
    FX_CHECK_EQ(fx_vsd_octree_build(&o, nodes, cap, vox2, k), 0);
    int32_t *depth = malloc(sizeof(int32_t) * 64 * 64);
    FX_CHECK(fx_vsd_octree_render(&o, 2, depth, 64, 64) > 0);
    /* the first voxel along +z at each pixel is the first solid one */
    int wrong = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            int want = -1;
            for (int z = 0; z < n && want < 0; z++)
                if (vox2[(z * n + y / 2) * n + x / 2])
                    want = z;
            wrong += depth[y * 64 + x] != want;
        }
    FX_CHECK_EQ(wrong, 0);
    FX_CHECK_EQ(fx_voxels_from_implicit(vox2, 9, org, 6 * ONE, blob_minus_iso, &b), -FX_EINVAL);
    FX_CHECK_EQ(fx_voxels_from_ptab(vox2, k, org, 2048 * ONE, &s.t), -FX_EINVAL);
    free(depth);
    free(nodes);
    free(vox);
    free(vox2);
    tabs_free(&s);
    free(m.pos);
    free(m.nrm);
    free(m.tri);
}
