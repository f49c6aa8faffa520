/* SPDX-License-Identifier: MIT */
/* A spot light with distance attenuation over a tessellated floor, a
 * second coloured point light, the cylinder and a teapot drawn with its
 * clockwise front faces culled the right way round (freeglut.h: the
 * cylinder is a freeglut solid). */
#include <GL/freeglut.h>

#define N 48

void floor_grid(void)
{
    int i, j;
    glNormal3f(0.0, 1.0, 0.0);
    for (i = 0; i < N; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= N; j++) {
            glVertex3f(-5.0 + 10.0 * j / N, 0.0, -5.0 + 10.0 * i / N);
            glVertex3f(-5.0 + 10.0 * j / N, 0.0, -5.0 + 10.0 * (i + 1) / N);
        }
        glEnd();
    }
}

void display(void)
{
    GLfloat spot_pos[] = { 0.5, 4.0, 0.5, 1.0 };
    GLfloat spot_dir[] = { -0.1, -1.0, -0.1 };
    GLfloat blue_pos[] = { -4.0, 2.0, 3.0, 1.0 };
    GLfloat blue[] = { 0.2, 0.3, 1.0, 1.0 };
    GLfloat white[] = { 1.0, 1.0, 1.0, 1.0 };
    GLfloat grey[] = { 0.6, 0.6, 0.6, 1.0 };
    GLfloat dim[] = { 0.1, 0.1, 0.1, 1.0 };

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 6.0, 9.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    glLightfv(GL_LIGHT0, GL_POSITION, spot_pos);
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 35.0);
    glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 6.0);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.4);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1);
    glLightf(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, 0.02);

    glLightfv(GL_LIGHT1, GL_POSITION, blue_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightfv(GL_LIGHT1, GL_SPECULAR, blue);
    glLighti(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.15);

    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, dim);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
    glMateriali(GL_FRONT_AND_BACK, GL_SHININESS, 30);

    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, grey);
    floor_grid();

    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glColor3f(0.9, 0.6, 0.2);
    glPushMatrix();
    glTranslatef(-2.0, 0.0, 0.0);
    glRotatef(-90.0, 1.0, 0.0, 0.0);
    glutSolidCylinder(0.6, 1.8, 24, 3);
    glPopMatrix();

    glColor3f(0.3, 0.8, 0.4);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CW);
    glPushMatrix();
    glTranslatef(1.5, 0.75, 0.5);
    glutSolidTeapot(1.0);
    glPopMatrix();
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
    glDisable(GL_COLOR_MATERIAL);
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)w / h, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Spot light");
    glClearColor(0.0, 0.0, 0.0, 0.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glEnable(GL_NORMALIZE);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
