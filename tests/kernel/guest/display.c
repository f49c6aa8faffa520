/* SPDX-License-Identifier: MIT */
/* Guest program: the display backends on real drivers. Each case runs in a
 * child process so a crash (deliberate or not) cannot take the rest down,
 * and so the console/CRTC state can be inspected after the child is gone.
 * Pictures are checked by the host (SCREEN markers, exact compare). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/kd.h>
#include <linux/vt.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

#include "fixel/display.h"
#include "fixel/error.h"
#include "guest.h"
#include "scenes.h"

/* ---- helpers ------------------------------------------------------------ */

static void opts(fx_display_options *o, fx_backend b, fx_present_mode pm, int rot)
{
    fx_display_options_init(o);
    fx_display_options_from_env(o); /* the variables the rig sets, as the tools do */
    o->backend = b;
    o->present = pm;
    o->rotation = rot;
    o->log = capture_log;
    o->log_priority = FX_LOG_DEBUG;
}

#define in_child guest_in_child

static int screen(const char *name, fx_display *d, const char *spec)
{
    fx_display_info info;
    fx_display_get_info(d, &info);
    return guest_request("SCREEN %s %d %d %d %s", name, info.width, info.height, info.rotation, spec);
}

/* ---- pictures through each backend --------------------------------------- */

struct pic_case {
    const char *name;
    fx_backend backend;
    fx_present_mode present;
    int rotation;
};

static void pic_child(void *arg)
{
    const struct pic_case *c = arg;
    fx_display *d;
    fx_display_options o;
    opts(&o, c->backend, c->present, c->rotation);
    int r = guest_open(c->name, &d, &o);
    if (r < 0)
        return;
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    r = fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    if (r < 0)
        guest_check(c->name, 0, "present: %s", fx_strerror(r));
    else
        screen(c->name, d, "bars");

    /* A second full frame lands in the other buffer. */
    char n2[64];
    snprintf(n2, sizeof n2, "%s-frame2", c->name);
    s = fx_display_surface(d);
    scene_draw("checker", &s);
    r = fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    if (r < 0)
        guest_check(n2, 0, "present: %s", fx_strerror(r));
    else
        screen(n2, d, "checker");

    /* Damage: draw the next picture only inside a small rectangle and
     * present just that rectangle: nothing else may change on screen. The
     * scene is drawn at full size into scratch memory (its pixels depend on
     * the surface size) and the rectangle copied over. */
    fx_display_info info;
    fx_display_get_info(d, &info);
    s = fx_display_surface(d);
    fx_rect dmg = {s.w / 5, s.h / 3, s.w / 5 + 61, s.h / 3 + 37};
    {
        fx_surface sub = fx_surface_sub(s, dmg);
        int32_t stride = fx_format_min_stride(s.format, s.w);
        uint8_t *tmp = malloc((size_t)s.h * (size_t)stride);
        fx_surface full;
        fx_surface_init(&full, tmp, s.w, s.h, stride, s.format);
        scene_draw("bars", &full);
        fx_surface fsub = fx_surface_sub(full, dmg);
        fx_blit(&sub, 0, 0, &fsub);
        free(tmp);
    }
    r = fx_display_present(d, &dmg, 1);
    fx_display_wait(d, 1000);
    char n3[64], spec[96];
    snprintf(n3, sizeof n3, "%s-damage", c->name);
    snprintf(spec, sizeof spec, "checker,bars:%d:%d:%d:%d", dmg.x0, dmg.y0, dmg.x1, dmg.y1);
    if (r < 0)
        guest_check(n3, 0, "present: %s", fx_strerror(r));
    else
        screen(n3, d, spec);

    fx_display_get_info(d, &info);
    if (info.backend == FX_BACKEND_DRM && info.buffers == 2) {
        char n4[64];
        snprintf(n4, sizeof n4, "%s-flip", c->name);
        guest_check(n4, info.flips + info.fallbacks >= 3, "flips %u, SetCrtc fallbacks %u, dirtyfb %d",
                    info.flips, info.fallbacks, info.dirtyfb);
    }
    if (info.backend != c->backend)
        guest_check(c->name, 0, "backend %s, wanted %s", fx_backend_name(info.backend),
                    fx_backend_name(c->backend));
    fx_display_close(d);
}

/* ---- console ------------------------------------------------------------ */

struct vt_state {
    int mode, kbmode, vtmode;
    uint32_t crtc_fb;
};

