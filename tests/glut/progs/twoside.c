/* SPDX-License-Identifier: MIT */
/* Two-sided lighting, the way a course shows why it exists: an open tube
 * and a bowl (a sphere cut below its equator) seen from above, so their
 * insides face the camera. The outsides are lit with the GL_FRONT
 * material, the insides with the GL_BACK one and the normal reversed
 * (glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE)). The bowl's back colour
 * comes from glColor through glColorMaterial(GL_BACK, ...), its front from
 * glMaterial; a second tube, drawn flat-shaded, takes the back colour of
 * its provoking vertex. */
#include <GL/glut.h>
#include <math.h>

#define SLICES 36
#define STACKS 12

void tube(float r, float h)
{
    int i;
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= SLICES; i++) {
        float a = 2.0 * M_PI * i / SLICES;
        glNormal3f(cos(a), 0.0, sin(a));        /* outward: the front */
        glVertex3f(r * cos(a), 0.0, r * sin(a));
        glVertex3f(r * cos(a), h, r * sin(a));
    }
    glEnd();
}

/* the part of a sphere below the plane y = cut, normals outward (both
 * shapes wound counter-clockwise seen from outside) */
void bowl(float r, float cut)
{
    int i, j;
    float top = asin(cut / r);
    for (j = 0; j < STACKS; j++) {
        float p0 = -M_PI / 2 + (top + M_PI / 2) * j / STACKS;
        float p1 = -M_PI / 2 + (top + M_PI / 2) * (j + 1) / STACKS;
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= SLICES; i++) {
            float a = 2.0 * M_PI * i / SLICES;
            glNormal3f(cos(p0) * cos(a), sin(p0), cos(p0) * sin(a));
            glVertex3f(r * cos(p0) * cos(a), r * sin(p0), r * cos(p0) * sin(a));
            glNormal3f(cos(p1) * cos(a), sin(p1), cos(p1) * sin(a));
            glVertex3f(r * cos(p1) * cos(a), r * sin(p1), r * cos(p1) * sin(a));
        }
        glEnd();
    }
}

void display(void)
{
    GLfloat gold[] = { 0.8, 0.6, 0.2, 1.0 };
    GLfloat teal[] = { 0.1, 0.5, 0.5, 1.0 };
    GLfloat white[] = { 1.0, 1.0, 1.0, 1.0 };
    GLfloat dark[] = { 0.05, 0.0, 0.1, 1.0 };
    GLfloat red[] = { 0.7, 0.1, 0.1, 1.0 };

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 5.0, 6.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    /* the tube: gold outside with a highlight, teal inside, a dim glow */
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0);
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, teal);
    glMaterialfv(GL_BACK, GL_SPECULAR, dark);
    glMaterialf(GL_BACK, GL_SHININESS, 5.0);
    glMaterialfv(GL_BACK, GL_EMISSION, dark);
    glPushMatrix();
    glTranslatef(-1.6, -0.5, 0.0);
    tube(1.0, 1.5);
    glPopMatrix();

    /* the bowl: its inside follows glColor */
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, (GLfloat[]){ 0.0, 0.0, 0.0, 1.0 });
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glColorMaterial(GL_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.3, 0.8, 0.3);
    glPushMatrix();
    glTranslatef(1.5, 0.3, 0.5);
    bowl(1.1, 0.4);
    glPopMatrix();
    glDisable(GL_COLOR_MATERIAL);

    /* a thin flat-shaded tube at the back */
    glShadeModel(GL_FLAT);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
    glMaterialfv(GL_BACK, GL_DIFFUSE, (GLfloat[]){ 0.6, 0.4, 0.9, 1.0 });
    glPushMatrix();
    glTranslatef(0.2, -0.8, -2.2);
    tube(0.6, 1.0);
    glPopMatrix();
    glShadeModel(GL_SMOOTH);

    glFlush();
}

void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

void init(void)
{
    GLfloat pos[] = { -2.0, 6.0, 4.0, 1.0 };
    GLfloat amb[] = { 0.15, 0.15, 0.15, 1.0 };
    glClearColor(0.9, 0.9, 0.85, 1.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Two-sided lighting");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
