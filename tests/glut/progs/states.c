/* SPDX-License-Identifier: MIT */
/* A tour of GL 1.x state in one 2D frame: the ten glBegin modes, glVertex
 * and glColor in their other types (4 components, bytes, shorts, ints,
 * arrays), glRect, polygon modes, blending, scissor, glMultMatrix /
 * glLoadMatrix / glGet of matrices and the viewport, glDrawPixels at
 * glRasterPos in several forms, and glGetError after a bad enum. */
#include <GL/glut.h>

GLubyte img[8][12][3];

void panel(int x, int y)
{
    glLoadIdentity();
    glTranslatef(x, y, 0);
}

void display(void)
{
    int i, vp[4];
    GLfloat m[16];
    GLdouble shear[16] = { 1, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    GLshort sv[2] = { 40, 10 };
    GLint iv[3] = { 70, 30, 0 };
    GLdouble dv[3] = { 10.0, 60.0, 0.0 };
    GLubyte ub[3] = { 255, 128, 0 };
    GLint rv4[4] = { 120, 160, 0, 1 };

    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);

    /* the ten modes, one panel each, first row and second row */
    panel(10, 250);
    glColor3ub(255, 255, 255);
    glPointSize(3);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) glVertex2i(5 + 10 * i, 10 + 5 * i);
    glEnd();
    panel(110, 250);
    glColor3b(127, 40, 40);
    glBegin(GL_LINES);
    glVertex2s(0, 0); glVertex2s(80, 60); glVertex2s(0, 60); glVertex2s(80, 0);
    glEnd();
    panel(210, 250);
    glColor3s(0, 32767, 16000);
    glBegin(GL_LINE_STRIP);
    glVertex2f(0, 0); glVertex2f(20, 60); glVertex2f(40, 0); glVertex2f(60, 60); glVertex2f(80, 0);
    glEnd();
    panel(310, 250);
    glColor3i(2147483647, 2147483647, 0);
    glBegin(GL_LINE_LOOP);
    glVertex2d(0, 0); glVertex2d(80, 10); glVertex2d(60, 60); glVertex2d(10, 50);
    glEnd();
    panel(410, 250);
    glColor3ubv(ub);
    glBegin(GL_TRIANGLES);
    glVertex2i(0, 0); glVertex2i(40, 0); glVertex2i(20, 60);
    glVertex2i(45, 60); glVertex2i(85, 60); glVertex2i(65, 0);
    glEnd();
    panel(10, 150);
    /* flat: each triangle takes its last vertex's colour (Gouraud rounding
     * is the smooth program's business; this one stays pixel-exact) */
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 6; i++) {
        glColor3f(i / 5.0, 1 - i / 5.0, 0.5);
        glVertex2i(15 * i, (i & 1) * 60);
    }
    glEnd();
    panel(110, 150);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex2i(40, 30);
    for (i = 0; i < 5; i++) {
        glColor3f(0.2 * i, 0.3, 1 - 0.2 * i);
        glVertex2i(i & 1 ? 80 - 10 * i : 10 * i, i < 3 ? 0 : 60);
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    panel(210, 150);
    glColor4f(0.3, 0.6, 1.0, 1.0);
    glBegin(GL_QUADS);
    glVertex4f(0, 0, 0, 1); glVertex4f(60, 0, 0, 2); glVertex4f(60, 30, 0, 1); glVertex4f(0, 60, 0, 2);
    glEnd();
    panel(310, 150);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 5; i++) {
        glColor4ub(40 * i, 200, 255 - 40 * i, 255);
        glVertex3i(20 * i, 0, 0); glVertex3i(20 * i, 40 + 4 * i, 0);
    }
    glEnd();
    panel(410, 150);
    glColor3d(0.8, 0.2, 0.6);
    glBegin(GL_POLYGON);
    glVertex2sv(sv); glVertex2i(80, 20); glVertex2i(70, 60); glVertex2i(20, 55); glVertex2i(5, 30);
    glEnd();

    /* polygon modes: lines and points, front and back */
    panel(10, 60);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 0.5, 0.5);
    glRecti(0, 0, 40, 40);
    glPolygonMode(GL_FRONT, GL_POINT);
    glPolygonMode(GL_BACK, GL_FILL);
    glRectf(50, 0, 80, 40);   /* counter-clockwise: front, points */
    glRectd(80, 40, 100, 0);  /* clockwise: back, filled */
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    /* blending: translucent squares over each other */
    panel(130, 40);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1, 0, 0, 0.5); glRecti(0, 0, 50, 50);
    glColor4f(0, 1, 0, 0.5); glRecti(25, 25, 75, 75);
    glColor4ub(0, 0, 255, 96); glRecti(10, 40, 60, 90);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor3f(0.3, 0.3, 0.3); glRecti(60, 0, 90, 20);
    glDisable(GL_BLEND);

    /* a sheared frame from glMultMatrixd, read back with glGetFloatv and
     * loaded again (glLoadMatrixf) to place a second one */
    panel(240, 20);
    glMultMatrixd(shear);
    glColor3f(0.9, 0.9, 0.2);
    glBegin(GL_LINE_LOOP);
    glVertex2i(0, 0); glVertex2i(50, 0); glVertex2i(50, 50); glVertex2i(0, 50);
    glEnd();
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    m[12] += 70;
    glLoadMatrixf(m);
    glBegin(GL_TRIANGLES);
    glVertex2i(0, 0); glVertex2i(40, 0); glVertex2i(0, 40);
    glEnd();

    /* scissor: only a band of a big rectangle */
    glGetIntegerv(GL_VIEWPORT, vp);
    glEnable(GL_SCISSOR_TEST);
    glScissor(vp[2] - 80, 20, 30, 100);
    glLoadIdentity();
    glColor3f(0.2, 0.8, 0.8);
    glRecti(vp[2] - 120, 10, vp[2] - 10, 110);
    glDisable(GL_SCISSOR_TEST);

    /* pixels at raster positions given four ways */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glLoadIdentity();
    glTranslatef(400, 0, 0);
    glRasterPos2s(10, 10);
    glDrawPixels(12, 8, GL_RGB, GL_UNSIGNED_BYTE, img);
    glRasterPos3dv(dv);
    glDrawPixels(12, 8, GL_RGB, GL_UNSIGNED_BYTE, img);
    glRasterPos3iv(iv);
    glDrawPixels(12, 8, GL_RGB, GL_UNSIGNED_BYTE, img);
    glRasterPos4iv(rv4);
    glDrawPixels(12, 8, GL_RGB, GL_UNSIGNED_BYTE, img);

    /* glGetError: clean so far, then a bad enum is reported once */
    glLoadIdentity();
    i = glGetError() == GL_NO_ERROR;
    glBegin(0x7777);
    i = i && glGetError() == GL_INVALID_ENUM && glGetError() == GL_NO_ERROR;
    glColor3f(i ? 0 : 1, i ? 1 : 0, 0);
    glRecti(560, 10, 590, 40);
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    int x, y;
    for (y = 0; y < 8; y++)
        for (x = 0; x < 12; x++) {
            img[y][x][0] = (GLubyte)(x * 20);
            img[y][x][1] = (GLubyte)(y * 30);
            img[y][x][2] = (GLubyte)(((x ^ y) & 1) * 255);
        }
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(600, 340);
    glutCreateWindow("GL state tour");
    glClearColor(0.1, 0.1, 0.15, 1.0);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