static void read_vt_state(struct vt_state *st)
{
    st->mode = st->kbmode = st->vtmode = -1;
    st->crtc_fb = 0;
    int fd = open("/dev/tty1", O_RDWR | O_NOCTTY);
    if (fd >= 0) {
        struct vt_mode vm;
        ioctl(fd, KDGETMODE, &st->mode);
        ioctl(fd, KDGKBMODE, &st->kbmode);
        if (ioctl(fd, VT_GETMODE, &vm) == 0)
            st->vtmode = vm.mode;
        close(fd);
    }
    fd = open("/dev/dri/card0", O_RDWR);
    if (fd >= 0) {
        drmModeResPtr res = drmModeGetResources(fd);
        if (res && res->count_crtcs > 0) {
            drmModeCrtcPtr c = drmModeGetCrtc(fd, res->crtcs[0]);
            if (c)
                st->crtc_fb = c->buffer_id;
            drmModeFreeCrtc(c);
        }
        drmModeFreeResources(res);
        close(fd);
    }
}

static int tty_log_has(const char *what)
{
    char buf[512] = "";
    FILE *f = fopen("/tmp/tty1.log", "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    return strstr(buf, what) != NULL;
}

static void boom(fx_display *d, void *user)
{
    (void)d;
    /* A bug in the program's callback: write through a null pointer. */
    volatile int *p = user;
    *p = 1;
}

enum vt_how { VT_EXIT, VT_SIGTERM, VT_SIGSEGV };

static int ready_pipe[2];

static void vt_child(void *arg)
{
    enum vt_how how = *(enum vt_how *)arg;
    fx_display *d;
    fx_display_options o;
    opts(&o, FX_BACKEND_DRM, FX_PRESENT_AUTO, 0);
    int r = guest_open("console-open", &d, &o);
    if (r < 0)
        return;
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_surface(d);
    if (how == VT_EXIT) {
        struct vt_state st;
        read_vt_state(&st);
        guest_check("console-graphics", st.mode == KD_GRAPHICS && st.kbmode == K_OFF,
                    "while running: mode %d (KD_GRAPHICS=%d), kbmode %d (K_OFF=%d)", st.mode,
                    KD_GRAPHICS, st.kbmode, K_OFF);
        guest_request("KEYS abc");
        msleep(300);
        guest_check("console-keys-muted", !tty_log_has("abc"),
                    "keys typed while running %s the shell's tty",
                    tty_log_has("abc") ? "reached" : "did not reach");
        fx_display_close(d);
        return;
    }
    if (how == VT_SIGSEGV) {
        fx_display_set_flip_callback(d, boom, NULL);
        s = fx_display_surface(d);
        scene_draw("checker", &s);
        fx_display_present(d, NULL, 0);
        fx_display_surface(d); /* the flip completes -> callback -> SIGSEGV */
        fx_display_present(d, NULL, 0);
        fx_display_surface(d);
        printf("  callback did not crash\n");
        _exit(3);
    }
    /* SIGTERM: tell the parent we are drawing, then wait to be killed. */
    if (write(ready_pipe[1], "r", 1) != 1)
        _exit(4);
    for (;;)
        pause();
}

static void console_checks(void)
{
    struct vt_state before, after;
    read_vt_state(&before);
    printf("  console before: mode %d kbmode %d crtc fb %u\n", before.mode, before.kbmode,
           before.crtc_fb);

    static const char *names[] = {"console-restore-exit", "console-restore-sigterm",
                                  "console-restore-sigsegv"};
    for (enum vt_how how = VT_EXIT; how <= VT_SIGSEGV; how++) {
        int st;
        if (how == VT_SIGTERM) {
            if (pipe(ready_pipe) < 0)
                return;
            fflush(stdout);
            pid_t pid = fork();
            if (pid == 0) {
                close(ready_pipe[0]);
                vt_child(&how);
                _exit(0);
            }
            close(ready_pipe[1]);
            char c;
            if (read(ready_pipe[0], &c, 1) != 1)
                printf("  child died before drawing\n");
            close(ready_pipe[0]);
            kill(pid, SIGTERM);
            waitpid(pid, &st, 0);
        } else {
            st = in_child(vt_child, &how);
        }
        read_vt_state(&after);
        int want_sig = how == VT_SIGTERM ? SIGTERM : how == VT_SIGSEGV ? SIGSEGV : 0;
        int ended_ok = want_sig ? WIFSIGNALED(st) && WTERMSIG(st) == want_sig
                                : WIFEXITED(st) && WEXITSTATUS(st) == 0;
        guest_check(names[how],
                    ended_ok && after.mode == before.mode && after.kbmode == before.kbmode &&
                        after.crtc_fb == before.crtc_fb && after.vtmode == before.vtmode,
                    "child %s %d; mode %d->%d kbmode %d->%d vt mode %d->%d crtc fb %u->%u",
                    WIFSIGNALED(st) ? "signal" : "exit", WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st),
                    before.mode, after.mode, before.kbmode, after.kbmode, before.vtmode, after.vtmode,
                    before.crtc_fb, after.crtc_fb);
        if (how == VT_EXIT) {
            guest_request("KEYS xyz");
            msleep(300);
            guest_check("console-keys-restored", tty_log_has("xyz"),
                        "keys typed after exit %s the shell's tty",
                        tty_log_has("xyz") ? "reached" : "did not reach");
        }
    }
}

