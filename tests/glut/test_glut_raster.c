/* SPDX-License-Identifier: MIT */
/* The GL layer against pixels measured on Mesa 22.3 llvmpipe (the probes of
 * tests/glut/mesa: 40x40 window, gluOrtho2D(0, 40, 0, 40), white on black).
 * Coordinates in the expectations are GL window pixels, y up. */
#include <GL/glut.h>
#include <stdio.h>
#include <string.h>

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
    glDisable(GL_LINE_STIPPLE);
    glShadeModel(GL_SMOOTH);
    glPointSize(1);
    glLineWidth(1);
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

/* The lit pixels as "x,y x,y ..." sorted by row then column. */
static void lit_list(char *buf, size_t n)
{
    size_t k = 0;
    buf[0] = 0;
    for (int y = 0; y < 40; y++)
        for (int x = 0; x < 40; x++)
            if (lit(x, y) && k + 12 < n)
                k += (size_t)snprintf(buf + k, n - k, "%s%d,%d", k ? " " : "", x, y);
}

#define EXPECT_LIT(str)                                                       \
    do {                                                                      \
        char got_[4096];                                                      \
        lit_list(got_, sizeof got_);                                          \
        FX_CHECK_MSG(!strcmp(got_, str), "got  %s\nwant %s", got_, str);      \
    } while (0)

FX_TEST(glut_points_size1_floor)
{
    setup();
    glBegin(GL_POINTS);
    glVertex2i(5, 5);
    glVertex2f(10.5f, 5.5f);
    glVertex2f(15.25f, 5.75f);
    glVertex2f(20.5f, 5.0f);
    glVertex2f(25.0f, 5.5f);
    glEnd();
    EXPECT_LIT("5,5 10,5 15,5 20,5 25,5");
}

FX_TEST(glut_points_wide_squares)
{
    setup();
    glPointSize(2);
    glBegin(GL_POINTS);
    glVertex2i(5, 5);
    glVertex2f(10.5f, 10.5f);
    glEnd();
    EXPECT_LIT("4,4 5,4 4,5 5,5 10,10 11,10 10,11 11,11");
    setup();
    glPointSize(3);
    glBegin(GL_POINTS);
    glVertex2i(5, 5);
    glVertex2f(10.5f, 10.5f);
    glEnd();
    EXPECT_LIT("4,4 5,4 6,4 4,5 5,5 6,5 4,6 5,6 6,6 9,9 10,9 11,9 9,10 10,10 11,10 9,11 10,11 11,11");
}

static void line2(double x0, double y0, double x1, double y1)
{
    glBegin(GL_LINES);
    glVertex2d(x0, y0);
    glVertex2d(x1, y1);
    glEnd();
}

FX_TEST(glut_lines_integer_ties)
{
    /* each line drawn both ways lights the same pixels */
    static const struct {
        double x0, y0, x1, y1;
        const char *want;
    } lines[] = {
        {2, 20, 12, 20, "2,19 3,19 4,19 5,19 6,19 7,19 8,19 9,19 10,19 11,19"},
        {20, 2, 20, 12, "19,2 19,3 19,4 19,5 19,6 19,7 19,8 19,9 19,10 19,11"},
        {2, 2, 10, 10, "2,2 3,3 4,4 5,5 6,6 7,7 8,8 9,9"},
        {2, 2, 10, 6, "2,2 3,2 4,3 5,3 6,4 7,4 8,5 9,5"},
        {2, 2, 6, 10, "2,2 2,3 3,4 3,5 4,6 4,7 5,8 5,9"},
    };
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        setup();
        line2(lines[i].x0, lines[i].y0, lines[i].x1, lines[i].y1);
        EXPECT_LIT(lines[i].want);
        setup();
        line2(lines[i].x1, lines[i].y1, lines[i].x0, lines[i].y0);
        EXPECT_LIT(lines[i].want);
    }
}

