/* SPDX-License-Identifier: MIT */
/* fixel GLUT layer — the window, the main loop, input, menus and the
 * headless runs.
 *
 * The window is a window-sized back buffer (gl.c draws into it); each frame
 * (glFlush/glFinish single-buffered, glutSwapBuffers double-buffered) it is
 * copied to its rectangle of the screen through fx_app, with an open popup
 * menu drawn over it. Headless (FIXEL_BACKEND=memory, or no display) there is
 * no fx_app: the loop runs the callbacks itself on a virtual clock, takes
 * input from FIXEL_GLUT_REPLAY (replay.c; the format is tests/glut/README.md's)
 * and FIXEL_GLUT_FRAMES / FIXEL_GLUT_OUT end it and write the frame.
 * The environment is read in one place, fx_glut_env_read (env.c, at glutInit). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <stdarg.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

#include "fixel/app.h"
#include "fixel/env.h"
#include "fixel/files.h"
#include "fixel/draw.h"
#include "fixel/font.h"
#include "fixel/input.h"
#include "glut_int.h"
#include "glut_replay.h"

static void out_check(const char *path);

#define MAX_TIMERS 64
#define MAX_MENUS 64
#define MAX_ITEMS 64

typedef struct menu_item {
    char label[64];
    int value, submenu; /* submenu: menu id or 0 */
} menu_item;

typedef struct menu {
    int used;
    void (*cb)(int);
    menu_item items[MAX_ITEMS];
    int n;
} menu;

static struct {
    int inited, created;
    unsigned mode;
    int init_x, init_y, init_w, init_h;
    fx_glut_env env; /* read once at glutInit (env.c) */
    uint64_t bench_t1; /* FIXEL_GLUT_BENCH: wall clock at the end of frame 1 */
    /* runtime */
    fx_app *app;
    int headless;
    int32_t scr_w, scr_h;
    int32_t win_x, win_y; /* on screen */
    long frames;
    int redisplay, leave;
    int in_loop; /* inside glutMainLoop */
    void (*close_pending)(void); /* glutDestroyWindow: the window's close callback, still due */
    int had_window;    /* a window was created (and destroyed): its buffers are still held */
    int on_close; /* GLUT_ACTION_ON_WINDOW_CLOSE: what the end of glutMainLoop does */
    uint64_t t0_us, vclock_us;
    unsigned mods;
    char title[128];
    /* callbacks */
    void (*display)(void);
    void (*reshape)(int, int);
    void (*keyboard)(unsigned char, int, int);
    void (*keyboard_up)(unsigned char, int, int);
    void (*special)(int, int, int);
    void (*special_up)(int, int, int);
    void (*mouse)(int, int, int, int);
    void (*motion)(int, int);
    void (*passive)(int, int);
    void (*wheel)(int, int, int, int);
    void (*idle)(void);
    void (*visibility)(int);
    void (*close)(void);
    void (*entry)(int);
    void (*menu_status)(int, int, int);
    void (*menu_state)(int);
    struct {
        uint64_t at;
        void (*fn)(int);
        int value, used;
    } timers[MAX_TIMERS];
    /* menus */
    menu menus[MAX_MENUS];
    int cur_menu;
    int attached[3];
    int open_menu[4]; /* stack of open menus (0: none) */
    int open_depth;
    int open_x[4], open_y[4], sel[4];
    int menu_button;
    /* replay */
    fx_glut_replay rp;
    fx_input in;
    fx_input_dev kbd, mouse_dev;
    int32_t px, py; /* last pointer, window coords */
} G = {
    /* glutInitWindowSize/Position may come before glutInit (freeglut keeps
     * them), so the defaults are here and glutInit does not touch them */
    .init_x = -1, .init_y = -1, .init_w = 300, .init_h = 300,
};

void fx_glut_log(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "fixel-glut: ");
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

static uint64_t wall_us(void);
static uint64_t now_us(void)
{
    if (G.headless)
        return G.vclock_us;
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000;
}

/* ---- init ---- */
void glutInit(int *pargc, char **argv)
{
    (void)pargc, (void)argv;
    if (G.inited)
        return;
    G.inited = 1;
    fx_glut_env_read(&G.env);
    if (G.env.out)
        out_check(G.env.out); /* a FIFO or directory fails now, not at the last frame */
    if (G.env.replay)
        fx_glut_replay_load(&G.rp, G.env.replay); /* a bad line exits 5 now */
    G.t0_us = now_us();
}
void glutInitWindowPosition(int x, int y) { G.init_x = x, G.init_y = y; }
void glutInitWindowSize(int w, int h)
{
    if (w > 0 && h > 0)
        G.init_w = w, G.init_h = h;
}
void glutInitDisplayMode(unsigned int mode) { G.mode = mode; }
void glutInitDisplayString(const char *s)
{
    G.mode = 0;
    if (s && strstr(s, "double"))
        G.mode |= GLUT_DOUBLE;
    if (s && strstr(s, "depth"))
        G.mode |= GLUT_DEPTH;
}

static void place_window(int full)
{
    int32_t w = G.init_w, h = G.init_h;
    if (G.headless) {
        G.scr_w = w, G.scr_h = h;
        G.win_x = G.win_y = 0;
        return;
    }
    if (full) {
        w = G.scr_w, h = G.scr_h;
    } else if (w > G.scr_w || h > G.scr_h) {
        /* scale down, keeping the aspect */
        if ((int64_t)w * G.scr_h > (int64_t)h * G.scr_w) {
            h = (int32_t)((int64_t)h * G.scr_w / w);
            w = G.scr_w;
        } else {
            w = (int32_t)((int64_t)w * G.scr_h / h);
            h = G.scr_h;
        }
        if (w < 1) w = 1;
        if (h < 1) h = 1;
    }
    G.win_x = (G.scr_w - w) / 2, G.win_y = (G.scr_h - h) / 2;
    if (!full && G.init_x >= 0 && G.init_y >= 0 && G.init_x + w <= G.scr_w && G.init_y + h <= G.scr_h)
        G.win_x = G.init_x, G.win_y = G.init_y;
    G.init_w = w, G.init_h = h;
}

