/* SPDX-License-Identifier: MIT */
/* Guest program: screen power (fx_display_set_power) on the real drivers.
 * The state is read back independently of fixel: the connector's DPMS
 * property through libdrm and /sys/class/drm/<card>-<connector>/dpms. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <fcntl.h>
#include <linux/vt.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <xf86drm.h>
#include <xf86drmMode.h>

#include "fixel/display.h"
#include "fixel/error.h"
#include "guest.h"

/* "On", "Off"... of the first connected connector's sysfs dpms file. */
static void sysfs_dpms(char *out, size_t n)
{
    snprintf(out, n, "?");
    DIR *dp = opendir("/sys/class/drm");
    struct dirent *e;
    while (dp && (e = readdir(dp))) {
        char p[300], st[32] = "";
        if (strncmp(e->d_name, "card", 4) || !strchr(e->d_name, '-'))
            continue;
        snprintf(p, sizeof p, "/sys/class/drm/%s/status", e->d_name);
        FILE *f = fopen(p, "r");
        if (!f)
            continue;
        if (!fgets(st, sizeof st, f))
            st[0] = 0;
        fclose(f);
        if (strncmp(st, "connected", 9))
            continue;
        snprintf(p, sizeof p, "/sys/class/drm/%s/dpms", e->d_name);
        if ((f = fopen(p, "r"))) {
            if (fgets(out, (int)n, f))
                out[strcspn(out, "\n")] = 0;
            fclose(f);
        }
        break;
    }
    if (dp)
        closedir(dp);
}

/* The DPMS property's enum name as the kernel reports it now, through a
 * second, unprivileged-for-modeset fd. */
static void prop_dpms(char *out, size_t n)
{
    snprintf(out, n, "?");
    int fd = open("/dev/dri/card0", O_RDWR | O_CLOEXEC);
    if (fd < 0)
        return;
    drmModeResPtr res = drmModeGetResources(fd);
    for (int i = 0; res && i < res->count_connectors; i++) {
        drmModeConnectorPtr c = drmModeGetConnector(fd, res->connectors[i]);
        if (c && c->connection == DRM_MODE_CONNECTED) {
            drmModeObjectPropertiesPtr pr = drmModeObjectGetProperties(fd, c->connector_id, DRM_MODE_OBJECT_CONNECTOR);
            for (uint32_t k = 0; pr && k < pr->count_props; k++) {
                drmModePropertyPtr p = drmModeGetProperty(fd, pr->props[k]);
                if (p && !strcmp(p->name, "DPMS"))
                    for (int e = 0; e < p->count_enums; e++)
                        if (p->enums[e].value == pr->prop_values[k])
                            snprintf(out, n, "%s", p->enums[e].name);
                drmModeFreeProperty(p);
            }
            drmModeFreeObjectProperties(pr);
            drmModeFreeConnector(c);
            break;
        }
        drmModeFreeConnector(c);
    }
    drmModeFreeResources(res);
    close(fd);
}

static int both(const char *want, char *s, char *p)
{
    sysfs_dpms(s, 32);
    prop_dpms(p, 32);
    return !strcmp(s, want) && !strcmp(p, want);
}

/* The display's events for ms milliseconds, as an event loop runs them
 * (VT switch requests, hotplug uevents). */
static void pump_for(fx_display *d, int ms)
{
    for (int t = 0; t < ms; t += 10) {
        struct pollfd pfd = {.fd = fx_display_fd(d), .events = POLLIN};
        poll(&pfd, 1, 10);
        fx_display_dispatch(d);
    }
}

/* chvt n from another process (as logind would) while d's events run. */
static int chvt(fx_display *d, int n)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        int fd = open("/dev/tty0", O_RDWR | O_NOCTTY);
        _exit(fd < 0 || ioctl(fd, VT_ACTIVATE, n) < 0 || ioctl(fd, VT_WAITACTIVE, n) < 0);
    }
    int st = -1;
    for (int t = 0; t < 4000 && waitpid(pid, &st, WNOHANG) != pid; t += 10)
        pump_for(d, 10);
    pump_for(d, 200);
    return st;
}

/* Switched off, a screen stays off when the kiosk's VT comes back and when
 * its connector is unplugged and plugged again (issue #24 review: both
 * used to set the mode, which lit it), and a crash while off leaves it on
 * like an orderly close. */
