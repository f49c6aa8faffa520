/* SPDX-License-Identifier: MIT */
/* Guest program: faults (issue 14). The console must come back — text mode,
 * keyboard mode, the CRTC — when the program gets SIGHUP and when the shell
 * that started it (the session leader owning the VT) is SIGKILLed, which
 * makes the kernel hang the VT up under the program; a GPIO chip removed
 * while the program waits on its lines is reported once and survived; a
 * display that is not there fails with one clear error. SIGTERM, a crash in
 * a callback and normal exit are display.c's console-restore-* checks. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

#include "fixel/app.h"
#include "fixel/display.h"
#include "fixel/error.h"
#include "guest.h"
#include "scenes.h"

static int count(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = hay; (p = strstr(p, needle)); p += strlen(needle))
        n++;
    return n;
}

/* ---- console state -------------------------------------------------------- */

struct vt_state {
    int mode, kbmode, vtmode;
    uint32_t crtc_fb;
};

static void read_vt_state(struct vt_state *s)
{
    memset(s, 0, sizeof *s);
    s->mode = s->kbmode = s->vtmode = -1;
    /* A fresh open each time: a hung-up file would answer EIO. */
    int fd = open("/dev/tty1", O_RDWR | O_NOCTTY);
    if (fd >= 0) {
        struct vt_mode vm;
        ioctl(fd, KDGETMODE, &s->mode);
        ioctl(fd, KDGKBMODE, &s->kbmode);
        if (ioctl(fd, VT_GETMODE, &vm) == 0)
            s->vtmode = vm.mode;
        close(fd);
    }
    int dfd = open("/dev/dri/card0", O_RDWR | O_CLOEXEC);
    if (dfd >= 0) {
        drmModeResPtr res = drmModeGetResources(dfd);
        if (res && res->count_crtcs > 0) {
            drmModeCrtcPtr c = drmModeGetCrtc(dfd, res->crtcs[0]);
            if (c) {
                s->crtc_fb = c->buffer_id;
                drmModeFreeCrtc(c);
            }
        }
        drmModeFreeResources(res);
        close(dfd);
    }
}

static int same_state(const struct vt_state *a, const struct vt_state *b)
{
    return a->mode == b->mode && a->kbmode == b->kbmode && a->vtmode == b->vtmode && a->crtc_fb == b->crtc_fb;
}

/* The program: DRM with the console, a picture, "r" on ready, then wait.
 * quit_fd readable (or closed) means close the display and exit 0. */
static void program(int ready_fd, int quit_fd)
{
    fx_display *d;
    fx_display_options o;
    fx_display_options_init(&o);
    fx_display_options_from_env(&o); /* the variables the rig sets, as the tools do */
    o.backend = FX_BACKEND_DRM;
    o.log = capture_log;
    o.log_priority = FX_LOG_DEBUG;
    if (fx_display_open(&d, &o) < 0)
        _exit(2);
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    if (write(ready_fd, "r", 1) != 1)
        _exit(4);
    char c;
    while (read(quit_fd, &c, 1) < 0 && errno == EINTR)
        ;
    fx_display_close(d);
    fflush(stdout);
    _exit(0);
}

static int wait_ready(int fd)
{
    char c;
    return read(fd, &c, 1) == 1;
}

static void describe(char *out, size_t n, int st)
{
    if (WIFSIGNALED(st))
        snprintf(out, n, "signal %d", WTERMSIG(st));
    else
        snprintf(out, n, "exit %d", WEXITSTATUS(st));
}

/* SIGHUP straight to the program (a terminal closed, a supervisor's reload). */
static void sighup_case(const struct vt_state *before)
{
    int rp[2], qp[2];
    if (pipe(rp) < 0 || pipe(qp) < 0)
        return;
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        close(rp[0]);
        close(qp[1]);
        program(rp[1], qp[0]);
    }
    close(rp[1]);
    close(qp[0]);
    int ready = wait_ready(rp[0]);
    struct vt_state during, after;
    read_vt_state(&during);
    kill(pid, SIGHUP);
    int st = 0;
    waitpid(pid, &st, 0);
    close(rp[0]);
    close(qp[1]);
    read_vt_state(&after);
    char how[32];
    describe(how, sizeof how, st);
    guest_check("console-restore-sighup",
                ready && during.mode == KD_GRAPHICS && WIFSIGNALED(st) && WTERMSIG(st) == SIGHUP &&
                    same_state(before, &after),
                "%s; mode %d->%d->%d kbmode %d->%d->%d crtc fb %u->%u->%u", how, before->mode, during.mode,
                after.mode, before->kbmode, during.kbmode, after.kbmode, before->crtc_fb, during.crtc_fb,
                after.crtc_fb);
}

