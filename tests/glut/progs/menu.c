/* SPDX-License-Identifier: MIT */
/* Popup menu on the right button: pick a shape and, from a submenu, a colour. */
#include <GL/glut.h>
#include <math.h>
#include <stdlib.h>

int shape = 1;
float r = 1, g = 1, b = 1;

void drawShape(void)
{
    int i;
    glColor3f(r, g, b);
    switch (shape) {
    case 1:
        glRecti(150, 100, 350, 300);
        break;
    case 2:
        glBegin(GL_TRIANGLES);
        glVertex2i(100, 80);
        glVertex2i(400, 80);
        glVertex2i(250, 340);
        glEnd();
        break;
    case 3:
        glBegin(GL_POLYGON);
        for (i = 0; i < 36; i++)
            glVertex2f(250 + 120 * cos(i * 10 * M_PI / 180), 200 + 120 * sin(i * 10 * M_PI / 180));
        glEnd();
        break;
    case 4:
        glBegin(GL_LINE_LOOP);
        for (i = 0; i < 5; i++)
            glVertex2f(250 + 140 * cos((90 + i * 144) * M_PI / 180), 200 + 140 * sin((90 + i * 144) * M_PI / 180));
        glEnd();
        break;
    }
}

void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    drawShape();
    glFlush();
}

void shapeMenu(int id)
{
    if (id == 0) exit(0);
    shape = id;
    glutPostRedisplay();
}

void colourMenu(int id)
{
    r = g = b = 0;
    if (id == 1) r = 1;
    if (id == 2) g = 1;
    if (id == 3) b = 1;
    if (id == 4) { r = 1; g = 1; }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    int sub;
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 400);
    glutCreateWindow("Menu");
    glClearColor(0.0, 0.0, 0.0, 1.0);
    gluOrtho2D(0, 500, 0, 400);
    glutDisplayFunc(display);

    sub = glutCreateMenu(colourMenu);
    glutAddMenuEntry("Red", 1);
    glutAddMenuEntry("Green", 2);
    glutAddMenuEntry("Blue", 3);
    glutAddMenuEntry("Yellow", 4);
    glutCreateMenu(shapeMenu);
    glutAddMenuEntry("Square", 1);
    glutAddMenuEntry("Triangle", 2);
    glutAddMenuEntry("Circle", 3);
    glutAddMenuEntry("Star", 4);
    glutAddSubMenu("Colour", sub);
    glutAddMenuEntry("Quit", 0);
    glutAttachMenu(GLUT_RIGHT_BUTTON);
    glutMainLoop();
    return 0;
}
