/* SPDX-License-Identifier: MIT */
/* DDA line algorithm. The window is 800x600 but the world is 400x300, so
 * every unit is two pixels wide and the points come out dotted. */
#include <GL/glut.h>
#include <math.h>
#include <stdlib.h>

int round_(float a) { return (int)(a + 0.5); }

void lineDDA(int xa, int ya, int xb, int yb)
{
    int dx = xb - xa, dy = yb - ya, steps, k;
    float xIncrement, yIncrement, x = xa, y = ya;

    if (abs(dx) > abs(dy))
        steps = abs(dx);
    else
        steps = abs(dy);
    xIncrement = dx / (float)steps;
    yIncrement = dy / (float)steps;

    glBegin(GL_POINTS);
    glVertex2i(round_(x), round_(y));
    for (k = 0; k < steps; k++) {
        x += xIncrement;
        y += yIncrement;
        glVertex2i(round_(x), round_(y));
    }
    glEnd();
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(1.0, 1.0, 1.0, 1.0);   /* too late for this frame: the first one is black */
    glColor3f(1.0, 0.0, 0.0);
    lineDDA(10, 10, 390, 290);
    glColor3f(0.0, 1.0, 0.0);
    lineDDA(10, 290, 390, 10);
    glColor3f(0.0, 0.0, 1.0);
    lineDDA(200, 10, 210, 290);
    glColor3f(1.0, 1.0, 0.0);
    lineDDA(10, 150, 390, 160);
    glColor3f(0.0, 1.0, 2.0);            /* student typo: blue 2.0 is clamped to 1 */
    lineDDA(50, 20, 120, 270);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(800, 600);
    glutCreateWindow("DDA");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 400, 0, 300);
    glMatrixMode(GL_MODELVIEW);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