static void app_display(void *u);
static void app_reshape(void *u, int w, int h);
static void app_event_key(void *u, unsigned char k, int x, int y);
static void app_event_keyup(void *u, unsigned char k, int x, int y);
static void app_event_special(void *u, int k, int x, int y);
static void app_event_specialup(void *u, int k, int x, int y);
static void app_event_mouse(void *u, int b, int s, int x, int y);
static void app_event_motion(void *u, int x, int y);
static void app_event_passive(void *u, int x, int y);
static void app_event_wheel(void *u, int d, int x, int y);
static void app_event_touch(void *u, int id, int x, int y, int phase);
static void app_idle(void *u);
static void app_close(void *u);
static void install_app_callbacks(void);

static void close_at_exit(void)
{
    if (G.app) {
        fx_app *a = G.app;
        G.app = NULL;
        fx_app_close(a);
    }
}

int glutCreateWindow(const char *title)
{
    if (!G.inited)
        glutInit(NULL, NULL);
    if (G.created) {
        fx_glut_unimplemented("glutCreateWindow (a second window)", GL_INVALID_OPERATION);
        return 1;
    }
    snprintf(G.title, sizeof G.title, "%s", title ? title : "");
    G.headless = G.env.headless;
    if (!G.headless) {
        fx_app_options o;
        fx_app_options_init(&o);
        /* the FIXEL_* display and input variables, as every fixel program */
        if (fx_app_options_from_env(&o) < 0)
            exit(1);
        /* when no display opens, the library's log line names the memory
         * surface it falls back to: make it the window, not 640x480 */
        o.display.memory_w = G.init_w, o.display.memory_h = G.init_h;
        if (fx_app_open(&G.app, &o) < 0) {
            G.app = NULL;
            if (o.display.backend != FX_BACKEND_AUTO) {
                /* a display asked for by name that cannot open is an error,
                 * not a silent headless run (issue #20) */
                fx_glut_log("cannot open the display asked for (reason above)");
                exit(1);
            }
            G.headless = 1;
        } else {
            fx_display_info info;
            fx_display_get_info(fx_app_display(G.app), &info);
            if (info.backend == FX_BACKEND_MEMORY) {
                fx_app_close(G.app);
                G.app = NULL;
                G.headless = 1;
            } else {
                fx_app_size(G.app, &G.scr_w, &G.scr_h);
                /* Course programs end with exit() in a callback: the display
                 * must still give the console back (text mode, the CRTC). */
                static int registered;
                if (!registered && atexit(close_at_exit) == 0)
                    registered = 1;
            }
        }
    }
    place_window(G.env.fullscreen);
    if (G.had_window) {
        /* a window after glutDestroyWindow: a new GL context and buffers,
         * and none of the old window's callbacks or attached menus (idle,
         * timers and menus themselves are global in freeglut) */
        fx_memfb_destroy(&fx_gl.fb);
        free(fx_gl.depth);
        fx_gl.depth = NULL;
        G.display = NULL, G.reshape = NULL, G.keyboard = NULL, G.keyboard_up = NULL;
        G.special = NULL, G.special_up = NULL, G.mouse = NULL, G.motion = NULL;
        G.passive = NULL, G.wheel = NULL, G.visibility = NULL, G.close = NULL, G.entry = NULL;
        memset(G.attached, 0, sizeof G.attached);
    }
    if (G.headless && !G.env.out)
        /* a run with no display and no output file otherwise ends in silence
         * with status 0, looking as if it worked (issue #39) */
        fx_glut_log("%s: the %dx%d window runs headless and nothing is shown or written; "
                "FIXEL_GLUT_OUT=FILE.png writes a frame (FIXEL_GLUT_FRAMES=N: the N-th, then exit)",
                G.env.headless ? "FIXEL_BACKEND=memory" : "no display", G.init_w, G.init_h);
    if (fx_glut_gl_init(G.init_w, G.init_h) < 0) {
        fx_glut_log("out of memory for a %dx%d window", G.init_w, G.init_h);
        exit(1);
    }
    fx_input_init(&G.in, G.init_w, G.init_h, 0);
    fx_input_dev_init(&G.kbd, FX_DEV_KEYBOARD);
    fx_input_dev_init(&G.mouse_dev, FX_DEV_MOUSE);
    if (G.rp.n && !G.headless)
        fx_glut_log("FIXEL_GLUT_REPLAY drives headless runs only; ignored on a display");
    if (G.app)
        install_app_callbacks();
    G.created = 1;
    G.had_window = 1;
    return 1;
}
int fx_glut_offscreen_window(int w, int h)
{
    if (G.created || w <= 0 || h <= 0)
        return 0;
    glutInit(NULL, NULL);
    /* no frame limit, output file or replay of the environment: the caller
     * owns the loop and the pictures */
    G.env.headless = 1;
    G.env.frames = 0;
    G.env.out = NULL;
    G.env.bench = 0;
    G.env.fullscreen = 0;
    G.rp.n = 0;
    G.init_w = w, G.init_h = h;
    return glutCreateWindow("fixel offscreen");
}
int glutCreateSubWindow(int win, int x, int y, int w, int h)
{
    (void)win, (void)x, (void)y, (void)w, (void)h;
    fx_glut_unimplemented("glutCreateSubWindow", GL_INVALID_OPERATION);
    return 0;
}
/* freeglut calls a destroyed window's close callback later, where it
 * really closes windows: at the end of the main-loop iteration, at the end
 * of glutMainLoop, or at exit. */
static void run_pending_close(void)
{
    void (*f)(void) = G.close_pending;
    G.close_pending = NULL;
    if (f)
        f();
}

