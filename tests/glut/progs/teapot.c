/* SPDX-License-Identifier: MIT */
/* A lit teapot that spins two degrees a frame: depth test, one light,
 * GL_COLOR_MATERIAL. Redrawn from the idle callback (also the benchmark). */
#include <GL/glut.h>

float angle = 0.0;

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 1.5, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(angle, 0.0, 1.0, 0.0);
    glColor3f(0.8, 0.5, 0.2);
    glutSolidTeapot(1.0);
    glutSwapBuffers();
    angle += 2.0;                 /* one step per frame, not per second */
}

void idle(void)
{
    glutPostRedisplay();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (float)w / (float)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

void init(void)
{
    GLfloat light_position[] = { 2.0, 4.0, 3.0, 0.0 };
    GLfloat white[] = { 1.0, 1.0, 1.0, 1.0 };
    GLfloat ambient[] = { 0.2, 0.2, 0.2, 1.0 };
    glClearColor(0.1, 0.1, 0.3, 1.0);
    glShadeModel(GL_SMOOTH);
    glLightfv(GL_LIGHT0, GL_POSITION, light_position);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 50.0);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(800, 600);
    glutCreateWindow("Teapot");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
