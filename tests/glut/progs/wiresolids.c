/* SPDX-License-Identifier: MIT */
/* The GLUT wire solids, unlit, each in its own colour. */
#include <GL/glut.h>

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 10.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(20, 1, 0, 0);

    glPushMatrix(); glTranslatef(-3.0, 2.2, 0); glColor3f(1, 0, 0); glutWireCube(1.2); glPopMatrix();
    glPushMatrix(); glTranslatef(0.0, 2.2, 0); glColor3f(0, 1, 0); glutWireSphere(0.8, 12, 8); glPopMatrix();
    glPushMatrix(); glTranslatef(3.0, 2.2, 0); glRotatef(-90, 1, 0, 0); glColor3f(0.3, 0.5, 1); glutWireCone(0.7, 1.4, 12, 4); glPopMatrix();
    glPushMatrix(); glTranslatef(-3.0, 0.0, 0); glColor3f(1, 1, 0); glutWireTorus(0.25, 0.7, 8, 16); glPopMatrix();
    glPushMatrix(); glTranslatef(0.0, 0.0, 0); glColor3f(1, 0.5, 0); glutWireTeapot(0.7); glPopMatrix();
    glPushMatrix(); glTranslatef(3.0, 0.0, 0); glColor3f(0, 1, 1); glutWireIcosahedron(); glPopMatrix();
    glPushMatrix(); glTranslatef(-3.0, -2.2, 0); glScalef(0.5, 0.5, 0.5); glColor3f(1, 0, 1); glutWireDodecahedron(); glPopMatrix();
    glPushMatrix(); glTranslatef(0.0, -2.2, 0); glColor3f(1, 1, 1); glutWireOctahedron(); glPopMatrix();
    glPushMatrix(); glTranslatef(3.0, -2.2, 0); glColor3f(1, 0.6, 0.6); glutWireTetrahedron(); glPopMatrix();
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -0.75, 0.75, 2.0, 30.0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Wire solids");
    glClearColor(0, 0, 0, 0);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
