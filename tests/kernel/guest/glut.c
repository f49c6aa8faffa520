/* SPDX-License-Identifier: MIT */
/* Guest program: a GLUT course program, unchanged in form, on the guest's
 * real DRM driver (bochs-drm / virtio-gpu) through fixel's GLUT layer
 * (boards/glut, issue #21), driven by a uinput mouse and keyboard.
 *
 * The course program (course_main below: polylines placed with the mouse,
 * keys that change them) prints each callback it gets on its stdout, a pipe
 * read here; each injected event is checked against the callback it must
 * cause, with GLUT's window coordinates (origin at the window's top-left,
 * y down), GLUT_LEFT_BUTTON/GLUT_DOWN, ASCII with shift and a GLUT_KEY_*
 * special. The screen is then checked: the same program run headless with
 * the same events as a replay file (FIXEL_GLUT_REPLAY, the path the corpus
 * compares with Mesa) writes its window, and the host's screendump must
 * show exactly that picture where the window is. Also checked: the window
 * position given by glutInitWindowPosition, a window larger than the screen
 * scaled down with its aspect and centred, FIXEL_GLUT_FULLSCREEN=1 and
 * glutFullScreen(). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <GL/glut.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fixel/memfb.h"
#include "guest.h"
#include "image.h"
#include "uinput.h"

/* ---- the course program ------------------------------------------------ */

#define MAXP 64
static int px[MAXP], py[MAXP], np;
static int winW = 320, winH = 240, frames, dragging, closed, red;
static int course_w = 320, course_h = 240, course_fullscreen;

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(red ? 1.0f : 0.0f, 0.0f, red ? 0.0f : 1.0f);
    glLineWidth(2.0);
    glBegin(closed ? GL_LINE_LOOP : GL_LINE_STRIP);
    for (int i = 0; i < np; i++)
        glVertex2i(px[i], winH - py[i]);
    glEnd();
    glColor3f(0.0f, 0.6f, 0.0f);
    glPointSize(5.0);
    glBegin(GL_POINTS);
    for (int i = 0; i < np; i++)
        glVertex2i(px[i], winH - py[i]);
    glEnd();
    /* before the flush: FIXEL_GLUT_FRAMES=1 ends the program in it */
    if (++frames == 1)
        printf("window %d %d %d %d %d %d\n", glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y),
               glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_SCREEN_WIDTH),
               glutGet(GLUT_SCREEN_HEIGHT));
    fflush(stdout);
    glFlush();
    printf("display %d np %d\n", frames, np);
    fflush(stdout);
}

static void reshape(int w, int h)
{
    winW = w, winH = h;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    printf("reshape %d %d\n", w, h);
    fflush(stdout);
}

static void mouse(int button, int state, int x, int y)
{
    printf("mouse %d %d %d %d\n", button, state, x, y);
    fflush(stdout);
    if (button == GLUT_LEFT_BUTTON && state == GLUT_DOWN && np < MAXP) {
        px[np] = x, py[np] = y, np++;
        dragging = 1;
    } else if (button == GLUT_LEFT_BUTTON && state == GLUT_UP) {
        dragging = 0;
    }
    glutPostRedisplay();
}

static void motion(int x, int y) /* rubber band: the last vertex follows */
{
    printf("motion %d %d\n", x, y);
    fflush(stdout);
    if (dragging && np)
        px[np - 1] = x, py[np - 1] = y;
    glutPostRedisplay();
}

static void passive(int x, int y)
{
    printf("passive %d %d\n", x, y);
    fflush(stdout);
}

static void keyboard(unsigned char key, int x, int y)
{
    printf("key %d %d %d %d\n", key, glutGetModifiers(), x, y);
    fflush(stdout);
    if (key == 'R')
        red = 1;
    if (key == 'c')
        np = 0;
    if (key == 'q')
        exit(0);
    glutPostRedisplay();
}

static void keyboard_up(unsigned char key, int x, int y)
{
    printf("keyup %d %d %d\n", key, x, y);
    fflush(stdout);
}