/* As freeglut: the window goes and the call returns; a program that
 * destroys its window outside glutMainLoop carries on (conformance-style
 * programs print their results after it). Inside the loop, the loop ends
 * once the iteration is over, since no window is left, and
 * GLUT_ACTION_ON_WINDOW_CLOSE says whether glutMainLoop exits or returns
 * (tests/glut/self/winlife.c, checked against freeglut too). */
void glutDestroyWindow(int win)
{
    if (!G.created || win != 1) {
        fx_glut_log("glutDestroyWindow(%d): no such window", win);
        return;
    }
    G.created = 0;
    G.redisplay = 0;
    G.close_pending = G.close;
    static int registered;
    if (!registered && atexit(run_pending_close) == 0)
        registered = 1;
    if (G.app) {
        if (G.in_loop) {
            fx_app_quit(G.app); /* glutMainLoop closes it */
        } else {
            fx_app *a = G.app;
            G.app = NULL;
            fx_app_close(a);
        }
    }
}
void glutSetWindow(int win) { (void)win; }
int glutGetWindow(void) { return G.created ? 1 : 0; }
void glutSetWindowTitle(const char *t) { snprintf(G.title, sizeof G.title, "%s", t ? t : ""); }
void glutSetIconTitle(const char *t) { (void)t; }
static void resize_to(int32_t w, int32_t h)
{
    fx_glut_gl_resize(w, h);
    if (G.reshape)
        G.reshape(w, h);
    else
        glViewport(0, 0, w, h);
    G.redisplay = 1;
}
void glutReshapeWindow(int w, int h)
{
    if (w <= 0 || h <= 0 || !G.created)
        return;
    G.init_w = w, G.init_h = h;
    place_window(0);
    resize_to(G.init_w, G.init_h);
}
void glutPositionWindow(int x, int y) { G.init_x = x, G.init_y = y; }
void glutFullScreen(void)
{
    if (!G.created || G.headless)
        return;
    place_window(1);
    resize_to(G.init_w, G.init_h);
}
void glutFullScreenToggle(void) { glutFullScreen(); }
void glutLeaveFullScreen(void) {}
void glutShowWindow(void) {}
void glutHideWindow(void) {}
void glutIconifyWindow(void) {}
void glutPushWindow(void) {}
void glutPopWindow(void) {}
void glutPostRedisplay(void)
{
    G.redisplay = 1;
    if (G.app)
        fx_app_post_redisplay(G.app);
}
void glutPostWindowRedisplay(int w)
{
    (void)w;
    glutPostRedisplay();
}
void glutWarpPointer(int x, int y) { G.px = x, G.py = y; }
void glutSetCursor(int c) { (void)c; }

/* ---- callbacks ---- */
void glutDisplayFunc(void (*f)(void)) { G.display = f; }
void glutReshapeFunc(void (*f)(int, int)) { G.reshape = f; }
void glutKeyboardFunc(void (*f)(unsigned char, int, int)) { G.keyboard = f; }
void glutKeyboardUpFunc(void (*f)(unsigned char, int, int)) { G.keyboard_up = f; }
void glutSpecialFunc(void (*f)(int, int, int)) { G.special = f; }
void glutSpecialUpFunc(void (*f)(int, int, int)) { G.special_up = f; }
void glutMouseFunc(void (*f)(int, int, int, int)) { G.mouse = f; }
void glutMotionFunc(void (*f)(int, int)) { G.motion = f; }
void glutPassiveMotionFunc(void (*f)(int, int)) { G.passive = f; }
void glutMouseWheelFunc(void (*f)(int, int, int, int)) { G.wheel = f; }
void glutIdleFunc(void (*f)(void))
{
    G.idle = f;
    if (G.app)
        install_app_callbacks();
}
void glutVisibilityFunc(void (*f)(int)) { G.visibility = f; }
void glutWindowStatusFunc(void (*f)(int)) { (void)f; }
void glutEntryFunc(void (*f)(int)) { G.entry = f; }
void glutCloseFunc(void (*f)(void)) { G.close = f; }
void glutWMCloseFunc(void (*f)(void)) { G.close = f; }
void glutMenuStatusFunc(void (*f)(int, int, int)) { G.menu_status = f; }
void glutMenuStateFunc(void (*f)(int)) { G.menu_state = f; }
static void timer_bridge(void *u, int i);
void glutTimerFunc(unsigned int ms, void (*f)(int), int value)
{
    for (int i = 0; i < MAX_TIMERS; i++)
        if (!G.timers[i].used) {
            G.timers[i].used = 1;
            G.timers[i].at = now_us() + (uint64_t)ms * 1000u;
            G.timers[i].fn = f;
            G.timers[i].value = value;
            if (G.app)
                fx_app_timer(G.app, ms, timer_bridge, i);
            return;
        }
    fx_glut_log("glutTimerFunc: more than %d timers pending; dropped", MAX_TIMERS);
}

int glutGetModifiers(void) { return (int)(G.mods & 7u); }

