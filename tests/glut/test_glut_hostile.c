/* SPDX-License-Identifier: MIT */
/* Issue #40: the GL layer at the edges of its numbers. Each test is one
 * finding of the campaign: on the code before the fix it stopped on a
 * UBSan report (the SAN=1 build), wrote past a buffer, ran for hours or
 * drew the wrong thing; here it must draw what GL draws, set GL's error or
 * take the documented clamp, quickly. 40x40 window, gluOrtho2D(0, 40, 0, 40). */
#include <GL/glut.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include <time.h>

#include "../../boards/glut/glut_int.h"
#include "fx_test.h"

static void setup(void)
{
    static int done;
    if (!done) {
        if (!fx_gl.depth) /* one 40x40 window for every test file of the binary */
            fx_glut_gl_init(40, 40);
        done = 1;
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_LINE_STIPPLE);
    glShadeModel(GL_SMOOTH);
    glPointSize(1);
    glLineWidth(1);
    glPixelZoom(1, 1);
    glViewport(0, 0, 40, 40);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 40, 0, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    while (glGetError() != GL_NO_ERROR) {
    }
}

static int lit(int x, int y)
{
    unsigned char p[3];
    glReadPixels(x, y, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, p);
    return p[0] | p[1] | p[2];
}
static int nlit(void)
{
    int n = 0;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++)
            n += lit(x, y) != 0;
    return n;
}
static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec / 1e9;
}

/* -2 f of a far plane at 2e9 (8.6e18 in Q32.32) overflowed int64 */
FX_TEST(glut_hostile_far_plane_2e9)
{
    setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 2e9);
    glMatrixMode(GL_MODELVIEW);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
    glBegin(GL_TRIANGLES);
    glVertex3d(-5, -5, -10), glVertex3d(5, -5, -10), glVertex3d(0, 5, -10);
    glEnd();
    FX_CHECK(lit(20, 20));
    FX_CHECK(!lit(1, 38));
}

/* r - l = 2.2e9 units passed INT64_MAX in Q32.32 */
FX_TEST(glut_hostile_ortho_1_1e9)
{
    setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.1e9, 1.1e9, -1.1e9, 1.1e9, -1, 1);
    GLdouble m[16];
    glGetDoublev(GL_PROJECTION_MATRIX, m);
    /* 2 / 2.2e9 is 3.9 units of 2^-32: the nearest is 4; r - l wrapped to
     * a negative extent before */
    FX_CHECK(m[0] == 4 / 4294967296.0 && m[5] == m[0] && m[12] == 0 && m[13] == 0);
    glMatrixMode(GL_MODELVIEW);
    glRectd(-5.5e8, -5.5e8, 5.5e8, 5.5e8); /* the middle half: window [10, 30) */
    FX_CHECK(lit(20, 20));
    FX_CHECK(lit(10, 10) && lit(29, 29));
    FX_CHECK(!lit(9, 20) && !lit(30, 20) && !lit(20, 9) && !lit(20, 30));
}

/* the second glTranslated(2e9) summed two 8.6e18 entries: the point
 * wrapped to the other side of the window */
FX_TEST(glut_hostile_translate_twice_2e9)
{
    setup();
    glTranslated(2e9, 0, 0);
    glTranslated(2e9, 0, 0);
    GLdouble m[16];
    glGetDoublev(GL_MODELVIEW_MATRIX, m);
    FX_CHECK(m[12] >= 2147483647.0); /* pinned at the top, not wrapped below zero */
    glPointSize(3);
    glBegin(GL_POINTS);
    glVertex2d(20, 20);
    glVertex2d(-1e9, 20);
    glEnd();
    FX_CHECK_EQ(nlit(), 0); /* both far to the right, whatever the saturation */
}

/* a light at 1e30 (saturated) minus the vertex overflowed; the light
 * still lights a face turned to it */
FX_TEST(glut_hostile_huge_light_position)
{
    setup();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    GLfloat pos[4] = {1e30f, 1e30f, 1e30f, 1}, dif[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0);
    glNormal3d(1e30, 1e30, 1e30); /* saturated normal, used as given */
    glRectd(10, 10, 30, 30);
    FX_CHECK(lit(20, 20));
    GLfloat lpos[4] = {-1e38f, 3e38f, -3e38f, 1e-45f};
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1e-30f); /* att near 1 / 0 */
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 45);
    glRectd(10, 10, 30, 30);
    glDisable(GL_LIGHTING);
    glDisable(GL_LIGHT0);
    GLfloat def[4] = {0, 0, 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, def);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
}

/* A spot direction under a saturated modelview (found by fuzz_gl after the
 * campaign): three saturated products were summed in int64 and overflowed;
 * now the sum pins, and the direction stays a huge vector along -1,-1,-1. */
FX_TEST(glut_hostile_spot_direction_saturated_modelview)
{
    setup();
    GLdouble m[16];
    for (int i = 0; i < 16; i++)
        m[i] = 2e9;
    glLoadMatrixd(m);
    GLfloat dir[3] = {-2e9f, -2e9f, -2e9f};
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir);
    for (int k = 0; k < 3; k++)
        FX_CHECK(fx_gl.L.light[1].spot_dir[k] == INT64_MIN);
    glLoadIdentity();
    GLfloat def[3] = {0, 0, -1};
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, def);
}

