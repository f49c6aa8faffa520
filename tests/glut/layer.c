/* SPDX-License-Identifier: MIT */
/* fixel's GLUT layer on its own (no Mesa): what a frame cannot show.
 * tests/glut/layer.sh runs it once per case and judges exit status and
 * output; this program prints "ok NAME" / "FAIL NAME detail" lines.
 *   layer api          glutGet, glutGetModifiers, stroke and bitmap text
 *                      metrics against what they draw, glGet round trips
 *   layer leave-return glutLeaveMainLoop with GLUT_ACTION_CONTINUE_EXECUTION:
 *                      glutMainLoop returns (prints "returned", exit 7)
 *   layer leave-exit   the same without the option: exit(0) inside, as freeglut
 *   layer menu-keys    a pop-up menu opened and used with keys alone */
#include <GL/freeglut.h>
#include <stdio.h>
#include <string.h>

static int failed;
static void check(const char *name, int ok, const char *detail)
{
    printf("%s %s%s%s\n", ok ? "ok" : "FAIL", name, ok ? "" : " ", ok ? "" : detail);
    failed |= !ok;
}

/* Pixels of the window that are not the clear colour (black). */
static int lit_pixels(int w, int h)
{
    static unsigned char px[320 * 240 * 3];
    int n = 0;
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, px);
    for (int i = 0; i < w * h * 3; i += 3)
        n += px[i] || px[i + 1] || px[i + 2];
    return n;
}

