/* SPDX-License-Identifier: MIT */
/* Display lists: a petal compiled once, a flower list that calls it eight
 * times, and a field of flowers drawn with glCallList. */
#include <GL/glut.h>

GLuint petal, flower;

void init(void)
{
    int i;
    petal = glGenLists(2);
    flower = petal + 1;
    glNewList(petal, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(0.0, 0.0);
    glVertex2f(8.0, 30.0);
    glVertex2f(-8.0, 30.0);
    glEnd();
    glEndList();

    glNewList(flower, GL_COMPILE);
    for (i = 0; i < 8; i++) {
        glColor3f(1.0, i % 2 ? 0.4 : 0.8, 0.6);
        glCallList(petal);
        glRotatef(45.0, 0.0, 0.0, 1.0);       /* eight turns: back where it started */
    }
    glColor3f(1.0, 1.0, 0.0);
    glRectf(-5.0, -5.0, 5.0, 5.0);
    glEndList();
}

void display(void)
{
    int i, j;
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.1, 0.6, 0.1);
    glBegin(GL_LINES);
    for (i = 0; i < 5; i++) {
        glVertex2i(60 + i * 120, 0);
        glVertex2i(60 + i * 120, 380);
    }
    glEnd();
    for (j = 0; j < 4; j++)
        for (i = 0; i < 5; i++) {
            glPushMatrix();
            glTranslatef(60 + i * 120, 80 + j * 100, 0);
            glRotatef(i * 10.0 + j * 5.0, 0, 0, 1);
            glCallList(flower);
            glPopMatrix();
        }
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(600, 480);
    glutCreateWindow("Display lists");
    glClearColor(0.0, 0.2, 0.0, 1.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 600.0, 0.0, 480.0);
    glMatrixMode(GL_MODELVIEW);
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