FX_TEST(glut_lines_centres_and_width)
{
    setup();
    line2(2.5, 2.5, 10.5, 6.5);
    EXPECT_LIT("2,2 3,3 4,3 5,4 6,4 7,5 8,5 9,6");
    setup();
    glLineWidth(2);
    line2(2, 20, 12, 20);
    line2(2, 10.5, 12, 10.5);
    EXPECT_LIT("2,9 3,9 4,9 5,9 6,9 7,9 8,9 9,9 10,9 11,9 2,10 3,10 4,10 5,10 6,10 7,10 8,10 9,10 "
               "10,10 11,10 2,19 3,19 4,19 5,19 6,19 7,19 8,19 9,19 10,19 11,19 2,20 3,20 4,20 "
               "5,20 6,20 7,20 8,20 9,20 10,20 11,20");
}

FX_TEST(glut_line_loop_no_double_corners)
{
    setup();
    glBegin(GL_LINE_LOOP);
    glVertex2i(2, 2);
    glVertex2i(10, 2);
    glVertex2i(10, 8);
    glVertex2i(2, 8);
    glEnd();
    EXPECT_LIT("2,1 3,1 4,1 5,1 6,1 7,1 8,1 9,1 1,2 9,2 1,3 9,3 1,4 9,4 1,5 9,5 1,6 9,6 1,7 2,7 "
               "3,7 4,7 5,7 6,7 7,7 8,7 9,7");
}

FX_TEST(glut_triangle_ties_bottom_left)
{
    setup();
    glBegin(GL_TRIANGLES);
    glVertex2i(2, 2), glVertex2i(10, 2), glVertex2i(2, 10);
    glEnd();
    EXPECT_LIT("2,2 3,2 4,2 5,2 6,2 7,2 8,2 2,3 3,3 4,3 5,3 6,3 7,3 2,4 3,4 4,4 5,4 6,4 2,5 3,5 4,5 "
               "5,5 2,6 3,6 4,6 2,7 3,7 2,8");
    setup();
    glBegin(GL_TRIANGLES);
    glVertex2i(10, 2), glVertex2i(10, 10), glVertex2i(2, 10);
    glEnd();
    EXPECT_LIT("9,2 8,3 9,3 7,4 8,4 9,4 6,5 7,5 8,5 9,5 5,6 6,6 7,6 8,6 9,6 4,7 5,7 6,7 7,7 8,7 9,7 "
               "3,8 4,8 5,8 6,8 7,8 8,8 9,8 2,9 3,9 4,9 5,9 6,9 7,9 8,9 9,9");
    setup();
    glBegin(GL_TRIANGLES);
    glVertex2f(2, 2.5f), glVertex2f(10, 2.5f), glVertex2f(2, 10.5f);
    glEnd();
    EXPECT_LIT("2,2 3,2 4,2 5,2 6,2 7,2 8,2 9,2 2,3 3,3 4,3 5,3 6,3 7,3 8,3 2,4 3,4 4,4 5,4 6,4 7,4 "
               "2,5 3,5 4,5 5,5 6,5 2,6 3,6 4,6 5,6 2,7 3,7 4,7 2,8 3,8 2,9");
}

static void rgb(int x, int y, int *r, int *g, int *b)
{
    unsigned char p[3];
    glReadPixels(x, y, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, p);
    *r = p[0], *g = p[1], *b = p[2];
}
#define EXPECT_RGB(x, y, R, G, B)                                                       \
    do {                                                                                \
        int r_, g_, b_;                                                                 \
        rgb(x, y, &r_, &g_, &b_);                                                       \
        FX_CHECK_MSG(r_ == (R) && g_ == (G) && b_ == (B), "(%d,%d) = %d,%d,%d want %d,%d,%d", \
                     x, y, r_, g_, b_, R, G, B);                                        \
    } while (0)

static void quad4(GLenum mode)
{
    glBegin(mode);
    glColor3f(1, 0, 0), glVertex2i(2, 2);
    glColor3f(0, 1, 0), glVertex2i(20, 2);
    glColor3f(0, 0, 1), glVertex2i(20, 20);
    glColor3f(1, 1, 1), glVertex2i(2, 20);
    glEnd();
}

/* A triangle from a red (2, 2) to a green (bx, by) and a blue (cx, cy) vertex. */
static void rgb_triangle(int bx, int by, int cx, int cy)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0), glVertex2i(2, 2);
    glColor3f(0, 1, 0), glVertex2i(bx, by);
    glColor3f(0, 0, 1), glVertex2i(cx, cy);
    glEnd();
}

