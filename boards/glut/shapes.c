/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — the GLUT solids, tessellated as freeglut 3 tessellates
 * them (its documented construction, re-implemented here), so that a course
 * program's sphere or teapot has the same vertices under fixel as under
 * freeglut + Mesa:
 *   - sphere: slices around z (running clockwise seen from +z), stacks from
 *     +z to -z, the poles single vertices; solid as one triangle strip per
 *     stack, wire as a line strip per slice and a line loop per stack;
 *   - cone / cylinder: around z from z = 0, base (and top) closed by fans
 *     with flat normals, `stacks` rings on the side; wire as lines along the
 *     side and a loop per ring;
 *   - torus: rings around z, sides around the tube; strips per side, wire
 *     loops per ring and per side;
 *   - the Platonic solids with freeglut's radii and orientation (cube of
 *     edge `size`, tetrahedron / octahedron / icosahedron radius 1 with a
 *     vertex on +x, dodecahedron radius sqrt 3), flat face normals, quads
 *     and pentagons split into triangles as freeglut splits them, wire as a
 *     line loop per face (no diagonals);
 *   - the teapot: Newell's 32 patches (fixel's mesh data) sampled 8 x 8
 *     (solid) or 10 x 10 (wire, line strips both ways), scaled into the
 *     vertices (so unit normals stay unit), centred at 1.575 like freeglut,
 *     its triangles clockwise seen from outside as freeglut's are (every
 *     other solid is counter-clockwise, as GL's default front face).
 * Coordinates are computed in float as freeglut does (sin/cos tables, then
 * products), and handed to GL with glNormal3f/glVertex3f like a program. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/mesh.h"
#include "glut_int.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct cache {
    fx_mesh_params p;
    fx_mesh m;
    int valid;
} cache;
static cache C[FX_MESH_KIND_COUNT];

static const fx_mesh *get_mesh(const fx_mesh_params *p)
{
    cache *c = &C[p->kind];
    if (c->valid && !memcmp(&c->p, p, sizeof *p))
        return &c->m;
    int32_t nv, nt;
    if (fx_mesh_size(p, &nv, &nt) < 0)
        return NULL;
    free(c->m.pos), free(c->m.nrm), free(c->m.tri);
    memset(&c->m, 0, sizeof c->m);
    c->valid = 0;
    c->m.pos = malloc((size_t)nv * sizeof(fx_vec3));
    c->m.nrm = malloc((size_t)nv * sizeof(fx_vec3));
    c->m.tri = malloc((size_t)nt * 3 * sizeof(uint32_t));
    c->m.cap_verts = nv, c->m.cap_tris = nt;
    if (!c->m.pos || !c->m.nrm || !c->m.tri || fx_mesh_make(&c->m, p) < 0)
        return NULL;
    c->p = *p;
    c->valid = 1;
    return &c->m;
}

static void draw(fx_mesh_kind kind, double a, double b, int n, int k, int wire, int y_to_z)
{
    fx_mesh_params p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.a = fx_glut_d2q16(a), p.b = fx_glut_d2q16(b), p.c = p.a;
    p.n = n, p.k = k;
    const fx_mesh *m = get_mesh(&p);
    if (!m)
        return;
    if (y_to_z) {
        glPushMatrix();
        glRotated(90, 1, 0, 0);
    }
    fx_glut_draw_tris_q16(&m->pos[0].x, &m->nrm[0].x, m->tri, m->ntris, wire);
    if (y_to_z)
        glPopMatrix();
}

static int clampn(int v, int lo) { return v < lo ? lo : v > FX_MESH_MAX_SEG ? FX_MESH_MAX_SEG : v; }

/* ---- circular solids ---- */
/* cos/sin of n equal steps around the circle (or half of it), n + 1
 * entries with the last closing the loop; a negative n runs backwards. */
