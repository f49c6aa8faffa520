/* fixel GLUT layer — the GLUT solids from fixel's mesh generators
 * (fixel/mesh.h), drawn as GL_TRIANGLES through the pipeline (so they take
 * the matrices, lighting, materials, polygon mode and culling). Placed as
 * GLUT places them: cone, cylinder and torus around +z (fixel builds them
 * around +y), the teapot scaled by size / 2 and centred as classic GLUT,
 * Platonic solids with GLUT's circumradii (tetrahedron and dodecahedron
 * sqrt 3, octahedron and icosahedron 1). Wire versions draw the edges of the
 * triangles (a quad face shows its diagonal: freeglut draws polygon edges). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/mesh.h"
#include "glut_int.h"

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
    p.a = fxg_d2q16(a), p.b = fxg_d2q16(b), p.c = p.a;
    p.n = n, p.k = k;
    const fx_mesh *m = get_mesh(&p);
    if (!m)
        return;
    if (y_to_z) {
        glPushMatrix();
        glRotated(90, 1, 0, 0);
    }
    fxg_draw_tris_q16(&m->pos[0].x, &m->nrm[0].x, m->tri, m->ntris, wire);
    if (y_to_z)
        glPopMatrix();
}

static int clampn(int v, int lo) { return v < lo ? lo : v > FX_MESH_MAX_SEG ? FX_MESH_MAX_SEG : v; }

void glutSolidCube(double s) { draw(FX_MESH_CUBE, s, 0, 0, 0, 0, 0); }
void glutWireCube(double s) { draw(FX_MESH_CUBE, s, 0, 0, 0, 1, 0); }
void glutSolidSphere(double r, GLint sl, GLint st) { draw(FX_MESH_SPHERE, r, 0, clampn(sl, 3), clampn(st, 2), 0, 1); }
void glutWireSphere(double r, GLint sl, GLint st) { draw(FX_MESH_SPHERE, r, 0, clampn(sl, 3), clampn(st, 2), 1, 1); }
void glutSolidCone(double b, double h, GLint sl, GLint st) { (void)st, draw(FX_MESH_CONE, b, h, clampn(sl, 3), 0, 0, 1); }
void glutWireCone(double b, double h, GLint sl, GLint st) { (void)st, draw(FX_MESH_CONE, b, h, clampn(sl, 3), 0, 1, 1); }
void glutSolidCylinder(double r, double h, GLint sl, GLint st) { (void)st, draw(FX_MESH_CYLINDER, r, h, clampn(sl, 3), 0, 0, 1); }
void glutWireCylinder(double r, double h, GLint sl, GLint st) { (void)st, draw(FX_MESH_CYLINDER, r, h, clampn(sl, 3), 0, 1, 1); }
void glutSolidTorus(double in, double out, GLint sides, GLint rings) { draw(FX_MESH_TORUS, out, in, clampn(sides, 3), clampn(rings, 3), 0, 1); }
void glutWireTorus(double in, double out, GLint sides, GLint rings) { draw(FX_MESH_TORUS, out, in, clampn(sides, 3), clampn(rings, 3), 1, 1); }
void glutSolidTetrahedron(void) { draw(FX_MESH_TETRAHEDRON, sqrt(3.0), 0, 0, 0, 0, 0); }
void glutWireTetrahedron(void) { draw(FX_MESH_TETRAHEDRON, sqrt(3.0), 0, 0, 0, 1, 0); }
void glutSolidOctahedron(void) { draw(FX_MESH_OCTAHEDRON, 1, 0, 0, 0, 0, 0); }
void glutWireOctahedron(void) { draw(FX_MESH_OCTAHEDRON, 1, 0, 0, 0, 1, 0); }
void glutSolidDodecahedron(void) { draw(FX_MESH_DODECAHEDRON, sqrt(3.0), 0, 0, 0, 0, 0); }
void glutWireDodecahedron(void) { draw(FX_MESH_DODECAHEDRON, sqrt(3.0), 0, 0, 0, 1, 0); }
void glutSolidIcosahedron(void) { draw(FX_MESH_ICOSAHEDRON, 1, 0, 0, 0, 0, 0); }
void glutWireIcosahedron(void) { draw(FX_MESH_ICOSAHEDRON, 1, 0, 0, 0, 1, 0); }

static void teapot(double size, int wire)
{
    glPushMatrix();
    glScaled(0.5 * size, 0.5 * size, 0.5 * size);
    glTranslated(0, -1.5, 0);
    /* the teapot's faces wind clockwise in the patch data: GLUT draws it with
     * glFrontFace(GL_CW); keep culling programs working the same way */
    GLenum ff = fxg.front_face;
    draw(FX_MESH_TEAPOT, 1.0, 0, 8, 0, wire, 0);
    fxg.front_face = ff;
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
    GLenum save_f = fxg.poly_front, save_b = fxg.poly_back;
    if (q && q->draw != GLU_FILL)
        fxg.poly_front = fxg.poly_back = GL_LINE;
    glNormal3d(0, 0, 1);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= n; i++) {
        fx_angle a = (fx_angle)(uint32_t)(((uint64_t)i << 32) / (uint64_t)n);
        double c = fxg_x2d(fx32_cos(a)), s = fxg_x2d(fx32_sin(a));
        glVertex2d(out * c, out * s);
        glVertex2d(in * c, in * s);
    }
    glEnd();
    fxg.poly_front = save_f, fxg.poly_back = save_b;
}
void gluPartialDisk(GLUquadric *q, GLdouble in, GLdouble out, GLint sl, GLint loops, GLdouble start,
                    GLdouble sweep)
{
    (void)start, (void)sweep;
    gluDisk(q, in, out, sl, loops);
}
