/* SPDX-License-Identifier: MIT */
/* The console: put the active VT into graphics mode (the text console and
 * its cursor stop drawing over the picture) and switch its keyboard off
 * (keystrokes never reach the shell underneath), and put both back however
 * the program ends: close, SIGINT/SIGTERM/SIGHUP, or a fatal signal, where
 * only async-signal-safe calls (ioctl, sigaction, raise) are used. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <termios.h>
#include <unistd.h>

#include "console_int.h"
#include "fixel/error.h"

struct fx_vt {
    int fd;
    char path[16];  /* /dev/ttyN, reopened when fd was hung up */
    int num;        /* N of /dev/ttyN */
    int old_mode;   /* KD_TEXT or KD_GRAPHICS as found */
    int old_kbmode; /* K_XLATE, K_UNICODE, ... as found */
    int kb_changed;
    int switching;  /* VT_PROCESS set by us */
    struct vt_mode old_vtmode;
    int pipe_r;     /* SIGUSR1/SIGUSR2 arrive here as 'r'/'a' */
    int deny;       /* kiosk policy, for the log line */
    fx_logger log;
    fx_vt_hooks hooks;
};

/* The write end for the switch-signal handler: one VT per process can be
 * in VT_PROCESS mode for us, so one global suffices. */
static volatile int vt_sig_fd = -1;
static struct sigaction old_usr1, old_usr2;

static int is_vt(int fd)
{
    int mode;
    struct vt_stat st;
    return ioctl(fd, KDGETMODE, &mode) == 0 && ioctl(fd, VT_GETSTATE, &st) == 0;
}

static int vt_num_of(int fd)
{
    struct stat st;
    /* VT minors 1..63 are /dev/tty1..63 (major 4). */
    if (fstat(fd, &st) == 0 && major(st.st_rdev) == 4 && minor(st.st_rdev) >= 1 && minor(st.st_rdev) < 64)
        return (int)minor(st.st_rdev);
    return 0;
}

static int open_active_vt(const fx_logger *l)
{
    /* A program started on a VT uses that one; otherwise (ssh, serial,
     * systemd service) take the VT currently on screen. */
    if (isatty(STDIN_FILENO) && is_vt(STDIN_FILENO)) {
        const char *name = ttyname(STDIN_FILENO);
        if (name) {
            int fd = open(name, O_RDWR | O_CLOEXEC | O_NOCTTY);
            if (fd >= 0)
                return fd;
        }
    }
    int fd0 = open("/dev/tty0", O_RDWR | O_CLOEXEC | O_NOCTTY);
    if (fd0 < 0) {
        fx_log(l, FX_LOG_DEBUG, "no console VT (/dev/tty0: %s); console left alone",
                       strerror(errno));
        return -errno;
    }
    struct vt_stat st;
    int r = ioctl(fd0, VT_GETSTATE, &st);
    close(fd0);
    if (r < 0)
        return -errno;
    char path[32];
    snprintf(path, sizeof path, "/dev/tty%u", st.v_active);
    int fd = open(path, O_RDWR | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        fx_log(l, FX_LOG_INFO, "%s: %s; the text console may draw over the picture", path,
                       strerror(errno));
        return -errno;
    }
    return fd;
}

static void on_switch_signal(int sig)
{
    int saved_errno = errno;
    char c = sig == SIGUSR1 ? 'r' : 'a';
    if (vt_sig_fd >= 0 && write(vt_sig_fd, &c, 1) < 0) {
        /* a full pipe already holds a wake-up; nothing else to do */
    }
    errno = saved_errno;
}

static int default_action(int sig)
{
    struct sigaction cur;
    return sigaction(sig, NULL, &cur) == 0 && !(cur.sa_flags & SA_SIGINFO) && cur.sa_handler == SIG_DFL;
}

/* VT_PROCESS: the kernel asks (SIGUSR1) before switching away and tells
 * (SIGUSR2) when we are back, so the display can be dropped and retaken
 * cleanly, or the switch refused (kiosk). */
static void setup_switching(fx_vt *vt)
{
    const fx_logger *l = &vt->log;
    if (vt_sig_fd >= 0 || !default_action(SIGUSR1) || !default_action(SIGUSR2)) {
        fx_log(l, FX_LOG_INFO, "SIGUSR1/SIGUSR2 are in use; VT switches are not handled");
        return;
    }
    int p[2];
    if (ioctl(vt->fd, VT_GETMODE, &vt->old_vtmode) < 0 || pipe2(p, O_CLOEXEC | O_NONBLOCK) < 0)
        return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_switch_signal;
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    vt_sig_fd = p[1];
    sigaction(SIGUSR1, &sa, &old_usr1);
    sigaction(SIGUSR2, &sa, &old_usr2);
    struct vt_mode m = {.mode = VT_PROCESS, .relsig = SIGUSR1, .acqsig = SIGUSR2};
    if (ioctl(vt->fd, VT_SETMODE, &m) < 0) {
        fx_log(l, FX_LOG_INFO, "VT_SETMODE VT_PROCESS refused (%s)", strerror(errno));
        sigaction(SIGUSR1, &old_usr1, NULL);
        sigaction(SIGUSR2, &old_usr2, NULL);
        vt_sig_fd = -1;
        close(p[0]);
        close(p[1]);
        return;
    }
    vt->pipe_r = p[0];
    vt->switching = 1;
    fx_log(l, FX_LOG_DEBUG, "VT %d: switching %s", vt->num,
                   vt->deny ? "refused (kiosk)" : "handled");
}

