/* SPDX-License-Identifier: MIT */
/* LD_PRELOAD shim that makes an unchanged freeglut + Mesa program behave like
 * fixel's GLUT layer headless:
 *   FIXEL_GLUT_FRAMES=N   end the program after its N-th frame
 *   FIXEL_GLUT_OUT=F.png  write that frame (glReadPixels) as an RGB PNG
 *   FIXEL_GLUT_REPLAY=F   feed the program's callbacks from a replay file
 *   FIXEL_GLUT_BENCH=1    print the time from the end of frame 1 to frame N
 * A frame is glFlush/glFinish/glutSwapBuffers in a GLUT_SINGLE window and
 * glutSwapBuffers in a GLUT_DOUBLE one, except inside a display callback the
 * program did not ask for (X's own redraws: see shim_display) (tests/glut/
 * README.md has the rules and the replay format; the fixel side implements
 * the same).
 *
 * The interposed GLUT entry points forward to freeglut (dlsym RTLD_NEXT) and
 * remember the callbacks; replayed events are delivered from an idle function
 * the shim installs, i.e. between main-loop iterations after the display work
 * and before the program's own idle callback. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <GL/freeglut.h>

#define REAL(name) static __typeof__(name) *real_##name; \
    if (!real_##name) real_##name = (__typeof__(name) *)must_sym(#name)

static void *must_sym(const char *n)
{
    void *p = dlsym(RTLD_NEXT, n);
    if (!p) { fprintf(stderr, "glut-shim: no symbol %s\n", n); _exit(4); }
    return p;
}

static long frames_wanted;      /* 0: never stop */
static long frames_done;
static const char *out_path;
static int bench;
static double t_frame1;
static unsigned display_mode = GLUT_RGB | GLUT_SINGLE;
static int in_swap;             /* freeglut's glutSwapBuffers calls glFlush */
static int started;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* ---- callbacks the program registered ---- */
static void (*cb_mouse)(int, int, int, int);
static void (*cb_motion)(int, int);
static void (*cb_passive)(int, int);
static void (*cb_key)(unsigned char, int, int);
static void (*cb_keyup)(unsigned char, int, int);
static void (*cb_special)(int, int, int);
static void (*cb_specialup)(int, int, int);
static void (*cb_idle)(void);
static void (*cb_wheel)(int, int, int, int);

/* ---- menus ---- */
#define MAXMENU 64
#define MAXENTRY 64
struct entry { char label[96]; int value; int submenu; };
struct menu { int id; void (*cb)(int); int n; struct entry e[MAXENTRY]; };
static struct menu menus[MAXMENU];
static int nmenus, cur_menu = -1;
static int attached[3] = { -1, -1, -1 };   /* menu index per button */

static struct menu *menu_by_id(int id)
{
    for (int i = 0; i < nmenus; i++)
        if (menus[i].id == id) return &menus[i];
    return NULL;
}

/* ---- replay ---- */
enum { EV_MOUSE, EV_MOTION, EV_PASSIVE, EV_KEY, EV_KEYUP, EV_SPECIAL, EV_SPECIALUP, EV_MENU, EV_WHEEL };
struct event {
    long frame; int kind, a, b, x, y, mods, has_xy; char path[192]; int line;
};
static struct event *evs;
static int nev, next_ev;
static int last_x, last_y;
static int cur_mods = -1;       /* >= 0 while a replayed input callback runs */

static void die(const char *why, int line)
{
    fprintf(stderr, "glut-shim: replay line %d: %s\n", line, why);
    exit(5);
}

static int parse_key(const char *t, int line)
{
    static const struct { const char *n; int c; } names[] = {
        { "space", ' ' }, { "enter", 13 }, { "escape", 27 }, { "esc", 27 }, { "tab", 9 },
        { "backspace", 8 }, { "delete", 127 } };
    if (t[0] && !t[1]) return (unsigned char)t[0];
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(t, names[i].n)) return names[i].c;
    if (t[0] == '0' && t[1] == 'x') return (int)strtol(t, NULL, 16) & 255;
    die("unknown key name", line);
    return 0;
}