static void circle_table(int n, int half, float *s, float *c)
{
    int size = abs(n);
    float angle = (half ? 1 : 2) * (float)M_PI / (float)(n == 0 ? 1 : n);
    s[0] = 0.0f, c[0] = 1.0f;
    for (int i = 1; i < size; i++) {
        s[i] = (float)sin((double)(angle * (float)i));
        c[i] = (float)cos((double)(angle * (float)i));
    }
    if (half)
        s[size] = 0.0f, c[size] = -1.0f;
    else
        s[size] = s[0], c[size] = c[0];
}

typedef struct vbuf {
    float *v, *n;
    int count;
} vbuf;
static int vbuf_alloc(vbuf *b, int count)
{
    b->v = malloc((size_t)count * 3 * sizeof(float));
    b->n = malloc((size_t)count * 3 * sizeof(float));
    b->count = count;
    if (!b->v || !b->n) {
        free(b->v), free(b->n);
        b->v = b->n = NULL;
        return -1;
    }
    return 0;
}
static void vbuf_free(vbuf *b) { free(b->v), free(b->n); }
static void put(vbuf *b, int i, float x, float y, float z, float nx, float ny, float nz)
{
    b->v[3 * i] = x, b->v[3 * i + 1] = y, b->v[3 * i + 2] = z;
    b->n[3 * i] = nx, b->n[3 * i + 1] = ny, b->n[3 * i + 2] = nz;
}
static void emit(const vbuf *b, int i)
{
    glNormal3f(b->n[3 * i], b->n[3 * i + 1], b->n[3 * i + 2]);
    glVertex3f(b->v[3 * i], b->v[3 * i + 1], b->v[3 * i + 2]);
}

/* The GLUT solids' counts: slices, stacks, sides and rings are clamped to
 * FXG_MAX_SHAPE_SEG (256, gluSphere's FX_MESH_MAX_SEG: past what a frame
 * can show, a 256 x 256 sphere is 65,000 vertices), and every vertex count
 * is computed in 64 bits from the clamped values before it is allocated.
 * glutSolidSphere(1, 65536, 65537) had 65536 * 65536 + 2 wrap to 2 in an
 * int and wrote past a two-vertex buffer. */
#define FXG_MAX_SHAPE_SEG FX_MESH_MAX_SEG
static int seg_clamp(int v) { return v > FXG_MAX_SHAPE_SEG ? FXG_MAX_SHAPE_SEG : v; }
/* A radius or size as a float: doubles past FLT_MAX are +-FLT_MAX (the
 * conversion of an out-of-range double to float is undefined in C), NaN
 * stays NaN (fx_glut_d2x takes it as 0). */
static float d2f(double d)
{
    return d > 3.4e38 ? 3.4e38f : d < -3.4e38 ? -3.4e38f : (float)d;
}

static void sphere(float r, int slices, int stacks, int wire)
{
    if (slices <= 0 || stacks < 2)
        return;
    slices = seg_clamp(slices), stacks = seg_clamp(stacks);
    float *s1 = malloc((size_t)(slices + 1) * 2 * sizeof(float)), *c1 = s1 + slices + 1;
    float *s2 = malloc((size_t)(stacks + 1) * 2 * sizeof(float)), *c2 = s2 + stacks + 1;
    vbuf b;
    int nv = (int)((int64_t)slices * (stacks - 1) + 2); /* <= 256 * 255 + 2 */
    if (!s1 || !s2 || vbuf_alloc(&b, nv) < 0) {
        free(s1), free(s2);
        return;
    }
    circle_table(-slices, 0, s1, c1);
    circle_table(stacks, 1, s2, c2);
    put(&b, 0, 0, 0, r, 0, 0, 1);
    int k = 1;
    for (int i = 1; i < stacks; i++)
        for (int j = 0; j < slices; j++, k++) {
            float x = c1[j] * s2[i], y = s1[j] * s2[i], z = c2[i];
            put(&b, k, x * r, y * r, z * r, x, y, z);
        }
    put(&b, k, 0, 0, -r, 0, 0, -1);
    int last = nv - 1;
    if (wire) {
        for (int i = 0; i < slices; i++) {
            glBegin(GL_LINE_STRIP);
            emit(&b, 0);
            for (int j = 0; j < stacks - 1; j++)
                emit(&b, 1 + i + j * slices);
            emit(&b, last);
            glEnd();
        }
        for (int i = 0; i < stacks - 1; i++) {
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < slices; j++)
                emit(&b, 1 + i * slices + j);
            glEnd();
        }
    } else {
        glBegin(GL_TRIANGLE_STRIP); /* the top cap */
        for (int j = 0; j < slices; j++)
            emit(&b, j + 1), emit(&b, 0);
        emit(&b, 1), emit(&b, 0);
        glEnd();
        for (int i = 0; i < stacks - 2; i++) {
            int o = 1 + i * slices;
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j < slices; j++)
                emit(&b, o + j + slices), emit(&b, o + j);
            emit(&b, o + slices), emit(&b, o);
            glEnd();
        }
        int o = 1 + (stacks - 2) * slices; /* the bottom cap */
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j < slices; j++)
            emit(&b, last), emit(&b, o + j);
        emit(&b, last), emit(&b, o);
        glEnd();
    }
    vbuf_free(&b);
    free(s1), free(s2);
}