int glutGet(GLenum q)
{
    switch (q) {
    case GLUT_WINDOW_X: return G.win_x;
    case GLUT_WINDOW_Y: return G.win_y;
    case GLUT_WINDOW_WIDTH: return fx_gl.w;
    case GLUT_WINDOW_HEIGHT: return fx_gl.h;
    case GLUT_SCREEN_WIDTH: return G.created ? G.scr_w : 0;
    case GLUT_SCREEN_HEIGHT: return G.created ? G.scr_h : 0;
    case GLUT_WINDOW_DOUBLEBUFFER: return (G.mode & GLUT_DOUBLE) != 0;
    case GLUT_WINDOW_RGBA: return 1;
    case GLUT_WINDOW_DEPTH_SIZE: return (G.mode & GLUT_DEPTH) ? 24 : 0;
    case GLUT_WINDOW_RED_SIZE: case GLUT_WINDOW_GREEN_SIZE: case GLUT_WINDOW_BLUE_SIZE: return 8;
    case GLUT_WINDOW_BUFFER_SIZE: return 24;
    case GLUT_ELAPSED_TIME: return (int)((now_us() - G.t0_us) / 1000u);
    case GLUT_INIT_WINDOW_X: return G.init_x;
    case GLUT_INIT_WINDOW_Y: return G.init_y;
    case GLUT_INIT_WINDOW_WIDTH: return G.init_w;
    case GLUT_INIT_WINDOW_HEIGHT: return G.init_h;
    case GLUT_INIT_DISPLAY_MODE: return (int)G.mode;
    case GLUT_DISPLAY_MODE_POSSIBLE: return 1;
    case GLUT_INIT_STATE: return G.inited;
    case GLUT_FULL_SCREEN: return G.created && fx_gl.w == G.scr_w && fx_gl.h == G.scr_h;
    case GLUT_MENU_NUM_ITEMS: return G.cur_menu ? G.menus[G.cur_menu].n : 0;
    case GLUT_WINDOW_BORDER_WIDTH: case GLUT_WINDOW_HEADER_HEIGHT: return 0;
    case GLUT_VERSION: return 30400;
    case GLUT_ACTION_ON_WINDOW_CLOSE: return G.on_close;
    default: return 0;
    }
}
int glutDeviceGet(GLenum q)
{
    switch (q) {
    case GLUT_HAS_KEYBOARD: case GLUT_HAS_MOUSE: return 1;
    case GLUT_NUM_MOUSE_BUTTONS: return 3;
    default: return 0;
    }
}
int glutLayerGet(GLenum q)
{
    (void)q;
    return 0;
}
void glutSetOption(GLenum o, int v)
{
    if (o == GLUT_ACTION_ON_WINDOW_CLOSE && v >= GLUT_ACTION_EXIT && v <= GLUT_ACTION_CONTINUE_EXECUTION)
        G.on_close = v;
}
int glutExtensionSupported(const char *e)
{
    (void)e;
    return 0;
}
void glutIgnoreKeyRepeat(int i) { (void)i; }
void glutSetKeyRepeat(int m) { (void)m; }
void glutReportErrors(void)
{
    GLenum e;
    while ((e = glGetError()) != GL_NO_ERROR)
        fx_glut_log("GL error 0x%04x", e);
}

/* ---- menus ---- */
int glutCreateMenu(void (*cb)(int))
{
    for (int i = 1; i < MAX_MENUS; i++)
        if (!G.menus[i].used) {
            memset(&G.menus[i], 0, sizeof G.menus[i]);
            G.menus[i].used = 1;
            G.menus[i].cb = cb;
            G.cur_menu = i;
            return i;
        }
    return 0;
}
void glutDestroyMenu(int m)
{
    if (m > 0 && m < MAX_MENUS)
        G.menus[m].used = 0;
}
int glutGetMenu(void) { return G.cur_menu; }
void glutSetMenu(int m)
{
    if (m > 0 && m < MAX_MENUS && G.menus[m].used)
        G.cur_menu = m;
}
static void add_item(const char *label, int value, int sub)
{
    menu *m = &G.menus[G.cur_menu];
    if (!G.cur_menu || m->n == MAX_ITEMS)
        return;
    snprintf(m->items[m->n].label, sizeof m->items[m->n].label, "%s", label ? label : "");
    m->items[m->n].value = value;
    m->items[m->n].submenu = sub;
    m->n++;
}
void glutAddMenuEntry(const char *label, int value) { add_item(label, value, 0); }
void glutAddSubMenu(const char *label, int sub) { add_item(label, 0, sub); }
void glutChangeToMenuEntry(int item, const char *label, int value)
{
    menu *m = &G.menus[G.cur_menu];
    if (item >= 1 && item <= m->n) {
        snprintf(m->items[item - 1].label, sizeof m->items[0].label, "%s", label);
        m->items[item - 1].value = value, m->items[item - 1].submenu = 0;
    }
}
void glutChangeToSubMenu(int item, const char *label, int sub)
{
    menu *m = &G.menus[G.cur_menu];
    if (item >= 1 && item <= m->n) {
        snprintf(m->items[item - 1].label, sizeof m->items[0].label, "%s", label);
        m->items[item - 1].submenu = sub;
    }
}
void glutRemoveMenuItem(int item)
{
    menu *m = &G.menus[G.cur_menu];
    if (item >= 1 && item <= m->n) {
        memmove(&m->items[item - 1], &m->items[item], (size_t)(m->n - item) * sizeof m->items[0]);
        m->n--;
    }
}
void glutAttachMenu(int b)
{
    if (b >= 0 && b < 3)
        G.attached[b] = G.cur_menu;
}
void glutDetachMenu(int b)
{
    if (b >= 0 && b < 3)
        G.attached[b] = 0;
}
void glutSetMenuFont(int id, void *font) { (void)id, (void)font; }