/* ---- VT switching --------------------------------------------------------- */

static int vt_events[2];
static struct vt_state vt_before;

static void on_vt(fx_display *d, int active, void *user)
{
    (void)d, (void)user;
    vt_events[active ? 1 : 0]++;
}

static int active_vt(void)
{
    struct vt_stat st = {0};
    int fd = open("/dev/tty0", O_RDWR | O_NOCTTY);
    if (fd >= 0) {
        ioctl(fd, VT_GETSTATE, &st);
        close(fd);
    }
    return st.v_active;
}

/* chvt from another process, as a user or logind would. */
static pid_t switcher(int n, int wait_active)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open("/dev/tty0", O_RDWR | O_NOCTTY);
        if (fd < 0 || ioctl(fd, VT_ACTIVATE, n) < 0)
            _exit(1);
        if (wait_active && ioctl(fd, VT_WAITACTIVE, n) < 0)
            _exit(2);
        _exit(0);
    }
    return pid;
}

/* Run the display's events (as an event loop would) until pid exits, then
 * for linger_ms more; returns pid's wait status or -1 on timeout. */
static int pump(fx_display *d, pid_t pid, int linger_ms)
{
    int st = -1, done = 0;
    for (int t = 0; t < 4000; t += 10) {
        struct pollfd pfd = {.fd = fx_display_fd(d), .events = POLLIN};
        poll(&pfd, 1, 10);
        fx_display_dispatch(d);
        if (!done && waitpid(pid, &st, WNOHANG) == pid) {
            done = 1;
            t = 4000 - linger_ms;
        }
    }
    if (!done) {
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
        return -1;
    }
    return st;
}

struct vt_case {
    const char *name;
    fx_backend backend;
    fx_present_mode present;
    fx_vt_switch policy;
};

static void vtswitch_child(void *arg)
{
    const struct vt_case *c = arg;
    fx_display *d;
    fx_display_options o;
    char n[64];
    opts(&o, c->backend, c->present, 0);
    o.vt_switch = c->policy;
    int r = guest_open(c->name, &d, &o);
    if (r < 0)
        return;
    fx_display_set_vt_callback(d, on_vt, NULL);
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);

    if (c->policy == FX_VT_SWITCH_DENY) {
        int st = pump(d, switcher(2, 0), 500);
        fx_display_info info;
        fx_display_get_info(d, &info);
        guest_check(c->name, st == 0 && active_vt() == 1 && info.vt_refused == 1 && vt_events[0] == 0,
                    "switch request %d, active VT %d, refused %u, away callbacks %d", st, active_vt(),
                    info.vt_refused, vt_events[0]);
        snprintf(n, sizeof n, "%s-screen", c->name);
        screen(n, d, "bars");
        fx_display_close(d);
        return;
    }

    int st = pump(d, switcher(2, 1), 100);
    struct vt_state away;
    read_vt_state(&away);
    snprintf(n, sizeof n, "%s-away", c->name);
    guest_check(n, st == 0 && active_vt() == 2 && vt_events[0] == 1 && !fx_display_active(d) &&
                       away.crtc_fb == vt_before.crtc_fb,
                "chvt 2 status %d, active VT %d, away callbacks %d, console fb on CRTC %s (%u)", st,
                active_vt(), vt_events[0], away.crtc_fb == vt_before.crtc_fb ? "yes" : "no", away.crtc_fb);

    snprintf(n, sizeof n, "%s-console-shown", c->name);
    screen(n, d, "!bars");

    /* A frame drawn and presented while away must be the one on screen
     * after the return: DRM keeps flipping its own buffers without showing
     * them, fbdev copies the whole shadow back over the console's text. */
    s = fx_display_surface(d);
    scene_draw("checker", &s);
    r = fx_display_present(d, NULL, 0);
    st = pump(d, switcher(1, 1), 100);
    snprintf(n, sizeof n, "%s-back", c->name);
    guest_check(n, r == 0 && st == 0 && active_vt() == 1 && vt_events[1] == 1 && fx_display_active(d),
                "present while away %d, chvt 1 status %d, active VT %d, back callbacks %d", r, st,
                active_vt(), vt_events[1]);
    snprintf(n, sizeof n, "%s-redrawn", c->name);
    screen(n, d, "checker");
    fx_display_close(d);
}

