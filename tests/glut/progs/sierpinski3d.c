/* SPDX-License-Identifier: MIT */
/* 3D Sierpinski gasket: a tetrahedron divided into four smaller ones, recursively,
 * one colour per face, hidden surfaces removed with the depth buffer (Angel, ch. 2). */
#include <GL/glut.h>

typedef float point[3];

point v[] = { { 0.0, 0.0, 1.0 }, { 0.0, 0.942809, -0.33333 },
              { -0.816497, -0.471405, -0.333333 }, { 0.816497, -0.471405, -0.333333 } };
static GLfloat theta[] = { 0.0, 0.0, 0.0 };
int n = 3;

void triangle(point a, point b, point c)
{
    glBegin(GL_POLYGON);
    glVertex3fv(a);
    glVertex3fv(b);
    glVertex3fv(c);
    glEnd();
}

void tetra(point a, point b, point c, point d)
{
    glColor3f(1.0, 0.0, 0.0);
    triangle(a, b, c);
    glColor3f(0.0, 1.0, 0.0);
    triangle(a, c, d);
    glColor3f(0.0, 0.0, 1.0);
    triangle(a, d, b);
    glColor3f(0.0, 0.0, 0.0);
    triangle(b, d, c);
}

void divide_tetra(point a, point b, point c, point d, int m)
{
    point mid[6];
    int j;
    if (m > 0) {
        for (j = 0; j < 3; j++) mid[0][j] = (a[j] + b[j]) / 2;
        for (j = 0; j < 3; j++) mid[1][j] = (a[j] + c[j]) / 2;
        for (j = 0; j < 3; j++) mid[2][j] = (a[j] + d[j]) / 2;
        for (j = 0; j < 3; j++) mid[3][j] = (b[j] + c[j]) / 2;
        for (j = 0; j < 3; j++) mid[4][j] = (c[j] + d[j]) / 2;
        for (j = 0; j < 3; j++) mid[5][j] = (b[j] + d[j]) / 2;
        divide_tetra(a, mid[0], mid[1], mid[2], m - 1);
        divide_tetra(mid[0], b, mid[3], mid[5], m - 1);
        divide_tetra(mid[1], mid[3], c, mid[4], m - 1);
        divide_tetra(mid[2], mid[4], d, mid[5], m - 1);
    } else
        tetra(a, b, c, d);
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(theta[0], 1.0, 0.0, 0.0);
    glRotatef(theta[1], 0.0, 1.0, 0.0);
    divide_tetra(v[0], v[1], v[2], v[3], n);
    glFlush();
}

void myReshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (w <= h)
        glOrtho(-2.0, 2.0, -2.0 * (GLfloat)h / (GLfloat)w, 2.0 * (GLfloat)h / (GLfloat)w, -10.0, 10.0);
    else
        glOrtho(-2.0 * (GLfloat)w / (GLfloat)h, 2.0 * (GLfloat)w / (GLfloat)h, -2.0, 2.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(500, 500);
    glutCreateWindow("3D Gasket");
    theta[0] = -15.0;
    theta[1] = 20.0;
    glutReshapeFunc(myReshape);
    glutDisplayFunc(display);
    glEnable(GL_DEPTH_TEST);
    glClearColor(1.0, 1.0, 1.0, 1.0);
    glutMainLoop();
    return 0;
}