/* Cone (cyl = 0) or cylinder (cyl = 1) around z from z = 0 to height. */
static void cone_cyl(float base, float height, int slices, int stacks, int wire, int cyl)
{
    if (slices <= 0 || stacks < 1)
        return;
    slices = seg_clamp(slices), stacks = seg_clamp(stacks);
    float *s = malloc((size_t)(slices + 1) * 2 * sizeof(float)), *c = s + slices + 1;
    vbuf b;
    int nv = (int)(cyl ? (int64_t)slices * (stacks + 3) + 2 : (int64_t)slices * (stacks + 2) + 1); /* < 2^17 */
    if (!s || vbuf_alloc(&b, nv) < 0) {
        free(s);
        return;
    }
    circle_table(-slices, 0, s, c);
    float z = 0, r = base;
    const float zstep = height / (float)stacks, rstep = cyl ? 0.0f : base / (float)stacks;
    float cosn = 1.0f, sinn = 0.0f;
    if (!cyl) {
        cosn = (float)(height / sqrt(height * height + base * base));
        sinn = (float)(base / sqrt(height * height + base * base));
    }
    put(&b, 0, 0, 0, 0, 0, 0, -1);
    int k = 1;
    for (int j = 0; j < slices; j++, k++)
        put(&b, k, c[j] * r, s[j] * r, z, 0, 0, -1);
    for (int i = 0; i < stacks + 1; i++) {
        for (int j = 0; j < slices; j++, k++)
            put(&b, k, c[j] * r, s[j] * r, z, c[j] * cosn, s[j] * cosn, sinn);
        z += zstep;
        r -= rstep;
    }
    if (cyl) {
        z -= zstep;
        for (int j = 0; j < slices; j++, k++)
            put(&b, k, c[j] * base, s[j] * base, z, 0, 0, 1);
        put(&b, k, 0, 0, height, 0, 0, 1);
    }
    int rings = cyl ? stacks + 1 : stacks;
    if (wire) {
        glBegin(GL_LINES);
        for (int i = 0; i < slices; i++)
            emit(&b, 1 + i + slices), emit(&b, 1 + i + (stacks + 1) * slices);
        glEnd();
        for (int i = 0; i < rings; i++) {
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < slices; j++)
                emit(&b, 1 + (i + 1) * slices + j);
            glEnd();
        }
    } else {
        glBegin(GL_TRIANGLE_STRIP); /* the base */
        for (int j = 0; j < slices; j++)
            emit(&b, 0), emit(&b, j + 1);
        emit(&b, 0), emit(&b, 1);
        glEnd();
        for (int i = 0; i < stacks; i++) {
            int o = 1 + (i + 1) * slices;
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j < slices; j++)
                emit(&b, o + j), emit(&b, o + j + slices);
            emit(&b, o), emit(&b, o + slices);
            glEnd();
        }
        if (cyl) { /* the top */
            int o = 1 + (stacks + 2) * slices;
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j < slices; j++)
                emit(&b, o + j), emit(&b, nv - 1);
            emit(&b, o), emit(&b, nv - 1);
            glEnd();
        }
    }
    vbuf_free(&b);
    free(s);
}