FX_TEST(glut_smooth_quads_fan_from_v0)
{
    /* llvmpipe's values at these pixels (the quad is split along v0-v2) */
    GLenum modes[2] = {GL_QUADS, GL_POLYGON};
    for (int i = 0; i < 2; i++) {
        setup();
        quad4(modes[i]);
        EXPECT_RGB(3, 3, 234, 0, 21);
        EXPECT_RGB(18, 3, 21, 213, 21);
        EXPECT_RGB(18, 18, 21, 0, 234);
        EXPECT_RGB(10, 4, 135, 85, 35);
        EXPECT_RGB(4, 10, 220, 85, 120);
        EXPECT_RGB(10, 10, 135, 0, 120);
        EXPECT_RGB(11, 11, 120, 0, 135);
    }
}

FX_TEST(glut_flat_provoking_vertex)
{
    setup();
    glShadeModel(GL_FLAT);
    quad4(GL_QUADS); /* last vertex: white */
    EXPECT_RGB(3, 3, 255, 255, 255);
    EXPECT_RGB(18, 18, 255, 255, 255);
    setup();
    glShadeModel(GL_FLAT);
    quad4(GL_POLYGON); /* first vertex: red */
    EXPECT_RGB(3, 3, 255, 0, 0);
    EXPECT_RGB(4, 10, 255, 0, 0);
    setup();
    glShadeModel(GL_FLAT);
    rgb_triangle(20, 2, 20, 20);
    EXPECT_RGB(10, 4, 0, 0, 255);
}

FX_TEST(glut_smooth_triangle_values)
{
    setup();
    rgb_triangle(30, 2, 2, 30);
    EXPECT_RGB(3, 3, 228, 14, 14);
    EXPECT_RGB(10, 4, 155, 77, 23);
    EXPECT_RGB(10, 10, 100, 77, 77);
    EXPECT_RGB(11, 11, 82, 87, 87);
}

FX_TEST(glut_colour_conversion_and_clamp)
{
    setup();
    glColor3f(0.5f, 0.25f, 1.0f / 3);
    glBegin(GL_POINTS), glVertex2i(1, 1), glEnd();
    EXPECT_RGB(1, 1, 128, 64, 85);
    glColor3f(0, 1, 2); /* textbooks pass colours above 1: clamped */
    glBegin(GL_POINTS), glVertex2i(2, 1), glEnd();
    EXPECT_RGB(2, 1, 0, 255, 255);
    glColor3ub(12, 34, 56);
    glBegin(GL_POINTS), glVertex2i(3, 1), glEnd();
    EXPECT_RGB(3, 1, 12, 34, 56);
    /* boundary conversion: nearest, saturating */
    FX_CHECK_EQ(fx_glut_d2x(0.5), (int64_t)1 << 31);
    FX_CHECK_EQ(fx_glut_d2x(-1.0), -((int64_t)1 << 32));
    FX_CHECK_EQ(fx_glut_d2x(1e300), INT64_MAX);
    FX_CHECK_EQ(fx_glut_d2c(2.0), 65536);
    FX_CHECK_EQ(fx_glut_d2c(-0.5), 0);
    FX_CHECK_EQ(fx_glut_deg2angle(90.0), 0x40000000u);
    FX_CHECK_EQ(fx_glut_deg2angle(-90.0), 0xC0000000u);
}

FX_TEST(glut_viewport_clips_wide_points)
{
    setup();
    glViewport(10, 10, 20, 20);
    glPointSize(5);
    glBegin(GL_POINTS), glVertex2f(0.5f, 20), glEnd();
    EXPECT_LIT("10,18 11,18 12,18 10,19 11,19 12,19 10,20 11,20 12,20 10,21 11,21 12,21 10,22 "
               "11,22 12,22");
}