static void special(int key, int x, int y)
{
    printf("special %d %d %d\n", key, x, y);
    fflush(stdout);
    if (key == GLUT_KEY_RIGHT)
        for (int i = 0; i < np; i++)
            px[i] += 10;
    if (key == GLUT_KEY_F1)
        closed = !closed;
    glutPostRedisplay();
}

static int course_main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(course_w, course_h);
    glutInitWindowPosition(40, 30);
    glutCreateWindow("polyline");
    if (course_fullscreen)
        glutFullScreen();
    glClearColor(1.0f, 1.0f, 0.9f, 1.0f);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMouseFunc(mouse);
    glutMotionFunc(motion);
    glutPassiveMotionFunc(passive);
    glutKeyboardFunc(keyboard);
    glutKeyboardUpFunc(keyboard_up);
    glutSpecialFunc(special);
    glutMainLoop();
    return 0;
}

/* ---- a second course program: a pop-up menu with a submenu ---------- */

static void menu_display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
    if (++frames == 1)
        printf("window %d %d %d %d %d %d\n", glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y),
               glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_SCREEN_WIDTH),
               glutGet(GLUT_SCREEN_HEIGHT));
    printf("display %d\n", frames);
    fflush(stdout);
}

static void menu_pick(int value)
{
    printf("menu %d %d\n", value, glutGetMenu());
    fflush(stdout);
    if (value == 99)
        exit(0);
    glutPostRedisplay();
}

static void menu_timer(int value)
{
    printf("timer %d\n", value);
    fflush(stdout);
}
static int idles;
static void menu_idle(void)
{
    if (++idles == 3) {
        glutIdleFunc(NULL); /* the loop goes back to sleeping on input */
        printf("idle %d\n", idles);
        fflush(stdout);
    }
}

static int menu_main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutInitWindowPosition(40, 30);
    glutCreateWindow("menu");
    glutDisplayFunc(menu_display);
    int size = glutCreateMenu(menu_pick);
    glutAddMenuEntry("Small", 10);
    glutAddMenuEntry("Large", 11);
    glutCreateMenu(menu_pick);
    glutAddMenuEntry("Red", 1);
    glutAddMenuEntry("Green", 2);
    glutAddSubMenu("Size", size);
    glutAddMenuEntry("Quit", 99);
    glutAttachMenu(GLUT_RIGHT_BUTTON);
    glutTimerFunc(50, menu_timer, 5);
    glutIdleFunc(menu_idle);
    glutMainLoop();
    return 0;
}

/* ---- the driver ---------------------------------------------------------- */

static struct libevdev_uinput *mouse_dev, *kbd_dev;
static void ev(struct libevdev_uinput *u, unsigned t, unsigned c, int v)
{
    libevdev_uinput_write_event(u, t, c, v);
}
static void syn(struct libevdev_uinput *u) { ev(u, EV_SYN, SYN_REPORT, 0); }
static void move(int dx, int dy)
{
    ev(mouse_dev, EV_REL, REL_X, dx);
    ev(mouse_dev, EV_REL, REL_Y, dy);
    syn(mouse_dev);
}
static void button(int down)
{
    ev(mouse_dev, EV_KEY, BTN_LEFT, down);
    syn(mouse_dev);
}
static void key(unsigned code, int down)
{
    ev(kbd_dev, EV_KEY, code, down);
    syn(kbd_dev);
}

static int from_child = -1;
static char pending[4096];
static size_t npending;

/* The child's next output line within ms; 0 on timeout or end of file. */
static int next_line(char *out, size_t n, int ms)
{
    for (;;) {
        char *nl = memchr(pending, '\n', npending);
        if (nl) {
            size_t l = (size_t)(nl - pending);
            snprintf(out, n, "%.*s", (int)l, pending);
            memmove(pending, nl + 1, npending - l - 1);
            npending -= l + 1;
            return 1;
        }
        struct pollfd p = {from_child, POLLIN, 0};
        if (npending == sizeof pending || poll(&p, 1, ms) <= 0)
            return 0;
        ssize_t r = read(from_child, pending + npending, sizeof pending - npending);
        if (r <= 0)
            return 0;
        npending += (size_t)r;
    }
}