/* Menu geometry: items of 16 px (scaled 2x on screens wider than 1000 px). */
#define MENU_ITEM_H 16
#define MENU_PAD 6
static int menu_width(int id)
{
    int wmax = 40;
    for (int i = 0; i < G.menus[id].n; i++) {
        int w = (int)strlen(G.menus[id].items[i].label) * 6 + 2 * MENU_PAD + 12;
        if (w > wmax)
            wmax = w;
    }
    return wmax;
}
static fx_rect menu_rect(int level)
{
    int id = G.open_menu[level];
    fx_rect r = {G.open_x[level], G.open_y[level], G.open_x[level] + menu_width(id),
                 G.open_y[level] + G.menus[id].n * MENU_ITEM_H + 4};
    return r;
}
static void open_menu(int id, int x, int y)
{
    if (G.open_depth >= 4 || !G.menus[id].used)
        return;
    int l = G.open_depth++;
    G.open_menu[l] = id;
    int w = menu_width(id), h = G.menus[id].n * MENU_ITEM_H + 4;
    if (x + w > fx_gl.w)
        x = fx_gl.w - w;
    if (y + h > fx_gl.h)
        y = fx_gl.h - h;
    G.open_x[l] = x < 0 ? 0 : x, G.open_y[l] = y < 0 ? 0 : y;
    G.sel[l] = -1;
    if (l == 0 && G.menu_state)
        G.menu_state(GLUT_MENU_IN_USE);
    if (l == 0 && G.menu_status)
        G.menu_status(GLUT_MENU_IN_USE, x, y);
    G.redisplay = 1;
}
static void close_menus(void)
{
    if (!G.open_depth)
        return;
    G.open_depth = 0;
    if (G.menu_state)
        G.menu_state(GLUT_MENU_NOT_IN_USE);
    if (G.menu_status)
        G.menu_status(GLUT_MENU_NOT_IN_USE, G.px, G.py);
    G.redisplay = 1;
}
/* The item under (x, y): sets *level, returns the item index or -1. */
static int menu_hit(int x, int y, int *level)
{
    for (int l = G.open_depth - 1; l >= 0; l--) {
        fx_rect r = menu_rect(l);
        if (x >= r.x0 && x < r.x1 && y >= r.y0 + 2 && y < r.y1 - 2) {
            *level = l;
            return (y - r.y0 - 2) / MENU_ITEM_H;
        }
    }
    return -1;
}
static void menu_select(int l, int i)
{
    menu_item *it = &G.menus[G.open_menu[l]].items[i];
    if (it->submenu) {
        G.open_depth = l + 1;
        fx_rect r = menu_rect(l);
        open_menu(it->submenu, r.x1 - 2, r.y0 + 2 + i * MENU_ITEM_H);
        return;
    }
    void (*cb)(int) = G.menus[G.open_menu[l]].cb;
    int saved = G.cur_menu, value = it->value;
    G.cur_menu = G.open_menu[l];
    close_menus();
    if (cb)
        cb(value);
    G.cur_menu = saved;
}
static void draw_menus(const fx_surface *s)
{
    fx_ctx c;
    fx_ctx_init(&c, s);
    for (int l = 0; l < G.open_depth; l++) {
        fx_rect r = menu_rect(l);
        int id = G.open_menu[l];
        fx_ctx_set_color(&c, 0xFF404040u);
        fx_fill_rect(&c, r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0);
        fx_ctx_set_color(&c, 0xFFE8E8E8u);
        fx_fill_rect(&c, r.x0 + 1, r.y0 + 1, r.x1 - r.x0 - 2, r.y1 - r.y0 - 2);
        for (int i = 0; i < G.menus[id].n; i++) {
            int y = r.y0 + 2 + i * MENU_ITEM_H;
            if (i == G.sel[l]) {
                fx_ctx_set_color(&c, 0xFF3060C0u);
                fx_fill_rect(&c, r.x0 + 2, y, r.x1 - r.x0 - 4, MENU_ITEM_H);
                fx_ctx_set_color(&c, 0xFFFFFFFFu);
            } else {
                fx_ctx_set_color(&c, 0xFF101010u);
            }
            fx_text(&c, r.x0 + MENU_PAD, y + 3, G.menus[id].items[i].label);
            if (G.menus[id].items[i].submenu)
                fx_text(&c, r.x1 - MENU_PAD - 6, y + 3, ">");
        }
    }
}

/* ---- frames ---- */
static void present(void)
{
    if (G.headless)
        return; /* nothing to show: FIXEL_GLUT_OUT writes the window's pixels */
    fx_surface s = fx_app_surface(G.app);
    fx_rect r = {G.win_x, G.win_y, G.win_x + fx_gl.w, G.win_y + fx_gl.h};
    fx_surface sub = fx_surface_sub(s, r);
    fx_blit(&sub, 0, 0, &fx_gl.fb.surf);
    if (G.open_depth)
        draw_menus(&sub);
    fx_app_present(G.app, &r, 1);
}

/* FIXEL_GLUT_OUT must be a regular file or not exist: a FIFO would block
 * the write until some reader came (and a device or directory is not an
 * image). Checked at glutInit, so a scripted run fails before it draws,
 * and again before the write. Exit 6 with the variable and the path. */
static void out_check(const char *path)
{
    char why[128];
    if (fx_check_replaceable(path, why, sizeof why) < 0 && errno != ENOENT) {
        fprintf(stderr, "fixel-glut: FIXEL_GLUT_OUT=%s: %s\n", path, why);
        exit(6);
    }
}

static void write_out(void)
{
    if (!G.env.out)
        return;
    out_check(G.env.out);
    /* the window's pixels, as glReadPixels sees them: the layer's popup
     * menus are not in them (freeglut's are windows of their own); a frame
     * that was asked for and not written fails the run */
    errno = 0;
    if (fx_write_image(G.env.out, &fx_gl.fb.surf) < 0) {
        fprintf(stderr, "fixel-glut: FIXEL_GLUT_OUT=%s: cannot write the frame%s%s\n", G.env.out,
                errno ? ": " : "", errno ? strerror(errno) : "");
        exit(6);
    }
}

void fx_glut_frame_done(int swap)
{
    if (!G.created)
        return;
    int db = (G.mode & GLUT_DOUBLE) != 0;
    if (swap != db) {
        /* glFlush in a double-buffered window shows nothing yet; glutSwapBuffers
         * in a single-buffered one is a flush */
        if (!swap)
            return;
    }
    present();
    G.frames++;
    if (G.env.bench && G.frames == 1)
        G.bench_t1 = wall_us();
    if (G.env.frames > 0 && G.frames >= G.env.frames) {
        write_out();
        if (G.env.bench) {
            double t = (double)(wall_us() - G.bench_t1) / 1e6;
            printf("fixel-glut: frames 2..%ld in %.3f s = %.2f fps\n", G.frames, t,
                   G.frames > 1 && t > 0 ? (double)(G.frames - 1) / t : 0.0);
        }
        exit(0);
    }
}