static int parse_special(const char *t, int line)
{
    static const struct { const char *n; int c; } names[] = {
        { "left", GLUT_KEY_LEFT }, { "right", GLUT_KEY_RIGHT }, { "up", GLUT_KEY_UP },
        { "down", GLUT_KEY_DOWN }, { "page_up", GLUT_KEY_PAGE_UP },
        { "page_down", GLUT_KEY_PAGE_DOWN }, { "home", GLUT_KEY_HOME }, { "end", GLUT_KEY_END },
        { "insert", GLUT_KEY_INSERT } };
    for (unsigned i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(t, names[i].n)) return names[i].c;
    if (t[0] == 'f' && t[1]) {
        int n = atoi(t + 1);
        if (n >= 1 && n <= 12) return GLUT_KEY_F1 + n - 1;
    }
    die("unknown special key", line);
    return 0;
}

static int parse_button(const char *t, int line)
{
    if (!strcmp(t, "left")) return GLUT_LEFT_BUTTON;
    if (!strcmp(t, "middle")) return GLUT_MIDDLE_BUTTON;
    if (!strcmp(t, "right")) return GLUT_RIGHT_BUTTON;
    die("button must be left, middle or right", line);
    return 0;
}

static int parse_mods(const char *t, int line)
{
    int m = 0;
    char buf[64];
    snprintf(buf, sizeof buf, "%s", t);
    for (char *s = strtok(buf, ","); s; s = strtok(NULL, ",")) {
        if (!strcmp(s, "shift")) m |= GLUT_ACTIVE_SHIFT;
        else if (!strcmp(s, "ctrl")) m |= GLUT_ACTIVE_CTRL;
        else if (!strcmp(s, "alt")) m |= GLUT_ACTIVE_ALT;
        else die("mods= takes shift, ctrl, alt", line);
    }
    return m;
}

