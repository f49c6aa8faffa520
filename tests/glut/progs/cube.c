/* SPDX-License-Identifier: MIT */
/* The seed program: a colour cube of GL_QUADS seen from (3,2,1). */
#include <GL/glut.h>

void drawCube(void)
{
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0);                 /* front  z = +0.5 */
    glVertex3f(-0.5, -0.5, 0.5); glVertex3f(0.5, -0.5, 0.5);
    glVertex3f(0.5, 0.5, 0.5);   glVertex3f(-0.5, 0.5, 0.5);
    glColor3f(0, 1, 0);                 /* back   z = -0.5 */
    glVertex3f(-0.5, -0.5, -0.5); glVertex3f(-0.5, 0.5, -0.5);
    glVertex3f(0.5, 0.5, -0.5);   glVertex3f(0.5, -0.5, -0.5);
    glColor3f(0, 0, 1);                 /* top    y = +0.5 */
    glVertex3f(-0.5, 0.5, -0.5); glVertex3f(-0.5, 0.5, 0.5);
    glVertex3f(0.5, 0.5, 0.5);   glVertex3f(0.5, 0.5, -0.5);
    glColor3f(1, 1, 0);                 /* bottom y = -0.5 */
    glVertex3f(-0.5, -0.5, -0.5); glVertex3f(0.5, -0.5, -0.5);
    glVertex3f(0.5, -0.5, 0.5);   glVertex3f(-0.5, -0.5, 0.5);
    glColor3f(1, 0, 1);                 /* right  x = +0.5 */
    glVertex3f(0.5, -0.5, -0.5); glVertex3f(0.5, 0.5, -0.5);
    glVertex3f(0.5, 0.5, 0.5);   glVertex3f(0.5, -0.5, 0.5);
    glColor3f(0, 1, 1);                 /* left   x = -0.5 */
    glVertex3f(-0.5, -0.5, -0.5); glVertex3f(-0.5, -0.5, 0.5);
    glVertex3f(-0.5, 0.5, 0.5);   glVertex3f(-0.5, 0.5, -0.5);
    glEnd();
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(3, 2, 1, 0, 0, 0, 0, 1, 0);
    drawCube();
    glPushMatrix();                     /* a smaller one beside it */
    glTranslatef(0.2, 0.0, -1.3);
    glScalef(0.5, 0.5, 0.5);
    drawCube();
    glPopMatrix();
    glutSwapBuffers();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (double)w / h, 0.1, 100.0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Cube");
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    glClearColor(0.2, 0.2, 0.2, 1.0);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
