/* SPDX-License-Identifier: MIT */
/* The classic material table: a grid of spheres, one row per ambient
 * setting (none, grey, coloured), one column per specular/emission setting
 * (diffuse only; specular with shininess 5; with 100; emission), lit by a
 * positional light with the viewer local (glLightModeli(
 * GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE)), so every sphere's highlight sits
 * where the eye really sees it. Also integer glMaterialiv/glLightModeliv
 * and a glMaterial call while glColorMaterial tracks that parameter (GL:
 * the tracked parameter keeps following the colour). */
#include <GL/glut.h>

void sphere(float x, float y, const GLfloat *amb, const GLfloat *spec, float shin,
            const GLfloat *emi)
{
    GLfloat none[] = { 0.0, 0.0, 0.0, 1.0 };
    GLfloat diffuse[] = { 0.1, 0.5, 0.8, 1.0 };
    glPushMatrix();
    glTranslatef(x, y, 0.0);
    glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec ? spec : none);
    glMaterialf(GL_FRONT, GL_SHININESS, shin);
    glMaterialfv(GL_FRONT, GL_EMISSION, emi ? emi : none);
    glutSolidSphere(1.0, 24, 16);
    glPopMatrix();
}

void display(void)
{
    GLfloat none[] = { 0.0, 0.0, 0.0, 1.0 };
    GLfloat grey[] = { 0.7, 0.7, 0.7, 1.0 };
    GLfloat tint[] = { 0.8, 0.8, 0.2, 1.0 };
    GLfloat white[] = { 1.0, 1.0, 1.0, 1.0 };
    GLfloat glow[] = { 0.3, 0.2, 0.2, 0.0 };
    const GLfloat *amb[3] = { none, grey, tint };
    int row;

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (row = 0; row < 3; row++) {
        float y = 3.0 - 3.0 * row;
        sphere(-3.75, y, amb[row], NULL, 0.0, NULL);
        sphere(-1.25, y, amb[row], white, 5.0, NULL);
        sphere(1.25, y, amb[row], white, 100.0, NULL);
        sphere(3.75, y, amb[row], NULL, 0.0, glow);
    }
    /* an out-of-range shininess is an error and changes nothing */
    glMaterialf(GL_FRONT, GL_SHININESS, 200.0);
    glGetError();
    /* a small sphere whose diffuse colour follows glColor even though
     * glMaterial sets it afterwards */
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9, 0.3, 0.1);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, white);
    glPushMatrix();
    glTranslatef(5.4, 4.2, 0.0);
    glutSolidSphere(0.4, 16, 12);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);
    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 0.0, 14.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

void init(void)
{
    GLfloat pos[] = { 0.0, 3.0, 4.0, 1.0 };
    GLfloat white[] = { 1.0, 1.0, 1.0, 1.0 };
    GLint amb[] = { 214748364, 214748364, 214748364, 2147483647 }; /* ~0.1 */
    glClearColor(0.0, 0.1, 0.1, 1.0);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightModeliv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(600, 450);
    glutCreateWindow("Materials");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
