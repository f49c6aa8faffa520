/* SPDX-License-Identifier: MIT */
/* Polylines drawn with the mouse: each left click adds a vertex, a right
 * click starts a new polyline, 'c' clears everything. */
#include <GL/glut.h>
#include <stdlib.h>

#define MAXP 100
#define MAXL 10
int px[MAXL][MAXP], py[MAXL][MAXP], np[MAXL];
int nl = 1;
int winH = 480;

void display(void)
{
    int i, j;
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 0; i < nl; i++) {
        glColor3f(0.0, 0.0, 0.0);
        glBegin(GL_LINE_STRIP);
        for (j = 0; j < np[i]; j++)
            glVertex2i(px[i][j], py[i][j]);
        glEnd();
        glColor3f(1.0, 0.0, 0.0);
        glPointSize(5.0);
        glBegin(GL_POINTS);
        for (j = 0; j < np[i]; j++)
            glVertex2i(px[i][j], py[i][j]);
        glEnd();
    }
    glFlush();
}

void mouse(int button, int state, int x, int y)
{
    if (state != GLUT_DOWN) return;
    if (button == GLUT_LEFT_BUTTON && np[nl - 1] < MAXP) {
        px[nl - 1][np[nl - 1]] = x;
        py[nl - 1][np[nl - 1]] = winH - y;    /* GLUT's y grows downwards */
        np[nl - 1]++;
    } else if (button == GLUT_RIGHT_BUTTON && nl < MAXL) {
        nl++;
    }
    glutPostRedisplay();
}

void keyboard(unsigned char key, int x, int y)
{
    (void)x; (void)y;
    if (key == 'c') {
        nl = 1;
        np[0] = 0;
        glutPostRedisplay();
    }
    if (key == 'q') exit(0);
}

void reshape(int w, int h)
{
    winH = h;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Polyline");
    glClearColor(1, 1, 1, 1);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
