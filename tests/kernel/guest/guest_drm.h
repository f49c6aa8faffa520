/* SPDX-License-Identifier: MIT */
/* libdrm helpers of the guest programs that query cards apart from the
 * library (kms.c, outputs.c). Header-only, like guest.h. */
#ifndef FIXEL_GUEST_DRM_H
#define FIXEL_GUEST_DRM_H

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <xf86drm.h>

/* The DRM driver name of a card node ("?" when it cannot be read). */
static const char *guest_drm_driver(const char *dev, char *out, size_t n) __attribute__((unused));
static const char *guest_drm_driver(const char *dev, char *out, size_t n)
{
    snprintf(out, n, "?");
    int fd = open(dev, O_RDWR | O_CLOEXEC);
    if (fd < 0)
        return out;
    drmVersionPtr v = drmGetVersion(fd);
    if (v) {
        snprintf(out, n, "%s", v->name);
        drmFreeVersion(v);
    }
    close(fd);
    return out;
}

/* The second card (outputs.c, multi.c): load its driver from
 * /modules.cards and wait for card1 with a connector on each card (their
 * names into conn0, conn1: 32 bytes each). Returns 1 when it is there;
 * *loaded is 0 when every module loaded. Needs guest.h. */
static int guest_second_card(char *conn0, char *conn1, char *detail, size_t n, int *loaded)
    __attribute__((unused));
static int guest_second_card(char *conn0, char *conn1, char *detail, size_t n, int *loaded)
{
    *loaded = guest_load_modules("/modules.cards", detail, n) < 0 || strstr(detail, "(failed)") ? -1 : 0;
    int ok = 0;
    for (int t = 0; t < 50 && !ok; t++) {
        DIR *dir = opendir("/sys/class/drm");
        struct dirent *e;
        /* a card with several (heads.c's two-head card1): its lowest
         * numbered, whatever order readdir gives */
        while (dir && (e = readdir(dir)))
            if (!strncmp(e->d_name, "card0-", 6) || !strncmp(e->d_name, "card1-", 6)) {
                char *c = e->d_name[4] == '0' ? conn0 : conn1;
                const char *nd = strrchr(e->d_name, '-'), *od = strrchr(c, '-');
                if (!c[0] || (nd && od && atoi(nd + 1) < atoi(od + 1)))
                    snprintf(c, 32, "%s", e->d_name + 6);
            }
        if (dir)
            closedir(dir);
        ok = access("/dev/dri/card1", F_OK) == 0 && conn0[0] && conn1[0];
        if (!ok)
            msleep(100);
    }
    return ok;
}

/* rmmod the second card's module and check card1 is gone (check name). */
static void guest_remove_second_card(const char *name, const char *module) __attribute__((unused));
static void guest_remove_second_card(const char *name, const char *module)
{
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rmmod %s 2>&1", module);
    int rm = system(cmd);
    int gone = 0;
    for (int t = 0; t < 30 && !gone; t++) {
        gone = access("/dev/dri/card1", F_OK) != 0;
        if (!gone)
            msleep(100);
    }
    guest_check(name, rm == 0 && gone, "rmmod %s: %d, card1 %s", module, rm, gone ? "gone" : "still there");
}

/* The second card's driver module for the cases that load and unload it
 * (multi.c, bind.c; outputs.c names the same in its fuller table): a
 * two-head virtio-gpu on x86_64, a bochs-display on aarch64. */
#ifndef CARD1_MODULE
#if defined(__x86_64__)
#define CARD1_MODULE "virtio_gpu"
#else
#define CARD1_MODULE "bochs"
#endif
#endif

#endif