/* A shell on tty1 (session leader, tty1 its controlling terminal) starts the
 * program and is SIGKILLed. The kernel hangs tty1 up: the program's VT file
 * answers EIO from then on, and the program gets SIGHUP as a member of the
 * terminal's foreground group (if it survives that, it is asked to quit).
 * The console must be back when it is gone. */
static void parent_killed_case(const struct vt_state *before)
{
    const char *name = "console-restore-parent-killed";
    int rp[2], qp[2], pp[2];
    if (pipe(rp) < 0 || pipe(qp) < 0 || pipe(pp) < 0)
        return;
    fflush(stdout);
    pid_t shell = fork();
    if (shell == 0) {
        setsid();
        int tty = open("/dev/tty1", O_RDWR);
        if (tty < 0 || ioctl(tty, TIOCSCTTY, 1) < 0)
            _exit(5);
        pid_t prog = fork();
        if (prog == 0) {
            close(rp[0]);
            close(qp[1]);
            close(tty);
            program(rp[1], qp[0]);
        }
        if (write(pp[1], &prog, sizeof prog) != sizeof prog)
            _exit(6);
        for (;;)
            pause();
    }
    close(rp[1]);
    close(qp[0]);
    close(pp[1]);
    pid_t prog = -1;
    int got = read(pp[0], &prog, sizeof prog) == sizeof prog;
    close(pp[0]);
    int ready = got && wait_ready(rp[0]);
    struct vt_state during;
    read_vt_state(&during);
    kill(shell, SIGKILL);
    waitpid(shell, NULL, 0);
    msleep(300);
    /* The program is not our child: kill 0 tells whether it lives. */
    int alive = prog > 0 && kill(prog, 0) == 0;
    if (alive && write(qp[1], "q", 1) != 1)
        printf("  quit pipe: %s\n", strerror(errno));
    /* Reparented to init (pid 1, our /init shell), so poll for its end. */
    int gone = 0;
    for (int t = 0; t < 300 && !gone; t++) {
        gone = prog > 0 && kill(prog, 0) < 0 && errno == ESRCH;
        if (!gone)
            msleep(10);
    }
    close(rp[0]);
    close(qp[1]);
    struct vt_state after;
    read_vt_state(&after);
    guest_check(name,
                ready && gone && during.mode == KD_GRAPHICS && during.kbmode == K_OFF &&
                    same_state(before, &after),
                "program %s after the shell's SIGKILL, %s; mode %d->%d->%d kbmode %d->%d->%d "
                "vt mode %d->%d crtc fb %u->%u->%u",
                alive ? "alive (then asked to quit)" : "ended by the hangup", gone ? "gone" : "still running",
                before->mode, during.mode, after.mode, before->kbmode, during.kbmode, after.kbmode,
                before->vtmode, after.vtmode, before->crtc_fb, during.crtc_fb, after.crtc_fb);
    if (!gone && prog > 0)
        kill(prog, SIGKILL);
}

/* ---- GPIO chip removed at run time ------------------------------------- */

#define SIM "/sys/kernel/config/gpio-sim/fxfault"

struct gpio_run {
    fx_app *app;
    int inputs_before, inputs_after;
    int ticks_after;     /* timer ticks seen after the removal */
    int removed;
    int errors_at_removal;
};

static void gpio_tick(void *user, int k)
{
    struct gpio_run *g = user;
    if (k == 2) {
        g->inputs_before = fx_app_input_count(g->app);
        g->errors_at_removal = log_errors;
        g->removed = write_file(SIM "/live", "0") == 0;
        printf("  gpio-sim chip %s\n", g->removed ? "removed" : "could not be removed");
    } else if (k > 2 && k < 12) {
        g->ticks_after++;
    } else if (k == 12) {
        g->inputs_after = fx_app_input_count(g->app);
        fx_app_quit(g->app);
    }
}

