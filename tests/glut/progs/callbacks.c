/* SPDX-License-Identifier: MIT */
/* Every GLUT input callback a course uses, each one drawing what it got:
 * a timer that re-arms itself three times before asking for a redisplay,
 * the visibility callback, key and special presses and releases with
 * glutGetModifiers, passive and active motion, mouse buttons. Each event
 * becomes a bar group: x from the order, heights from the values. */
#include <GL/glut.h>

#define MAXE 32
int ev_kind[MAXE], ev_a[MAXE], ev_b[MAXE], ev_c[MAXE], ev_m[MAXE], nev;
int ticks, visible;

void record(int kind, int a, int b, int c)
{
    if (nev == MAXE) return;
    ev_kind[nev] = kind; ev_a[nev] = a; ev_b[nev] = b; ev_c[nev] = c;
    ev_m[nev] = kind <= 4 || kind == 7 ? glutGetModifiers() : 0;
    nev++;
    glutPostRedisplay();
}

void keyboard(unsigned char k, int x, int y) { record(1, k, x, y); }
void keyboard_up(unsigned char k, int x, int y) { record(2, k, x, y); }
void special(int k, int x, int y) { record(3, k, x, y); }
void special_up(int k, int x, int y) { record(4, k, x, y); }
void passive(int x, int y) { record(5, 0, x, y); }
void motion(int x, int y) { record(6, 0, x, y); }
void mouse(int b, int s, int x, int y) { record(7, b * 2 + s, x, y); }
void visibility(int state) { visible = state == GLUT_VISIBLE ? 2 : 1; }

void timer(int value)
{
    ticks += value;
    if (ticks < 3)
        glutTimerFunc(15, timer, 1);
    else
        glutPostRedisplay();
}

void bar(int x, int h, float r, float g, float b)
{
    glColor3f(r, g, b);
    glRecti(x, 20, x + 4, 20 + h);
}

void display(void)
{
    int i, w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.4, 0.4, 0.4);
    glBegin(GL_LINE_LOOP);
    glVertex2i(5, 5); glVertex2i(w - 5, 5); glVertex2i(w - 5, h - 5); glVertex2i(5, h - 5);
    glEnd();
    for (i = 0; i < ticks; i++)
        bar(12 + 6 * i, 250, 1, 1, 1);
    bar(36, 100 * visible, 1, 0.5, 0);
    for (i = 0; i < nev; i++) {
        int x = 60 + 22 * i;
        bar(x, 20 * ev_kind[i], 0.8, 0.8, 0.2);
        bar(x + 4, ev_a[i] % 256, 0.2, 0.8, 0.2);
        bar(x + 8, ev_b[i] / 2, 0.2, 0.5, 1);
        bar(x + 12, ev_c[i] / 2, 1, 0.3, 0.3);
        bar(x + 16, 30 * ev_m[i] + 1, 0.8, 0.3, 0.8);
    }
    glutSwapBuffers();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(480, 300);
    glutCreateWindow("Callbacks");
    glClearColor(0.05, 0.05, 0.1, 1);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboard_up);
    glutSpecialFunc(special);
    glutSpecialUpFunc(special_up);
    glutPassiveMotionFunc(passive);
    glutMotionFunc(motion);
    glutMouseFunc(mouse);
    glutVisibilityFunc(visibility);
    glutTimerFunc(15, timer, 1);
    glutMainLoop();
    return 0;
}
