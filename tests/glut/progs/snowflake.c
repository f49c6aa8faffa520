/* SPDX-License-Identifier: MIT */
/* Koch snowflake with GL_LINE_LOOP in the default coordinates (no projection
 * set at all), drawn with a turtle. */
#include <GL/glut.h>
#include <math.h>
#include <stdlib.h>

int depth = 4;

double cx, cy, angle;

void forward(double len, int depth)
{
    if (depth == 0) {
        cx += len * cos(angle * M_PI / 180.0);
        cy += len * sin(angle * M_PI / 180.0);
        glVertex2d(cx, cy);
        return;
    }
    len /= 3.0;
    forward(len, depth - 1);
    angle += 60;
    forward(len, depth - 1);
    angle -= 120;
    forward(len, depth - 1);
    angle += 60;
    forward(len, depth - 1);
}

void snowflake(double len, int depth)
{
    int i;
    cx = -len / 2;
    cy = len * sqrt(3.0) / 6;
    angle = 0;
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 3; i++) {
        forward(len, depth);
        angle -= 120;
    }
    glEnd();
}

void display(void)
{
    glClearColor(0.0, 0.0, 0.3, 0.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 1.0, 1.0);
    snowflake(1.5, depth);
    glColor3f(0.4, 0.8, 1.0);
    snowflake(0.6, 2);
    glFlush();
}

int main(int argc, char **argv)
{
    if (argc > 1)                 /* ./snowflake 5 (read before glutInit sees argv) */
        depth = atoi(argv[1]);
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 500);
    glutCreateWindow("Koch Snowflake");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