FX_TEST(glut_matrix_stack_and_errors)
{
    setup();
    glLoadIdentity();
    glTranslatef(3, 4, 5);
    glPushMatrix();
    glScalef(2, 2, 2);
    GLfloat m[16];
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    FX_CHECK(m[0] == 2 && m[5] == 2 && m[12] == 3 && m[13] == 4 && m[14] == 5);
    glPopMatrix();
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    FX_CHECK(m[0] == 1 && m[12] == 3);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
    glPopMatrix();
    FX_CHECK_EQ(glGetError(), GL_STACK_UNDERFLOW);
    for (int i = 0; i < 40; i++)
        glPushMatrix();
    FX_CHECK_EQ(glGetError(), GL_STACK_OVERFLOW);
    for (int i = 0; i < 40; i++)
        glPopMatrix();
    glGetError();
    glBegin(12345);
    FX_CHECK_EQ(glGetError(), GL_INVALID_ENUM);
    glEnd();
    FX_CHECK_EQ(glGetError(), GL_INVALID_OPERATION);
    glLogicOp(GL_XOR); /* declared, not implemented: recorded */
    FX_CHECK_EQ(glGetError(), GL_INVALID_OPERATION);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
    glRotatef(90, 0, 0, 1);
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    FX_CHECK(m[0] == 0 && m[1] == 1 && m[4] == -1 && m[5] == 0);
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    FX_CHECK(vp[0] == 0 && vp[2] == 40);
}

FX_TEST(glut_lighting_equation)
{
    /* one white directional light along +z onto a normal tilted 60 degrees:
     * ambient 0.2*0.2 (global) + 0 (light ambient) + 0.8 * cos 60 = 0.44 */
    fx_gl_lighting L;
    memset(&L, 0, sizeof L);
    L.model_ambient[0] = L.model_ambient[1] = L.model_ambient[2] = fx_glut_d2c(0.2);
    L.light[0].enabled = 1;
    for (int k = 0; k < 4; k++)
        L.light[0].diffuse[k] = L.light[0].specular[k] = 65536;
    L.light[0].pos[2] = FX32_ONE;
    L.light[0].att[0] = FX32_ONE;
    fx_gl_material m;
    memset(&m, 0, sizeof m);
    for (int k = 0; k < 3; k++)
        m.ambient[k] = fx_glut_d2c(0.2), m.diffuse[k] = fx_glut_d2c(0.8);
    m.diffuse[3] = 65536;
    fx32 p[4] = {0, 0, -5 * FX32_ONE, FX32_ONE};
    fx32 n[3] = {fx_glut_d2x(0.8660254037844386), 0, fx_glut_d2x(0.5)};
    fx16 out[4];
    fx_gl_shade(&L, &m, p, n, out);
    FX_CHECK_MSG(out[0] > fx_glut_d2c(0.4399) && out[0] < fx_glut_d2c(0.4401), "got %d", out[0]);
    /* specular: shininess 10, H = normalize(L + z) = z, N.H = 0.5 -> 0.5^10 */
    m.specular[0] = 65536;
    m.shininess = 10 << 16;
    fx_gl_shade(&L, &m, p, n, out);
    double want = 0.44 + 1.0 / 1024;
    FX_CHECK_MSG(out[0] > fx_glut_d2c(want - 0.0002) && out[0] < fx_glut_d2c(want + 0.0002), "got %d", out[0]);
    FX_CHECK_EQ(out[3], 65536);
    /* attenuation 1 / (1 + 0.5 d) with a point light at distance 2 along +z */
    L.light[0].pos[2] = 2 * FX32_ONE - 5 * FX32_ONE;
    L.light[0].pos[3] = FX32_ONE;
    L.light[0].att[1] = FX32_HALF;
    m.specular[0] = 0;
    n[0] = 0, n[2] = FX32_ONE;
    fx_gl_shade(&L, &m, p, n, out);
    FX_CHECK_MSG(out[0] > fx_glut_d2c(0.04 + 0.4 - 0.0003) && out[0] < fx_glut_d2c(0.44 + 0.0003), "got %d", out[0]);
    FX_CHECK_EQ(fx_gl_pow(32768, 2 << 16), 16384);
}