static void api_display(void)
{
    char d[160];
    GLfloat m[16];
    glClear(GL_COLOR_BUFFER_BIT);
    snprintf(d, sizeof d, "%d x %d at (%d,%d), double %d", glutGet(GLUT_WINDOW_WIDTH),
             glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y),
             glutGet(GLUT_WINDOW_DOUBLEBUFFER));
    check("glutGet-window", glutGet(GLUT_WINDOW_WIDTH) == 320 && glutGet(GLUT_WINDOW_HEIGHT) == 240 &&
                                glutGet(GLUT_WINDOW_DOUBLEBUFFER) == 1 && glutGet(GLUT_WINDOW_DEPTH_SIZE) > 0,
          d);
    check("glutGet-init", glutGet(GLUT_INIT_WINDOW_WIDTH) == 320 && glutGet(GLUT_INIT_DISPLAY_MODE) ==
                              (GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH), "init values");
    check("glutGetModifiers-outside", glutGetModifiers() == 0, "not 0 outside a callback");

    /* stroke text: the advance is glutStrokeWidthf, the string length the
     * sum, and the strokes land where the text is */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(10, 100, 0);
    glScalef(0.25f, 0.25f, 1);
    glColor3f(1, 1, 1);
    float before, after;
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    before = m[12];
    glutStrokeCharacter(GLUT_STROKE_ROMAN, 'W');
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    after = m[12];
    snprintf(d, sizeof d, "advance %.3f, width %.3f", (after - before) / 0.25f,
             glutStrokeWidthf(GLUT_STROKE_ROMAN, 'W'));
    check("glutStrokeCharacter-advance",
          (after - before) / 0.25f > glutStrokeWidthf(GLUT_STROKE_ROMAN, 'W') - 0.01f &&
              (after - before) / 0.25f < glutStrokeWidthf(GLUT_STROKE_ROMAN, 'W') + 0.01f, d);
    int lit = lit_pixels(320, 240);
    snprintf(d, sizeof d, "%d pixels", lit);
    check("glutStrokeCharacter-draws", lit > 20, d);
    const unsigned char *s = (const unsigned char *)"GLUT";
    float sum = 0;
    for (int i = 0; s[i]; i++)
        sum += glutStrokeWidthf(GLUT_STROKE_MONO_ROMAN, s[i]);
    snprintf(d, sizeof d, "length %f, sum %f", glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, s), sum);
    check("glutStrokeLength", glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, s) > sum - 0.01f &&
                                  glutStrokeLengthf(GLUT_STROKE_MONO_ROMAN, s) < sum + 0.01f &&
                                  glutStrokeLength(GLUT_STROKE_MONO_ROMAN, s) == (int)(sum + 0.5f), d);
    check("glutStrokeHeight", glutStrokeHeight(GLUT_STROKE_ROMAN) > 100, "freeglut's 119.05");

    /* the seven bitmap fonts: length is the sum of widths; the fixed fonts
     * keep their cell width */
    void *fonts[7] = {GLUT_BITMAP_9_BY_15, GLUT_BITMAP_8_BY_13, GLUT_BITMAP_TIMES_ROMAN_10,
                      GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
                      GLUT_BITMAP_HELVETICA_18};
    int good = 1;
    for (int f = 0; f < 7; f++) {
        int w = 0;
        for (int i = 0; s[i]; i++)
            w += glutBitmapWidth(fonts[f], s[i]);
        good &= w == glutBitmapLength(fonts[f], s) && w > 0;
        /* each font draws, and glutBitmapCharacter moves the raster
         * position by the width */
        glClear(GL_COLOR_BUFFER_BIT);
        glLoadIdentity();
        glRasterPos2i(20, 120);
        GLint p0[4], p1[4];
        glGetIntegerv(GL_CURRENT_RASTER_POSITION, p0);
        glutBitmapCharacter(fonts[f], 'M');
        glGetIntegerv(GL_CURRENT_RASTER_POSITION, p1);
        good &= p1[0] - p0[0] == glutBitmapWidth(fonts[f], 'M') && lit_pixels(320, 240) > 5;
    }
    check("glutBitmap-seven-fonts", good, "a width, length, advance or drawing does not add up");
    check("glutBitmapWidth-fixed", glutBitmapWidth(GLUT_BITMAP_9_BY_15, 'i') == 9 &&
                                       glutBitmapWidth(GLUT_BITMAP_8_BY_13, 'W') == 8, "cell widths 9 and 8");

    /* glGet round trips of what the program set */
    GLint vp[4];
    GLfloat cc[4];
    glViewport(3, 4, 100, 50);
    glGetIntegerv(GL_VIEWPORT, vp);
    glClearColor(0.25f, 0.5f, 0.75f, 1);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
    glColor4f(0.5f, 0.25f, 1, 1);
    GLfloat cur[4];
    glGetFloatv(GL_CURRENT_COLOR, cur);
    check("glGet-viewport-colours", vp[0] == 3 && vp[1] == 4 && vp[2] == 100 && vp[3] == 50 && cc[0] == 0.25f &&
                                        cc[2] == 0.75f && cur[0] == 0.5f && cur[1] == 0.25f,
          "viewport / clear colour / current colour");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2, 2, -1, 1, 1, 3);
    GLdouble pm[16];
    glGetDoublev(GL_PROJECTION_MATRIX, pm);
    check("glGet-projection", pm[0] == 0.5 && pm[5] == 1.0 && pm[10] == -1.0 && pm[14] == -2.0, "glOrtho");
    GLint depth;
    glGetIntegerv(GL_MATRIX_MODE, &depth);
    check("glGet-matrix-mode", depth == GL_PROJECTION, "GL_MATRIX_MODE");
    glMatrixMode(GL_MODELVIEW);
    check("glGetError-clean", glGetError() == GL_NO_ERROR, "an error was left");

    /* the light model and material state: kept per face, the GL 1.x ranges */
    GLint tw = 0, lv = 0, cm[2] = {0, 0};
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glGetIntegerv(GL_LIGHT_MODEL_TWO_SIDE, &tw);
    glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, &lv);
    check("glLightModel-two-side-local-viewer", tw == 1 && lv == 1 && glGetError() == GL_NO_ERROR,
          "GL_LIGHT_MODEL_TWO_SIDE / LOCAL_VIEWER not kept, or an error");
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0);
    GLfloat fd[4] = {0.25f, 0.5f, 0.75f, 1}, bd[4] = {1, 0.5f, 0, 1}, got_f[4], got_b[4], sh = -1;
    glMaterialfv(GL_FRONT, GL_DIFFUSE, fd);
    glMaterialfv(GL_BACK, GL_DIFFUSE, bd);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, got_f);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, got_b);
    check("glMaterial-per-face", got_f[0] == 0.25f && got_f[2] == 0.75f && got_b[0] == 1 && got_b[2] == 0 &&
                                     glGetError() == GL_NO_ERROR, "front and back diffuse mixed up");
    glMaterialf(GL_BACK, GL_SHININESS, 129);
    GLenum e1 = glGetError();
    glGetMaterialfv(GL_BACK, GL_SHININESS, &sh);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 95);
    GLenum e2 = glGetError();
    glMaterialfv(GL_LEFT, GL_DIFFUSE, fd);
    GLenum e3 = glGetError();
    glColorMaterial(GL_FRONT, GL_POSITION);
    GLenum e4 = glGetError();
    check("glMaterial-glLight-ranges", e1 == GL_INVALID_VALUE && sh == 20 && e2 == GL_INVALID_VALUE &&
                                           e3 == GL_INVALID_ENUM && e4 == GL_INVALID_ENUM,
          "shininess 129 / cut-off 95 / face GL_LEFT / colour-material GL_POSITION accepted");
    /* while GL_COLOR_MATERIAL tracks the back diffuse, glMaterial leaves it */
    glColorMaterial(GL_BACK, GL_DIFFUSE);
    glGetIntegerv(GL_COLOR_MATERIAL_FACE, &cm[0]);
    glGetIntegerv(GL_COLOR_MATERIAL_PARAMETER, &cm[1]);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0, 1, 0);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, fd);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, got_f);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, got_b);
    glDisable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    check("glColorMaterial-tracked-face", cm[0] == GL_BACK && cm[1] == GL_DIFFUSE && got_f[0] == 0.25f &&
                                              got_b[0] == 0 && got_b[1] == 1 && glGetError() == GL_NO_ERROR,
          "the tracked back diffuse was overwritten, or the front one not set");
    glutSwapBuffers(); /* frame 1: FIXEL_GLUT_FRAMES=1 ends here */
}

