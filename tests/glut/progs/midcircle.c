/* SPDX-License-Identifier: MIT */
/* Midpoint circle algorithm with eight-way symmetry. */
#include <GL/glut.h>

int xc = 320, yc = 240;

void plot(int x, int y)
{
    glBegin(GL_POINTS);
    glVertex2i(x + xc, y + yc);
    glEnd();
}

void circlePoints(int x, int y)
{
    plot(x, y);  plot(y, x);  plot(-x, y); plot(-y, x);
    plot(-x, -y); plot(-y, -x); plot(x, -y); plot(y, -x);
}

void midPointCircle(int r)
{
    int x = 0, y = r;
    int p = 1 - r;
    circlePoints(x, y);
    while (x < y) {
        x++;
        if (p < 0)
            p += 2 * x + 1;
        else {
            y--;
            p += 2 * (x - y) + 1;
        }
        circlePoints(x, y);
    }
}

void display(void)
{
    int r;
    glClear(GL_COLOR_BUFFER_BIT);
    for (r = 20; r <= 220; r += 40) {
        glColor3f(r / 220.0, 1.0 - r / 220.0, 0.5);
        midPointCircle(r);
    }
    glPointSize(3.0);
    glColor3f(1.0, 1.0, 1.0);
    xc = 100; yc = 100;
    midPointCircle(60);
    glPointSize(1.0);
    xc = 320; yc = 240;
    glFlush();
}

void myInit(void)
{
    glClearColor(0.0, 0.0, 0.2, 1.0);
    glColor3f(1.0, 1.0, 1.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 640.0, 0.0, 480.0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutInitWindowPosition(0, 0);
    glutCreateWindow("Midpoint Circle");
    glutDisplayFunc(display);
    myInit();
    glutMainLoop();
    return 0;
}