static void load_replay(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "glut-shim: %s: %s\n", path, strerror(errno)); exit(5); }
    char buf[512];
    int line = 0, cap = 0;
    long last_frame = 0;
    while (fgets(buf, sizeof buf, f)) {
        line++;
        char *s = buf;
        char *hash = strchr(s, '#');
        if (hash) *hash = 0;
        while (*s == ' ' || *s == '\t') s++;
        size_t L = strlen(s);
        while (L && (s[L - 1] == '\n' || s[L - 1] == '\r' || s[L - 1] == ' ' || s[L - 1] == '\t')) s[--L] = 0;
        if (!*s) continue;
        struct event e;
        memset(&e, 0, sizeof e);
        e.line = line;
        int n = 0;
        if (sscanf(s, "frame %ld: %n", &e.frame, &n) != 1 || n == 0) die("expected 'frame N: ...'", line);
        if (e.frame < 1) die("frame numbers start at 1", line);
        if (e.frame < last_frame) die("frame numbers must not decrease", line);
        last_frame = e.frame;
        s += n;
        char *tok[8];
        int nt = 0;
        if (!strncmp(s, "menu ", 5)) {          /* menu BUTTON LABEL[/LABEL...] */
            char btn[16];
            int m = 0;
            if (sscanf(s + 5, "%15s %n", btn, &m) != 1 || !s[5 + m]) die("menu BUTTON LABEL/...", line);
            e.kind = EV_MENU;
            e.a = parse_button(btn, line);
            snprintf(e.path, sizeof e.path, "%s", s + 5 + m);
        } else {
            for (char *t = strtok(s, " \t"); t && nt < 8; t = strtok(NULL, " \t")) tok[nt++] = t;
            e.mods = 0;
            if (nt > 1 && !strncmp(tok[nt - 1], "mods=", 5)) e.mods = parse_mods(tok[--nt] + 5, line);
            const char *k = tok[0];
            int need_xy = 0, args = 0;
            if (!strcmp(k, "mouse")) {
                if (nt != 5) die("mouse BUTTON down|up X Y", line);
                e.kind = EV_MOUSE; e.a = parse_button(tok[1], line);
                if (!strcmp(tok[2], "down")) e.b = GLUT_DOWN;
                else if (!strcmp(tok[2], "up")) e.b = GLUT_UP;
                else die("mouse BUTTON down|up X Y", line);
                args = 3; need_xy = 1;
            } else if (!strcmp(k, "motion") || !strcmp(k, "passive")) {
                if (nt != 3) die("motion|passive X Y", line);
                e.kind = k[0] == 'm' ? EV_MOTION : EV_PASSIVE;
                args = 1; need_xy = 1;
            } else if (!strcmp(k, "key") || !strcmp(k, "keyup")) {
                if (nt != 2 && nt != 4) die("key|keyup KEY [X Y]", line);
                e.kind = k[3] ? EV_KEYUP : EV_KEY; e.a = parse_key(tok[1], line);
                args = 2;
            } else if (!strcmp(k, "special") || !strcmp(k, "specialup")) {
                if (nt != 2 && nt != 4) die("special|specialup NAME [X Y]", line);
                e.kind = k[7] ? EV_SPECIALUP : EV_SPECIAL; e.a = parse_special(tok[1], line);
                args = 2;
            } else if (!strcmp(k, "wheel")) {    /* wheel up|down [X Y] */
                if (nt != 2 && nt != 4) die("wheel up|down [X Y]", line);
                e.kind = EV_WHEEL;
                if (!strcmp(tok[1], "up")) e.a = 1;
                else if (!strcmp(tok[1], "down")) e.a = -1;
                else die("wheel up|down [X Y]", line);
                args = 2;
            } else die("unknown event (mouse, motion, passive, key, keyup, special, specialup, menu, wheel)", line);
            if (nt == args + 2) {
                e.x = atoi(tok[args]); e.y = atoi(tok[args + 1]); e.has_xy = 1;
            } else if (need_xy) die("missing X Y", line);
        }
        if (nev == cap) {
            cap = cap ? cap * 2 : 64;
            evs = realloc(evs, (size_t)cap * sizeof *evs);
            if (!evs) die("out of memory", line);
        }
        evs[nev++] = e;
    }
    fclose(f);
}

static void deliver_menu(const struct event *e)
{
    int mi = attached[e->a == GLUT_LEFT_BUTTON ? 0 : e->a == GLUT_MIDDLE_BUTTON ? 1 : 2];
    if (mi < 0) die("no menu attached to that button", e->line);
    struct menu *m = &menus[mi];
    char path[192];
    snprintf(path, sizeof path, "%s", e->path);
    char *save = NULL;
    for (char *lab = strtok_r(path, "/", &save); lab; lab = strtok_r(NULL, "/", &save)) {
        struct entry *hit = NULL;
        for (int i = 0; i < m->n; i++)
            if (!strcmp(m->e[i].label, lab)) { hit = &m->e[i]; break; }
        if (!hit) die("no such menu entry", e->line);
        if (hit->submenu) {
            m = menu_by_id(hit->submenu);
            if (!m) die("submenu vanished", e->line);
            continue;
        }
        if (save && *save) die("entry is not a submenu", e->line);
        REAL(glutSetMenu);
        real_glutSetMenu(m->id);
        if (m->cb) m->cb(hit->value);
        return;
    }
    die("menu path ends at a submenu", e->line);
}