static void vtswitch_checks(void)
{
    static const struct vt_case cases[] = {
        {"vt-switch-drm", FX_BACKEND_DRM, FX_PRESENT_DIRECT, FX_VT_SWITCH_ALLOW},
        {"vt-switch-fbdev", FX_BACKEND_FBDEV, FX_PRESENT_SHADOW, FX_VT_SWITCH_ALLOW},
        {"vt-switch-kiosk", FX_BACKEND_DRM, FX_PRESENT_AUTO, FX_VT_SWITCH_DENY},
    };
    read_vt_state(&vt_before);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        in_child(vtswitch_child, (void *)&cases[i]);
        if (active_vt() != 1) /* never leave a later case on the wrong VT */
            waitpid(switcher(1, 1), NULL, 0);
    }
}

/* ---- hotplug -------------------------------------------------------------- */

static int reshapes_seen;

static void on_reshape(fx_display *d, int32_t w, int32_t h, void *user)
{
    (void)d, (void)w, (void)h, (void)user;
    reshapes_seen++;
}

static void pump_ms(fx_display *d, int ms)
{
    for (int t = 0; t < ms; t += 10) {
        struct pollfd pfd = {.fd = fx_display_fd(d), .events = POLLIN};
        poll(&pfd, 1, 10);
        fx_display_dispatch(d);
    }
}

/* Forcing the connector off and on through sysfs changes what the kernel's
 * probe reports; bochs and virtio-gpu do not announce that themselves, so
 * the test then sends the "change" uevent of the card that a driver's
 * hotplug interrupt would (drm_sysfs_hotplug_event). */
static void hotplug_child(void *arg)
{
    (void)arg;
    fx_display *d;
    fx_display_options o;
    fx_display_info info;
    char path[160];
    opts(&o, FX_BACKEND_DRM, FX_PRESENT_AUTO, 0);
    int r = guest_open("hotplug", &d, &o);
    if (r < 0)
        return;
    fx_display_set_reshape_callback(d, on_reshape, NULL);
    fx_surface s = fx_display_surface(d);
    scene_draw("bars", &s);
    fx_display_present(d, NULL, 0);
    fx_display_wait(d, 1000);
    fx_display_get_info(d, &info);
    snprintf(path, sizeof path, "/sys/class/drm/card0-%s/status", info.connector);

    int w = write_file(path, "off");
    if (w == 0)
        w = write_file("/sys/class/drm/card0/uevent", "change");
    pump_ms(d, 500);
    fx_display_get_info(d, &info);
    guest_check("hotplug-off", w == 0 && info.hotplugs >= 1 && !info.connected,
                "write off: %d, uevents %u, connected %d", w, info.hotplugs, info.connected);
    uint32_t seen = info.hotplugs;

    w = write_file(path, "on");
    if (w == 0)
        w = write_file("/sys/class/drm/card0/uevent", "change");
    pump_ms(d, 500);
    fx_display_get_info(d, &info);
    guest_check("hotplug-on", w == 0 && info.hotplugs > seen && info.connected && reshapes_seen == 0,
                "write on: %d, uevents %u, connected %d, reshapes %d (same mode: none expected)", w,
                info.hotplugs, info.connected, reshapes_seen);
    screen("hotplug-relit", d, "bars");
    write_file(path, "detect");
    pump_ms(d, 200);
    fx_display_close(d);
}

/* ---- DRM master held elsewhere ----------------------------------------- */

