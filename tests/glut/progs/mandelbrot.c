/* SPDX-License-Identifier: MIT */
/* Mandelbrot set: a million separate glBegin(GL_POINTS)/glEnd pairs, one per
 * sample of a 1000x1000 grid squeezed into an 800x600 window. Redraws from the
 * idle callback, so it doubles as a benchmark. */
#include <GL/glut.h>

#define MAXITER 64

void display(void)
{
    int i, j, k;
    double x, y, zx, zy, t;
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 0; i < 1000; i++) {
        for (j = 0; j < 1000; j++) {
            x = -2.2 + 3.0 * i / 1000.0;
            y = -1.2 + 2.4 * j / 1000.0;
            zx = 0; zy = 0;
            for (k = 0; k < MAXITER && zx * zx + zy * zy < 4.0; k++) {
                t = zx * zx - zy * zy + x;
                zy = 2 * zx * zy + y;
                zx = t;
            }
            if (k == MAXITER)
                glColor3f(0.0, 0.0, 0.0);
            else
                glColor3f(k / 16.0, k / 32.0, 1.0 - k / 64.0);  /* > 1 clamps */
            glBegin(GL_POINTS);
            glVertex2i(i, j);
            glEnd();
        }
    }
    glutSwapBuffers();
}

void idle(void)
{
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(800, 600);
    glutCreateWindow("Mandelbrot");
    glClearColor(1, 1, 1, 1);
    gluOrtho2D(0, 1000, 0, 1000);
    glutDisplayFunc(display);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