FX_TEST(glut_lighting_local_viewer)
{
    /* a directional light along +x and a vertex at (3, 0, -3) with normal
     * (1, 0, 1)/sqrt2: the infinite viewer's H = normalize(x + z) is the
     * normal (N.H = 1, full highlight); the local viewer looks along
     * normalize(-P) = (-1, 0, 1)/sqrt2, so H = normalize((1 - 0.7071, 0,
     * 0.7071)) and N.H = cos 22.5 = 0.92388 -> 0.92388^8 = 0.5306 */
    fx_gl_lighting L;
    memset(&L, 0, sizeof L);
    L.light[0].enabled = 1;
    for (int k = 0; k < 4; k++)
        L.light[0].specular[k] = 65536;
    L.light[0].pos[0] = FX32_ONE;
    L.light[0].att[0] = FX32_ONE;
    fx_gl_material m;
    memset(&m, 0, sizeof m);
    m.specular[0] = 65536;
    m.shininess = 8 << 16;
    fx32 p[4] = {3 * FX32_ONE, 0, -3 * FX32_ONE, FX32_ONE};
    fx32 n[3] = {fx_glut_d2x(0.7071067811865476), 0, fx_glut_d2x(0.7071067811865476)};
    fx16 out[4];
    fx_gl_shade(&L, &m, p, n, out);
    FX_CHECK_MSG(out[0] > fx_glut_d2c(0.999), "infinite viewer: got %d", out[0]);
    L.local_viewer = 1;
    fx_gl_shade(&L, &m, p, n, out);
    FX_CHECK_MSG(out[0] > fx_glut_d2c(0.5306 - 0.001) && out[0] < fx_glut_d2c(0.5306 + 0.001), "local viewer: got %d",
                 out[0]);
    /* the cached entry point gives the same bits with a local viewer */
    fx_gl_shade_cache c;
    memset(&c, 0, sizeof c);
    fx16 out2[4];
    fx_gl_shade_cached(&L, &c, &m, p, n, out2);
    fx_gl_shade_cached(&L, &c, &m, p, n, out2);
    FX_CHECK_EQ(out2[0], out[0]);
}

FX_TEST(glut_display_list_replays)
{
    setup();
    GLuint l = glGenLists(1);
    glNewList(l, GL_COMPILE);
    glBegin(GL_POINTS);
    glVertex2i(7, 7);
    glEnd();
    glEndList();
    FX_CHECK(!lit(7, 7));
    glTranslatef(1, 0, 0);
    glCallList(l);
    FX_CHECK(lit(8, 7));
    FX_CHECK(!lit(7, 7));
    glDeleteLists(l, 1);
}

/* Hidden triangles are left out before set-up (glraster.c, hidden_by_depth):
 * that must change no pixel. A triangle behind a nearer one leaves it; one
 * at the same depth is drawn under GL_LEQUAL and not under GL_LESS; one
 * a depth step in front is drawn under GL_LESS; gradients of depth inside
 * a tilted triangle behind a flat one at its nearest vertex's depth. */
