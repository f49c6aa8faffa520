/* SPDX-License-Identifier: MIT */
/* What glNewList(GL_COMPILE) holds (issue #38, "glBitmap executed instead
 * of recorded"): each state call and each raster call below is compiled
 * into a list and must change nothing until the list is called, and then
 * must do what it does outside a list. Bitmaps and pixel rectangles are
 * unpacked when the list is compiled, so changing the caller's array
 * afterwards changes nothing; glCallLists inside a list adds the list base
 * in effect when the list runs. Prints "ok NAME" or "bad NAME: why";
 * tests/glut/self.sh runs it on fixel and on freeglut + Mesa, and both
 * must print only ok lines, the same ones. */
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64
static int bad;

static void check(const char *name, int ok, const char *why)
{
    if (ok)
        printf("ok %s\n", name);
    else
        printf("bad %s: %s\n", name, why), bad = 1;
}
static void geti(GLenum p, GLint *v) { glGetIntegerv(p, v); }
static int red_at(int x, int y)
{
    unsigned char px[4] = {0};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return px[0];
}
static int lit_count(void)
{
    static unsigned char px[W * H * 4];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += px[i * 4] > 128;
    return n;
}
static void clear(void)
{
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void states(void)
{
    GLint v[4];
    GLfloat f[4];
    GLboolean b[4];

    glNewList(1, GL_COMPILE);
    glViewport(1, 2, 30, 40);
    glEndList();
    geti(GL_VIEWPORT, v);
    check("viewport-compiled", v[0] == 0 && v[1] == 0 && v[2] == W && v[3] == H, "changed by GL_COMPILE");
    glCallList(1);
    geti(GL_VIEWPORT, v);
    check("viewport-called", v[0] == 1 && v[1] == 2 && v[2] == 30 && v[3] == 40, "list did not set it");
    glViewport(0, 0, W, H);

    glNewList(2, GL_COMPILE);
    glScissor(3, 4, 5, 6);
    glEndList();
    geti(GL_SCISSOR_BOX, v);
    check("scissor-compiled", v[2] == W && v[3] == H, "changed by GL_COMPILE");
    glCallList(2);
    geti(GL_SCISSOR_BOX, v);
    check("scissor-called", v[0] == 3 && v[1] == 4 && v[2] == 5 && v[3] == 6, "list did not set it");
    glScissor(0, 0, W, H);

    glNewList(3, GL_COMPILE);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glDepthMask(GL_FALSE);
    glClearDepth(0.25);
    glEndList();
    glGetBooleanv(GL_COLOR_WRITEMASK, b);
    check("colormask-compiled", b[0] && b[1] && b[2] && b[3], "changed by GL_COMPILE");
    glGetBooleanv(GL_DEPTH_WRITEMASK, b);
    check("depthmask-compiled", b[0], "changed by GL_COMPILE");
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, f);
    check("cleardepth-compiled", f[0] == 1.0f, "changed by GL_COMPILE");
    glCallList(3);
    glGetBooleanv(GL_COLOR_WRITEMASK, b);
    check("colormask-called", !b[0] && b[1] && !b[2] && b[3], "list did not set it");
    glGetBooleanv(GL_DEPTH_WRITEMASK, b);
    check("depthmask-called", !b[0], "list did not set it");
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, f);
    check("cleardepth-called", f[0] > 0.249f && f[0] < 0.251f, "list did not set it");
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);

    glNewList(4, GL_COMPILE);
    glPixelZoom(2, 3);
    glListBase(7);
    glEndList();
    glGetFloatv(GL_ZOOM_X, f);
    geti(GL_LIST_BASE, v);
    check("zoom-listbase-compiled", f[0] == 1.0f && v[0] == 0, "changed by GL_COMPILE");
    glCallList(4);
    glGetFloatv(GL_ZOOM_Y, f);
    geti(GL_LIST_BASE, v);
    check("zoom-listbase-called", f[0] == 3.0f && v[0] == 7, "list did not set them");
    glPixelZoom(1, 1);
    glListBase(0);

    glRasterPos2i(5, 5);
    glNewList(5, GL_COMPILE);
    glWindowPos2i(20, 21);
    glEndList();
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    check("windowpos-compiled", f[0] == 5 && f[1] == 5, "changed by GL_COMPILE");
    glCallList(5);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    check("windowpos-called", f[0] == 20 && f[1] == 21, "list did not set it");
}