void glutSwapBuffers(void) { fx_glut_frame_done(1); }

/* ---- input (window coordinates, y down) ---- */
static void do_key(unsigned char k, int x, int y, int up)
{
    if (G.open_depth && !up) {
        /* keys drive an open menu: up/down via specials, Enter picks, Esc closes */
        if (k == 27)
            close_menus();
        else if (k == 13 || k == ' ') {
            int l = G.open_depth - 1;
            if (G.sel[l] >= 0)
                menu_select(l, G.sel[l]);
        }
        return;
    }
    if (up) {
        if (G.keyboard_up)
            G.keyboard_up(k, x, y);
    } else if (G.keyboard) {
        G.keyboard(k, x, y);
    }
}
static void do_special(int k, int x, int y, int up)
{
    if (k == FX_KEY_MENU) {
        /* not a GLUT key: the Menu key (or a GPIO button) opens the menu
         * attached to the right (else middle, else left) button at the
         * pointer, or closes an open one; the program never sees it */
        if (up)
            return;
        if (G.open_depth) {
            close_menus();
            return;
        }
        for (int b = GLUT_RIGHT_BUTTON; b >= GLUT_LEFT_BUTTON; b--)
            if (G.attached[b]) {
                open_menu(G.attached[b], x, y);
                G.menu_button = -1;
                return;
            }
        return;
    }
    if (G.open_depth && !up) {
        int l = G.open_depth - 1, n = G.menus[G.open_menu[l]].n;
        if (k == GLUT_KEY_DOWN)
            G.sel[l] = (G.sel[l] + 1) % n;
        else if (k == GLUT_KEY_UP)
            G.sel[l] = G.sel[l] <= 0 ? n - 1 : G.sel[l] - 1;
        else if (k == GLUT_KEY_RIGHT && G.sel[l] >= 0 && G.menus[G.open_menu[l]].items[G.sel[l]].submenu)
            menu_select(l, G.sel[l]);
        else if (k == GLUT_KEY_LEFT && l > 0)
            G.open_depth--;
        G.redisplay = 1;
        return;
    }
    if (up) {
        if (G.special_up)
            G.special_up(k, x, y);
    } else if (G.special) {
        G.special(k, x, y);
    }
}
static void do_mouse(int b, int s, int x, int y)
{
    G.px = x, G.py = y;
    if (G.open_depth) {
        int l, i = menu_hit(x, y, &l);
        if (s == GLUT_UP && b == G.menu_button) {
            if (i >= 0)
                menu_select(l, i);
            else if (G.open_depth && G.open_menu[0] && G.sel[0] < 0 && G.open_depth == 1) {
                /* a click that opened the menu and released on the spot keeps it open */
            }
        } else if (s == GLUT_DOWN) {
            if (i >= 0) {
                G.menu_button = b;
                G.sel[l] = i;
            } else {
                close_menus();
            }
        }
        G.redisplay = 1;
        return;
    }
    if (b < 3 && s == GLUT_DOWN && G.attached[b]) {
        G.menu_button = b;
        open_menu(G.attached[b], x, y);
        return;
    }
    if (G.mouse)
        G.mouse(b, s, x, y);
}
static void do_motion(int x, int y, int held)
{
    G.px = x, G.py = y;
    if (G.open_depth) {
        int l, i = menu_hit(x, y, &l);
        if (i >= 0 && G.sel[l] != i) {
            G.sel[l] = i;
            G.redisplay = 1;
        }
        return;
    }
    if (held && G.motion)
        G.motion(x, y);
    else if (!held && G.passive)
        G.passive(x, y);
}
static void do_wheel(int dir, int x, int y)
{
    if (G.wheel)
        G.wheel(0, dir, x, y);
    else if (G.mouse) {
        /* freeglut reports the wheel as buttons 3 (away) and 4 (towards) */
        int b = dir > 0 ? 3 : 4;
        G.mouse(b, GLUT_DOWN, x, y);
        G.mouse(b, GLUT_UP, x, y);
    }
}

/* fx_app callbacks: screen coordinates to window coordinates */
static void app_display(void *u)
{
    (void)u;
    G.redisplay = 0;
    if (G.display)
        G.display();
    if (G.open_depth)
        present(); /* menu state changed without the program drawing */
}
static void app_reshape(void *u, int w, int h)
{
    (void)u, (void)w, (void)h;
    if (G.reshape)
        G.reshape(fx_gl.w, fx_gl.h);
    else
        glViewport(0, 0, fx_gl.w, fx_gl.h);
    if (G.visibility)
        G.visibility(GLUT_VISIBLE);
}
static void sync_mods(void)
{
    /* fx_app's event carries no mods through fx_callbacks: ask nothing more */
}
static void app_event_key(void *u, unsigned char k, int x, int y)
{
    (void)u;
    sync_mods();
    G.mods = (k >= 'A' && k <= 'Z') ? GLUT_ACTIVE_SHIFT : (k < 27 && k != 8 && k != 9 && k != 13) ? GLUT_ACTIVE_CTRL : 0;
    do_key(k, x - G.win_x, y - G.win_y, 0);
    if (G.redisplay)
        glutPostRedisplay();
}
static void app_event_keyup(void *u, unsigned char k, int x, int y)
{
    (void)u;
    do_key(k, x - G.win_x, y - G.win_y, 1);
}
static void app_event_special(void *u, int k, int x, int y)
{
    (void)u;
    do_special(k, x - G.win_x, y - G.win_y, 0);
    if (G.redisplay)
        glutPostRedisplay();
}
static void app_event_specialup(void *u, int k, int x, int y)
{
    (void)u;
    do_special(k, x - G.win_x, y - G.win_y, 1);
}
static void app_event_mouse(void *u, int b, int s, int x, int y)
{
    (void)u;
    do_mouse(b, s, x - G.win_x, y - G.win_y);
    if (G.redisplay)
        glutPostRedisplay();
}
static void app_event_motion(void *u, int x, int y)
{
    (void)u;
    do_motion(x - G.win_x, y - G.win_y, 1);
    if (G.redisplay)
        glutPostRedisplay();
}
static void app_event_passive(void *u, int x, int y)
{
    (void)u;
    do_motion(x - G.win_x, y - G.win_y, 0);
    if (G.redisplay)
        glutPostRedisplay();
}
static void app_event_wheel(void *u, int d, int x, int y)
{
    (void)u;
    do_wheel(d, x - G.win_x, y - G.win_y);
}
/* Touch: one finger is the left button (fx_input makes it so). A touch
 * screen has no right button, so a second finger put down while the first
 * is held opens the menu attached to the right button (else the middle
 * one) where the first finger is; a tap on an entry then picks it, as a
 * click does. The first finger's lift picks nothing. */
