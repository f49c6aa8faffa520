/* SPDX-License-Identifier: MIT */
/* Liang-Barsky line clipping with a window-to-viewport mapping. */
#include <GL/glut.h>

float xwmin = 100, ywmin = 100, xwmax = 300, ywmax = 250;
float xvmin = 420, yvmin = 80, xvmax = 620, yvmax = 230;

int cliptest(float p, float q, float *t1, float *t2)
{
    float r;
    if (p < 0.0) {
        r = q / p;
        if (r > *t2) return 0;
        else if (r > *t1) *t1 = r;
    } else if (p > 0.0) {
        r = q / p;
        if (r < *t1) return 0;
        else if (r < *t2) *t2 = r;
    } else if (q < 0.0)
        return 0;
    return 1;
}

void toViewport(float x, float y)
{
    float sx = (xvmax - xvmin) / (xwmax - xwmin);
    float sy = (yvmax - yvmin) / (ywmax - ywmin);
    glVertex2f(xvmin + (x - xwmin) * sx, yvmin + (y - ywmin) * sy);
}

void liangBarsky(float x1, float y1, float x2, float y2)
{
    float dx = x2 - x1, dy, t1 = 0.0, t2 = 1.0;
    if (cliptest(-dx, x1 - xwmin, &t1, &t2))
        if (cliptest(dx, xwmax - x1, &t1, &t2)) {
            dy = y2 - y1;
            if (cliptest(-dy, y1 - ywmin, &t1, &t2))
                if (cliptest(dy, ywmax - y1, &t1, &t2)) {
                    if (t2 < 1.0) {
                        x2 = x1 + t2 * dx;
                        y2 = y1 + t2 * dy;
                    }
                    if (t1 > 0.0) {
                        x1 = x1 + t1 * dx;
                        y1 = y1 + t1 * dy;
                    }
                    glColor3f(0.0, 0.0, 1.0);
                    glBegin(GL_LINES);
                    toViewport(x1, y1);
                    toViewport(x2, y2);
                    glEnd();
                }
        }
}

float seg[][4] = {
    { 50, 50, 350, 300 }, { 150, 20, 150, 320 }, { 20, 180, 380, 200 },
    { 120, 120, 280, 230 }, { 320, 50, 360, 300 }, { 60, 300, 250, 60 },
};

void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.0, 0.0, 0.0);
    glBegin(GL_LINE_LOOP);
    glVertex2f(xwmin, ywmin); glVertex2f(xwmax, ywmin);
    glVertex2f(xwmax, ywmax); glVertex2f(xwmin, ywmax);
    glEnd();
    glColor3f(1.0, 0.0, 0.0);
    for (i = 0; i < 6; i++) {
        glBegin(GL_LINES);
        glVertex2f(seg[i][0], seg[i][1]);
        glVertex2f(seg[i][2], seg[i][3]);
        glEnd();
    }
    glColor3f(0.0, 0.0, 0.0);
    glBegin(GL_LINE_LOOP);
    glVertex2f(xvmin, yvmin); glVertex2f(xvmax, yvmin);
    glVertex2f(xvmax, yvmax); glVertex2f(xvmin, yvmax);
    glEnd();
    for (i = 0; i < 6; i++)
        liangBarsky(seg[i][0], seg[i][1], seg[i][2], seg[i][3]);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 360);
    glutCreateWindow("Liang Barsky");
    glClearColor(1.0, 1.0, 1.0, 1.0);
    glMatrixMode(GL_PROJECTION);
    gluOrtho2D(0.0, 640.0, 0.0, 360.0);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
