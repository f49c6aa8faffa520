/* SPDX-License-Identifier: MIT */
/* Self-checking (issue #38): a window's life as freeglut has it. Built and
 * run the same way against fixel's layer and against freeglut + Mesa
 * (tests/glut/self.sh), so the expectations are known to be freeglut's.
 * Prints "ok NAME" / "FAIL NAME detail" and event lines; self.sh judges
 * them and the exit status.
 *   winlife size-before-init   glutInitWindowSize/Position before glutInit
 *   winlife destroy-outside    glutDestroyWindow outside glutMainLoop returns
 *   winlife destroy-exit       ... inside it: the loop ends, exit(0)
 *   winlife destroy-return     ... with GLUT_ACTION_GLUTMAINLOOP_RETURNS
 *   winlife destroy-create     a new window after glutDestroyWindow */
#include <GL/freeglut.h>
#include <stdio.h>
#include <string.h>

static int win;

static void check(const char *name, int ok, int got, int want)
{
    if (ok)
        printf("ok %s\n", name);
    else
        printf("FAIL %s got %d want %d\n", name, got, want);
    fflush(stdout);
}
#define EQ(name, got, want) check(name, (got) == (want), (got), (want))

static void on_close(void)
{
    printf("close\n");
    fflush(stdout);
}
static void size_display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    EQ("window-width", glutGet(GLUT_WINDOW_WIDTH), 123);
    EQ("window-height", glutGet(GLUT_WINDOW_HEIGHT), 77);
    EQ("init-width", glutGet(GLUT_INIT_WINDOW_WIDTH), 123);
    EQ("init-height", glutGet(GLUT_INIT_WINDOW_HEIGHT), 77);
    EQ("init-x", glutGet(GLUT_INIT_WINDOW_X), 10);
    EQ("init-y", glutGet(GLUT_INIT_WINDOW_Y), 20);
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    EQ("viewport-width", vp[2], 123);
    EQ("viewport-height", vp[3], 77);
    glFlush();
    glutLeaveMainLoop();
}
static void second_display(void)
{
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    unsigned char px[3];
    glReadPixels(31, 23, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, px);
    EQ("second-width", glutGet(GLUT_WINDOW_WIDTH), 32);
    EQ("second-height", glutGet(GLUT_WINDOW_HEIGHT), 24);
    EQ("second-pixel", px[1], 255);
    glFlush();
    glutLeaveMainLoop();
}
static void destroy_display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
    printf("display\n");
    glutDestroyWindow(win);
    printf("destroyed\n");
    fflush(stdout);
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "";
    if (!strcmp(mode, "size-before-init")) {
        glutInitWindowSize(123, 77);
        glutInitWindowPosition(10, 20);
    }
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    if (strcmp(mode, "size-before-init"))
        glutInitWindowSize(64, 48);
    win = glutCreateWindow("winlife");
    glutCloseFunc(on_close);
    if (!strcmp(mode, "size-before-init")) {
        glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
        glutDisplayFunc(size_display);
        glutMainLoop();
        return 0;
    }
    if (!strcmp(mode, "destroy-outside")) {
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        glutDestroyWindow(win);
        printf("returned\n");
        EQ("current-window", glutGetWindow(), 0);
        return 7;
    }
    if (!strcmp(mode, "destroy-exit") || !strcmp(mode, "destroy-return")) {
        if (!strcmp(mode, "destroy-return"))
            glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
        glutDisplayFunc(destroy_display);
        glutMainLoop();
        printf("returned\n");
        return 7;
    }
    if (!strcmp(mode, "destroy-create")) {
        glutDestroyWindow(win);
        glutInitWindowSize(32, 24);
        win = glutCreateWindow("second");
        EQ("second-id", win > 0, 1);
        glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
        glutDisplayFunc(second_display);
        glutMainLoop();
        printf("returned\n");
        return 7;
    }
    fprintf(stderr, "winlife: unknown mode '%s'\n", mode);
    return 2;
}
