/* SPDX-License-Identifier: MIT */
/* Flythrough with a camera kept as eye + u, v, n (Hill, ch. 7): slide, roll,
 * pitch and yaw, the view matrix loaded with glLoadMatrixf.
 * Keys: f/b slide forward/back, l/r slide left/right, u/d up/down,
 *       x/X roll, p/P pitch, y/Y yaw; the arrows yaw and pitch. */
#include <GL/glut.h>
#include <math.h>

typedef struct { float x, y, z; } Vec3;

Vec3 eye, u, v, n;

Vec3 cross(Vec3 a, Vec3 b)
{
    Vec3 c = { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
    return c;
}

Vec3 normalize(Vec3 a)
{
    float l = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    Vec3 r = { a.x / l, a.y / l, a.z / l };
    return r;
}

float dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

void setModelViewMatrix(void)
{
    float m[16];
    Vec3 e = eye;
    m[0] = u.x; m[4] = u.y; m[8] = u.z;  m[12] = -dot(e, u);
    m[1] = v.x; m[5] = v.y; m[9] = v.z;  m[13] = -dot(e, v);
    m[2] = n.x; m[6] = n.y; m[10] = n.z; m[14] = -dot(e, n);
    m[3] = 0;   m[7] = 0;   m[11] = 0;   m[15] = 1.0;
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(m);
}

void set(Vec3 Eye, Vec3 look, Vec3 up)
{
    Vec3 d = { Eye.x - look.x, Eye.y - look.y, Eye.z - look.z };
    eye = Eye;
    n = normalize(d);
    u = normalize(cross(up, n));
    v = cross(n, u);
    setModelViewMatrix();
}

void slide(float delU, float delV, float delN)
{
    eye.x += delU * u.x + delV * v.x + delN * n.x;
    eye.y += delU * u.y + delV * v.y + delN * n.y;
    eye.z += delU * u.z + delV * v.z + delN * n.z;
    setModelViewMatrix();
}

void rotateAxes(Vec3 *a, Vec3 *b, float angle)
{
    float cs = cos(3.14159265 / 180 * angle), sn = sin(3.14159265 / 180 * angle);
    Vec3 t = *a;
    a->x = cs * t.x - sn * b->x; a->y = cs * t.y - sn * b->y; a->z = cs * t.z - sn * b->z;
    b->x = sn * t.x + cs * b->x; b->y = sn * t.y + cs * b->y; b->z = sn * t.z + cs * b->z;
}

void roll(float angle)  { rotateAxes(&u, &v, angle); setModelViewMatrix(); }
void pitch(float angle) { rotateAxes(&v, &n, angle); setModelViewMatrix(); }
void yaw(float angle)   { rotateAxes(&n, &u, angle); setModelViewMatrix(); }

void drawScene(void)
{
    int i, j;
    glColor3f(0.4, 0.4, 0.4);
    glBegin(GL_LINES);
    for (i = -10; i <= 10; i++) {
        glVertex3f(i, 0, -10); glVertex3f(i, 0, 10);
        glVertex3f(-10, 0, i); glVertex3f(10, 0, i);
    }
    glEnd();
    for (i = -2; i <= 2; i++)
        for (j = -2; j <= 2; j++) {
            glPushMatrix();
            glTranslatef(i * 3.0, 0.5, j * 3.0);
            glColor3f(0.5 + 0.1 * i, 0.5 + 0.1 * j, 0.8);
            glutSolidCube(1.0);
            glColor3f(0, 0, 0);
            glutWireCube(1.02);       /* a hair bigger, or the outline z-fights */
            glPopMatrix();
        }
    glPushMatrix();
    glTranslatef(0, 2, 0);
    glColor3f(1, 1, 0);
    glutWireTeapot(1.0);
    glPopMatrix();
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawScene();
    glutSwapBuffers();
}

void keyboard(unsigned char key, int x, int y)
{
    (void)x; (void)y;
    switch (key) {
    case 'f': slide(0, 0, -0.5); break;
    case 'b': slide(0, 0, 0.5); break;
    case 'l': slide(-0.5, 0, 0); break;
    case 'r': slide(0.5, 0, 0); break;
    case 'u': slide(0, 0.5, 0); break;
    case 'd': slide(0, -0.5, 0); break;
    case 'x': roll(5); break;
    case 'X': roll(-5); break;
    case 'p': pitch(5); break;
    case 'P': pitch(-5); break;
    case 'y': yaw(5); break;
    case 'Y': yaw(-5); break;
    case 27: exit(0);
    }
    glutPostRedisplay();
}

void special(int key, int x, int y)
{
    (void)x; (void)y;
    if (key == GLUT_KEY_LEFT) yaw(-5);
    if (key == GLUT_KEY_RIGHT) yaw(5);
    if (key == GLUT_KEY_UP) pitch(5);
    if (key == GLUT_KEY_DOWN) pitch(-5);
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    Vec3 e = { 4, 4, 12 }, l = { 0, 0, 0 }, up = { 0, 1, 0 };
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(640, 480);
    glutInitWindowPosition(50, 50);
    glutCreateWindow("Fly through");
    glutKeyboardFunc(keyboard);
    glutSpecialFunc(special);
    glutDisplayFunc(display);
    glClearColor(0.6, 0.8, 1.0, 1.0);
    glEnable(GL_DEPTH_TEST);
    glViewport(0, 0, 640, 480);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, 64.0 / 48.0, 0.5, 50.0);
    set(e, l, up);
    glutMainLoop();
    return 0;
}
