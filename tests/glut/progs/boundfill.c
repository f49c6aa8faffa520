/* SPDX-License-Identifier: MIT */
/* Boundary fill (4-connected, recursive) that reads the frame back with
 * glReadPixels to find the border. */
#include <GL/glut.h>

float fillColor[3] = { 1.0, 1.0, 0.0 };
float borderColor[3] = { 1.0, 0.0, 0.0 };

void setPixel(int x, int y, float c[3])
{
    glColor3fv(c);
    glBegin(GL_POINTS);
    glVertex2i(x, y);
    glEnd();
}

void getPixel(int x, int y, float c[3])
{
    glReadPixels(x, y, 1, 1, GL_RGB, GL_FLOAT, c);
}

void boundaryFill4(int x, int y, float fill[3], float border[3])
{
    float c[3];
    getPixel(x, y, c);
    if ((c[0] != border[0] || c[1] != border[1] || c[2] != border[2]) &&
        (c[0] != fill[0] || c[1] != fill[1] || c[2] != fill[2])) {
        setPixel(x, y, fill);
        boundaryFill4(x + 1, y, fill, border);
        boundaryFill4(x - 1, y, fill, border);
        boundaryFill4(x, y + 1, fill, border);
        boundaryFill4(x, y - 1, fill, border);
    }
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3fv(borderColor);
    glBegin(GL_LINE_LOOP);           /* a small hexagon */
    glVertex2i(150, 100);
    glVertex2i(190, 100);
    glVertex2i(210, 130);
    glVertex2i(190, 160);
    glVertex2i(150, 160);
    glVertex2i(130, 130);
    glEnd();
    glColor3f(0.0, 0.0, 1.0);
    glRecti(40, 40, 90, 70);
    boundaryFill4(170, 130, fillColor, borderColor);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Boundary Fill");
    glClearColor(1.0, 1.0, 1.0, 0.0);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
