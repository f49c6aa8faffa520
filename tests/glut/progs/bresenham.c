/* SPDX-License-Identifier: MIT */
/* Lab 2: Bresenham's line drawing algorithm (all octants) with GL_POINTS. */
#include <GL/glut.h>
#include <stdlib.h>

void setPixel(int x, int y)
{
    glBegin(GL_POINTS);
    glVertex2i(x, y);
    glEnd();
}

void bresenham(int x1, int y1, int x2, int y2)
{
    int dx = abs(x2 - x1), dy = abs(y2 - y1);
    int sx = x2 > x1 ? 1 : -1, sy = y2 > y1 ? 1 : -1;
    int x = x1, y = y1, p, i;

    setPixel(x, y);
    if (dx > dy) {
        p = 2 * dy - dx;
        for (i = 0; i < dx; i++) {
            x += sx;
            if (p < 0) {
                p += 2 * dy;
            } else {
                y += sy;
                p += 2 * dy - 2 * dx;
            }
            setPixel(x, y);
        }
    } else {
        p = 2 * dx - dy;
        for (i = 0; i < dy; i++) {
            y += sy;
            if (p < 0) {
                p += 2 * dx;
            } else {
                x += sx;
                p += 2 * dx - 2 * dy;
            }
            setPixel(x, y);
        }
    }
}

void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 1.0, 1.0);
    /* a star of lines through the centre, one per octant */
    for (i = 0; i <= 400; i += 50) {
        bresenham(250, 250, 50 + i, 50);
        bresenham(250, 250, 50 + i, 450);
    }
    glColor3f(1.0, 1.0, 0.0);
    for (i = 50; i <= 450; i += 50) {
        bresenham(250, 250, 50, i);
        bresenham(250, 250, 450, i);
    }
    /* a triangle */
    glColor3f(0.0, 1.0, 0.0);
    bresenham(20, 20, 480, 100);
    bresenham(480, 100, 300, 480);
    bresenham(300, 480, 20, 20);
    glFlush();
}

void init(void)
{
    glClearColor(0.0, 0.0, 0.0, 0.0);
    gluOrtho2D(0.0, 500.0, 0.0, 500.0);   /* still in MODELVIEW mode, as in the handout */
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 500);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("Bresenham Line Drawing");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
