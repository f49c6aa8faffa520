/* SPDX-License-Identifier: MIT */
/* Scan-line polygon fill: intersections of each scan line with the edges are
 * sorted and filled in pairs with GL_LINES. */
#include <GL/glut.h>

#define N 7
int px[N] = { 100, 250, 380, 330, 240, 150, 60 };
int py[N] = { 60, 40, 150, 320, 200, 330, 200 };

void scanfill(void)
{
    int y, i, j, n, xs[N], t;
    for (y = 0; y < 400; y++) {
        n = 0;
        for (i = 0; i < N; i++) {
            j = (i + 1) % N;
            int y1 = py[i], y2 = py[j];
            if (y1 == y2) continue;
            if ((y >= y1 && y < y2) || (y >= y2 && y < y1)) {
                float x = px[i] + (float)(y - y1) * (px[j] - px[i]) / (y2 - y1);
                xs[n++] = (int)x;
            }
        }
        for (i = 0; i < n - 1; i++)          /* bubble sort the crossings */
            for (j = 0; j < n - 1 - i; j++)
                if (xs[j] > xs[j + 1]) { t = xs[j]; xs[j] = xs[j + 1]; xs[j + 1] = t; }
        for (i = 0; i + 1 < n; i += 2) {
            glBegin(GL_LINES);
            glVertex2i(xs[i], y);
            glVertex2i(xs[i + 1], y);
            glEnd();
        }
    }
}

void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 0.5, 0.0);
    scanfill();
    glColor3f(0.0, 0.0, 1.0);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < N; i++)
        glVertex2i(px[i], py[i]);
    glEnd();
    glFlush();
}

void init(void)
{
    glClearColor(1.0, 1.0, 1.0, 1.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 400, 0, 400);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Scan line polygon fill");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