/* Reads child lines until one starts with prefix; that line in out.
 * 0 after 20 s without one (TCG is slow, not that slow). */
static int wait_for(const char *prefix, char *out, size_t n)
{
    while (next_line(out, n, 20000)) {
        printf("  glut child: %s\n", out);
        if (!strncmp(out, prefix, strlen(prefix)))
            return 1;
    }
    out[0] = 0;
    return 0;
}

/* The next callback must be exactly want; the display callbacks the
 * program runs in between are passed over. */
static void expect(const char *check, const char *want)
{
    char got[256];
    int found = 0;
    while (!found && next_line(got, sizeof got, 20000)) {
        printf("  glut child: %s\n", got);
        found = strncmp(got, "display ", 8) != 0;
    }
    if (!found)
        snprintf(got, sizeof got, "(nothing in 20 s)");
    guest_check(check, !strcmp(got, want), "callback \"%s\", want \"%s\"", got, want);
}

/* The child's "window X Y W H SW SH" line. */
typedef struct winfo {
    int x, y, w, h, sw, sh, ok;
} winfo;
static winfo read_window(void)
{
    char line[256];
    winfo w = {0};
    if (wait_for("window ", line, sizeof line))
        w.ok = sscanf(line, "window %d %d %d %d %d %d", &w.x, &w.y, &w.w, &w.h, &w.sw, &w.sh) == 6;
    return w;
}

static int (*course)(int, char **) = course_main;
static pid_t start_course(const char *const *env, int cw, int ch)
{
    int fds[2];
    if (pipe(fds) < 0)
        return -1;
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        dup2(fds[1], 1);
        close(fds[1]);
        for (int i = 0; env[i]; i += 2)
            setenv(env[i], env[i + 1], 1);
        course_w = cw, course_h = ch;
        char *argv[] = {"course", NULL};
        _exit(course(1, argv));
    }
    close(fds[1]);
    if (from_child >= 0)
        close(from_child);
    from_child = fds[0];
    npending = 0;
    return pid;
}

static int finish(pid_t pid, int ms)
{
    int st = 0;
    for (int t = 0; t < ms; t += 50) {
        if (waitpid(pid, &st, WNOHANG) == pid)
            return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
        msleep(50);
    }
    kill(pid, SIGTERM);
    waitpid(pid, &st, 0);
    return -1;
}

/* The pointer to window point (X, Y): sx, sy track it on the screen. */
#define GOTO(X, Y) (move((X) + w.x - sx, (Y) + w.y - sy), sx = (X) + w.x, sy = (Y) + w.y)
/* A right click (opens the menu), a left click, at window point (X, Y). */
#define RIGHT_CLICK(X, Y) (GOTO(X, Y), rbutton(1), rbutton(0))
#define LEFT_CLICK(X, Y) (GOTO(X, Y), button(1), button(0))
static void tap_key(unsigned code, int times)
{
    for (int i = 0; i < times; i++) {
        key(code, 1);
        key(code, 0);
    }
}

/* ---- menus by mouse, keys and touch ---- */
static struct libevdev_uinput *touch_dev;
static void rbutton(int down)
{
    ev(mouse_dev, EV_KEY, BTN_RIGHT, down);
    syn(mouse_dev);
}
/* A contact in slot at screen (sx, sy) of a W x H screen (0..4095 on both
 * axes, rounded so fixel's scaling lands on that pixel); slot 0 also moves
 * the legacy axes and holds BTN_TOUCH, as a kernel driver reports it. */
