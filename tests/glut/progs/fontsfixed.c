/* SPDX-License-Identifier: MIT */
/* A terminal-style screen in GLUT's two fixed fonts: 8x13 and 9x15 lines
 * laid out on the cell grid with glutBitmapHeight/glutBitmapWidth, a
 * two-line glutBitmapString, a status line right-aligned by
 * glutBitmapLength. The text keeps to the characters whose glyphs
 * freeglut's data and today's misc-fixed draw the same (tests/glut/README.md,
 * "Bitmap fonts"; tests/glut/self.sh checks all 256 of each). */
#include <GL/freeglut.h>
#include <stdio.h>

static void line(void *font, int col, int row, const char *s)
{
    int h = glutBitmapHeight(font), w = glutBitmapWidth(font, 'm');
    glRasterPos2i(8 + col * w, 470 - (row + 1) * h);
    for (; *s; s++)
        glutBitmapCharacter(font, (unsigned char)*s);
}

static void display(void)
{
    char buf[96];
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.3f, 1.0f, 0.3f);
    line(GLUT_BITMAP_8_BY_13, 0, 0, "$ ls /home/student/lab3");
    line(GLUT_BITMAP_8_BY_13, 0, 1, "main.c    main.o    a.out    Makefile    notes.txt");
    line(GLUT_BITMAP_8_BY_13, 0, 2, "$ ./a.out");
    line(GLUT_BITMAP_8_BY_13, 0, 3, "points: 1431   lines: 820   time: 0.013 s");
    line(GLUT_BITMAP_8_BY_13, 0, 4, "the quick brown fox jumps over the lazy dog");
    line(GLUT_BITMAP_8_BY_13, 0, 5, "THE QUICK CHARM OF LAZY NIGHTS 0123456789 (x, y) = [3.5; 7]");
    line(GLUT_BITMAP_8_BY_13, 0, 6, "!\"#%&+,./:;<=>?@\\^_{|}~");
    glColor3f(1.0f, 0.8f, 0.2f);
    line(GLUT_BITMAP_9_BY_15, 0, 6, "the quick brown fox jumps over the lazy dog");
    line(GLUT_BITMAP_9_BY_15, 0, 7, "QUICK MATH: 12 + 34 = 46; 9 / 3 = 3 (ok)");
    line(GLUT_BITMAP_9_BY_15, 0, 8, "!\"#%&+,-./:;<=>?@[\\]^_{|}~");
    line(GLUT_BITMAP_9_BY_15, 0, 9, "\xe0\xe1\xe2\xe3\xe4\xe5\xe7\xe8\xe9\xea\xeb\xf1\xf6\xfc\xc4\xd6\xdc\xdf");
    glColor3f(0.7f, 0.8f, 1.0f);
    glRasterPos2i(8, 200);
    glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char *)"frame 1 of 1\ncells 9 x 15");
    glRasterPos2i(8, 150);
    glutBitmapString(GLUT_BITMAP_8_BY_13, (const unsigned char *)"cells 8 x 13\nline two\nline three");
    snprintf(buf, sizeof buf, "row %d col %d", 24, 80);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos2i(632 - glutBitmapLength(GLUT_BITMAP_9_BY_15, (const unsigned char *)buf), 6);
    glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char *)buf);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(640, 480);
    glutCreateWindow("Fixed bitmap fonts");
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gluOrtho2D(0, 640, 0, 480);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