/* A texture matrix that saturates the texture coordinates (fuzz_gl): the
 * rounding to Q16.16 added half a unit to INT64_MAX. */
FX_TEST(glut_hostile_texture_matrix_saturated)
{
    setup();
    GLdouble m[16];
    for (int i = 0; i < 16; i++)
        m[i] = i % 4 == 3 ? i == 15 : 2e9; /* q stays 1: no divide */
    glMatrixMode(GL_TEXTURE);
    glLoadMatrixd(m);
    glMatrixMode(GL_MODELVIEW);
    static const GLubyte white[4] = {255, 255, 255, 255};
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(1, 1), glVertex2f(10, 10);
    glTexCoord2f(1, 1), glVertex2f(30, 10);
    glTexCoord2f(1, 1), glVertex2f(30, 30);
    glTexCoord2f(1, 1), glVertex2f(10, 30);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &t);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    FX_CHECK(lit(20, 20)); /* drawn, the texture or its colour */
}

/* A list that calls itself twice (fuzz_gl's slow input): at GL's nesting
 * depth of 64 that is 2^64 replays, a hang in Mesa too. One top-level call
 * stops at the budget, and the next top-level call has a whole one again. */
FX_TEST(glut_hostile_list_calling_itself_twice_ends)
{
    setup();
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glCallList(l);
    glCallList(l);
    glEndList();
    glCallList(l);
    FX_CHECK(fx_gl.replay_left == 0);
    FX_CHECK(!fx_gl.replaying);
    glNewList(l, GL_COMPILE);
    glRectd(10, 10, 30, 30);
    glEndList();
    glCallList(l);
    FX_CHECK(lit(20, 20)); /* a fresh budget: the next call draws */
    glDeleteLists(l, 1);
}

/* glClear inside a scissor box reaching past INT32_MAX (fuzz_gl): its
 * corners were summed in int; now it clears from (1, 1) to the edges. */
FX_TEST(glut_hostile_clear_huge_scissor)
{
    setup();
    glClearColor(1, 1, 1, 1);
    glScissor(1, 1, INT32_MAX, INT32_MAX);
    glEnable(GL_SCISSOR_TEST);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glScissor(0, 0, 40, 40);
    glClearColor(0, 0, 0, 1);
    FX_CHECK(lit(39, 39));
    FX_CHECK(lit(1, 1));
    FX_CHECK(!lit(0, 0));
}

/* vertices at the boundary's saturation point (+-2^31 units): the
 * clipper's distances and the window transform overflowed */
FX_TEST(glut_hostile_vertices_near_saturation)
{
    setup();
    glBegin(GL_TRIANGLES);
    glVertex2d(-2.1e9, -2.1e9), glVertex2d(2.1e9, -2.1e9), glVertex2d(20, 2.1e9);
    glEnd();
    FX_CHECK(lit(20, 20));
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glVertex2d(-2.2e9, 20.5), glVertex2d(2.2e9, 20.5);
    glEnd();
    FX_CHECK(lit(0, 20) && lit(39, 20) && !lit(20, 21) && !lit(20, 19));
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLES); /* clip w at the saturation point too */
    glVertex4d(-2.1e9, -2.1e9, 0, 2.1e9), glVertex4d(2.1e9, -2.1e9, 0, 2.1e9),
        glVertex4d(0, 2.1e9, 0, 2.1e9);
    glEnd();
    FX_CHECK(lit(20, 20));
}