static void touch(int slot, int down, int sx, int sy, int W, int H)
{
    ev(touch_dev, EV_ABS, ABS_MT_SLOT, slot);
    if (down) {
        int rx = (sx * 4095 * 2 + (W - 1)) / (2 * (W - 1)), ry = (sy * 4095 * 2 + (H - 1)) / (2 * (H - 1));
        ev(touch_dev, EV_ABS, ABS_MT_TRACKING_ID, 100 + slot);
        ev(touch_dev, EV_ABS, ABS_MT_POSITION_X, rx);
        ev(touch_dev, EV_ABS, ABS_MT_POSITION_Y, ry);
        if (slot == 0) {
            ev(touch_dev, EV_ABS, ABS_X, rx);
            ev(touch_dev, EV_ABS, ABS_Y, ry);
            ev(touch_dev, EV_KEY, BTN_TOUCH, 1);
        }
    } else {
        ev(touch_dev, EV_ABS, ABS_MT_TRACKING_ID, -1);
        if (slot == 0)
            ev(touch_dev, EV_KEY, BTN_TOUCH, 0);
    }
    syn(touch_dev);
}
static void expect_menu(const char *check, int value, const char *how)
{
    char line[256];
    int got = -1, id = 0;
    if (wait_for("menu ", line, sizeof line))
        sscanf(line, "menu %d %d", &got, &id);
    guest_check(check, got == value && id > 0, "%s: menu callback %d (menu %d), want %d", how, got, id, value);
}

/* The layer's popup geometry (boards/glut/glut.c): opened at the pointer,
 * entries 16 px high from 2 px below its top, a submenu opened beside its
 * entry; the top menu here is 54 px wide ("Green": 5 x 6 + 24). Entry i's
 * centre is at (x + 20, y + 2 + 16 i + 8). */
static void menu_cases(void)
{
    course = menu_main;
    static const char *const env[] = {NULL};
    pid_t pid = start_course(env, 320, 240);
    winfo w = read_window();
    char line[256];
    wait_for("display 1", line, sizeof line);
    /* the timer and the idle callback run on the display's loop too */
    int timer = -1, idle = -1;
    while ((timer < 0 || idle < 0) && next_line(line, sizeof line, 20000)) {
        printf("  glut child: %s\n", line);
        sscanf(line, "timer %d", &timer);
        sscanf(line, "idle %d", &idle);
    }
    guest_check("glut-timer", timer == 5, "glutTimerFunc(50, f, 5): f(%d)", timer);
    guest_check("glut-idle", idle == 3, "idle callback ran %d times, then glutIdleFunc(NULL)", idle);
    if (!w.ok) {
        guest_check("glut-menu-mouse", 0, "no window");
        finish(pid, 100);
        return;
    }
    /* this program's pointer starts at the screen's centre: to the corner */
    move(-20000, -20000);
    int sx = 0, sy = 0;
    const int mx = 100, my = 80; /* where the menu opens, window coordinates */
    /* mouse: press right, release on the spot (the menu stays), click "Green" */
    RIGHT_CLICK(mx, my);
    LEFT_CLICK(mx + 20, my + 2 + 16 * 1 + 8);
    expect_menu("glut-menu-mouse", 2, "right click, then a left click on Green");
    /* mouse into the submenu: Size opens it beside (x = 54 - 2), Large */
    RIGHT_CLICK(mx, my);
    LEFT_CLICK(mx + 20, my + 2 + 16 * 2 + 8);
    LEFT_CLICK(mx + 52 + 20, my + 2 + 16 * 2 + 2 + 16 * 1 + 8);
    expect_menu("glut-menu-submenu-mouse", 11, "Size > Large by mouse");
    /* keys: open with the mouse, Down x3 to Size, Right, Down, Enter: Small */
    RIGHT_CLICK(mx, my);
    tap_key(KEY_DOWN, 3);
    tap_key(KEY_RIGHT, 1);
    tap_key(KEY_DOWN, 1);
    tap_key(KEY_ENTER, 1);
    expect_menu("glut-menu-submenu-keys", 10, "Down Down Down Right Down Enter");
    /* keys alone: the Menu key opens it at the pointer, Down Down Enter */
    tap_key(KEY_COMPOSE, 1);
    tap_key(KEY_DOWN, 2);
    tap_key(KEY_ENTER, 1);
    expect_menu("glut-menu-keys-only", 2, "Menu key, Down Down Enter");
    /* touch: a finger at (mx, my), a second finger opens the menu there,
     * both lift, a tap on Red */
    touch(0, 1, w.x + mx, w.y + my, w.sw, w.sh);
    touch(1, 1, w.x + mx + 150, w.y + my + 100, w.sw, w.sh);
    touch(1, 0, 0, 0, w.sw, w.sh);
    touch(0, 0, 0, 0, w.sw, w.sh);
    touch(0, 1, w.x + mx + 20, w.y + my + 2 + 8, w.sw, w.sh);
    touch(0, 0, 0, 0, w.sw, w.sh);
    expect_menu("glut-menu-touch", 1, "two fingers, then a tap on Red");
    /* Quit by mouse: the program exits from its menu callback */
    RIGHT_CLICK(mx, my);
    LEFT_CLICK(mx + 20, my + 2 + 16 * 3 + 8);
    expect_menu("glut-menu-quit", 99, "Quit");
    int st = finish(pid, 20000);
    guest_check("glut-menu-exit", st == 0, "exit status %d", st);
    course = course_main;
}

