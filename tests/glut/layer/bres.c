/* SPDX-License-Identifier: MIT */
/* Course style: Bresenham with GL_POINTS, gluOrtho2D called in MODELVIEW,
 * a mouse-drawn polyline, keyboard and a right-button menu. */
#include <GL/glut.h>
#include <stdio.h>
static int px[64][2], np, colour = 1;
static void plot(int x, int y) { glBegin(GL_POINTS); glVertex2i(x, y); glEnd(); }
static void bres(int x0, int y0, int x1, int y1)
{
    int dx = x1 - x0, dy = y1 - y0, p = 2 * dy - dx, x = x0, y = y0;
    for (int k = 0; k <= dx; k++) {
        plot(x, y);
        x++;
        if (p >= 0) { y++; p += 2 * dy - 2 * dx; } else p += 2 * dy;
    }
}
static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(colour == 1, colour == 2, 1);
    bres(10, 12, 150, 80);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < np; i++) glVertex2i(px[i][0], 150 - px[i][1]);
    glEnd();
    glFlush();
}
static void mouse(int b, int s, int x, int y)
{
    if (b == GLUT_LEFT_BUTTON && s == GLUT_DOWN && np < 64) { px[np][0] = x; px[np][1] = y; np++; glutPostRedisplay(); }
}
static void key(unsigned char k, int x, int y) { (void)x, (void)y; printf("key %d\n", k); fflush(stdout); }
static void menu(int v) { colour = v; printf("menu %d\n", v); fflush(stdout); glutPostRedisplay(); }
int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(200, 150);
    glutCreateWindow("bres");
    glClearColor(0, 0, 0, 0);
    gluOrtho2D(0, 200, 0, 150);
    glutDisplayFunc(display);
    glutMouseFunc(mouse);
    glutKeyboardFunc(key);
    glutCreateMenu(menu);
    glutAddMenuEntry("magenta", 1);
    glutAddMenuEntry("cyan", 2);
    glutAttachMenu(GLUT_RIGHT_BUTTON);
    glutMainLoop();
    return 0;
}
