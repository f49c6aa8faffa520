/* SPDX-License-Identifier: MIT */
/* Guest program: several displays open at once in one process (issue #25),
 * on two DRM cards (card0 and the second device gpu1, whose driver is
 * loaded here from /modules.cards and removed at the end, as outputs.c
 * does). Checked: both open with the console taken once (KD_GRAPHICS while
 * either is open, back to text only when the last closes), each picture on
 * its own device (host screendump, every pixel), damage presented on one
 * leaves the other's picture alone, card1's connector forced off and on
 * through sysfs while card0 keeps drawing (card0's new picture checked
 * while card1 is off, card1 redrawn after it is back), and the console and
 * both CRTCs restored after a SIGSEGV with both open. */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <linux/kd.h>
#include <signal.h>
#include <stdint.h>
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
#include "guest_drm.h"
#include "scenes.h"

static char conn0[32], conn1[32];

static int kd_mode(void)
{
    int m = -1, fd = open("/dev/tty1", O_RDWR | O_NOCTTY);
    if (fd >= 0) {
        ioctl(fd, KDGETMODE, &m);
        close(fd);
    }
    return m;
}

/* The framebuffer on card N's first CRTC (0: none). */
static uint32_t crtc_fb(const char *card)
{
    uint32_t fb = 0;
    int fd = open(card, O_RDWR | O_CLOEXEC);
    if (fd < 0)
        return 0;
    drmModeResPtr res = drmModeGetResources(fd);
    if (res && res->count_crtcs > 0) {
        drmModeCrtcPtr c = drmModeGetCrtc(fd, res->crtcs[0]);
        if (c)
            fb = c->buffer_id;
        drmModeFreeCrtc(c);
    }
    drmModeFreeResources(res);
    close(fd);
    return fb;
}

static int open_on(const char *name, fx_display **d, const char *connector)
{
    fx_display_options o;
    fx_display_options_init(&o);
    o.backend = FX_BACKEND_DRM;
    o.connector = connector;
    o.log = capture_log;
    o.log_priority = FX_LOG_DEBUG;
    return guest_open(name, d, &o);
}

/* With a damage rectangle only it is drawn (the scene is rendered at full
 * size in scratch memory, its pixels depend on the size): in direct mode
 * the surface is the scanout buffer, so anything drawn outside would show. */
static void draw(fx_display *d, const char *scene, const fx_rect *dmg)
{
    fx_surface s = fx_display_surface(d);
    if (dmg) {
        int32_t stride = fx_format_min_stride(s.format, s.w);
        uint8_t *tmp = malloc((size_t)s.h * (size_t)stride);
        if (tmp) {
            fx_surface full, sub = fx_surface_sub(s, *dmg);
            fx_surface_init(&full, tmp, s.w, s.h, stride, s.format);
            scene_draw(scene, &full);
            fx_surface fsub = fx_surface_sub(full, *dmg);
            fx_blit(&sub, 0, 0, &fsub);
            free(tmp);
        }
    } else {
        scene_draw(scene, &s);
    }
    fx_display_present(d, dmg, dmg ? 1 : 0);
    fx_display_wait(d, 1000);
}

static void screen(fx_display *d, const char *name, const char *spec, const char *dev)
{
    fx_display_info in;
    fx_display_get_info(d, &in);
    guest_request("SCREEN %s %d %d %d %s%s%s", name, in.width, in.height, in.rotation, spec, dev ? " " : "",
                  dev ? dev : "");
}

/* card0's and card1's outputs, named by card (checks PREFIX-card0/1). */
static int open_both(const char *prefix, fx_display **a, fx_display **b)
{
    char c0[48], c1[48], n0[48], n1[48];
    snprintf(c0, sizeof c0, "card0:%s", conn0);
    snprintf(c1, sizeof c1, "card1:%s", conn1);
    snprintf(n0, sizeof n0, "%s-card0", prefix);
    snprintf(n1, sizeof n1, "%s-card1", prefix);
    *a = *b = NULL;
    if (open_on(n0, a, c0) < 0)
        return -1;
    if (open_on(n1, b, c1) < 0) {
        fx_display_close(*a);
        *a = NULL;
        return -1;
    }
    return 0;
}