/* Window placement: a window larger than the screen is scaled down with its
 * aspect and centred; FIXEL_GLUT_FULLSCREEN=1 and glutFullScreen() take the
 * whole screen. */
static void placement_cases(void)
{
    static const char *const big_env[] = {"FIXEL_GLUT_FRAMES", "1", NULL};
    pid_t pid = start_course(big_env, 4000, 1000);
    winfo w = read_window();
    int st = finish(pid, 20000);
    if (w.ok) {
        int eh = 1000 * w.sw / 4000;
        if (eh > w.sh) { /* a screen taller than wide: height-bound */
            guest_check("glut-window-scaled", 0, "screen %dx%d too narrow for this case", w.sw, w.sh);
        } else {
            guest_check("glut-window-scaled", w.w == w.sw && w.h == eh && w.x == 0 && w.y == (w.sh - eh) / 2 && st == 0,
                        "4000x1000 asked on %dx%d: %dx%d at (%d,%d), want %dx%d at (0,%d); exit %d", w.sw, w.sh,
                        w.w, w.h, w.x, w.y, w.sw, eh, (w.sh - eh) / 2, st);
        }
    } else {
        guest_check("glut-window-scaled", 0, "no window line; exit %d", st);
    }
    static const char *const full_env[] = {"FIXEL_GLUT_FRAMES", "1", "FIXEL_GLUT_FULLSCREEN", "1", NULL};
    pid = start_course(full_env, 320, 240);
    w = read_window();
    st = finish(pid, 20000);
    guest_check("glut-fullscreen-env", w.ok && w.w == w.sw && w.h == w.sh && w.x == 0 && w.y == 0 && st == 0,
                "FIXEL_GLUT_FULLSCREEN=1: %dx%d at (%d,%d) on %dx%d; exit %d", w.w, w.h, w.x, w.y, w.sw, w.sh, st);
    course_fullscreen = 1;
    pid = start_course(big_env, 320, 240);
    w = read_window();
    st = finish(pid, 20000);
    course_fullscreen = 0;
    guest_check("glut-fullscreen-call", w.ok && w.w == w.sw && w.h == w.sh && w.x == 0 && w.y == 0 && st == 0,
                "glutFullScreen(): %dx%d at (%d,%d) on %dx%d; exit %d", w.w, w.h, w.x, w.y, w.sw, w.sh, st);
}

/* The events of the DRM run as a replay file (window coordinates), for the
 * headless run that makes the expected picture: all of them after frame 1,
 * so they land in one redisplay, frame 2. The program's state is the same
 * whatever the batching. */