static int frames;
static void leave_display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
    frames++;
}
static void leave_idle(void)
{
    if (frames >= 3)
        glutLeaveMainLoop();
    else
        glutPostRedisplay();
}

/* layer menu-keys: a menu with a submenu on the right button, driven by
 * keys alone (raw evdev through the keymap: the Menu key, arrows, Enter) */
static void menu_display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
}
static void menu_pick(int v)
{
    printf("menu %d\n", v);
    glutPostRedisplay();
}
static void menu_special(int k, int x, int y)
{
    printf("special %d %d %d\n", k, x, y);
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "api";
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("layer");
    if (!strcmp(mode, "api")) {
        glutDisplayFunc(api_display);
    } else if (!strcmp(mode, "menu-keys")) {
        int sub = glutCreateMenu(menu_pick);
        glutAddMenuEntry("Small", 10);
        glutAddMenuEntry("Large", 11);
        glutCreateMenu(menu_pick);
        glutAddMenuEntry("Red", 1);
        glutAddMenuEntry("Green", 2);
        glutAddSubMenu("Size", sub);
        glutAttachMenu(GLUT_RIGHT_BUTTON);
        glutDisplayFunc(menu_display);
        glutSpecialFunc(menu_special);
    } else {
        if (!strcmp(mode, "leave-return"))
            glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_CONTINUE_EXECUTION);
        glutDisplayFunc(leave_display);
        glutIdleFunc(leave_idle);
    }
    glutMainLoop();
    printf("returned frames=%d action=%d\n", frames, glutGet(GLUT_ACTION_ON_WINDOW_CLOSE));
    return 7;
}