/* glCallLists in a list: the base is the one in effect at glCallList */
static void bases(void)
{
    GLint v[4];
    glNewList(11, GL_COMPILE);
    glViewport(0, 0, 11, 11);
    glEndList();
    glNewList(12, GL_COMPILE);
    glViewport(0, 0, 12, 12);
    glEndList();
    GLubyte one = 1;
    glListBase(10);
    glNewList(13, GL_COMPILE);
    glCallLists(1, GL_UNSIGNED_BYTE, &one);
    glEndList();
    geti(GL_VIEWPORT, v);
    check("calllists-compiled", v[2] == W, "a list ran while compiling");
    glListBase(11);
    glCallList(13);
    geti(GL_VIEWPORT, v);
    check("calllists-base-at-run", v[2] == 12, "the base at compile time was used");
    glListBase(0);
    glViewport(0, 0, W, H);
}

static void rasters(void)
{
    static GLubyte bits[8 * 4]; /* 8 rows of 32 pixels, 4-byte rows */
    memset(bits, 0xFF, sizeof bits);
    glColor3f(1, 1, 1);
    clear();
    glRasterPos2i(10, 10);
    glNewList(21, GL_COMPILE);
    glBitmap(32, 8, 0, 0, 7, 3, bits);
    glEndList();
    memset(bits, 0, sizeof bits); /* the list holds its own copy */
    GLfloat f[4];
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    check("bitmap-compiled", lit_count() == 0 && f[0] == 10 && f[1] == 10, "drawn or moved by GL_COMPILE");
    glCallList(21);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    check("bitmap-called", lit_count() == 32 * 8 && red_at(10, 10) && red_at(41, 17) && !red_at(42, 17),
          "not the 32x8 block at (10,10)");
    check("bitmap-moved", f[0] == 17 && f[1] == 13, "the raster position did not move by (7,3)");

    clear();
    glRasterPos2i(30, 30);
    glNewList(22, GL_COMPILE_AND_EXECUTE);
    glutBitmapCharacter(GLUT_BITMAP_8_BY_13, 'W');
    glEndList();
    int direct = lit_count();
    clear();
    glRasterPos2i(30, 30);
    glCallList(22);
    check("glut-char-in-list", direct > 10 && lit_count() == direct, "the character's list draws otherwise");
    clear();
    glRasterPos2i(30, 30);
    glNewList(23, GL_COMPILE);
    glutBitmapCharacter(GLUT_BITMAP_8_BY_13, 'W');
    glEndList();
    check("glut-char-compiled", lit_count() == 0, "drawn by GL_COMPILE");

    static GLubyte rgb[4 * 3 * 3]; /* 3x3 RGB, rows 1-byte aligned */
    memset(rgb, 0xFF, sizeof rgb);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    clear();
    glRasterPos2i(40, 40);
    glNewList(24, GL_COMPILE);
    glDrawPixels(3, 3, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    glEndList();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4); /* the list unpacked with 1 */
    memset(rgb, 0, sizeof rgb);
    check("drawpixels-compiled", lit_count() == 0, "drawn by GL_COMPILE");
    glCallList(24);
    check("drawpixels-called", lit_count() == 9 && red_at(40, 40) && red_at(42, 42), "not the 3x3 white block");
}

/* a texture environment and filter set inside a list */
static void textures(void)
{
    static const GLubyte tex[2 * 4] = {0, 0, 0, 255, 255, 255, 255, 255}; /* black, white */
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glNewList(31, GL_COMPILE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEndList();
    /* a quad over the whole window, coloured red: MODULATE gives black and
     * red halves, REPLACE black and white; NEAREST is flat per half,
     * LINEAR ramps */
    for (int pass = 0; pass < 2; pass++) {
        clear();
        glColor3f(1, 0, 0);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0), glVertex2f(0, 0);
        glTexCoord2f(1, 0), glVertex2f(W, 0);
        glTexCoord2f(1, 1), glVertex2f(W, H);
        glTexCoord2f(0, 1), glVertex2f(0, H);
        glEnd();
        unsigned char px[4];
        glReadPixels(W - 2, H / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        int white = px[1] > 200, red = px[0] > 200 && px[1] < 50;
        int mid = red_at(W / 2 - 1, H / 2), ramp = mid > 20 && mid < 235, step = red_at(W / 4, H / 2) == 0;
        if (pass == 0) {
            check("texenv-compiled", red && !white, "the mode changed by GL_COMPILE");
            check("texparam-compiled", step && !ramp, "the filter changed by GL_COMPILE");
            glCallList(31);
        } else {
            check("texenv-called", white, "the list did not set GL_REPLACE");
            check("texparam-called", ramp, "the list did not set GL_LINEAR");
        }
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(1, &t);
}

static void display(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(0, 0, W, H);
    states();
    bases();
    rasters();
    textures();
    GLenum e = glGetError();
    check("no-gl-error", e == GL_NO_ERROR, "glGetError was not GL_NO_ERROR");
    fflush(stdout);
    _Exit(bad);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGBA | GLUT_DEPTH | GLUT_SINGLE);
    glutInitWindowSize(W, H);
    glutCreateWindow("lists");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