static const char replay_text[] =
    "frame 1: passive 50 60\n"
    "frame 1: mouse left down 50 60\n"
    "frame 1: mouse left up 50 60\n"
    "frame 1: passive 250 40\n"
    "frame 1: mouse left down 250 40\n"
    "frame 1: motion 150 190\n"
    "frame 1: mouse left up 150 190\n"
    "frame 1: passive 290 200\n"
    "frame 1: mouse left down 290 200\n"
    "frame 1: mouse left up 290 200\n"
    "frame 1: key R mods=shift\n"
    "frame 1: keyup R\n"
    "frame 1: special right\n"
    "frame 1: special f1\n";

static void expected_picture(void)
{
    FILE *f = fopen("/tmp/glut-replay.txt", "w");
    if (!f) {
        guest_check("glut-screen", 0, "cannot write the replay file");
        return;
    }
    fputs(replay_text, f);
    fclose(f);
    static const char *const env[] = {"FIXEL_BACKEND", "memory", "FIXEL_GLUT_FRAMES", "2",
                                      "FIXEL_GLUT_OUT", "/tmp/glut-expected.ppm", "FIXEL_GLUT_REPLAY",
                                      "/tmp/glut-replay.txt", NULL};
    pid_t pid = start_course(env, 320, 240);
    char line[256];
    while (next_line(line, sizeof line, 20000)) /* drain: the pipe must not fill */
        ;
    int st = finish(pid, 20000);
    if (st != 0)
        guest_check("glut-headless-replay", 0, "headless run exit %d", st);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    signal(SIGPIPE, SIG_IGN);

    struct libevdev *d = libevdev_new();
    libevdev_set_name(d, "fixel glut mouse");
    libevdev_enable_event_code(d, EV_REL, REL_X, NULL);
    libevdev_enable_event_code(d, EV_REL, REL_Y, NULL);
    libevdev_enable_event_code(d, EV_KEY, BTN_LEFT, NULL);
    libevdev_enable_event_code(d, EV_KEY, BTN_RIGHT, NULL);
    libevdev_enable_event_code(d, EV_KEY, BTN_MIDDLE, NULL);
    mouse_dev = uinput_create(d);
    d = libevdev_new();
    libevdev_set_name(d, "fixel glut keyboard");
    for (int k = KEY_ESC; k <= KEY_F10; k++)
        libevdev_enable_event_code(d, EV_KEY, (unsigned)k, NULL);
    libevdev_enable_event_code(d, EV_KEY, KEY_RIGHT, NULL);
    libevdev_enable_event_code(d, EV_KEY, KEY_DOWN, NULL);
    libevdev_enable_event_code(d, EV_KEY, KEY_COMPOSE, NULL);
    kbd_dev = uinput_create(d);
    d = libevdev_new();
    libevdev_set_name(d, "fixel glut touch");
    uinput_enable_multitouch(d, 4);
    touch_dev = uinput_create(d);
    if (!mouse_dev || !kbd_dev || !touch_dev) {
        guest_check("glut-uinput", 0, "uinput devices not created");
        return 1;
    }

    /* 1. the interactive run on DRM */
    static const char *const env[] = {NULL};
    pid_t pid = start_course(env, 320, 240);
    char line[256];
    int reshaped = wait_for("reshape ", line, sizeof line);
    guest_check("glut-reshape", reshaped && !strcmp(line, "reshape 320 240"), "\"%s\"", line);
    winfo w = read_window();
    guest_check("glut-window-position", w.ok && w.x == 40 && w.y == 30 && w.w == 320 && w.h == 240,
                "glutInitWindowPosition(40,30) 320x240 on %dx%d: %dx%d at (%d,%d)", w.sw, w.sh, w.w, w.h, w.x,
                w.y);
    if (!w.ok) {
        finish(pid, 100);
        return 1;
    }
    wait_for("display 1 ", line, sizeof line);
    /* The pointer starts at the screen's centre: to the top-left corner
     * (clamped there; no acceleration), then to exact places. */
    move(-20000, -20000);
    wait_for("passive ", line, sizeof line);
    int sx = 0, sy = 0; /* pointer on screen */
    GOTO(50, 60);
    expect("glut-passive", "passive 50 60");
    button(1);
    expect("glut-mouse-left-down", "mouse 0 0 50 60");
    button(0);
    expect("glut-mouse-left-up", "mouse 0 1 50 60");
    GOTO(250, 40);
    expect("glut-passive-2", "passive 250 40");
    button(1);
    expect("glut-mouse-left-down-2", "mouse 0 0 250 40");
    GOTO(150, 190);
    expect("glut-motion-drag", "motion 150 190");
    button(0);
    expect("glut-mouse-left-up-2", "mouse 0 1 150 190");
    GOTO(290, 200);
    expect("glut-passive-3", "passive 290 200");
    button(1);
    expect("glut-mouse-left-down-3", "mouse 0 0 290 200");
    button(0);
    expect("glut-mouse-left-up-3", "mouse 0 1 290 200");
    key(KEY_LEFTSHIFT, 1);
    key(KEY_R, 1);
    expect("glut-key-shift", "key 82 1 290 200"); /* 'R', GLUT_ACTIVE_SHIFT */
    key(KEY_R, 0);
    expect("glut-keyup-shift", "keyup 82 290 200");
    key(KEY_LEFTSHIFT, 0);
    key(KEY_RIGHT, 1);
    expect("glut-special-right", "special 102 290 200"); /* GLUT_KEY_RIGHT */
    key(KEY_RIGHT, 0);
    key(KEY_F1, 1);
    expect("glut-special-f1", "special 1 290 200"); /* GLUT_KEY_F1 */
    key(KEY_F1, 0);
    /* the last display shows every event: wait until the program is idle */
    char last[256] = "";
    while (next_line(line, sizeof line, 1500)) {
        printf("  glut child: %s\n", line);
        snprintf(last, sizeof last, "%s", line);
    }
    int screen_ok = !strcmp(last, "display") || !strncmp(last, "display ", 8);
    if (!screen_ok)
        guest_check("glut-screen", 0, "the last callback was \"%s\", not a display", last);

    /* 2. the same events headless: the expected window, compared with the screen */
    pid_t drm_pid = pid;
    int saved_fd = from_child;
    from_child = -1;
    expected_picture();
    uint8_t *rgb = NULL;
    int32_t ew = 0, eh = 0;
    if (screen_ok && fx_read_ppm_rgb("/tmp/glut-expected.ppm", &rgb, &ew, &eh) == 0) {
        char spec[64];
        snprintf(spec, sizeof spec, "screen@%d,%d", w.x, w.y);
        send_image("glut-screen", spec, rgb, ew, eh);
        free(rgb);
    } else if (screen_ok) {
        guest_check("glut-screen", 0, "no expected picture from the headless run");
    }
    if (from_child >= 0)
        close(from_child);
    from_child = saved_fd;
    npending = 0;

    /* 3. 'q': the program exits 0 from its keyboard callback */
    key(KEY_Q, 1);
    key(KEY_Q, 0);
    int st = finish(drm_pid, 20000);
    guest_check("glut-quit-key", st == 0, "exit status %d after 'q'", st);
    /* exit() from a callback still gives the console back */
    int kd = -1, tty = open("/dev/tty1", O_RDWR | O_NOCTTY);
    if (tty >= 0) {
        ioctl(tty, KDGETMODE, &kd);
        close(tty);
    }
    guest_check("glut-quit-console", kd == KD_TEXT, "KDGETMODE %d after the program's exit(0), want text (%d)", kd,
                KD_TEXT);

    menu_cases();
    placement_cases();
    libevdev_uinput_destroy(touch_dev);
    libevdev_uinput_destroy(mouse_dev);
    libevdev_uinput_destroy(kbd_dev);
    return guest_failed;
}