static void app_event_touch(void *u, int id, int x, int y, int phase)
{
    (void)u, (void)x, (void)y;
    if (phase != FX_TOUCH_DOWN || id == 0 || G.open_depth)
        return;
    int b = G.attached[GLUT_RIGHT_BUTTON] ? GLUT_RIGHT_BUTTON
            : G.attached[GLUT_MIDDLE_BUTTON] ? GLUT_MIDDLE_BUTTON : -1;
    if (b < 0)
        return;
    open_menu(G.attached[b], G.px, G.py);
    G.menu_button = -1;
    glutPostRedisplay();
}
static void app_idle(void *u)
{
    (void)u;
    if (G.idle)
        G.idle();
}
static void app_close(void *u)
{
    (void)u;
    if (G.close && G.created)
        G.close();
    G.created = 0; /* once: glutMainLoop's end does not call it again */
}

/* ---- replay (headless input, FIXEL_GLUT_REPLAY; parsed by replay.c) ---- */
static void replay_emit(void *u, const fx_event *e)
{
    (void)u;
    G.mods = e->mods & 7u;
    switch (e->type) {
    case FX_EVENT_KEY: do_key((unsigned char)e->key, e->x, e->y, 0); break;
    case FX_EVENT_KEY_UP: do_key((unsigned char)e->key, e->x, e->y, 1); break;
    case FX_EVENT_SPECIAL: do_special(e->key, e->x, e->y, 0); break;
    case FX_EVENT_SPECIAL_UP: do_special(e->key, e->x, e->y, 1); break;
    case FX_EVENT_MOUSE: do_mouse(e->button, e->state, e->x, e->y); break;
    case FX_EVENT_MOTION: do_motion(e->x, e->y, 1); break;
    case FX_EVENT_PASSIVE: do_motion(e->x, e->y, 0); break;
    case FX_EVENT_WHEEL: do_wheel(e->value, e->x, e->y); break;
    default: break;
    }
}
/* menu BUTTON PATH: the callback of the menu holding the last entry, with
 * that menu current; nothing is opened or drawn. */
static void replay_menu(const fx_glut_replay_event *e)
{
    int id = G.attached[e->a];
    if (!id || !G.menus[id].used)
        fx_glut_replay_fail(&G.rp, e, "no menu attached to that button");
    char path[sizeof e->path];
    snprintf(path, sizeof path, "%s", e->path);
    char *save = NULL;
    for (char *lab = strtok_r(path, "/", &save); lab; lab = strtok_r(NULL, "/", &save)) {
        menu *m = &G.menus[id];
        menu_item *hit = NULL;
        for (int i = 0; i < m->n && !hit; i++)
            if (!strcmp(m->items[i].label, lab))
                hit = &m->items[i];
        if (!hit)
            fx_glut_replay_fail(&G.rp, e, "no such menu entry");
        if (hit->submenu) {
            id = hit->submenu;
            if (id <= 0 || id >= MAX_MENUS || !G.menus[id].used)
                fx_glut_replay_fail(&G.rp, e, "submenu vanished");
            continue;
        }
        if (save && *save)
            fx_glut_replay_fail(&G.rp, e, "entry is not a submenu");
        int saved = G.cur_menu;
        G.cur_menu = id;
        if (m->cb)
            m->cb(hit->value);
        G.cur_menu = saved;
        return;
    }
    fx_glut_replay_fail(&G.rp, e, "menu path ends at a submenu");
}
static void replay_deliver(const fx_glut_replay_event *e)
{
    if (e->has_xy)
        G.px = e->x, G.py = e->y;
    int x = G.px, y = G.py;
    G.mods = (unsigned)e->mods;
    switch (e->kind) {
    case FXG_EV_MOUSE: do_mouse(e->a, e->b, x, y); break;
    case FXG_EV_MOTION: do_motion(x, y, 1); break;
    case FXG_EV_PASSIVE: do_motion(x, y, 0); break;
    case FXG_EV_KEY: do_key((unsigned char)e->a, x, y, 0); break;
    case FXG_EV_KEYUP: do_key((unsigned char)e->a, x, y, 1); break;
    case FXG_EV_SPECIAL: do_special(e->a, x, y, 0); break;
    case FXG_EV_SPECIALUP: do_special(e->a, x, y, 1); break;
    case FXG_EV_WHEEL: do_wheel(e->a, x, y); break;
    case FXG_EV_MENU: replay_menu(e); break;
    case FXG_EV_EVDEV: {
        fx_raw_event ev = {0, e->type, e->code, e->b};
        G.in.px = G.px, G.in.py = G.py;
        fx_input_feed(&G.in, e->a ? &G.mouse_dev : &G.kbd, &ev, replay_emit, NULL);
        break;
    }
    default: break;
    }
    G.mods = 0;
}
/* Delivers the events due now (tagged with a frame that has ended), in file
 * order, checking the next one after each delivery; returns how many. */