static void deliver(const struct event *e)
{
    if (e->has_xy) { last_x = e->x; last_y = e->y; }
    cur_mods = e->mods;
    switch (e->kind) {
    case EV_MOUSE:   /* a button with a menu attached goes to the menu, as in GLUT */
        if (cb_mouse && attached[e->a == GLUT_LEFT_BUTTON ? 0 : e->a == GLUT_MIDDLE_BUTTON ? 1 : 2] < 0)
            cb_mouse(e->a, e->b, last_x, last_y);
        break;
    case EV_MOTION: if (cb_motion) cb_motion(last_x, last_y); break;
    case EV_PASSIVE: if (cb_passive) cb_passive(last_x, last_y); break;
    case EV_KEY: if (cb_key) cb_key((unsigned char)e->a, last_x, last_y); break;
    case EV_KEYUP: if (cb_keyup) cb_keyup((unsigned char)e->a, last_x, last_y); break;
    case EV_SPECIAL: if (cb_special) cb_special(e->a, last_x, last_y); break;
    case EV_SPECIALUP: if (cb_specialup) cb_specialup(e->a, last_x, last_y); break;
    case EV_MENU: cur_mods = -1; deliver_menu(e); break;
    case EV_WHEEL:   /* freeglut: the wheel callback, else buttons 3 (up) / 4 (down) */
        if (cb_wheel) cb_wheel(0, e->a, last_x, last_y);
        else if (cb_mouse) {
            cb_mouse(e->a > 0 ? 3 : 4, GLUT_DOWN, last_x, last_y);
            cb_mouse(e->a > 0 ? 3 : 4, GLUT_UP, last_x, last_y);
        }
        break;
    }
    cur_mods = -1;
}