static unsigned char red_at(int x, int y)
{
    unsigned char p[3];
    glReadPixels(x, y, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, p);
    return p[0];
}
static void quad_z(float z0, float z1, float r)
{
    glColor3f(r, 0, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(5, 5, z0);
    glVertex3f(35, 5, z0);
    glVertex3f(5, 35, z1);
    glEnd();
}
FX_TEST(glut_hidden_triangles_same_pixels)
{
    setup();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 40, 0, 40, -1, 1); /* depth = (1 - z) / 2 of the range */
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    /* the whole window at one depth, so that every box below lies on it */
    glColor3f(0.2f, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, 0.5f);
    glVertex3f(40, 0, 0.5f);
    glVertex3f(40, 40, 0.5f);
    glVertex3f(0, 40, 0.5f);
    glEnd();
    quad_z(0.25f, 0.25f, 1.0f); /* behind */
    FX_CHECK_EQ(red_at(10, 10), 51);
    quad_z(0.5f, 0.5f, 1.0f); /* same depth, GL_LESS: fails */
    FX_CHECK_EQ(red_at(10, 10), 51);
    glDepthFunc(GL_LEQUAL);
    quad_z(0.5f, 0.5f, 0.6f); /* same depth, GL_LEQUAL: passes */
    FX_CHECK_EQ(red_at(10, 10), 153);
    FX_CHECK_EQ(red_at(20, 12), 153);
    glDepthFunc(GL_LESS);
    quad_z(0.5f + 1.0f / 8388608, 0.5f + 1.0f / 8388608, 0.8f); /* one depth step nearer */
    FX_CHECK_EQ(red_at(10, 10), 204);
    /* tilted: nearest vertex level with the stored depth, the rest behind */
    quad_z(0.5f + 1.0f / 8388608, -0.5f, 0.4f);
    FX_CHECK_EQ(red_at(10, 10), 204);
    /* tilted the other way: in front away from its farthest vertex */
    quad_z(0.0f, 0.9f, 1.0f);
    FX_CHECK_EQ(red_at(6, 30), 255);
    FX_CHECK_EQ(red_at(30, 6), 204);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

/* glMatrixMode(GL_TEXTURE): the texture matrix moves the texture on the
 * quad (GL 1.x 2.11.2). A 2x2 texture red green / blue white (t up),
 * nearest, repeat, replace, on a quad with (s, t) = (x, y) / 40. */
static void texel_probe(unsigned char out[4][3])
{
    static const int at[4][2] = {{10, 10}, {30, 10}, {10, 30}, {30, 30}};
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0), glVertex2f(0, 0);
    glTexCoord2f(1, 0), glVertex2f(40, 0);
    glTexCoord2f(1, 1), glVertex2f(40, 40);
    glTexCoord2f(0, 1), glVertex2f(0, 40);
    glEnd();
    for (int i = 0; i < 4; i++)
        glReadPixels(at[i][0], at[i][1], 1, 1, GL_RGB, GL_UNSIGNED_BYTE, out[i]);
}

static int is_rgb(const unsigned char p[3], int r, int g, int b) { return p[0] == r && p[1] == g && p[2] == b; }

FX_TEST(glut_texture_matrix_moves_the_texture)
{
    setup();
    static const unsigned char img[2][2][3] = {{{255, 0, 0}, {0, 255, 0}}, {{0, 0, 255}, {255, 255, 255}}};
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    unsigned char p[4][3];
    texel_probe(p); /* identity: bottom-left red, bottom-right green, top-left blue */
    FX_CHECK(is_rgb(p[0], 255, 0, 0) && is_rgb(p[1], 0, 255, 0) && is_rgb(p[2], 0, 0, 255) &&
             is_rgb(p[3], 255, 255, 255));
    glMatrixMode(GL_TEXTURE);
    glPushMatrix();
    glTranslatef(0.5f, 0, 0); /* s + 1/2: the columns swap (repeat) */
    glMatrixMode(GL_MODELVIEW);
    texel_probe(p);
    FX_CHECK_MSG(is_rgb(p[0], 0, 255, 0) && is_rgb(p[1], 255, 0, 0) && is_rgb(p[2], 255, 255, 255) &&
                     is_rgb(p[3], 0, 0, 255),
                 "translated: %d,%d,%d %d,%d,%d", p[0][0], p[0][1], p[0][2], p[1][0], p[1][1], p[1][2]);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glRotatef(90, 0, 0, 1); /* (s, t) -> (-t, s) */
    texel_probe(p);
    /* (0.25, 0.25) -> (-0.25, 0.25) = green; (0.75, 0.25) -> (-0.25, 0.75) = white;
     * (0.25, 0.75) -> (-0.75, 0.25) = red; (0.75, 0.75) -> (-0.75, 0.75) = blue */
    FX_CHECK(is_rgb(p[0], 0, 255, 0) && is_rgb(p[1], 255, 255, 255) && is_rgb(p[2], 255, 0, 0) &&
             is_rgb(p[3], 0, 0, 255));
    GLfloat m[16];
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    FX_CHECK(m[0] == 0 && m[1] == 1 && m[4] == -1);
    glPopMatrix();
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    FX_CHECK(m[0] == 1 && m[1] == 0 && m[4] == 0 && m[12] == 0);
    FX_CHECK_EQ(glGetError(), GL_NO_ERROR);
    glMatrixMode(GL_MODELVIEW);
    texel_probe(p); /* popped: the identity again */
    FX_CHECK(is_rgb(p[0], 255, 0, 0) && is_rgb(p[1], 0, 255, 0));
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &tex);
}