/* x + w of glViewport, glScissor and glReadPixels overflowed an int */
FX_TEST(glut_hostile_viewport_scissor_readpixels_sizes)
{
    setup();
    glViewport(INT32_MAX - 5, INT32_MAX - 5, INT32_MAX, INT32_MAX);
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    FX_CHECK_EQ(vp[2], 16384); /* GL_MAX_VIEWPORT_DIMS */
    FX_CHECK_EQ(vp[3], 16384);
    FX_CHECK(vp[0] <= (1 << 20) && vp[1] <= (1 << 20));
    glRectd(0, 0, 40, 40);
    glViewport(INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX);
    glRectd(0, 0, 40, 40);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
    glViewport(0, 0, 40, 40);
    glScissor(INT32_MAX, INT32_MAX, INT32_MAX, INT32_MAX);
    glEnable(GL_SCISSOR_TEST);
    glRectd(0, 0, 40, 40);
    glDisable(GL_SCISSOR_TEST);
    FX_CHECK_EQ(nlit(), 0);
    unsigned char px[4 * 3];
    memset(px, 0x55, sizeof px);
    glReadPixels(INT32_MAX - 1, INT32_MAX - 1, 4, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < 12; i++)
        FX_CHECK_EQ(px[i], 0);
    glReadPixels(0, 0, -1, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
    FX_CHECK_EQ(glGetError(), GL_INVALID_VALUE);
}

/* glBitmap's moves summed into the raster position without bound */
FX_TEST(glut_hostile_bitmap_move_saturates)
{
    setup();
    glRasterPos2i(20, 20);
    for (int i = 0; i < 4; i++)
        glBitmap(0, 0, 0, 0, 1e38f, -1e38f, NULL);
    GLfloat rp[4];
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    FX_CHECK(rp[0] >= 1e6f && rp[1] <= -1e6f); /* pinned, not wrapped */
    FX_CHECK(rp[0] <= 4.2e6f && rp[1] >= -4.2e6f);
    glWindowPos2f(3e38f, -INFINITY);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    FX_CHECK(rp[0] >= 1e6f && rp[1] <= -1e6f);
    static const GLubyte one[4] = {0x80, 0, 0, 0};
    glRasterPos2i(20, 20);
    glBitmap(1, 1, 1e38f, -INFINITY, 0, 0, one); /* the origin far away */
    FX_CHECK_EQ(nlit(), 0);
    glBitmap(-1, 1, 0, 0, 0, 0, one);
    FX_CHECK_EQ(glGetError(), GL_INVALID_VALUE);
}

/* glPixelZoom(1e5, 1e5) made glDrawPixels a 10^10-iteration loop */
FX_TEST(glut_hostile_pixel_zoom_bounded)
{
    setup();
    glPixelZoom(1e5f, 1e5f);
    glRasterPos2i(0, 0);
    static const GLubyte px[2 * 2 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* bounded by the window, not by the zoom: about the cost of a zoom that
     * just fills the window (relative, so a loaded machine or valgrind
     * slows both alike; the unbounded loop took minutes) */
    glPixelZoom(20.0f, 20.0f);
    double t0 = now_s();
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, px);
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, px);
    double t_fill = now_s() - t0;
    glPixelZoom(1e5f, 1e5f);
    t0 = now_s();
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, px);
    glPixelZoom(1e38f, NAN);
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, px);
    double t_huge = now_s() - t0;
    FX_CHECK_MSG(t_huge < 20 * t_fill + 0.5, "glDrawPixels zoomed 1e5: %.3f s, zoom filling the window: %.3f s",
                 t_huge, t_fill);
    glPixelZoom(1e5f, 1e5f);
    glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, px);
    unsigned char p[3];
    glReadPixels(39, 39, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, p);
    FX_CHECK(p[0] == 255 && p[1] == 0 && p[2] == 0); /* the first pixel's block covers all */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

/* 65536 * 65536 + 2 wrapped to 2: the sphere wrote past a 2-vertex
 * buffer; glutWireSphere(-2^31) walked 2^21 columns per line */
FX_TEST(glut_hostile_sphere_counts)
{
    setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2, 2, -2, 2, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glutSolidSphere(1, 65536, 65537); /* clamped to 256 x 256 */
    FX_CHECK(lit(20, 20) && !lit(1, 1));
    /* a huge wire sphere costs about what a small one does: its lines walk
     * the window's columns only (relative, so valgrind's pace is no matter) */
    double t0 = now_s();
    glutWireSphere(1, 3, 200);
    double t_small = now_s() - t0;
    t0 = now_s();
    glutWireSphere(-2147483648.0, 3, 200);
    double t_huge = now_s() - t0;
    FX_CHECK_MSG(t_huge < 20 * t_small + 0.5, "huge wire sphere %.3f s, small %.3f s", t_huge, t_small);
    glutWireTorus(1e38, -1e38, 65536, 65536);
    glutSolidCone(1, 1, INT32_MAX, INT32_MAX);
    glutSolidCylinder(1, 1, INT32_MAX, 3);
    glutWireSphere(1, INT32_MIN, INT32_MAX);
    glutSolidCube(1e300);
    glutSolidTeapot(-1e300);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
}

/* NaN and infinities at entry points: GL's error or the documented clamp */
FX_TEST(glut_hostile_nan_inf_entry)
{
    setup();
    glPointSize(NAN);
    FX_CHECK_EQ(glGetError(), GL_INVALID_VALUE);
    glLineWidth(NAN);
    FX_CHECK_EQ(glGetError(), GL_INVALID_VALUE);
    GLfloat w;
    glGetFloatv(GL_LINE_WIDTH, &w);
    FX_CHECK(w == 1.0f);
    glClearDepth(NAN);
    GLdouble d = -1;
    glGetDoublev(GL_DEPTH_CLEAR_VALUE, &d);
    FX_CHECK(d == 0.0);
    glClearDepth(1);
    glRotated(INFINITY, 0, 0, 1); /* no angle: the identity */
    glRotated(NAN, 0, 0, 1);
    GLdouble m[16];
    glGetDoublev(GL_MODELVIEW_MATRIX, m);
    FX_CHECK(m[0] == 1.0 && m[5] == 1.0 && m[1] == 0.0);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, 1e38f); /* saturates: no UB */
    while (glGetError() != GL_NO_ERROR) {
    }
    glPixelStoref(GL_UNPACK_ALIGNMENT, -INFINITY);
    FX_CHECK_EQ(glGetError(), GL_INVALID_VALUE);
    GLint ui;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &ui);
    FX_CHECK_EQ(ui, 4);
}
