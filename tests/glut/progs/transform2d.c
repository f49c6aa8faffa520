/* SPDX-License-Identifier: MIT */
/* 2D transformations: a house translated, rotated about a pivot and scaled,
 * each in its own glPushMatrix/glPopMatrix. */
#include <GL/glut.h>

void house(void)
{
    glBegin(GL_POLYGON);          /* walls */
    glVertex2i(0, 0);
    glVertex2i(80, 0);
    glVertex2i(80, 60);
    glVertex2i(0, 60);
    glEnd();
    glColor3f(0.6, 0.1, 0.1);
    glBegin(GL_TRIANGLES);        /* roof */
    glVertex2i(-10, 60);
    glVertex2i(90, 60);
    glVertex2i(40, 100);
    glEnd();
    glColor3f(0.3, 0.2, 0.0);
    glRecti(50, 0, 65, 35);       /* door, off centre so the mirror shows */
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);

    glColor3f(0.2, 0.6, 1.0);     /* the original */
    glPushMatrix();
    glTranslatef(40, 40, 0);
    house();
    glPopMatrix();

    glPushMatrix();               /* translated */
    glTranslatef(300, 40, 0);
    glColor3f(0.2, 1.0, 0.2);
    house();
    glPopMatrix();

    glPushMatrix();               /* rotated 30 degrees about (240, 260) */
    glTranslatef(240, 260, 0);
    glRotatef(30, 0, 0, 1);
    glTranslatef(-40, -30, 0);
    glColor3f(1.0, 0.8, 0.0);
    house();
    glPopMatrix();

    glPushMatrix();               /* scaled about its corner, then mirrored */
    glTranslatef(440, 300, 0);
    glScalef(1.5, 0.75, 1);
    glColor3f(1.0, 0.4, 1.0);
    house();
    glScalef(-1, 1, 1);
    glTranslatef(20, 0, 0);
    glColor3f(0.8, 0.8, 0.8);
    house();
    glPopMatrix();

    glColor3f(1, 1, 1);           /* axes through the pivot */
    glBegin(GL_LINES);
    glVertex2i(240, 0); glVertex2i(240, 480);
    glVertex2i(0, 260); glVertex2i(640, 260);
    glEnd();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("2D Transformations");
    glClearColor(0.1, 0.1, 0.1, 1);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, 640, 0, 480, 500, 0);   /* near/far reversed, as copied from a slide */
    glMatrixMode(GL_MODELVIEW);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
