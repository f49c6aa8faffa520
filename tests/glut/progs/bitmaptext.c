/* SPDX-License-Identifier: MIT */
/* Bitmap text in every GLUT bitmap font, with a string centred by width. */
#include <GL/freeglut.h>   /* glutBitmapString is freeglut's */
#include <string.h>

void drawString(void *font, const char *s, int x, int y)
{
    glRasterPos2i(x, y);
    while (*s)
        glutBitmapCharacter(font, *s++);
}

int stringWidth(void *font, const char *s)
{
    int w = 0;
    while (*s)
        w += glutBitmapWidth(font, *s++);
    return w;
}

void display(void)
{
    const char *title = "Computer Graphics Lab";
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 1.0, 0.0);
    drawString(GLUT_BITMAP_TIMES_ROMAN_24, title,
               (640 - stringWidth(GLUT_BITMAP_TIMES_ROMAN_24, title)) / 2, 430);
    glColor3f(1.0, 1.0, 1.0);
    drawString(GLUT_BITMAP_8_BY_13, "GLUT_BITMAP_8_BY_13: The quick brown fox 0123456789", 20, 370);
    drawString(GLUT_BITMAP_9_BY_15, "GLUT_BITMAP_9_BY_15: jumps over the lazy dog !?", 20, 330);
    glColor3f(0.5, 1.0, 0.5);
    drawString(GLUT_BITMAP_TIMES_ROMAN_10, "GLUT_BITMAP_TIMES_ROMAN_10: Sphinx of black quartz", 20, 290);
    drawString(GLUT_BITMAP_HELVETICA_10, "GLUT_BITMAP_HELVETICA_10: judge my vow", 20, 250);
    drawString(GLUT_BITMAP_HELVETICA_12, "GLUT_BITMAP_HELVETICA_12: Pack my box with five dozen", 20, 210);
    drawString(GLUT_BITMAP_HELVETICA_18, "GLUT_BITMAP_HELVETICA_18: liquor jugs", 20, 160);
    glColor3f(0.6, 0.8, 1.0);
    glRasterPos2i(20, 100);
    glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char *)"Score: 42   Lives: 3");
    glColor3f(1.0, 0.3, 0.3);
    glRasterPos2i(20, 40);
    glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char *)"Press q to quit");
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Bitmap text");
    glClearColor(0.1, 0.1, 0.3, 1);
    gluOrtho2D(0, 640, 0, 480);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
