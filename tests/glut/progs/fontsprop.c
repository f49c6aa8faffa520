/* SPDX-License-Identifier: MIT */
/* A HUD in the proportional GLUT fonts: every printable character of
 * Helvetica 12 and 18 (ASCII and Latin-1), labels in Times and Helvetica
 * 10, right-aligned numbers by glutBitmapLength, a multi-line
 * glutBitmapString, a label at a non-integer raster position, one running
 * off the right edge and one whose position is off the window. */
#include <GL/freeglut.h>
#include <stdio.h>
#include <string.h>

static void text(void *font, float x, float y, const char *s)
{
    glRasterPos2f(x, y);
    for (; *s; s++)
        glutBitmapCharacter(font, (unsigned char)*s);
}
static void right(void *font, int x, int y, const char *s)
{
    glRasterPos2i(x - glutBitmapLength(font, (const unsigned char *)s), y);
    glutBitmapString(font, (const unsigned char *)s);
}

static void display(void)
{
    char line[128];
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);
    for (int row = 0; row < 3; row++) {
        int n = 0;
        for (int c = 32 + row * 32; c < 64 + row * 32 && c < 127; c++)
            line[n++] = (char)c;
        line[n] = 0;
        text(GLUT_BITMAP_HELVETICA_12, 10, 470 - 16 * row, line);
    }
    glColor3f(1.0f, 0.9f, 0.4f);
    for (int row = 0; row < 4; row++) {
        int n = 0;
        for (int c = 160 + row * 24; c < 184 + row * 24 && c < 256; c++)
            line[n++] = (char)c;
        line[n] = 0;
        text(GLUT_BITMAP_HELVETICA_18, 10, 405 - 23 * row, line);
    }
    glColor3f(0.5f, 1.0f, 0.5f);
    for (int row = 0; row < 3; row++) {
        int n = 0;
        for (int c = 32 + row * 32; c < 64 + row * 32 && c < 127; c++)
            line[n++] = (char)c;
        line[n] = 0;
        text(GLUT_BITMAP_HELVETICA_18, 10, 300 - 23 * row, line);
    }
    glColor3f(0.6f, 0.8f, 1.0f);
    text(GLUT_BITMAP_TIMES_ROMAN_24, 10, 200, "Sphinx of black quartz, judge my vow!");
    text(GLUT_BITMAP_TIMES_ROMAN_10, 10, 180, "Times 10: THE QUICK BROWN FOX JUMPS OVER THE LAZY DOG (0123456789).");
    text(GLUT_BITMAP_HELVETICA_10, 10, 166, "Helvetica 10: the quick brown fox jumps over the lazy dog [0123456789].");
    glColor3f(1.0f, 0.5f, 0.3f);
    for (int i = 0; i < 4; i++) {
        snprintf(line, sizeof line, "%d.%02d", 7 * i * i * i + 3, 17 * i % 100);
        right(GLUT_BITMAP_HELVETICA_12, 630, 140 - 14 * i, line);
        right(GLUT_BITMAP_TIMES_ROMAN_24, 500, 140 - 26 * i, line);
    }
    glColor3f(0.9f, 0.9f, 0.9f);
    glRasterPos2i(10, 140);
    glutBitmapString(GLUT_BITMAP_HELVETICA_12, (const unsigned char *)"Score: 42\nLives: 3\nLevel: Nine");
    text(GLUT_BITMAP_HELVETICA_12, 200.6f, 100.4f, "at (200.6, 100.4)");
    text(GLUT_BITMAP_TIMES_ROMAN_24, 540, 40, "cut at the edge");
    text(GLUT_BITMAP_HELVETICA_18, -5, 20, "not drawn: raster position off the window");
    text(GLUT_BITMAP_HELVETICA_18, 3, 2, "gjpqy below the baseline");
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Proportional bitmap fonts");
    glClearColor(0.1f, 0.1f, 0.25f, 1.0f);
    gluOrtho2D(0, 640, 0, 480);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
