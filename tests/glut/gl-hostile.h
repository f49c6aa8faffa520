/* SPDX-License-Identifier: MIT */
/* Shared by the GL corner test (tests/glut/gl-corners.c) and the GL fuzz
 * target (tests/fuzz/fuzz_gl.c): the arguments of a generated call (the
 * table comes from the layer's headers: tests/glut/gen-gl-table.sh), the
 * hostile values, the enums an entry point's GLenum parameters take (by the
 * parameter's name), a probe scene that pushes the state through every
 * stage of the pipeline, and a reset to a known state. Issue #40. */
#ifndef FIXEL_TESTS_GL_HOSTILE_H
#define FIXEL_TESTS_GL_HOSTILE_H

#include <GL/freeglut.h>
#include <GL/glu.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../../boards/glut/glut_int.h"

#define FXGL_ARR 1024

typedef struct fxgl_args {
    double d[12];       /* scalar float/double arguments and pointer slots, in order */
    int i[8];
    GLenum e[4];
    float fa[FXGL_ARR]; /* what GLfloat * / GLdouble * parameters point to */
    double da[FXGL_ARR];
    GLint ia[4];        /* const GLint * (a viewport) */
    unsigned char bytes[4096];
    void *font;
    GLUquadric *quad;
} fxgl_args;

typedef struct fxgl_entry {
    const char *name;
    const char *sig;   /* per parameter: f float, d double, F float *, D double *,
                          e enum, i int, I int *, B bytes, T font, Q quadric */
    const char *names; /* the parameters' names, comma separated */
    void (*call)(fxgl_args *a);
} fxgl_entry;

#include "gl_table.h"

/* Hostile values. Floats (for GLfloat parameters: a double outside float's
 * range converted to float is undefined in C, so these stay in it). */
static const float fxgl_hostile_f[] = {
    NAN, INFINITY, -INFINITY, 1e38f, -1e38f, FLT_MAX, -FLT_MAX, 1e-45f, -1e-45f, FLT_MIN,
    2147483648.0f, -2147483648.0f, 2147483520.0f, 32768.0f, -32769.0f, 65536.0f, 1e9f, -1.1e9f, 0.0f, -0.0f,
};
#define FXGL_NHF ((int)(sizeof fxgl_hostile_f / sizeof fxgl_hostile_f[0]))
/* Doubles: the floats plus what only a double holds, and the points just
 * around the boundary's saturation at +-2^31 units and the 16.16 colour
 * range at +-2^15. */
static const double fxgl_hostile_d[] = {
    NAN, INFINITY, -INFINITY, 1e38, -1e38, DBL_MAX, -DBL_MAX, 4.9e-324, -4.9e-324, DBL_MIN,
    1e300, -1e300, 2147483647.0, 2147483648.0, -2147483648.0, -2147483649.0, 2147483646.999,
    4294967296.0, 32767.99, -32768.01, 2e9, -1.1e9, 0.0, -0.0,
};
#define FXGL_NHD ((int)(sizeof fxgl_hostile_d / sizeof fxgl_hostile_d[0]))

/* The enums a parameter takes, by its name in the headers. */
static const GLenum fxgl_en_light[] = {GL_LIGHT0, GL_LIGHT7};
static const GLenum fxgl_en_face[] = {GL_FRONT_AND_BACK, GL_BACK};
static const GLenum fxgl_en_target[] = {GL_TEXTURE_2D, GL_TEXTURE_ENV, GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_3};
static const GLenum fxgl_en_coord[] = {GL_S};
static const GLenum fxgl_en_plane[] = {GL_CLIP_PLANE0};
static const GLenum fxgl_en_op[] = {GL_ACCUM, GL_LOAD, GL_MULT};
static const GLenum fxgl_en_func[] = {GL_LESS, GL_ALWAYS};
static const GLenum fxgl_en_pname[] = {
    GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
    GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION,
    GL_EMISSION, GL_SHININESS, GL_AMBIENT_AND_DIFFUSE, GL_LIGHT_MODEL_AMBIENT,
    GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TEXTURE_MAG_FILTER,
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR,
    GL_UNPACK_ALIGNMENT, GL_PACK_ALIGNMENT, GL_FOG_DENSITY, GL_FOG_COLOR, GL_FOG_MODE,
    GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_CURRENT_COLOR, GL_MODELVIEW_MATRIX,
    GL_CURRENT_RASTER_POSITION, GL_VIEWPORT, GL_POINT_SIZE, GL_LINE_WIDTH,
};
typedef struct fxgl_enums {
    const char *name;
    const GLenum *v;
    int n;
} fxgl_enums;
#define FXGL_E(nm, arr) {nm, arr, (int)(sizeof arr / sizeof arr[0])}
static const fxgl_enums fxgl_enum_lists[] = {
    FXGL_E("light", fxgl_en_light), FXGL_E("face", fxgl_en_face), FXGL_E("target", fxgl_en_target),
    FXGL_E("coord", fxgl_en_coord), FXGL_E("plane", fxgl_en_plane), FXGL_E("op", fxgl_en_op),
    FXGL_E("func", fxgl_en_func), FXGL_E("pname", fxgl_en_pname),
};
/* The list of the k-th parameter of e (a GLenum one); pname's when unknown. */
static inline const fxgl_enums *fxgl_enum_list(const fxgl_entry *e, int k)
{
    const char *p = e->names;
    for (int i = 0; i < k && p; i++) {
        p = strchr(p, ',');
        if (p)
            p++;
    }
    size_t n = p ? strcspn(p, ",") : 0;
    for (size_t i = 0; i < sizeof fxgl_enum_lists / sizeof fxgl_enum_lists[0]; i++)
        if (p && strlen(fxgl_enum_lists[i].name) == n && !strncmp(p, fxgl_enum_lists[i].name, n))
            return &fxgl_enum_lists[i];
    return &fxgl_enum_lists[sizeof fxgl_enum_lists / sizeof fxgl_enum_lists[0] - 1];
}