static void two_cards_child(void *arg)
{
    (void)arg;
    fx_display *a, *b;
    if (open_both("multi-open", &a, &b) < 0)
        return;
    fx_display_info ia, ib;
    fx_display_get_info(a, &ia);
    fx_display_get_info(b, &ib);
    guest_check("multi-two-cards",
                !strcmp(ia.device, "/dev/dri/card0") && !strcmp(ib.device, "/dev/dri/card1") &&
                    !strcmp(ia.connector, conn0) && !strcmp(ib.connector, conn1) && ia.vt && ia.vt == ib.vt,
                "a %s %s vt %d, b %s %s vt %d", ia.device, ia.connector, ia.vt, ib.device, ib.connector, ib.vt);
    guest_check("multi-console-graphics", kd_mode() == KD_GRAPHICS, "KDGETMODE %d with both open", kd_mode());

    draw(a, "bars", NULL);
    draw(b, "checker", NULL);
    screen(a, "multi-card0-picture", "bars", NULL);
    screen(b, "multi-card1-picture", "checker", "gpu1");

    /* damage on a only: b's picture must stay */
    fx_rect r = {20, 10, 81, 47};
    draw(a, "checker", &r);
    screen(a, "multi-card0-damage", "bars,checker:20:10:81:47", NULL);
    screen(b, "multi-card1-untouched", "checker", "gpu1");

    /* card1's connector off: card0 keeps drawing */
    char status[96];
    snprintf(status, sizeof status, "/sys/class/drm/card1-%s/status", conn1);
    int w = write_file(status, "off");
    if (w == 0)
        w = write_file("/sys/class/drm/card1/uevent", "change");
    for (int t = 0; t < 40; t++) {
        fx_display_dispatch(b);
        fx_display_dispatch(a);
        fx_display_get_info(b, &ib);
        if (!ib.connected)
            break;
        msleep(50);
    }
    guest_check("multi-hotplug-off", w == 0 && !ib.connected, "card1 %s forced off (%d); display sees %s", conn1, w,
                ib.connected ? "it connected" : "it gone");
    draw(a, "black", NULL);
    draw(a, "bars", NULL);
    screen(a, "multi-hotplug-other-draws", "bars", NULL);
    w = write_file(status, "on");
    if (w == 0)
        w = write_file("/sys/class/drm/card1/uevent", "change");
    for (int t = 0; t < 40; t++) {
        fx_display_dispatch(b);
        fx_display_get_info(b, &ib);
        if (ib.connected)
            break;
        msleep(50);
    }
    guest_check("multi-hotplug-on", w == 0 && ib.connected && ib.hotplugs >= 2,
                "forced on (%d); connected %d after %u hotplugs", w, ib.connected, ib.hotplugs);
    draw(b, "bars", NULL);
    screen(b, "multi-hotplug-redrawn", "bars", "gpu1");
    write_file(status, "detect");
    write_file("/sys/class/drm/card1/uevent", "change");

    /* the console stays in graphics until the last display closes */
    fx_display_close(a);
    int after_one = kd_mode();
    draw(b, "checker", NULL);
    screen(b, "multi-close-one-other-draws", "checker", "gpu1");
    fx_display_close(b);
    int after_both = kd_mode();
    guest_check("multi-console-last-close", after_one == KD_GRAPHICS && after_both == KD_TEXT,
                "KDGETMODE %d after the first close, %d after the last", after_one, after_both);
}

static void crash_child(void *arg)
{
    (void)arg;
    fx_display *a, *b;
    if (open_both("multi-crash-open", &a, &b) < 0)
        _exit(3);
    draw(a, "bars", NULL);
    draw(b, "bars", NULL);
    fflush(stdout);
    /* a real fault: the handler restores, then the instruction faults again
     * under the default action (raise() would just return) */
    *(volatile int *)(uintptr_t)8 = 1;
    _exit(4);
}

int main(void)
{
    setvbuf(stdout, NULL, _IOLBF, 0);
    char detail[300];
    int lr = 0;
    int ok = guest_second_card(conn0, conn1, detail, sizeof detail, &lr);
    guest_check("multi-second-card", lr == 0 && ok, "loaded %s; card1 %s", detail, ok ? "present" : "missing");
    if (!ok)
        return 1;
    msleep(300); /* the new card's fbdev emulation and fbcon settle */

    int st = guest_in_child(two_cards_child, NULL);
    if (!WIFEXITED(st) || WEXITSTATUS(st))
        guest_failed = 1;

    uint32_t fb0 = crtc_fb("/dev/dri/card0"), fb1 = crtc_fb("/dev/dri/card1");
    int mode = kd_mode();
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        crash_child(NULL);
        _exit(5);
    }
    waitpid(pid, &st, 0);
    uint32_t fb0a = crtc_fb("/dev/dri/card0"), fb1a = crtc_fb("/dev/dri/card1");
    guest_check("multi-restore-sigsegv",
                WIFSIGNALED(st) && WTERMSIG(st) == SIGSEGV && kd_mode() == mode && fb0a == fb0 && fb1a == fb1,
                "child %s %d; console mode %d->%d; card0 crtc fb %u->%u, card1 %u->%u",
                WIFSIGNALED(st) ? "signal" : "exit", WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st), mode,
                kd_mode(), fb0, fb0a, fb1, fb1a);

    guest_remove_second_card("multi-second-card-removed", CARD1_MODULE);
    return guest_failed;
}