static int replay_run(void)
{
    int n = 0;
    while (!G.leave && G.rp.next < G.rp.n && G.rp.ev[G.rp.next].frame <= G.frames) {
        replay_deliver(&G.rp.ev[G.rp.next++]);
        n++;
    }
    return n;
}

/* ---- the loops ---- */
static int run_timers(void)
{
    uint64_t t = now_us();
    int ran = 0;
    for (int i = 0; i < MAX_TIMERS; i++)
        if (G.timers[i].used && G.timers[i].at <= t) {
            G.timers[i].used = 0;
            G.timers[i].fn(G.timers[i].value);
            ran = 1;
        }
    return ran;
}
static uint64_t next_timer(void)
{
    uint64_t n = UINT64_MAX;
    for (int i = 0; i < MAX_TIMERS; i++)
        if (G.timers[i].used && G.timers[i].at < n)
            n = G.timers[i].at;
    return n;
}

static uint64_t wall_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000u + (uint64_t)ts.tv_nsec / 1000;
}
__attribute__((noreturn)) static void stalled(void)
{
    if (G.rp.next < G.rp.n)
        fx_glut_log("stalled at frame %ld of %ld (next replay event at frame %ld)", G.frames,
                G.env.frames, G.rp.ev[G.rp.next].frame);
    else
        fx_glut_log("stalled at frame %ld of %ld (no replay event left)", G.frames, G.env.frames);
    exit(3);
}

/* One iteration as freeglut's loop runs it: the display callback when a
 * redisplay is pending, then the replay events due, timers, the idle
 * callback. Returns 1 when anything ran. */
static int headless_iteration(int with_idle)
{
    int did = 0;
    if (G.redisplay) {
        G.redisplay = 0;
        if (G.display)
            G.display();
        else
            fx_glut_log("no display callback registered");
        did = 1;
    }
    if (!G.created)
        return did; /* glutDestroyWindow: no window left for events */
    if (replay_run())
        did = 1;
    if (G.leave || !G.created)
        return did;
    if (run_timers())
        did = 1;
    if (with_idle && G.idle && G.created) {
        G.idle();
        did = 1;
    }
    return did;
}

static void headless_loop(void)
{
    if (G.reshape)
        G.reshape(fx_gl.w, fx_gl.h);
    else
        glViewport(0, 0, fx_gl.w, fx_gl.h);
    if (G.visibility)
        G.visibility(GLUT_VISIBLE);
    G.redisplay = 1;
    long seen = G.frames;
    uint64_t since = 0;
    unsigned spins = 0;
    while (!G.leave && G.created) {
        int did = headless_iteration(1);
        run_pending_close();
        if (did || G.redisplay) {
            /* an idle callback that never ends a frame: stalled after 10 s,
             * as the Mesa shim is, when frames are wanted */
            if (G.frames != seen) {
                seen = G.frames, since = 0;
            } else if (G.env.frames > 0 && (++spins & 1023) == 0) {
                uint64_t t = wall_us();
                if (!since)
                    since = t;
                else if (t - since > 10000000u)
                    stalled();
            }
            continue;
        }
        uint64_t nt = next_timer();
        if (nt != UINT64_MAX) {
            if (nt > G.vclock_us)
                G.vclock_us = nt; /* virtual clock: straight to the next timer */
            continue;
        }
        /* nothing can happen any more */
        if (G.env.frames > 0 || G.rp.next < G.rp.n)
            stalled();
        write_out();
        exit(0);
    }
}

static void timer_bridge(void *u, int i)
{
    (void)u;
    if (i >= 0 && i < MAX_TIMERS && G.timers[i].used) {
        G.timers[i].used = 0;
        G.timers[i].fn(G.timers[i].value);
    }
}

static void install_app_callbacks(void)
{
    fx_callbacks cb;
    memset(&cb, 0, sizeof cb);
    cb.display = app_display;
    cb.reshape = app_reshape;
    cb.keyboard = app_event_key;
    cb.keyboard_up = app_event_keyup;
    cb.special = app_event_special;
    cb.special_up = app_event_specialup;
    cb.mouse = app_event_mouse;
    cb.motion = app_event_motion;
    cb.passive_motion = app_event_passive;
    cb.wheel = app_event_wheel;
    cb.touch = app_event_touch;
    cb.close = app_close;
    cb.idle = G.idle ? app_idle : NULL;
    fx_app_set_callbacks(G.app, &cb, NULL);
}

void glutMainLoop(void)
{
    if (!G.created) {
        fx_glut_log("glutMainLoop without a window");
        exit(1);
    }
    G.leave = 0;
    G.in_loop = 1;
    if (G.headless) {
        headless_loop();
    } else {
        install_app_callbacks();
        fx_app_main_loop(G.app);
        fx_app_close(G.app);
        G.app = NULL;
        /* glutDestroyWindow called it already */
        if (G.close && G.created)
            G.close();
        G.created = 0;
    }
    G.in_loop = 0;
    /* freeglut closes what is left when its loop ends, whether it then
     * exits or returns */
    run_pending_close();
    if (G.created) {
        G.created = 0;
        if (G.close)
            G.close();
    }
    /* As freeglut: the loop's end (glutLeaveMainLoop, the window closed)
     * exits the program unless GLUT_ACTION_ON_WINDOW_CLOSE says to return. */
    if (G.on_close == GLUT_ACTION_EXIT)
        exit(0);
}
void glutMainLoopEvent(void)
{
    if (G.headless && G.created)
        headless_iteration(0);
    run_pending_close();
}
void glutLeaveMainLoop(void)
{
    G.leave = 1;
    if (G.app)
        fx_app_quit(G.app);
}
void glutExit(void) { glutLeaveMainLoop(); }