int fx_vt_event_fd(const fx_vt *vt)
{
    return vt && vt->switching ? vt->pipe_r : -1;
}

int fx_vt_number(const fx_vt *vt)
{
    return vt ? vt->num : 0;
}

int fx_vt_activate(fx_vt *vt, int n)
{
    if (!vt || n < 1 || n > 63)
        return -FX_EINVAL;
    return ioctl(vt->fd, VT_ACTIVATE, n) < 0 ? -errno : 0;
}

void fx_vt_handle_events(fx_vt *vt)
{
    char buf[16];
    ssize_t n;
    if (!vt || !vt->switching)
        return;
    while ((n = read(vt->pipe_r, buf, sizeof buf)) > 0) {
        for (ssize_t i = 0; i < n; i++) {
            if (buf[i] == 'r') {
                int allow = vt->hooks.release(vt->hooks.user);
                ioctl(vt->fd, VT_RELDISP, allow ? 1 : 0);
            } else {
                ioctl(vt->fd, VT_RELDISP, VT_ACKACQ);
                vt->hooks.acquire(vt->hooks.user);
            }
        }
    }
}

int fx_vt_enter(fx_vt **out, const fx_logger *log, int deny_switch, const fx_vt_hooks *hooks)
{
    const fx_logger *l = log;
    *out = NULL;
    int fd = open_active_vt(l);
    if (fd < 0)
        return fd;
    fx_vt *vt = calloc(1, sizeof *vt);
    if (!vt) {
        close(fd);
        return -FX_ENOMEM;
    }
    vt->fd = fd;
    vt->num = vt_num_of(fd);
    if (vt->num)
        snprintf(vt->path, sizeof vt->path, "/dev/tty%d", vt->num);
    vt->pipe_r = -1;
    vt->deny = deny_switch;
    vt->log = *log;
    vt->hooks = *hooks;
    if (ioctl(fd, KDGETMODE, &vt->old_mode) < 0 || ioctl(fd, KDGKBMODE, &vt->old_kbmode) < 0) {
        int e = errno;
        fx_log(l, FX_LOG_INFO, "console ioctls refused (%s); console left alone", strerror(e));
        close(fd);
        free(vt);
        return -e;
    }
    if (ioctl(fd, KDSETMODE, KD_GRAPHICS) < 0) {
        int e = errno;
        fx_log(l, FX_LOG_INFO, "KDSETMODE KD_GRAPHICS refused (%s)", strerror(e));
        close(fd);
        free(vt);
        return -e;
    }
    if (ioctl(fd, KDSKBMODE, K_OFF) == 0)
        vt->kb_changed = 1;
    else
        fx_log(l, FX_LOG_INFO, "cannot mute the console keyboard (%s)", strerror(errno));
    *out = vt;
    setup_switching(vt);
    return 0;
}

static int restore_on(const fx_vt *vt, int fd)
{
    if (vt->switching)
        ioctl(fd, VT_SETMODE, &vt->old_vtmode);
    if (vt->kb_changed)
        ioctl(fd, KDSKBMODE, vt->old_kbmode);
    return ioctl(fd, KDSETMODE, vt->old_mode);
}

void fx_vt_emergency_restore(fx_vt *vt)
{
    if (!vt)
        return;
    /* When the session leader on the VT dies (the shell that started us was
     * killed) the kernel hangs the tty up, and every ioctl on our old file
     * fails with EIO: open the VT again (open is async-signal-safe). */
    if (restore_on(vt, vt->fd) < 0 && errno == EIO && vt->path[0]) {
        int fd = open(vt->path, O_RDWR | O_CLOEXEC | O_NOCTTY);
        if (fd >= 0) {
            restore_on(vt, fd);
            close(fd);
        }
    }
}

void fx_vt_leave(fx_vt *vt)
{
    if (!vt)
        return;
    /* Keys typed while muted never were queued, but drop anything that
     * raced in so the shell does not run half a command. */
    tcflush(vt->fd, TCIFLUSH);
    fx_vt_emergency_restore(vt);
    if (vt->switching) {
        sigaction(SIGUSR1, &old_usr1, NULL);
        sigaction(SIGUSR2, &old_usr2, NULL);
        int w = vt_sig_fd;
        vt_sig_fd = -1;
        if (w >= 0)
            close(w);
        close(vt->pipe_r);
    }
    close(vt->fd);
    free(vt);
}
