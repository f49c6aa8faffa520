/* SPDX-License-Identifier: MIT */
/* The ten GLUT solids with back faces culled (GL_CCW fronts, as GLUT
 * draws them; the teapot is GL_CW in freeglut, so it is drawn with
 * glFrontFace(GL_CW)), each one turned a little, and a wire cylinder. */
#include <GL/freeglut.h>

void place(float x, float y)
{
    glLoadIdentity();
    glTranslatef(x, y, -9.0);
    glRotatef(25, 1, 0, 0);
    glRotatef(-30, 0, 1, 0);
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(0.9, 0.2, 0.2); place(-2.6, 2.0); glutSolidCube(1.1);
    glColor3f(0.2, 0.9, 0.2); place(0.0, 2.0);  glutSolidSphere(0.7, 24, 16);
    glColor3f(0.2, 0.4, 1.0); place(2.6, 1.6);  glRotatef(-90, 1, 0, 0); glutSolidCone(0.6, 1.2, 20, 8);
    glColor3f(0.9, 0.9, 0.2); place(-2.6, 0.0); glutSolidTorus(0.2, 0.55, 16, 24);
    glColor3f(0.9, 0.5, 0.1); place(0.0, 0.0);
    glFrontFace(GL_CW); glutSolidTeapot(0.6); glFrontFace(GL_CCW);
    glColor3f(0.5, 0.5, 1.0); place(-4.6, 0.0); glRotatef(-90, 1, 0, 0); glutSolidCylinder(0.4, 1.0, 16, 2);
    glDisable(GL_LIGHTING); /* wire solids are lines: culling leaves them */
    glColor3f(1.0, 1.0, 1.0); place(4.6, 0.0); glRotatef(-90, 1, 0, 0); glutWireCylinder(0.4, 1.0, 12, 3);
    glEnable(GL_LIGHTING);
    glColor3f(0.2, 0.9, 0.9); place(2.6, 0.0);  glutSolidIcosahedron();
    glColor3f(0.9, 0.2, 0.9); place(-2.6, -2.0); glScalef(0.45, 0.45, 0.45); glutSolidDodecahedron();
    glColor3f(0.8, 0.8, 0.8); place(0.0, -2.0); glutSolidOctahedron();
    glColor3f(1.0, 0.6, 0.6); place(2.6, -2.0); glutSolidTetrahedron();
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLfloat)w / (GLfloat)h, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    GLfloat pos[] = { -3.0, 5.0, 6.0, 1.0 };
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(800, 480);
    glutCreateWindow("Culled solids");
    glClearColor(0.0, 0.0, 0.0, 0.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CULL_FACE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
