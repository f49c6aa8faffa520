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

#include "display_int.h"
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

static int open_active_vt(fx_display *d)
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
        fx_display_log(d, FX_LOG_DEBUG, "no console VT (/dev/tty0: %s); console left alone",
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
        fx_display_log(d, FX_LOG_INFO, "%s: %s; the text console may draw over the picture", path,
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
static void setup_switching(fx_display *d, fx_vt *vt)
{
    fx_vt_switch policy = d->opt.vt_switch;
    const char *e = getenv("FIXEL_VT_SWITCH");
    if (e && !strcasecmp(e, "deny"))
        policy = FX_VT_SWITCH_DENY;
    else if (e && !strcasecmp(e, "allow"))
        policy = FX_VT_SWITCH_ALLOW;
    d->opt.vt_switch = policy;
    if (vt_sig_fd >= 0 || !default_action(SIGUSR1) || !default_action(SIGUSR2)) {
        fx_display_log(d, FX_LOG_INFO, "SIGUSR1/SIGUSR2 are in use; VT switches are not handled");
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
        fx_display_log(d, FX_LOG_INFO, "VT_SETMODE VT_PROCESS refused (%s)", strerror(errno));
        sigaction(SIGUSR1, &old_usr1, NULL);
        sigaction(SIGUSR2, &old_usr2, NULL);
        vt_sig_fd = -1;
        close(p[0]);
        close(p[1]);
        return;
    }
    vt->pipe_r = p[0];
    vt->switching = 1;
    fx_display_log(d, FX_LOG_DEBUG, "VT %d: switching %s", vt->num,
                   policy == FX_VT_SWITCH_DENY ? "refused (kiosk)" : "handled");
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

void fx_vt_handle_events(fx_display *d)
{
    fx_vt *vt = d->vt;
    char buf[16];
    ssize_t n;
    if (!vt || !vt->switching)
        return;
    while ((n = read(vt->pipe_r, buf, sizeof buf)) > 0) {
        for (ssize_t i = 0; i < n; i++) {
            if (buf[i] == 'r') {
                int allow = fx_display_vt_release(d);
                ioctl(vt->fd, VT_RELDISP, allow ? 1 : 0);
            } else {
                ioctl(vt->fd, VT_RELDISP, VT_ACKACQ);
                fx_display_vt_acquire(d);
            }
        }
    }
}

int fx_vt_enter(fx_display *d, fx_vt **out)
{
    *out = NULL;
    int fd = open_active_vt(d);
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
    if (ioctl(fd, KDGETMODE, &vt->old_mode) < 0 || ioctl(fd, KDGKBMODE, &vt->old_kbmode) < 0) {
        int e = errno;
        fx_display_log(d, FX_LOG_INFO, "console ioctls refused (%s); console left alone", strerror(e));
        close(fd);
        free(vt);
        return -e;
    }
    if (ioctl(fd, KDSETMODE, KD_GRAPHICS) < 0) {
        int e = errno;
        fx_display_log(d, FX_LOG_INFO, "KDSETMODE KD_GRAPHICS refused (%s)", strerror(e));
        close(fd);
        free(vt);
        return -e;
    }
    if (ioctl(fd, KDSKBMODE, K_OFF) == 0)
        vt->kb_changed = 1;
    else
        fx_display_log(d, FX_LOG_INFO, "cannot mute the console keyboard (%s)", strerror(errno));
    *out = vt;
    setup_switching(d, vt);
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

/* ---- signals ------------------------------------------------------------ */

/* Signal handlers can only find state through globals; this table is the
 * one piece of mutable global state of the boards side. */
#define MAX_DISPLAYS 8
static fx_display *volatile registered[MAX_DISPLAYS];
static volatile sig_atomic_t restoring;
static int installed;

static const int fatal_sigs[] = {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL};
static const int term_sigs[] = {SIGINT, SIGTERM, SIGHUP};
static struct sigaction old_act[65];
static unsigned char ours[65];

static void restore_all(void)
{
    if (restoring)
        return;
    restoring = 1;
    for (int i = 0; i < MAX_DISPLAYS; i++) {
        fx_display *d = registered[i];
        if (!d)
            continue;
        if (d->info.backend == FX_BACKEND_DRM)
            fx_drm_emergency_restore(d->priv);
        fx_vt_emergency_restore(d->vt);
    }
}

static void on_signal(int sig, siginfo_t *si, void *uc)
{
    int saved_errno = errno;
    restore_all();
    /* Hand the signal to whoever had it before: the default action (so the
     * exit status still says SIGSEGV/SIGTERM), or a chained handler such as
     * a sanitizer's. Returning from a synchronous fault re-executes the
     * faulting instruction under the restored action. */
    sigaction(sig, &old_act[sig], NULL);
    ours[sig] = 0;
    if (old_act[sig].sa_flags & SA_SIGINFO) {
        if (old_act[sig].sa_sigaction)
            old_act[sig].sa_sigaction(sig, si, uc);
    } else if (old_act[sig].sa_handler == SIG_DFL) {
        if (sig != SIGSEGV && sig != SIGBUS && sig != SIGFPE && sig != SIGILL)
            raise(sig);
    } else if (old_act[sig].sa_handler != SIG_IGN) {
        old_act[sig].sa_handler(sig);
    }
    errno = saved_errno;
}

static void install(int sig, int only_if_default)
{
    struct sigaction sa, cur;
    if (sigaction(sig, NULL, &cur) < 0)
        return;
    /* A program (or event loop) that handles SIGINT/SIGTERM/SIGHUP itself
     * closes the display on its own; only the default "die" needs help. */
    if (only_if_default && (cur.sa_flags & SA_SIGINFO || cur.sa_handler != SIG_DFL))
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = on_signal;
    sa.sa_flags = SA_SIGINFO | SA_NODEFER;
    sigemptyset(&sa.sa_mask);
    if (sigaction(sig, &sa, &old_act[sig]) == 0)
        ours[sig] = 1;
}

static void uninstall_all(void)
{
    for (int s = 1; s < 65; s++)
        if (ours[s]) {
            sigaction(s, &old_act[s], NULL);
            ours[s] = 0;
        }
    installed = 0;
}

void fx_signals_register(fx_display *d)
{
    for (int i = 0; i < MAX_DISPLAYS; i++)
        if (!registered[i]) {
            registered[i] = d;
            break;
        }
    if (!installed) {
        installed = 1;
        restoring = 0;
        for (size_t i = 0; i < sizeof fatal_sigs / sizeof fatal_sigs[0]; i++)
            install(fatal_sigs[i], 0);
        for (size_t i = 0; i < sizeof term_sigs / sizeof term_sigs[0]; i++)
            install(term_sigs[i], 1);
    }
}

void fx_signals_unregister(fx_display *d)
{
    int left = 0;
    for (int i = 0; i < MAX_DISPLAYS; i++) {
        if (registered[i] == d)
            registered[i] = NULL;
        if (registered[i])
            left = 1;
    }
    if (!left && installed)
        uninstall_all();
}

/* ---- permission hints --------------------------------------------------- */

static int group_name(gid_t gid, char *out, size_t n)
{
    /* /etc/group read directly: getgrgid() drags NSS in, which static
     * builds (the qemu rig, small Pi images) cannot load. */
    FILE *f = fopen("/etc/group", "re");
    char line[512];
    int found = 0;
    if (!f)
        return 0;
    while (!found && fgets(line, sizeof line, f)) {
        char *name = strtok(line, ":");
        char *pw = name ? strtok(NULL, ":") : NULL;
        char *id = pw ? strtok(NULL, ":") : NULL;
        if (id && (gid_t)strtoul(id, NULL, 10) == gid) {
            snprintf(out, n, "%s", name);
            found = 1;
        }
    }
    fclose(f);
    return found;
}

void fx_log_access_hint(const fx_display *d, const char *path)
{
    struct stat st;
    char name[64];
    if (stat(path, &st) < 0) {
        fx_display_log(d, FX_LOG_ERROR, "%s: permission denied", path);
        return;
    }
    if (!group_name(st.st_gid, name, sizeof name))
        snprintf(name, sizeof name, "%u", (unsigned)st.st_gid);
    if (st.st_gid == 0 || !(st.st_mode & S_IRWXG))
        fx_display_log(d, FX_LOG_ERROR, "%s: permission denied (owned by root, mode %03o): run as root "
                       "or give the device a group such as 'video' with a udev rule",
                       path, (unsigned)(st.st_mode & 0777));
    else
        fx_display_log(d, FX_LOG_ERROR, "%s: permission denied: the user must be in group '%s' "
                       "(usermod -aG %s USER, then log in again) or run as root",
                       path, name, name);
}