static void gpio_vanish_case(void)
{
    char chip[64] = "", p[128];
    mkdir(SIM, 0755);
    mkdir(SIM "/bank0", 0755);
    write_file(SIM "/bank0/num_lines", "2");
    if (write_file(SIM "/live", "1") < 0 || read_line(SIM "/bank0/chip_name", chip, sizeof chip) < 0 || !chip[0]) {
        guest_check("gpio-chip-vanished", 0, "could not create a gpio-sim chip");
        return;
    }
    fx_gpio_button b[2] = {{chip, 0, NULL, 0, 20, 'a', 0}, {chip, 1, NULL, 0, 20, 'b', 0}};
    fx_app_options o;
    fx_app_options_init(&o);
    fx_app_options_from_env(&o); /* FIXEL_POINTER=off from init.sh, as the tools do */
    o.display.backend = FX_BACKEND_MEMORY;
    o.display.console = 0;
    o.display.log = capture_log;
    o.display.log_priority = FX_LOG_DEBUG;
    o.input = 0;
    o.buttons = b;
    o.nbuttons = 2;
    logbuf[0] = 0;
    log_errors = 0;
    struct gpio_run g;
    memset(&g, 0, sizeof g);
    int r = fx_app_open(&g.app, &o);
    if (r < 0) {
        guest_check("gpio-chip-vanished", 0, "app open: %s", fx_strerror(r));
    } else {
        fx_callbacks cb;
        memset(&cb, 0, sizeof cb);
        fx_app_set_callbacks(g.app, &cb, &g); /* timers get the callbacks' user pointer */
        for (int k = 0; k <= 12; k++)
            fx_app_timer(g.app, (unsigned)(50 + k * 50), gpio_tick, k);
        fx_app_main_loop(g.app);
        fx_app_close(g.app);
        int msgs = count(logbuf, "vanished");
        int errs = log_errors - g.errors_at_removal;
        /* One message for the chip, though both its lines report in. */
        guest_check("gpio-chip-vanished",
                    g.removed && g.inputs_before == 2 && g.inputs_after == 0 && g.ticks_after == 9 &&
                        msgs == 1 && errs == 1,
                    "chip %s removed %d; inputs %d -> %d; loop ticks after removal %d/9; "
                    "'vanished' messages %d (want 1), errors after removal %d",
                    chip, g.removed, g.inputs_before, g.inputs_after, g.ticks_after, msgs, errs);
    }
    write_file(SIM "/live", "0");
    rmdir(SIM "/bank0");
    rmdir(SIM);
    (void)p;
}

/* ---- no display ------------------------------------------------------- */

static void missing_display_case(void)
{
    static const struct {
        const char *name, *env, *value;
        fx_backend backend;
    } cases[] = {
        {"missing-display-drm", "FIXEL_DRM_DEVICE", "/dev/dri/card9", FX_BACKEND_DRM},
        {"missing-display-fbdev", "FIXEL_FB_DEVICE", "/dev/fb9", FX_BACKEND_FBDEV},
    };
    for (int i = 0; i < 2; i++) {
        setenv(cases[i].env, cases[i].value, 1);
        fx_display *d = NULL;
        fx_display_options o;
        fx_display_options_init(&o);
        fx_display_options_from_env(&o); /* the variables the rig sets, as the tools do */
        o.backend = cases[i].backend;
        o.log = capture_log;
        o.log_priority = FX_LOG_INFO; /* what a user sees by default */
        logbuf[0] = 0;
        log_errors = 0;
        int r = fx_display_open(&d, &o);
        unsetenv(cases[i].env);
        int named = strstr(logbuf, cases[i].value) != NULL && strstr(logbuf, "no ") != NULL;
        guest_check(cases[i].name, r < 0 && !d && log_errors == 1 && named,
                    "open returned %d (%s), %d error line(s)%s", r, r < 0 ? fx_strerror(r) : "ok", log_errors,
                    named ? ", naming the device" : ", device not named");
        if (d)
            fx_display_close(d);
    }
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    struct vt_state before;
    read_vt_state(&before);
    printf("  console before: mode %d kbmode %d vt mode %d crtc fb %u\n", before.mode, before.kbmode,
           before.vtmode, before.crtc_fb);
    sighup_case(&before);
    signal(SIGPIPE, SIG_IGN);
    parent_killed_case(&before);
    /* The hangup ended /init's reader of tty1 (the stand-in shell): start
     * another so later programs still see what reaches the console. */
    system("cat /dev/tty1 >> /tmp/tty1.log 2>/dev/null &");
    gpio_vanish_case();
    missing_display_case();
    return guest_failed;
}