static void torus(float ir, float or_, int sides, int rings, int wire)
{
    if (sides < 2 || rings < 2)
        return;
    sides = seg_clamp(sides), rings = seg_clamp(rings);
    float *sp = malloc((size_t)(rings + 1) * 2 * sizeof(float)), *cp = sp + rings + 1;
    float *sh = malloc((size_t)(sides + 1) * 2 * sizeof(float)), *ch = sh + sides + 1;
    vbuf b;
    if (!sp || !sh || vbuf_alloc(&b, (int)((int64_t)sides * rings)) < 0) { /* <= 2^16 */
        free(sp), free(sh);
        return;
    }
    circle_table(rings, 0, sp, cp);
    circle_table(-sides, 0, sh, ch);
    for (int j = 0; j < rings; j++)
        for (int i = 0; i < sides; i++)
            put(&b, j * sides + i, cp[j] * (or_ + ch[i] * ir), sp[j] * (or_ + ch[i] * ir), sh[i] * ir,
                cp[j] * ch[i], sp[j] * ch[i], sh[i]);
    if (wire) {
        for (int j = 0; j < rings; j++) {
            glBegin(GL_LINE_LOOP);
            for (int i = 0; i < sides; i++)
                emit(&b, j * sides + i);
            glEnd();
        }
        for (int i = 0; i < sides; i++) {
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < rings; j++)
                emit(&b, j * sides + i);
            glEnd();
        }
    } else {
        for (int i = 0; i < sides; i++) {
            int ioff = i == sides - 1 ? -i : 1;
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j < rings; j++)
                emit(&b, j * sides + i), emit(&b, j * sides + i + ioff);
            emit(&b, i), emit(&b, i + ioff);
            glEnd();
        }
    }
    vbuf_free(&b);
    free(sp), free(sh);
}

void glutSolidSphere(double r, GLint sl, GLint st) { sphere(d2f(r), sl, st, 0); }
void glutWireSphere(double r, GLint sl, GLint st) { sphere(d2f(r), sl, st, 1); }
void glutSolidCone(double b, double h, GLint sl, GLint st) { cone_cyl(d2f(b), d2f(h), sl, st, 0, 0); }
void glutWireCone(double b, double h, GLint sl, GLint st) { cone_cyl(d2f(b), d2f(h), sl, st, 1, 0); }
void glutSolidCylinder(double r, double h, GLint sl, GLint st) { cone_cyl(d2f(r), d2f(h), sl, st, 0, 1); }
void glutWireCylinder(double r, double h, GLint sl, GLint st) { cone_cyl(d2f(r), d2f(h), sl, st, 1, 1); }
void glutSolidTorus(double in, double out, GLint sides, GLint rings) { torus(d2f(in), d2f(out), sides, rings, 0); }
void glutWireTorus(double in, double out, GLint sides, GLint rings) { torus(d2f(in), d2f(out), sides, rings, 1); }

/* ---- the Platonic solids ---- */
/* Faces list their vertices counter-clockwise seen from outside; a face of
 * 4 is drawn as triangles (0 1 2) (0 2 3), of 5 as (0 1 2) (0 2 4) (4 2 3). */
static void polyhedron(const float (*v)[3], const unsigned char *face, int nfaces, int per, float scale,
                       int wire)
{
    static const unsigned char split4[] = {0, 1, 2, 0, 2, 3}, split5[] = {0, 1, 2, 0, 2, 4, 4, 2, 3};
    if (!wire)
        glBegin(GL_TRIANGLES);
    for (int f = 0; f < nfaces; f++) {
        const unsigned char *fv = face + f * per;
        /* the face normal: unit cross product of two edges (in double) */
        const float *a = v[fv[0]], *b = v[fv[1]], *c = v[fv[2]];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        glNormal3f((float)(n[0] / len), (float)(n[1] / len), (float)(n[2] / len));
        if (wire) {
            glBegin(GL_LINE_LOOP);
            for (int i = 0; i < per; i++)
                glVertex3f(v[fv[i]][0] * scale, v[fv[i]][1] * scale, v[fv[i]][2] * scale);
            glEnd();
            continue;
        }
        const unsigned char *sp = per == 3 ? split4 : per == 4 ? split4 : split5;
        int ns = per == 3 ? 3 : per == 4 ? 6 : 9;
        for (int i = 0; i < ns; i++)
            glVertex3f(v[fv[sp[i]]][0] * scale, v[fv[sp[i]]][1] * scale, v[fv[sp[i]]][2] * scale);
    }
    if (!wire)
        glEnd();
}

