/* SPDX-License-Identifier: MIT */
/* Midpoint ellipse algorithm (regions 1 and 2), four-way symmetry. */
#include <GL/glut.h>

void ellipsePlotPoints(int xc, int yc, int x, int y)
{
    glBegin(GL_POINTS);
    glVertex2i(xc + x, yc + y);
    glVertex2i(xc - x, yc + y);
    glVertex2i(xc + x, yc - y);
    glVertex2i(xc - x, yc - y);
    glEnd();
}

void ellipseMidpoint(int xc, int yc, int rx, int ry)
{
    long rx2 = (long)rx * rx, ry2 = (long)ry * ry;
    long twoRx2 = 2 * rx2, twoRy2 = 2 * ry2;
    long p, x = 0, y = ry, px = 0, py = twoRx2 * y;

    ellipsePlotPoints(xc, yc, x, y);
    /* region 1 */
    p = (long)(ry2 - (rx2 * ry) + (0.25 * rx2) + 0.5);
    while (px < py) {
        x++;
        px += twoRy2;
        if (p < 0)
            p += ry2 + px;
        else {
            y--;
            py -= twoRx2;
            p += ry2 + px - py;
        }
        ellipsePlotPoints(xc, yc, x, y);
    }
    /* region 2 */
    p = (long)(ry2 * (x + 0.5) * (x + 0.5) + rx2 * (y - 1) * (y - 1) - rx2 * ry2 + 0.5);
    while (y > 0) {
        y--;
        py -= twoRx2;
        if (p > 0)
            p += rx2 - py;
        else {
            x++;
            px += twoRy2;
            p += rx2 - py + px;
        }
        ellipsePlotPoints(xc, yc, x, y);
    }
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 0, 0);
    ellipseMidpoint(300, 200, 250, 120);
    glColor3f(0, 1, 0);
    ellipseMidpoint(300, 200, 120, 180);
    glColor3f(1, 1, 0);
    ellipseMidpoint(300, 200, 40, 40);
    glColor3f(0, 1, 1);
    ellipseMidpoint(100, 330, 80, 30);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(600, 400);
    glutCreateWindow("Midpoint Ellipse");
    glClearColor(1, 1, 1, 0);
    glClearColor(0, 0, 0, 0);
    gluOrtho2D(0, 600, 0, 400);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