static void power_survives(void)
{
    char s[32], p[32], path[160];
    fx_display_options o;
    fx_display *d = NULL;
    fx_display_options_init(&o);
    fx_display_options_from_env(&o);
    o.backend = FX_BACKEND_DRM;
    if (guest_open("power-drm-reopen", &d, &o) < 0)
        return;
    fx_display_present(d, NULL, 0);
    fx_display_set_power(d, 0);
    int a = chvt(d, 2), b = chvt(d, 1);
    guest_check("power-drm-off-after-vt-return", a == 0 && b == 0 && both("Off", s, p) && fx_display_active(d),
                "chvt 2 status %d, chvt 1 status %d; sysfs %s, property %s", a, b, s, p);
    int r = fx_display_set_power(d, 1);
    guest_check("power-drm-on-after-vt-return", r == 0 && both("On", s, p), "set_power(1) = %d; sysfs %s, property %s",
                r, s, p);

    fx_display_info info;
    fx_display_get_info(d, &info);
    snprintf(path, sizeof path, "/sys/class/drm/card0-%s/status", info.connector);
    fx_display_set_power(d, 0);
    int w = write_file(path, "off");
    if (w == 0)
        w = write_file("/sys/class/drm/card0/uevent", "change");
    pump_for(d, 500);
    if (w == 0)
        w = write_file(path, "on");
    if (w == 0)
        w = write_file("/sys/class/drm/card0/uevent", "change");
    pump_for(d, 500);
    fx_display_get_info(d, &info);
    guest_check("power-drm-off-after-hotplug", w == 0 && info.connected && both("Off", s, p),
                "unplug/replug %d, connected %d; sysfs %s, property %s", w, info.connected, s, p);
    write_file(path, "detect");
    r = fx_display_set_power(d, 1);
    guest_check("power-drm-on-after-hotplug", r == 0 && both("On", s, p), "set_power(1) = %d; sysfs %s, property %s",
                r, s, p);
    fx_display_close(d);

    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        fx_display *c = NULL;
        if (fx_display_open(&c, &o) < 0)
            _exit(3);
        fx_display_present(c, NULL, 0);
        fx_display_set_power(c, 0);
        abort(); /* the fatal-signal path, not fx_display_close */
    }
    int st = 0;
    waitpid(pid, &st, 0);
    guest_check("power-drm-restored-after-crash", WIFSIGNALED(st) && WTERMSIG(st) == SIGABRT && both("On", s, p),
                "child %s %d; sysfs %s, property %s", WIFSIGNALED(st) ? "signal" : "exit",
                WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st), s, p);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char s[32], p[32];
    fx_display_options o;
    fx_display_options_init(&o);
    fx_display_options_from_env(&o);
    o.backend = FX_BACKEND_DRM;
    fx_display *d = NULL;
    if (guest_open("power-drm-open", &d, &o) < 0)
        return 1;
    guest_check("power-drm-method", !strcmp(fx_display_power_method(d), "dpms"), "method %s",
                fx_display_power_method(d));
    fx_surface sf = fx_display_surface(d);
    fx_display_present(d, NULL, 0);
    guest_check("power-drm-on-at-start", both("On", s, p), "sysfs %s, property %s", s, p);
    int r = fx_display_set_power(d, 0);
    guest_check("power-drm-off", r == 0 && both("Off", s, p) && fx_display_power(d) == 0,
                "set_power(0) = %d; sysfs %s, property %s", r, s, p);
    /* A present while off must not switch the CRTC back on. */
    sf = fx_display_surface(d);
    (void)sf;
    r = fx_display_present(d, NULL, 0);
    guest_check("power-drm-present-while-off", r == 0 && both("Off", s, p), "present = %d; sysfs %s, property %s",
                r, s, p);
    r = fx_display_set_power(d, 1);
    guest_check("power-drm-on", r == 0 && both("On", s, p), "set_power(1) = %d; sysfs %s, property %s", r, s, p);
    fx_display_set_power(d, 0);
    fx_display_close(d);
    guest_check("power-drm-restored-at-close", both("On", s, p), "closed while off; sysfs %s, property %s", s, p);
    power_survives();

    fx_display_options_init(&o);
    fx_display_options_from_env(&o);
    o.backend = FX_BACKEND_FBDEV;
    if (guest_open("power-fbdev-open", &d, &o) < 0)
        return 1;
    int r0 = fx_display_set_power(d, 0), r1 = fx_display_set_power(d, 1);
    guest_check("power-fbdev-blank", r0 == 0 && r1 == 0 && !strcmp(fx_display_power_method(d), "fbblank"),
                "FBIOBLANK off %d, on %d, method %s", r0, r1, fx_display_power_method(d));
    fx_display_close(d);
    return guest_failed;
}
