/* SPDX-License-Identifier: MIT */
/* Every glyph of every GLUT_BITMAP_* font, read back (issue #37): for each
 * font its glutBitmapHeight, then for each character 0-255 its
 * glutBitmapWidth, how far glutBitmapCharacter moved the raster position
 * and the lit pixels relative to the raster position; then
 * glutBitmapLength and the raster position after glutBitmapString of a
 * two-line string. tests/glut/self.sh runs it on fixel and on freeglut +
 * Mesa and compares the two outputs glyph by glyph. */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

#define S 96 /* the window, and the raster position at (O, O) */
#define O 40
static void *fonts[7];
static const char *names[7] = {"8x13", "9x15", "times10", "times24", "helv10", "helv12", "helv18"};

static void display(void)
{
    static unsigned char px[S * S * 3];
    float rp[4];
    for (int f = 0; f < 7; f++) {
        printf("font %s height %d\n", names[f], glutBitmapHeight(fonts[f]));
        for (int c = 0; c < 256; c++) {
            glClear(GL_COLOR_BUFFER_BIT);
            glRasterPos2i(O, O);
            glutBitmapCharacter(fonts[f], c);
            glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
            glReadPixels(0, 0, S, S, GL_RGB, GL_UNSIGNED_BYTE, px);
            printf("%s c %d width %d moved %g %g:", names[f], c, glutBitmapWidth(fonts[f], c), rp[0] - O,
                   rp[1] - O);
            for (int y = 0; y < S; y++)
                for (int x = 0; x < S; x++)
                    if (px[(y * S + x) * 3])
                        printf(" %d,%d", x - O, y - O);
            printf("\n");
        }
        const unsigned char two[] = "Ab\nlonger line";
        glRasterPos2i(O, O);
        glutBitmapString(fonts[f], two);
        glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
        printf("%s length %d string moved %g %g\n", names[f], glutBitmapLength(fonts[f], two), rp[0] - O,
               rp[1] - O);
    }
    /* the stroke metrics freeglut has as single numbers (ROMAN's advances
     * are freeglut's own table, not reproduced) */
    const unsigned char two[] = "ab\ncde";
    printf("stroke height %.3f %.3f length %.3f\n", glutStrokeHeight(GLUT_STROKE_ROMAN),
           glutStrokeHeight(GLUT_STROKE_MONO_ROMAN), glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, two));
    for (int c = 0; c < 256; c += 5)
        printf("stroke mono %d width %.3f %d\n", c, glutStrokeWidthf(GLUT_STROKE_MONO_ROMAN, c),
               glutStrokeWidth(GLUT_STROKE_MONO_ROMAN, c));
    fflush(stdout);
    exit(0);
}

int main(int argc, char **argv)
{
    fonts[0] = GLUT_BITMAP_8_BY_13, fonts[1] = GLUT_BITMAP_9_BY_15;
    fonts[2] = GLUT_BITMAP_TIMES_ROMAN_10, fonts[3] = GLUT_BITMAP_TIMES_ROMAN_24;
    fonts[4] = GLUT_BITMAP_HELVETICA_10, fonts[5] = GLUT_BITMAP_HELVETICA_12;
    fonts[6] = GLUT_BITMAP_HELVETICA_18;
    glutInit(&argc, argv);
    glutInitWindowSize(S, S);
    glutInitWindowPosition(0, 0);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutCreateWindow("glyphs");
    glViewport(0, 0, S, S);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, S, 0, S, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
