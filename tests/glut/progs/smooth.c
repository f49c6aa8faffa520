/* SPDX-License-Identifier: MIT */
/* Smooth (Gouraud) shading of a triangle and a quad strip, and a flat-shaded
 * fan beside them: the provoking vertex picks the fan's colours. */
#include <GL/glut.h>

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0, 0.0, 0.0); glVertex2f(5.0, 5.0);
    glColor3f(0.0, 1.0, 0.0); glVertex2f(25.0, 5.0);
    glColor3f(0.0, 0.0, 1.0); glVertex2f(5.0, 25.0);
    glEnd();
    glBegin(GL_QUAD_STRIP);
    glColor3f(1, 1, 0); glVertex2f(2, 28);
    glColor3f(1, 0, 1); glVertex2f(2, 29.5);
    glColor3f(0, 1, 1); glVertex2f(15, 28);
    glColor3f(1, 1, 1); glVertex2f(15, 29.5);
    glColor3f(1, 0, 0); glVertex2f(28, 28);
    glColor3f(0, 0, 0); glVertex2f(28, 29.5);
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex2f(22, 18);
    glColor3f(1, 0, 0); glVertex2f(29, 18);
    glColor3f(0, 1, 0); glVertex2f(27, 24);
    glColor3f(0, 0, 1); glVertex2f(22, 26);
    glColor3f(1, 1, 0); glVertex2f(16, 22);
    glEnd();
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (w <= h)
        gluOrtho2D(0.0, 30.0, 0.0, 30.0 * (GLfloat)h / (GLfloat)w);
    else
        gluOrtho2D(0.0, 30.0 * (GLfloat)w / (GLfloat)h, 0.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 500);
    glutCreateWindow("Smooth");
    glClearColor(0.0, 0.0, 0.0, 0.0);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
