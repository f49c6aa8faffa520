/* SPDX-License-Identifier: MIT */
/* Koch curve, recursion depths 1 to 4, in the default -1..1 coordinates. */
#include <GL/glut.h>
#include <math.h>

void koch(float x1, float y1, float x2, float y2, int n)
{
    float dx = (x2 - x1) / 3, dy = (y2 - y1) / 3;
    float xa = x1 + dx, ya = y1 + dy;
    float xb = x1 + 2 * dx, yb = y1 + 2 * dy;
    /* the apex: the middle third turned by 60 degrees */
    float xc = xa + dx * cos(M_PI / 3) - dy * sin(M_PI / 3);
    float yc = ya + dx * sin(M_PI / 3) + dy * cos(M_PI / 3);
    if (n == 0) {
        glVertex2f(x1, y1);
        glVertex2f(x2, y2);
        return;
    }
    koch(x1, y1, xa, ya, n - 1);
    koch(xa, ya, xc, yc, n - 1);
    koch(xc, yc, xb, yb, n - 1);
    koch(xb, yb, x2, y2, n - 1);
}

void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 1; i <= 4; i++) {
        glColor3f(1.0, 1.0 - i * 0.2, i * 0.25);
        glBegin(GL_LINES);
        koch(-0.9, 0.9 - i * 0.45, 0.9, 0.9 - i * 0.45, i);
        glEnd();
    }
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(600, 600);
    glutCreateWindow("Koch Curve");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
