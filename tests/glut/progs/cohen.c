/* SPDX-License-Identifier: MIT */
/* Cohen-Sutherland line clipping. Left: the clip window (GL_LINE_LOOP) and
 * the lines in red; right: the viewport, with the clipped lines mapped into it
 * by the window-to-viewport transformation. */
#include <GL/glut.h>
#include <stdio.h>

double xmin = 50, ymin = 50, xmax = 100, ymax = 100;     /* window */
double xvmin = 200, yvmin = 200, xvmax = 300, yvmax = 300; /* viewport */

const int RIGHT = 8, TOP = 4, LEFT = 2, BOTTOM = 1;

int computeOutCode(double x, double y)
{
    int code = 0;
    if (y > ymax) code |= TOP;
    else if (y < ymin) code |= BOTTOM;
    if (x > xmax) code |= RIGHT;
    else if (x < xmin) code |= LEFT;
    return code;
}

void CohenSutherlandLineClipAndDraw(double x0, double y0, double x1, double y1)
{
    int outcode0 = computeOutCode(x0, y0), outcode1 = computeOutCode(x1, y1), outcodeOut;
    int accept = 0, done = 0;
    double x = 0, y = 0;

    do {
        if (!(outcode0 | outcode1)) {
            accept = 1;
            done = 1;
        } else if (outcode0 & outcode1) {
            done = 1;
        } else {
            outcodeOut = outcode0 ? outcode0 : outcode1;
            if (outcodeOut & TOP) {
                x = x0 + (x1 - x0) * (ymax - y0) / (y1 - y0);
                y = ymax;
            } else if (outcodeOut & BOTTOM) {
                x = x0 + (x1 - x0) * (ymin - y0) / (y1 - y0);
                y = ymin;
            } else if (outcodeOut & RIGHT) {
                y = y0 + (y1 - y0) * (xmax - x0) / (x1 - x0);
                x = xmax;
            } else {
                y = y0 + (y1 - y0) * (xmin - x0) / (x1 - x0);
                x = xmin;
            }
            if (outcodeOut == outcode0) {
                x0 = x; y0 = y;
                outcode0 = computeOutCode(x0, y0);
            } else {
                x1 = x; y1 = y;
                outcode1 = computeOutCode(x1, y1);
            }
        }
    } while (!done);

    if (accept) {
        double sx = (xvmax - xvmin) / (xmax - xmin);
        double sy = (yvmax - yvmin) / (ymax - ymin);
        double vx0 = xvmin + (x0 - xmin) * sx;
        double vy0 = yvmin + (y0 - ymin) * sy;
        double vx1 = xvmin + (x1 - xmin) * sx;
        double vy1 = yvmin + (y1 - ymin) * sy;
        glColor3f(0.0, 0.0, 1.0);
        glBegin(GL_LINE_LOOP);
        glVertex2f(xvmin, yvmin);
        glVertex2f(xvmax, yvmin);
        glVertex2f(xvmax, yvmax);
        glVertex2f(xvmin, yvmax);
        glEnd();
        glColor3f(0.0, 0.6, 0.0);
        glBegin(GL_LINES);
        glVertex2d(vx0, vy0);
        glVertex2d(vx1, vy1);
        glEnd();
    }
}

double lines[][4] = {
    { 60, 20, 80, 120 }, { 30, 60, 120, 90 }, { 10, 10, 130, 130 },
    { 20, 110, 110, 20 }, { 70, 70, 90, 80 }, { 10, 120, 40, 140 },
};

void display(void)
{
    unsigned i;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 0.0, 0.0);
    for (i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        glBegin(GL_LINES);
        glVertex2d(lines[i][0], lines[i][1]);
        glVertex2d(lines[i][2], lines[i][3]);
        glEnd();
    }
    glColor3f(0.0, 0.0, 1.0);
    glBegin(GL_LINE_LOOP);
    glVertex2f(xmin, ymin);
    glVertex2f(xmax, ymin);
    glVertex2f(xmax, ymax);
    glVertex2f(xmin, ymax);
    glEnd();
    for (i = 0; i < sizeof lines / sizeof lines[0]; i++)
        CohenSutherlandLineClipAndDraw(lines[i][0], lines[i][1], lines[i][2], lines[i][3]);
    glFlush();
}

void myinit(void)
{
    glClearColor(1.0, 1.0, 1.0, 1.0);
    glColor3f(1.0, 0.0, 0.0);
    glPointSize(1.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 499.0, 0.0, 499.0);
}

int main(int argc, char **argv)
{
    printf("Cohen-Sutherland line clipping\n");
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 500);
    glutInitWindowPosition(0, 0);
    glutCreateWindow("Cohen Sutherland Line Clipping Algorithm");
    glutDisplayFunc(display);
    myinit();
    glutMainLoop();
    return 0;
}