static void master_child(void *arg)
{
    (void)arg;
    fx_display *d;
    fx_display_options o;
    opts(&o, FX_BACKEND_DRM, FX_PRESENT_AUTO, 0);
    logbuf[0] = 0;
    int r = fx_display_open(&d, &o);
    guest_check("drm-master-busy", r == -FX_EBUSY && strstr(logbuf, "DRM master") &&
                                       strstr(logbuf, "fbdev"),
                "open returned %d (%s), log names master and fbdev: %s", r, fx_strerror(r),
                strstr(logbuf, "DRM master") ? "yes" : "no");
    if (r == 0)
        fx_display_close(d);

    opts(&o, FX_BACKEND_AUTO, FX_PRESENT_AUTO, 0);
    logbuf[0] = 0;
    r = fx_display_open(&d, &o);
    if (r < 0) {
        guest_check("drm-master-fallback", 0, "auto open: %s", fx_strerror(r));
        return;
    }
    fx_display_info info;
    fx_display_get_info(d, &info);
    guest_check("drm-master-fallback-choice", info.backend == FX_BACKEND_FBDEV && strstr(logbuf, "drm:"),
                "auto chose %s; reason logged: %s", fx_backend_name(info.backend),
                strstr(logbuf, "drm:") ? "yes" : "no");
    fx_surface s = fx_display_surface(d);
    scene_draw("checker", &s);
    fx_display_present(d, NULL, 0);
    screen("drm-master-fallback", d, "checker");
    fx_display_close(d);
}

static void master_checks(void)
{
    int p[2];
    if (pipe(p) < 0)
        return;
    fflush(stdout);
    pid_t holder = fork();
    if (holder == 0) {
        /* Stands in for a desktop: the first opener of the card is master. */
        int fd = open("/dev/dri/card0", O_RDWR);
        char c = fd >= 0 && drmIsMaster(fd) ? 'm' : 'x';
        if (write(p[1], &c, 1) != 1)
            _exit(1);
        for (;;)
            pause();
    }
    char c = 0;
    if (read(p[0], &c, 1) != 1 || c != 'm') {
        guest_check("drm-master-holder", 0, "helper could not become master (%c)", c);
    } else {
        int st = in_child(master_child, NULL);
        (void)st;
    }
    kill(holder, SIGKILL);
    waitpid(holder, NULL, 0);
    close(p[0]);
    close(p[1]);
}

/* ---- permissions -------------------------------------------------------- */

static void nonroot_child(void *arg)
{
    (void)arg;
    if (setgroups(0, NULL) < 0 || setgid(1000) < 0 || setuid(1000) < 0) {
        guest_check("nonroot", 0, "cannot drop privileges: %s", strerror(errno));
        return;
    }
    static const fx_backend bs[] = {FX_BACKEND_DRM, FX_BACKEND_FBDEV};
    static const char *names[] = {"nonroot-drm", "nonroot-fbdev"};
    for (int i = 0; i < 2; i++) {
        fx_display *d;
        fx_display_options o;
        opts(&o, bs[i], FX_PRESENT_AUTO, 0);
        logbuf[0] = 0;
        int r = fx_display_open(&d, &o);
        guest_check(names[i], r == -FX_EACCES && strstr(logbuf, "group 'video'"),
                    "open returned %d (%s); log names group video: %s", r, fx_strerror(r),
                    strstr(logbuf, "group 'video'") ? "yes" : "no");
        if (r == 0)
            fx_display_close(d);
    }
}

int main(int argc, char **argv)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    const char *only = argc > 1 ? argv[1] : NULL;
    static const struct pic_case cases[] = {
        {"drm-direct", FX_BACKEND_DRM, FX_PRESENT_DIRECT, 0},
        {"drm-shadow", FX_BACKEND_DRM, FX_PRESENT_SHADOW, 0},
        {"drm-rot90", FX_BACKEND_DRM, FX_PRESENT_AUTO, 90},
        {"drm-rot270", FX_BACKEND_DRM, FX_PRESENT_AUTO, 270},
        {"drm-rot180", FX_BACKEND_DRM, FX_PRESENT_AUTO, 180},
        {"fbdev", FX_BACKEND_FBDEV, FX_PRESENT_AUTO, 0},
        {"fbdev-rot90", FX_BACKEND_FBDEV, FX_PRESENT_AUTO, 90},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (!only || !strcmp(only, "pictures"))
            in_child(pic_child, (void *)&cases[i]);
    if (!only || !strcmp(only, "console"))
        console_checks();
    if (!only || !strcmp(only, "vt"))
        vtswitch_checks();
    if (!only || !strcmp(only, "hotplug"))
        in_child(hotplug_child, NULL);
    if (!only || !strcmp(only, "master"))
        master_checks();
    if (!only || !strcmp(only, "nonroot"))
        in_child(nonroot_child, NULL);
    return 0;
}