static void cube(float size, int wire)
{
    /* corners: +z face first, then the -z face from (+,-) */
    static const float v[8][3] = {{.5f, .5f, .5f},   {-.5f, .5f, .5f},  {-.5f, -.5f, .5f},
                                  {.5f, -.5f, .5f},  {.5f, -.5f, -.5f}, {.5f, .5f, -.5f},
                                  {-.5f, .5f, -.5f}, {-.5f, -.5f, -.5f}};
    static const unsigned char f[6 * 4] = {0, 1, 2, 3, 0, 3, 4, 5, 0, 5, 6, 1,
                                           1, 6, 7, 2, 7, 4, 3, 2, 4, 7, 6, 5};
    polyhedron(v, f, 6, 4, size, wire);
}
static void octahedron(int wire)
{
    static const float v[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    static const unsigned char f[8 * 3] = {0, 1, 2, 0, 5, 1, 0, 2, 4, 0, 4, 5,
                                           3, 2, 1, 3, 1, 5, 3, 4, 2, 3, 5, 4};
    polyhedron(v, f, 8, 3, 1.0f, wire);
}
static void tetrahedron(int wire)
{
    /* one vertex on +x, one in the x-y plane, radius 1 */
    float v[4][3] = {{1, 0, 0}, {-1.0f / 3, (float)(2 * sqrt(2.0) / 3), 0},
                     {-1.0f / 3, (float)(-sqrt(2.0) / 3), (float)(sqrt(6.0) / 3)},
                     {-1.0f / 3, (float)(-sqrt(2.0) / 3), (float)(-sqrt(6.0) / 3)}};
    static const unsigned char f[4 * 3] = {1, 3, 2, 0, 2, 3, 0, 3, 1, 0, 1, 2};
    polyhedron((const float (*)[3])v, f, 4, 3, 1.0f, wire);
}
static void icosahedron(int wire)
{
    /* apexes on +-x, two rings of five at x = +-1/sqrt 5, radius 2/sqrt 5:
     * the upper ring at 0, 72, ... degrees in the y-z plane, the lower one
     * half a step off */
    float v[12][3];
    const double rx = 1 / sqrt(5.0), rr = 2 / sqrt(5.0);
    v[0][0] = 1, v[0][1] = 0, v[0][2] = 0;
    v[11][0] = -1, v[11][1] = 0, v[11][2] = 0;
    static const int lower_deg[5] = {180, 108, 36, 324, 252};
    for (int k = 0; k < 5; k++) {
        double a = k * 72.0 * M_PI / 180, b = lower_deg[k] * M_PI / 180;
        v[1 + k][0] = (float)rx, v[1 + k][1] = (float)(rr * cos(a)), v[1 + k][2] = (float)(rr * sin(a));
        v[6 + k][0] = (float)-rx, v[6 + k][1] = (float)(rr * cos(b)), v[6 + k][2] = (float)(rr * sin(b));
    }
    unsigned char f[20 * 3];
    int n = 0;
    static const unsigned char below[5] = {8, 7, 6, 10, 9}; /* the lower vertex between upper k, k+1 */
    for (int k = 0; k < 5; k++) /* the cap around +x */
        f[n++] = 0, f[n++] = (unsigned char)(1 + k), f[n++] = (unsigned char)(1 + (k + 1) % 5);
    for (int k = 0; k < 5; k++) /* down-pointing triangles of the belt */
        f[n++] = (unsigned char)(1 + k), f[n++] = below[k], f[n++] = (unsigned char)(1 + (k + 1) % 5);
    for (int k = 0; k < 5; k++) /* up-pointing ones */
        f[n++] = (unsigned char)(1 + k), f[n++] = below[(k + 4) % 5], f[n++] = below[k];
    static const unsigned char cap[5][2] = {{9, 10}, {8, 9}, {7, 8}, {6, 7}, {10, 6}};
    for (int k = 0; k < 5; k++) /* the cap around -x */
        f[n++] = 11, f[n++] = cap[k][0], f[n++] = cap[k][1];
    polyhedron((const float (*)[3])v, f, 20, 3, 1.0f, wire);
}
static void dodecahedron(int wire)
{
    /* the cube's corners (+-1, +-1, +-1) and (0, +-z, +-x), (+-x, 0, +-z),
     * (+-z, +-x, 0) with x = 1/phi, z = phi: radius sqrt 3 */
    const float x = (float)((sqrt(5.0) - 1) / 2), z = (float)((sqrt(5.0) + 1) / 2);
    const float v[20][3] = {{0, z, x},   {-1, 1, 1},  {-x, 0, z},  {x, 0, z},  {1, 1, 1},
                            {0, z, -x},  {1, 1, -1},  {x, 0, -z},  {-x, 0, -z}, {-1, 1, -1},
                            {0, -z, x},  {1, -1, 1},  {-1, -1, 1}, {0, -z, -x}, {-1, -1, -1},
                            {1, -1, -1}, {z, -x, 0},  {z, x, 0},   {-z, x, 0},  {-z, -x, 0}};
    static const unsigned char f[12 * 5] = {
        0, 1, 2, 3, 4,     5, 6, 7, 8, 9,      10, 11, 3, 2, 12,  13, 14, 8, 7, 15,
        3, 11, 16, 17, 4,  2, 1, 18, 19, 12,   7, 6, 17, 16, 15,  8, 14, 19, 18, 9,
        17, 6, 5, 0, 4,    16, 11, 10, 13, 15, 18, 1, 0, 5, 9,    19, 14, 13, 10, 12};
    polyhedron(v, f, 12, 5, 1.0f, wire);
}

void glutSolidCube(double s) { cube(d2f(s), 0); }
void glutWireCube(double s) { cube(d2f(s), 1); }
void glutSolidTetrahedron(void) { tetrahedron(0); }
void glutWireTetrahedron(void) { tetrahedron(1); }
void glutSolidOctahedron(void) { octahedron(0); }
void glutWireOctahedron(void) { octahedron(1); }
void glutSolidDodecahedron(void) { dodecahedron(0); }
void glutWireDodecahedron(void) { dodecahedron(1); }
void glutSolidIcosahedron(void) { icosahedron(0); }
void glutWireIcosahedron(void) { icosahedron(1); }

/* ---- the teapot ---- */
static void teapot(double size, int wire)
{
    int n = wire ? 9 : 7; /* 10 x 10 or 8 x 8 samples a patch */
    fx_mesh_params p;
    memset(&p, 0, sizeof p);
    p.kind = FX_MESH_TEAPOT;
    p.a = fx_glut_d2q16(0.5 * size); /* into the vertices: the normals stay unit */
    p.n = n;
    const fx_mesh *m = get_mesh(&p);
    if (!m)
        return;
    glPushMatrix();
    glTranslated(0, -1.575 * 0.5 * size, 0);
    if (!wire) {
        /* freeglut's teapot faces are clockwise seen from outside (its
         * patches run the other way from fixel's mesh): a program culls it
         * with glFrontFace(GL_CW), so each triangle goes in reversed */
        static uint32_t *rev;
        static int32_t rev_n;
        static const uint32_t *rev_of;
        if (rev_of != m->tri || rev_n != m->ntris) {
            uint32_t *r = realloc(rev, (size_t)m->ntris * 3 * sizeof *r);
            if (!r) {
                glPopMatrix();
                return;
            }
            for (int32_t t = 0; t < m->ntris; t++)
                r[3 * t] = m->tri[3 * t], r[3 * t + 1] = m->tri[3 * t + 2], r[3 * t + 2] = m->tri[3 * t + 1];
            rev = r, rev_n = m->ntris, rev_of = m->tri;
        }
        fx_glut_draw_tris_q16(&m->pos[0].x, &m->nrm[0].x, rev, m->ntris, 0);
    } else {
        const int32_t *pos = &m->pos[0].x, *nrm = &m->nrm[0].x;
        int side = n + 1, per = side * side;
        for (int pt = 0; pt < m->nverts / per; pt++)
            for (int dir = 0; dir < 2; dir++)
                for (int a = 0; a < side; a++) {
                    glBegin(GL_LINE_STRIP);
                    for (int b = 0; b < side; b++) {
                        int k = pt * per + (dir ? a * side + b : b * side + a);
                        glNormal3d(nrm[3 * k] / 65536.0, nrm[3 * k + 1] / 65536.0, nrm[3 * k + 2] / 65536.0);
                        glVertex3d(pos[3 * k] / 65536.0, pos[3 * k + 1] / 65536.0, pos[3 * k + 2] / 65536.0);
                    }
                    glEnd();
                }
    }
    glPopMatrix();
}
void glutSolidTeapot(double s) { teapot(s, 0); }
void glutWireTeapot(double s) { teapot(s, 1); }

/* gluQuadrics: spheres, cylinders and disks of fixel's meshes too */
struct GLUquadric {
    GLenum draw;
};
GLUquadric *gluNewQuadric(void)
{
    GLUquadric *q = calloc(1, sizeof *q);
    if (q)
        q->draw = GLU_FILL;
    return q;
}
void gluDeleteQuadric(GLUquadric *q) { free(q); }
void gluQuadricDrawStyle(GLUquadric *q, GLenum d)
{
    if (q)
        q->draw = d;
}
void gluQuadricNormals(GLUquadric *q, GLenum n) { (void)q, (void)n; }
void gluQuadricOrientation(GLUquadric *q, GLenum o) { (void)q, (void)o; }
void gluQuadricTexture(GLUquadric *q, GLboolean t) { (void)q, (void)t; }
void gluSphere(GLUquadric *q, GLdouble r, GLint sl, GLint st)
{
    draw(FX_MESH_SPHERE, r, 0, clampn(sl, 3), clampn(st, 2), q && q->draw != GLU_FILL, 1);
}
void gluCylinder(GLUquadric *q, GLdouble base, GLdouble top, GLdouble h, GLint sl, GLint st)
{
    (void)st;
    if (top == 0.0)
        draw(FX_MESH_CONE, base, h, clampn(sl, 3), 0, q && q->draw != GLU_FILL, 1);
    else
        draw(FX_MESH_CYLINDER, base, h, clampn(sl, 3), 0, q && q->draw != GLU_FILL, 1);
}
void gluDisk(GLUquadric *q, GLdouble in, GLdouble out, GLint sl, GLint loops)
{
    (void)loops;
    int n = clampn(sl, 3);
    GLenum save_f = fx_gl.poly_front, save_b = fx_gl.poly_back;
    if (q && q->draw != GLU_FILL)
        fx_gl.poly_front = fx_gl.poly_back = GL_LINE;
    glNormal3d(0, 0, 1);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; i++) {
        fx_angle a = (fx_angle)(uint32_t)(((uint64_t)i << 32) / (uint64_t)n);
        double c = fx_glut_x2d(fx32_cos(a)), s = fx_glut_x2d(fx32_sin(a));
        glVertex2d(out * c, out * s);
        glVertex2d(in * c, in * s);
    }
    glEnd();
    fx_gl.poly_front = save_f, fx_gl.poly_back = save_b;
}
void gluPartialDisk(GLUquadric *q, GLdouble in, GLdouble out, GLint sl, GLint loops, GLdouble start,
                    GLdouble sweep)
{
    (void)start, (void)sweep;
    gluDisk(q, in, out, sl, loops);
}