/* Benign arguments: every scalar 0.5, arrays of 0.5, ints 3 (a sphere's
 * slices, a bitmap's side), a 40x40 viewport, the first enum of each list. */
static inline void fxgl_benign(fxgl_args *a, const fxgl_entry *e, void *font, GLUquadric *q)
{
    for (int i = 0; i < 12; i++)
        a->d[i] = 0.5;
    for (int i = 0; i < 8; i++)
        a->i[i] = 3;
    for (int i = 0; i < FXGL_ARR; i++)
        a->fa[i] = 0.5f, a->da[i] = 0.5;
    a->ia[0] = a->ia[1] = 0, a->ia[2] = a->ia[3] = 40;
    memset(a->bytes, 0xA5, sizeof a->bytes);
    a->bytes[sizeof a->bytes - 1] = 0;
    a->font = font, a->quad = q;
    int ne = 0;
    for (int k = 0; e->sig[k]; k++)
        if (e->sig[k] == 'e' && ne < 4)
            a->e[ne++] = fxgl_enum_list(e, k)->v[0];
}

/* Pops every stack, ends a glBegin, and puts back the state the probe
 * expects (lighting on with light 0, a perspective-ish projection). */
static inline void fxgl_reset(void)
{
    glEnd();
    GLenum modes[3] = {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE};
    for (int m = 0; m < 3; m++) {
        glMatrixMode(modes[m]);
        for (int i = 0; i < 64; i++)
            glPopMatrix();
        glLoadIdentity();
    }
    glMatrixMode(GL_PROJECTION);
    glOrtho(-2, 2, -2, 2, -10, 10);
    glMatrixMode(GL_MODELVIEW);
    glViewport(0, 0, 40, 40);
    glScissor(0, 0, 40, 40);
    glPixelZoom(1, 1);
    glPointSize(1);
    glLineWidth(1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    static const GLfloat pos[4] = {1, 1, 1, 0}, one[4] = {1, 1, 1, 1}, dir[3] = {0, 0, -1};
    for (GLenum l = GL_LIGHT0; l <= GL_LIGHT7; l++) {
        glLightfv(l, GL_POSITION, pos);
        glLightfv(l, GL_DIFFUSE, one);
        glLightfv(l, GL_SPOT_DIRECTION, dir);
        glLightf(l, GL_SPOT_CUTOFF, 180);
        glLightf(l, GL_CONSTANT_ATTENUATION, 1);
        glLightf(l, GL_LINEAR_ATTENUATION, 0);
        glLightf(l, GL_QUADRATIC_ATTENUATION, 0);
    }
    glColor4f(1, 1, 1, 1);
    glNormal3f(0, 0, 1);
    glTexCoord2f(0, 0);
    while (glGetError() != GL_NO_ERROR) {
    }
}

/* Everything drawn once with the current state: lit and unlit triangles,
 * lines, points, a raster position with a bitmap and pixels, a sphere. */
static inline void fxgl_probe(int lit)
{
    static const GLubyte bm[8] = {0xFF, 0x81, 0x81, 0x81, 0x81, 0x81, 0x81, 0xFF};
    static const GLubyte px[4 * 4 * 3] = {255, 0, 0, 0, 255, 0};
    if (lit) {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_LIGHT1);
    }
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1, -1, 0), glVertex3f(1, -1, 0.5f), glVertex3f(0, 1, -0.5f);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex2f(-1.5f, -1.5f), glVertex2f(1.5f, -1.2f), glVertex2f(0.2f, 1.7f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex2f(0.3f, 0.3f);
    glEnd();
    glBegin(GL_QUADS);
    glVertex2f(-0.5f, -0.5f), glVertex2f(0.5f, -0.5f), glVertex2f(0.5f, 0.5f), glVertex2f(-0.5f, 0.5f);
    glEnd();
    glutWireSphere(0.8, 5, 4);
    glRasterPos2f(-1, -1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1); /* bm and px are packed */
    glBitmap(8, 8, 0, 0, 9, 0, bm);
    glDrawPixels(2, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0);
    glDisable(GL_LIGHT1);
    glDisable(GL_DEPTH_TEST);
}

/* GL's errors: anything else from glGetError is a bug. */
static inline int fxgl_valid_error(GLenum e)
{
    return e == GL_NO_ERROR || e == GL_INVALID_ENUM || e == GL_INVALID_VALUE ||
           e == GL_INVALID_OPERATION || e == GL_STACK_OVERFLOW || e == GL_STACK_UNDERFLOW ||
           e == GL_OUT_OF_MEMORY;
}

#endif