/* ---- frame capture ---- */
static void write_png(const char *path, int w, int h, const unsigned char *rgba)
{
    FILE *f = fopen(path, "wb");
    if (!f) { fprintf(stderr, "glut-shim: %s: %s\n", path, strerror(errno)); exit(6); }
    png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(p);
    if (setjmp(png_jmpbuf(p))) { fprintf(stderr, "glut-shim: png write failed\n"); exit(6); }
    png_init_io(p, f);
    png_set_IHDR(p, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(p, info);
    unsigned char *row = malloc((size_t)w * 3);
    for (int y = 0; y < h; y++) {              /* GL rows go bottom-up */
        const unsigned char *src = rgba + (size_t)(h - 1 - y) * (size_t)w * 4;
        for (int x = 0; x < w; x++) memcpy(row + x * 3, src + x * 4, 3);
        png_write_row(p, row);
    }
    free(row);
    png_write_end(p, info);
    png_destroy_write_struct(&p, &info);
    fclose(f);
}

static void capture(int back)
{
    REAL(glutGet);
    int w = real_glutGet(GLUT_WINDOW_WIDTH), h = real_glutGet(GLUT_WINDOW_HEIGHT);
    unsigned char *px = malloc((size_t)w * (size_t)h * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glReadBuffer(back ? GL_BACK : GL_FRONT);
    REAL(glFinish);
    real_glFinish();
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    write_png(out_path, w, h, px);
    free(px);
}

/* Only the program's frames count: the first display and those it asked
 * for with glutPostRedisplay. X also makes freeglut redraw on its own (an
 * Expose or ConfigureNotify that arrives after the first frame, as it does
 * on a loaded machine), and counting that redraw moved every later frame
 * number, so a replay's "frame 2:" events came before the timer frame they
 * were written after. fixel's memory window has no such redraws. A flush
 * outside any display callback (drawing from a mouse callback) counts. */
#define MAXWIN 64 /* per window: freeglut's menus are windows with display functions of their own */
static void (*cb_display[MAXWIN])(void);
static int asked = 1, in_display, display_counts;

static void shim_display(void)
{
    REAL(glutGetWindow);
    int w = real_glutGetWindow();
    display_counts = asked;
    asked = 0;
    in_display = 1;
    if (w >= 0 && w < MAXWIN && cb_display[w]) cb_display[w]();
    in_display = 0;
}

static void frame_end(int back)
{
    if (in_display && !display_counts) return;
    frames_done++;
    if (bench && frames_done == 1) t_frame1 = now();
    if (frames_wanted && frames_done == frames_wanted) {
        if (out_path) capture(back);
        if (bench) {
            REAL(glFinish);
            real_glFinish();
            double t = now() - t_frame1;
            printf("glut-shim: frames 2..%ld in %.3f s = %.2f fps\n", frames_done, t,
                   frames_done > 1 && t > 0 ? (double)(frames_done - 1) / t : 0.0);
        }
        fflush(stdout);
        exit(0);
    }
}

/* ---- the shim's idle function: replay, then the program's idle ---- */
static double stall_since;
static long stall_frames = -1;

static void shim_idle(void)
{
    int delivered = 0;
    while (next_ev < nev && evs[next_ev].frame <= frames_done) {
        deliver(&evs[next_ev++]);
        delivered = 1;
    }
    if (cb_idle) { cb_idle(); return; }
    if (!delivered) usleep(1000);
    if (frames_done != stall_frames) { stall_frames = frames_done; stall_since = now(); }
    else if (frames_wanted && now() - stall_since > 10.0) {
        fprintf(stderr, "glut-shim: stalled at frame %ld of %ld (next replay event at frame %ld)\n",
                frames_done, frames_wanted, next_ev < nev ? evs[next_ev].frame : -1L);
        exit(3);
    }
}

/* ---- interposed entry points ---- */
void glutInitDisplayMode(unsigned int mode)
{
    REAL(glutInitDisplayMode);
    display_mode = mode;
    real_glutInitDisplayMode(mode);
}

void glFlush(void)
{
    REAL(glFlush);
    real_glFlush();
    if (!in_swap && !(display_mode & GLUT_DOUBLE)) frame_end(0);
}

void glFinish(void)
{
    REAL(glFinish);
    real_glFinish();
    if (!in_swap && !(display_mode & GLUT_DOUBLE)) frame_end(0);
}

void glutSwapBuffers(void)
{
    REAL(glutSwapBuffers);
    if (display_mode & GLUT_DOUBLE) {
        frame_end(1);          /* reads the back buffer before it is swapped */
        in_swap = 1;
        real_glutSwapBuffers();
        in_swap = 0;
    } else {
        in_swap = 1;
        real_glutSwapBuffers();
        in_swap = 0;
        frame_end(0);
    }
}

/* freeglut leaves a window without glutInitWindowPosition at (-1,-1), one
 * pixel off the Xvfb screen; softpipe reads a single-buffered window's front
 * buffer with XGetImage, which then fails with BadMatch and the program dies.
 * Such windows go to (0,0) instead: nothing in the frame changes. */
static int position_set;

void glutInitWindowPosition(int x, int y)
{
    REAL(glutInitWindowPosition);
    position_set = x >= 0 && y >= 0;
    real_glutInitWindowPosition(x, y);
}

int glutCreateWindow(const char *title)
{
    REAL(glutCreateWindow);
    REAL(glutInitWindowPosition);
    if (!position_set) real_glutInitWindowPosition(0, 0);
    return real_glutCreateWindow(title);
}

void glutMouseFunc(void (*f)(int, int, int, int)) { REAL(glutMouseFunc); cb_mouse = f; real_glutMouseFunc(f); }
void glutMotionFunc(void (*f)(int, int)) { REAL(glutMotionFunc); cb_motion = f; real_glutMotionFunc(f); }
void glutPassiveMotionFunc(void (*f)(int, int)) { REAL(glutPassiveMotionFunc); cb_passive = f; real_glutPassiveMotionFunc(f); }
void glutKeyboardFunc(void (*f)(unsigned char, int, int)) { REAL(glutKeyboardFunc); cb_key = f; real_glutKeyboardFunc(f); }
void glutKeyboardUpFunc(void (*f)(unsigned char, int, int)) { REAL(glutKeyboardUpFunc); cb_keyup = f; real_glutKeyboardUpFunc(f); }
void glutSpecialFunc(void (*f)(int, int, int)) { REAL(glutSpecialFunc); cb_special = f; real_glutSpecialFunc(f); }
void glutMouseWheelFunc(void (*f)(int, int, int, int)) { REAL(glutMouseWheelFunc); cb_wheel = f; real_glutMouseWheelFunc(f); }
void glutSpecialUpFunc(void (*f)(int, int, int)) { REAL(glutSpecialUpFunc); cb_specialup = f; real_glutSpecialUpFunc(f); }

void glutDisplayFunc(void (*f)(void))
{
    REAL(glutDisplayFunc);
    REAL(glutGetWindow);
    int w = real_glutGetWindow();
    if (w < 0 || w >= MAXWIN) { real_glutDisplayFunc(f); return; } /* not counted apart: as before */
    cb_display[w] = f;
    real_glutDisplayFunc(f ? shim_display : NULL);
}

void glutPostRedisplay(void)
{
    REAL(glutPostRedisplay);
    asked = 1;
    real_glutPostRedisplay();
}

void glutIdleFunc(void (*f)(void))
{
    REAL(glutIdleFunc);
    cb_idle = f;
    if (!started) real_glutIdleFunc(f);   /* before the loop runs: plain; then shim_idle owns it */
}

int glutGetModifiers(void)
{
    REAL(glutGetModifiers);
    return cur_mods >= 0 ? cur_mods : real_glutGetModifiers();
}

int glutCreateMenu(void (*cb)(int))
{
    REAL(glutCreateMenu);
    int id = real_glutCreateMenu(cb);
    if (nmenus < MAXMENU) {
        menus[nmenus].id = id; menus[nmenus].cb = cb; menus[nmenus].n = 0;
        cur_menu = nmenus++;
    }
    return id;
}

void glutSetMenu(int id)
{
    REAL(glutSetMenu);
    real_glutSetMenu(id);
    for (int i = 0; i < nmenus; i++) if (menus[i].id == id) cur_menu = i;
}

static void add_entry(const char *label, int value, int submenu)
{
    if (cur_menu < 0) return;
    struct menu *m = &menus[cur_menu];
    if (m->n >= MAXENTRY) return;
    snprintf(m->e[m->n].label, sizeof m->e[m->n].label, "%s", label);
    m->e[m->n].value = value;
    m->e[m->n].submenu = submenu;
    m->n++;
}

void glutAddMenuEntry(const char *label, int value)
{
    REAL(glutAddMenuEntry);
    add_entry(label, value, 0);
    real_glutAddMenuEntry(label, value);
}

void glutAddSubMenu(const char *label, int submenu)
{
    REAL(glutAddSubMenu);
    add_entry(label, 0, submenu);
    real_glutAddSubMenu(label, submenu);
}

void glutChangeToMenuEntry(int item, const char *label, int value)
{
    REAL(glutChangeToMenuEntry);
    if (cur_menu >= 0 && item >= 1 && item <= menus[cur_menu].n) {
        struct entry *e = &menus[cur_menu].e[item - 1];
        snprintf(e->label, sizeof e->label, "%s", label);
        e->value = value; e->submenu = 0;
    }
    real_glutChangeToMenuEntry(item, label, value);
}

void glutAttachMenu(int button)
{
    REAL(glutAttachMenu);
    if (button >= 0 && button < 3) attached[button] = cur_menu;
    real_glutAttachMenu(button);
}

__attribute__((constructor)) static void shim_init(void)
{
    const char *s = getenv("FIXEL_GLUT_FRAMES");
    frames_wanted = s ? atol(s) : 0;
    out_path = getenv("FIXEL_GLUT_OUT");
    if (out_path && !*out_path) out_path = NULL;
    bench = getenv("FIXEL_GLUT_BENCH") && atoi(getenv("FIXEL_GLUT_BENCH"));
    const char *r = getenv("FIXEL_GLUT_REPLAY");
    if (r && *r) load_replay(r);
}

void glutMainLoop(void)
{
    REAL(glutMainLoop);
    REAL(glutIdleFunc);
    started = 1;
    real_glutIdleFunc(shim_idle);
    real_glutMainLoop();
}
